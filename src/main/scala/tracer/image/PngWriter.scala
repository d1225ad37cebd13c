package tracer.image

import java.io.{ByteArrayOutputStream, DataOutputStream, OutputStream}
import java.nio.charset.StandardCharsets.US_ASCII
import java.util.concurrent.{Executors, ThreadFactory}
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
    // Perf: the rows are filtered in bands on worker threads while this thread deflates the bands
    // already done, in order: the deflater sees the same bytes as one row at a time, so the file
    // is the same bytes whatever the number of threads (docs/performance.md, round 8: a 960×540
    // picture's filtering took 145 ms of its 190 ms, five passes a row in code still cold).
    val bands = (h + BandRows - 1) / BandRows
    if bands <= 1 then zip.write(filterBand(bitmap, 0, h))
    else
      val pool    = Executors.newFixedThreadPool(Math.min(Workers, bands), EncoderThreads)
      val pending =
        (0 until bands).map { b =>
          val rows = b * BandRows until Math.min(h, (b + 1) * BandRows)
          pool.submit(() => filterBand(bitmap, rows.start, rows.end))
        }
      try pending.foreach(band => zip.write(band.get()))
      finally pool.shutdownNow(): Unit
    zip.finish()
    deflater.end()
    chunk(out, "IDAT")(_.write(data.toByteArray))
    chunk(out, "IEND")(_ => ())
    out.flush()

  /** Rows a band holds: filtered on one worker, deflated in one write. */
  private val BandRows = 32

  /** The encoder's worker threads at most (the deflating thread is one more). */
  private def Workers: Int = Runtime.getRuntime.availableProcessors

  /** Rows `from` until `until` of `bitmap` as 8-bit samples, each row its filter type's byte and
    * the row filtered with the filter whose bytes, taken as signed values, have the smallest sum of
    * magnitudes (the usual heuristic; the first of equal sums).
    */
  private def filterBand(bitmap: Bitmap, from: Int, until: Int): Array[Byte] =
    val stride  = 3 * bitmap.width
    val samples = Bitmap.samplesOf(bitmap)
    val maxval  = bitmap.maxval
    val band    = new Array[Byte]((until - from) * (stride + 1))
    // Perf: two row buffers, swapped after each row rather than allocated per row.
    var previous = new Array[Byte](stride)
    var current  = new Array[Byte](stride)
    if from > 0 then to8Bits(samples, (from - 1) * stride, maxval, previous)
    // Perf: a plain loop over the band's rows (a for over a range boxed its indices, round 3).
    var y = from
    while y < until do
      to8Bits(samples, y * stride, maxval, current)
      val filter = bestFilter(current, previous)
      val at     = (y - from) * (stride + 1)
      band(at) = filter.toByte
      applyFilter(filter, current, previous, band, at + 1)
      val swap = previous; previous = current; current = swap
      y += 1
    band

  /** Copies the `row.length` samples from `start` into `row` as 8-bit values. */
  private def to8Bits(samples: Array[Char], start: Int, maxval: Int, row: Array[Byte]): Unit =
    // Perf: a plain loop over the row's samples: the nested for boxed every index (a 1280×720
    // picture allocated 70 MB encoding; JFR allocation samples, docs/performance.md round 3).
    var i = 0
    while i < row.length do
      row(i) = to8Bit(samples(start + i), maxval).toByte
      i += 1

  /** The PNG filter (0 None, 1 Sub, 2 Up, 3 Average, 4 Paeth) whose filtered bytes of `row`, taken
    * as signed values, have the smallest sum of magnitudes; the first such filter at a tie.
    */
  private def bestFilter(row: Array[Byte], above: Array[Byte]): Int =
    // Perf: the five sums in one pass over the row, in five locals, with a table for the
    // magnitudes and the predictor written out: this runs cold, once a picture, where five passes
    // cost 3/4 of a 960×540 picture's encoding (the interpreter pays for every bytecode).
    var none, sub, up, average, paethSum = 0L
    val n                                = row.length
    // Perf: the first pixel's bytes have no left neighbour (a = c = 0, so Paeth predicts b).
    var i = 0
    while i < n && i < 3 do
      val x = row(i) & 0xff
      val b = above(i) & 0xff
      none += Magnitude(x)
      sub += Magnitude(x)
      up += Magnitude((x - b) & 0xff)
      average += Magnitude((x - (b >> 1)) & 0xff)
      paethSum += Magnitude((x - b) & 0xff)
      i += 1
    // Perf: the other bytes, every neighbour present.
    while i < n do
      val x = row(i) & 0xff
      val a = row(i - 3) & 0xff
      val b = above(i) & 0xff
      val c = above(i - 3) & 0xff
      none += Magnitude(x)
      sub += Magnitude((x - a) & 0xff)
      up += Magnitude((x - b) & 0xff)
      average += Magnitude((x - ((a + b) >> 1)) & 0xff)
      val pa = Math.abs(b - c)
      val pb = Math.abs(a - c)
      val pc = Math.abs(a + b - c - c)
      paethSum += Magnitude(
        (x - (if pa <= pb && pa <= pc then a else if pb <= pc then b else c)) & 0xff
      )
      i += 1
    if none <= sub && none <= up && none <= average && none <= paethSum then 0
    else if sub <= up && sub <= average && sub <= paethSum then 1
    else if up <= average && up <= paethSum then 2
    else if average <= paethSum then 3
    else 4

  /** The magnitude of each byte taken as a signed value: `Magnitude(v & 0xff) == |v.toByte|`. */
  private val Magnitude: Array[Int] = Array.tabulate(256)(v => if v < 128 then v else 256 - v)

  /** Writes `row` filtered with PNG filter `filter` (0 None, 1 Sub, 2 Up, 3 Average, 4 Paeth) into
    * `out` from `at`.
    */
  private def applyFilter(
      filter: Int,
      row: Array[Byte],
      above: Array[Byte],
      out: Array[Byte],
      at: Int
  ): Unit =
    // Perf: one pass over the row's bytes.
    var i = 0
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
      out(at + i) = (x - predicted).toByte
      i += 1

  /** Names the encoder's threads and lets the JVM exit without waiting for them. */
  private object EncoderThreads extends ThreadFactory:
    def newThread(task: Runnable): Thread =
      val thread = Thread(task, "tracer-png")
      thread.setDaemon(true)
      thread

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
