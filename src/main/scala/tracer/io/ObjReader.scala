package tracer.io

import java.io.{BufferedReader, IOException}
import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, NoSuchFileException, Path}
import scala.collection.mutable
import tracer.geometry.SurfaceCoordinates
import tracer.math.Vec3

/** One face of an OBJ file after fanning: three corners in the file's coordinates, their
  * texture coordinates when every corner has one, their `vn` normals (as written, not
  * normalised) when every corner has one, and the corners' `v` indices (0-based).
  */
final case class ObjTriangle(
    a: Vec3,
    b: Vec3,
    c: Vec3,
    uv: Option[(SurfaceCoordinates, SurfaceCoordinates, SurfaceCoordinates)],
    normals: Option[(Vec3, Vec3, Vec3)] = None,
    vertices: (Int, Int, Int) = (0, 0, 0)
)

/** The triangles of an OBJ file, and the kinds of statement it skipped (for one warning). */
final case class ObjMesh(triangles: Vector[ObjTriangle], skippedKinds: List[String])

/** Reads Wavefront OBJ files as scene-format.md's `mesh` element describes: `v`, `vt`, `vn` and
  * `f` in all four vertex forms, negative indices, polygons as fans; the grouping and material
  * statements ignored, anything else skipped and reported.
  */
object ObjReader:

  /** Statements that are read and ignored without a warning. */
  val Ignored: Set[String] = Set("o", "g", "s", "mtllib", "usemtl", "l", "p")

  /** Reads the OBJ file `path`, naming it `name` in errors ("name line 12: …"). */
  def read(path: Path, name: String): Either[String, ObjMesh] =
    try
      val reader = Files.newBufferedReader(path, UTF_8)
      try parse(reader, name)
      finally reader.close()
    catch
      case _: NoSuchFileException => Left(s"$name: no such file")
      case e: IOException         =>
        Left(s"$name: ${Option(e.getMessage).getOrElse(e.getClass.getSimpleName)}")

  /** Reads OBJ text line by line; `name` names the file in errors. */
  def parse(reader: BufferedReader, name: String): Either[String, ObjMesh] =
    ObjParser(reader, name).run()

/** One pass over an OBJ file; its growing tables never leave it. */
private final class ObjParser(reader: BufferedReader, name: String):
  // Perf: vertices in flat growable arrays of doubles, lines split by hand (no regex), so that
  // hundreds of thousands of faces load quickly (docs/performance.md, meshes).
  private val vertices     = DoubleBuffer()
  private var vertexCount  = 0
  private val texture      = DoubleBuffer()
  private var textureCount = 0
  private val normals      = DoubleBuffer()
  private var normalCount  = 0
  private val triangles    = Vector.newBuilder[ObjTriangle]
  private val skipped      = mutable.LinkedHashSet.empty[String]
  private var lineNumber   = 0

  /** Reads every line: the mesh, or the first error with its line. */
  def run(): Either[String, ObjMesh] =
    try
      var line = reader.readLine()
      while line != null do
        lineNumber += 1
        statement(tokens(line))
        line = reader.readLine()
      Right(ObjMesh(triangles.result(), skipped.toList))
    catch case ObjParser.Malformed(message) => Left(message)

  private def statement(words: Array[String]): Unit =
    if words.nonEmpty && !words(0).startsWith("#") then
      words(0) match
        case "v" =>
          if words.length < 4 then fail("a vertex needs x, y and z")
          vertices += number(words(1)); vertices += number(words(2)); vertices += number(words(3))
          vertexCount += 1
        case "vt" =>
          if words.length < 2 then fail("a texture coordinate needs u")
          texture += number(words(1));
          texture += (if words.length > 2 then number(words(2)) else 0.0)
          textureCount += 1
        case "vn" =>
          if words.length < 4 then fail("a normal needs x, y and z")
          normals += number(words(1)); normals += number(words(2)); normals += number(words(3))
          normalCount += 1
        case "f"                             => face(words)
        case kind if ObjReader.Ignored(kind) => ()
        case kind                            => skipped += kind

  /** A face: indices resolved against what is defined so far (negative ones count back from here). */
  private def face(words: Array[String]): Unit =
    val corners = words.length - 1
    if corners < 3 then fail(s"a face needs at least three vertices, got $corners")
    val v = new Array[Int](corners)
    val t = new Array[Int](corners)
    val n = new Array[Int](corners)
    for k <- 0 until corners do
      val parts = words(k + 1).split("/", -1)
      if parts.length > 3 || parts(0).isEmpty then fail(s"malformed face vertex '${words(k + 1)}'")
      v(k) = index(parts(0), vertexCount, "vertex")
      t(k) =
        if parts.length > 1 && parts(1).nonEmpty then
          index(parts(1), textureCount, "texture coordinate")
        else -1
      n(k) =
        if parts.length > 2 && parts(2).nonEmpty then index(parts(2), normalCount, "normal")
        else -1
    fan(v, t, n)

  /** The triangles (v0, vi, vi+1) of a polygon. */
  private def fan(v: Array[Int], t: Array[Int], n: Array[Int]): Unit =
    val textured = t.forall(_ >= 0)
    val normed   = n.forall(_ >= 0)
    for k <- 1 until v.length - 1 do
      val uv      = Option.when(textured)((uvAt(t(0)), uvAt(t(k)), uvAt(t(k + 1))))
      val corners = Option.when(normed)((normalAt(n(0)), normalAt(n(k)), normalAt(n(k + 1))))
      triangles += ObjTriangle(
        vertexAt(v(0)),
        vertexAt(v(k)),
        vertexAt(v(k + 1)),
        uv,
        corners,
        (v(0), v(k), v(k + 1))
      )

  private def vertexAt(i: Int) = Vec3(vertices(3 * i), vertices(3 * i + 1), vertices(3 * i + 2))
  private def normalAt(i: Int) = Vec3(normals(3 * i), normals(3 * i + 1), normals(3 * i + 2))
  private def uvAt(i: Int)     = SurfaceCoordinates(texture(2 * i), texture(2 * i + 1))

  /** A 1-based or negative OBJ index, as a 0-based index below `defined`. */
  private def index(text: String, defined: Int, what: String): Int =
    val i        = text.toIntOption.getOrElse(fail(s"malformed $what index '$text'"))
    val resolved = if i > 0 then i - 1 else if i < 0 then defined + i else -1
    if resolved < 0 || resolved >= defined then
      fail(s"$what index $i is out of range ($defined defined so far)")
    resolved

  /** A finite decimal number: digits, sign, point and exponent only (no NaN, no hex). */
  private def number(text: String): Double =
    val plain = text.nonEmpty && text.forall(c =>
      c.isDigit || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E'
    )
    val value = if plain then text.toDoubleOption else None
    value.filter(_.isFinite).getOrElse(fail(s"malformed number '$text'"))

  /** The line's words, split at spaces and tabs; a trailing comment is dropped. */
  private def tokens(line: String): Array[String] =
    val end = line.indexOf('#') match
      case -1 => line.length
      case i  => i
    val words = mutable.ArrayBuffer.empty[String]
    var i     = 0
    while i < end do
      while i < end && Character.isWhitespace(line.charAt(i)) do i += 1
      val start = i
      while i < end && !Character.isWhitespace(line.charAt(i)) do i += 1
      if i > start then words += line.substring(start, i)
    words.toArray

  private def fail(message: String): Nothing =
    throw ObjParser.Malformed(s"$name line $lineNumber: $message")

/** A growable array of unboxed doubles. */
private final class DoubleBuffer:
  private var data = new Array[Double](1024)
  private var size = 0

  /** Appends `d`. */
  def +=(d: Double): Unit =
    if size == data.length then data = java.util.Arrays.copyOf(data, 2 * size)
    data(size) = d
    size += 1

  /** The element at `i`. */
  def apply(i: Int): Double = data(i)

private object ObjParser:
  /** The parser's internal signal; it never escapes [[ObjParser.run]]. */
  final case class Malformed(message: String) extends Exception(message, null, false, false)
