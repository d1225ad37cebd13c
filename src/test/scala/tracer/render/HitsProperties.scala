package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{
  Box,
  Cone,
  Csg,
  CsgOperation,
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
import tracer.testkit.Generators.unitVec

/** The shading's hit on plain doubles ([[Hits.record]]) is [[Shape.hitAt]] with
  * [[Shape.shadingNormal]], bit for bit: the point, the normal facing the ray, the shading normal,
  * the leaf and the side, on every kind of shape, from outside and inside.
  */
class HitsProperties extends ScalaCheckSuite:

  private val near  = Gen.choose(-2.0, 2.0)
  private val point = for x <- near; y <- near; z <- near yield Vec3(x, y, z)
  private val size  = Gen.choose(0.3, 2.5)

  private val triangle: Gen[Triangle] =
    for
      corners <- Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled)
      smooth  <- Gen.option(Gen.zip(unitVec, unitVec, unitVec))
    yield Triangle(corners._1, corners._2, corners._3, cornerNormals = smooth)

  private val solid: Gen[Shape] = Gen.oneOf(
    for c <- point; dx <- size; dy <- size; dz <- size yield Box(c, c + Vec3(dx, dy, dz)),
    for b <- point; axis <- unitVec; h <- size; r0 <- size; r1 <- size
    yield Cone(b, r0, b + axis * h, r1),
    for c <- point; r <- size yield Sphere(c, r)
  )

  // A mesh of a few faces on shared vertices, some of them smooth: its faces' normals come from
  // its tree's planes, or from the corners when it has no tree.
  private val mesh: Gen[Mesh] =
    for
      vertices <- Gen.listOfN(5, point)
      faces    <- Gen
        .listOfN(4, Gen.listOfN(3, Gen.choose(0, 4)))
        .map(_.filter(c => Triangle.isProper(vertices(c(0)), vertices(c(1)), vertices(c(2)))))
        .retryUntil(_.nonEmpty)
      normals <- Gen.listOfN(5, unitVec)
      smooth  <- Gen.listOfN(faces.length, Gen.oneOf(true, false))
    yield Mesh(
      IArray.from(vertices.flatMap(v => List(v.x, v.y, v.z))),
      IArray.from(faces.flatten),
      IArray.from(normals.flatMap(n => List(n.x, n.y, n.z))),
      IArray.from(faces.zip(smooth).flatMap((c, s) => if s then c else List(-1, -1, -1)))
    )

  private val shape: Gen[Shape] = Gen.frequency(
    4 -> (for c <- point; r <- size yield Sphere(c, r)),
    4 -> triangle,
    3 -> mesh,
    1 -> (for n <- unitVec; d <- near yield Plane(n, d)),
    2 -> solid,
    1 -> (for r <- size; f <- Gen.choose(0.1, 0.8); s <- size; t <- point
    yield Placed(Torus(r, r * f), Placement(s, t * 20, t))),
    2 -> (for
      op   <- Gen.oneOf(CsgOperation.values.toIndexedSeq)
      kids <- Gen.listOfN(2, solid)
    yield Csg(op, kids.toVector)),
    // A union holding (smooth) triangles, placed or not: its leaves' own shading normals.
    2 -> (for
      kids <- Gen.listOfN(2, Gen.oneOf(triangle, solid))
      s    <- size
      t    <- point
      turn <- Gen.oneOf(Vec3.Zero, t * 20)
    yield Placed(Csg(CsgOperation.Union, kids.toVector), Placement(s, turn, t)))
  )

  // Rays from anywhere around, or from inside, aimed at points near the shapes.
  private val ray: Gen[Ray] =
    for
      far    <- Gen.oneOf(6.0, 0.5)
      from   <- unitVec
      target <- point
    yield
      val origin = target + from * far * 2
      Ray(origin, (target - origin).normalisedOr(Vec3.UnitZ))

  private def bits(a: Double, b: Double) =
    java.lang.Double.doubleToRawLongBits(a) == java.lang.Double.doubleToRawLongBits(b)

  private def same(a: Vec3, x: Double, y: Double, z: Double) =
    bits(a.x, x) && bits(a.y, y) && bits(a.z, z)

  property("Hits.record gives Shape.hitAt's point, normals, leaf and side, bit for bit"):
    forAll(shape, ray) { (shape, ray) =>
      val world =
        World(Scene(Camera(Vec3(0, 0, -20), Vec3.Zero), objects = List(SceneObject(shape))))
      val query = world.newQuery()
      val i     = world.nearest(ray, query)
      i < 0 || {
        val t       = query.distance
        val o       = ray.origin
        val d       = ray.direction
        val hit     = Shape.hitAt(shape, ray, t)
        val shading = Shape.shadingNormal(shape, hit, ray)
        // With the world's mesh tree (the shading's way) and without one.
        List(world.treeOf(i), None).forall { tree =>
          Hits.record(shape, o.x, o.y, o.z, d.x, d.y, d.z, t, query, tree)
          same(hit.point, query.px, query.py, query.pz) &&
          same(hit.normal, query.nx, query.ny, query.nz) &&
          same(shading, query.sx, query.sy, query.sz) &&
          hit.leaf == query.leaf && hit.front == query.front
        }
      }
    }

  test("a mesh in a world has its own tree to take its faces' normals from"):
    val corners = IArray(0.0, 0, 0, 1, 0, 0, 0, 1, 0)
    val mesh    = Mesh(corners, IArray(0, 1, 2))
    val world   = World(
      Scene(
        Camera(Vec3(0, 0, -20), Vec3.Zero),
        objects = List(SceneObject(Sphere(Vec3.Zero, 1)), SceneObject(mesh))
      )
    )
    assert(world.treeOf(0).isEmpty)
    assert(world.treeOf(1).exists(tree => world.meshTree(mesh).exists(_ eq tree)))

  test("a mesh of many leaves: each face's normal from its tree has Mesh.plane's bits"):
    // A 12 × 12 grid of squares on a bump, two faces a square: a tree whose leaves hold the faces
    // in an order of their own, so a normal read at the face's number instead fails.
    val n        = 12
    val vertices = for j <- 0 to n; i <- 0 to n yield Vec3(i, 0.3 * Math.sin(i * 0.7 + j), j)
    def at(i: Int, j: Int) = j * (n + 1) + i
    val corners            =
      for
        j <- 0 until n; i <- 0 until n
        c <- List(
          at(i, j),
          at(i + 1, j),
          at(i, j + 1),
          at(i + 1, j),
          at(i + 1, j + 1),
          at(i, j + 1)
        )
      yield c
    val mesh  = Mesh(IArray.from(vertices.flatMap(v => List(v.x, v.y, v.z))), IArray.from(corners))
    val world =
      World(Scene(Camera(Vec3(6, 20, 6), Vec3(6, 0, 6.5)), objects = List(SceneObject(mesh))))
    world.treeOf(0) match
      case None       => fail("a mesh at the top of a scene has a tree")
      case Some(tree) =>
        assert((0 until mesh.faceCount).exists(f => tree.leafFace(f) != f))
        (0 until mesh.faceCount).foreach { f =>
          val expected = Mesh.plane(mesh.vertices, mesh.corners, f)((x, y, z, _) => List(x, y, z))
          val read     = tree.faceNormal(f)((x, y, z) => List(x, y, z))
          assert(expected.zip(read).forall(bits(_, _)), s"face $f: $read, not $expected")
        }
        // And the shading's hit on each face, from above, is Shape.hitAt's.
        val query = world.newQuery()
        (0 until mesh.faceCount).foreach { f =>
          val centre = (0 until 3).map(k => mesh.vertex(mesh.corners(3 * f + k))).reduce(_ + _) / 3
          val ray    = Ray(centre + Vec3(0.01, 10, 0.02), -Vec3.UnitY)
          assertEquals(world.nearest(ray, query), 0)
          val o = ray.origin
          val d = ray.direction
          Hits.record(mesh, o.x, o.y, o.z, d.x, d.y, d.z, query.distance, query, world.treeOf(0))
          val hit = Shape.hitAt(mesh, ray, query.distance)
          assert(same(hit.normal, query.nx, query.ny, query.nz), s"face $f")
        }
