package tracer.render

import tracer.image.Encoding
import tracer.scene.{Camera, Scene}

/** How shading is done: the full Whitted model, or the quick preview of `-q`. */
enum ShadingMode:
  /** Lights, hard shadows and recursive reflection (rendering.md, full mode). */
  case Full

  /** One white light at the eye: no shadows, no reflection, no diffuse factor. */
  case Quick

/** Everything besides the scene that decides a picture's pixels.
  *
  * @param zoom      Z, the distance from the eye to the image plane, > 0
  * @param width     W, the image plane's width in world units, > 0
  * @param height    H, the image plane's height in world units, > 0
  * @param columns   X, the image width in pixels, ≥ 1
  * @param rows      Y, the image height in pixels, ≥ 1
  * @param depth     the most reflections a ray may make, ≥ 0
  * @param mode      full or quick shading
  * @param samples   n, for n × n samples a pixel (antialiasing), 1 to [[CameraConfig.MaxSamples]]
  * @param encoding  how a pixel's colour is encoded for the file (`-g`)
  */
final case class CameraConfig(
    zoom: Double,
    width: Double,
    height: Double,
    columns: Int,
    rows: Int,
    depth: Int = CameraConfig.DefaultDepth,
    mode: ShadingMode = ShadingMode.Full,
    samples: Int = 1,
    encoding: Encoding = Encoding.Linear
):
  require(zoom > 0 && width > 0 && height > 0, "zoom, width and height must be positive")
  require(columns >= 1 && rows >= 1, s"the image must be at least 1×1 pixels, got ${columns}×$rows")
  require(depth >= 0, s"the reflection depth must be at least 0, got $depth")
  require(
    samples >= 1 && samples <= CameraConfig.MaxSamples,
    s"samples must be 1..${CameraConfig.MaxSamples}, got $samples"
  )

/** Defaults and constructors for [[CameraConfig]]. */
object CameraConfig:
  /** The reflection depth when none is given. */
  val DefaultDepth: Int = 5

  /** The largest antialiasing grid, n in n × n. */
  val MaxSamples: Int = 16

  /** The camera's own Z, W and H at `columns` pixels wide, the height chosen so the picture is
    * not distorted (W/X = H/Y), as the command line does when given only `-x`.
    */
  def forCamera(camera: Camera, columns: Int = 640): CameraConfig =
    val rows = Math.max(1L, Math.round(camera.height * columns / camera.width)).toInt
    CameraConfig(camera.zoom, camera.width, camera.height, columns, rows)

  /** [[forCamera]] for the scene's camera. */
  def forScene(scene: Scene, columns: Int = 640): CameraConfig = forCamera(scene.camera, columns)
