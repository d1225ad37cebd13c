package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{
  Box,
  Csg,
  CsgOperation,
  Cylinder,
  Placed,
  Plane,
  Ray,
  Shape,
  Sphere,
  Torus,
  Triangle
}
import tracer.math.{Placement, Vec3}
import tracer.scene.{AreaLight, Camera, Light, Scene, SceneObject, Surface}
import tracer.testkit.Generators.*

/** An area light's shadow rays tested against the shapes in their beam give the share that the
  * world's tree gives, bit for bit, in opaque and in transmitting worlds.
  */
class ShadowProperties extends ScalaCheckSuite:

  private val small = Gen.choose(-6.0, 6.0)
  private val point = for x <- small; y <- small; z <- small yield Vec3(x, y, z)
  // A coarse grid makes coincident faces common: ties between clear and opaque shapes.
  private val gridPoint = for x <- Gen.choose(-3, 3); y <- Gen.choose(-3, 3); z <- Gen.choose(-3, 3)
  yield Vec3(x, y, z)

  private val shape: Gen[Shape] = Gen.frequency(
    3 -> (for c <- point; r <- Gen.choose(0.1, 2.0) yield Sphere(c, r)),
    3 -> Gen
      .zip(gridPoint, gridPoint, gridPoint)
      .retryUntil(Triangle.isProper.tupled)
      .map(Triangle(_, _, _)),
    2 -> (for c <- gridPoint; d <- Gen.choose(1, 3) yield Box(c, c + Vec3(d, d, d))),
    1 -> (for n <- Gen.oneOf(Vec3.UnitX, Vec3.UnitY); d <- Gen.choose(-4, 4) yield Plane.at(n, d)),
    1 -> (for b <- gridPoint; h <- Gen.choose(1, 3); r <- Gen.choose(0.2, 1.5)
    yield Cylinder(b, b + Vec3.UnitY * h, r, false)),
    1 -> (for s <- Gen.choose(0.3, 2.0); r <- point; t <- point
    yield Placed(Torus(1, 0.3), Placement(s, r * 18, t)))
  )

  // A transmit of 0 (opaque) or a share let through, 1 (a clear pane) included.
  private val transmit =
    Gen.frequency(3 -> Gen.const(0.0), 2 -> Gen.choose(0.1, 0.95), 1 -> Gen.const(1.0))

  private val plain: Gen[SceneObject] =
    for s <- shape; t <- transmit yield SceneObject(s, Surface(transmit = t))

  // A combination whose leaves show surfaces of their own, some clear and some opaque.
  private val mixed: Gen[SceneObject] =
    for
      a  <- gridPoint
      d  <- Gen.choose(1, 3)
      r  <- Gen.choose(0.3, 2.0)
      op <- Gen.oneOf(CsgOperation.values.toIndexedSeq)
      ta <- transmit
      tb <- transmit
    yield SceneObject(
      Csg(op, Vector(Box(a, a + Vec3(d, d, d)), Sphere(a + Vec3(d, d, d) * 0.5, r))),
      Surface(transmit = ta),
      Vector(Surface(transmit = ta), Surface(transmit = tb))
    )

  private val areaLight: Gen[Light] =
    for
      at <- point
      a  <- Gen.oneOf(unitVec.map(_ * 1.5), Gen.const(Vec3(1.6, 0, 0)))
      b  <- Gen.oneOf(unitVec.map(_ * 0.8), Gen.const(Vec3(0, 0, 1.6)))
      na <- Gen.choose(1, 5)
      nb <- Gen.choose(1, 5)
      if a.cross(b).normalised.isDefined
    yield Light(at * 1.5, area = Some(AreaLight(a, b, na, nb)))

  private def worldGen(objects: Gen[SceneObject], more: List[SceneObject] = Nil): Gen[World] =
    for
      n      <- Gen.choose(1, 40)
      shapes <- Gen.listOfN(n, objects)
      light  <- areaLight
    yield World(
      Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), lights = List(light), objects = shapes ++ more)
    )

  private val opaque: Gen[SceneObject] = shape.map(SceneObject(_))

  private val from: Gen[Vec3] = Gen.oneOf(point, gridPoint.map(_ + Vec3(0.25, 0.5, 1e-4)))

  private def bits(x: Double) = java.lang.Double.doubleToRawLongBits(x)

  private def agree(w: World, points: List[Vec3]): Unit =
    val beamed = Shadows(w, w.newQuery())
    val tree   = Shadows(w, w.newQuery(), beams = false)
    points.foreach { p =>
      val fast = beamed.areaFrom(p.x, p.y, p.z, 0)
      val slow = tree.areaFrom(p.x, p.y, p.z, 0)
      assertEquals(bits(fast), bits(slow), s"from $p: $fast, the tree's $slow")
    }

  property("an area light's share in a transmitting world: the tree's, bit for bit"):
    forAll(worldGen(Gen.frequency(5 -> plain, 1 -> mixed)), Gen.listOfN(40, from)) { (w, points) =>
      assert(w.beams)
      agree(w, points)
    }

  property("an area light's share in an opaque world: the tree's, bit for bit"):
    forAll(worldGen(opaque), Gen.listOfN(40, from)) { (w, points) =>
      assert(w.beams && !w.transmits)
      agree(w, points)
    }

  property("a transmitting world whose glass lies outside the beam: the tree's, bit for bit"):
    // The clear sphere is far from every point and light, so each beam is opaque (the any-hit
    // route) while the world itself transmits.
    val glass = SceneObject(Sphere(Vec3(200, 200, 200), 1), Surface(transmit = 0.9))
    forAll(worldGen(opaque, List(glass)), Gen.listOfN(40, from)) { (w, points) =>
      assert(w.beams && w.transmits)
      agree(w, points)
    }

  test("a box just outside the beam, and one just inside it, and a plane under the point"):
    // The light's grid spans x from -1 to 1 at y = 5 above the point at the origin.
    val light = Light(Vec3(0, 5, 0), area = Some(AreaLight(Vec3(2, 0, 0), Vec3(0, 0, 2), 3, 3)))
    for
      gap   <- List(-1e-6, 0.0, 1e-12, 1e-6)
      floor <- List(-1e-9, 0.0, -1.0)
    do
      // The side of the beam through x = 1 at y = 5 is the line x = y / 5: the box touches it.
      val box   = Box(Vec3(0.5 + gap, 2.4, -0.1), Vec3(0.6 + gap, 2.5, 0.1))
      val plane = Plane.at(Vec3.UnitY, floor)
      val w     = World(
        Scene(
          Camera(Vec3(0, 0, -20), Vec3.Zero),
          lights = List(light),
          objects = List(SceneObject(box), SceneObject(plane))
        )
      )
      agree(w, List(Vec3.Zero, Vec3(0, 1e-4, 0), Vec3(0.01, 0, 0)))

  /** The share by definition (docs/rendering.md, Shadows): 0 when an opaque shape is met at
    * 0 < t < `reach`; otherwise every clear shape's crossings along the whole ray in order (of
    * equal ts the lower index's), each counted when beyond ε past the last one counted.
    */
  private def defined(objects: List[SceneObject], from: Vec3, d: Vec3, reach: Double): Double =
    val ray             = Ray(from, d)
    val (clear, opaque) = objects.partition(_.surfaces.exists(_.transmit > 0))
    if opaque.exists(o => Shape.distance(o.shape, ray) < reach) then 0.0
    else
      val crossings = clear.zipWithIndex
        .flatMap((o, j) => Shape.crossings(o.shape, ray).map(c => (c.t, j, o.surfaceOf(c.leaf))))
        .sortBy((t, j, _) => (t, j))
      crossings
        .foldLeft((1.0, 0.0)) { case ((share, walked), (t, _, surface)) =>
          if t > walked && t < reach then (share * surface.transmit, t + Shading.Epsilon)
          else (share, walked)
        }
        ._1

  property("a point light's share: opaque shapes block, clear ones dim by each crossing"):
    val objects = Gen.listOfN(12, Gen.frequency(5 -> plain, 1 -> mixed))
    forAll(objects, Gen.listOfN(30, Gen.zip(from, point))) { (objects, rays) =>
      val w       = World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = objects))
      val shadows = Shadows(w, w.newQuery())
      assert(!w.transmits || w.clearWalks)
      rays.foreach { (p, to) =>
        (to - p).normalised.foreach { d =>
          val reach = (to - p).length
          val share = shadows.point(p, d, reach)
          assertEquals(bits(share), bits(defined(objects, p, d, reach)), s"from $p to $to")
        }
      }
    }

  test("an opaque surface blocks the light even where a clear one lies on it"):
    // A clear pane and an opaque one in the same plane z = 2, the clear one first: the walk from
    // hit to hit would count the clear one and step past the other.
    def pane(transmit: Double) = SceneObject(
      Triangle(Vec3(-5, -5, 2), Vec3(5, -5, 2), Vec3(0, 5, 2)),
      Surface(transmit = transmit)
    )
    val w = World(
      Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = List(pane(0.5), pane(0.0)))
    )
    assert(w.clearWalks)
    assertEquals(Shadows(w, w.newQuery()).point(Vec3.Zero, Vec3.UnitZ, 10), 0.0)
    assertEquals(Shadows(w, w.newQuery()).point(Vec3.Zero, -Vec3.UnitZ, 10), 1.0)
