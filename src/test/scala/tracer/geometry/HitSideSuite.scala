package tracer.geometry

import tracer.math.Vec3

/** Which side of a surface a ray meets ([[Hit.front]]): the outward side of a solid or of a
  * combination, the side a plane's or a triangle's normal faces, and a difference's hole.
  */
class HitSideSuite extends munit.FunSuite:

  private def ray(o: Vec3, d: Vec3)          = Ray(o, d.normalised.get)
  private def hit(shape: Shape, r: Ray): Hit =
    Shape.intersect(shape, r).getOrElse(fail(s"$r missed $shape"))

  test("a sphere met from outside is met on its front; from inside, on its back"):
    val s       = Sphere(Vec3.Zero, 1)
    val outside = hit(s, ray(Vec3(0, 0, -5), Vec3.UnitZ))
    val inside  = hit(s, ray(Vec3.Zero, Vec3.UnitZ))
    assert(outside.front)
    assert(!inside.front)
    assertEquals(outside.outward, Vec3(0, 0, -1))
    assertEquals(inside.outward, Vec3(0, 0, 1))

  test("a plane and a triangle: front on the side their normal faces"):
    val plane    = Plane(Vec3.UnitY, 0)
    val triangle = Triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)) // Pn = a × b = +z
    assert(hit(plane, ray(Vec3(0, 1, 0), -Vec3.UnitY)).front)
    assert(!hit(plane, ray(Vec3(0, -1, 0), Vec3.UnitY)).front)
    assertEquals(triangle.normal, Vec3.UnitZ)
    assert(hit(triangle, ray(Vec3(0.2, 0.2, 1), -Vec3.UnitZ)).front)
    val behind = hit(triangle, ray(Vec3(0.2, 0.2, -1), Vec3.UnitZ))
    assert(!behind.front)
    assertEquals(behind.outward, Vec3.UnitZ)

  test("a box from outside and from inside, through the general path"):
    val box = Box(Vec3(-1, -1, -1), Vec3(1, 1, 1))
    assert(hit(box, ray(Vec3(0, 0, -5), Vec3.UnitZ)).front)
    assert(!hit(box, ray(Vec3.Zero, Vec3.UnitZ)).front)

  test("a difference's hole: the cut face's outward side looks into the hole"):
    // A box less a sphere centred on its +z face: a ray down the hole meets the sphere's
    // surface, which is the inside of the sphere but the outside of the difference.
    val solid = Csg(
      CsgOperation.Difference,
      Vector(Box(Vec3(-1, -1, -1), Vec3(1, 1, 1)), Sphere(Vec3(0, 0, 1), 0.5))
    )
    val h = hit(solid, ray(Vec3(0, 0, 5), -Vec3.UnitZ))
    assertEqualsDouble(h.t, 4.5, 1e-9)
    assert(h.front, h.toString)
    assertEquals(h.leaf, 1)
    assert((h.outward - Vec3.UnitZ).length < 1e-12, h.toString)
