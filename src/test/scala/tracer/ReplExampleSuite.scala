package tracer

import java.nio.file.{Files, Path}
import tracer.geometry.*
import tracer.image.*
import tracer.io.*
import tracer.math.*
import tracer.render.*
import tracer.scene.*

/** The README's REPL example, line for line: build a scene in code, render it, save it. The
  * imports are the console's (`console / initialCommands` in build.sbt), `Path` among them.
  */
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

  test("the console imports what these examples use, Path among them"):
    val build = java.nio.file.Files.readString(Path.of("build.sbt"))
    assert(build.contains("initialCommands := \"import java.nio.file.Path, "), "build.sbt")

  test("a scene file loads in the REPL with SceneXml.load"):
    // --- as in README.md ---
    val loaded = SceneXml.load(Path.of("scenes/showcase.xml"), Path.of("scenes"))
    // --- end ---
    assert(loaded.exists(_.objects.nonEmpty), loaded.toString)

  test("the guide's CSG example renders as the same scene written in XML"):
    // --- as in docs/guide.md, Solids and CSG ---
    val cut = SceneObject(
      Placed(
        Csg(
          CsgOperation.Difference,
          Vector(Box(Vec3(-1, -1, -1), Vec3(1, 1, 1)), Sphere(Vec3(0, 0, 0), 1.3))
        ),
        Placement(rotate = Vec3(0, 35, 0))
      ),
      Surface(diffuse = 0.9, reflection = 0.2, pigment = Pigment.Solid(Colour(0.9, 0.8, 0.3)))
    )
    val floor = SceneObject(
      Plane.through(point = Vec3(0, -1, 0), normal = Vec3(0, 1, 0)),
      Surface(pigment = Pigment.Checker(Colour(0.9, 0.9, 0.9), Colour(0.1, 0.1, 0.12)))
    )
    val scene = Scene(
      camera = Camera(location = Vec3(0, 2, -5), lookAt = Vec3(0, 0, 0)),
      lights = List(Light(Vec3(-3, 4, -5))),
      objects = List(cut, floor)
    )
    // --- end ---
    val xml = """<scene><camera><location x="0" y="2" z="-5"/><lookat x="0" y="0" z="0"/></camera>
      |<light><location x="-3" y="4" z="-5"/></light>
      |<difference>
      |  <box><corner1 x="-1" y="-1" z="-1"/><corner2 x="1" y="1" z="1"/></box>
      |  <sphere radius="1.3"><centre x="0" y="0" z="0"/></sphere>
      |  <surface diffuse="0.9" reflection="0.2"><colour r="0.9" g="0.8" b="0.3"/></surface>
      |  <rotate x="0" y="35" z="0"/>
      |</difference>
      |<plane><normal x="0" y="1" z="0"/><point x="0" y="-1" z="0"/>
      |  <surface><checker><colour r="0.9" g="0.9" b="0.9"/><colour r="0.1" g="0.1" b="0.12"/></checker></surface>
      |</plane></scene>""".stripMargin
    val read = SceneXml.parse(xml, _ => Left("no textures")).fold(e => fail(e.describe), identity)
    assertEquals(read, scene)
    val config = CameraConfig.forScene(scene, columns = 64)
    val image  = Renderer.render(scene, config)
    assertEquals(image, Renderer.render(read, config))
    // The gold die shows in the middle of the picture.
    assert(image(32, 24).r > image(32, 24).b, image(32, 24).toString)
