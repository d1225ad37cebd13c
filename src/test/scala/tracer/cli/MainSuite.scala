package tracer.cli

import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.image.{Bitmap, Colour, Ppm}
import tracer.testkit.{Images, InProcess}

/** The `tracer` command run in-process: outputs, the sample pictures, and every kind of bad input. */
class MainSuite extends munit.FunSuite with Images with InProcess:

  private val dir = scratch("tracer-main")

  private def run(cwd: Path, scene: String, args: String*): Run = inProcess(cwd, scene, args)

  private def resource(name: String): String =
    String(getClass.getResourceAsStream(name).readAllBytes(), UTF_8)

  private val simple =
    """<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
      |<light><location x="-3" y="3" z="-5"/></light>
      |<sphere radius="1"><centre x="0" y="0" z="0"/><surface><colour r="1" g="0.5" b="0"/></surface></sphere>
      |</scene>""".stripMargin

  /** Asserts a failed run: the status, one `tracer: ` line on stderr, nothing on stdout. */
  private def assertFailed(r: Run, status: Int, expected: String*)(using munit.Location): Unit =
    assertEquals(r.status, status, r.err)
    assertEquals(r.out, "")
    assert(r.err.startsWith("tracer: ") && r.err.linesIterator.size == 1, s"stderr: '${r.err}'")
    expected.foreach(e => assert(r.err.contains(e), s"'${r.err.trim}' does not mention '$e'"))

  private def assertNoFilesBut(d: Path, names: String*)(using munit.Location): Unit =
    val present = Files.list(d).toList.asScala.toList.map(_.getFileName.toString)
    assertEquals(present.sorted, names.toList.sorted)

  private val samples = List(
    ("basics.xml", List("-x", "320"), "basics-320x240.png"),
    ("basics.xml", List("-x", "320", "-q"), "basics-q-320x240.png"),
    ("basics.xml", List("-x", "320", "-r", "0"), "basics-r0-320x240.png"),
    ("textures.xml", List("-x", "320"), "textures-320x240.png")
  )

  for (scene, args, expected) <- samples do
    dir.test(s"the sample ${args.mkString(" ")} < $scene gives $expected"): d =>
      Files.write(
        d.resolve("orientation.ppm"),
        getClass.getResourceAsStream("/samples/orientation.ppm").readAllBytes()
      )
      val r = run(d, resource(s"/samples/$scene"), (args :+ "out.png")*)
      assertEquals(r, Run(0, "", ""))
      assertImageClose(
        readImage(d.resolve("out.png")),
        resourceImage(s"/samples/expected/$expected"),
        expected
      )

  dir.test("-a 1 writes exactly the bytes of a run without -a"): d =>
    val scene = resource("/samples/basics.xml")
    assertEquals(run(d, scene, "-x", "80", "plain.ppm").status, 0)
    assertEquals(run(d, scene, "-x", "80", "-a", "1", "a1.ppm").status, 0)
    assertEquals(
      Files.readAllBytes(d.resolve("a1.ppm")).toList,
      Files.readAllBytes(d.resolve("plain.ppm")).toList
    )

  dir.test("-a 3 renders the basics sample as its reference picture, smoother than -a 1"): d =>
    assertEquals(run(d, resource("/samples/basics.xml"), "-x", "96", "-a", "3", "a3.png").status, 0)
    assertGolden(readImage(d.resolve("a3.png")), "basics-a3")

  dir.test("-t prints 'Tracetime: N ms' and nothing else on stdout"): d =>
    val r = run(d, simple, "-t", "-x", "40", "out.ppm")
    assertEquals(r.status, 0)
    assert(r.out.matches("Tracetime: \\d+ ms\n"), s"stdout: '${r.out}'")
    assertEquals(r.err, "")

  dir.test("a PNG, encoded while it renders, is the bytes of the PPM's picture as a PNG"): d =>
    val scene = resource("/samples/basics.xml")
    for threads <- List("1", "2") do
      assertEquals(run(d, scene, "-x", "200", "-p", threads, s"s$threads.png").status, 0)
      assertEquals(run(d, scene, "-x", "200", "-p", threads, s"s$threads.ppm").status, 0)
      val ppm = Ppm.read(Files.readAllBytes(d.resolve(s"s$threads.ppm")))
      val png = ppm.map(b => tracer.image.Png.encode(b).toList)
      assertEquals(Right(Files.readAllBytes(d.resolve(s"s$threads.png")).toList), png, threads)

  dir.test("without -t nothing is printed"): d =>
    assertEquals(run(d, simple, "-x", "40", "out.ppm"), Run(0, "", ""))

  dir.test("the output format follows the extension: PNG for .png, binary PPM otherwise"): d =>
    for name <- List("a.png", "b.PNG", "c.ppm", "d") do
      assertEquals(run(d, simple, "-x", "8", name).status, 0)
    def magic(name: String) = Files.readAllBytes(d.resolve(name)).take(4).toList
    assertEquals(magic("a.png"), List(0x89.toByte, 'P'.toByte, 'N'.toByte, 'G'.toByte))
    assertEquals(magic("b.PNG"), magic("a.png"))
    assertEquals(magic("c.ppm").take(2), List('P'.toByte, '6'.toByte))
    assertEquals(
      Files.readAllBytes(d.resolve("d")).toList,
      Files.readAllBytes(d.resolve("c.ppm")).toList
    )

  dir.test("the picture has the resolved size: -x 64 with the default camera is 64×48"): d =>
    run(d, simple, "-x", "64", "o.ppm"): Unit
    val image = Ppm.read(Files.readAllBytes(d.resolve("o.ppm"))).toOption.get
    assertEquals((image.width, image.height), (64, 48))

  dir.test("-z, -w and -h override the scene's camera"): d =>
    run(d, simple, "-x", "32", "-y", "24", "plain.ppm"): Unit
    run(d, simple, "-x", "32", "-y", "24", "-z", "2", "zoomed.ppm"): Unit
    run(d, simple, "-x", "32", "-y", "24", "-w", "2", "-h", "1.5", "wide.ppm"): Unit
    val List(plain, zoomed, wide) = List("plain.ppm", "zoomed.ppm", "wide.ppm").map(n =>
      Ppm.read(Files.readAllBytes(d.resolve(n))).toOption.get
    )
    // Doubling Z sees what doubling W and H at the same zoom would not: compare coverage of the sphere.
    def lit(b: Bitmap) =
      (for x <- 0 until 32; y <- 0 until 24 yield b.sample(x, y, 0) > 0).count(identity)
    assert(
      lit(zoomed) > lit(plain) && lit(wide) < lit(plain),
      s"${lit(plain)} ${lit(zoomed)} ${lit(wide)}"
    )

  dir.test("every thread count writes the same bytes"): d =>
    for p <- List(1, 2, 5) do
      assertEquals(run(d, simple, "-p", p.toString, "-x", "50", "-a", "2", s"p$p.ppm").status, 0)
    val bytes = List(1, 2, 5).map(p => Files.readAllBytes(d.resolve(s"p$p.ppm")).toList)
    assert(bytes.forall(_ == bytes.head))

  dir.test("a success replaces an existing file"): d =>
    Files.writeString(d.resolve("out.ppm"), "old")
    assertEquals(run(d, simple, "-x", "8", "out.ppm").status, 0)
    assert(Files.readAllBytes(d.resolve("out.ppm")).startsWith("P6".getBytes))
    assertNoFilesBut(d, "out.ppm")

  dir.test("an invalid scene exits 1 naming the element and line, and writes nothing"): d =>
    val bad = simple.replace("radius=\"1\"", "radius=\"-1\"")
    assertFailed(run(d, bad, "out.png"), 1, "line 3", "<sphere>", "radius")
    assertNoFilesBut(d)

  dir.test("a failed run never destroys an existing file"): d =>
    Files.writeString(d.resolve("out.png"), "precious")
    assertFailed(run(d, "<scene/>", "out.png"), 1, "missing <camera>")
    assertFailed(run(d, simple, "-x", "0", "out.png"), 2)
    assertEquals(Files.readString(d.resolve("out.png")), "precious")
    assertNoFilesBut(d, "out.png")

  dir.test("malformed XML and a DOCTYPE are failures with status 1"): d =>
    assertFailed(run(d, "<scene>", "o.png"), 1, "malformed XML")
    assertFailed(
      run(d, "<!DOCTYPE scene [<!ENTITY a \"b\">]><scene>&a;</scene>", "o.png"),
      1,
      "DOCTYPE"
    )
    assertNoFilesBut(d)

  dir.test("an output that is the -i scene file itself is refused, the scene kept"): d =>
    Files.writeString(d.resolve("mine.xml"), simple)
    assertFailed(run(d, "", "-i", "mine.xml", "mine.xml"), 2, "mine.xml", "scene file itself")
    assertFailed(run(d, "", "-i", "mine.xml", "./mine.xml"), 2, "scene file itself")
    assertEquals(Files.readString(d.resolve("mine.xml")), simple)

  dir.test("a scene error names the -i file, or `scene` for standard input"): d =>
    Files.writeString(d.resolve("bad.xml"), "<scene><camera/></scene>")
    assertFailed(run(d, "", "-i", "bad.xml", "o.png"), 1, "tracer: bad.xml: line 1: <camera>")
    assertFailed(run(d, "<scene><camera/></scene>", "o.png"), 1, "tracer: scene: line 1: <camera>")

  dir.test("a scene typed at a terminal is announced on stderr, with how to end it or use -i"): d =>
    def typed(args: String*) =
      val (out, err) = (java.io.ByteArrayOutputStream(), java.io.ByteArrayOutputStream())
      val status     = Main.run(
        args,
        java.io.ByteArrayInputStream(simple.getBytes(UTF_8)),
        java.io.PrintStream(out, true),
        java.io.PrintStream(err, true),
        d,
        typed = true
      )
      (status, err.toString(UTF_8))
    val (status, err) = typed("-x", "8", "o.ppm")
    assertEquals(status, 0)
    assertEquals(
      err,
      "tracer: reading the scene from standard input (end it with Ctrl-D, or give -i FILE)\n"
    )
    // With -i, standard input is not read, so nothing is announced.
    Files.writeString(d.resolve("s.xml"), simple)
    assertEquals(typed("-x", "8", "-i", "s.xml", "p.ppm"), (0, ""))

  dir.test("nothing on standard input is one clear line"): d =>
    assertFailed(run(d, "", "o.png"), 1, "no scene on standard input")
    assertNoFilesBut(d)

  dir.test("a missing or unreadable texture exits 1 naming the file"): d =>
    val textured =
      simple.replace("<colour r=\"1\" g=\"0.5\" b=\"0\"/>", "<texture file=\"maps/earth.ppm\"/>")
    assertFailed(run(d, textured, "o.png"), 1, "maps/earth.ppm", "no such file")
    // A relative name that is not there: where it was looked for, from the scene's directory.
    assertFailed(run(d, textured, "o.png"), 1, s"looked for ${d.resolve("maps/earth.ppm")}")
    Files.createDirectory(d.resolve("maps"))
    Files.writeString(d.resolve("maps/earth.ppm"), "P3 2 2 255 1 2 3")
    assertFailed(run(d, textured, "o.png"), 1, "maps/earth.ppm", "truncated")
    assertNoFilesBut(d, "maps")

  dir.test("textures are read relative to the working directory, as PPM or PNG"): d =>
    val textured =
      simple.replace("<colour r=\"1\" g=\"0.5\" b=\"0\"/>", "<texture file=\"tex.img\"/>")
    Files.write(d.resolve("tex.img"), tracer.image.Png.encode(Bitmap.fill(4, 4, Colour(0, 1, 0))))
    assertEquals(run(d, textured, "-x", "16", "-q", "o.ppm").status, 0)
    val image = Ppm.read(Files.readAllBytes(d.resolve("o.ppm"))).toOption.get
    assertEquals((image.sample(8, 6, 0), image.sample(8, 6, 2)), (0, 0))
    assert(image.sample(8, 6, 1) > 200)

  dir.test(
    "a mesh's OBJ problems: exit 1 with one message for bad files, warnings on stderr otherwise"
  ): d =>
    val withMesh = simple.replace("</scene>", "<mesh file=\"m.obj\"/></scene>")
    assertFailed(run(d, withMesh, "o.png"), 1, "m.obj", "no such file")
    Files.writeString(d.resolve("m.obj"), "")
    assertFailed(run(d, withMesh, "o.png"), 1, "m.obj has no faces")
    Files.writeString(d.resolve("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
    assertFailed(run(d, withMesh, "o.png"), 1, "m.obj line 4", "vertex index 4 is out of range")
    assertNoFilesBut(d, "m.obj")
    Files.writeString(
      d.resolve("m.obj"),
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nvp 1\nf 1 2 3\nf 1 2 4\n"
    )
    val r = run(d, withMesh, "-x", "8", "o.png")
    assertEquals((r.status, r.out), (0, ""))
    assertEquals(
      r.err.linesIterator.toList,
      List(
        "tracer: warning: m.obj: skipped unsupported statements: vp",
        "tracer: warning: m.obj: skipped 1 face whose corners are collinear"
      )
    )

  dir.test("an output in a missing directory exits 1 before rendering"): d =>
    assertFailed(run(d, simple, "-t", "nowhere/out.png"), 1, "nowhere", "no such directory")

  dir.test("an image too large for memory is a clear error, not an OutOfMemoryError"): d =>
    assertFailed(run(d, simple, "-x", "100000", "-y", "100000", "o.png"), 1, "too large")
    assertFailed(run(d, simple, "-x", "30000", "-y", "20000", "o.png"), 1, "too large for memory")
    assertNoFilesBut(d)

  test("-t's time leaves out the threads' share of the PNG encoding done while rendering"):
    assertEquals(Main.renderMillis(100, 60000000L, 2), 70L)
    assertEquals(Main.renderMillis(100, 60000000L, 1), 40L)
    assertEquals(Main.renderMillis(100, 0L, 4), 100L)
    assertEquals(Main.renderMillis(100, 1999999L, 1), 99L) // whole milliseconds, down
    assertEquals(Main.renderMillis(10, 60000000L, 1), 0L)  // never below 0

  dir.test("usage errors exit 2 and write nothing"): d =>
    assertFailed(run(d, simple), 2, "OUTPUT")
    assertFailed(run(d, simple, "-r", "-2", "o.png"), 2, "-r")
    assertFailed(run(d, simple, "-a", "17", "o.png"), 2, "-a")
    assertFailed(run(d, simple, "--frobnicate", "o.png"), 2, "frobnicate")
    assertNoFilesBut(d)

  dir.test("standard input that cannot be read, and -i '', are one line and exit 1"): d =>
    // Standard input redirected from a directory: reading it fails as the JDK's stdin does.
    val directory = new java.io.InputStream:
      def read(): Int = throw java.io.IOException("Is a directory") // Why: stdin's own failure
    val (out, err) = (java.io.ByteArrayOutputStream(), java.io.ByteArrayOutputStream())
    val status     = tracer.cli.Main.run(
      List("-x", "8", "o.png"),
      directory,
      java.io.PrintStream(out, true),
      java.io.PrintStream(err, true),
      d
    )
    assertFailed(
      Run(status, out.toString(UTF_8), err.toString(UTF_8)),
      1,
      "cannot read the scene from standard input: Is a directory"
    )
    assertFailed(run(d, "", "-i", "", "-x", "8", "o.png"), 1, "-i needs a file name")
    assertNoFilesBut(d)

  dir.test("an output whose directory is a file is one line naming it, exit 1"): d =>
    Files.writeString(d.resolve("plain"), "not a directory")
    assertFailed(run(d, simple, "-x", "8", "plain/o.png"), 1, "plain' is not a directory")
    assertNoFilesBut(d, "plain")

  dir.test("--help prints the usage on stdout and exits 0"): d =>
    val r = run(d, "", "--help")
    assertEquals((r.status, r.err), (0, ""))
    assert(r.out.contains("tracer [options] OUTPUT") && r.out.contains("-r, --depth d"), r.out)
