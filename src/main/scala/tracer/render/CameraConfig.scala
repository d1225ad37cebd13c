package tracer.render

import tracer.image.Encoding
import tracer.scene.{Camera, Scene}

/** How shading is done: the full Whitted model, or the quick preview of `-q`. */
enum ShadingMode:
  /** Lights, hard shadows and recursive reflection (rendering.md, full mode). */
  case Full

  /** One white light at the eye: no shadows, no reflection, no diffuse factor. */
  case Quick

/** Where path mode's random numbers come from (`--sampler`, docs/rendering.md, The sampler). */
enum SamplerKind:
  /** Owen-scrambled Sobol points, shuffled per pixel and per dimension: the default. */
  case Sobol

  /** Independent uniform numbers from a counter-based hash. */
  case Independent

/** The sampler names of `--sampler`, and the default. */
object SamplerKind:
  /** The sampler used when none is named. */
  val Default: SamplerKind = SamplerKind.Sobol

  /** The kind a `--sampler` name stands for, if any. */
  def named(name: String): Option[SamplerKind] = values.find(_.name == name)

  extension (kind: SamplerKind)
    /** The name `--sampler` takes for this kind. */
    def name: String = kind.toString.toLowerCase(java.util.Locale.ROOT)

/** The film: the image plane in the world and the pixels it is cut into (course text, section 4).
  *
  * @param zoom    Z, the distance from the eye to the image plane, > 0
  * @param width   W, the image plane's width in world units, > 0
  * @param height  H, the image plane's height in world units, > 0
  * @param columns X, the image width in pixels, ≥ 1
  * @param rows    Y, the image height in pixels, ≥ 1
  */
final case class Film(zoom: Double, width: Double, height: Double, columns: Int, rows: Int):
  require(zoom > 0 && width > 0 && height > 0, "zoom, width and height must be positive")
  require(columns >= 1 && rows >= 1, s"the image must be at least 1×1 pixels, got ${columns}×$rows")

/** How the light arriving through each pixel is computed. */
enum Integrator:
  /** The course's Whitted tracer (versions 1–3): `shading` full or quick, `samples` × `samples`
    * regular samples a pixel (`-a`), 1..16.
    */
  case Whitted(shading: ShadingMode = ShadingMode.Full, samples: Int = 1)

  /** Monte Carlo path tracing (version 4, `-m path`): `samples` random samples a pixel
    * (1..1,048,576), the noise pattern chosen by `seed` (0 ≤ seed < 2³¹) and `sampler`.
    */
  case Path(
      samples: Int = Integrator.DefaultPathSamples,
      seed: Int = 0,
      sampler: SamplerKind = SamplerKind.Sobol
  )

/** Limits and defaults of [[Integrator]]. */
object Integrator:
  /** Path mode's samples a pixel when none are given. */
  val DefaultPathSamples: Int = 64

  /** The most samples a pixel path mode takes. */
  val MaxPathSamples: Int = 1 << 20

/** Everything besides the scene that decides a picture's pixels: the film, the integrator, the
  * depth and the output encoding.
  *
  * @param film       the image plane and its pixels
  * @param integrator Whitted's tracer or the path tracer, with their settings
  * @param depth      Whitted: the most reflections a ray may make; path: the most bounces, ≥ 0
  * @param encoding   how a pixel's colour is encoded for an 8-bit or 16-bit file (`-g`)
  */
final case class CameraConfig(
    film: Film,
    integrator: Integrator,
    depth: Int,
    encoding: Encoding
):
  require(depth >= 0, s"the reflection depth must be at least 0, got $depth")
  integrator match
    case Integrator.Whitted(_, samples) =>
      require(
        samples >= 1 && samples <= CameraConfig.MaxSamples,
        s"samples must be 1..16, got $samples"
      )
    case Integrator.Path(samples, seed, _) =>
      require(
        samples >= 1 && samples <= Integrator.MaxPathSamples,
        s"path samples must be 1..${Integrator.MaxPathSamples}, got $samples"
      )
      require(seed >= 0, s"the seed must be at least 0, got $seed")

  /** X, the image width in pixels. */
  def columns: Int = film.columns

  /** Y, the image height in pixels. */
  def rows: Int = film.rows

  /** This configuration with another integrator. */
  def withIntegrator(other: Integrator): CameraConfig = copy(integrator = other)

/** Defaults and constructors for [[CameraConfig]]. */
object CameraConfig:
  /** The reflection depth when none is given. */
  val DefaultDepth: Int = 5

  /** The largest antialiasing grid, n in n × n. */
  val MaxSamples: Int = 16

  /** A Whitted configuration from the film's five numbers (the form most tests use): `mode` full
    * or quick, `samples` × `samples` a pixel.
    */
  def apply(
      zoom: Double,
      width: Double,
      height: Double,
      columns: Int,
      rows: Int,
      depth: Int = DefaultDepth,
      mode: ShadingMode = ShadingMode.Full,
      samples: Int = 1,
      encoding: Encoding = Encoding.Linear
  ): CameraConfig =
    CameraConfig(
      Film(zoom, width, height, columns, rows),
      Integrator.Whitted(mode, samples),
      depth,
      encoding
    )

  /** The camera's own Z, W and H at `columns` pixels wide, the height chosen so the picture is
    * not distorted (W/X = H/Y), as the command line does when given only `-x`.
    */
  def forCamera(camera: Camera, columns: Int = 640): CameraConfig =
    val rows = Math.max(1L, Math.round(camera.height * columns / camera.width)).toInt
    CameraConfig(camera.zoom, camera.width, camera.height, columns, rows)

  /** [[forCamera]] for the scene's camera. */
  def forScene(scene: Scene, columns: Int = 640): CameraConfig = forCamera(scene.camera, columns)
