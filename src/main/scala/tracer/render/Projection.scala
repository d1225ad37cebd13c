package tracer.render

import tracer.geometry.Ray
import tracer.math.Vec3
import tracer.scene.Camera

/** The camera's geometry, computed once per picture: the rays through points of the image plane
  * (course text, section 4, equations 8–16).
  */
final class Projection(camera: Camera, film: Film):

  /** The projection of `config`'s film. */
  def this(camera: Camera, config: CameraConfig) = this(camera, config.film)

  // Equation 10: the viewing direction c. Camera's requires (location ≠ lookat, up not parallel
  // to the viewing direction) make it and the next two normalisable: no fallback is ever used.
  private val forward = (camera.lookAt - camera.location).normalisedOr(Vec3.UnitZ)
  // Equations 11–12: the picture's right and down directions Cr and Cd.
  private val right = camera.up.cross(forward).normalisedOr(Vec3.UnitX)
  private val down  = right.cross(forward).normalisedOr(Vec3.UnitY)
  // Equation 13: the upper left corner Cc of the image plane.
  private val corner =
    camera.location + forward * film.zoom - right * (film.width / 2) - down * (film.height / 2)
  // Equations 8–9: the resolution Rx and Ry, world units a pixel.
  private val rx = film.width / film.columns
  private val ry = film.height / film.rows

  /** The primary ray through the image-plane point (x, y) in pixel units: pixel (i, j)'s centre
    * is (i + 0.5, j + 0.5), row 0 at the top (equations 14–16).
    */
  def ray(x: Double, y: Double): Ray =
    direction(x, y)((dx, dy, dz) => Ray(camera.location, Vec3(dx, dy, dz)))

  /** Where every primary ray starts: the camera's location. */
  def origin: Vec3 = camera.location

  /** The unit direction of [[ray]]`(x, y)`, handed to `k` as three doubles.
    *
    * Perf: inline with an inline function, so the renderer's primary ray makes no `Ray` or `Vec3`
    * (PrimaryRayBench: bytes per primary ray); the same operations as the vector form.
    */
  inline def direction[A](x: Double, y: Double)(inline k: (Double, Double, Double) => A): A =
    // p = Cc + Cr·(Rx·x) + Cd·(Ry·y), then (p − location) normalised, else c.
    val vx     = corner.x + right.x * (rx * x) + down.x * (ry * y) - camera.location.x
    val vy     = corner.y + right.y * (rx * x) + down.y * (ry * y) - camera.location.y
    val vz     = corner.z + right.z * (rx * x) + down.z * (ry * y) - camera.location.z
    val length = Math.sqrt(vx * vx + vy * vy + vz * vz)
    val proper = length > 0 && length < Double.PositiveInfinity
    k(
      if proper then vx / length else forward.x,
      if proper then vy / length else forward.y,
      if proper then vz / length else forward.z
    )

  /** Writes the unit direction of the primary ray through the centre of each pixel (x, y), x
    * from `from` until `until`, into `out` from 0, three doubles a pixel: [[direction]]`(x +
    * 0.5, y + 0.5)`.
    *
    * Perf: a direction is a square root and three divisions, which the ray's walk waits on; made
    * for a tile's row at once, in a loop whose turns do not depend on each other, the processor
    * overlaps them (docs/performance.md, round 50).
    */
  def directions(from: Int, until: Int, y: Int, out: Array[Double]): Unit =
    var x = from
    while x < until do
      val at = 3 * (x - from)
      direction(x + 0.5, y + 0.5) { (dx, dy, dz) =>
        out(at) = dx; out(at + 1) = dy; out(at + 2) = dz
      }
      x += 1

  /** The unit right, down and forward directions of the picture (Cr, Cd, c). */
  def basis: (Vec3, Vec3, Vec3) = (right, down, forward)
