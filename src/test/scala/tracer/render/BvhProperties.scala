package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{
  Box,
  Cone,
  Csg,
  CsgOperation,
  Cylinder,
  Mesh,
  Placed,
  Plane,
  Ray,
  Shape,
  Sphere,
  Torus,
  Triangle
}
import tracer.math.{Placement, Vec3}
import tracer.scene.{Camera, Scene, SceneObject}
import tracer.testkit.Generators.*

/** The accelerated queries of [[World]] agree with testing every shape. */
class BvhProperties extends ScalaCheckSuite:

  private val small = Gen.choose(-10.0, 10.0)
  private val point = for x <- small; y <- small; z <- small yield Vec3(x, y, z)
  // Coordinates on a coarse grid make coincident faces, shared edges and axis-aligned boxes common.
  private val gridPoint = for x <- Gen.choose(-4, 4); y <- Gen.choose(-4, 4); z <- Gen.choose(-4, 4)
  yield Vec3(x, y, z)

  private val plane: Gen[Shape] =
    for n <- Gen.oneOf(Vec3.UnitX, Vec3.UnitY, Vec3(1, 1, 0)); d <- Gen.choose(-6, 6)
    yield Plane.at(n, d)

  private val shape: Gen[Shape] = Gen.frequency(
    4 -> (for c <- point; r <- Gen.choose(0.05, 2.0) yield Sphere(c, r)),
    4 -> Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _)),
    3 -> Gen
      .zip(gridPoint, gridPoint, gridPoint)
      .retryUntil(Triangle.isProper.tupled)
      .map(Triangle(_, _, _)),
    1 -> plane
  )

  // The general route: version 3's solids, placed shapes and combinations, which the tree holds
  // by their bounds and tests through Shape.distance (or a kernel that must agree with it).
  private val size            = Gen.choose(0.2, 3.0)
  private val box: Gen[Shape] = Gen.oneOf(
    for c <- point; dx <- size; dy <- size; dz <- size yield Box(c, c + Vec3(dx, dy, dz)),
    // On the grid: faces shared with triangles and planes, so fast and general routes tie.
    for c <- gridPoint; d <- Gen.choose(1, 3) yield Box(c, c + Vec3(d, d, d))
  )
  private val cone: Gen[Shape] =
    for
      b     <- point
      axis  <- Gen.oneOf(unitVec, Gen.oneOf(Vec3.UnitX, Vec3.UnitY, Vec3.UnitZ))
      h     <- size
      r0    <- Gen.oneOf(Gen.const(0.0), size)
      r1    <- size
      open  <- Gen.oneOf(true, false)
      equal <- Gen.oneOf(true, false)
    yield if equal then Cylinder(b, b + axis * h, r1, open) else Cone(b, r0, b + axis * h, r1, open)
  private val placement: Gen[Placement] =
    for s <- Gen.choose(0.3, 3.0); r <- point; t <- point yield Placement(s, r * 18, t)
  // A torus sits at the origin: it reaches the rest of the scene placed.
  private val torus: Gen[Shape] =
    for r <- size; f <- Gen.choose(0.1, 0.8); p <- placement yield Placed(Torus(r, r * f), p)
  private val solid: Gen[Shape] =
    Gen.oneOf(box, cone, torus, for c <- point; r <- size yield Sphere(c, r))
  private val placed: Gen[Shape] =
    for s <- Gen.oneOf(box, cone, torus); p <- placement yield Placed(s, p)
  private val csg: Gen[Shape] =
    for
      op       <- Gen.oneOf(CsgOperation.values.toIndexedSeq)
      n        <- Gen.choose(1, 3)
      children <- Gen.listOfN(n, solid)
      nested   <- Gen.oneOf(true, false)
      inner    <- Gen.oneOf(CsgOperation.values.toIndexedSeq)
      moved    <- Gen.option(placement)
    yield
      val kids = children.toVector
      val tree =
        if nested && kids.size >= 2 then Csg(op, Csg(inner, kids.take(2)) +: kids.drop(2))
        else Csg(op, kids)
      moved.fold(tree: Shape)(Placed(tree, _))
  // A union holding triangles (a mesh in a combination), which only a union may.
  private val meshUnion: Gen[Shape] =
    Gen
      .listOfN(6, Gen.zip(gridPoint, gridPoint, gridPoint).retryUntil(Triangle.isProper.tupled))
      .map(ts => Csg(CsgOperation.Union, ts.map(Triangle(_, _, _)).toVector))
  // A mesh of a few faces on grid points (its own tree, MeshTree).
  private val mesh: Gen[Shape] =
    Gen
      .listOfN(8, Gen.zip(gridPoint, gridPoint, gridPoint).retryUntil(Triangle.isProper.tupled))
      .map { ts =>
        val corners = ts.flatMap((a, b, c) => List(a, b, c))
        Mesh(IArray.from(corners.flatMap(v => List(v.x, v.y, v.z))), IArray.from(corners.indices))
      }
  private val general: Gen[Shape] =
    Gen.frequency(3 -> box, 3 -> cone, 2 -> torus, 2 -> placed, 3 -> csg, 1 -> meshUnion)

  private def worldOf(shapes: Seq[Shape], eyeRays: Long = 0): World =
    World(
      Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = shapes.map(SceneObject(_))),
      eyeRays = eyeRays
    )

  // Trees of every coarseness (BvhBuilder.wholeLeaf): the finest (primary rays unknown), a short
  // render's (leaves up to about a tenth of the shapes), and the coarsest (leaves up to 64).
  private def anyTree(shapes: Gen[Seq[Shape]]): Gen[World] =
    for s <- shapes; rays <- Gen.oneOf(0L, 10L, 1L) yield worldOf(s, rays)

  private val world: Gen[World] = Gen.frequency(
    2 -> anyTree(Gen.choose(0, 300).flatMap(n => Gen.listOfN(n, shape))),
    // Fast and general shapes mixed in one tree, and a general-only tree.
    2 -> anyTree(
      Gen.choose(0, 120).flatMap(n => Gen.listOfN(n, Gen.frequency(1 -> shape, 1 -> general)))
    ),
    1 -> anyTree(Gen.choose(0, 60).flatMap(n => Gen.listOfN(n, general))),
    // One bounded shape, alone or over planes: a tree of one primitive (Bvh.nearestOfOne).
    1 -> anyTree(
      for
        one    <- Gen.frequency(2 -> shape, 2 -> general, 2 -> mesh)
        planes <- Gen.choose(0, 2).flatMap(Gen.listOfN(_, plane))
      yield planes :+ one
    )
  )

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

  property("limits at or below zero, or tiny: nearestAlong and occluded agree with every shape"):
    // The walks seed their stacks with the root at entry 0 (WideWalk.seed): a limit below that
    // must still find nothing, and the smallest limits what testing every shape finds.
    val limits = Gen.oneOf(0.0, -0.0, -1.0, Double.MinPositiveValue, 1e-9)
    forAll(world, Gen.listOfN(50, ray), limits) { (w, rays, limit) =>
      val query = w.newQuery()
      rays.foreach { r =>
        val i = w.nearestByBruteForce(r)
        val t = if i < 0 then Double.PositiveInfinity else Shape.distance(w.shape(i), r)
        val o = r.origin
        val d = r.direction
        assertEquals(
          w.nearestAlong(o.x, o.y, o.z, d.x, d.y, d.z, limit, query),
          if t <= limit then i else -1,
          r.toString
        )
        assertEquals(w.occluded(r, limit, query), t < limit, r.toString)
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

  test("a fast and a general shape at the same distance: the lowest index wins either way"):
    // A sphere and a union of just that sphere give the same t bit for bit (a union's distance is
    // its nearest child's); a box and a triangle lying on its top face meet a ray down at y = 1.
    val ball  = Sphere(Vec3(0, 0, 0), 1)
    val alone = Csg(CsgOperation.Union, Vector(ball))
    val cube  = Box(Vec3(-1, -1, -1), Vec3(1, 1, 1))
    val top   = Triangle(Vec3(-1, 1, -1), Vec3(1, 1, -1), Vec3(-1, 1, 1))
    val down  = Ray(Vec3(0, 3, 0), -Vec3.UnitY)
    for
      pair  <- List(List(ball, alone), List(cube, top))
      order <- List(pair, pair.reverse)
      many  <- List(1, 20) // alone, and spread over the leaves of a tree
    do
      val w = worldOf((0 until many).flatMap(_ => order))
      val q = w.newQuery()
      assertEquals(w.nearest(down, q), w.nearestByBruteForce(down), order.toString)
      assertEquals(w.nearest(down, q), 0, order.toString)
      assertEquals(q.distance, 2.0)

  test(
    "a degenerate input the builder cannot split evenly stops at its depth cap and still agrees"
  ):
    // Sizes and places growing geometrically: every binned split peels off the largest few, so
    // without the cap the tree would be as deep as the list is long.
    val chain = (0 until 480).map(i => Sphere(Vec3(Math.pow(2, i), 0, 0), Math.pow(2, i) / 20))
    val bvh   = Bvh(chain)
    assert(bvh.depth <= BvhBuilder.MaxDepth + 1, bvh.depth.toString) // the root and 128 levels
    assert(bvh.depth >= BvhBuilder.MaxDepth / 2, s"not degenerate: depth ${bvh.depth}")
    val w     = worldOf(chain)
    val q     = w.newQuery()
    val along =
      (0 until 480 by 7).map(i => Ray(Vec3(Math.pow(2, i), 5 * Math.pow(2, i), 0), -Vec3.UnitY))
    val back = Ray(Vec3(Math.pow(2, 481), 0, 0), -Vec3.UnitX)
    for r <- back +: along do assertEquals(w.nearest(r, q), w.nearestByBruteForce(r), r.toString)
    // And shapes that all sit at one point: one leaf, the lowest index on every tie.
    val same = worldOf((0 until 300).map(_ => Sphere(Vec3(1, 2, 3), 1)))
    assertEquals(same.nearest(Ray(Vec3(1, 2, -5), Vec3.UnitZ), same.newQuery()), 0)

  test("a large grid of spheres builds a tree, not a single leaf"):
    val spheres = for x <- 0 until 20; z <- 0 until 20 yield SceneObject(Sphere(Vec3(x, 0, z), 0.4))
    val w       = World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = spheres))
    val bvh     = Bvh(spheres.map(_.shape))
    assert(bvh.nodeCount > 100, bvh.nodeCount.toString)
    // Collapsed four-wide: at most about a third as many nodes as the binary tree.
    assert(bvh.wideNodeCount <= bvh.nodeCount / 2, s"${bvh.wideNodeCount} of ${bvh.nodeCount}")
    assertEquals(w.nearest(Ray(Vec3(5, 5, 5), -Vec3.UnitY), w.newQuery()), 105)

  test("a short render of many shapes builds a coarser tree, with the same answers"):
    val spheres        = for x <- 0 until 20; z <- 0 until 20 yield Sphere(Vec3(x, 0, z), 0.4)
    val (fine, coarse) = (Bvh(spheres), Bvh(spheres, rays = 16))
    assert(coarse.nodeCount * 4 < fine.nodeCount, s"${coarse.nodeCount} of ${fine.nodeCount}")
    assertEquals(BvhBuilder.wholeLeaf(400, 16), 25)
    assertEquals(BvhBuilder.wholeLeaf(400, 400), BvhBuilder.MaxLeaf / 2)
    assertEquals(BvhBuilder.wholeLeaf(1300000, 64), BvhBuilder.CoarseLeaf)
    assertEquals(BvhBuilder.wholeLeaf(1300000, 0), BvhBuilder.CoarseLeaf)
    val (q1, q2) = (Query(), Query())
    for x <- 0 until 20; z <- 0 until 20 do
      val (ox, oz) = (x + 0.1 * (z % 3), z - 0.05 * (x % 5))
      assertEquals(
        coarse.nearest(ox, 5, oz, 0, -1, 0, Double.PositiveInfinity, Int.MaxValue, q1),
        fine.nearest(ox, 5, oz, 0, -1, 0, Double.PositiveInfinity, Int.MaxValue, q2)
      )
      assertEquals(q1.distance, q2.distance)

  // The scene's walks with the Vector API (`TRACER_LANES=on`) against its walks one box at a time.
  property("the four-box walks (Lanes) answer as the one-box walks, bit for bit"):
    assume(LaneSupport.available, "the test JVM runs with --add-modules jdk.incubator.vector")
    val shapes =
      Gen.choose(0, 200).flatMap(n => Gen.listOfN(n, Gen.frequency(3 -> shape, 1 -> general)))
    val treeRays = Gen.oneOf(Long.MaxValue, 1L)
    forAll(shapes, Gen.listOfN(50, ray), Gen.choose(0.5, 30.0), treeRays) { (s, rays, limit, n) =>
      val (lanes, plain) = (
        Bvh(s.toIndexedSeq, lanes = _ => true, rays = n),
        Bvh(s.toIndexedSeq, lanes = _ => false, rays = n)
      )
      val (q1, q2) = (Query(), Query())
      rays.foreach { r =>
        val (o, d) = (r.origin, r.direction)
        val i      = lanes.nearest(o.x, o.y, o.z, d.x, d.y, d.z, limit, Int.MaxValue, q1)
        assertEquals(
          i,
          plain.nearest(o.x, o.y, o.z, d.x, d.y, d.z, limit, Int.MaxValue, q2),
          r.toString
        )
        assertEquals(
          java.lang.Double.doubleToRawLongBits(q1.distance),
          java.lang.Double.doubleToRawLongBits(q2.distance),
          r.toString
        )
        assertEquals(q1.face, q2.face, r.toString)
        val b = lanes.occluded(o.x, o.y, o.z, d.x, d.y, d.z, limit, q1)
        assertEquals(b, plain.occluded(o.x, o.y, o.z, d.x, d.y, d.z, limit, q2), r.toString)
        if b then assertEquals(q1.blocker, q2.blocker, r.toString)
      }
    }
