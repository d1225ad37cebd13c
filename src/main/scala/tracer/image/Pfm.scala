package tracer.image

import java.io.{BufferedOutputStream, OutputStream}
import java.nio.charset.StandardCharsets.US_ASCII
import java.nio.{ByteBuffer, ByteOrder}

/** Reads and writes Portable FloatMap images (`.pfm`): a text header, then 32-bit floats, the
  * rows from the bottom of the picture up (docs/cli.md, Floating-point output).
  */
object Pfm:

  /** Writes `raster` as a colour PFM: `PF`, the width and height, the scale `-1.0` (little-endian
    * floats), each on its own line, then red, green and blue of every pixel, the bottom row first.
    */
  def write(raster: Raster, out: OutputStream): Unit =
    val buffered = BufferedOutputStream(out, 1 << 16)
    buffered.write(s"PF\n${raster.width} ${raster.height}\n-1.0\n".getBytes(US_ASCII))
    val channels = Raster.channelsOf(raster)
    val row      = ByteBuffer.allocate(12 * raster.width).order(ByteOrder.LITTLE_ENDIAN)
    for y <- (raster.height - 1) to 0 by -1 do
      row.clear(): Unit
      row.asFloatBuffer.put(channels, 3 * raster.width * y, 3 * raster.width): Unit
      buffered.write(row.array)
    buffered.flush()

  /** Decodes a colour (`PF`) or grey (`Pf`) PFM of either byte order (the sign of the scale), its
    * values as they are (the scale's size is not applied, as most readers do); a grey image
    * becomes a raster of equal channels. Values that are not finite are refused.
    */
  def read(bytes: Array[Byte]): Either[String, Raster] =
    val tokens = header(bytes, 0, 4, Nil)
    tokens match
      case Some((List(magic, w, h, s), end)) =>
        for
          channels <- magic match
            case "PF" => Right(3)
            case "Pf" => Right(1)
            case _    => Left("expected the magic number PF or Pf at the start of the file")
          width <- w.toIntOption.filter(_ >= 1).toRight(s"expected a width of at least 1, got '$w'")
          height <- h.toIntOption
            .filter(_ >= 1)
            .toRight(s"expected a height of at least 1, got '$h'")
          _     <- Bitmap.checkSize(width, height)
          scale <- s.toDoubleOption
            .filter(v => v != 0 && v.isFinite)
            .toRight(s"expected a scale (a number other than 0), got '$s'")
          needed = 4L * channels * width * height
          _ <- Either.cond(
            bytes.length - end >= needed,
            (),
            s"expected $needed bytes of ${width}x$height samples, found ${bytes.length - end}"
          )
          raster <- values(bytes, end, width, height, channels, scale < 0)
        yield raster
      case _ => Left("expected a PFM header: PF or Pf, the width, the height and the scale")

  /** The first `count` whitespace-separated words from `at`, and where the data begins (one
    * whitespace byte after the last word).
    */
  @annotation.tailrec
  private def header(
      bytes: Array[Byte],
      at: Int,
      count: Int,
      found: List[String]
  ): Option[(List[String], Int)] =
    val start = bytes.indexWhere(b => !isSpace(b), at)
    if count == 0 then
      if at < bytes.length && isSpace(bytes(at)) then Some((found.reverse, at + 1)) else None
    else if start < 0 || start - at > 64 then None
    else
      val end = bytes.indexWhere(isSpace, start) match
        case -1 => bytes.length
        case e  => e
      if end - start > 32 then None
      else header(bytes, end, count - 1, String(bytes, start, end - start, US_ASCII) :: found)

  private def isSpace(b: Byte): Boolean = b == ' ' || b == '\n' || b == '\r' || b == '\t'

  private def values(
      bytes: Array[Byte],
      at: Int,
      width: Int,
      height: Int,
      channels: Int,
      little: Boolean
  ): Either[String, Raster] =
    val order  = if little then ByteOrder.LITTLE_ENDIAN else ByteOrder.BIG_ENDIAN
    val source = ByteBuffer
      .wrap(bytes, at, 4 * channels * width * height)
      .slice()
      .order(order)
      .asFloatBuffer
    val out = new Array[Float](3 * width * height)
    // Perf: one pass over the file's floats, bottom row first, into the raster's top-down rows.
    // Why: the first pixel that is not finite, for the message (−1 while there is none).
    var bad = -1
    var k   = 0
    while k < width * height do
      val y = height - 1 - k / width
      val x = k % width
      val i = 3 * (y * width + x)
      var c = 0
      while c < 3 do
        val v = source.get(k * channels + Math.min(c, channels - 1))
        if !v.isFinite && bad < 0 then bad = k
        out(i + c) = v
        c += 1
      k += 1
    if bad >= 0 then
      Left(
        s"the sample of pixel (${bad % width}, ${height - 1 - bad / width}) is not a finite number"
      )
    else Right(Raster.fromChannels(width, height, out))
