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
    // An index left empty is none of v, v/vt, v//vn, v/vt/vn.
    for corner <- List("1/", "1//", "1/1/", "/1") do
      assertError(square + s"f $corner 2 3", "line 10", s"malformed face vertex '$corner'")

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

  /** A reader that hands out at most a few characters a call (`sizes` in turn), so that lines and
    * their `\r\n` ends fall across the parser's reads.
    */
  private final class Trickle(text: String, sizes: Seq[Int]) extends java.io.Reader:
    // Why: a Reader's position, advanced by each read.
    private var at   = 0
    private var turn = 0

    def read(into: Array[Char], offset: Int, length: Int): Int =
      if at == text.length then -1
      else
        val n = Math.min(Math.min(length, sizes(turn % sizes.length)), text.length - at)
        turn += 1
        text.getChars(at, at + n, into, offset)
        at += n
        n
    def close(): Unit = ()

  private val lines = Vector(
    "# a comment",
    "v 0 0 0",
    "v 1 0 0 # a corner",
    "",
    "v 0 1 0",
    "\tvt 0.5  0.25 ",
    "vn 0 0 1",
    "g side\u00a0one",
    "o \u00e9t\u00e9",
    "f 1/1/1 2/1/1 3/1/1",
    "f -3 -2 -1",
    "usemtl x"
  )

  test("lines end at \\n, \\r or \\r\\n, as readLine ends them, wherever the reads end"):
    val reference = mesh(lines.mkString("\n"))
    val endings   = Vector("\n", "\r", "\r\n")
    for seed <- 0 until 50 do
      val random = scala.util.Random(seed)
      val text   = lines.map(_ + endings(random.nextInt(3))).mkString.dropRight(random.nextInt(2))
      val sizes  = Seq.fill(5)(1 + random.nextInt(7))
      ObjReader.parse(Trickle(text, sizes), "m.obj") match
        case Left(message) => fail(s"$message in ${text.replace("\r", "\\r")}")
        case Right(m)      =>
          assertEquals(m.triangles, reference.triangles, text)
          assertEquals(m.skippedKinds, reference.skippedKinds)

  test("an error names its line however the lines end"):
    assertError("v 0 0 0\r\nv 1 0 0\r\rv 1\r\n", "m.obj line 4", "x, y and z")
    assertError("v 0 0 0\rv 1 0 0\r\nf 1 2 3\n", "m.obj line 3", "vertex index 3 is out of range")

  test("Unicode whitespace separates words, as Character.isWhitespace says"):
    val m = mesh("v\u20030 0 0\nv 1\u2028 0 0\nv 0 1 0\nf 1 2 3\u3000\n")
    assertEquals(m.triangles.map(_.b), Vector(p1))
    assertError("v 0 0 0\u00a0\n", "malformed number") // a no-break space is not whitespace

  test("a line longer than the parser's block, and a file of many blocks"):
    val polygon = (1 to 20000).mkString("f ", " ", "\n")
    val ring    = (0 until 20000)
      .map(k => s"v ${Math.cos(k * 0.001)} ${Math.sin(k * 0.001)} 0.125\n")
      .mkString
    val m = mesh(ring + "# " + "x" * 100000 + "\n" + polygon)
    assertEquals(m.faceCount, 19998)
    assertEquals(m.vertex(19999), Vec3(Math.cos(19999 * 0.001), Math.sin(19999 * 0.001), 0.125))
