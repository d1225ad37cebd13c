package tracer.render

import tracer.math.Vec3
import tracer.scene.Camera
import tracer.testkit.Approx

/** The camera basis and primary rays of equations 10–16. */
class ProjectionSuite extends munit.FunSuite with Approx:

  private val camera = Camera(Vec3(0, 0, -5), Vec3.Zero)
  private def projection(x: Int, y: Int, zoom: Double = 1, w: Double = 1, h: Double = 0.75) =
    Projection(camera, CameraConfig(zoom, w, h, x, y))

  test("looking along +z with the default up, right is +x and down is −y (left-handed)"):
    val (right, down, forward) = projection(4, 3).basis
    assertVecClose(right, Vec3.UnitX)
    assertVecClose(down, -Vec3.UnitY)
    assertVecClose(forward, Vec3.UnitZ)

  test("the up vector need not be normalised nor at right angles to the view"):
    val tilted = Projection(
      Camera(Vec3(0, 0, -5), Vec3.Zero, up = Vec3(0, 7, 3)),
      CameraConfig(1, 1, 0.75, 4, 3)
    )
    assertEquals(tilted.basis, projection(4, 3).basis)

  test("rays start at the eye and have unit length"):
    val r = projection(4, 3).ray(1.5, 2.5)
    assertEquals(r.origin, camera.location)
    assertEqualsDouble(r.direction.length, 1.0, 1e-12)

  test("the ray through the image centre points at lookat"):
    assertVecClose(projection(640, 480).ray(320, 240).direction, Vec3.UnitZ)

  test("pixel (0, 0) is the top left: its centre is half a pixel from the corner Cc (equation 14)"):
    // W = 1, H = 0.75, X = 4, Y = 3: Rx = Ry = 0.25; Cc = (−0.5, 0.375, −4).
    val d = projection(4, 3).ray(0.5, 0.5).direction
    assertVecClose(d, Vec3(-0.375, 0.25, 1).normalised.get)

  test("the last pixel is the bottom right"):
    val d = projection(4, 3).ray(3.5, 2.5).direction
    assertVecClose(d, Vec3(0.375, -0.25, 1).normalised.get)

  test("zoom moves the image plane away from the eye: a narrower view"):
    val d = projection(4, 3, zoom = 2).ray(0.5, 0.5).direction
    assertVecClose(d, Vec3(-0.375, 0.25, 2).normalised.get)

  test("W and H are world units, independent of the pixel counts"):
    assertVecClose(projection(8, 6).ray(0, 0).direction, projection(4, 3).ray(0, 0).direction)
