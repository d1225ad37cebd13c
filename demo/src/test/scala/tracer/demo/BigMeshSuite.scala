package tracer.demo

import java.io.{BufferedReader, StringReader}
import tracer.io.ObjReader
import tracer.geometry.{Ray, Triangle}
import tracer.math.Vec3
import tracer.render.World
import tracer.scene.{Camera, Scene, SceneObject}

/** A generated mesh of some size (a torus knot, as the loading benchmark uses, but smaller) reads
  * completely and is traced as testing every triangle would.
  */
class BigMeshSuite extends munit.FunSuite:

  private val segments = 300
  private val sides    = 40
  private val obj      = Models.obj(
    Models.torusKnot(2, 3, segments, sides, 0.25).copy(uvs = Vector.empty, normals = Vector.empty),
    "test knot"
  )

  test("a generated 24,000-triangle OBJ mesh reads with every face, corners shared by faces"):
    val mesh =
      ObjReader.parse(BufferedReader(StringReader(obj)), "knot.obj").fold(fail(_), identity)
    assertEquals(mesh.triangles.length, 2 * segments * sides)
    assertEquals(mesh.skippedKinds, Nil)
    // One vertex each, shared by the faces that use it: the faces are index triples.
    assertEquals(mesh.vertices.length, 3 * segments * sides)
    assertEquals(mesh.corners.toSet.size, segments * sides)

  test("the mesh's world finds what testing every triangle finds"):
    val mesh =
      ObjReader.parse(BufferedReader(StringReader(obj)), "knot.obj").fold(fail(_), identity)
    val shapes = mesh.triangles.collect {
      case t if Triangle.isProper(t.a, t.b, t.c) => SceneObject(Triangle(t.a, t.b, t.c))
    }
    val world  = World(Scene(Camera(Vec3(0, 3, -4), Vec3.Zero), objects = shapes.toList))
    val query  = world.newQuery()
    val random = scala.util.Random(17)
    for _ <- 0 until 300 do
      val origin =
        Vec3(random.between(-3.0, 3.0), random.between(-3.0, 3.0), random.between(-3.0, 3.0))
      val direction = (Vec3(
        random.between(-1.0, 1.0),
        random.between(-1.0, 1.0),
        random.between(-1.0, 1.0)
      ) - origin * 0.3).normalisedOr(Vec3.UnitY)
      val ray = Ray(origin, direction)
      assertEquals(world.nearest(ray, query), world.nearestByBruteForce(ray), ray.toString)
