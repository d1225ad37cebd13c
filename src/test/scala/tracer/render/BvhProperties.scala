package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{Plane, Ray, Shape, Sphere, Triangle}
import tracer.math.Vec3
import tracer.scene.{Camera, Scene, SceneObject}
import tracer.testkit.Generators.*

/** The accelerated queries of [[World]] agree with testing every shape. */
class BvhProperties extends ScalaCheckSuite:

  private val small = Gen.choose(-10.0, 10.0)
  private val point = for x <- small; y <- small; z <- small yield Vec3(x, y, z)
  // Coordinates on a coarse grid make coincident faces, shared edges and axis-aligned boxes common.
  private val gridPoint = for x <- Gen.choose(-4, 4); y <- Gen.choose(-4, 4); z <- Gen.choose(-4, 4)
  yield Vec3(x, y, z)

  private val shape: Gen[Shape] = Gen.frequency(
    4 -> (for c <- point; r <- Gen.choose(0.05, 2.0) yield Sphere(c, r)),
    4 -> Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _)),
    3 -> Gen
      .zip(gridPoint, gridPoint, gridPoint)
      .retryUntil(Triangle.isProper.tupled)
      .map(Triangle(_, _, _)),
    1 -> (for n <- Gen.oneOf(Vec3.UnitX, Vec3.UnitY, Vec3(1, 1, 0)); d <- Gen.choose(-6, 6)
    yield Plane.at(n, d))
  )

  private val world: Gen[World] =
    Gen.choose(0, 300).flatMap(n => Gen.listOfN(n, shape)).map { shapes =>
      World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = shapes.map(SceneObject(_))))
    }

  /** Rays from anywhere, and axis-aligned rays from grid points (zero direction components). */
  private val ray: Gen[Ray] = Gen.oneOf(
    for o <- point; d <- unitVec yield Ray(o * 2, d),
    for
      o <- gridPoint;
      d <- Gen.oneOf(Vec3.UnitX, -Vec3.UnitY, Vec3.UnitZ, Vec3(0, 1, 1).normalised.get)
    yield Ray(o, d)
  )

  property("nearest finds the shape that testing every shape finds, ties included"):
    forAll(world, Gen.listOfN(50, ray)) { (w, rays) =>
      val query = w.newQuery()
      rays.foreach(r => assertEquals(w.nearest(r, query), w.nearestByBruteForce(r), r.toString))
    }

  property("nearest's distance is Shape.distance of the winner, bit for bit (+∞ for a miss)"):
    forAll(world, Gen.listOfN(50, ray)) { (w, rays) =>
      val query = w.newQuery()
      rays.foreach { r =>
        val i        = w.nearest(r, query)
        val expected = if i < 0 then Double.PositiveInfinity else Shape.distance(w.shape(i), r)
        assertEquals(
          java.lang.Double.doubleToRawLongBits(query.distance),
          java.lang.Double.doubleToRawLongBits(expected),
          r.toString
        )
      }
    }

  property("nearestAlong with a limit finds the nearest hit at t ≤ limit, or none"):
    forAll(world, Gen.listOfN(50, ray), Gen.choose(0.5, 30.0)) { (w, rays, limit) =>
      val query = w.newQuery()
      rays.foreach { r =>
        val i        = w.nearestByBruteForce(r)
        val t        = if i < 0 then Double.PositiveInfinity else Shape.distance(w.shape(i), r)
        val expected = if t <= limit then i else -1
        val o        = r.origin
        val d        = r.direction
        assertEquals(
          w.nearestAlong(o.x, o.y, o.z, d.x, d.y, d.z, limit, query),
          expected,
          r.toString
        )
      }
    }

  test("shapes hit at the same distance: the lowest index wins, wherever they sit in the tree"):
    // Many copies of one triangle and sphere, interleaved: every ray that hits them ties.
    val tile   = Triangle(Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(-1, 0, 1))
    val ball   = Sphere(Vec3(3, 0, 0), 1)
    val shapes = (0 until 40).flatMap(_ => List(ball, tile))
    val w = World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = shapes.map(SceneObject(_))))
    val query = w.newQuery()
    assertEquals(w.nearest(Ray(Vec3(-0.5, 3, -0.5), -Vec3.UnitY), query), 1)
    assertEquals(query.distance, 3.0)
    assertEquals(w.nearest(Ray(Vec3(3, 5, 0), -Vec3.UnitY), query), 0)
    assertEquals(query.distance, 4.0)

  property("occluded agrees with testing every shape"):
    forAll(world, Gen.listOfN(50, ray), Gen.choose(0.5, 30.0)) { (w, rays, limit) =>
      val query = w.newQuery()
      rays.foreach { r =>
        val expected = w.nearestByBruteForce(r) >= 0 && Shape.distance(
          w.shape(w.nearestByBruteForce(r)),
          r
        ) < limit
        assertEquals(w.occluded(r, limit, query), expected, r.toString)
      }
    }

  test("a triangle lying in a plane: the first in document order wins, as without the hierarchy"):
    val floor = Plane.at(Vec3.UnitY, 0)
    val tile  = Triangle(Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(-1, 0, 1))
    val down  = Ray(Vec3(-0.5, 3, -0.5), -Vec3.UnitY)
    for order <- List(List(floor, tile), List(tile, floor)) do
      val w = World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = order.map(SceneObject(_))))
      assertEquals(w.nearest(down, w.newQuery()), 0)

  test("a large grid of spheres builds a tree, not a single leaf"):
    val spheres = for x <- 0 until 20; z <- 0 until 20 yield SceneObject(Sphere(Vec3(x, 0, z), 0.4))
    val w       = World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = spheres))
    val bvh     = Bvh(spheres.map(_.shape))
    assert(bvh.nodeCount > 100, bvh.nodeCount.toString)
    assertEquals(w.nearest(Ray(Vec3(5, 5, 5), -Vec3.UnitY), w.newQuery()), 105)
