package tracer.image

import java.io.{BufferedOutputStream, ByteArrayOutputStream, OutputStream}
import java.nio.charset.StandardCharsets.US_ASCII
import scala.util.control.NoStackTrace

/** The two PPM encodings: P3 (ASCII samples) and P6 (binary samples). */
enum PpmFormat:
  /** ASCII samples, at most 70 characters a line. */
  case Ascii

  /** Binary samples: one byte each for maxval ≤ 255, else two, most significant first. */
  case Binary

/** Reads and writes PPM images (course text section 10; rendering.md, PPM). */
object Ppm:

  /** The longest line a P3 writer may produce. */
  val MaxAsciiLine: Int = 70

  /** Decodes a P3 or P6 image, or says what was expected where: no exception, no partial bitmap.
    *
    * Header fields may be separated by any whitespace and by `#` comments; P3 samples may have
    * comments between them. Anything after the last sample is ignored, as netpbm does.
    */
  def read(bytes: Array[Byte]): Either[String, Bitmap] = PpmReader(bytes).read()

  /** Writes `bitmap` in `format` to `out`, with a `# CREATOR: tracer` comment line. */
  def write(bitmap: Bitmap, out: OutputStream, format: PpmFormat = PpmFormat.Binary): Unit =
    val buffered = BufferedOutputStream(out, 1 << 16)
    val magic    = if format == PpmFormat.Ascii then "P3" else "P6"
    val header = s"$magic\n# CREATOR: tracer\n${bitmap.width} ${bitmap.height}\n${bitmap.maxval}\n"
    buffered.write(header.getBytes(US_ASCII))
    format match
      case PpmFormat.Binary => writeBinary(Bitmap.samplesOf(bitmap), bitmap.maxval, buffered)
      case PpmFormat.Ascii  => writeAscii(Bitmap.samplesOf(bitmap), buffered)
    buffered.flush()

  /** The bytes of `bitmap` as a PPM file in `format`. */
  def encode(bitmap: Bitmap, format: PpmFormat = PpmFormat.Binary): Array[Byte] =
    val out = ByteArrayOutputStream()
    write(bitmap, out, format)
    out.toByteArray

  private def writeBinary(samples: Array[Char], maxval: Int, out: OutputStream): Unit =
    val wide = maxval > 255
    samples.foreach { s =>
      if wide then out.write(s >> 8)
      out.write(s & 0xff)
    }

  private def writeAscii(samples: Array[Char], out: OutputStream): Unit =
    // Fill each line with as many samples as fit in MaxAsciiLine characters.
    val line = StringBuilder()
    samples.foreach { s =>
      val text = s.toInt.toString
      if line.nonEmpty && line.length + 1 + text.length > MaxAsciiLine then
        out.write(line.append('\n').toString.getBytes(US_ASCII))
        line.clear()
      if line.nonEmpty then line.append(' ')
      line.append(text)
    }
    if line.nonEmpty then out.write(line.append('\n').toString.getBytes(US_ASCII))

/** A one-shot PPM decoder over the bytes of a file; its cursor never leaves this class. */
private final class PpmReader(bytes: Array[Byte]):
  private var pos = 0 // Why: the decoder's cursor; one parse per reader, and it never escapes.

  /** The decoded image, or what was expected where. */
  def read(): Either[String, Bitmap] =
    try Right(parse())
    catch case PpmReader.Malformed(message) => Left(message)

  private def parse(): Bitmap =
    val ascii  = magic()
    val width  = headerField("width", 1, Int.MaxValue)
    val height = headerField("height", 1, Int.MaxValue)
    Bitmap.checkSize(width, height).left.foreach(msg => fail(msg))
    val maxval = headerField("maxval", 1, 65535)
    if ascii then asciiRaster(width, height, maxval) else binaryRaster(width, height, maxval)

  private def magic(): Boolean =
    if bytes.length < 2 || bytes(0) != 'P' || (bytes(1) != '3' && bytes(1) != '6') then
      fail("expected the magic number P3 or P6 at the start of the file")
    pos = 2
    bytes(1) == '3'

  /** Reads whitespace and comments, then a decimal field that must end in whitespace. */
  private def headerField(name: String, min: Int, max: Int): Int =
    if pos < bytes.length && !isSpace(bytes(pos)) && bytes(pos) != '#' then
      fail(s"expected whitespace before the $name ${where(pos)}, found ${shown(pos)}")
    skipSpaceAndComments()
    val value = number(s"the $name (a decimal integer from $min to $max)", max)
    if value < min then fail(s"expected the $name to be at least $min ${where(pos)}, found $value")
    if pos >= bytes.length then
      fail(s"expected whitespace after the $name ${where(pos)}, found the end of the file")
    if !isSpace(bytes(pos)) && bytes(pos) != '#' then
      fail(s"expected whitespace after the $name ${where(pos)}, found ${shown(pos)}")
    value

  private def binaryRaster(width: Int, height: Int, maxval: Int): Bitmap =
    // After maxval comes exactly one whitespace character, then the samples.
    if bytes(pos) == '#' then
      fail(s"expected one whitespace character after the maxval ${where(pos)}, found '#'")
    pos += 1
    val bytesPerSample = if maxval > 255 then 2 else 1
    val needed         = 3L * width * height * bytesPerSample
    if bytes.length - pos < needed then
      fail(
        s"expected $needed bytes of pixel data after the header, found ${bytes.length - pos} (truncated file)"
      )
    val start   = pos
    val count   = 3 * width * height
    val samples = new Array[Char](count)
    // Perf: one pass of primitive loads into the bitmap's own array: a texture is decoded before
    // every render, mostly in the interpreter (docs/performance.md, round 7: the movie).
    var i = 0
    while i < count do
      val s =
        if bytesPerSample == 1 then bytes(start + i) & 0xff
        else ((bytes(start + 2 * i) & 0xff) << 8) | (bytes(start + 2 * i + 1) & 0xff)
      if s > maxval then
        fail(s"sample ${i + 1} ${pixelOf(i, width)} is $s, above the maxval $maxval")
      samples(i) = s.toChar
      i += 1
    Bitmap.owning(width, height, maxval, samples)

  private def asciiRaster(width: Int, height: Int, maxval: Int): Bitmap =
    val count = 3 * width * height
    // Each sample takes at least one digit and one separator: refuse hopeless sizes before allocating.
    if bytes.length - pos < 2L * count - 1 then
      fail(
        s"expected $count samples after the header, but the file is too short to hold them (truncated file)"
      )
    // Perf: one pass over the samples into the bitmap's own array (a 4K ASCII picture has 25
    // million).
    val samples = new Array[Char](count)
    var i       = 0
    while i < count do
      val before = pos
      skipSpaceAndComments()
      if pos == before then
        fail(s"expected whitespace before sample ${i + 1} ${where(pos)}, found ${shown(pos)}")
      if pos >= bytes.length then
        fail(s"expected $count samples, found $i before the end of the file (truncated file)")
      val s = number(s"sample ${i + 1} ${pixelOf(i, width)} (a decimal integer)", Int.MaxValue)
      if s > maxval then
        fail(s"sample ${i + 1} ${pixelOf(i, width)} is $s, above the maxval $maxval ${where(pos)}")
      if pos < bytes.length && !isSpace(bytes(pos)) && bytes(pos) != '#' then
        fail(s"expected whitespace after sample ${i + 1} ${where(pos)}, found ${shown(pos)}")
      samples(i) = s.toChar
      i += 1
    Bitmap.owning(width, height, maxval, samples)

  // Perf: byte loops that move the cursor, no slices or strings.
  private def skipSpaceAndComments(): Unit =
    while pos < bytes.length && (isSpace(bytes(pos)) || bytes(pos) == '#') do
      if bytes(pos) == '#' then
        while pos < bytes.length && bytes(pos) != '\n' && bytes(pos) != '\r' do pos += 1
      else pos += 1

  /** A run of decimal digits at the cursor whose value is at most `max`. */
  private def number(what: String, max: Int): Int =
    if pos >= bytes.length then fail(s"expected $what ${where(pos)}, found the end of the file")
    if !isDigit(bytes(pos)) then fail(s"expected $what ${where(pos)}, found ${shown(pos)}")
    val start = pos
    // Perf: digits accumulated in place (capped above `max`, so it cannot overflow).
    var value = 0L
    while pos < bytes.length && isDigit(bytes(pos)) do
      value = Math.min(value * 10 + (bytes(pos) - '0'), max.toLong + 1)
      pos += 1
    if value > max then fail(s"expected $what ${where(start)}, found a number above $max")
    value.toInt

  private def isSpace(b: Byte): Boolean =
    b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == 0x0b || b == 0x0c
  private def isDigit(b: Byte): Boolean = b >= '0' && b <= '9'

  private def where(at: Int): String =
    val line = 1 + (0 until Math.min(at, bytes.length)).count(i => bytes(i) == '\n')
    s"at line $line (byte $at)"

  private def shown(at: Int): String =
    if at >= bytes.length then "the end of the file"
    else
      val b = bytes(at) & 0xff
      if b >= 0x21 && b < 0x7f then s"'${b.toChar}'" else f"byte 0x$b%02x"

  private def pixelOf(sample: Int, width: Int): String =
    val pixel = sample / 3
    s"(pixel ${pixel % width}, ${pixel / width})"

  // Why: unwinds the decoder to `read`, which turns it into a Left; it never leaves this file.
  private def fail(message: String): Nothing = throw PpmReader.Malformed(message)

private object PpmReader:
  /** The reader's internal signal; it never escapes [[PpmReader.read]]. */
  final case class Malformed(message: String) extends Exception(message) with NoStackTrace
