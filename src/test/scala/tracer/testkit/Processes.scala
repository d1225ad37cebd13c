package tracer.testkit

import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import scala.jdk.CollectionConverters.*

/** Running a real command as a user would, for the launcher's and the release's system tests. */
object Processes:

  /** What one process did: its exit status and what it wrote on stdout and stderr. */
  final case class Exit(status: Int, out: String, err: String)

  /** Runs `command` in `cwd` with standard input from /dev/null, the environment of this JVM
    * changed by `env` (a `None` value removes the variable), and waits at most `seconds`.
    */
  def run(
      command: Seq[String],
      cwd: Path,
      env: Map[String, Option[String]] = Map.empty,
      seconds: Int = 300
  ): Exit =
    val out = Files.createTempFile("tracer-out", ".txt")
    val err = Files.createTempFile("tracer-err", ".txt")
    try
      val builder = ProcessBuilder(command.asJava)
        .directory(cwd.toFile)
        .redirectInput(Path.of("/dev/null").toFile)
        .redirectOutput(out.toFile)
        .redirectError(err.toFile)
      env.foreach {
        case (name, Some(value)) => builder.environment.put(name, value)
        case (name, None)        => builder.environment.remove(name)
      }
      val process = builder.start()
      if !process.waitFor(seconds.toLong, TimeUnit.SECONDS) then
        process.destroyForcibly()
        Exit(-1, Files.readString(out, UTF_8), s"$command did not finish in $seconds s")
      else Exit(process.exitValue, Files.readString(out, UTF_8), Files.readString(err, UTF_8))
    finally List(out, err).foreach(Files.delete)

  /** Whether this JVM runs as root (then a read-only directory does not stop it writing). */
  def isRoot: Boolean =
    run(Seq("id", "-u"), Path.of("/")).out.trim == "0"

  /** Deletes `dir` and everything in it, making it writable first. */
  def deleteTree(dir: Path): Unit =
    if Files.exists(dir) then
      run(Seq("chmod", "-R", "u+w", dir.toString), Path.of("/")): Unit // then delete what it can
      Files.walk(dir).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
