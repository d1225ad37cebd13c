package tracer.image

import java.io.{ByteArrayOutputStream, DataOutputStream, OutputStream}
import java.nio.charset.StandardCharsets.US_ASCII
import java.util.zip.{CRC32, Deflater, DeflaterOutputStream}

/** A PNG encoder for 8-bit RGB images, written directly (PNG specification, ISO/IEC 15948).
  *
  * Perf: the JDK's image I/O loads the AWT imaging classes first, which cost each run about 80 ms
  * of start-up (docs/performance.md, step 7); this encoder needs only `java.util.zip`.
  */
private[image] object PngWriter:

  private val Signature = Array[Byte](0x89.toByte, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n')

  /** Writes `bitmap` to `out` as an 8-bit RGB PNG, each row with the filter that compresses best. */
  def write(bitmap: Bitmap, out: OutputStream): Unit =
    val (w, h) = (bitmap.width, bitmap.height)
    out.write(Signature)
    // IHDR: size, 8 bits a sample, colour type 2 (RGB), deflate, adaptive filtering, no interlace.
    chunk(out, "IHDR") { d =>
      d.writeInt(w); d.writeInt(h); d.writeByte(8); d.writeByte(2); d.writeByte(0); d.writeByte(0);
      d.writeByte(0)
    }
    val data     = ByteArrayOutputStream()
    val deflater = Deflater(6)
    val zip      = DeflaterOutputStream(data, deflater, 1 << 16)
    val stride   = 3 * w
    val samples  = Bitmap.samplesOf(bitmap)
    // Perf: two row buffers, swapped after each row rather than allocated per row.
    var previous  = new Array[Byte](stride)
    var current   = new Array[Byte](stride)
    val candidate = new Array[Byte](stride)
    val best      = new Array[Byte](stride)
    for y <- 0 until h do
      // Perf: a plain loop over the row's samples: the nested for boxed every index (a 1280×720
      // picture allocated 70 MB encoding; JFR allocation samples, docs/performance.md round 3).
      var i = 0
      while i < stride do
        current(i) = to8Bit(samples(y * stride + i), bitmap.maxval).toByte
        i += 1
      // Perf: choose the filter with the smallest sum of absolute differences (the usual
      // heuristic) in two locals, copying the best row once, not a row per candidate.
      var bestFilter = 0
      var bestScore  = Long.MaxValue
      for filter <- 0 to 4 do
        val score = applyFilter(filter, current, previous, candidate)
        if score < bestScore then
          bestScore = score
          bestFilter = filter
          System.arraycopy(candidate, 0, best, 0, stride)
      zip.write(bestFilter)
      zip.write(best)
      val swap = previous; previous = current; current = swap
    zip.finish()
    deflater.end()
    chunk(out, "IDAT")(_.write(data.toByteArray))
    chunk(out, "IEND")(_ => ())
    out.flush()

  /** Filters a row into `filtered` with PNG filter `filter` (0 None, 1 Sub, 2 Up, 3 Average, 4 Paeth)
    * and returns the sum of the filtered bytes taken as signed values' magnitudes.
    */
  private def applyFilter(
      filter: Int,
      row: Array[Byte],
      above: Array[Byte],
      filtered: Array[Byte]
  ): Long =
    // Perf: one pass over the row's bytes, summing as it filters (called five times a row).
    var sum = 0L
    var i   = 0
    while i < row.length do
      val x         = row(i) & 0xff
      val a         = if i >= 3 then row(i - 3) & 0xff else 0
      val b         = above(i) & 0xff
      val c         = if i >= 3 then above(i - 3) & 0xff else 0
      val predicted = filter match
        case 0 => 0
        case 1 => a
        case 2 => b
        case 3 => (a + b) / 2
        case _ => paeth(a, b, c)
      val f = (x - predicted).toByte
      filtered(i) = f
      sum += Math.abs(f.toInt)
      i += 1
    sum

  private def paeth(a: Int, b: Int, c: Int): Int =
    val p  = a + b - c
    val pa = Math.abs(p - a)
    val pb = Math.abs(p - b)
    val pc = Math.abs(p - c)
    if pa <= pb && pa <= pc then a else if pb <= pc then b else c

  /** Writes one chunk: length, type, data, and the CRC of type and data. */
  private def chunk(out: OutputStream, kind: String)(body: DataOutputStream => Unit): Unit =
    val bytes = ByteArrayOutputStream()
    val data  = DataOutputStream(bytes)
    body(data)
    data.flush()
    val payload = bytes.toByteArray
    val head    = DataOutputStream(out)
    head.writeInt(payload.length)
    val typeBytes = kind.getBytes(US_ASCII)
    head.write(typeBytes)
    head.write(payload)
    val crc = CRC32()
    crc.update(typeBytes)
    crc.update(payload)
    head.writeInt(crc.getValue.toInt)
    head.flush()

  private def to8Bit(sample: Int, maxval: Int): Int =
    if maxval == 255 then sample else Colour.quantise(sample.toDouble / maxval, 255)
