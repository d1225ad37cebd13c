package tracer.io

import java.io.{IOException, Reader}
import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import scala.collection.mutable
import scala.util.control.NoStackTrace
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

/** The triangles of an OBJ file as indexed arrays, and the kinds of statement it skipped (for one
  * warning). Triangle k's corners are `corners(3k until 3k + 3)` (0-based `v` numbers), likewise
  * its `vt` and `vn` numbers, −1 three times for a triangle without them (a polygon's fan has them
  * only when every corner of the polygon has one); those two arrays are empty when no triangle
  * has any.
  *
  * @param vertices       3 doubles a `v`: x, y, z
  * @param texture        2 doubles a `vt`: u, v (0 when not written)
  * @param normals        3 doubles a `vn`, as written (not normalised)
  * @param corners        3 `v` numbers a triangle
  * @param textureCorners 3 `vt` numbers a triangle, or empty
  * @param normalCorners  3 `vn` numbers a triangle, or empty
  * @param skippedKinds   the kinds of statement skipped, in the order first met
  */
final case class ObjMesh(
    vertices: IArray[Double],
    texture: IArray[Double],
    normals: IArray[Double],
    corners: IArray[Int],
    textureCorners: IArray[Int],
    normalCorners: IArray[Int],
    skippedKinds: List[String]
):
  /** The number of triangles. */
  def faceCount: Int = corners.length / 3

  /** Vertex `i` as a point. */
  def vertex(i: Int): Vec3 = Vec3(vertices(3 * i), vertices(3 * i + 1), vertices(3 * i + 2))

  /** Triangle `k` with its corners' points, texture coordinates and normals. */
  def triangle(k: Int): ObjTriangle =
    def uv(j: Int) =
      val at = 2 * textureCorners(3 * k + j)
      SurfaceCoordinates(texture(at), texture(at + 1))
    def normal(j: Int) =
      val at = 3 * normalCorners(3 * k + j)
      Vec3(normals(at), normals(at + 1), normals(at + 2))
    val (a, b, c) = (corners(3 * k), corners(3 * k + 1), corners(3 * k + 2))
    ObjTriangle(
      vertex(a),
      vertex(b),
      vertex(c),
      Option.when(textureCorners.length > 0 && textureCorners(3 * k) >= 0)((uv(0), uv(1), uv(2))),
      Option.when(normalCorners.length > 0 && normalCorners(3 * k) >= 0)(
        (normal(0), normal(1), normal(2))
      ),
      (a, b, c)
    )

  /** Every triangle, as [[triangle]] gives it (for tests and tools; the mesh reader reads the
    * arrays).
    */
  def triangles: Vector[ObjTriangle] = Vector.tabulate(faceCount)(triangle)

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
    catch case e: IOException => Left(s"$name: ${IoFailure.reason(e)}")

  /** Reads OBJ text line by line (lines end as `BufferedReader.readLine` ends them); `name`
    * names the file in errors.
    */
  def parse(reader: Reader, name: String): Either[String, ObjMesh] =
    ObjParser(reader, name).run()

/** One pass over an OBJ file; its growing tables never leave it. */
private final class ObjParser(reader: Reader, name: String):
  // Perf: the text read in large blocks of characters (decoded by the reader, as readLine's
  // are), each line scanned in place in the block: no String per line (a quarter of the 1.3M-face
  // file's reading was decoding and copying its lines; docs/performance.md, round 8). Its words
  // found as index ranges, numbers read from the characters (Decimal.parse) and indices parsed by
  // hand; the vertices and faces in growable arrays of unboxed numbers, no object per vertex or
  // face (rounds 4 and 6).
  private val vertices     = DoubleBuffer()
  private var vertexCount  = 0
  private val texture      = DoubleBuffer()
  private var textureCount = 0
  private val normals      = DoubleBuffer()
  private var normalCount  = 0
  private val faceV        = IntBuffer()
  private val faceT        = IntBuffer()
  private val faceN        = IntBuffer()
  private var anyTextured  = false
  private var anyNormed    = false
  private val skipped      = mutable.LinkedHashSet.empty[String]
  private var lineNumber   = 0
  // Perf: the block of text: `text(pos until filled)` is read and not yet scanned; the current
  // line is text(lineStart until lineEnd). A line longer than the block grows it.
  private var text      = new Array[Char](ObjParser.Block)
  private var filled    = 0
  private var pos       = 0
  private var atEnd     = false
  private var skipLF    = false
  private var lineStart = 0
  private var lineEnd   = 0
  // Perf: the current line's words: word k is text(starts(k) until ends(k)); the arrays are
  // reused for every line and grown as needed, so a line allocates no list of words.
  private var count  = 0
  private var starts = new Array[Int](16)
  private var ends   = new Array[Int](16)
  // Perf: a face's corners, reused for every face and grown as needed.
  private var cornerV = new Array[Int](8)
  private var cornerT = new Array[Int](8)
  private var cornerN = new Array[Int](8)

  /** Reads every line: the mesh, or the first error with its line. */
  def run(): Either[String, ObjMesh] =
    try
      // Why: a loop over the lines, each scanned in place.
      while nextLine() do
        lineNumber += 1
        split()
        statement()
      Right(
        ObjMesh(
          vertices.result(),
          texture.result(),
          normals.result(),
          faceV.result(),
          if anyTextured then faceT.result() else IArray.empty[Int],
          if anyNormed then faceN.result() else IArray.empty[Int],
          skipped.toList
        )
      )
    catch case ObjParser.Malformed(message) => Left(message)

  /** Finds the next line (without its end: `\n`, `\r` or `\r\n`, as `BufferedReader.readLine`
    * ends lines) at text(lineStart until lineEnd); false at the end of the text.
    */
  private def nextLine(): Boolean =
    if skipLF then
      if pos == filled then refill(): Unit
      if pos < filled && text(pos) == '\n' then pos += 1
      skipLF = false
    // Perf: a scan for the line's end in the block, refilled when it runs out.
    var i    = pos
    var open = true
    while open do
      while i < filled && text(i) != '\n' && text(i) != '\r' do i += 1
      if i < filled || atEnd then open = false
      else i -= refill()
    if i == pos && i == filled then false
    else
      lineStart = pos
      lineEnd = i
      if i < filled then
        skipLF = text(i) == '\r'
        pos = i + 1
      else pos = i
      true

  /** Moves the unscanned text to the block's start, grows the block when that is full, and reads
    * more into it (or notes the end); returns how far the text moved.
    */
  private def refill(): Int =
    val moved = pos
    if moved > 0 then
      System.arraycopy(text, pos, text, 0, filled - pos)
      filled -= pos
      pos = 0
    if filled == text.length then text = java.util.Arrays.copyOf(text, 2 * text.length)
    val n = reader.read(text, filled, text.length - filled)
    if n < 0 then atEnd = true else filled += n
    moved

  private def string(from: Int, to: Int): String = String(text, from, to - from)

  private def word(k: Int): String = string(starts(k), ends(k))

  /** True when word k is exactly `name`. */
  private def is(k: Int, name: String): Boolean =
    val from = starts(k)
    // Why: a comparison of the few characters in place.
    var same = ends(k) - from == name.length
    var i    = 0
    while same && i < name.length do
      same = text(from + i) == name.charAt(i)
      i += 1
    same

  private def statement(): Unit =
    if count > 0 then
      if is(0, "v") then
        if count < 4 then fail("a vertex needs x, y and z")
        vertices += number(1); vertices += number(2); vertices += number(3)
        vertexCount += 1
      else if is(0, "f") then face()
      else if is(0, "vt") then
        if count < 2 then fail("a texture coordinate needs u")
        texture += number(1)
        texture += (if count > 2 then number(2) else 0.0)
        textureCount += 1
      else if is(0, "vn") then
        if count < 4 then fail("a normal needs x, y and z")
        normals += number(1); normals += number(2); normals += number(3)
        normalCount += 1
      else
        val kind = word(0)
        if !ObjReader.Ignored(kind) then skipped += kind

  /** A face: indices resolved against what is defined so far (negative ones count back from here). */
  private def face(): Unit =
    val corners = count - 1
    if corners < 3 then fail(s"a face needs at least three vertices, got $corners")
    if cornerV.length < corners then
      cornerV = new Array[Int](2 * corners); cornerT = new Array[Int](2 * corners)
      cornerN = new Array[Int](2 * corners)
    // Perf: a counted loop over the corners, no Range or closure per face.
    var k = 0
    while k < corners do
      corner(k, starts(k + 1), ends(k + 1))
      k += 1
    fan(corners)

  /** Corner k of a face, written at text(from until to) as v, v/vt, v//vn or v/vt/vn. */
  private def corner(k: Int, from: Int, to: Int): Unit =
    // Perf: one scan for the slashes in place, instead of a split into substrings per corner.
    var slash1  = to
    var slash2  = to
    var slashes = 0
    var i       = from
    while i < to do
      if text(i) == '/' then
        slashes += 1
        if slashes == 1 then slash1 = i else if slashes == 2 then slash2 = i
      i += 1
    // Only v, v/vt, v//vn and v/vt/vn: an index left empty (1/, 1/2/, 1//) is malformed.
    val emptyTexture = slashes == 1 && slash1 + 1 == to
    val emptyNormal  = slashes == 2 && slash2 + 1 == to
    if slashes > 2 || slash1 == from || emptyTexture || emptyNormal then
      fail(s"malformed face vertex '${string(from, to)}'")
    cornerV(k) = index(from, slash1, vertexCount, "vertex")
    cornerT(k) =
      if slash1 + 1 < slash2 then index(slash1 + 1, slash2, textureCount, "texture coordinate")
      else -1
    cornerN(k) =
      if slash2 + 1 < to then index(slash2 + 1, to, normalCount, "normal")
      else -1

  /** The triangles (v0, vi, vi+1) of a polygon of `corners` corners. */
  private def fan(corners: Int): Unit =
    // Perf: counted loops over the corner arrays, no Range or closure per face.
    var textured = true
    var normed   = true
    var k        = 0
    while k < corners do
      textured &&= cornerT(k) >= 0
      normed &&= cornerN(k) >= 0
      k += 1
    // Perf: the vt and vn numbers are kept only from the first face that has them on (the ones
    // before it filled with −1 then), so a file of positions only grows one array of corners, not
    // three (docs/performance.md, round 7).
    if textured && !anyTextured then faceT.fill(-1, faceV.length)
    if normed && !anyNormed then faceN.fill(-1, faceV.length)
    anyTextured ||= textured
    anyNormed ||= normed
    k = 1
    while k < corners - 1 do
      faceV += cornerV(0); faceV += cornerV(k); faceV += cornerV(k + 1)
      if anyTextured then
        if textured then
          faceT += cornerT(0); faceT += cornerT(k); faceT += cornerT(k + 1)
        else
          faceT += -1; faceT += -1; faceT += -1
      if anyNormed then
        if normed then
          faceN += cornerN(0); faceN += cornerN(k); faceN += cornerN(k + 1)
        else
          faceN += -1; faceN += -1; faceN += -1
      k += 1

  /** The 1-based or negative OBJ index at text(from until to), as a 0-based index below `defined`. */
  private def index(from: Int, to: Int, defined: Int, what: String): Int =
    // Perf: parsed by hand ([+-]?digits, as toIntOption accepts), without a substring.
    var i        = from
    val negative = i < to && text(i) == '-'
    if i < to && (text(i) == '-' || text(i) == '+') then i += 1
    var value = 0L
    val first = i
    while i < to && text(i) >= '0' && text(i) <= '9' && value <= Int.MaxValue do
      value = 10 * value + (text(i) - '0')
      i += 1
    val signed = if negative then -value else value
    if i == first || i != to || signed > Int.MaxValue || signed < Int.MinValue then
      fail(s"malformed $what index '${string(from, to)}'")
    val n        = signed.toInt
    val resolved = if n > 0 then n - 1 else if n < 0 then defined + n else -1
    if resolved < 0 || resolved >= defined then
      fail(s"$what index $n is out of range ($defined defined so far)")
    resolved

  /** Word k as a finite decimal number (Decimal's grammar: no NaN, no hex). */
  private def number(k: Int): Double =
    val value = Decimal.parse(text, starts(k), ends(k))
    if java.lang.Double.isNaN(value) || java.lang.Double.isInfinite(value) then
      fail(s"malformed number '${word(k)}'")
    value

  /** Finds the line's words, split at whitespace (`Character.isWhitespace`); a trailing comment
    * is dropped.
    */
  private def split(): Unit =
    // Perf: the words found as index ranges in place, with no substring or array per word; one
    // scan that stops at the comment (a '#' ends the words as the end of the line does).
    val end = lineEnd
    count = 0
    var i = lineStart
    while i < end && text(i) != '#' do
      while i < end && text(i) != '#' && ObjParser.space(text(i)) do i += 1
      val start = i
      while i < end && text(i) != '#' && !ObjParser.space(text(i)) do i += 1
      if i > start then
        if count == starts.length then
          starts = java.util.Arrays.copyOf(starts, 2 * count)
          ends = java.util.Arrays.copyOf(ends, 2 * count)
        starts(count) = start
        ends(count) = i
        count += 1

  private def fail(message: String): Nothing =
    // Why: unwinds the parser to run(), which turns it into a Left; it never leaves this file.
    throw ObjParser.Malformed(s"$name line $lineNumber: $message")

/** A growable array of unboxed doubles. */
private final class DoubleBuffer:
  // Perf: unboxed storage, grown by doubling (an ArrayBuffer[Double] boxes every element).
  private var data = new Array[Double](1024)
  private var size = 0

  /** Appends `d`. */
  def +=(d: Double): Unit =
    if size == data.length then data = java.util.Arrays.copyOf(data, 2 * size)
    data(size) = d
    size += 1

  /** The element at `i`. */
  def apply(i: Int): Double = data(i)

  /** The elements appended so far, in order. */
  def result(): IArray[Double] = IArray.unsafeFromArray(java.util.Arrays.copyOf(data, size))

/** A growable array of unboxed ints. */
private final class IntBuffer:
  // Perf: unboxed storage, grown by doubling, as DoubleBuffer.
  private var data = new Array[Int](1024)
  private var size = 0

  /** Appends `i`. */
  def +=(i: Int): Unit =
    if size == data.length then data = java.util.Arrays.copyOf(data, 2 * size)
    data(size) = i
    size += 1

  /** The number of elements appended so far. */
  def length: Int = size

  /** Appends `value` until there are `n` elements. */
  def fill(value: Int, n: Int): Unit =
    // Why: appended one by one, growing as `+=` does.
    while size < n do this += value

  /** The elements appended so far, in order. */
  def result(): IArray[Int] = IArray.unsafeFromArray(java.util.Arrays.copyOf(data, size))

private object ObjParser:
  /** The characters read at a time (the block grows for a longer line). */
  val Block = 1 << 16

  /** `Character.isWhitespace(c)`, without its table look-up for the printable ASCII characters. */
  def space(c: Char): Boolean = c <= ' ' && (c == ' ' || Character.isWhitespace(c)) ||
    c >= '\u007f' && Character.isWhitespace(c)

  /** The parser's internal signal; it never escapes [[ObjParser.run]]. */
  final case class Malformed(message: String) extends Exception(message) with NoStackTrace
