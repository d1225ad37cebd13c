package tracer.demo

import tracer.image.{Bitmap, Colour}
import tracer.io.{SceneWriter, SceneXml}
import tracer.scene.Texture

/** The project's animation writes scenes that the tracer reads back. */
class AnimationSuite extends munit.FunSuite:

  private val image                            = Bitmap.fill(2, 2, Colour(0.2, 0.4, 0.6))
  private val textures: SceneXml.TextureLoader = _ => Right(image)

  test("the movie's frames are valid scenes"):
    val placeholder = Texture(image, "textures/planet.ppm")
    val frame       = Animation.frame(
      1.0,
      Animation.Textures(placeholder, placeholder.copy(name = "textures/checker.png"))
    )
    val text = SceneWriter.write(frame).fold(fail(_), identity)
    assert(SceneXml.parse(text, textures).isRight, text)
