package tracer.render.path

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{Box, Cone, Cylinder, Mesh, Placed, Ray, Shape, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.{Placement, Vec3}
import tracer.render.{SamplerKind, World}
import tracer.scene.{Camera, Scene, SceneObject, Surface}

/** The sampler's numbers and the emitters' densities. */
class SamplerSuite extends ScalaCheckSuite:

  private val counters =
    for
      x   <- Gen.choose(0, 5000)
      y   <- Gen.choose(0, 5000)
      j   <- Gen.choose(0, 1000)
      dim <- Gen.choose(0, 200)
    yield (x, y, j, dim)

  for kind <- SamplerKind.values do
    property(s"$kind: every number is in [0, 1) and a pure function of its counters"):
      forAll(counters, Gen.choose(1, 1 << 20), Gen.choose(0, Int.MaxValue)) {
        case ((x, y, j, dim), n, seed) =>
          val a = Sampler(kind, seed, n)
          val b = Sampler(kind, seed, n)
          val u = a.uniform(x, y, j % n, dim)
          assert(u >= 0 && u < 1, s"$u")
          assertEquals(u, b.uniform(x, y, j % n, dim))
          assertEquals(a.pair(x, y, j % n, dim), b.pair(x, y, j % n, dim))
      }

  test(
    "Sobol: the 16 points of a pixel fill each cell of a 4 × 4 grid and each 16th of a line once"
  ):
    val sampler = Sampler(SamplerKind.Sobol, 42, 16)
    for x <- 0 until 5; dim <- List(0, 4, 12) do
      val points = (0 until 16).map(j => sampler.pair(x, 3, j, dim))
      val cells  = points.map(p => ((Sampler.first(p) * 4).toInt, (Sampler.second(p) * 4).toInt))
      assertEquals(cells.distinct.size, 16)
      assertEquals(points.map(p => (Sampler.first(p) * 16).toInt).distinct.size, 16)
      assertEquals(points.map(p => (Sampler.second(p) * 16).toInt).distinct.size, 16)

  test("Sobol is unbiased for any N, not only powers of two: the mean over many pixels is ½"):
    for n <- List(3, 5, 7, 12) do
      val sampler = Sampler(SamplerKind.Sobol, 1, n)
      val xs      = for x <- 0 until 200; y <- 0 until 20; j <- 0 until n
      yield sampler.uniform(x, y, j, 6)
      // Uniform numbers: standard deviation 1/√12 each, standard error 1/√(12·count).
      val error = 1 / Math.sqrt(12.0 * xs.size)
      assert(Math.abs(xs.sum / xs.size - 0.5) <= 5 * error, s"N = $n: ${xs.sum / xs.size}")

  test("the permutation is a bijection of 0 until n"):
    for n <- List(1, 2, 5, 16, 100, 1000); p <- List(0, 7, 123456789) do
      assertEquals((0 until n).map(Sampler.permute(_, n, p)).sorted, 0 until n)

  test("neighbouring pixels, seeds and dimensions get different numbers"):
    val sampler = Sampler(SamplerKind.Sobol, 0, 64)
    val values  = for x <- 0 until 8; dim <- 0 until 8 yield sampler.uniform(x, 0, 0, dim)
    assertEquals(values.distinct.size, values.size)
    assertNotEquals(
      Sampler(SamplerKind.Sobol, 1, 64).uniform(0, 0, 0, 0),
      sampler.uniform(0, 0, 0, 0)
    )

  private val emitted =
    Scene(
      Camera(Vec3(0, 0, -5), Vec3.Zero),
      Colour.grey(0.3),
      Nil,
      List(
        SceneObject(Sphere(Vec3(1, 2, 3), 0.7), Surface(emission = Colour.White)),
        SceneObject(
          Triangle(Vec3(-1, 0, 2), Vec3(1, 0, 2), Vec3(0, 1.5, 2.5)),
          Surface(emission = Colour.White)
        )
      )
    )
  private val emitters = Emitters(emitted, World(emitted))

  property("an emitter sample's density is what density() gives for the point it reaches"):
    forAll(
      Gen.choose(-3.0, 3.0),
      Gen.choose(-3.0, 3.0),
      Gen.choose(-4.0, 0.0),
      Gen.choose(0.0, 1.0),
      Gen.choose(0.0, 1.0),
      Gen.choose(0.0, 1.0)
    ) { (x, y, z, choice, u1, u2) =>
      val p = Vec3(x, y, z)
      val s = emitters.sample(p, choice, u1, u2)
      if !s.dark && s.distance.isFinite then
        val q     = p + s.direction * s.distance
        val shape = if (q - Vec3(1, 2, 3)).length < 0.7 + 1e-6 then 0 else 1
        assertEqualsDouble(emitters.density(shape, p, q), s.density, 1e-6 * s.density)
      else if !s.dark then assertEqualsDouble(s.density, emitters.skyDensity, 0)
    }

  // A glowing mesh of four faces of different sizes in the plane z = 2, facing −z: one emitter,
  // a point drawn by area over all of it (as Mitsuba's mesh emitter), not four.
  private val fan = Mesh(
    IArray(0.0, 0, 2, 2, 0, 2, 2, 0.5, 2, 0, 1.5, 2, -3, 0, 2, 0, -2, 2),
    IArray(0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 5)
  )
  private val glowingFan =
    Scene(
      Camera(Vec3(0, 0, -5), Vec3.Zero),
      Colour.Black,
      Nil,
      List(SceneObject(fan, Surface(emission = Colour.White)))
    )
  private val fanEmitters = Emitters(glowingFan, World(glowingFan))

  test("a glowing mesh is one emitter, its faces drawn by their shares of its area"):
    assertEquals(fanEmitters.all.length, 1)
    val shares = IArray(0.1, 0.5, 1.0)
    assertEquals(
      List(0.0, 0.0999, 0.1, 0.4999, 0.5, 0.9999).map(Emitters.pick(shares, _)),
      List(0, 0, 1, 1, 2, 2)
    )

  property("a glowing mesh's sample density is what density() gives for the face it reaches"):
    forAll(
      Gen.choose(-3.0, 3.0),
      Gen.choose(-3.0, 3.0),
      Gen.choose(-4.0, 1.5),
      Gen.choose(0.0, 1.0),
      Gen.choose(0.0, 1.0),
      Gen.choose(0.0, 1.0)
    ) { (x, y, z, choice, u1, u2) =>
      val p = Vec3(x, y, z)
      val s = fanEmitters.sample(p, choice, u1, u2)
      if !s.dark then
        val q    = p + s.direction * s.distance
        val leaf = fan.faces.indexWhere(t =>
          Math.abs(Shape.distance(t, Ray(p, s.direction)) - s.distance) < 1e-9 * s.distance
        )
        assert(leaf >= 0, s"no face at $q")
        assertEqualsDouble(fanEmitters.density(0, p, q, leaf), s.density, 1e-6 * s.density)
    }

  /** The property that a sample of `emitters` (one for each of `shapes`, in order, nothing else)
    * drawn from a point in front of them lands on its shape at its distance, and has the density
    * that `density` gives for the point and the shape's normal there.
    */
  private def landsAsDensitySays(shapes: List[Shape], emitters: Emitters) =
    forAll(
      Gen.choose(-3.0, 3.0),
      Gen.choose(-3.0, 3.0),
      Gen.choose(-4.0, 0.0),
      Gen.choose(0.0, 1.0),
      Gen.choose(0.0, 1.0),
      Gen.choose(0.0, 1.0)
    ) { (x, y, z, choice, u1, u2) =>
      val p = Vec3(x, y, z)
      val s = emitters.sample(p, choice, u1, u2)
      if !s.dark then
        // Each emitter is chosen by its equal share of the choice.
        val k   = Math.min(shapes.length - 1, (choice * shapes.length).toInt)
        val ray = Ray(p, s.direction)
        assertEqualsDouble(Shape.distance(shapes(k), ray), s.distance, 1e-9 * s.distance)
        val hit = Shape.hitAt(shapes(k), ray, s.distance)
        assertEqualsDouble(
          emitters.density(k, p, hit.point, hit.leaf, hit.normal),
          s.density,
          1e-6 * s.density
        )
    }

  // A glowing box, and a box placed (turned and scaled) beside it: one emitter each, drawn by area
  // over their six faces as Mitsuba draws its cube; a hit's density from its normal there.
  private val lamp   = Box(Vec3(-1, 0.5, 1.5), Vec3(0.5, 1, 2.5))
  private val turned = Placed(
    Box(Vec3(-0.5, -0.2, -0.4), Vec3(0.5, 0.2, 0.4)),
    Placement(1.5, Vec3(20, 35, -10), Vec3(1.5, -1, 2))
  )
  private val boxes: List[Shape] = List(lamp, turned)
  private val glowingBoxes       =
    Scene(
      Camera(Vec3(0, 0, -5), Vec3.Zero),
      Colour.Black,
      Nil,
      boxes.map(SceneObject(_, Surface(emission = Colour.White)))
    )
  private val boxEmitters = Emitters(glowingBoxes, World(glowingBoxes))

  test("a glowing box, placed or not, is one emitter over its six faces"):
    assertEquals(boxEmitters.all.length, 2)
    assert(boxEmitters.samples(0) && boxEmitters.samples(1))
    for case Emitter.Cuboid(_, faces, _, _, area) <- boxEmitters.all do
      assertEquals(faces.length, 12)
      assertEqualsDouble(area, faces.map(Emitters.areaOf).sum, 1e-12)
    // The plain box's area: 2(1.5·0.5 + 0.5·1 + 1·1.5); the placed one's, scaled by 1.5².
    val areas = boxEmitters.all.collect { case Emitter.Cuboid(_, _, _, _, a) => a }
    assertEqualsDouble(areas(0), 2 * (0.75 + 0.5 + 1.5), 1e-12)
    assertEqualsDouble(areas(1), 2 * (0.8 + 0.32 + 0.4) * 2.25, 1e-12)

  test("a box's faces are wound outwards"):
    for t <- Emitters.boxFaces(lamp) do
      val centre = (t.t0 + t.t1 + t.t2) / 3
      assert(t.normal.dot(centre - Vec3(-0.25, 0.75, 2)) > 0, s"$t faces in")

  property("a glowing box's sample density is what density() gives for the point it reaches"):
    landsAsDensitySays(boxes, boxEmitters)

  // Glowing cylinders and cones: one emitter each over the side and, closed, both discs.
  private val frustums: List[Shape] = List(
    Cylinder(Vec3(-1, 0.5, 1.5), Vec3(-0.4, 1.5, 2.5), 0.4),
    Placed(
      Cone(Vec3(0, 0, 0), 0.5, Vec3(0, 1, 0), 0.2, open = true),
      Placement(1.2, Vec3(70, 0, 20), Vec3(1.5, -1, 2))
    ),
    Cone(Vec3(0.5, 1, 1.2), 0.6, Vec3(1.5, 1.5, 2.4), 0)
  )
  private val glowingFrustums =
    Scene(
      Camera(Vec3(0, 0, -5), Vec3.Zero),
      Colour.Black,
      Nil,
      frustums.map(SceneObject(_, Surface(emission = Colour.White)))
    )
  private val frustumEmitters = Emitters(glowingFrustums, World(glowingFrustums))

  test("a glowing cylinder or cone is one emitter over its side and, closed, its discs"):
    assertEquals(frustumEmitters.all.length, 3)
    val areas = frustumEmitters.all.collect { case Emitter.Frustum(_, _, _, _, a) => a }
    // The cylinder: side 2π·0.4·|(0.6, 1, 1)|, discs π·0.4² each.
    val length = Math.sqrt(0.36 + 1 + 1)
    assertEqualsDouble(areas(0), 2 * Math.PI * 0.4 * length + 2 * Math.PI * 0.16, 1e-12)
    // The open cone, scaled by 1.2: its side alone, π(r0 + r1)·slant.
    assertEqualsDouble(areas(1), Math.PI * 0.7 * Math.hypot(1, 0.3) * 1.44, 1e-12)

  test("a cone's side is drawn uniformly by area: its points' mean height is the side's centroid"):
    // Radius r(s) = r0 + (r1 − r0)s along the height s ∈ [0, 1]: the side's area density is ∝
    // r(s), so its points' mean s is ∫ s·r / ∫ r = (r0/2 + (r1 − r0)/3) / ((r0 + r1)/2).
    val cone    = Cone(Vec3(0, 0, 0), 0.9, Vec3(0, 2, 0), 0.1, open = true)
    val n       = 20000
    val heights = new Array[Double](n)
    for i <- 0 until n do
      Emitters.onFrustum(cone, Emitters.frustumAreas(cone), 0.5, (i + 0.5) / n, 0.3)(
        (_, y, _, _, _, _) => heights(i) = y / 2
      )
    val exact = (0.45 + (0.1 - 0.9) / 3) / 0.5
    assertEqualsDouble(heights.sum / n, exact, 1e-6)

  property("a glowing cylinder's or cone's sample density is what density() gives where it lands"):
    landsAsDensitySays(frustums, frustumEmitters)

  test("a sphere sampled by solid angle: the estimate of its solid angle is exact"):
    // ∫ over the cone 1 dω = 2π(1 − cos θmax); each sample's 1/density (choice removed) is that.
    val sphere = Sphere(Vec3(0, 0, 4), 1)
    val exact  = 2 * Math.PI * (1 - Math.sqrt(1 - 1.0 / 16))
    assertEqualsDouble(1 / Emitters.coneDensity(sphere, Vec3.Zero), exact, 1e-12)
