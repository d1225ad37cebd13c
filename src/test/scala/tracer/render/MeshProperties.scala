package tracer.render

import java.util.concurrent.Executors
import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import scala.concurrent.ExecutionContext
import tracer.geometry.{Kernel, Mesh, Ray, Shape, Sphere, SurfaceCoordinates, Triangle}
import tracer.math.Vec3
import tracer.scene.{Camera, Scene, SceneObject}
import tracer.testkit.Generators.unitVec

/** A [[Mesh]] (one shape, its own tree) answers every query with the same bits as its faces as
  * [[Triangle]]s of their own, the way meshes were traced before (issue 23): the face and
  * distance found, the tie rule between faces, the hit's point and normal, the shading normal,
  * the texture coordinates and the shadow test; and its tree is the same built on a pool.
  */
class MeshProperties extends ScalaCheckSuite:

  // Coordinates on a coarse grid make shared edges, coplanar neighbours and repeated faces common,
  // so rays often meet two faces at exactly the same t.
  private val gridPoint =
    for x <- Gen.choose(-3, 3); y <- Gen.choose(-3, 3); z <- Gen.choose(-1, 1)
    yield Vec3(x, y, z)
  private val freePoint =
    for x <- Gen.choose(-3.0, 3.0); y <- Gen.choose(-3.0, 3.0); z <- Gen.choose(-3.0, 3.0)
    yield Vec3(x, y, z)

  /** A mesh of 1–60 faces on a pool of shared vertices, some faces smooth, some textured. */
  private val mesh: Gen[Mesh] =
    for
      count    <- Gen.choose(3, 30)
      points   <- Gen.listOfN(count, Gen.frequency(2 -> gridPoint, 1 -> freePoint))
      triples  <- Gen.listOfN(60, Gen.listOfN(3, Gen.choose(0, count - 1)))
      smooth   <- Gen.oneOf(true, false)
      textured <- Gen.oneOf(true, false)
      normals  <- Gen.listOfN(count, unitVec)
      uvs      <- Gen.listOfN(count, Gen.zip(Gen.choose(-2.0, 2.0), Gen.choose(-2.0, 2.0)))
      flags    <- Gen.listOfN(60, Gen.oneOf(true, false))
      proper = triples.filter(f => Triangle.isProper(points(f(0)), points(f(1)), points(f(2))))
      if proper.nonEmpty
    yield
      val faces                = proper ++ proper.take(2) // repeated faces: exact ties
      def numbers(on: Boolean) =
        IArray.from(
          faces.zip(flags ++ flags).flatMap((f, keep) => if on && keep then f else List(-1, -1, -1))
        )
      Mesh(
        IArray.from(points.flatMap(p => List(p.x, p.y, p.z))),
        IArray.from(faces.flatten),
        if smooth then IArray.from(normals.flatMap(n => List(n.x, n.y, n.z)))
        else IArray.empty[Double],
        if smooth then numbers(true) else IArray.empty[Int],
        if textured then IArray.from(uvs.flatMap((u, v) => List(u, v)))
        else IArray.empty[Double],
        if textured then numbers(true) else IArray.empty[Int]
      )

  /** Rays from afar, aimed at a face's corner, edge or inside, or anywhere. */
  private def rays(m: Mesh): Gen[List[Ray]] =
    val target = Gen.oneOf(
      Gen.choose(0, m.vertices.length / 3 - 1).map(m.vertex),
      for f <- Gen.choose(0, m.faceCount - 1); u <- Gen.choose(0.0, 1.0); edge <- Gen.oneOf(0, 1)
      yield
        val t = m.face(f)
        if edge == 0 then t.t0 + t.a * u else t.t0 + t.a * (u / 2) + t.b * (u / 2)
      ,
      freePoint
    )
    val ray =
      for
        o <- Gen.zip(Gen.choose(-9.0, 9.0), Gen.choose(-9.0, 9.0), Gen.choose(-9.0, 9.0));
        p <- target
      yield
        val origin = Vec3(o._1, o._2, o._3)
        (p - origin).normalised.map(Ray(origin, _))
    Gen.listOfN(30, ray).map(_.flatten)

  private def scene(objects: Seq[SceneObject]) =
    Scene(Camera(Vec3(0, 0, -10), Vec3.Zero), objects = objects.toVector)

  private def bits(d: Double) = java.lang.Double.doubleToRawLongBits(d)

  // A sphere before and after the mesh: ties and prunes across the scene's tree as well.
  private val before = SceneObject(Sphere(Vec3(0, 0, 5), 0.5))
  private val after  = SceneObject(Sphere(Vec3(1, 1, -5), 0.5))

  property(
    "nearest: the same face, distance, hit, shading normal and texture as per-face triangles"
  ):
    // The mesh's tree the finest (primary rays unknown), or the coarsest a short render builds
    // (BvhBuilder.wholeLeaf).
    forAll(mesh.flatMap(m => rays(m).map((m, _))), Gen.oneOf(0L, 1L)) { case ((m, rs), treeRays) =>
      val triangles = m.faces.toVector
      val meshWorld = World(scene(Vector(before, SceneObject(m), after)), eyeRays = treeRays)
      val oldWorld  = World(scene(before +: triangles.map(SceneObject(_)) :+ after))
      val (q1, q2)  = (meshWorld.newQuery(), oldWorld.newQuery())
      rs.foreach { r =>
        val i = meshWorld.nearest(r, q1)
        val j = oldWorld.nearest(r, q2)
        assertEquals(bits(q1.distance), bits(q2.distance), s"$m $r")
        val expected = if j <= 0 then j else if j > triangles.length then 2 else 1
        assertEquals(i, expected, s"$m $r")
        if i == 1 then
          assertEquals(q1.face, j - 1, s"the first face at the distance: $m $r")
          val hit = meshWorld.hitAt(i, r, q1)
          val old = Shape.hitAt(triangles(j - 1), r, q2.distance)
          assertEquals(hit, old.copy(leaf = j - 1))
          assertEquals(Shape.hitAt(m, r, q1.distance), hit, "the reference finds the same face")
          assertEquals(
            Shape.shadingNormal(m, hit, r),
            Shape.shadingNormal(triangles(j - 1), old, r)
          )
          assertEquals(
            Shape.surfaceCoordinates(m, hit.point, hit.leaf),
            Shape.surfaceCoordinates(triangles(j - 1), old.point)
          )
      }
    }

  property("occluded: the same answer as per-face triangles, at every limit"):
    forAll(
      mesh.flatMap(m => rays(m).map((m, _))),
      Gen.choose(0.5, 20.0),
      Gen.oneOf(0L, 1L)
    ) { case ((m, rs), limit, treeRays) =>
      val meshWorld = World(scene(Vector(SceneObject(m))), eyeRays = treeRays)
      val oldWorld  = World(scene(m.faces.map(SceneObject(_)).toVector))
      val (q1, q2)  = (meshWorld.newQuery(), oldWorld.newQuery())
      rs.foreach { r =>
        val exact = oldWorld.nearest(r, q2)
        val at    = if exact >= 0 then q2.distance else limit
        List(limit, at, Math.nextUp(at)).foreach { l =>
          assertEquals(meshWorld.occluded(r, l, q1), oldWorld.occluded(r, l, q2), s"$m $r $l")
        }
      }
    }

  property("the reference and the kernel's brute force agree with the faces, bit for bit"):
    forAll(mesh.flatMap(m => rays(m).map((m, _)))) { (m, rs) =>
      val buffer = tracer.geometry.CrossingBuffer()
      rs.foreach { r =>
        val each = m.faces.map(Shape.distance(_, r)).min
        assertEquals(bits(Shape.distance(m, r)), bits(each))
        val o = r.origin; val d = r.direction
        assertEquals(bits(Kernel.distance(m, o.x, o.y, o.z, d.x, d.y, d.z, buffer)), bits(each))
        val crossings = Shape.crossings(m, r)
        assertEquals(
          crossings.map(_.t),
          m.faces.map(Shape.distance(_, r)).filter(_.isFinite).toList.sorted
        )
        assertEquals(Kernel.collect(m, o.x, o.y, o.z, d.x, d.y, d.z, buffer, 0), crossings.length)
      }
    }

  test("a face's plane is its triangle's, bit for bit"):
    val m = mesh.sample.get
    (0 until m.faceCount).foreach { f =>
      val t = m.face(f)
      assertEquals(m.faceNormal(f), t.normal)
      assertEquals(bits(m.planes(4 * f + 3)), bits(t.distance))
    }

  test("the tree of a large mesh is the same built on a pool as on one thread"):
    // A 300 × 300 grid of squares, two faces each: above BvhBuilder.ParallelFrom.
    val n        = 300
    val vertices =
      IArray.from(for i <- 0 to n; j <- 0 to n; c <- List(i.toDouble, Math.sin(i * j), j.toDouble)
      yield c)
    def at(i: Int, j: Int) = i * (n + 1) + j
    val corners            =
      IArray.from(for
        i <- 0 until n; j <- 0 until n;
        c <- List(
          at(i, j),
          at(i + 1, j),
          at(i, j + 1),
          at(i + 1, j),
          at(i + 1, j + 1),
          at(i, j + 1)
        )
      yield c)
    val m = Mesh(vertices, corners)
    assert(m.faceCount >= BvhBuilder.ParallelFrom)
    val pool = Executors.newFixedThreadPool(3)
    // The finest tree, and the coarse one of a short render (BvhBuilder.wholeLeaf).
    try
      for treeRays <- List(Long.MaxValue, 64L) do
        val parallel =
          BvhBuilder
            .faces(m, rays = treeRays)
            .build(Some(ExecutionContext.fromExecutorService(pool)))
        val serial = BvhBuilder.faces(m, rays = treeRays).build(None)
        assertEquals(parallel.size, serial.size)
        assert(parallel.order.sameElements(serial.order))
        assert(parallel.links.sameElements(serial.links))
        assert(parallel.boxes.sameElements(serial.boxes))
        val wide   = WideTree.collapse(parallel, Some(ExecutionContext.fromExecutorService(pool)))
        val narrow = WideTree.collapse(serial)
        assertEquals(wide.size, narrow.size)
        assert(wide.boxes.sameElements(narrow.boxes))
        assert(wide.child.sameElements(narrow.child))
        assert(wide.count.sameElements(narrow.count))
    finally pool.shutdown()

  test("a big mesh's buffer items, made in parts on a pool, are those made on one thread"):
    val m = BufferWorlds.terrain(190, 0, 0.3)
    assert(m.faceCount >= BvhBuilder.ParallelFrom)
    val shapes = IndexedSeq[Shape](
      Sphere(Vec3(0, 2, 0), 0.5),
      m,
      Triangle(Vec3(0, 3, 0), Vec3(1, 3, 0), Vec3(0, 3, 1))
    )
    val pool = Executors.newFixedThreadPool(3)
    try
      for outlines <- List(true, false) do
        val parallel =
          Bvh(shapes, Some(ExecutionContext.fromExecutorService(pool))).bufferItems(outlines)
        val serial = Bvh(shapes).bufferItems(outlines)
        assertEquals(parallel.size, m.faceCount + 2)
        assert(parallel.boxes.sameElements(serial.boxes))
        assert(parallel.owner.sameElements(serial.owner))
        assert(parallel.face.sameElements(serial.face))
        assertEquals(
          parallel.corners.toList.map(java.lang.Double.doubleToRawLongBits),
          serial.corners.toList.map(java.lang.Double.doubleToRawLongBits)
        )
    finally pool.shutdown()

  test("a world whose area lights test shapes by beam builds each mesh's tree once"):
    val m     = Mesh(IArray(0.0, 0, 0, 1, 0, 0, 0, 1, 0), IArray(0, 1, 2))
    val light = tracer.scene.Light(
      Vec3(0, 5, 0),
      area = Some(tracer.scene.AreaLight(Vec3(1, 0, 0), Vec3(0, 0, 1), 2, 2))
    )
    val world = World(scene(Vector(before, SceneObject(m))).copy(lights = Vector(light)))
    assert(world.beams)
    val trees = world.each.meshes
    assertEquals(trees.length, 1)
    assert(world.each.treeOf(m).exists(_ eq trees(0)))
    assert(world.meshTree(m).exists(_ eq trees(0)), "the beams' tree is the hierarchy's")

  test("texture coordinates: a textured face's, and (0, 0)-(1, 0)-(0, 1) on one without"):
    val m = Mesh(
      IArray(0.0, 0, 0, 1, 0, 0, 0, 1, 0),
      IArray(0, 1, 2, 0, 2, 1),
      uvs = IArray(0.25, 0.5, 0.75, 0.5, 0.25, 1.0),
      cornerUvs = IArray(0, 1, 2, -1, -1, -1)
    )
    assertEquals(Shape.surfaceCoordinates(m, Vec3(0, 0, 0), 0), SurfaceCoordinates(0.25, 0.5))
    assertEquals(Shape.surfaceCoordinates(m, Vec3(0, 1, 0), 1), SurfaceCoordinates(1, 0))

  // A mesh's walks with the Vector API (`TRACER_LANES=on`) against its walks one box at a time:
  // the same face, distance and shadow answer, bit for bit, and the same blocker's node.
  property("the four-box walks (Lanes) answer as the one-box walks, bit for bit"):
    assume(LaneSupport.available, "the test JVM runs with --add-modules jdk.incubator.vector")
    val treeRays = Gen.oneOf(Long.MaxValue, 1L)
    forAll(mesh.flatMap(m => rays(m).map((m, _))), Gen.choose(0.5, 30.0), treeRays) {
      case ((m, rs), l, n) =>
        val (lanes, plain) =
          (MeshTree(m, lanes = _ => true, rays = n), MeshTree(m, lanes = _ => false, rays = n))
        val (q1, q2) = (Query(), Query())
        rs.foreach { r =>
          val (o, d) = (r.origin, r.direction)
          val t1     = lanes.nearest(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, q1)
          val t2     = plain.nearest(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, q2)
          assertEquals(bits(t1), bits(t2), s"$m $r")
          assertEquals(q1.meshFace, q2.meshFace, s"$m $r")
          val b1 = lanes.occluded(o.x, o.y, o.z, d.x, d.y, d.z, l, q1)
          assertEquals(b1, plain.occluded(o.x, o.y, o.z, d.x, d.y, d.z, l, q2), s"$m $r $l")
          if b1 then assertEquals(q1.blockerNode, q2.blockerNode, s"$m $r $l")
        }
    }
