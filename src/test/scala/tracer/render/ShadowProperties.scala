package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{Box, Csg, CsgOperation, Plane, Shape, Sphere, Triangle}
import tracer.math.Vec3
import tracer.scene.{Camera, Scene, SceneObject, Surface}
import tracer.testkit.Generators.*

/** [[Shadows.point]] in a world that transmits (the any-hit test where no transmitting object is
  * crossed, else the walk) agrees with the walk over every object it replaced.
  */
class ShadowProperties extends ScalaCheckSuite:

  private val small = Gen.choose(-8.0, 8.0)
  private val point = for x <- small; y <- small; z <- small yield Vec3(x, y, z)
  private val size  = Gen.choose(0.2, 3.0)

  private val sphere: Gen[Shape] = for c <- point; r <- Gen.choose(0.1, 2.5) yield Sphere(c, r)
  private val box: Gen[Shape]    =
    for c <- point; dx <- size; dy <- size; dz <- size yield Box(c, c + Vec3(dx, dy, dz))
  private val triangle: Gen[Shape] =
    Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _))
  private val plane: Gen[Shape] =
    for n <- unitVec; d <- Gen.choose(-9.0, 9.0) yield Plane.at(n, d)

  // Opaque, half-clear and fully clear surfaces, so an object may block, dim or let all through.
  private val surface: Gen[Surface] =
    Gen.oneOf(0.0, 0.0, 0.3, 0.8, 1.0).map(t => Surface(transmit = t))

  private val simple: Gen[SceneObject] =
    for
      s    <- Gen.frequency(4 -> sphere, 3 -> box, 2 -> triangle, 1 -> plane)
      look <- surface
    yield SceneObject(s, look)

  // A combination whose leaves show surfaces of their own: one transmitting leaf makes the whole
  // a transmitting object, whose opaque leaves must still block.
  private val combination: Gen[SceneObject] =
    for
      op    <- Gen.oneOf(CsgOperation.values.toIndexedSeq)
      n     <- Gen.choose(2, 3)
      kids  <- Gen.listOfN(n, Gen.oneOf(sphere, box))
      looks <- Gen.listOfN(n, surface)
      whole <- surface
    yield SceneObject(Csg(op, kids.toVector), whole, looks.toVector)

  private val world: Gen[World] =
    Gen
      .choose(1, 40)
      .flatMap(n => Gen.listOfN(n, Gen.frequency(3 -> simple, 1 -> combination)))
      .map(os => World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = os)))

  private val shadowRay: Gen[(Vec3, Vec3, Double)] =
    for o <- point; d <- unitVec; reach <- Gen.choose(0.5, 30.0) yield (o, d, reach)

  property("the share of a point light is the walk's over every object, bit for bit"):
    forAll(world, Gen.listOfN(60, shadowRay)) { (w, rays) =>
      val shadows = Shadows(w, w.newQuery())
      rays.foreach { case (from, toward, reach) =>
        assertEquals(
          java.lang.Double.doubleToRawLongBits(shadows.point(from, toward, reach)),
          java.lang.Double.doubleToRawLongBits(shadows.walked(from, toward, reach)),
          s"$from $toward $reach"
        )
      }
    }

  test("an opaque leaf of a transmitting combination blocks; its clear leaves dim"):
    val clear  = Surface(transmit = 0.5)
    val opaque = Surface()
    // Two disjoint spheres in one union along the x axis: the first clear, the second opaque.
    val pair =
      Csg(CsgOperation.Union, Vector(Sphere(Vec3(2, 0, 0), 0.5), Sphere(Vec3(5, 0, 0), 0.5)))
    val w = World(
      Scene(
        Camera(Vec3(0, 0, -20), Vec3.Zero),
        objects = Seq(SceneObject(pair, clear, Vector(clear, opaque)))
      )
    )
    val shadows = Shadows(w, w.newQuery())
    assert(w.transmits)
    // Through the clear sphere only (two crossings), then through both.
    assertEqualsDouble(shadows.point(Vec3.Zero, Vec3.UnitX, 3.5), 0.25, 1e-12)
    assertEquals(shadows.point(Vec3.Zero, Vec3.UnitX, 10.0), 0.0)
