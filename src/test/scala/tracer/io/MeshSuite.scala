package tracer.io

import java.nio.file.Files
import tracer.geometry.{Mesh, Shape, SurfaceCoordinates, Triangle}
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3
import tracer.render.{CameraConfig, Renderer}
import tracer.scene.*
import tracer.testkit.Scenes.firstShape
import tracer.testkit.Approx

/** The `<mesh>` element: placement, texture coordinates, and pictures equal to hand-written triangles. */
class MeshSuite extends munit.FunSuite with Approx:

  private val checker = Bitmap.tabulate(4, 4)((x, y) =>
    if (x + y) % 2 == 0 then Colour(1, 0.2, 0) else Colour(0, 0.3, 1)
  )
  private val warnings             = collection.mutable.ListBuffer.empty[String]
  private def sources(obj: String) =
    SceneSources(
      _ => Right(checker),
      _ => ObjReader.parse(java.io.BufferedReader(java.io.StringReader(obj)), "m.obj"),
      warnings += _
    )
  override def beforeEach(context: BeforeEach): Unit = warnings.clear()

  private val camera =
    """<camera><location x="0" y="0.5" z="-4"/><lookat x="0" y="0.3" z="0"/></camera><light><location x="-2" y="3" z="-4"/></light>"""
  private def scene(body: String, obj: String)(using munit.Location): Scene =
    val xml  = s"<scene>$camera$body</scene>"
    val read = SceneXml.parse(xml, sources(obj)).fold(e => fail(e.describe), identity)
    tracer.testkit.SceneSchema
      .validate(xml)
      .left
      .foreach(why => fail(s"docs/scene.xsd refuses the scene: $why"))
    read

  extension (s: Scene)
    /** The first face of the first object, a mesh: the triangle it stands for. */
    private def firstFace(using munit.Location): Triangle = s.firstShape[Mesh].face(0)

  /** The faces of the scene's meshes, all told. */
  private def faceCount(s: Scene): Int = s.objects.map(o => Shape.leafCount(o.shape)).sum

  private val quad = "v -1 0 0\nv 1 0 0\nv 1 1.5 0\nv -1 1.5 0\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n"

  test(
    "each vertex is scaled, rotated about x, then y, then z, then translated (POV-Ray's rotate)"
  ):
    val placed = scene(
      """<mesh file="m.obj" scale="2"><rotate x="90" y="90" z="0"/><translate x="1" y="2" z="3"/></mesh>""",
      "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3"
    )
    val t = placed.firstFace
    // (1,0,0)·2 = (2,0,0): Rx(90) keeps it, Ry(90) gives (0,0,−2), + (1,2,3) = (1,2,1).
    assertVecClose(t.t0, Vec3(1, 2, 1), 1e-12)
    // (0,2,0): Rx(90) → (0,0,2); Ry(90) → (2,0,0); + T = (3,2,3).
    assertVecClose(t.t1, Vec3(3, 2, 3), 1e-12)
    // (0,0,2): Rx(90) → (0,−2,0); Ry(90) keeps it; + T = (1,0,3).
    assertVecClose(t.t2, Vec3(1, 0, 3), 1e-12)

  test("Rz turns x towards y"):
    val t = scene(
      """<mesh file="m.obj"><rotate x="0" y="0" z="90"/></mesh>""",
      "v 1 0 0\nv 0 0 1\nv 0 1 0\nf 1 2 3"
    ).firstFace
    assertVecClose(t.t0, Vec3(0, 1, 0), 1e-12)
    assertVecClose(t.t2, Vec3(-1, 0, 0), 1e-12)

  test("collinear faces are skipped with one warning; unknown statements warned once"):
    val s =
      scene("""<mesh file="m.obj"/>""", quad + "v 2 0 0\nvp 1\nf 1 2 3\nf 1 2 5\nf 1 5 2\nf 1 3 4")
    assertEquals(faceCount(s), 2)
    assertEquals(
      warnings.toList,
      List(
        "m.obj: skipped unsupported statements: vp",
        "m.obj: skipped 2 faces whose corners are collinear"
      )
    )

  test("mesh errors name the element and the file's own line"):
    val bad =
      SceneXml.parse(s"<scene>$camera\n<mesh file=\"m.obj\"/></scene>", sources("v 0 0 0\nf 1 1 2"))
    assertEquals(
      bad.left.map(_.describe),
      Left(
        "line 2: <mesh>: cannot read mesh file: m.obj line 2: vertex index 2 is out of range (1 defined so far)"
      )
    )
    val empty =
      SceneXml.parse(s"<scene>$camera<mesh file=\"m.obj\"/></scene>", sources("# nothing\n"))
    assert(empty.left.exists(_.message.contains("has no faces")), empty.toString)
    val noFile = SceneXml.parse(s"<scene>$camera<mesh/></scene>", sources(""))
    assert(noFile.left.exists(_.message.contains("missing attribute file")), noFile.toString)
    val badScale = SceneXml.parse(
      s"<scene>$camera<mesh file=\"m.obj\" scale=\"0\"/></scene>",
      sources(quad + "f 1 2 3")
    )
    assert(
      badScale.left.exists(_.message.contains("scale must be greater than 0")),
      badScale.toString
    )

  private def picture(s: Scene) = Renderer.render(s, CameraConfig.forCamera(s.camera, 64))

  /** Asserts that the quad as a mesh and as two hand-written triangles give the same picture. */
  private def assertMeshEqualsTriangles(surface: String)(using munit.Location): Unit =
    val fromMesh = scene(s"""<mesh file="m.obj">$surface</mesh>""", quad + "f 1 2 3 4")
    val byHand   = scene(
      s"""<triangle><corner x="-1" y="0" z="0"/><corner x="1" y="0" z="0"/><corner x="1" y="1.5" z="0"/>$surface</triangle>
         |<triangle><corner x="-1" y="0" z="0"/><corner x="1" y="1.5" z="0"/><corner x="-1" y="1.5" z="0"/>$surface</triangle>""".stripMargin,
      ""
    )
    assertEquals(picture(fromMesh), picture(byHand))

  test("a mesh renders exactly like the same triangles written as <triangle> elements"):
    assertMeshEqualsTriangles(
      """<surface diffuse="0.9"><colour r="0.8" g="0.6" b="0.2"/></surface>"""
    )

  test("a textured mesh without vt renders like textured <triangle> elements"):
    assertMeshEqualsTriangles("""<surface><texture file="c.ppm"/></surface>""")

  test("vt coordinates are interpolated and wrapped into [0, 1): 0..2 repeats the texture twice"):
    val s = scene(
      """<mesh file="m.obj"><surface><texture file="c.ppm"/></surface></mesh>""",
      quad + "f 1/1 2/2 3/3 4/4"
    )
    val t = s.firstFace
    assertEquals(
      t.textureCorners,
      Some((SurfaceCoordinates(0, 0), SurfaceCoordinates(2, 0), SurfaceCoordinates(2, 2)))
    )
    // Three quarters along a (u = 0.75), nothing along b: U = 1.5 wraps to 0.5.
    val at = tracer.geometry.Shape.surfaceCoordinates(t, t.t0 + t.a * 0.75)
    assertEqualsDouble(at.u, 0.5, 1e-12)
    assertEqualsDouble(at.v, 0.0, 1e-12)

  test("mesh files are read relative to the working directory"):
    val dir = Files.createTempDirectory("mesh")
    Files.createDirectories(dir.resolve("models"))
    Files.writeString(dir.resolve("models/q.obj"), quad + "f 1 2 3 4\n")
    val loaded = SceneXml.parse(
      s"<scene>$camera<mesh file=\"models/q.obj\"/></scene>",
      SceneSources.files(dir)
    )
    assertEquals(loaded.map(faceCount), Right(2))
    Files.delete(dir.resolve("models/q.obj")); Files.delete(dir.resolve("models"));
    Files.delete(dir)

  private val bent = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -1\nvn 1 0 -1\nvn 0 3 -3\n"

  test("smooth=\"true\" keeps the vn normals, turned by rotate only and normalised"):
    val placed = scene(
      """<mesh file="m.obj" smooth="true" scale="3"><rotate x="0" y="90" z="0"/><translate x="5" y="0" z="0"/></mesh>""",
      bent + "f 1//1 2//2 3//3"
    )
    val t    = placed.firstFace
    val half = Math.sqrt(0.5)
    // Ry(90) takes (x, y, z) to (z, y, −x).
    val (n0, n1, n2) = t.cornerNormals.getOrElse(fail("no normals"))
    assertVecClose(n0, Vec3(-1, 0, 0), 1e-12)
    assertVecClose(n1, Vec3(-half, 0, -half), 1e-12)
    assertVecClose(n2, Vec3(-half, half, 0), 1e-12)

  test("without smooth, or on a face lacking a normal at a corner, a mesh face stays flat"):
    val flat = scene("""<mesh file="m.obj"/>""", bent + "f 1//1 2//2 3//3")
    assertEquals(flat.firstFace.cornerNormals, None)
    val partly = scene("""<mesh file="m.obj" smooth="true"/>""", bent + "f 1//1 2 3//3")
    assertEquals(partly.firstFace.cornerNormals, None)
    val explicit = scene("""<mesh file="m.obj" smooth="false"/>""", bent + "f 1//1 2//2 3//3")
    assertEquals(explicit.firstFace.cornerNormals, None)

  test("a smooth face shades with its corners' normals blended by barycentric weights"):
    import tracer.geometry.{Hit, Ray}
    val t =
      scene("""<mesh file="m.obj" smooth="true"/>""", bent + "f 1//1 2//2 3//3").objects.head.shape
    val ray         = Ray(Vec3(0.25, 0.25, -1), Vec3.UnitZ)
    def at(p: Vec3) = Shape.shadingNormal(t, Hit(1, p, Vec3(0, 0, -1)), ray)
    val half        = Math.sqrt(0.5)
    assertVecClose(at(Vec3(0, 0, 0)), Vec3(0, 0, -1), 1e-12)
    assertVecClose(at(Vec3(1, 0, 0)), Vec3(half, 0, -half), 1e-12)
    // The centroid: the mean of the three unit normals, normalised.
    val mean = (Vec3(0, 0, -1) + Vec3(half, 0, -half) + Vec3(0, half, -half)) / 3
    assertVecClose(at(Vec3(1.0 / 3, 1.0 / 3, 0)), mean / mean.length, 1e-12)
    // Seen from the other side, the shading normal turns to face the ray, like the geometric one.
    val back = Ray(Vec3(0.25, 0.25, 1), -Vec3.UnitZ)
    assertVecClose(Shape.shadingNormal(t, Hit(1, Vec3.Zero, Vec3.UnitZ), back), Vec3.UnitZ, 1e-12)
