package tracer.geometry

import tracer.math.Vec3
import tracer.testkit.Approx

/** Ray–shape intersections on hand-made cases: outside, inside, tangent, behind, parallel, edges. */
class ShapeSuite extends munit.FunSuite with Approx:

  private val unitSphere                         = Sphere(Vec3.Zero, 1)
  private def ray(origin: Vec3, direction: Vec3) = Ray(origin, direction.normalised.get)
  private def hit(shape: Shape, r: Ray): Hit     =
    Shape.intersect(shape, r).getOrElse(fail(s"$r missed $shape"))
  private def assertMiss(shape: Shape, r: Ray)(using munit.Location): Unit =
    assertEquals(Shape.distance(shape, r), Double.PositiveInfinity)
    assertEquals(Shape.intersect(shape, r), None)

  test("a ray from outside hits a sphere at its near side, normal outward"):
    val h = hit(unitSphere, ray(Vec3(0, 0, -5), Vec3.UnitZ))
    assertEqualsDouble(h.t, 4.0, 1e-12)
    assertVecClose(h.point, Vec3(0, 0, -1))
    assertVecClose(h.normal, Vec3(0, 0, -1))

  test("a ray from inside hits the far side, normal flipped inward (equation 23)"):
    val h = hit(unitSphere, ray(Vec3(0, 0, 0.5), Vec3.UnitZ))
    assertEqualsDouble(h.t, 0.5, 1e-12)
    assertVecClose(h.point, Vec3(0, 0, 1))
    assertVecClose(h.normal, Vec3(0, 0, -1))

  test("a ray grazing a sphere's edge touches it once"):
    val h = hit(unitSphere, ray(Vec3(1, 0, -5), Vec3.UnitZ))
    assertEqualsDouble(h.t, 5.0, 1e-12)
    assertVecClose(h.normal, Vec3.UnitX)

  test("a ray passing beside a sphere misses"):
    assertMiss(unitSphere, ray(Vec3(1.0001, 0, -5), Vec3.UnitZ))

  test("a sphere behind the ray is missed"):
    assertMiss(unitSphere, ray(Vec3(0, 0, 5), Vec3.UnitZ))

  test("a plane is hit where p · n = D, with the normal facing the ray"):
    val floor     = Plane.through(Vec3(0, -1, 0), Vec3(0, 2, 0))
    val fromAbove = hit(floor, ray(Vec3(0, 1, 0), Vec3(0, -1, 0)))
    assertEqualsDouble(fromAbove.t, 2.0, 1e-12)
    assertVecClose(fromAbove.normal, Vec3.UnitY)
    val fromBelow = hit(floor, ray(Vec3(0, -3, 0), Vec3(0, 1, 1)))
    assertVecClose(fromBelow.point, Vec3(0, -1, 2))
    assertVecClose(fromBelow.normal, -Vec3.UnitY)

  test("the distance form of a plane uses the normalised normal (POV-Ray's form)"):
    val wall = Plane.at(Vec3(0, 0, -2), 20)
    assertVecClose(wall.normal, -Vec3.UnitZ)
    assertVecClose(hit(wall, ray(Vec3.Zero, -Vec3.UnitZ)).point, Vec3(0, 0, -20))

  test("a ray parallel to a plane misses it (vd = 0)"):
    assertMiss(Plane.at(Vec3.UnitY, 0), ray(Vec3(0, 1, 0), Vec3.UnitX))
    assertMiss(Plane.at(Vec3.UnitY, 0), ray(Vec3(0, 0, 0), Vec3.UnitX))

  test("a plane behind the ray is missed"):
    assertMiss(Plane.at(Vec3.UnitY, -1), ray(Vec3.Zero, Vec3.UnitY))

  private val tri                           = Triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0))
  private def towards(x: Double, y: Double) = ray(Vec3(x, y, -1), Vec3.UnitZ)

  test("a ray through a triangle's inside hits it, normal facing the ray"):
    val h = hit(tri, towards(0.25, 0.25))
    assertVecClose(h.point, Vec3(0.25, 0.25, 0))
    assertVecClose(h.normal, -Vec3.UnitZ)
    assertVecClose(hit(tri, ray(Vec3(0.2, 0.2, 1), -Vec3.UnitZ)).normal, Vec3.UnitZ)

  test("edges and corners of a triangle count as hits"):
    for (x, y) <- List((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.5, 0.0), (0.0, 0.5), (0.5, 0.5)) do
      assert(Shape.intersect(tri, towards(x, y)).isDefined, s"($x, $y) missed")

  test("points just outside each edge of a triangle miss"):
    for (x, y) <- List((-1e-9, 0.5), (0.5, -1e-9), (0.5 + 1e-9, 0.5), (1.0 + 1e-9, 0.0)) do
      assertMiss(tri, towards(x, y))

  test("a ray parallel to a triangle's plane misses"):
    assertMiss(tri, ray(Vec3(-1, 0.1, 0), Vec3.UnitX))

  test("a triangle made from legs equals the one made from corners"):
    assertEquals(
      Triangle.fromLegs(Vec3(1, 2, 3), Vec3(1, 0, 0), Vec3(0, 1, 0)),
      Triangle(Vec3(1, 2, 3), Vec3(2, 2, 3), Vec3(1, 3, 3))
    )

  test("collinear corners are not a triangle"):
    assert(!Triangle.isProper(Vec3.Zero, Vec3(1, 1, 1), Vec3(2, 2, 2)))
    intercept[IllegalArgumentException](Triangle(Vec3.Zero, Vec3(1, 1, 1), Vec3(2, 2, 2)))

  test("invalid shapes cannot be built"):
    intercept[IllegalArgumentException](Sphere(Vec3.Zero, 0)): Unit
    intercept[IllegalArgumentException](
      Sphere(Vec3.Zero, 1, pole = Vec3.UnitY, equator = Vec3(0, 1, 1))
    ): Unit
    intercept[IllegalArgumentException](Plane.at(Vec3.Zero, 1))

  test(
    "Shape.hitAt at a t where a general shape has no crossing fails loudly, not with a made-up normal"
  ):
    val box  = Box(Vec3(-1, -1, -1), Vec3(1, 1, 1))
    val miss = Ray(Vec3(5, 5, -5), Vec3.UnitZ)
    assertEquals(Shape.distance(box, miss), Double.PositiveInfinity)
    val e = intercept[IllegalArgumentException](Shape.hitAt(box, miss, 1.0))
    assert(e.getMessage.contains("no crossing"), e.getMessage)
    // With the t that distance gives, the hit is the crossing's.
    val ray = Ray(Vec3(0, 0, -5), Vec3.UnitZ)
    assertEquals(Shape.hitAt(box, ray, Shape.distance(box, ray)).normal, -Vec3.UnitZ)
