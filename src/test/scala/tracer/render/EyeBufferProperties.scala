package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{Mesh, Plane, Ray, Shape, Sphere}
import tracer.math.Vec3
import tracer.scene.{Camera, Light, Scene, SceneObject, Surface}
import tracer.testkit.Generators.unitVec

/** The camera's [[EyeBuffer]] answers every ray from the camera's location as the tree's
  * nearest-hit walk does ([[World.nearestAlong]] with and without the buffer): the same shape, the
  * same distance to the bit and, on a mesh, the same face, with the eye anywhere, on a coarse grid
  * (so that directions along the buffer's cube edges are common), inside shapes, on their surfaces
  * and far away, and rays in every direction, through grid points and along the axes.
  */
class EyeBufferProperties extends ScalaCheckSuite:
  import BufferWorlds.*

  override def scalaCheckTestParameters =
    super.scalaCheckTestParameters.withMinSuccessfulTests(60)

  private def sceneOf(shapes: Seq[Shape], eye: Vec3): Scene =
    Scene(
      Camera(eye, eye + Vec3(0.3, -0.2, 1)),
      lights = Vector(Light(Vec3(2, 9, -4))),
      objects = shapes.map(SceneObject(_)).toVector
    )

  /** A world with the camera's buffer, and the same world without it. */
  private def worlds(shapes: Seq[Shape], eye: Vec3): (World, World) =
    val scene = sceneOf(shapes, eye)
    (World(scene, eyeRays = Long.MaxValue), World(scene))

  /** Where the eye goes: anywhere, on the grid, far off, or on (or inside) one of the shapes. */
  private def eyeFor(shapes: Seq[Shape]): Gen[Vec3] =
    val onSurface = for o <- point; d <- unitVec yield
      val w = World(sceneOf(shapes, Vec3(0, 0, -20)))
      val q = w.newQuery()
      val i = w.nearestAlong(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, q)
      if i < 0 then o else o + d * q.distance
    val far = for d <- unitVec; e <- Gen.choose(2, 7) yield d * Math.pow(10, e)
    Gen.frequency(3 -> point, 3 -> gridPoint, 3 -> onSurface, 1 -> far)

  /** Points where two faces of a mesh meet, so that rays through them tie: a corner, or the
    * middle of an edge of a face.
    */
  private def seams(shapes: Seq[Shape]): Gen[Vec3] =
    val meshes = shapes.collect { case m: Mesh => m }
    if meshes.isEmpty then point
    else
      for
        m <- Gen.oneOf(meshes)
        f <- Gen.choose(0, m.faceCount - 1)
        e <- Gen.choose(0, 2)
        w <- Gen.oneOf(0.0, 0.5)
      yield
        def corner(c: Int) =
          val v = 3 * m.corners(3 * f + c % 3)
          Vec3(m.vertices(v), m.vertices(v + 1), m.vertices(v + 2))
        corner(e) * (1 - w) + corner(e + 1) * w

  /** Directions from the eye: any, toward grid points, points of space and the meshes' seams,
    * and along the axes, the cube's edges and its diagonals.
    */
  private def directions(shapes: Seq[Shape], eye: Vec3): Gen[List[Vec3]] =
    val toward = Gen
      .oneOf(point, gridPoint, seams(shapes), seams(shapes))
      .map(p => (p - eye).normalised.getOrElse(Vec3.UnitZ))
    val axial = for
      x <- Gen.oneOf(-1, 0, 1); y <- Gen.oneOf(-1, 0, 1); z <- Gen.oneOf(-1, 0, 1)
      if x != 0 || y != 0 || z != 0
    yield Vec3(x, y, z).normalised.get
    Gen.listOfN(80, Gen.frequency(3 -> unitVec, 5 -> toward, 1 -> axial))

  /** Random shapes and, so that every world is large enough for the buffers
    * ([[EyeBuffer.MinItems]]), a bumpy grid of 288 faces at some height.
    */
  private val shapes: Gen[Seq[Shape]] =
    for
      n      <- Gen.choose(2, 60)
      random <- Gen.listOfN(n, shape)
      y      <- small
      at     <- Gen.choose(0, n)
    yield random.patch(at, Seq(terrain(12, y, 0.4)), 0)

  private val cases: Gen[(Seq[Shape], Vec3, List[Vec3])] =
    for
      shapes <- shapes
      eye    <- eyeFor(shapes)
      ds     <- directions(shapes, eye)
    yield (shapes, eye, ds)

  property("the camera's buffer answers each ray from the eye as the tree's walk"):
    forAll(cases) { (shapes, eye, ds) =>
      val (buffered, walked) = worlds(shapes, eye)
      // Every world gets the buffer (no vacuous cases).
      assert(buffered.eyeBuffer.isDefined)
      val (qb, qw) = (buffered.newQuery(), walked.newQuery())
      for d <- ds; limit <- List(Double.PositiveInfinity, 3.5) do
        val seen = s"eye $eye, direction $d, limit $limit"
        val ib   = buffered.nearestAlong(eye.x, eye.y, eye.z, d.x, d.y, d.z, limit, qb)
        val iw   = walked.nearestAlong(eye.x, eye.y, eye.z, d.x, d.y, d.z, limit, qw)
        assertEquals(ib, iw, seen)
        assertEquals(
          java.lang.Double.doubleToRawLongBits(qb.distance),
          java.lang.Double.doubleToRawLongBits(qw.distance),
          seen
        )
        if iw >= 0 then
          shapes(iw) match
            case _: Mesh => assertEquals(qb.face, qw.face, seen)
            case _       => ()
    }

  /** A mirroring plane: a normal along an axis or anywhere, at a small distance. */
  private val mirror: Gen[Plane] =
    for
      n <- Gen.oneOf(Gen.const(Vec3.UnitY), Gen.const(Vec3(0, 0, -1)), unitVec)
      d <- Gen.choose(-3.0, 3.0)
    yield Plane.at(n, d)

  private val mirrored: Gen[(Seq[Shape], Plane, Vec3, List[Vec3])] =
    for
      shapes <- shapes
      plane  <- mirror
      eye    <- Gen.oneOf(point, gridPoint).retryUntil(e => plane.normal.dot(e) != plane.distance)
      ds     <- directions(shapes, eye)
    yield (shapes, plane, eye, ds)

  property("a mirroring plane's buffer answers each ray it reflects from the eye as the walk"):
    forAll(mirrored) { (shapes, plane, eye, ds) =>
      val scene = Scene(
        Camera(eye, eye + Vec3(0.3, -0.2, 1)),
        objects = shapes.map(SceneObject(_)).toVector :+
          SceneObject(plane, Surface(reflection = 0.5))
      )
      val buffered = World(scene, mirrorRays = Long.MaxValue)
      val walked   = World(scene)
      assertEquals(buffered.eyeBuffers.length, 1)
      val (qb, qw) = (buffered.newQuery(), walked.newQuery())
      // The rays from the eye that meet the plane first, reflected as shading reflects them.
      for d <- ds do
        val i = walked.nearestAlong(eye.x, eye.y, eye.z, d.x, d.y, d.z, Double.PositiveInfinity, qw)
        if i == shapes.length then
          Hits.record(plane, eye.x, eye.y, eye.z, d.x, d.y, d.z, qw.distance, qw)
          val o    = Vec3(qw.px, qw.py, qw.pz) + Vec3(qw.nx, qw.ny, qw.nz) * Shading.Epsilon
          val k    = 2 * (qw.sx * d.x + qw.sy * d.y + qw.sz * d.z)
          val r    = Vec3(d.x - qw.sx * k, d.y - qw.sy * k, d.z - qw.sz * k)
          val seen = s"eye $eye, direction $d, reflected from $o along $r"
          for b <- buffered.eyeBuffers do assert(b.behind(o.x, o.y, o.z, r.x, r.y, r.z) > 0, seen)
          val ib = buffered.nearestAlong(o.x, o.y, o.z, r.x, r.y, r.z, Double.PositiveInfinity, qb)
          val iw = walked.nearestAlong(o.x, o.y, o.z, r.x, r.y, r.z, Double.PositiveInfinity, qw)
          assertEquals(ib, iw, seen)
          assertEquals(
            java.lang.Double.doubleToRawLongBits(qb.distance),
            java.lang.Double.doubleToRawLongBits(qw.distance),
            seen
          )
          if iw >= 0 && iw < shapes.length then
            shapes(iw) match
              case _: Mesh => assertEquals(qb.face, qw.face, seen)
              case _       => ()
    }

  test("a world of many faces gets a buffer of the camera's, filled; a short render none"):
    val shapes = Seq(terrain(30, 0, 0.5), Sphere(Vec3(0, 2, 0), 1), Plane.at(Vec3.UnitY, -1))
    val scene  = sceneOf(shapes, Vec3(0, 3, -9))
    val buffer = World(scene, eyeRays = Long.MaxValue).eyeBuffer
    assert(buffer.isDefined)
    assert(buffer.get.cells.cellCount > 1000, buffer.get.cells.cellCount)
    assert(buffer.get.cells.entryCount >= 2 * 30 * 30, buffer.get.cells.entryCount)
    assert(World(scene, eyeRays = 1000).eyeBuffer.isEmpty)
    // A 1280×720 picture is too short a render to pay for the buffer; a 3840×2160 one is not.
    assert(World(scene, eyeRays = 1280L * 720).eyeBuffer.isEmpty)
    assert(World(scene, eyeRays = 3840L * 2160).eyeBuffer.isDefined)
    // But 300 spheres build their buffer in a moment: 1280×720 is 3,072 rays an item, enough;
    // 640×360 is 768, not.
    val balls =
      sceneOf((0 until 300).map(i => Sphere(Vec3(i % 20, i / 20, 5), 0.3)), Vec3(9, 7, -9))
    assert(World(balls, eyeRays = 1280L * 720).eyeBuffer.isDefined)
    assert(World(balls, eyeRays = 640L * 360).eyeBuffer.isEmpty)
    // A few shapes are walked in a node or two: no buffer.
    val few = Seq(Sphere(Vec3.Zero, 1), Sphere(Vec3(3, 0, 0), 1), Sphere(Vec3(0, 3, 0), 1))
    assert(World(sceneOf(few, Vec3(0, 0, -5)), eyeRays = Long.MaxValue).eyeBuffer.isEmpty)

  test(
    "quick mode, whose rays the camera's buffer all answers, builds coarse trees: the same answers"
  ):
    // 2,450 faces and 40 spheres: enough items for the coarse trees to be deep.
    val land   = terrain(35, 0, 0.5)
    val shapes = land +: Plane.at(Vec3.UnitY, -1) +: (0 until 40).map(i =>
      Sphere(Vec3(i % 8 - 4, 1.2, i / 8), 0.3)
    )
    val scene = sceneOf(shapes, Vec3(0, 3, -9))
    val rays  = 3840L * 2160
    val quick = World(scene, eyeRays = rays, eyeOnly = true)
    val fine  = World(scene, eyeRays = rays)
    assert(quick.eyeBuffer.isDefined)
    assert(quick.tree.nodeCount < fine.tree.nodeCount, (quick.tree.nodeCount, fine.tree.nodeCount))
    val (coarse, finer) = (quick.meshTree(land).get, fine.meshTree(land).get)
    assert(coarse.nodeCount < finer.nodeCount, (coarse.nodeCount, finer.nodeCount))
    // A short quick render, or too few items, keeps the fine trees.
    assertEquals(
      World(scene, eyeRays = 1000, eyeOnly = true).tree.nodeCount,
      World(scene, eyeRays = 1000).tree.nodeCount
    )
    val (qq, qf) = (quick.newQuery(), fine.newQuery())
    val eye      = scene.camera.location
    for i <- -40 to 40; j <- -25 to 25 do
      val d  = Vec3(i / 40.0, j / 40.0 - 0.2, 1).normalised.get
      val hq = quick.nearestAlong(eye.x, eye.y, eye.z, d.x, d.y, d.z, Double.PositiveInfinity, qq)
      val hf = fine.nearestAlong(eye.x, eye.y, eye.z, d.x, d.y, d.z, Double.PositiveInfinity, qf)
      assertEquals(hq, hf, d.toString)
      if hq >= 0 then
        assertEquals(qq.distance, qf.distance, d.toString)
        assertEquals(qq.face, qf.face, d.toString)

  test("a buffer's items are sorted by their boxes' distance from the eye"):
    val shapes = Seq(terrain(12, 0, 0.5), Sphere(Vec3(0, 2, 0), 1), Sphere(Vec3(2, 1, 3), 0.5))
    val buffer = World(sceneOf(shapes, Vec3(1, 4, -7)), eyeRays = Long.MaxValue).eyeBuffer.get
    val gaps   = buffer.cells.gaps.toSeq
    assertEquals(gaps, gaps.sorted)
    assert(gaps.head >= 0 && gaps.last > 0, gaps)

  test("shading through the camera's buffers gives the walk's colours, bit for bit"):
    val shapes = Seq(
      terrain(24, 0, 0.6),
      Sphere(Vec3(0, 1.5, 0), 1),
      Plane.at(Vec3.UnitY, -1),
      tracer.geometry.Box(Vec3(1, 0, 1), Vec3(2, 1, 2))
    )
    val eye   = Vec3(0, 3, -9)
    val scene = Scene(
      Camera(eye, Vec3.Zero),
      lights = Vector(Light(Vec3(-4, 7, -5)), Light(Vec3(5, 3, -2))),
      objects = shapes.map(SceneObject(_, Surface(reflection = 0.3))).toVector :+
        SceneObject(Sphere(Vec3(-1.5, 1, -1), 0.6), Surface(transmit = 0.7, ior = 1.5))
    )
    val walked = Shading(World(scene), ShadingMode.Full)
    val world  = World(scene, eyeRays = Long.MaxValue, mirrorRays = Long.MaxValue)
    // The camera's buffer and its mirror image's in the mirroring floor.
    assertEquals(world.eyeBuffers.length, 2)
    val buffered = Shading(world, ShadingMode.Full)
    for i <- 0 until 40; j <- 0 until 30 do
      val d   = Vec3(-0.4 + i * 0.02, -0.35 + j * 0.02, 1).normalised.get
      val ray = Ray(eye, d)
      assertEquals(buffered.colour(ray, 5), walked.colour(ray, 5), ray.toString)
