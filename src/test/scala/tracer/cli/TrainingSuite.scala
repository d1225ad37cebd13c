package tracer.cli

import java.io.{ByteArrayOutputStream, PrintStream}
import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import tracer.image.Png
import tracer.testkit.InProcess

/** The start-up cache's training run (`tracer.cli.Training`): one picture of the list's first
  * scene as a user renders it, then the whole list as a batch; a failure of either fails it.
  */
class TrainingSuite extends munit.FunSuite with InProcess:

  private val dir = scratch("tracer-training")

  // A triangle read from an OBJ file beside the scene: found only from the scene's directory.
  private val scene =
    """<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
      |<light><location x="-3" y="3" z="-5"/></light>
      |<mesh file="m.obj"/>
      |</scene>""".stripMargin

  /** Runs the training on `args`: its status, what it wrote to out and to err. */
  private def train(args: String*): Run =
    val (out, err) = (ByteArrayOutputStream(), ByteArrayOutputStream())
    val status     = Training.run(args, PrintStream(out, true), PrintStream(err, true))
    Run(status, out.toString(UTF_8), err.toString(UTF_8))

  /** A list of the scene in `d`/s, rendered twice, and the list's path. */
  private def list(d: Path): Path =
    Files.createDirectories(d.resolve("s"))
    Files.writeString(d.resolve("s/scene.xml"), scene)
    Files.writeString(d.resolve("s/m.obj"), "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n")
    val lines = List(1, 2).map(n => s"${d.resolve("s/scene.xml")}\t${d.resolve(s"f$n.png")}")
    Files.writeString(d.resolve("list"), lines.mkString("", "\n", "\n"))

  dir.test("one picture from standard input in the scene's directory, then the batch"): d =>
    val r = train("24", list(d).toString)
    assertEquals((r.status, r.err), (0, ""))
    // Only the single picture runs with -t: one Tracetime line.
    assertEquals(r.out.linesIterator.count(_.startsWith("Tracetime: ")), 1, r.out)
    for n <- List(1, 2) do
      val png = Png.read(Files.readAllBytes(d.resolve(s"f$n.png"))).fold(fail(_), identity)
      assertEquals(png.width, 24)

  dir.test("a list that cannot be read or names no frames fails with one line"): d =>
    val missing = train("24", d.resolve("none").toString)
    assertEquals(missing.status, Main.Failure)
    assert(missing.err.startsWith("tracer: training list ") && missing.err.linesIterator.size == 1)
    Files.writeString(d.resolve("empty"), "# nothing\n")
    assertEquals(train("24", d.resolve("empty").toString).status, Main.Failure)

  dir.test("a first scene that fails fails the training, after the batch"): d =>
    val l = list(d)
    Files.delete(d.resolve("s/m.obj"))
    val r = train("24", l.toString)
    assertEquals(r.status, Main.Failure)
    assert(r.err.contains("m.obj"), r.err)

  test("anything but WIDTH LIST is a usage error"):
    assertEquals(train("24").status, Main.UsageError)
