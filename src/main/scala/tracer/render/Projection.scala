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
    val p = corner + right * (rx * x) + down * (ry * y)
    Ray(camera.location, (p - camera.location).normalisedOr(forward))

  /** The unit right, down and forward directions of the picture (Cr, Cd, c). */
  def basis: (Vec3, Vec3, Vec3) = (right, down, forward)
