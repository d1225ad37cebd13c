package tracer

import java.nio.file.Files
import tracer.geometry.*
import tracer.image.*
import tracer.io.*
import tracer.math.*
import tracer.render.*
import tracer.scene.*

/** The README's REPL example, line for line: build a scene in code, render it, save it. */
class ReplExampleSuite extends munit.FunSuite:

  test("the README's REPL example renders and saves a picture"):
    val dir  = Files.createTempDirectory("repl")
    val file = dir.resolve("repl.png").toString
    // --- as in README.md ---
    val scene = Scene(
      camera = Camera(location = Vec3(0, 1, -5), lookAt = Vec3(0, 0, 0)),
      lights = List(Light(Vec3(-3, 4, -5))),
      objects = List(
        SceneObject(
          Sphere(Vec3(0, 0, 0), 1),
          Surface(reflection = 0.3, pigment = Pigment.Solid(Colour(0.9, 0.2, 0.2)))
        ),
        SceneObject(
          Plane.through(point = Vec3(0, -1, 0), normal = Vec3(0, 1, 0)),
          Surface(reflection = 0.4)
        )
      )
    )
    val image = Renderer.render(scene, CameraConfig.forScene(scene, columns = 320))
    val saved = Images.save(image, file)
    // --- end ---
    assertEquals(saved, Right(()))
    val back = Images.load(file).fold(fail(_), identity)
    assertEquals(back, image)
    assertEquals((back.width, back.height), (320, 240))
    // The sphere is red in the middle of the picture.
    assert(back(160, 110).r > back(160, 110).g * 2, back(160, 110).toString)
    Files.delete(dir.resolve("repl.png")); Files.delete(dir)

  test("a scene file loads in the REPL with SceneXml.load"):
    val loaded =
      SceneXml.load(java.nio.file.Path.of("scenes/showcase.xml"), java.nio.file.Path.of("scenes"))
    assert(loaded.exists(_.objects.nonEmpty), loaded.toString)
