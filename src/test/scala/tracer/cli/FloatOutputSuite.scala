package tracer.cli

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.image.{Colour, Exr, Pfm, Raster}
import tracer.io.SceneXml
import tracer.render.{CameraConfig, Integrator, Renderer}
import tracer.testkit.InProcess

/** `.pfm` and `.exr` output from the command (docs/cli.md, Floating-point output): the linear,
  * unclamped picture, `-g` refused with them, bands and `--stack`, a batch's bad frame alone.
  */
class FloatOutputSuite extends munit.FunSuite with InProcess:

  private val dir = scratch("tracer-float")

  private def run(cwd: Path, scene: String, args: String*): Run = inProcess(cwd, scene, args)

  // A lit ball and a ball glowing at 3 in red, so the picture holds values above 1.
  private val scene =
    """<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
      |<background r="0.1" g="0.2" b="2"/>
      |<light><location x="-3" y="3" z="-5"/></light>
      |<sphere radius="1"><centre x="-1" y="0" z="0"/><surface><colour r="1" g="0.5" b="0"/></surface></sphere>
      |<sphere radius="0.8"><centre x="1.2" y="0" z="0"/><surface diffuse="0"><emission r="3" g="0.5" b="0"/></surface></sphere>
      |</scene>""".stripMargin

  private lazy val expected: Raster =
    val s = SceneXml.parse(scene, _ => Left("no textures")).fold(e => fail(e.describe), identity)
    Renderer.renderRaster(s, CameraConfig.forScene(s, 16), threads = 1)

  private def assertFailed(r: Run, status: Int, expected: String*)(using munit.Location): Unit =
    assertEquals(r.status, status, r.err)
    assertEquals(r.out, "")
    assert(r.err.startsWith("tracer: ") && r.err.linesIterator.size == 1, s"stderr: '${r.err}'")
    expected.foreach(e => assert(r.err.contains(e), s"'${r.err.trim}' does not mention '$e'"))

  private def files(d: Path) =
    Files.list(d).toList.asScala.map(_.getFileName.toString).sorted.toList

  private def pfm(path: Path) = Pfm.read(Files.readAllBytes(path)).fold(fail(_), identity)
  private def exr(path: Path) = Exr.read(Files.readAllBytes(path)).fold(fail(_), identity)

  dir.test(".pfm and .exr (any case) hold Renderer.renderRaster's linear, unclamped picture"): d =>
    for name <- List("o.pfm", "O.PFM", "o.exr", "o.ExR") do
      assertEquals(run(d, scene, "-x", "16", "-p", "2", name), Run(0, "", ""))
    for name <- List("o.pfm", "O.PFM") do assertEquals(pfm(d.resolve(name)), expected)
    for name <- List("o.exr", "o.ExR") do assertEquals(exr(d.resolve(name)), expected)
    // The glowing ball's 3 and the sky's 2 are kept as they are.
    assertEquals(expected(12, 6), Colour(3, 0.5, 0))
    assertEquals(expected(0, 0), Colour(0.1f.toDouble, 0.2f.toDouble, 2))
    assertEquals(Files.readAllBytes(d.resolve("o.pfm")).take(3).toList, "PF\n".getBytes.toList)

  dir.test("-a n: the mean of the unclamped samples"): d =>
    assertEquals(run(d, scene, "-x", "16", "-a", "3", "o.pfm").status, 0)
    val s    = SceneXml.parse(scene, _ => Left("none")).fold(e => fail(e.describe), identity)
    val mean = Renderer.renderRaster(
      s,
      CameraConfig.forScene(s, 16).withIntegrator(Integrator.Whitted(samples = 3)),
      1
    )
    assertEquals(pfm(d.resolve("o.pfm")), mean)

  dir.test(
    "any -g with a .pfm or .exr output, even -g 1, is a usage error: exit 2, nothing written"
  ): d =>
    for (g, out) <- List(("1", "o.pfm"), ("srgb", "o.exr"), ("2.2", "O.EXR")) do
      assertFailed(run(d, scene, "-g", g, "-x", "8", out), 2, "-g", out, "see tracer --help")
    Files.writeString(d.resolve("kept.exr"), "precious")
    assertFailed(run(d, scene, "-g", "1", "kept.exr"), 2, "-g")
    assertEquals(Files.readString(d.resolve("kept.exr")), "precious")
    assertEquals(files(d), List("kept.exr"))
    // -g stays fine with 8-bit output.
    assertEquals(run(d, scene, "-g", "1", "-x", "8", "o.png").status, 0)

  dir.test("-R bands of a .pfm and an .exr are the rows of the whole, and --stack joins them"): d =>
    for kind <- List("pfm", "exr") do
      assertEquals(run(d, scene, "-x", "16", s"whole.$kind").status, 0)
      assertEquals(run(d, scene, "-x", "16", "-R", "0:5", s"top.$kind").status, 0)
      assertEquals(run(d, scene, "-x", "16", "-R", "5:12", s"rest.$kind").status, 0)
      val r = run(d, "", "--stack", s"top.$kind", "--stack", s"rest.$kind", s"joined.$kind")
      assertEquals(r, Run(0, "", ""))
      assertEquals(
        Files.readAllBytes(d.resolve(s"joined.$kind")).toList,
        Files.readAllBytes(d.resolve(s"whole.$kind")).toList
      )
    // Bands of one float kind may be joined into the other.
    assertEquals(run(d, "", "--stack", "top.exr", "--stack", "rest.pfm", "mixed.pfm").status, 0)
    assertEquals(pfm(d.resolve("mixed.pfm")), expected)

  dir.test(
    "--stack refuses to mix floating-point and 8-bit kinds: exit 2, one line, nothing written"
  ): d =>
    assertEquals(run(d, scene, "-x", "16", "-R", "0:5", "top.pfm").status, 0)
    assertEquals(run(d, scene, "-x", "16", "-R", "5:12", "rest.png").status, 0)
    assertFailed(run(d, "", "--stack", "top.pfm", "--stack", "rest.png", "j.pfm"), 2, "rest.png")
    assertFailed(run(d, "", "--stack", "top.pfm", "--stack", "top.pfm", "j.png"), 2, "j.png")
    // A band whose content is of the other kind than its name says: exit 1, naming it.
    Files.copy(d.resolve("rest.png"), d.resolve("fake.pfm"))
    assertFailed(run(d, "", "--stack", "top.pfm", "--stack", "fake.pfm", "j.pfm"), 1, "fake.pfm")
    assertEquals(files(d), List("fake.pfm", "rest.png", "top.pfm"))

  dir.test("--batch: an .exr frame under -g fails alone, the others are rendered, status 1"): d =>
    Files.writeString(d.resolve("s.xml"), scene)
    Files.writeString(d.resolve("list.txt"), "s.xml\ta.png\ns.xml\tb.exr\ns.xml\tc.ppm\n")
    val r = run(d, "", "-x", "8", "-g", "srgb", "--batch", "list.txt")
    assertEquals((r.status, r.out), (1, ""))
    assertEquals(r.err.linesIterator.toList.length, 1, r.err)
    assert(r.err.startsWith("tracer: s.xml: -g encodes 8-bit output only"), r.err)
    assertEquals(files(d), List("a.png", "c.ppm", "list.txt", "s.xml"))
    // Without -g the float frame is written beside the others.
    Files.writeString(d.resolve("list.txt"), "s.xml\tb.exr\ns.xml\td.pfm\n")
    assertEquals(run(d, "", "-x", "16", "--batch", "list.txt"), Run(0, "", ""))
    assertEquals(exr(d.resolve("b.exr")), expected)
    assertEquals(pfm(d.resolve("d.pfm")), expected)
