package tracer.geometry

import tracer.math.Vec3

/** Texture coordinates on spheres (equations 35–38) and triangles (33–34): poles, seam, corners. */
class SurfaceCoordinatesSuite extends munit.FunSuite:

  private val globe               = Sphere(Vec3(1, 2, 3), 2)
  private def at(direction: Vec3) =
    Shape.surfaceCoordinates(globe, globe.centre + direction.normalised.get * 2)
  // arccos is steep near ±1, so an argument off by one rounding step (1e-16) moves θ by ~1e-8:
  // equation 37 is only that exact where Se · rn / sin φ is close to ±1.
  private def assertUv(obtained: SurfaceCoordinates, u: Double, v: Double)(using
      munit.Location
  ): Unit =
    assertEqualsDouble(obtained.u, u, 1e-7, s"u of $obtained")
    assertEqualsDouble(obtained.v, v, 1e-7, s"v of $obtained")

  test("the north pole is v = 1 (the image's top) and u = 0"):
    assertUv(at(Vec3.UnitY), 0, 1)

  test("the south pole is v = 0 and u = 0"):
    assertUv(at(-Vec3.UnitY), 0, 0)

  test("the point facing a camera on −z is the centre column, halfway up"):
    assertUv(at(-Vec3.UnitZ), 0.5, 0.5)

  test("the equator direction is the seam, u = 1 there (θ = 0, on the ≤ 0 side)"):
    assertUv(at(Vec3.UnitZ), 1, 0.5)

  test("seen from −z, u grows to the right: the texture is not mirrored"):
    val right = at(Vec3(0.5, 0, -1))
    val left  = at(Vec3(-0.5, 0, -1))
    assert(right.u > 0.5 && left.u < 0.5, s"left $left, right $right")
    assertUv(at(Vec3.UnitX), 0.75, 0.5)
    assertUv(at(-Vec3.UnitX), 0.25, 0.5)

  test("v grows towards the pole"):
    assertUv(at(Vec3(0, 1, -1)), 0.5, 0.75)

  test("pole and equator turn the mapping"):
    val turned = Sphere(Vec3.Zero, 1, pole = Vec3.UnitZ, equator = Vec3.UnitX)
    assertUv(Shape.surfaceCoordinates(turned, Vec3.UnitZ), 0, 1)
    assertUv(Shape.surfaceCoordinates(turned, -Vec3.UnitX), 0.5, 0.5)

  test("rounding near the poles never gives NaN (arccos arguments are clamped)"):
    val near = Shape.surfaceCoordinates(globe, globe.centre + Vec3(1e-17, 2, 1e-17))
    assert(!near.u.isNaN && !near.v.isNaN, near.toString)

  private val tri = Triangle(Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(1, 4, 0))

  test("a triangle's corners are (0, 0), (1, 0) and (0, 1)"):
    assertUv(Shape.surfaceCoordinates(tri, tri.t0), 0, 0)
    assertUv(Shape.surfaceCoordinates(tri, tri.t1), 1, 0)
    assertUv(Shape.surfaceCoordinates(tri, tri.t2), 0, 1)

  test("a point of a triangle is u·a + v·b from the origin corner"):
    assertUv(Shape.surfaceCoordinates(tri, tri.t0 + tri.a * 0.25 + tri.b * 0.5), 0.25, 0.5)
