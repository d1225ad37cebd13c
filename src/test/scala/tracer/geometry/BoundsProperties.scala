package tracer.geometry

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.{Placement, Vec3}
import tracer.testkit.Generators.*

/** [[Shape.bounds]] holds every point a ray can hit and leaves out only unbounded shapes, and
  * [[Bounds.of]] and [[Bounds.around]] are the smallest boxes holding their points.
  */
class BoundsProperties extends ScalaCheckSuite:

  private val small               = Gen.choose(-10.0, 10.0)
  private val point               = for x <- small; y <- small; z <- small yield Vec3(x, y, z)
  private val bounded: Gen[Shape] = Gen.oneOf(
    for c <- point; r <- Gen.choose(0.05, 4.0) yield Sphere(c, r),
    Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _)),
    for c <- point; d <- point.retryUntil(d => d.x != c.x && d.y != c.y && d.z != c.z)
    yield Box(c, d),
    for
      a <- point; b <- point.retryUntil(_ != a); r <- Gen.choose(0.0, 3.0);
      q <- Gen.choose(0.05, 3.0)
    yield Cone(a, r, b, q),
    for r <- Gen.choose(0.1, 4.0); m <- Gen.choose(0.05, 3.0); p <- point; angles <- point
    yield Placed(Torus(r, m), Placement(1.5, angles * 20, p)),
    for a <- point; b <- point; op <- Gen.oneOf(CsgOperation.values.toIndexedSeq)
    yield Csg(
      op,
      Vector(Sphere(a, 2), Placed(Box(Vec3.Zero, Vec3(2, 3, 4)), Placement(translate = b)))
    )
  )

  /** The box grown by a hair, for hit points computed in floating point: 1e-7 of the box's size,
    * for every shape alike (placed ones, whose hits come back through a transform, included).
    */
  private def near(b: Bounds, p: Vec3): Boolean =
    val e = 1e-7 * (1 + b.hi.length + b.lo.length)
    Bounds(b.lo - Vec3(e, e, e), b.hi + Vec3(e, e, e)).contains(p)

  property("every hit of a bounded shape lies in its bounds"):
    forAll(bounded, point, unitVec) { (shape, origin, direction) =>
      val ray = Ray(origin * 2, direction)
      val t   = Shape.distance(shape, ray)
      Shape.bounds(shape).exists(b => t == Double.PositiveInfinity || near(b, ray.at(t)))
    }

  property("Bounds.of three points is the smallest box holding them, as Bounds.around"):
    forAll(point, point, point) { (a, b, c) =>
      val box = Bounds.of(a, b, c)
      val all = List(a, b, c)
      // Holds each point, and each of its six faces touches one of them: nothing smaller holds all.
      all.forall(box.contains) && box == Bounds.around(all) &&
      all.exists(_.x == box.lo.x) && all.exists(_.x == box.hi.x) &&
      all.exists(_.y == box.lo.y) && all.exists(_.y == box.hi.y) &&
      all.exists(_.z == box.lo.z) && all.exists(_.z == box.hi.z)
    }

  test("a plane has no bounds"):
    assertEquals(Shape.bounds(Plane.at(Vec3.UnitY, 1)), None)

  test("a sphere's bounds are its centre ± its radius on each axis"):
    assertEquals(
      Shape.bounds(Sphere(Vec3(1, 2, 3), 2)),
      Some(Bounds(Vec3(-1, 0, 1), Vec3(3, 4, 5)))
    )

  test("the union of two boxes holds both"):
    val u = Bounds(Vec3(0, 0, 0), Vec3(1, 1, 1)).union(Bounds(Vec3(-1, 2, 0), Vec3(0, 3, 0.5)))
    assertEquals(u, Bounds(Vec3(-1, 0, 0), Vec3(1, 3, 1)))
