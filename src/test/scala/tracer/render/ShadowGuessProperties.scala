package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{Box, Mesh, Plane, Ray, Shape, Sphere, Triangle}
import tracer.math.Vec3
import tracer.scene.{Camera, Light, Scene, SceneObject}
import tracer.testkit.Generators.unitVec

/** The point lights' last-blocker guess ([[Shadows.pointToward]], [[Bvh.blocks]], and for a light
  * with a buffer [[World.itemBlocks]]) never changes an answer: a guess that blocks is a blocker
  * the walk finds too, and a shadow ray gets the walk's share whatever was guessed before it. The
  * same for the shading point's own surface, tested first for a light behind it
  * ([[World.ownBlocks]]).
  */
class ShadowGuessProperties extends ScalaCheckSuite:

  import BufferWorlds.{point, small, terrain}

  private val shape: Gen[Shape] = Gen.frequency(
    4 -> (for c <- point; r <- Gen.choose(0.1, 1.5) yield Sphere(c, r)),
    3 -> Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _)),
    1 -> (for c <- point; d <- Gen.choose(0.2, 2.0) yield Box(c, c + Vec3(d, d, d))),
    1 -> (for n <- Gen.choose(2, 12); y <- small; b <- Gen.choose(0.0, 1.0)
    yield terrain(n, y, b)),
    1 -> Gen.choose(-6, 6).map(d => Plane.at(Vec3.UnitY, d))
  )

  private val lights = Gen.listOfN(2, point.map(p => Light(p * 2)))

  /** Worlds without light buffers, or with one for each point light (`shadowRays`). */
  private def worlds(shadowRays: Long): Gen[World] =
    for n <- Gen.choose(1, 40); shapes <- Gen.listOfN(n, shape); ls <- lights
    yield World(
      Scene(
        Camera(Vec3(0, 0, -20), Vec3.Zero),
        lights = ls.toVector,
        objects = shapes.map(SceneObject(_)).toVector
      ),
      shadowRays = shadowRays
    )

  private val world: Gen[World] = worlds(0)

  /** Points along a random segment: neighbouring shadow rays, as a row's shading points. */
  private val row: Gen[List[Vec3]] =
    for a <- point; d <- unitVec; n <- Gen.choose(5, 40); step <- Gen.choose(0.01, 0.5)
    yield List.tabulate(n)(i => a + d * (i * step))

  /** The ray from `p` toward `l`, its direction and length, or None when they coincide. */
  private def toward(p: Vec3, l: Vec3): Option[(Vec3, Double)] =
    val reach = (l - p).length
    if reach > 0 then Some(((l - p) / reach, reach)) else None

  property("a guess that blocks is a blocker the walk finds, and guessing the root is the test"):
    forAll(world, Gen.listOfN(20, Gen.zip(point, unitVec)), Gen.choose(0.5, 20.0)) {
      (w, rays, limit) =>
        val query = w.newQuery()
        val tree  = w.tree
        rays.foreach { (o, d) =>
          val walked = w.occludedAlong(o.x, o.y, o.z, d.x, d.y, d.z, limit, query)
          (0 until tree.primitiveCount).foreach { k =>
            val shape = w.shape(tree.shapeOf(k))
            val nodes = shape match
              case m: Mesh => w.meshTree(m).fold(1)(_.nodeCount)
              case _       => 1
            (0 until nodes).foreach { node =>
              val guessed = tree.blocks(k, node, o.x, o.y, o.z, d.x, d.y, d.z, limit, query)
              if guessed then assert(walked, s"$shape $node ${Ray(o, d)} $limit")
              if node == 0 then
                assertEquals(
                  guessed,
                  Shape.distance(shape, Ray(o, d)) < limit,
                  s"$shape ${Ray(o, d)}"
                )
            }
          }
        }
    }

  /** pointToward's share equals the walk's along rows of neighbouring points, whatever light,
    * depth and guess came before.
    */
  private def sharesOfRows(worlds: Gen[World]) =
    forAll(worlds, Gen.listOfN(6, Gen.zip(row, Gen.choose(0, 1), Gen.choose(0, 9)))) { (w, rows) =>
      val query   = w.newQuery()
      val shadows = Shadows(w, w.newQuery())
      rows.foreach { (points, k, depth) =>
        points.foreach { p =>
          toward(p, w.lights(k).location).foreach { (d, reach) =>
            val walked = w.occludedAlong(p.x, p.y, p.z, d.x, d.y, d.z, reach, query)
            val share  = shadows.pointToward(k, depth, p.x, p.y, p.z, d.x, d.y, d.z, reach)
            assertEquals(share, if walked then 0.0 else 1.0, s"$p $k $depth")
            assertEquals(share, shadows.pointAlong(p.x, p.y, p.z, d.x, d.y, d.z, reach))
          }
        }
      }
    }

  property("pointToward gives the walk's share, whatever light, depth and guess came before"):
    sharesOfRows(world)

  property("through the lights' buffers too, guessing the last blocking item"):
    sharesOfRows(
      worlds(Long.MaxValue).suchThat(w => w.lights.indices.forall(w.lightBuffer(_).isDefined))
    )

  property(
    "a surface's own test is its shape's (a mesh's: the face hit), and a blocker the walk finds"
  ):
    forAll(world, Gen.listOfN(30, Gen.zip(point, point))) { (w, pairs) =>
      val query = w.newQuery()
      val eye   = Vec3(0, 0, -20)
      pairs.foreach { (aim, light) =>
        val d = (aim - eye).normalisedOr(Vec3.UnitZ)
        val i = w.nearestAlong(eye.x, eye.y, eye.z, d.x, d.y, d.z, Double.PositiveInfinity, query)
        if i >= 0 then
          val face = query.face
          Hits.record(w.shape(i), eye.x, eye.y, eye.z, d.x, d.y, d.z, query.distance, query)
          val s0 = Vec3(query.px, query.py, query.pz) +
            Vec3(query.nx, query.ny, query.nz) * Shading.Epsilon
          toward(s0, light).foreach { (sd, reach) =>
            val own    = w.ownBlocks(i, face, s0.x, s0.y, s0.z, sd.x, sd.y, sd.z, reach, query)
            val target = w.shape(i) match
              case m: Mesh => m.face(face)
              case s       => s
            val tested = Shape.bounds(w.shape(i)).isDefined &&
              Shape.distance(target, Ray(s0, sd)) < reach
            assertEquals(own, tested, s"${w.shape(i)} $face ${Ray(s0, sd)} $reach")
            if own then assert(w.occludedAlong(s0.x, s0.y, s0.z, sd.x, sd.y, sd.z, reach, query))
          }
      }
    }
