package tracer.cli

import java.io.{InputStream, PrintStream}
import java.nio.file.Path
import scala.util.control.NonFatal
import tracer.image.Bitmap
import tracer.io.{Images, OutputFile, SceneSources, SceneXml}
import tracer.render.{CameraConfig, Renderer, ShadingMode}
import tracer.scene.Scene

/** The `tracer` command: `tracer [options] OUTPUT < scene.xml` (cli.md). */
object Main:

  /** Exit status of a successful run. */
  val Success = 0

  /** Exit status of a failure: bad scene, unreadable texture, unwritable output, too large. */
  val Failure = 1

  /** Exit status of a usage error. */
  val UsageError = 2

  /** Runs the command and exits with its status. */
  def main(args: Array[String]): Unit =
    val status = run(args.toSeq, System.in, System.out, System.err, Path.of("").toAbsolutePath)
    System.out.flush()
    sys.exit(status)

  /** Runs the command on the given streams, with relative paths resolved against `cwd`, and
    * returns the exit status. Every failure is one line on `err`, prefixed `tracer: `.
    */
  def run(args: Seq[String], in: InputStream, out: PrintStream, err: PrintStream, cwd: Path): Int =
    def fail(status: Int, message: String): Int =
      err.println(s"tracer: $message")
      status
    try
      Options.parse(args) match
        case Command.Help(usage) =>
          out.println(usage)
          Success
        case Command.UsageError(message) => fail(UsageError, s"$message (see tracer --help)")
        case Command.Render(options)     =>
          render(options, in, out, err, cwd).fold(fail(Failure, _), _ => Success)
    catch
      case _: OutOfMemoryError =>
        fail(Failure, "out of memory: try a smaller image or more heap (-Xmx)")
      case NonFatal(e) => fail(Failure, s"internal error: $e")

  private def render(
      options: Options,
      in: InputStream,
      out: PrintStream,
      err: PrintStream,
      cwd: Path
  ): Either[String, Unit] =
    val output = cwd.resolve(options.output)
    for
      _     <- OutputFile.checkWritable(output)
      scene <- SceneXml
        .parse(in.readAllBytes(), SceneSources.files(cwd, w => err.println(s"tracer: warning: $w")))
        .left
        .map(e => s"scene: ${e.describe}")
      config = cameraConfig(scene, options)
      _ <- fitsInMemory(config)
      threads         = options.threads.getOrElse(Renderer.defaultThreads)
      (image, millis) = timed(
        withProgress(err, config.rows)(Renderer.render(scene, config, threads, _))
      )
      _ <- Images.save(image, output)
    yield if options.timing then out.println(s"Tracetime: $millis ms")

  /** The camera configuration: the scene's camera with the command line's overrides (cli.md). */
  def cameraConfig(scene: Scene, options: Options): CameraConfig =
    val camera = scene.camera
    val size   = Resolution.resolve(
      options.width,
      options.height,
      options.columns,
      options.rows,
      camera.width,
      camera.height
    )
    CameraConfig(
      zoom = options.zoom.getOrElse(camera.zoom),
      width = size.width,
      height = size.height,
      columns = size.columns,
      rows = size.rows,
      depth = options.depth,
      mode = if options.quick then ShadingMode.Quick else ShadingMode.Full,
      samples = options.samples
    )

  /** Refuses a picture whose pixels cannot fit in this JVM's memory, before any is rendered. */
  private def fitsInMemory(config: CameraConfig): Either[String, Unit] =
    val (x, y) = (config.columns, config.rows)
    Bitmap.checkSize(x, y).left.map(why => s"image too large: $why").flatMap { _ =>
      // The rows and the stacked image: 6 bytes a pixel each, with room to spare for the rest.
      val needed    = 3L * x * y * 2 * 2 + (64L << 20)
      val available = Runtime.getRuntime.maxMemory
      if needed <= available then Right(())
      else
        Left(
          s"image too large for memory: ${x}x$y needs about ${needed >> 20} MiB, at most ${available >> 20} MiB available"
        )
    }

  /** Runs `body`, returning its result and its wall time in whole milliseconds. */
  private def timed[A](body: => A): (A, Long) =
    val start  = System.nanoTime
    val result = body
    (result, (System.nanoTime - start) / 1000000)

  private def withProgress[A](err: PrintStream, rows: Int)(body: (() => Unit) => A): A =
    Progress.start(err, rows) match
      case None           => body(() => ())
      case Some(progress) =>
        try body(() => progress.rowDone())
        finally progress.finish()
