package tracer.testkit

import java.io.{ByteArrayInputStream, ByteArrayOutputStream, PrintStream}
import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}

/** The `tracer` command run in-process (`tracer.cli.Main.run`) from a scratch directory: what the
  * command's in-process system suites share.
  */
trait InProcess:
  self: munit.FunSuite =>

  /** What one run did: its exit status, and what it wrote to standard output and error. */
  final case class Run(status: Int, out: String, err: String)

  /** A scratch directory for each test, named from `prefix`, removed with all it holds after. */
  def scratch(prefix: String): FunFixture[Path] = FunFixture[Path](
    _ => Files.createTempDirectory(prefix),
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
  )

  /** Runs `tracer ARGS` in `cwd` with `scene` on its standard input. */
  def inProcess(cwd: Path, scene: String, args: Seq[String]): Run =
    val (out, err) = (ByteArrayOutputStream(), ByteArrayOutputStream())
    val status     = tracer.cli.Main.run(
      args,
      ByteArrayInputStream(scene.getBytes(UTF_8)),
      PrintStream(out, true),
      PrintStream(err, true),
      cwd
    )
    Run(status, out.toString(UTF_8), err.toString(UTF_8))
