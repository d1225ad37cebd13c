package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{
  Box,
  Cone,
  CrossingBuffer,
  Csg,
  CsgOperation,
  Cylinder,
  Kernel,
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
  * world's tree gives, bit for bit, in opaque worlds and in transmitting worlds whose clear
  * shapes the walk tests again from each surface crossed; a clear solid's crossings kept from the
  * ray's start (one query through a clear shape) give the share of a walk on the shape model's
  * total functions that keeps them too, bit for bit, and in general position the tree's.
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

  private def worldGen(objects: Gen[SceneObject], light: Gen[Light] = areaLight): Gen[World] =
    for
      n      <- Gen.choose(1, 40)
      shapes <- Gen.listOfN(n, objects)
      light  <- light
    yield World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), lights = List(light), objects = shapes))

  // The solids whose crossings a walk keeps made opaque: the walk tests every clear shape again
  // from each surface crossed, as the tree's does.
  private def testedAgain(o: SceneObject): SceneObject =
    if !Shadows.firstIsDistance(o.shape) then o
    else o.copy(surface = Surface(), leafSurfaces = o.leafSurfaces.map(_ => Surface()))

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
    val objects = Gen.frequency(5 -> plain, 1 -> mixed).map(testedAgain)
    forAll(worldGen(objects), Gen.listOfN(40, from)) { (w, points) =>
      assert(w.beams)
      agree(w, points)
    }

  // The documented walk (docs/rendering.md, Shadows) on the shape model's total functions, with
  // the beam's rounding: each clear solid's crossings (Shape.crossings) from the ray's start, the
  // next of them less the way walked; every other shape's Shape.distance from the moved origin
  // (the first in index order on a tie); each leaf's transmit multiplied in, ε past each hit.
  private def modelShare(w: World, from: Vec3, to: Vec3): Double =
    val tx    = to.x - from.x
    val ty    = to.y - from.y
    val tz    = to.z - from.z
    val reach = Math.sqrt(tx * tx + ty * ty + tz * tz)
    val d     = Vec3(tx / reach, ty / reach, tz / reach)
    val kept  = (0 until w.size).map { i =>
      if Shadows.keeps(w, i) then Some(Shape.crossings(w.shape(i), Ray(from, d)).toVector)
      else None
    }
    @annotation.tailrec
    def go(o: Vec3, left: Double, walked: Double, share: Double): Double =
      if share <= 0 || left <= 0 then share
      else
        val ray   = Ray(o, d)
        val found = (0 until w.size).map { i =>
          kept(i) match
            case Some(cs) =>
              cs.find(_.t - walked > 0)
                .fold((Double.PositiveInfinity, 0))(c => (c.t - walked, c.leaf))
            case None =>
              val t    = Shape.distance(w.shape(i), ray)
              val leaf =
                if t < Double.PositiveInfinity && w.hasLeafSurfaces(i) then
                  Shape.hitAt(w.shape(i), ray, t).leaf
                else 0
              (t, leaf)
        }
        // The least t ≤ left, the first in index order of equal ones.
        val best = (0 until w.size).foldLeft(-1) { (b, i) =>
          val t = found(i)._1
          if t <= left && t < Double.PositiveInfinity && (b < 0 || t < found(b)._1) then i else b
        }
        if best < 0 || found(best)._1 >= left then share
        else
          val (t, leaf) = found(best)
          val step      = t + Shading.Epsilon
          val moved     = Vec3(o.x + d.x * step, o.y + d.y * step, o.z + d.z * step)
          go(moved, left - step, walked + step, share * w.surface(best, leaf).transmit)
    if reach > 0 then go(from, reach, 0.0, 1.0) else 1.0

  // One sub-light (a 1 × 1 grid), so the share is that ray's, averaged as the four corners are.
  private val oneSubLight: Gen[Light] =
    point.map(at => Light(at * 1.5, area = Some(AreaLight(Vec3(1, 0, 0), Vec3(0, 0, 1), 1, 1))))

  property(
    "clear solids kept from the ray's start: the shape model's walk that keeps them, bit for bit"
  ):
    forAll(worldGen(Gen.frequency(5 -> plain, 1 -> mixed), oneSubLight), Gen.listOfN(40, from)) {
      (w, points) =>
        assert(w.beams)
        val beamed = Shadows(w, w.newQuery())
        val light  = w.subLights(0)
        val to     = Vec3(light(0), light(1), light(2))
        points.foreach { p =>
          val r     = modelShare(w, p, to)
          val model = (r + r + r + r) * 0.25
          val fast  = beamed.areaFrom(p.x, p.y, p.z, 0)
          assertEquals(bits(fast), bits(model), s"from $p: $fast, the model's $model")
        }
    }

  // Clear solids of the general route in general position (no grid): kept crossings and the
  // tree's tests from each moved origin round differently, which can change a share only when a
  // crossing lies within rounding of ε past another, of another shape's or of the light.
  private val anywhere = Gen.choose(-4.0, 4.0)
  private val spot     = for x <- anywhere; y <- anywhere; z <- anywhere yield Vec3(x, y, z)
  private val clearSolid: Gen[Shape] =
    val tumbler =
      for
        b <- spot
        a <- unitVec
        h <- Gen.choose(0.5, 2.5)
        r <- Gen.choose(0.2, 1.5)
        k <- Gen.choose(0.5, 0.95)
        f <- Gen.choose(0.05, 0.4)
      yield Csg(
        CsgOperation.Difference,
        Vector(Cylinder(b, b + a * h, r), Cylinder(b + a * f, b + a * (h + 1), r * k))
      )
    val box = for c <- spot; d <- spot
    yield Box(
      c,
      c + Vec3(1 + Math.abs(d.x) * 0.3, 1 + Math.abs(d.y) * 0.3, 1 + Math.abs(d.z) * 0.3)
    )
    val cone =
      for b <- spot; a <- unitVec; h <- Gen.choose(0.3, 3.0); r <- Gen.choose(0.1, 1.5)
      yield Cone(b, r, b + a * h, r * 0.3)
    val torus = for s <- Gen.choose(0.3, 2.0); r <- spot; t <- spot
    yield Placed(Torus(1, 0.3), Placement(s, r * 40, t))
    val rounded =
      for
        c  <- spot
        d  <- Gen.choose(0.5, 2.0)
        op <- Gen.oneOf(CsgOperation.Intersection, CsgOperation.Difference)
      yield Csg(op, Vector(Box(c, c + Vec3(d, d, d)), Sphere(c + Vec3(d, d, d) * 0.5, d * 0.65)))
    val solid = Gen.frequency(3 -> tumbler, 1 -> box, 1 -> cone, 1 -> torus, 1 -> rounded)
    Gen.frequency(
      3 -> solid,
      1 -> (for x <- solid; s <- Gen.choose(0.4, 2.0); r <- spot; t <- spot
      yield Placed(x, Placement(s, r * 40, t)))
    )

  private val clearObject: Gen[SceneObject] =
    Gen.frequency(
      5 -> (for x <- clearSolid; t <- Gen.choose(0.1, 0.95)
      yield SceneObject(x, Surface(transmit = t))),
      1 -> (for c <- spot; r <- Gen.choose(0.1, 1.0); t <- transmit
      yield SceneObject(Sphere(c, r), Surface(transmit = t))),
      // Leaves that show surfaces of their own, clear and opaque.
      1 -> (for x <- clearSolid; c <- spot; t <- Gen.choose(0.1, 0.95)
      yield SceneObject(
        Csg(CsgOperation.Intersection, Vector(x, Sphere(c, 3))),
        Surface(transmit = t),
        Vector.tabulate(Shape.leafCount(x) + 1)(l =>
          Surface(transmit = if l % 2 == 0 then t else 0)
        )
      ))
    )

  property("clear solids kept from the ray's start, in general position: the tree's, bit for bit"):
    forAll(worldGen(clearObject), Gen.listOfN(40, spot)) { (w, points) =>
      assert(w.beams && w.transmits)
      agree(w, points)
    }

  // A kept solid's first step is its test: Kernel.collect's first crossing is the shape's
  // distance (the general route's and the shape model's) and the leaf Shape.hitAt reports.
  property("a kept solid's first crossing: Shape.distance and Shape.hitAt's leaf, bit for bit"):
    forAll(clearSolid, spot, unitVec) { (shape, o, d) =>
      assert(Shadows.firstIsDistance(shape))
      val buffer = CrossingBuffer()
      val n      = Kernel.collect(shape, o.x, o.y, o.z, d.x, d.y, d.z, buffer, 0, normals = false)
      val t      = Shape.distance(shape, Ray(o, d))
      val kernel = Kernel.distance(shape, o.x, o.y, o.z, d.x, d.y, d.z, CrossingBuffer())
      assertEquals(bits(kernel), bits(t))
      if n == 0 then assertEquals(t, Double.PositiveInfinity)
      else
        assertEquals(bits(buffer.tAt(0)), bits(t))
        assertEquals(buffer.leafAt(0), Shape.hitAt(shape, Ray(o, d), t).leaf)
    }

  test("a union and the fast shapes are not kept: their distance is not their first crossing"):
    val ball = Sphere(Vec3.Zero, 1)
    assert(
      !Shadows.firstIsDistance(Csg(CsgOperation.Union, Vector(ball, Box(Vec3.Zero, Vec3(1, 1, 1)))))
    )
    assert(!Shadows.firstIsDistance(Placed(ball, Placement(2.0, Vec3.Zero, Vec3.Zero))))
    assert(Shadows.firstIsDistance(Placed(Torus(1, 0.3), Placement(2.0, Vec3.Zero, Vec3.Zero))))

  property("an area light's share in an opaque world: the tree's, bit for bit"):
    forAll(worldGen(opaque), Gen.listOfN(40, from)) { (w, points) =>
      assert(w.beams && !w.transmits)
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
