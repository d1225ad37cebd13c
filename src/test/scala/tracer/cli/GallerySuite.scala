package tracer.cli

import java.io.{ByteArrayInputStream, ByteArrayOutputStream, PrintStream}
import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import scala.xml.{Elem, XML}
import tracer.testkit.Images

/** The gallery in `scenes/`: each scene renders as its committed reference picture, and together
  * they use every element and attribute of the scene format.
  *
  * After a deliberate change to the pictures, regenerate the references with
  * `GOLDEN_UPDATE=true ./sbt "testOnly tracer.cli.GallerySuite"` and look at them before committing.
  */
class GallerySuite extends munit.FunSuite with Images:

  private val scenes  = Path.of("scenes")
  private val gallery = Files
    .list(scenes)
    .iterator
    .asScala
    .map(_.getFileName.toString)
    .filter(_.endsWith(".xml"))
    .toList
    .sorted

  test("the gallery has scenes"):
    assert(gallery.length >= 3, gallery.toString)

  for name <- gallery do
    test(s"scenes/$name renders as its reference picture (96 pixels wide, -a 2)"):
      val output = Files.createTempFile("gallery", ".png")
      try
        val err    = ByteArrayOutputStream()
        val scene  = ByteArrayInputStream(Files.readAllBytes(scenes.resolve(name)))
        val status = Main.run(
          List("-x", "96", "-a", "2", "-r", "8", output.toString),
          scene,
          PrintStream(ByteArrayOutputStream()),
          PrintStream(err),
          scenes.toAbsolutePath
        )
        assertEquals(status, 0, err.toString)
        assertGolden(readImage(output), name.replace(".xml", ""))
      finally Files.delete(output)

  for name <- gallery do
    test(s"scenes/$name path-traces: every shape, texture and checker, finite and never negative"):
      val output = Files.createTempFile("gallery", ".pfm")
      try
        val err    = ByteArrayOutputStream()
        val scene  = ByteArrayInputStream(Files.readAllBytes(scenes.resolve(name)))
        val status = Main.run(
          List("-m", "path", "-s", "2", "-r", "4", "-x", "32", output.toString),
          scene,
          PrintStream(ByteArrayOutputStream()),
          PrintStream(err),
          scenes.toAbsolutePath
        )
        assertEquals(status, 0, err.toString)
        val raster = tracer.image.Pfm.read(Files.readAllBytes(output)).fold(fail(_), identity)
        val values =
          for y <- 0 until raster.height; x <- 0 until raster.width; c <- 0 until 3
          yield raster.channel(x, y, c)
        assert(values.forall(v => v >= 0 && v.isFinite), s"$name: a negative or non-finite pixel")
        assert(values.exists(_ > 0), s"$name: black")
      finally Files.delete(output)

  test("scenes/cornell.xml path-traced renders as its reference picture (48 pixels, -s 16)"):
    val output = Files.createTempFile("gallery", ".png")
    try
      val err    = ByteArrayOutputStream()
      val scene  = ByteArrayInputStream(Files.readAllBytes(scenes.resolve("cornell.xml")))
      val status = Main.run(
        List("-m", "path", "-s", "16", "-r", "7", "-x", "48", "-g", "srgb", output.toString),
        scene,
        PrintStream(ByteArrayOutputStream()),
        PrintStream(err),
        scenes.toAbsolutePath
      )
      assertEquals(status, 0, err.toString)
      assertGolden(readImage(output), "cornell-path")
    finally Files.delete(output)

  test("together the gallery scenes use every element and attribute of docs/scene-format.md"):
    val used = gallery
      .flatMap(n => XML.loadFile(scenes.resolve(n).toFile).descendant_or_self)
      .collect {
        case e: Elem => (e.label :: e.attributes.asAttrMap.keys.map(k => s"${e.label}@$k").toList)
      }
      .flatten
      .toSet
    val format = Set(
      "scene",
      "camera",
      "camera@zoom",
      "camera@width",
      "camera@height",
      "location",
      "lookat",
      "up",
      "background",
      "light",
      "colour",
      "color",
      "sphere",
      "sphere@radius",
      "centre",
      "center",
      "pole",
      "equator",
      "surface",
      "surface@diffuse",
      "surface@reflection",
      "texture",
      "texture@file",
      "plane",
      "plane@distance",
      "normal",
      "point",
      "triangle",
      "corner",
      "origin",
      "a",
      "b",
      "mesh",
      "mesh@file",
      "mesh@scale",
      "rotate",
      "translate",
      // Version 2.
      "surface@phong",
      "surface@phong-size",
      "surface@specular",
      "surface@roughness",
      "surface@transmit",
      "surface@ior",
      "area",
      "area@samples-a",
      "area@samples-b",
      "mesh@smooth",
      // Version 3.
      "box",
      "box@scale",
      "corner1",
      "corner2",
      "cylinder",
      "cylinder@radius",
      "cylinder@open",
      "cylinder@scale",
      "cone",
      "cone@base-radius",
      "cone@cap-radius",
      "cone@scale",
      "base",
      "cap",
      "torus",
      "torus@major",
      "torus@minor",
      "torus@scale",
      "union",
      "union@scale",
      "intersection",
      "difference",
      "difference@scale",
      "checker",
      "checker@size"
    )
    assertEquals(format -- used, Set.empty[String])

  test("the gallery's textures come in every format the tracer reads: P6, P3 and PNG"):
    val kinds = Files
      .list(scenes.resolve("textures"))
      .iterator
      .asScala
      .map(p => String(Files.readAllBytes(p).take(4), "ISO-8859-1").take(2))
      .toSet
    assertEquals(kinds, Set("P6", "P3", "\u0089P"))
