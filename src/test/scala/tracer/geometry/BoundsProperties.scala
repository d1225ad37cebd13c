package tracer.geometry

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.Vec3
import tracer.testkit.Generators.*

/** [[Bounds.of]] holds every point a ray can hit, and leaves out only unbounded shapes. */
class BoundsProperties extends ScalaCheckSuite:

  private val small               = Gen.choose(-10.0, 10.0)
  private val point               = for x <- small; y <- small; z <- small yield Vec3(x, y, z)
  private val bounded: Gen[Shape] = Gen.oneOf(
    for c <- point; r <- Gen.choose(0.05, 4.0) yield Sphere(c, r),
    Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _))
  )

  /** The box grown by a hair, for hit points computed in floating point. */
  private def near(b: Bounds, p: Vec3): Boolean =
    val e = 1e-9 * (1 + b.hi.length + b.lo.length)
    Bounds(b.lo - Vec3(e, e, e), b.hi + Vec3(e, e, e)).contains(p)

  property("every hit of a bounded shape lies in its bounds"):
    forAll(bounded, point, unitVec) { (shape, origin, direction) =>
      val ray = Ray(origin * 2, direction)
      val t   = Shape.distance(shape, ray)
      Bounds.of(shape).isDefined &&
      (t == Double.PositiveInfinity || near(Bounds.of(shape).get, ray.at(t)))
    }

  test("a plane has no bounds"):
    assertEquals(Bounds.of(Plane.at(Vec3.UnitY, 1)), None)

  test("a sphere's bounds are its centre ± its radius on each axis"):
    assertEquals(
      Bounds.of(Sphere(Vec3(1, 2, 3), 2)),
      Some(Bounds(Vec3(-1, 0, 1), Vec3(3, 4, 5)))
    )

  test("the union of two boxes holds both"):
    val u = Bounds(Vec3(0, 0, 0), Vec3(1, 1, 1)).union(Bounds(Vec3(-1, 2, 0), Vec3(0, 3, 0.5)))
    assertEquals(u, Bounds(Vec3(-1, 0, 0), Vec3(1, 3, 1)))
