package tracer.cli

import java.io.{FileInputStream, OutputStream, PrintStream}
import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import scala.util.{Try, Using}

/** The start-up cache's training run (launcher/launcher.sh): the two ways users run the tracer, in
  * one process, so that the cache holds the classes and method profiles of both.
  *
  * `java -cp tracer.jar tracer.cli.Training WIDTH LIST` renders the first scene of the batch list
  * LIST as one picture (`tracer -t -p 2 -x 32 -g srgb OUTPUT < SCENE`, run from the scene's
  * directory: the gallery's scenes are made for `-g srgb`), then the whole list as one batch 4
  * pixels wide, where a scene of many primitives gets a coarse tree in Morton order
  * (render.LinearBuild) as short renders of large scenes do, then as one batch `WIDTH` pixels
  * wide (`tracer -x WIDTH -p 2 --batch LIST`), whose pictures stay. A batch alone left the
  * one-picture path untrained: its classes were loaded from the jar and its lambdas spun at run
  * time, about 10 ms of a 32×24 render (docs/performance.md, round 23).
  */
object Training:

  /** Runs the training and exits with its status. */
  def main(args: Array[String]): Unit =
    val status = run(args.toSeq, PrintStream(OutputStream.nullOutputStream()), System.err)
    sys.exit(status)

  /** Runs the training on `args` (WIDTH LIST), the renders' reports to `out`, failures to `err`,
    * and returns the exit status: [[Main.Success]] when both renders succeed.
    */
  def run(args: Seq[String], out: PrintStream, err: PrintStream): Int =
    // The jar's main class, which the launcher starts: Scala code calls its module (Main$), so
    // nothing else here loads it.
    Class.forName("tracer.cli.Main")
    val cwd = Path.of("").toAbsolutePath
    args match
      case Seq(width, list) =>
        val first = Try(Files.readString(cwd.resolve(list), UTF_8)).toEither.left
          .map(e => s"training list $list: ${e.getMessage}")
          .flatMap(Batch.parse)
          .flatMap(_.headOption.toRight(s"training list $list: no frames"))
        first match
          case Left(why) =>
            err.println(s"tracer: $why")
            Main.Failure
          case Right(frame) =>
            val scene  = cwd.resolve(frame.scene)
            val output = cwd.resolve(frame.output).toString
            val single = Seq("-t", "-p", "2", "-x", "32", "-g", "srgb", output)
            val one    =
              Using(FileInputStream(scene.toFile))(Main.run(single, _, out, err, scene.getParent))
                .recover { e =>
                  err.println(s"tracer: ${frame.scene}: ${e.getMessage}")
                  Main.Failure
                }
                .getOrElse(Main.Failure)
            val coarse =
              Main.run(Seq("-x", "4", "-p", "2", "--batch", list), System.in, out, err, cwd)
            val all =
              Main.run(Seq("-x", width, "-p", "2", "--batch", list), System.in, out, err, cwd)
            Math.max(one, Math.max(coarse, all))
      case _ =>
        err.println("tracer: training takes WIDTH LIST")
        Main.UsageError
