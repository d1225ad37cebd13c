package tracer.cli

import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import tracer.testkit.Images

/** System tests: the real `tracer` launcher script run as a process, as a user would run it.
  *
  * They need the assembled jar; `./sbt test` builds it first (build.sbt), and without it the
  * launcher would start a nested build, so these tests then stop with a clear message.
  */
class LauncherSuite extends munit.FunSuite with Images:

  private val home     = Path.of("").toAbsolutePath
  private val launcher = home.resolve("tracer")
  private val jar      = home.resolve("target/scala-3.8.3/tracer.jar")

  override def beforeAll(): Unit =
    assume(Files.exists(jar), s"$jar is missing: run ./sbt assembly (./sbt test does it first)")

  /** What one process did. */
  final case class Exit(status: Int, out: String, err: String)

  private def tracer(cwd: Path, stdin: Path, args: String*): Exit =
    runIn(cwd, stdin, launcher.toString +: args)

  private def runIn(cwd: Path, stdin: Path, command: Seq[String]): Exit =
    val out = Files.createTempFile("tracer-out", ".txt")
    val err = Files.createTempFile("tracer-err", ".txt")
    try
      val process = ProcessBuilder(command*)
        .directory(cwd.toFile)
        .redirectInput(stdin.toFile)
        .redirectOutput(out.toFile)
        .redirectError(err.toFile)
        .start()
      assert(process.waitFor(120, TimeUnit.SECONDS), s"$command did not finish")
      Exit(process.exitValue, Files.readString(out, UTF_8), Files.readString(err, UTF_8))
    finally List(out, err).foreach(Files.delete)

  private val work = FunFixture[Path](
    _ =>
      val d = Files.createTempDirectory("tracer launcher")
      for name <- List("basics.xml", "textures.xml", "orientation.ppm") do
        Files.write(d.resolve(name), getClass.getResourceAsStream(s"/samples/$name").readAllBytes())
      d
    ,
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
  )

  work.test("from another directory (whose path has a space) it renders the samples as expected"):
    d =>
      assertEquals(tracer(d, d.resolve("textures.xml"), "-x", "320", "t.png"), Exit(0, "", ""))
      assertImageClose(
        readImage(d.resolve("t.png")),
        resourceImage("/samples/expected/textures-320x240.png"),
        "launcher-textures"
      )
      assertEquals(tracer(d, d.resolve("basics.xml"), "-x", "320", "-t", "b.png").status, 0)
      assertImageClose(
        readImage(d.resolve("b.png")),
        resourceImage("/samples/expected/basics-320x240.png"),
        "launcher-basics"
      )

  work.test("through a symbolic link it still finds its jar"): d =>
    val link = Files.createSymbolicLink(d.resolve("tracer-link"), launcher)
    assertEquals(
      runIn(d, d.resolve("basics.xml"), List(link.toString, "-x", "16", "o.ppm")).status,
      0
    )

  work.test("-t prints exactly 'Tracetime: N ms' on stdout"): d =>
    val e = tracer(d, d.resolve("basics.xml"), "-t", "-x", "64", "-p", "2", "o.ppm")
    assertEquals(e.status, 0, e.err)
    assert(e.out.matches("Tracetime: \\d+ ms\n"), s"'${e.out}'")

  work.test("a bad scene exits 1 with one line on stderr, no stack trace"): d =>
    Files.writeString(d.resolve("bad.xml"), "<scene><camera/></scene>")
    val e = tracer(d, d.resolve("bad.xml"), "o.png")
    assertEquals((e.status, e.out), (1, ""))
    assertEquals(e.err.linesIterator.toList.length, 1, e.err)
    assert(e.err.startsWith("tracer: scene: line 1: <camera>: missing <location>"), e.err)
    assert(!Files.exists(d.resolve("o.png")))

  work.test("a usage error exits 2 with one line on stderr"): d =>
    val e = tracer(d, d.resolve("basics.xml"), "-p", "zero", "o.png")
    assertEquals((e.status, e.out), (2, ""))
    assertEquals(e.err.linesIterator.toList.length, 1, e.err)

  work.test("--help exits 0 with the usage on stdout"): d =>
    val e = tracer(d, d.resolve("basics.xml"), "--help")
    assertEquals((e.status, e.err), (0, ""))
    assert(e.out.contains("Usage: tracer"), e.out)

  work.test("on a terminal a long render shows a progress line on stderr, then erases it"): d =>
    assume(
      Files.isExecutable(Path.of("/usr/bin/script")),
      "needs script(1) to give the run a terminal"
    )
    Files.copy(home.resolve("scenes/showcase.xml"), d.resolve("showcase.xml"))
    Files.createSymbolicLink(d.resolve("textures"), home.resolve("scenes/textures"))
    // script(1) runs the command on a pseudo-terminal and copies what it shows to its stdout.
    val command = s"cd '$d' && '$launcher' -x 1200 -a 3 -p 1 o.png < showcase.xml"
    val e = runIn(d, Path.of("/dev/null"), List("/usr/bin/script", "-qec", command, "/dev/null"))
    assertEquals(e.status, 0, e.out + e.err)
    assert(e.out.contains("\rtracer: rendering ") && e.out.contains(" rows)"), e.out)
    assert(e.out.contains("\r\u001b[K"), "the line is erased at the end")
