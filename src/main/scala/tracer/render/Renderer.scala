package tracer.render

import java.util.concurrent.{Executors, ThreadFactory}
import scala.concurrent.duration.Duration
import scala.concurrent.{Await, ExecutionContext, Future}
import tracer.image.{Bitmap, ByteLevels, Colour, Encoding, PixelWriter, Raster}
import tracer.render.path.PathTracer
import tracer.scene.Scene

/** Turns a scene into a picture: a pure function of the scene and the camera configuration. */
object Renderer:

  /** The thread count used when none is given: the machine's available processors. */
  def defaultThreads: Int = Runtime.getRuntime.availableProcessors

  /** Renders `scene` as `config` says, on a fixed pool of `threads` threads, a few rows a task
    * ([[Tiles]]).
    *
    * The picture depends only on `scene` and `config`, never on `threads`. `band` chooses the
    * rows to render (the `-R a:b` option), by default all: the result is those rows of the whole
    * picture, pixel for pixel. `onRow` is called once for every finished row, from the worker
    * threads (for progress reports).
    */
  def render(
      scene: Scene,
      config: CameraConfig,
      threads: Int = defaultThreads,
      onRow: () => Unit = () => (),
      band: Range = Range(0, Int.MaxValue)
  ): Bitmap =
    inRows(scene, config, threads, everyRow(onRow), band)((w, h) => Bitmap.byRows(w, h)(_))(
      _.rows
    )

  /** Renders `scene` as [[render]] does, into `picture` (as many columns as the camera's
    * picture, and as many rows as `band` holds of it), and calls `onRows(at, count)` from the
    * worker threads each time rows `at` until `at + count` of `picture` are stored (each row
    * once): a PNG's bands can be encoded as the render goes on ([[tracer.image.PngStream]]).
    */
  def renderInto(
      scene: Scene,
      config: CameraConfig,
      picture: Bitmap.Builder,
      threads: Int = defaultThreads,
      onRows: (Int, Int) => Unit = (_, _) => (),
      band: Range = Range(0, Int.MaxValue)
  ): Unit =
    inRows(scene, config, threads, onRows, band) { (w, h) => fill =>
      require(
        picture.width == w && picture.height == h,
        s"the picture is ${picture.width}×${picture.height}, the render's rows ${w}×$h"
      )
      fill(picture)
    }(_.rows)

  /** Renders `scene` as [[render]] does, into linear floating-point pixels for a `.pfm` or `.exr`
    * file: each pixel the mean of its samples as they are, neither brought into range nor encoded
    * (`config.encoding` is not used). Same threads, band and row reports as [[render]].
    */
  def renderRaster(
      scene: Scene,
      config: CameraConfig,
      threads: Int = defaultThreads,
      onRow: () => Unit = () => (),
      band: Range = Range(0, Int.MaxValue)
  ): Raster =
    inRows(scene, config, threads, everyRow(onRow), band)((w, h) => Raster.byRows(w, h)(_))(
      _.linearRows
    )

  /** `onRow` called once for each of the `count` rows a task reports. */
  private def everyRow(onRow: () => Unit): (Int, Int) => Unit = (_, count) =>
    (0 until count).foreach(_ => onRow())

  /** The rows of `band` of the picture, a few a task ([[Tiles.rowsPerTask]]) on a fixed pool of
    * `threads` threads, each task's written by `rows` of the frame straight into the image that
    * `image` builds (a [[Bitmap]] or a [[Raster]], both filled row by row), then reported to
    * `onRows` (the first of the image's rows the task wrote, and how many).
    */
  private def inRows[A](
      scene: Scene,
      config: CameraConfig,
      threads: Int,
      onRows: (Int, Int) => Unit,
      band: Range
  )(image: (Int, Int) => (PixelWriter => Unit) => A)(rows: Frame => RowsWriter): A =
    require(threads >= 1, s"threads must be at least 1, got $threads")
    val first = Math.max(0, band.start)
    val end   = Math.min(config.rows, band.end)
    require(first < end, s"the band $band holds no rows of a picture ${config.rows} rows high")
    val height = Tiles.rowsPerTask(end - first, threads)
    val pool   = Executors.newFixedThreadPool(threads, WorkerThreads)
    try
      given context: ExecutionContext = ExecutionContext.fromExecutorService(pool)
      // The world is built on the same threads (a large mesh's tree in parallel).
      val write = rows(Frame(scene, config, Some(context)))
      // A queue of many small tasks keeps every thread busy however uneven the rows are; each
      // writes its rows straight into the picture (no row images to stack afterwards).
      image(config.columns, end - first) { store =>
        val done = Future.traverse(first until end by height) { y =>
          Future(RowFailure.guard {
            WorkerThreads.lowerForRows()
            val count = Math.min(height, end - y)
            write(y - first, y, count, store)
            onRows(y - first, count)
          })
        }
        Await.result(done, Duration.Inf): Unit
      }
    // Why: rethrows the fatal error a row task carried out (RowFailure), as on this thread.
    catch case RowFailure(cause) => throw cause
    finally pool.shutdownNow(): Unit

  /** A frame's writer of a task's rows: rows `y` until `y + count` of the picture (the second
    * and third numbers) stored as rows from `at` (the first) through the image's [[PixelWriter]]
    * (from [[Bitmap.byRows]] or [[Raster.byRows]]).
    */
  private type RowsWriter = (Int, Int, Int, PixelWriter) => Unit

  /** Renders `scene` on the calling thread alone, a row at a time from left to right (the plain
    * order, which the tests compare [[render]]'s tiles with).
    */
  def renderSequential(scene: Scene, config: CameraConfig): Bitmap =
    val frame = Frame(scene, config)
    Bitmap.byRows(config.columns, config.rows)(out =>
      (0 until config.rows).foreach(y => frame.rows(y, y, 1, out))
    )

  /** Where a pixel's n × n samples lie along each axis, from its top left corner in pixel units:
    * (i + 0.5)/n for 0 ≤ i < n, so n = 1 is the pixel's centre (rendering.md, Antialiasing).
    */
  def sampleOffsets(n: Int): IndexedSeq[Double] = (0 until n).map(i => (i + 0.5) / n)

  /** The parts of a picture that every row shares, built once: the camera, the world, and the
    * integrator's own precomputation.
    */
  private abstract class Frame:
    /** Rows `y` until `y + count` of the picture, written as rows from `at` through `out` (from
      * [[Bitmap.byRows]]), a tile at a time ([[Tiles.foreach]], [[Tiles.runs]]).
      */
    def rows(at: Int, y: Int, count: Int, out: PixelWriter): Unit

    /** The rows as [[rows]] writes them, for floating-point output: unclamped means, not
      * encoded.
      */
    def linearRows(at: Int, y: Int, count: Int, out: PixelWriter): Unit

  private object Frame:
    /** The frame of `config`'s integrator. */
    def apply(
        scene: Scene,
        config: CameraConfig,
        pool: Option[ExecutionContext] = None
    ): Frame =
      val projection = Projection(scene.camera, config.film)
      // Whitted's full mode traces a shadow ray toward each point light from each sample's hit at
      // least, and reflects a sample that meets a mirroring plane: enough to tell World whether
      // its lights' buffers and its camera's mirror images' pay for themselves.
      val fullRays = config.integrator match
        case Integrator.Whitted(ShadingMode.Full, n) => config.columns.toLong * config.rows * n * n
        case _                                       => 0L
      // Every primary ray starts at the camera's location: enough to tell World whether a buffer
      // of the camera's pays for itself.
      val eyeRays = config.integrator match
        case Integrator.Whitted(_, n)  => config.columns.toLong * config.rows * n * n
        case settings: Integrator.Path => config.columns.toLong * config.rows * settings.samples
      // Whitted's quick mode traces the primary rays alone.
      val eyeOnly = config.integrator match
        case Integrator.Whitted(ShadingMode.Quick, _) => true
        case _                                        => false
      val world =
        World(scene, pool, shadowRays = fullRays, eyeRays, mirrorRays = fullRays, eyeOnly = eyeOnly)
      config.integrator match
        case Integrator.Whitted(mode, n) => WhittedFrame(world, projection, config, mode, n)
        case settings: Integrator.Path   =>
          PathFrame(PathTracer(scene, world, projection, settings, config.depth), config)

  /** Whitted's frame: n × n regular samples a pixel. */
  private final class WhittedFrame(
      world: World,
      projection: Projection,
      config: CameraConfig,
      mode: ShadingMode,
      n: Int
  ) extends Frame:
    private val offsets = Renderer.sampleOffsets(n).toArray
    // The clear objects around the camera, which its rays start inside (empty in most scenes).
    private val eyeInsides = world.containing(projection.origin)
    // The 8-bit samples of the encoding, shared by the rows (the picture is a bitmap of maxval
    // 255: Bitmap.byRows).
    private val levels = ByteLevels(config.encoding)

    def rows(at: Int, y: Int, count: Int, out: PixelWriter): Unit =
      val shading = Shading(world, mode)
      // Perf: each pixel a method call (aimed): the loops stay small, so the JIT compiles the
      // pixel once, not the loops on-stack and then again (docs/performance.md, round 9;
      // RenderBench). One sample a pixel: the directions of a tile's row made first
      // (Projection.directions).
      if n == 1 then
        val aims = new Array[Double](3 * Tiles.Width)
        Tiles.runs(config.columns, y, count) { (from, until, row, i) =>
          projection.directions(from, until, row, aims)
          // Why: a counted loop over the run's columns.
          var x = from
          while x < until do
            aimed(shading, x, at + i, out, aims, 3 * (x - from))
            x += 1
        }
      else
        Tiles.foreach(config.columns, y, count)((x, row, i) =>
          sampledEncoded(shading, x, row, at + i, out)
        )

    def linearRows(at: Int, y: Int, count: Int, out: PixelWriter): Unit =
      val shading = Shading(world, mode)
      Tiles.foreach(config.columns, y, count)((x, row, i) => linear(shading, x, row, at + i, out))

    /** The one-sample pixel whose primary ray's direction is at `k` of `aims`, encoded, stored as
      * (x, at) through `out`.
      */
    private def aimed(
        shading: Shading,
        x: Int,
        at: Int,
        out: PixelWriter,
        aims: Array[Double],
        k: Int
    ): Unit =
      val o = projection.origin
      shading.trace(o.x, o.y, o.z, aims(k), aims(k + 1), aims(k + 2), config.depth, eyeInsides)
      store(x, at, out)(shading.r, shading.g, shading.b)

    /** The pixel (x, y) of n × n samples (n > 1), encoded, stored as (x, at) through `out`. */
    private def sampledEncoded(shading: Shading, x: Int, y: Int, at: Int, out: PixelWriter): Unit =
      samples(shading, x, y, inRange = true)((r, g, b) => store(x, at, out)(r, g, b))

    /** Pixel (x, y) of the picture as [[linearRows]] gives it, stored as (x, at) through `out`. */
    private def linear(shading: Shading, x: Int, y: Int, at: Int, out: PixelWriter): Unit =
      if n == 1 then
        centre(shading, x, y)
        out.put(x, at, shading.r, shading.g, shading.b)
      else samples(shading, x, y, inRange = false)((r, g, b) => out.put(x, at, r, g, b))

    /** Traces the primary ray through the centre of pixel (x, y), its colour left in `shading`'s
      * r, g and b (inline: the one-sample pixel's methods stay without a call or a loop).
      */
    private inline def centre(shading: Shading, x: Int, y: Int): Unit =
      val o = projection.origin
      projection.direction(x + 0.5, y + 0.5)((dx, dy, dz) =>
        shading.trace(o.x, o.y, o.z, dx, dy, dz, config.depth, eyeInsides)
      )

    /** Stores the pixel (r, g, b) as (x, at) through `out`, encoded as the picture's encoding
      * says.
      */
    private inline def store(x: Int, at: Int, out: PixelWriter)(
        r: Double,
        g: Double,
        b: Double
    ): Unit =
      config.encoding match
        case Encoding.Linear => out.put(x, at, r, g, b)
        case _               =>
          // Encoding.encode(colour): brought into range, then each channel encoded; the
          // table gives the sample that the bitmap would store of the encoded value.
          Colour.inRangeOf(r, g, b)((r, g, b) =>
            out.put(x, at, levels.encoded(r), levels.encoded(g), levels.encoded(b))
          )

    /** Pixel (x, y) of n × n samples (n > 1), handed to `k` as three doubles: the mean of its
      * samples, each brought into range first when `inRange` (rendering.md: the 8-bit rule), or
      * as they are (floating-point output).
      *
      * Perf: inline with an inline function, the samples' channels summed in locals and each
      * primary ray traced from its six doubles: no Ray or Colour a sample (PrimaryRayBench).
      */
    private inline def samples(shading: Shading, x: Int, y: Int, inRange: Boolean)(
        inline k: (Double, Double, Double) => Unit
    ): Unit =
      val o = projection.origin
      var r = 0.0
      var g = 0.0
      var b = 0.0
      var j = 0
      while j < n do
        var i = 0
        while i < n do
          projection.direction(x + offsets(i), y + offsets(j))((dx, dy, dz) =>
            shading.trace(o.x, o.y, o.z, dx, dy, dz, config.depth, eyeInsides)
          )
          if inRange then
            Colour.inRangeOf(shading.r, shading.g, shading.b) { (sr, sg, sb) =>
              r += sr
              g += sg
              b += sb
            }
          else
            r += shading.r
            g += shading.g
            b += shading.b
          i += 1
        j += 1
      // Colour(r, g, b) / (n * n)
      val samples = (n * n).toDouble
      k(r / samples, g / samples, b / samples)

  /** The path tracer's frame: a pixel is the mean of its samples, brought into range only as a
    * whole for an 8-bit file (an unbiased estimate is never clamped sample by sample).
    */
  private final class PathFrame(tracer: PathTracer, config: CameraConfig) extends Frame:
    def rows(at: Int, y: Int, count: Int, out: PixelWriter): Unit =
      val task = tracer.task()
      Tiles.foreach(config.columns, y, count)((x, row, i) =>
        out.put(x, at + i, config.encoding.encode(task.pixel(x, row).inRange))
      )

    def linearRows(at: Int, y: Int, count: Int, out: PixelWriter): Unit =
      val task = tracer.task()
      Tiles.foreach(config.columns, y, count)((x, row, i) => out.put(x, at + i, task.pixel(x, row)))

  /** Names the worker threads and lets the JVM exit without waiting for them. */
  private object WorkerThreads extends ThreadFactory:
    def newThread(task: Runnable): Thread =
      val thread = Thread(task, "tracer-render")
      thread.setDaemon(true)
      thread

    /** Gives the calling thread the lowest Java priority (once): a row task's, so that while the
      * JIT compiles the render's code its compiler threads come first and the compiled code
      * arrives sooner (the world's build, before the rows, keeps the normal priority).
      *
      * Perf: a Java priority reaches the operating system only where the JVM maps it
      * (`-XX:ThreadPriorityPolicy=1` on Linux, which the launcher passes with the lowest
      * priority mapped to nice 4 and none above nice 0); elsewhere this changes nothing. Whole
      * runs alternating with the commit before: the gallery's showcase 389 → 344 ms, solids 1332
      * → 1287, 720p mesh-20000 920 → 854, mesh-80000 within its noise (docs/performance.md,
      * round 30).
      */
    def lowerForRows(): Unit =
      val thread = Thread.currentThread
      if thread.getPriority != Thread.MIN_PRIORITY then thread.setPriority(Thread.MIN_PRIORITY)

/** Carries a fatal error (such as running out of memory) out of a row task: a Future would
  * otherwise never complete, and the render would wait forever.
  */
private final case class RowFailure(cause: Throwable) extends Exception(cause)

private object RowFailure:
  /** Runs `body`, turning a fatal JVM error into a [[RowFailure]] the Future can carry. */
  inline def guard[A](inline body: A): A =
    // Why: a Future never completes on a fatal error; wrapped, the error fails it instead.
    try body
    catch case e: VirtualMachineError => throw RowFailure(e)
