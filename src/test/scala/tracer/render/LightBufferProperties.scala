package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.forAll
import tracer.geometry.{Box, Plane, Ray, Shape, Sphere, Triangle}
import tracer.math.Vec3
import tracer.scene.{Camera, Light, Scene, SceneObject, Surface}
import tracer.testkit.Generators.unitVec

/** A point light's [[LightBuffer]] answers every shadow ray toward it as the tree's any-hit walk
  * does ([[World.occludedToward]] against [[World.occludedAlong]]): from points anywhere, on the
  * shapes' surfaces, next to the light and very far from it, with lights and shapes on a coarse
  * grid so that directions along the cube's edges and faces through the light are common.
  */
class LightBufferProperties extends ScalaCheckSuite:

  override def scalaCheckTestParameters =
    super.scalaCheckTestParameters.withMinSuccessfulTests(60)

  import BufferWorlds.*

  private val light: Gen[Vec3] = Gen.oneOf(point, gridPoint, point.map(_ * 3))

  private def worldOf(shapes: Seq[Shape], lights: Seq[Vec3], clear: Set[Int] = Set.empty): World =
    World(
      Scene(
        Camera(Vec3(0, 0, -20), Vec3.Zero),
        lights = lights.map(Light(_)).toVector,
        objects = shapes.zipWithIndex.map { (s, i) =>
          SceneObject(s, if clear(i) then Surface(transmit = 0.6) else Surface())
        }.toVector
      ),
      shadowRays = Long.MaxValue
    )

  // Worlds that let no light through, and worlds with some clear shapes (whose point lights'
  // buffers hold the opaque shapes alone).
  private val world: Gen[World] =
    for
      n      <- Gen.choose(1, 60)
      shapes <- Gen.listOfN(n, shape)
      lights <- Gen.listOfN(2, light)
      clear <- Gen.oneOf(Gen.const(Set.empty[Int]), Gen.containerOf[Set, Int](Gen.choose(0, n - 1)))
    yield worldOf(shapes, lights, clear)

  /** The walk's answer the buffer must give: any blocker, or in a world that lets light through,
    * any opaque blocker.
    */
  private def walked(w: World, p: Vec3, d: Vec3, reach: Double, query: Query): Boolean =
    if w.transmits then w.opaqueAlong(p.x, p.y, p.z, d.x, d.y, d.z, reach, query)
    else w.occludedAlong(p.x, p.y, p.z, d.x, d.y, d.z, reach, query)

  /** Shading points: anywhere, on a grid, beside a light, far away, and where rays from a light's
    * neighbourhood meet the shapes (points on their surfaces, as shading's are).
    */
  private def points(w: World): Gen[List[Vec3]] =
    val l         = w.lights.map(_.location)
    val onSurface = for o <- point; d <- unitVec yield
      val q = w.newQuery()
      val i = w.nearestAlong(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, q)
      if i < 0 then o else o + d * q.distance
    val nearLight = for k <- Gen.choose(0, l.size - 1); d <- unitVec; e <- Gen.choose(-9, -1)
    yield l(k) + d * Math.pow(10, e)
    val far = for d <- unitVec; e <- Gen.choose(2, 12) yield d * Math.pow(10, e)
    Gen.listOfN(
      60,
      Gen.frequency(3 -> point, 2 -> gridPoint, 4 -> onSurface, 1 -> nearLight, 1 -> far)
    )

  property("a point light's buffer answers each shadow ray as the tree's walk"):
    forAll(world.flatMap(w => points(w).map(w -> _))) { (w, from) =>
      val query = w.newQuery()
      for k <- w.lights.indices; buffer <- w.lightBuffer(k); p <- from do
        val t     = w.lights(k).location - p
        val reach = t.length
        if reach > 0 then
          val d = t / reach
          assertEquals(
            w.occludedToward(buffer, p.x, p.y, p.z, d.x, d.y, d.z, reach, query),
            walked(w, p, d, reach, query),
            s"light $k at ${w.lights(k).location}, from $p"
          )
    }

  test("a world of many faces gets a buffer for each point light, filled"):
    val w      = worldOf(Seq(terrain(30, 0, 0.5), Sphere(Vec3(0, 2, 0), 1)), Seq(Vec3(1, 8, -2)))
    val buffer = w.lightBuffer(0)
    assert(buffer.isDefined)
    assert(buffer.get.cellCount > 1000, buffer.get.cellCount)
    assert(buffer.get.entryCount >= 2 * 30 * 30, buffer.get.entryCount)

  test("a triangle is binned by its outline in a long render: slivers fill fewer cells than boxes"):
    // 400 slivers on the floor, each along the diagonal of its square, seen from above: a box
    // covers its square of directions, a face only a strip along the diagonal.
    val slivers = (0 until 400).map { i =>
      val x = (i % 20) * 0.5 - 5
      val z = (i / 20) * 0.5 - 5
      Triangle(Vec3(x, 0, z), Vec3(x + 2.45, 0, z + 2.45), Vec3(x + 2.4, 0.01, z + 2.45))
    }
    val light                    = Vec3(0.3, 6, -0.2)
    def items(outlined: Boolean) =
      val boxes   = new Array[Double](6 * slivers.size)
      val corners = new Array[Double](9 * slivers.size)
      for (t, i) <- slivers.zipWithIndex do
        val cs = Seq(t.t0, t.t1, t.t2)
        for a <- 0 until 3 do
          val xs = cs.map(c => Seq(c.x, c.y, c.z)(a))
          boxes(6 * i + a) = xs.min; boxes(6 * i + 3 + a) = xs.max
        World.widen(boxes, 6 * i)
        for (c, j) <- cs.zipWithIndex do
          corners(9 * i + 3 * j) = c.x; corners(9 * i + 3 * j + 1) = c.y
          corners(9 * i + 3 * j + 2) = c.z
        if !outlined then corners(9 * i) = Double.NaN
      BufferItems(boxes, slivers.indices.toArray, Array.fill(slivers.size)(-1), corners)
    val outlined = LightBuffer.build(light.x, light.y, light.z, items(true)).get
    val boxed    = LightBuffer.build(light.x, light.y, light.z, items(false)).get
    assert(2 * outlined.entryCount < boxed.entryCount, (outlined.entryCount, boxed.entryCount))
    // And a world of them answers as its walk: from points under the floor, and from points
    // whose rays pass through the slivers' edges and corners, where an outline drawn too tight
    // would leave a face out of the ray's cell.
    val w     = worldOf(slivers, Seq(light))
    val query = w.newQuery()
    val under = for i <- -120 to 120; j <- -120 to 120 yield Vec3(i / 24.0 + 1e-3, -0.02, j / 24.0)
    val throughEdges =
      for t <- slivers; (a, b) <- Seq(t.t0 -> t.t1, t.t1 -> t.t2, t.t2 -> t.t0); k <- 0 to 4
      yield light + (a + (b - a) * (k / 4.0) - light) * 1.5
    val blocked = (under ++ throughEdges).count { p =>
      val t     = light - p
      val reach = t.length
      val d     = t / reach
      val walk  = walked(w, p, d, reach, query)
      assertEquals(
        w.occludedToward(w.lightBuffer(0).get, p.x, p.y, p.z, d.x, d.y, d.z, reach, query),
        walk,
        s"from $p"
      )
      walk
    }
    assert(blocked > 6000, blocked)
    // A render of fewer rays an item bins them by their boxes, and answers as the walk too.
    val short = World(
      Scene(
        Camera(Vec3(0, 0, -20), Vec3.Zero),
        lights = Vector(Light(light)),
        objects = slivers.map(SceneObject(_)).toVector
      ),
      shadowRays = LightBuffer.RaysPerItem * slivers.size
    )
    val boxes = short.lightBuffer(0).get
    assertEquals(boxes.entryCount, boxed.entryCount)
    for p <- under do
      val t     = light - p
      val reach = t.length
      val d     = t / reach
      assertEquals(
        short.occludedToward(boxes, p.x, p.y, p.z, d.x, d.y, d.z, reach, query),
        walked(w, p, d, reach, query),
        s"from $p, by boxes"
      )

  test("a world of a few shapes in one leaf gets a buffer too, answering as the walk"):
    val few =
      Seq(Sphere(Vec3(0, 1, 0), 1), Sphere(Vec3(2, 0.5, 1), 0.5), Sphere(Vec3(-2, 0.4, 2), 0.4))
    val w = worldOf(few, Seq(Vec3(-5, 8, -6)))
    assert(w.lightBuffer(0).isDefined)
    val query   = w.newQuery()
    val answers =
      for x <- -30 to 30; z <- -30 to 30 yield
        val p      = Vec3(x / 10.0, 0, z / 10.0)
        val t      = w.lights(0).location - p
        val d      = t / t.length
        val buffer = w.lightBuffer(0).get
        val walk   = walked(w, p, d, t.length, query)
        assertEquals(
          w.occludedToward(buffer, p.x, p.y, p.z, d.x, d.y, d.z, t.length, query),
          walk,
          s"from $p"
        )
        walk
    // The floor is both in shadow and in light there: both answers were checked.
    assert(answers.contains(true) && answers.contains(false))

  test("no buffer for a short render, a clear mesh, or an area light; one for glass"):
    val shapes = Seq(terrain(30, 0, 0.5), Sphere(Vec3(0, 2, 0), 1))
    val scene  = Scene(
      Camera(Vec3(0, 0, -20), Vec3.Zero),
      lights = Vector(Light(Vec3(1, 8, -2))),
      objects = shapes.map(SceneObject(_)).toVector
    )
    assert(World(scene, shadowRays = 100).lightBuffer(0).isEmpty)
    val glass = scene.copy(objects =
      scene.objects :+ SceneObject(Sphere(Vec3(3, 1, 0), 1), Surface(transmit = 0.5))
    )
    assert(World(glass, shadowRays = Long.MaxValue).lightBuffer(0).isDefined)
    val clearMesh = scene.copy(objects =
      scene.objects :+ SceneObject(terrain(4, 3, 0.2), Surface(transmit = 0.5))
    )
    assert(World(clearMesh, shadowRays = Long.MaxValue).lightBuffer(0).isEmpty)
    val area = tracer.scene.AreaLight(Vec3(1, 0, 0), Vec3(0, 0, 1), 4, 4)
    val lit  = scene.copy(lights = Vector(Light(Vec3(1, 8, -2), area = Some(area))))
    assert(World(lit, shadowRays = Long.MaxValue).lightBuffer(0).isEmpty)

  test("shading through the buffers gives the walk's colours, bit for bit"):
    val shapes = Seq(
      terrain(24, 0, 0.6),
      Sphere(Vec3(0, 1.5, 0), 1),
      Plane.at(Vec3.UnitY, -1),
      Box(Vec3(1, 0, 1), Vec3(2, 1, 2))
    )
    val scene = Scene(
      Camera(Vec3(0, 3, -9), Vec3.Zero),
      lights = Vector(Light(Vec3(-4, 7, -5)), Light(Vec3(5, 3, -2))),
      objects = shapes.map(SceneObject(_, Surface(reflection = 0.3))).toVector :+
        SceneObject(Sphere(Vec3(-1.5, 1, -1), 0.6), Surface(transmit = 0.7, ior = 1.5))
    )
    val walked   = Shading(World(scene), ShadingMode.Full)
    val buffered = Shading(World(scene, shadowRays = Long.MaxValue), ShadingMode.Full)
    for i <- 0 until 40; j <- 0 until 30 do
      val d   = Vec3(-0.4 + i * 0.02, -0.35 + j * 0.02, 1).normalised.get
      val ray = Ray(Vec3(0, 3, -9), d)
      assertEquals(buffered.colour(ray, 5), walked.colour(ray, 5), ray.toString)

  test("a cell's items come nearest the light first, the buffer's gaps nondecreasing"):
    val w      = worldOf(Seq(terrain(20, 0, 0.5), Sphere(Vec3(0, 2, 0), 1)), Seq(Vec3(1, 8, -2)))
    val buffer = w.lightBuffer(0).get
    assertEquals(buffer.gaps.toSeq, buffer.gaps.toSeq.sorted)
    for c <- 0 until buffer.cellCount do
      val cell = buffer.items.slice(buffer.start(c), buffer.start(c + 1)).toSeq
      assertEquals(cell, cell.sorted, s"cell $c")
    assertEquals(buffer.always.toSeq, buffer.always.toSeq.sorted)

  test("a blocker just above the shading point, its gap within a float's step of the ray, blocks"):
    // The plate under the light has its top 2·10⁻⁹ above the shading point: its gap (its widened
    // box's distance from the light, less 10⁻⁹ of it, rounded down to a float) lies within a
    // float's step below the shadow ray's length, so the test of the cell's items must reach
    // it. The light sits 3·10⁻⁶ below the float 100: a gap rounded to the nearest float (100)
    // would exceed the ray's length and skip the plate.
    val plates = (0 until 300).map { i =>
      val x = (i % 20) * 3.0
      val z = (i / 20) * 3.0
      Box(Vec3(x - 1, -1e-9, z - 1), Vec3(x + 1, 0, z + 1))
    }
    val light  = Vec3(0, 100 - 3e-6, 0)
    val w      = worldOf(plates, Seq(light))
    val buffer = w.lightBuffer(0).get
    val query  = w.newQuery()
    val under  = Vec3(0, -2e-9, 0)
    assert(buffer.gaps(0) <= (light - under).length, buffer.gaps(0))
    assert((light - under).length - buffer.gaps(0) < Math.ulp(buffer.gaps(0)), buffer.gaps(0))
    // The float nearest the plate's gap is 100, beyond the ray's length.
    assertEquals((light.y - 1e-7).toFloat, 100f)
    val others = (0 until 300).map(i => Vec3((i % 20) * 3.0 + 0.25, -2e-9, (i / 20) * 3.0 - 0.25))
    for p <- under +: others do
      val t     = light - p
      val reach = t.length
      val d     = t / reach
      assert(walked(w, p, d, reach, query), s"the walk from $p")
      assert(w.occludedToward(buffer, p.x, p.y, p.z, d.x, d.y, d.z, reach, query), s"from $p")

  property("the keys' radix sort orders them as a sort of the longs does"):
    // High halves from few values (many ties, which must keep their index order) to many, some
    // with every byte but the lowest the same (passes skipped) and some spread over all four.
    val keys = for
      n     <- Gen.choose(0, 600)
      range <- Gen.oneOf(1, 4, 300, 70000, Int.MaxValue)
      highs <- Gen.listOfN(n, Gen.choose(0, range - 1))
    yield highs.zipWithIndex.map((h, i) => (h.toLong << 32) | i).toArray
    forAll(keys) { original =>
      val ours = original.clone()
      LightBuffer.sortByHigh(ours)
      val expected = original.clone()
      java.util.Arrays.sort(expected)
      Prop(ours.sameElements(expected))
    }
