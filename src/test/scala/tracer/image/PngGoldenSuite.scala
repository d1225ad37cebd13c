package tracer.image

import java.io.{ByteArrayInputStream, ByteArrayOutputStream}
import java.nio.ByteBuffer
import java.nio.charset.StandardCharsets.US_ASCII
import java.util.zip.{CRC32, Inflater, InflaterInputStream}

/** The PNG encoder's output pinned to constants: a fixed picture's filter types, row by row, and
  * the checksum of its whole filtered stream, as the command writes it ([[PngStream]]) and as
  * [[Png.write]] does. The zlib stream is inflated first, so the constants do not depend on the
  * deflater's choices (another zlib may deflate the same bytes differently).
  */
class PngGoldenSuite extends munit.FunSuite:

  private val (width, height) = (300, 100)

  /** The picture: bands of ten rows alike down each column (noisy across: Up wins after a band's
    * first row) between bands that are smooth across and change from row to row (Sub wins).
    */
  private def pixel(x: Int, y: Int): Colour =
    if (y / 10) % 2 == 0 then Colour(((x * x * 37) % 251) / 250.0, ((x * 13) % 17) / 16.0, 0.25)
    else Colour(x / 299.0, ((y * y * 29) % 97) / 96.0, (x + y) / 398.0)

  /** The PNG of `pixel` as the command makes it: rows stored and reported top to bottom a few at
    * a time, as a render's pool finishes them, then the file written on two threads.
    */
  private def asTheCommandWrites(pixel: (Int, Int) => Colour): (Bitmap, Array[Byte]) =
    val picture = Bitmap.Builder(width, height)
    val png     = PngStream(picture)
    for at <- 0 until height by 4 do
      for y <- at until Math.min(height, at + 4); x <- 0 until width do
        picture.put(x, y, pixel(x, y))
      png.rowsDone(at, Math.min(4, height - at))
    val out = ByteArrayOutputStream()
    png.write(out, 2)
    (picture.result, out.toByteArray)

  /** The chunks of a PNG file after its signature, each its type and data, in order (each
    * chunk's CRC is the decoder's to check, and is skipped here).
    */
  private def chunks(png: Array[Byte]): List[(String, Array[Byte])] =
    List.unfold(ByteBuffer.wrap(png, 8, png.length - 8)) { buffer =>
      Option.when(buffer.hasRemaining) {
        val length = buffer.getInt
        val kind   = String(Array.fill(4)(buffer.get), US_ASCII)
        val data   = Array.fill(length)(buffer.get)
        buffer.getInt: Unit
        ((kind, data), buffer)
      }
    }

  /** The filtered stream of a PNG: its IDAT chunks' data joined and inflated (the Inflater checks
    * the zlib stream's Adler-32), the stream whole and nothing after it.
    */
  private def filtered(png: Array[Byte]): Array[Byte] =
    val data     = chunks(png).collect { case ("IDAT", data) => data }.reduce(_ ++ _)
    val inflater = Inflater()
    // The input read in one buffer, so that the inflater's remaining bytes are all that is left.
    val stream = InflaterInputStream(ByteArrayInputStream(data), inflater, data.length).readAllBytes
    assert(inflater.finished, "the zlib stream ends early")
    assertEquals(inflater.getRemaining, 0, "bytes after the zlib stream")
    inflater.end()
    stream

  /** Each row's filter type (the byte before its 3 · width filtered bytes), as digits, a string
    * for each band of 32 rows.
    */
  private def filterTypes(stream: Array[Byte]): List[String] =
    (0 until height)
      .map(y => stream(y * (3 * width + 1)).toString)
      .grouped(32)
      .map(_.mkString)
      .toList

  private def crc(bytes: Array[Byte]): Long =
    val sum = CRC32()
    sum.update(bytes)
    sum.getValue

  // The constants below were taken from the encoder as it is (its choice between Sub and Up, and
  // its bands of 32 rows, one IDAT chunk each). A deliberate change of the filter choice or of the
  // band layout must update them; any other change that moves them changes the files written.
  private val goldenFilters = List(
    "12222222221111111111122222222211",
    "11111111122222222211111111111222",
    "22222211111111111222222222111111",
    "1111"
  )
  private val goldenCrc = 0x043e6e66L

  test("the command's PNG of a fixed 300×100 picture: its chunks, filter types and stream"):
    val (bitmap, bytes) = asTheCommandWrites(pixel)
    assertEquals(chunks(bytes).map(_._1), "IHDR" :: List.fill(4)("IDAT") ::: List("IEND"))
    val stream = filtered(bytes)
    assertEquals(stream.length, height * (3 * width + 1))
    assertEquals(filterTypes(stream), goldenFilters)
    assertEquals(crc(stream), goldenCrc, s"CRC-32 0x${crc(stream).toHexString}")
    assertEquals(Png.read(bytes), Right(bitmap), "decodes to another picture")

  test("Png.write of the same picture: the same filter types and stream"):
    val (bitmap, _) = asTheCommandWrites(pixel)
    val out         = ByteArrayOutputStream()
    Png.write(bitmap, out, 1)
    val stream = filtered(out.toByteArray)
    assertEquals(filterTypes(stream), goldenFilters)
    assertEquals(crc(stream), goldenCrc)

  test("a black picture, every row a tie of Sub and Up: every row filtered with Sub"):
    val (_, bytes) = asTheCommandWrites((_, _) => Colour(0, 0, 0))
    assertEquals(filterTypes(filtered(bytes)).mkString, "1" * height)
