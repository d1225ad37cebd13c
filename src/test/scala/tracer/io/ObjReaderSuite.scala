package tracer.io

import java.io.{BufferedReader, StringReader}
import tracer.geometry.SurfaceCoordinates
import tracer.math.Vec3

/** Reading OBJ files as modelling tools write them. */
class ObjReaderSuite extends munit.FunSuite:

  private def read(text: String): Either[String, ObjMesh] =
    ObjReader.parse(BufferedReader(StringReader(text)), "m.obj")
  private def mesh(text: String): ObjMesh = read(text).fold(fail(_), identity)
  private def assertError(text: String, expected: String*)(using munit.Location): Unit =
    read(text) match
      case Right(m)      => fail(s"read $m")
      case Left(message) =>
        expected.foreach(e => assert(message.contains(e), s"'$message' does not mention '$e'"))

  private val square =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 -1\n"
  private val (p0, p1, p2, p3) = (Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0))
  private val (t0, t1, t2)     =
    (SurfaceCoordinates(0, 0), SurfaceCoordinates(1, 0), SurfaceCoordinates(1, 1))

  test("all four vertex forms of a face: v, v/vt, v//vn, v/vt/vn"):
    val first = (0, 1, 2)
    assertEquals(
      mesh(square + "f 1 2 3").triangles,
      Vector(ObjTriangle(p0, p1, p2, None, None, first))
    )
    assertEquals(
      mesh(square + "f 1/1 2/2 3/3").triangles,
      Vector(ObjTriangle(p0, p1, p2, Some((t0, t1, t2)), None, first))
    )
    val n = Vec3(0, 0, -1)
    assertEquals(
      mesh(square + "f 1//1 2//1 3//1").triangles,
      Vector(ObjTriangle(p0, p1, p2, None, Some((n, n, n)), first))
    )
    assertEquals(
      mesh(square + "f 1/1/1 2/2/1 3/3/1").triangles,
      Vector(ObjTriangle(p0, p1, p2, Some((t0, t1, t2)), Some((n, n, n)), first))
    )

  test("normals are kept as written, per corner, only when every corner of the face has one"):
    val normals = "vn 1 0 0\nvn 0 2 0\nvn 0 0 3\n"
    assertEquals(
      mesh(square + normals + "f 1//2 2//3 3//4").triangles.map(_.normals),
      Vector(Some((Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 3))))
    )
    assertEquals(mesh(square + normals + "f 1//2 2 3//4").triangles.map(_.normals), Vector(None))
    assertEquals(
      mesh(square + normals + "f 1//-1 2//-2 3//-3 4//-4").triangles.map(_.normals),
      Vector(
        Some((Vec3(0, 0, 3), Vec3(0, 2, 0), Vec3(1, 0, 0))),
        Some((Vec3(0, 0, 3), Vec3(1, 0, 0), Vec3(0, 0, -1)))
      )
    )

  test("a normal index out of range, or a short vn line, is an error naming the line"):
    assertError(square + "f 1//1 2//1 3//2", "line 10", "normal index 2 is out of range")
    assertError(square + "vn 1 0\n", "line 10", "a normal needs x, y and z")

  test("negative indices count back from the latest vertex"):
    assertEquals(
      mesh(square + "f -4/-4 -3/-3 -2/-2").triangles,
      mesh(square + "f 1/1 2/2 3/3").triangles
    )

  test("quads and n-gons become fans (v0, vi, vi+1)"):
    assertEquals(
      mesh(square + "f 1 2 3 4").triangles,
      Vector(
        ObjTriangle(p0, p1, p2, None, None, (0, 1, 2)),
        ObjTriangle(p0, p2, p3, None, None, (0, 2, 3))
      )
    )
    assertEquals(mesh(square + "v 0.5 2 0\nf 1 2 3 5 4").triangles.length, 3)

  test("a face where only some corners have vt is untextured"):
    assertEquals(mesh(square + "f 1/1 2 3/3").triangles.head.uv, None)

  test("vt without v defaults v to 0; a fourth coordinate w is ignored"):
    val m = mesh("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nvt 0.5\nvt 0.25 0.75 0\nf 1/1 2/2 3/2")
    assertEquals(m.triangles.head.uv.map(_._1), Some(SurfaceCoordinates(0.5, 0)))

  test("comments, blank lines, \\r\\n line ends and the ignored statements are fine"):
    val text =
      "# a model\r\n\r\nmtllib m.mtl\r\no thing\r\ng group\r\ns 1\r\nusemtl red\r\n" + square
        .replace("\n", "\r\n") +
        "f 1 2 3 # trailing comment\r\nl 1 2\r\np 1\r\n"
    val m = mesh(text)
    assertEquals(m.triangles.length, 1)
    assertEquals(m.skippedKinds, Nil)

  test("unknown statements are skipped and reported once each"):
    assertEquals(
      mesh(square + "vp 1 2\ncstype bspline\nvp 3 4\nf 1 2 3").skippedKinds,
      List("vp", "cstype")
    )

  test("malformed lines are errors naming the file and the line"):
    assertError(square + "f 1 2 x", "m.obj line 10", "malformed vertex index 'x'")
    assertError("v 1 2\n", "m.obj line 1", "x, y and z")
    assertError("v 1 two 3\n", "line 1", "malformed number 'two'")
    assertError("v 1 NaN 3\n", "malformed number 'NaN'")
    assertError("v 1 1e999 3\n", "malformed number")
    assertError(square + "f 1 2", "line 10", "at least three vertices, got 2")
    assertError(square + "f 1/2/3/4 2 3", "malformed face vertex")

  test("an index out of range is an error"):
    assertError(square + "f 1 2 5", "line 10", "vertex index 5 is out of range", "4 defined so far")
    assertError(square + "f 1 2 0", "vertex index 0 is out of range")
    assertError(square + "f -5 1 2", "vertex index -5")
    assertError(square + "f 1/9 2/1 3/1", "texture coordinate index 9")

  test("a missing file is an error naming it"):
    assertEquals(
      ObjReader.read(java.nio.file.Path.of("/no/such/model.obj"), "model.obj"),
      Left("model.obj: no such file")
    )
