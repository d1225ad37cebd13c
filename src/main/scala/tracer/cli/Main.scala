package tracer.cli

import java.io.{IOException, InputStream, PrintStream}
import java.nio.file.{Files, Path}
import scala.util.control.NonFatal
import tracer.image.Bitmap
import tracer.io.{Images, OutputFile, SceneSources, SceneXml, TextureFiles}
import tracer.render.{CameraConfig, Renderer, ShadingMode}
import tracer.scene.Scene

/** The `tracer` command: `tracer [options] OUTPUT < scene.xml` or `tracer -i scene.xml OUTPUT`
  * (docs/cli.md).
  */
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
        case Command.Version(line) =>
          out.println(line)
          Success
        case Command.Stack(bands, output) =>
          stack(bands, output, cwd).fold(fail(Failure, _), _ => Success)
        case Command.UsageError(message) => fail(UsageError, s"$message (see tracer --help)")
        case Command.Render(options)     =>
          render(options, in, err, cwd).fold(
            p => fail(p.status, p.message),
            millis =>
              if options.timing then out.println(s"Tracetime: $millis ms")
              Success
          )
        case Command.Batch(options, list) =>
          batch(options, list, in, out, err, cwd).fold(fail(Failure, _), identity)
        case Command.Size(options) =>
          val size = scene(options, in, err, cwd).map(cameraConfig(_, options))
          size.fold(
            fail(Failure, _),
            c =>
              out.println(s"${c.columns} ${c.rows}"); Success
          )
    catch
      case _: OutOfMemoryError =>
        fail(Failure, "out of memory: try a smaller image or more heap (-Xmx)")
      case NonFatal(e) => fail(Failure, s"internal error: $e")

  /** Why a run failed: the exit status and the message. */
  private final case class Problem(status: Int, message: String)

  /** Renders the picture `options` ask for and returns the rendering time in milliseconds. */
  private def render(
      options: Options,
      in: InputStream,
      err: PrintStream,
      cwd: Path
  ): Either[Problem, Long] =
    def failure(message: String) = Problem(Failure, message)
    val output                   = cwd.resolve(options.output)
    for
      _     <- OutputFile.checkWritable(output).left.map(failure)
      scene <- scene(options, in, err, cwd).left.map(failure)
      config = cameraConfig(scene, options)
      band <- rowsToRender(options.band, config.rows)
      _    <- fitsInMemory(config.columns, band.size).left.map(failure)
      threads         = options.threads.getOrElse(Renderer.defaultThreads)
      (image, millis) = timed(
        withProgress(err, band.size)(Renderer.render(scene, config, threads, _, band))
      )
      _ <- Images.save(image, output).left.map(failure)
    yield millis

  /** Renders every frame of the batch list `list` in this one process, each as `-i SCENE OUTPUT`
    * with `options`; with `-t`, prints `Tracetime: N ms OUTPUT` for each. A frame that fails is
    * reported as `tracer: SCENE: why` and the others go on; the status is 1 if any failed.
    */
  private def batch(
      options: Options,
      list: String,
      in: InputStream,
      out: PrintStream,
      err: PrintStream,
      cwd: Path
  ): Either[String, Int] =
    val text =
      try Right(Files.readString(cwd.resolve(list)))
      catch
        case _: java.nio.file.NoSuchFileException =>
          Left(s"cannot read batch list $list: no such file")
        case e: IOException => Left(s"cannot read batch list $list: ${e.getMessage}")
    for
      source <- text
      frames <- Batch.parse(source).left.map(why => s"batch list $list: $why")
    yield
      val failed = frames.count { frame =>
        render(options.copy(input = Some(frame.scene), output = frame.output), in, err, cwd) match
          case Right(millis) =>
            if options.timing then out.println(s"Tracetime: $millis ms ${frame.output}")
            false
          case Left(problem) =>
            err.println(s"tracer: ${frame.scene}: ${problem.message}")
            true
      }
      if failed == 0 then Success else Failure

  /** The scene, from `-i FILE` or standard input, with its textures and meshes; warnings to `err`. */
  private def scene(
      options: Options,
      in: InputStream,
      err: PrintStream,
      cwd: Path
  ): Either[String, Scene] =
    sceneBytes(options.input, in, cwd).flatMap { (bytes, where) =>
      SceneXml
        .parse(bytes, SceneSources.files(where, w => err.println(s"tracer: warning: $w")))
        .left
        .map(e => s"scene: ${e.describe}")
    }

  /** Writes `output` as the images `bands`, read in order, one below the other (`--stack`). */
  private def stack(bands: List[String], output: String, cwd: Path): Either[String, Unit] =
    val target = cwd.resolve(output)
    for
      _      <- OutputFile.checkWritable(target)
      images <- bands.foldLeft[Either[String, List[Bitmap]]](Right(Nil)) { (done, name) =>
        done.flatMap(list =>
          TextureFiles.read(cwd.resolve(name)) match
            case Right(image) => Right(image :: list)
            case Left(why)    => Left(s"--stack: cannot read $name: $why")
        )
      }
      joined <- images.reverse match
        case first :: rest
            if rest.forall(b => b.width == first.width && b.maxval == first.maxval) =>
          Right(Bitmap.stack(first :: rest))
        case _ => Left(s"--stack: the images ${bands.mkString(", ")} differ in width or depth")
      _ <- Images.save(joined, target)
    yield ()

  /** The scene's bytes and the directory its relative paths resolve against: FILE's own
    * directory with `-i FILE`, else standard input and the working directory.
    */
  private def sceneBytes(
      input: Option[String],
      in: InputStream,
      cwd: Path
  ): Either[String, (Array[Byte], Path)] =
    input match
      case None       => Right((in.readAllBytes(), cwd))
      case Some(name) =>
        val file = cwd.resolve(name)
        try
          if Files.isDirectory(file) then Left(s"cannot read scene file $name: it is a directory")
          else Right((Files.readAllBytes(file), file.toAbsolutePath.getParent))
        catch
          case _: java.nio.file.NoSuchFileException =>
            Left(s"cannot read scene file $name: no such file")
          case e: IOException => Left(s"cannot read scene file $name: ${e.getMessage}")

  /** The rows `-R` asks for, which must lie inside the picture's `rows`; all rows without it. */
  private def rowsToRender(band: Option[Range], rows: Int): Either[Problem, Range] =
    band match
      case None                     => Right(0 until rows)
      case Some(b) if b.end <= rows => Right(b)
      case Some(b)                  =>
        Left(
          Problem(
            UsageError,
            s"-R ${b.start}:${b.end} reaches past the picture's $rows rows (see tracer --help)"
          )
        )

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
      samples = options.samples,
      encoding = options.encoding
    )

  /** Refuses a picture whose pixels cannot fit in this JVM's memory, before any is rendered. */
  private def fitsInMemory(x: Int, y: Int): Either[String, Unit] =
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
