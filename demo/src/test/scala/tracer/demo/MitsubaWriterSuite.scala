package tracer.demo

import tracer.geometry.*
import tracer.image.{Bitmap, Colour}
import tracer.math.{Placement, Vec3}
import tracer.scene.*

/** The Mitsuba twin's text (no Mitsuba needed): the numbers the spec's table fixes, and a clear
  * refusal for every scene that has no twin.
  */
class MitsubaWriterSuite extends munit.FunSuite:

  private val camera   = Camera(Vec3(0, 0, -5), Vec3(0, 0, 0), zoom = 2, width = 1, height = 0.75)
  private val settings = Mitsuba.Settings(40, 30, 16, 3)
  private def scene(objects: SceneObject*) = Scene(camera, objects = objects)
  private val ball                         = Sphere(Vec3(0, 0, 0), 1)

  /** The scene part of the twin (after the fixed Python preamble). */
  private def twin(s: Scene): String =
    val program = Mitsuba.write(s, settings).fold(fail(_), identity)
    program.substring(program.indexOf("\nrender("))

  test("the camera: fov = 2·atan(W / 2Z) along x, look_at then the mirror of x"):
    val program = twin(scene(SceneObject(ball)))
    val fov     = Math.toDegrees(2 * Math.atan(1.0 / 4))
    assert(program.contains(s"\"fov\": $fov"), program)
    assert(program.contains("\"fov_axis\": \"x\""))
    assert(program.contains("look_at([0.0, 0.0, -5.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0])"))
    assert(program.contains("\"width\": 40") && program.contains("\"height\": 30"))
    assert(program.contains("\"sample_count\": 16"))
    assert(
      program.contains("\"type\": \"box\""),
      "a box reconstruction filter, not Mitsuba's Gaussian"
    )

  test(
    "-r d is max_depth d + 1 under path with rr_depth 5, volpath with rr_depth 4 where a surface is clear"
  ):
    val solid = twin(scene(SceneObject(ball)))
    assert(solid.contains("\"type\": \"path\",\n    \"max_depth\": 4,\n    \"rr_depth\": 5"), solid)
    val clear = twin(scene(SceneObject(ball, Surface(transmit = 0.5))))
    assert(
      clear.contains("\"type\": \"volpath\",\n    \"max_depth\": 4,\n    \"rr_depth\": 4"),
      clear
    )
    assert(clear.contains("\"type\": \"mask\""), clear)

  test(
    "a delta lobe beside a smooth one is mixed by the Python BSDF, a lone lobe is Mitsuba's own"
  ):
    val mixed = twin(scene(SceneObject(ball, Surface(diffuse = 0.5, reflection = 0.5))))
    assert(mixed.contains("mixture([0.5, {"), mixed)
    assert(!mixed.contains("blendbsdf"))
    val lone = twin(scene(SceneObject(ball, Surface(diffuse = 0, transmit = 1, ior = 1.5))))
    assert(!lone.contains("mixture(["), lone)
    assert(lone.contains("\"int_ior\": 1.5"), lone)

  test("an area light becomes its NA·NB sub-lights of C/(NA·NB), with the light's fade"):
    val light = Light(
      Vec3(0, 3, 0),
      Colour(0.6, 0.6, 0.6),
      Some(AreaLight(Vec3(1, 0, 0), Vec3(0, 0, 1), 2, 3)),
      Some(Fade(2, 1))
    )
    val program = twin(Scene(camera, lights = Seq(light), objects = Seq(SceneObject(ball))))
    assertEquals("\"type\": \"tracer_light\"".r.findAllIn(program).size, 6)
    assertEquals("\"fade_distance\": 2.0".r.findAllIn(program).size, 6)
    assert(program.contains(s"mi.ScalarColor3f(${0.6 / 6}, ${0.6 / 6}, ${0.6 / 6})"), program)
    assert(program.contains("\"position\": [-0.5, 3.0, -0.5]"), program)

  test(
    "cones, tori, CSG, textures, checkers and a stretched image plane have no twin, said in one line"
  ):
    val texture = Pigment.Textured(Texture(Bitmap.tabulate(1, 1)((_, _) => Colour.White)))
    val cases   = List(
      scene(SceneObject(Cone(Vec3(0, 0, 0), 1, Vec3(0, 1, 0), 0.5))) -> "cone",
      scene(SceneObject(Placed(Torus(1, 0.2), Placement(2))))        -> "torus",
      scene(
        SceneObject(Csg(CsgOperation.Union, Vector(ball, Box(Vec3(0, 0, 0), Vec3(1, 1, 1)))))
      )                                                    -> "CSG",
      scene(SceneObject(ball, Surface(pigment = texture))) -> "texture",
      scene(
        SceneObject(ball, Surface(pigment = Pigment.Checker(Colour.White, Colour.Black)))
      )                                                                -> "checker",
      Scene(camera.copy(height = 1), objects = Seq(SceneObject(ball))) -> "W/H"
    )
    cases.foreach { (s, word) =>
      val why = Mitsuba.write(s, settings).swap.getOrElse(fail(s"$word: a twin was written"))
      assert(why.contains(word) && !why.contains("\n"), why)
    }
