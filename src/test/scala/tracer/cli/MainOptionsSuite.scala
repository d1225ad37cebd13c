package tracer.cli

import java.nio.file.{Files, Path}
import tracer.image.{Bitmap, Encoding}
import tracer.testkit.{Images, InProcess}

/** The options beyond the course text, run in-process: `-g`, `-R`, `-i` and `--version`. */
class MainOptionsSuite extends munit.FunSuite with Images with InProcess:

  private val dir = scratch("tracer-options")

  private val scenes = Path.of("scenes").toAbsolutePath

  private def run(cwd: Path, args: String*)(scene: String = ""): Run = inProcess(cwd, scene, args)

  private def assertFailed(r: Run, status: Int, expected: String*)(using munit.Location): Unit =
    assertEquals(r.status, status, r.err)
    assertEquals(r.out, "")
    assert(r.err.startsWith("tracer: ") && r.err.linesIterator.size == 1, s"stderr: '${r.err}'")
    expected.foreach(e => assert(r.err.contains(e), s"'${r.err.trim}' does not mention '$e'"))

  private def bytes(p: Path) = Files.readAllBytes(p).toList

  private val simple =
    """<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
      |<light><location x="-3" y="3" z="-5"/><colour r="1.5" g="1.5" b="1.5"/></light>
      |<sphere radius="1"><centre x="0" y="0" z="0"/><surface phong="0.5"><colour r="1" g="0.5" b="0"/></surface></sphere>
      |</scene>""".stripMargin

  test("--version prints 'tracer VERSION' alone, with or without OUTPUT"):
    for args <- List(List("--version"), List("--version", "out.png")) do
      val r = run(Path.of("."), args*)()
      assertEquals(r.status, 0)
      assert(r.out.matches("tracer \\d+\\.\\d+\\.\\d+\n"), r.out)
      assertEquals(r.err, "")

  test("--help ends with the Java it runs on"):
    val r = run(Path.of("."), "--help")()
    assertEquals((r.status, r.err), (0, ""))
    val java =
      s"Java ${System.getProperty("java.version")} (${System.getProperty("java.vendor")}) at " +
        System.getProperty("java.home")
    assertEquals(r.out.linesIterator.toList.last, java)

  for scene <- List("textures.xml", "meshes.xml") do
    dir.test(
      s"-i $scene from another directory writes the bytes of stdin in the scene's directory"
    ): d =>
      val xml = Files.readString(scenes.resolve(scene))
      assertEquals(run(scenes, "-x", "64", d.resolve("stdin.png").toString)(xml).status, 0)
      val r = run(d, "-x", "64", "-i", scenes.resolve(scene).toString, "file.png")()
      assertEquals(r, Run(0, "", ""))
      assertEquals(bytes(d.resolve("file.png")), bytes(d.resolve("stdin.png")))

  dir.test("-i resolves a relative FILE against the working directory"): d =>
    Files.writeString(d.resolve("s.xml"), simple)
    assertEquals(run(d, "-x", "16", "--input", "s.xml", "o.ppm")().status, 0)
    assert(Files.exists(d.resolve("o.ppm")))

  dir.test("-i with a missing or unreadable FILE is one line naming it, exit 1, output kept"): d =>
    Files.writeString(d.resolve("o.ppm"), "old")
    assertFailed(run(d, "-i", "nowhere.xml", "o.ppm")(), 1, "nowhere.xml", "no such file")
    Files.createDirectory(d.resolve("folder.xml"))
    assertFailed(run(d, "-i", "folder.xml", "o.ppm")(), 1, "folder.xml")
    assertEquals(Files.readString(d.resolve("o.ppm")), "old")

  dir.test("-R a:b writes exactly rows a … b − 1 of the whole picture"): d =>
    val scene = Files.readString(scenes.resolve("textures.xml"))
    val whole = (args: Seq[String]) =>
      assertEquals(run(scenes, (args :+ d.resolve("whole.ppm").toString)*)(scene).status, 0)
      readImage(d.resolve("whole.ppm"))
    for options <- List(List("-x", "48"), List("-x", "48", "-a", "3"), List("-x", "48", "-q")) do
      val all = whole(options)
      val y   = all.height
      for (a, b) <- List((0, 1), (0, y), (5, 17), (y - 1, y)) do
        val out = d.resolve(s"band-$a-$b.ppm").toString
        val r   = run(scenes, (options ++ List("-R", s"$a:$b", "-p", "3", out))*)(scene)
        assertEquals(r.status, 0, r.err)
        val band = readImage(Path.of(out))
        assertEquals((band.width, band.height), (48, b - a))
        val expected = Bitmap.tabulate(48, b - a)((x, y) => all(x, y + a))
        assertEquals(band, expected, s"${options.mkString(" ")} -R $a:$b")

  dir.test("-R bands of a mesh scene stack up to the whole picture"): d =>
    val scene = Files.readString(scenes.resolve("meshes.xml"))
    run(scenes, "-x", "40", d.resolve("whole.ppm").toString)(scene): Unit
    val bands = List((0, 7), (7, 8), (8, 23)).map { (a, b) =>
      run(scenes, "-x", "40", "--rows", s"$a:$b", d.resolve(s"$a.ppm").toString)(scene): Unit
      readImage(d.resolve(s"$a.ppm"))
    }
    assertEquals(Bitmap.stack(bands), readImage(d.resolve("whole.ppm")))

  dir.test("-R with -t times the band"): d =>
    val r = run(d, "-x", "40", "-R", "0:2", "-t", "o.ppm")(simple)
    assert(r.out.matches("Tracetime: \\d+ ms\n"), r.out)

  dir.test("bad -R values are usage errors, exit 2, old output kept"): d =>
    Files.writeString(d.resolve("o.ppm"), "old")
    for value <- List("5:5", "3:2", "-1:2", "a:b", "1", "1:2:3", ":4", "2.5:4") do
      assertFailed(run(d, "-x", "40", "-R", value, "o.ppm")(simple), 2, "-R")
    // b beyond the picture's Y (30 rows here) is known only once the scene is read.
    assertFailed(run(d, "-x", "40", "-R", "0:31", "o.ppm")(simple), 2, "-R 0:31", "30 rows")
    assertEquals(Files.readString(d.resolve("o.ppm")), "old")

  dir.test("-g 1 is byte-identical to no -g; -g srgb and -g 2.2 encode every channel"): d =>
    run(d, "-x", "40", "plain.ppm")(simple): Unit
    run(d, "-x", "40", "-g", "1", "g1.ppm")(simple): Unit
    assertEquals(bytes(d.resolve("g1.ppm")), bytes(d.resolve("plain.ppm")))
    val plain = readImage(d.resolve("plain.ppm"))
    for (option, encoding) <- List("srgb" -> Encoding.Srgb, "2.2" -> Encoding.Power(2.2)) do
      assertEquals(run(d, "-x", "40", "-g", option, "g.ppm")(simple).status, 0)
      val encoded = readImage(d.resolve("g.ppm"))
      // Encoding the linear picture's rounded bytes again strays from encoding the exact colours
      // by less than two levels where the linear level is 32 or more (dark levels stretch).
      for x <- 0 until 40; y <- 0 until 30; c <- 0 until 3 if plain.sample(x, y, c) >= 32 do
        val expected = 255 * encoding.encode(plain.sample(x, y, c) / 255.0)
        assert(Math.abs(encoded.sample(x, y, c) - expected) < 2, s"-g $option at ($x, $y)")
      assertNotEquals(encoded, plain)

  dir.test("bad -g values are usage errors, exit 2"): d =>
    for value <- List("0", "-1", "abc", "", "NaN") do
      assertFailed(run(d, "-x", "8", "-g", value, "o.ppm")(simple), 2, "-g")

  dir.test("--size prints the picture's size after the size rule, and renders nothing"): d =>
    assertEquals(run(d, "-x", "800", "--size")(simple), Run(0, "800 600\n", ""))
    assertEquals(run(d, "-w", "2", "-x", "100", "-y", "50", "--size")(simple).out, "100 50\n")
    Files.writeString(d.resolve("s.xml"), simple)
    assertEquals(run(d, "-i", "s.xml", "--size", "ignored.png")().out, "640 480\n")
    assert(!Files.exists(d.resolve("ignored.png")))
    assertFailed(run(d, "--size")("<scene>"), 1, "scene")

  dir.test("--size --stack: exit 2, one line naming both, nothing written"): d =>
    run(d, "-x", "20", "-R", "0:4", "top.ppm")(simple): Unit
    val r = run(d, "--size", "--stack", "top.ppm", "joined.ppm")(simple)
    assertFailed(r, 2, "--size and --stack")
    assert(!Files.exists(d.resolve("joined.ppm")))

  dir.test("--stack writes OUTPUT as the images one below the other, whole or not at all"): d =>
    run(d, "-x", "20", "-R", "0:4", "top.ppm")(simple): Unit
    run(d, "-x", "20", "-R", "4:15", "bottom.png")(simple): Unit
    run(d, "-x", "20", "-R", "0:15", "whole.ppm")(simple): Unit
    assertEquals(
      run(d, "--stack", "top.ppm", "--stack", "bottom.png", "joined.ppm")(),
      Run(0, "", "")
    )
    assertEquals(bytes(d.resolve("joined.ppm")), bytes(d.resolve("whole.ppm")))
    run(d, "-x", "21", "-R", "0:4", "wide.ppm")(simple): Unit
    Files.writeString(d.resolve("out.png"), "old")
    assertFailed(
      run(d, "--stack", "top.ppm", "--stack", "wide.ppm", "out.png")(),
      1,
      "differ in width"
    )
    assertFailed(run(d, "--stack", "top.ppm", "--stack", "none.ppm", "out.png")(), 1, "none.ppm")
    assertEquals(Files.readString(d.resolve("out.png")), "old")

  dir.test("--batch renders every frame of a list in one run, each exactly as a separate run"): d =>
    // Scenes in other directories, with textures and meshes relative to them (kept for the next
    // frame, and read again after a frame without them); -a and -t.
    val frames =
      List(
        "textures.xml",
        "textures.xml",
        "meshes.xml",
        "meshes.xml",
        "materials.xml",
        "textures.xml"
      )
    val list = frames.zipWithIndex
      .map((scene, i) => s"${scenes.resolve(scene)}\tframe $i.png")
      .mkString("# frames\n\n", "\n", "\n")
    Files.writeString(d.resolve("list.txt"), list)
    val r = run(d, "-x", "40", "-a", "2", "-t", "--batch", "list.txt")()
    assertEquals(r.status, 0, r.err)
    assertEquals(r.err, "")
    val times = r.out.linesIterator.toList
    assertEquals(times.length, frames.length, r.out)
    for (scene, i) <- frames.zipWithIndex do
      assert(times(i).matches(s"Tracetime: \\d+ ms frame $i\\.png"), times(i))
      run(d, "-x", "40", "-a", "2", "-i", scenes.resolve(scene).toString, s"single $i.png")(): Unit
      assertEquals(bytes(d.resolve(s"frame $i.png")), bytes(d.resolve(s"single $i.png")), scene)

  dir.test("--batch: a bad frame is named, the others are rendered, and the status is 1"): d =>
    Files.writeString(d.resolve("good.xml"), simple)
    Files.writeString(d.resolve("bad.xml"), "<scene>\n<camera/>\n</scene>")
    Files.writeString(d.resolve("list.txt"), "good.xml\ta.ppm\nbad.xml\tb.ppm\ngood.xml\tc.ppm\n")
    val r = run(d, "-x", "16", "-t", "--batch", "list.txt")()
    assertEquals(r.status, 1)
    assert(
      r.err.linesIterator.toList.length == 1 && r.err.startsWith("tracer: bad.xml: line 2: "),
      r.err
    )
    assertEquals(
      r.out.linesIterator.map(_.replaceAll("\\d+ ms", "N ms")).toList,
      List("Tracetime: N ms a.ppm", "Tracetime: N ms c.ppm")
    )
    assert(Files.exists(d.resolve("a.ppm")) && Files.exists(d.resolve("c.ppm")))
    assert(!Files.exists(d.resolve("b.ppm")))

  dir.test("--batch: a malformed or missing list, or an OUTPUT beside it, is refused"): d =>
    Files.writeString(d.resolve("list.txt"), "only-one-column.xml\n")
    assertFailed(run(d, "--batch", "list.txt")(), 1, "line 1", "SCENE<TAB>OUTPUT")
    Files.writeString(d.resolve("empty.txt"), "# nothing\n")
    assertFailed(run(d, "--batch", "empty.txt")(), 1, "no frames")
    assertFailed(run(d, "--batch", "none.txt")(), 1, "none.txt")
    assertFailed(run(d, "--batch", "list.txt", "out.png")(), 2, "--batch takes no OUTPUT")

  dir.test("--batch: a third column renders that band of the picture, as -R would"): d =>
    Files.writeString(d.resolve("s.xml"), simple)
    Files.writeString(d.resolve("list.txt"), "s.xml\ttop.ppm\t0:10\ns.xml\trest.ppm\t10:30\n")
    assertEquals(run(d, "-x", "40", "--batch", "list.txt")(), Run(0, "", ""))
    run(d, "-x", "40", "-i", "s.xml", "whole.ppm")(): Unit
    val joined = Bitmap.stack(List("top.ppm", "rest.ppm").map(n => readImage(d.resolve(n))))
    assertEquals(joined, readImage(d.resolve("whole.ppm")))
    Files.writeString(d.resolve("bad.txt"), "s.xml\tx.ppm\t3:2\n")
    assertFailed(run(d, "--batch", "bad.txt")(), 1, "line 1", "-R must be a:b")

  dir.test("--batch: a last column of options renders that frame with them, as a separate run"):
    d =>
      // Path mode for one frame (what the launcher's training run uses), a band with options,
      // and the command line's options kept for the frames without.
      Files.writeString(d.resolve("s.xml"), simple)
      Files.writeString(
        d.resolve("list.txt"),
        "s.xml\tpath.pfm\t-m path -s 2\ns.xml\tband.ppm\t0:10\t-r 1\ns.xml\twhitted.ppm\n"
      )
      assertEquals(run(d, "-x", "40", "--batch", "list.txt")(), Run(0, "", ""))
      run(d, "-x", "40", "-m", "path", "-s", "2", "-i", "s.xml", "path1.pfm")(): Unit
      run(d, "-x", "40", "-r", "1", "-R", "0:10", "-i", "s.xml", "band1.ppm")(): Unit
      run(d, "-x", "40", "-i", "s.xml", "whitted1.ppm")(): Unit
      for (batched, single) <- List("path.pfm" -> "path1.pfm", "band.ppm" -> "band1.ppm") do
        assertEquals(bytes(d.resolve(batched)), bytes(d.resolve(single)), batched)
      assertEquals(bytes(d.resolve("whitted.ppm")), bytes(d.resolve("whitted1.ppm")))
      // A frame whose options are bad fails alone, named by its line.
      Files.writeString(
        d.resolve("bad.txt"),
        "s.xml\ta.ppm\t-a 2 -m path\ns.xml\tb.ppm\t-i t.xml\n"
      )
      val r = run(d, "-x", "8", "--batch", "bad.txt")()
      assertEquals(r.status, 1)
      assert(r.err.contains("line 1") && r.err.contains("-a is Whitted's"), r.err)
      assert(r.err.contains("line 2") && r.err.contains("render options"), r.err)
