package tracer.cli

import java.io.{FileDescriptor, FileInputStream, InputStream, PrintStream}
import java.nio.file.{Files, Path}
import scala.util.control.NonFatal
import tracer.image.{Bitmap, ImageFile, ImageFormat, PngStream}
import tracer.io.{Images, OutputFile, SceneSources}
import tracer.render.{CameraConfig, Film, Integrator, Renderer, SamplerKind, ShadingMode}
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

  /** Runs the command and exits with its status.
    *
    * With `-Dtracer.exit=halt` (the launcher's, when its own JVM options are used) the JVM halts
    * once both streams are flushed, instead of exiting: from JDK 21 an exit first looks up a
    * system logger for its debug message, which loads the JDK's logging and looks for its
    * providers on the class path, 15–20 ms of every run (docs/performance.md, round 23). A halt
    * skips the shutdown hooks, so it is only for a JVM that has none left to run: the tracer's own
    * (a partial output's removal) are gone once its files are written, and with
    * `TRACER_JAVA_OPTS` (a flight recording, an agent) the launcher leaves the property out.
    */
  def main(args: Array[String]): Unit =
    // Perf: standard input unbuffered, so a scene file given with `<` is read in one piece of its
    // own size (FileInputStream.readAllBytes) rather than grown chunk by chunk.
    val in     = FileInputStream(FileDescriptor.in)
    val status =
      run(
        args.toSeq,
        in,
        System.out,
        System.err,
        Path.of("").toAbsolutePath,
        Progress.isTerminal(0)
      )
    System.out.flush()
    System.err.flush()
    if sys.props.get("tracer.exit").contains("halt") then Runtime.getRuntime.halt(status)
    else sys.exit(status)

  /** Runs the command on the given streams, with relative paths resolved against `cwd`, and
    * returns the exit status. Every failure is one line on `err`, prefixed `tracer: `. With
    * `typed` (standard input is a terminal), a scene read from `in` is announced on `err` first,
    * so that a forgotten `-i` does not wait in silence.
    */
  def run(
      args: Seq[String],
      in: InputStream,
      out: PrintStream,
      err: PrintStream,
      cwd: Path,
      typed: Boolean = false
  ): Int =
    def fail(status: Int, message: String): Int =
      err.println(s"tracer: $message")
      status
    try
      Options.parse(args) match
        case Command.Help(usage) =>
          out.println(usage)
          out.println(s"\n${Options.javaLine}")
          Success
        case Command.Version(line) =>
          out.println(line)
          Success
        case Command.Stack(bands, output) =>
          Stack
            .sameKind(bands, output)
            .fold(
              why => fail(UsageError, s"$why (see tracer --help)"),
              _ => Stack.write(bands, output, cwd).fold(fail(Failure, _), _ => Success)
            )
        case Command.UsageError(message) => fail(UsageError, s"$message (see tracer --help)")
        case Command.Render(options)     =>
          render(options, in, err, cwd, typed = typed).fold(
            p => fail(p.status, p.message),
            millis =>
              if options.timing then out.println(s"Tracetime: $millis ms")
              Success
          )
        case Command.Batch(options, list) =>
          batch(options, list, in, out, err, cwd).fold(fail(Failure, _), identity)
        case Command.Size(options) =>
          val size =
            Inputs.scene(options, in, err, cwd, typed = typed).map(cameraConfig(_, options))
          size.fold(
            fail(Failure, _),
            c =>
              out.println(s"${c.columns} ${c.rows}"); Success
          )
    catch
      case _: OutOfMemoryError =>
        fail(Failure, "out of memory: try a smaller image or more heap (-Xmx)")
      case _: StackOverflowError =>
        fail(Failure, "the scene nests its elements too deeply to read (the stack overflowed)")
      case NonFatal(e) => fail(Failure, s"internal error: $e")

  /** Why a run failed: the exit status and the message. */
  private final case class Problem(status: Int, message: String)

  /** Renders the picture `options` ask for and returns the rendering time in milliseconds. */
  private def render(
      options: Options,
      in: InputStream,
      err: PrintStream,
      cwd: Path,
      reuse: Option[SceneSources.Reuse] = None,
      typed: Boolean = false
  ): Either[Problem, Long] =
    def failure(message: String) = Problem(Failure, message)
    val output                   = cwd.resolve(options.output)
    val format                   = ImageFile.formatFor(output.getFileName.toString)
    for
      _     <- floatWithoutEncoding(options, format)
      _     <- notTheScene(options, output, cwd)
      _     <- OutputFile.checkWritable(output).left.map(failure)
      scene <- Inputs.scene(options, in, err, cwd, reuse, typed).left.map(failure)
      config = cameraConfig(scene, options)
      band <- rowsToRender(options.band, config.rows)
      _    <- fitsInMemory(config.columns, band.size).left.map(failure)
      threads         = options.threads.getOrElse(Renderer.defaultThreads)
      (drawn, millis) = timed(
        withProgress(err, band.size)(onRow => draw(scene, config, threads, onRow, band, format))
      )
      _ <- drawn.save(output).left.map(failure)
    yield renderMillis(millis, drawn.encodingNanos, threads)

  /** The render's time for `-t`, in whole milliseconds: the draw's wall time less the threads'
    * share of the time they spent encoding its file meanwhile (`encodingNanos`, summed over the
    * `threads`), since the specification leaves the writing out; never below 0.
    */
  private[cli] def renderMillis(wallMillis: Long, encodingNanos: Long, threads: Int): Long =
    Math.max(0L, wallMillis - encodingNanos / threads / 1000000)

  /** A rendered picture: how to save it, and how long the render's threads spent encoding its
    * file while they rendered (nanoseconds, summed over the threads), which the render's time
    * leaves out.
    */
  private final class Drawn(val save: Path => Either[String, Unit], val encodingNanos: Long = 0)

  /** Renders the picture for a file of `format` and returns how to save it: a `.pfm` or `.exr`
    * holds the linear values; the 8-bit formats the range rule and `-g`, and a PNG's bands are
    * deflated while the render goes on ([[PngStream]]), so little of it is left to do after (the
    * time its threads spent on them is returned too, for `-t`).
    */
  private def draw(
      scene: Scene,
      config: CameraConfig,
      threads: Int,
      onRow: () => Unit,
      band: Range,
      format: ImageFormat
  ): Drawn =
    format match
      case ImageFormat.Pfm | ImageFormat.Exr =>
        val raster = Renderer.renderRaster(scene, config, threads, onRow, band)
        Drawn(Images.save(raster, _))
      case ImageFormat.Png =>
        val picture                             = Bitmap.Builder(config.columns, band.size)
        val png                                 = PngStream(picture)
        def rowsDone(at: Int, count: Int): Unit =
          (0 until count).foreach(_ => onRow())
          png.rowsDone(at, count)
        Renderer.renderInto(scene, config, picture, threads, rowsDone, band)
        Drawn(Images.save(png, _, threads), png.encodingNanos)
      case ImageFormat.Ppm =>
        val bitmap = Renderer.render(scene, config, threads, onRow, band)
        Drawn(Images.save(bitmap, _, threads))

  /** Refuses an output file that is the `-i` scene file itself, which the picture would replace. */
  private def notTheScene(options: Options, output: Path, cwd: Path): Either[Problem, Unit] =
    def same(scene: Path) =
      try Files.exists(output) && Files.isSameFile(scene, output)
      catch case _: java.io.IOException => false // an unreadable pair: the reads will say why
    options.input.filter(_.nonEmpty).map(cwd.resolve) match
      case Some(scene) if same(scene) =>
        Left(
          Problem(
            UsageError,
            s"the output ${options.output} is the scene file itself: give the picture another name"
          )
        )
      case _ => Right(())

  /** Refuses `-g` (any value, even 1) with a floating-point output: `.pfm` and `.exr` hold the
    * linear values, which no encoding touches.
    */
  private def floatWithoutEncoding(options: Options, format: ImageFormat): Either[Problem, Unit] =
    if format.isFloat && options.encodingGiven then
      Left(
        Problem(
          UsageError,
          s"-g encodes 8-bit output only: ${options.output} holds linear floats (see tracer --help)"
        )
      )
    else Right(())

  /** Renders every frame of the batch list `list` in this one process, each as `-i SCENE OUTPUT`
    * (with `-R a:b` when its line gives rows) and `options`, then the line's own options; with
    * `-t`, prints
    * `Tracetime: N ms OUTPUT` for each. A frame that fails is
    * reported as `tracer: SCENE: why` and the others go on; the status is 1 if any failed. A
    * texture or mesh file that the frame before also used is not read again while it is unchanged
    * ([[tracer.io.FileReuse]]).
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
      Inputs.read(cwd.resolve(list), s"batch list $list").map(String(_, "UTF-8"))
    for
      source <- text
      frames <- Batch.parse(source).left.map(why => s"batch list $list: $why")
    yield
      val reuse  = SceneSources.Reuse()
      val failed = frames.count { frame =>
        reuse.nextFrame()
        val placed = options.copy(
          input = Some(frame.scene),
          output = frame.output,
          band = frame.band.orElse(options.band)
        )
        val one =
          if frame.options.isEmpty then Right(placed)
          else
            Options
              .forFrame(placed, frame.options)
              .left
              .map(why => Problem(UsageError, s"line ${frame.line}: $why"))
        one.flatMap(render(_, in, err, cwd, Some(reuse))) match
          case Right(millis) =>
            if options.timing then out.println(s"Tracetime: $millis ms ${frame.output}")
            false
          case Left(problem) =>
            // The frame's scene named once: a scene error names it already.
            val named =
              if problem.message.startsWith(s"${frame.scene}: ") then problem.message
              else s"${frame.scene}: ${problem.message}"
            err.println(s"tracer: $named")
            true
      }
      if failed == 0 then Success else Failure

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
    val integrator =
      if options.pathMode then
        Integrator.Path(
          options.pathSamples.getOrElse(Integrator.DefaultPathSamples),
          options.seed.getOrElse(0),
          options.sampler.getOrElse(SamplerKind.Default)
        )
      else
        Integrator.Whitted(
          if options.quick then ShadingMode.Quick else ShadingMode.Full,
          options.samples
        )
    CameraConfig(
      Film(options.zoom.getOrElse(camera.zoom), size.width, size.height, size.columns, size.rows),
      integrator,
      options.depth,
      options.encoding
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
