package tracer.image

import java.io.{ByteArrayOutputStream, DataOutputStream, OutputStream}
import java.nio.charset.StandardCharsets.US_ASCII
import java.util.concurrent.{Executors, ThreadFactory}
import java.util.zip.{Adler32, CRC32, Deflater}

/** A PNG encoder for 8-bit RGB images, written directly (PNG specification, ISO/IEC 15948).
  *
  * Perf: the JDK's image I/O loads the AWT imaging classes first, which cost each run about 80 ms
  * of start-up (docs/performance.md, step 7); this encoder needs only `java.util.zip`.
  */
private[image] object PngWriter:

  private val Signature = Array[Byte](0x89.toByte, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n')

  /** Writes `bitmap` to `out` as an 8-bit RGB PNG, each row filtered with Sub or Up ([[bestFilter]]),
    * filtering and deflating on up to `workers` threads besides this one (none for 1: this thread
    * does it all); the bytes are the same for any number.
    */
  def write(bitmap: Bitmap, out: OutputStream, workers: Int): Unit =
    val (w, h) = (bitmap.width, bitmap.height)
    out.write(Signature)
    // IHDR: size, 8 bits a sample, colour type 2 (RGB), deflate, adaptive filtering, no interlace.
    chunk(out, "IHDR") { d =>
      d.writeInt(w); d.writeInt(h); d.writeByte(8); d.writeByte(2); d.writeByte(0); d.writeByte(0);
      d.writeByte(0)
    }
    // Perf: the picture is cut into bands of rows, each filtered and deflated on a worker thread
    // (as pigz does), and this thread writes them in order, one IDAT chunk a band: the serial
    // level-6 deflate took 0.8 s of a 3840×2160 run (docs/performance.md, rounds 10 and 11). A band
    // depends only on the bitmap, so the file is the same bytes whatever the number of threads.
    val bands                          = (h + BandRows - 1) / BandRows
    val adler                          = Adler32()
    def emit(b: Int, band: Band): Unit =
      adler.update(band.filtered)
      val head = if b == 0 then ZlibHeader else Array.emptyByteArray
      val tail = if b == bands - 1 then checksum(adler) else Array.emptyByteArray
      chunk(out, "IDAT") { d => d.write(head); d.write(band.deflated); d.write(tail) }
    if bands <= 1 || workers <= 1 then (0 until bands).foreach(b => emit(b, encodeBand(bitmap, b)))
    else
      val pool    = Executors.newFixedThreadPool(Math.min(workers, bands), EncoderThreads)
      val pending = (0 until bands).map(b => pool.submit(() => encodeBand(bitmap, b)))
      try pending.indices.foreach(b => emit(b, pending(b).get()))
      finally pool.shutdownNow(): Unit
    chunk(out, "IEND")(_ => ())
    out.flush()

  /** Rows a band holds: filtered and deflated on one worker, written as one IDAT chunk. */
  private val BandRows = 32

  /** A band of rows: its filtered bytes (for the stream's checksum) and their deflated form. */
  private final class Band(val filtered: Array[Byte], val deflated: Array[Byte])

  /** The deflate level: 4, where zlib's default is 6.
    *
    * Perf: on a 3840×2160 picture of 500 spheres, level 6 took about 0.4 s more of the whole run
    * (two threads) for a file 3% smaller (docs/performance.md, round 11); level 4 against 5 takes
    * 600–634 ms to encode it instead of 817–850, about 5% of the whole run, for a file 3% larger
    * (the gallery's pictures 4–5%; round 26). Level 3 (zlib's greedy search) deflated the 720p
    * picture no faster than 4, into a file 3% larger again.
    */
  private val Level = 4

  /** A zlib stream's header for [[Level]] (RFC 1950): deflate with a 32 KiB window (`0x78`), then
    * the level's class in the top two bits (0 for levels 0–1, 1 for 2–5, 2 for 6, 3 for 7–9, as
    * zlib writes it), no preset dictionary, and the check bits that make the pair a multiple of
    * 31: `0x785e` at level 4.
    */
  private val ZlibHeader: Array[Byte] =
    val levelClass = if Level < 2 then 0 else if Level < 6 then 1 else if Level == 6 then 2 else 3
    val flags      = levelClass << 6
    Array(0x78.toByte, (flags + (31 - (0x78 * 256 + flags) % 31) % 31).toByte)

  /** The deflate window: a band's dictionary is the stream's last this many bytes before it. */
  private val Window = 32768

  /** Band `b` of `bitmap`, filtered, and deflated as the next piece of one raw deflate stream: the
    * stream's preceding 32 KiB (the tail of the rows before, filtered again here) as its dictionary,
    * ended by a sync flush (byte-aligned, so pieces join), or by the final block for the last band.
    */
  private def encodeBand(bitmap: Bitmap, b: Int): Band =
    val from     = b * BandRows
    val until    = Math.min(bitmap.height, from + BandRows)
    val last     = until == bitmap.height
    val filtered = filterBand(bitmap, from, until)
    val deflater = Deflater(Level, true)
    if from > 0 then
      // A row's filtered bytes depend only on it and the row above, so these are the stream's own.
      val rows  = Math.min(from, (Window + 3 * bitmap.width) / (3 * bitmap.width + 1))
      val tail  = filterBand(bitmap, from - rows, from)
      val start = Math.max(0, tail.length - Window)
      deflater.setDictionary(tail, start, tail.length - start)
    deflater.setInput(filtered)
    if last then deflater.finish()
    val deflated = ByteArrayOutputStream(filtered.length / 4 + 64)
    val buffer   = new Array[Byte](1 << 16)
    // Why: the JDK's Deflater is driven in a loop until it has given every byte of the piece.
    var more = true
    while more do
      val flush = if last then Deflater.NO_FLUSH else Deflater.SYNC_FLUSH
      val n     = deflater.deflate(buffer, 0, buffer.length, flush)
      deflated.write(buffer, 0, n)
      more = if last then !deflater.finished() else n == buffer.length
    deflater.end()
    Band(filtered, deflated.toByteArray)

  /** The stream's closing Adler-32 of the filtered bytes, most significant byte first. */
  private def checksum(adler: Adler32): Array[Byte] =
    val v = adler.getValue
    Array((v >>> 24).toByte, (v >>> 16).toByte, (v >>> 8).toByte, v.toByte)

  /** Rows `from` until `until` of `bitmap` as 8-bit samples, each row its filter type's byte and
    * the row filtered with [[bestFilter]]'s choice.
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

  /** The PNG filter for `row` below `above`: Sub (1) or Up (2), whichever's filtered bytes, taken
    * as signed values, have the smaller sum of magnitudes; Sub at a tie.
    *
    * Perf: the usual heuristic tries all five filters (None, Sub, Up, Average, Paeth). Choosing
    * between Sub and Up alone made smaller files on twelve of thirteen pictures measured (the
    * benchmark scenes at 3840×2160 and the gallery at 960×540 1–8% smaller, a noisy path-traced
    * picture 0.1% smaller and another 0.6% larger), at two table lookups a byte instead of five
    * and Paeth's predictor; 3840×2160 runs 3–5% sooner (docs/performance.md, round 35).
    */
  private[image] def bestFilter(row: Array[Byte], above: Array[Byte]): Int =
    var sub, up = 0L
    val n       = row.length
    // Perf: the first pixel's bytes have no left neighbour (Sub predicts 0).
    var i = 0
    while i < n && i < 3 do
      sub += Magnitude(row(i) & 0xff)
      up += Magnitude((row(i) - above(i)) & 0xff)
      i += 1
    while i < n do
      sub += Magnitude((row(i) - row(i - 3)) & 0xff)
      up += Magnitude((row(i) - above(i)) & 0xff)
      i += 1
    if sub <= up then 1 else 2

  /** The magnitude of each byte taken as a signed value: `Magnitude(v & 0xff) == |v.toByte|`. */
  private[image] val Magnitude: Array[Int] =
    Array.tabulate(256)(v => if v < 128 then v else 256 - v)

  /** Writes `row` filtered with PNG filter `filter` (1 Sub, 2 Up: [[bestFilter]]'s choices) into
    * `out` from `at`.
    */
  private[image] def applyFilter(
      filter: Int,
      row: Array[Byte],
      above: Array[Byte],
      out: Array[Byte],
      at: Int
  ): Unit =
    // Perf: a loop of its own for each filter, Sub's first pixel (no left neighbour) apart, rather
    // than the filter's and the neighbours' tests on every byte (JFR: applyFilter took 4% of a
    // 3840×2160 run's samples). Bytes wrap, so x − a is the same byte signed or not.
    val n = row.length
    // Why: the byte index of each loop below.
    var i = 0
    if filter == 1 then
      val first = Math.min(n, 3)
      System.arraycopy(row, 0, out, at, first)
      i = first
      while i < n do
        out(at + i) = (row(i) - row(i - 3)).toByte
        i += 1
    else
      while i < n do
        out(at + i) = (row(i) - above(i)).toByte
        i += 1

  /** Names the encoder's threads and lets the JVM exit without waiting for them. */
  private object EncoderThreads extends ThreadFactory:
    def newThread(task: Runnable): Thread =
      val thread = Thread(task, "tracer-png")
      thread.setDaemon(true)
      thread

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
