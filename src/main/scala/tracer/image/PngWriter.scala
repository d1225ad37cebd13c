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
    val picture = Picture(bitmap.width, bitmap.height, bitmap.maxval, Bitmap.samplesOf(bitmap))
    writeBands(picture, out, workers)(_ => None)

  /** A bitmap's size, depth and samples, as the encoder reads them (a finished [[Bitmap]] or the
    * samples of a [[Bitmap.Builder]]).
    */
  private[image] final class Picture(
      val width: Int,
      val height: Int,
      val maxval: Int,
      val samples: Array[Char]
  )

  /** Writes `picture` as a PNG: each band `ready` gives as it is, the others encoded on up to
    * `workers` threads besides this one, all written in order, one IDAT chunk a band.
    */
  private[image] def writeBands(picture: Picture, out: OutputStream, workers: Int)(
      ready: Int => Option[Band]
  ): Unit =
    val (w, h) = (picture.width, picture.height)
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
    val bands = bandCount(h)
    // Why: the Adler-32 of the filtered bytes so far, each band's own folded in as it is written.
    var adler                          = 1L
    def emit(b: Int, band: Band): Unit =
      adler = Adler.combine(adler, band.adler, band.length)
      val head = if b == 0 then ZlibHeader else Array.emptyByteArray
      val tail = if b == bands - 1 then checksum(adler) else Array.emptyByteArray
      chunk(out, "IDAT") { d => d.write(head); d.write(band.deflated); d.write(tail) }
    val missing = (0 until bands).count(ready(_).isEmpty)
    if missing <= 1 || workers <= 1 then
      (0 until bands).foreach(b => emit(b, ready(b).getOrElse(encodeBand(picture, b))))
    else
      val pool    = Executors.newFixedThreadPool(Math.min(workers, missing), EncoderThreads)
      val pending =
        (0 until bands).map(b => ready(b).toLeft(pool.submit(() => encodeBand(picture, b))))
      try pending.indices.foreach(b => emit(b, pending(b).fold(identity, _.get())))
      finally pool.shutdownNow(): Unit
    chunk(out, "IEND")(_ => ())
    out.flush()

  /** Rows a band holds: filtered and deflated on one worker, written as one IDAT chunk. */
  private[image] val BandRows = 32

  /** The number of bands of a picture `height` rows high. */
  private[image] def bandCount(height: Int): Int = (height + BandRows - 1) / BandRows

  /** The row after band `b`'s last. */
  private[image] def bandEnd(picture: Picture, b: Int): Int =
    Math.min(picture.height, (b + 1) * BandRows)

  /** The rows before band `b` whose filtered bytes are its dictionary ([[encodeBand]]). */
  private def dictionaryRows(picture: Picture, b: Int): Int =
    Math.min(b * BandRows, (Window + 3 * picture.width) / (3 * picture.width + 1))

  /** The first row that encoding band `b` reads: the row above its dictionary's first, whose
    * bytes the Up filter of that row needs (row 0 has none).
    */
  private[image] def firstRead(picture: Picture, b: Int): Int =
    Math.max(0, b * BandRows - dictionaryRows(picture, b) - 1)

  /** A band of rows: the Adler-32 and length of its filtered bytes (the stream's checksum is
    * made of the bands' own), and their deflated form.
    */
  private[image] final class Band(val adler: Long, val length: Int, val deflated: Array[Byte])

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

  /** Band `b` of `picture`, filtered, and deflated as the next piece of one raw deflate stream:
    * the stream's preceding 32 KiB (the tail of the rows before, filtered again here) as its
    * dictionary, ended by a sync flush (byte-aligned, so pieces join), or by the final block for
    * the last band.
    */
  private[image] def encodeBand(picture: Picture, b: Int): Band =
    val from     = b * BandRows
    val until    = bandEnd(picture, b)
    val last     = until == picture.height
    val work     = workspaces.get()
    val length   = filterBand(picture, from, until, work, tail = false)
    val deflater = work.deflater
    deflater.reset()
    if from > 0 then
      // A row's filtered bytes depend only on it and the row above, so these are the stream's own.
      val size  = filterBand(picture, from - dictionaryRows(picture, b), from, work, tail = true)
      val start = Math.max(0, size - Window)
      deflater.setDictionary(work.tail, start, size - start)
    deflater.setInput(work.band, 0, length)
    if last then deflater.finish()
    val deflated = work.output
    deflated.reset()
    // Why: the JDK's Deflater is driven in a loop until it has given every byte of the piece.
    var more = true
    while more do
      val flush = if last then Deflater.NO_FLUSH else Deflater.SYNC_FLUSH
      val n     = deflater.deflate(work.buffer, 0, work.buffer.length, flush)
      deflated.write(work.buffer, 0, n)
      more = if last then !deflater.finished() else n == work.buffer.length
    val adler = Adler32()
    adler.update(work.band, 0, length)
    Band(adler.getValue, length, deflated.toByteArray)

  /** A thread's buffers for encoding bands, kept from one band to the next: the band's filtered
    * rows, its dictionary's, two rows of 8-bit samples, the deflater and its output.
    *
    * Perf: made afresh for every band, they were about 40 MB of garbage a 3840×2160 picture (by
    * their sizes: the filtered rows, the dictionary's rows filtered again, the deflater's
    * buffers), enough to bring a young collection into the render, which copied its 51 MB bitmap
    * (30 ms with both threads stopped, `-Xlog:gc`; docs/performance.md, round 38); a deflater
    * reset keeps zlib's state instead of allocating and clearing it again. A render pool's threads
    * end with the render, and their workspaces with them; the calling thread keeps its own for
    * the next picture (a batch's).
    */
  private final class Workspace:
    val deflater = Deflater(Level, true)
    val output   = ByteArrayOutputStream(1 << 16)
    val buffer   = new Array[Byte](1 << 16)
    // Why: each grown to the largest this thread has needed, then reused.
    var band     = Array.emptyByteArray
    var tail     = Array.emptyByteArray
    var previous = Array.emptyByteArray
    var current  = Array.emptyByteArray

  /** Each thread's [[Workspace]]. */
  private val workspaces = ThreadLocal.withInitial(() => Workspace())

  /** The stream's closing Adler-32 of the filtered bytes, most significant byte first. */
  private def checksum(adler: Long): Array[Byte] =
    Array((adler >>> 24).toByte, (adler >>> 16).toByte, (adler >>> 8).toByte, adler.toByte)

  /** Rows `from` until `until` of `picture` as 8-bit samples, each row its filter type's byte and
    * the row filtered with [[bestFilter]]'s choice, into the workspace's `tail` or `band` (grown
    * when too short); returns how many bytes they take.
    */
  private def filterBand(
      picture: Picture,
      from: Int,
      until: Int,
      work: Workspace,
      tail: Boolean
  ): Int =
    val stride  = 3 * picture.width
    val samples = picture.samples
    val maxval  = picture.maxval
    val length  = (until - from) * (stride + 1)
    if tail && work.tail.length < length then work.tail = new Array[Byte](length)
    if !tail && work.band.length < length then work.band = new Array[Byte](length)
    if work.current.length != stride then
      work.previous = new Array[Byte](stride)
      work.current = new Array[Byte](stride)
    val band = if tail then work.tail else work.band
    // Perf: two row buffers, swapped after each row rather than allocated per row.
    var previous = work.previous
    var current  = work.current
    // The row above the first: none (zeros, for the Up filter) above row 0.
    if from > 0 then to8Bits(samples, (from - 1) * stride, maxval, previous)
    else java.util.Arrays.fill(previous, 0.toByte)
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
    length

  /** Bytes of a row that each call of the filtering's inner loops takes ([[to8Bits]],
    * [[bestFilter]], [[applyFilter]]).
    *
    * Perf: the JIT's second tier (C1 with light profiling, where the start-up cache's profiles
    * send these methods) counts calls but not a loop's turns (the launcher's
    * `-XX:Tier2BackedgeNotifyFreqLog=30`), so a loop over a whole row of a 3840-pixel picture,
    * called twice a row, reached C2 only after about 2,000 rows: most of the picture was filtered
    * in C1's code. In pieces of this many bytes the same work is 23 calls a row, and C2 compiles
    * it within the first few hundred (docs/performance.md, round 38).
    */
  private val Piece = 512

  /** Runs `body` on bytes `from` until `length` of a row, a [[Piece]] at a time (each call given
    * the piece's first byte and the byte after its last).
    *
    * Perf: inline, so each caller's loop is written out in it, with no closure.
    */
  private inline def inPieces(from: Int, length: Int)(inline body: (Int, Int) => Unit): Unit =
    // Why: the first byte of the next piece.
    var at = from
    while at < length do
      val until = Math.min(length, at + Piece)
      body(at, until)
      at = until

  /** Copies the `row.length` samples from `start` into `row` as 8-bit values. */
  private def to8Bits(samples: Array[Char], start: Int, maxval: Int, row: Array[Byte]): Unit =
    inPieces(0, row.length)((from, until) => to8BitsPiece(samples, start, maxval, row, from, until))

  /** [[to8Bits]] of bytes `from` until `until` of the row. */
  private def to8BitsPiece(
      samples: Array[Char],
      start: Int,
      maxval: Int,
      row: Array[Byte],
      from: Int,
      until: Int
  ): Unit =
    // Perf: a plain loop over the row's samples: the nested for boxed every index (a 1280×720
    // picture allocated 70 MB encoding; JFR allocation samples, docs/performance.md round 3).
    var i = from
    if maxval == 255 then
      while i < until do
        row(i) = samples(start + i).toByte
        i += 1
    else
      while i < until do
        row(i) = to8Bit(samples(start + i).toInt, maxval).toByte
        i += 1

  /** The PNG filter for `row` below `above`: Sub (1) or Up (2), whichever's filtered bytes, taken
    * as signed values, have the smaller sum of magnitudes; Sub at a tie.
    *
    * Perf: the usual heuristic tries all five filters (None, Sub, Up, Average, Paeth). Choosing
    * between Sub and Up alone made smaller files on twelve of thirteen pictures measured (the
    * benchmark scenes at 3840×2160 and the gallery at 960×540 1–8% smaller, a noisy path-traced
    * picture 0.1% smaller and another 0.6% larger), at two magnitudes a byte instead of five and
    * Paeth's predictor; 3840×2160 runs 3–5% sooner (docs/performance.md, round 35).
    */
  private[image] def bestFilter(row: Array[Byte], above: Array[Byte]): Int =
    // Why: Sub's sum of magnitudes minus Up's so far.
    var balance = 0L
    inPieces(0, row.length)((from, until) => balance += weigh(row, above, from, until))
    if balance <= 0 then 1 else 2

  /** Sub's sum of magnitudes minus Up's over bytes `from` until `until` of `row`. */
  private def weigh(row: Array[Byte], above: Array[Byte], from: Int, until: Int): Long =
    // Why: the two sums, and the byte index.
    var sub, up = 0L
    var i       = from
    // Perf: the first pixel's bytes have no left neighbour (Sub predicts 0).
    while i < until && i < 3 do
      sub += magnitude(row(i))
      up += magnitude((row(i) - above(i)).toByte)
      i += 1
    while i < until do
      sub += magnitude((row(i) - row(i - 3)).toByte)
      up += magnitude((row(i) - above(i)).toByte)
      i += 1
    sub - up

  /** |b|, the magnitude of byte `b` taken as a signed value (128 for −128).
    *
    * Perf: shifts and an exclusive or, no call or table: the first bands of a render are weighed
    * before the JIT has compiled this, in the interpreter, where a table read through its
    * accessor was a call a byte.
    */
  private[image] inline def magnitude(b: Byte): Int =
    val sign = b >> 31
    (b ^ sign) - sign

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
    // Perf: Sub's first pixel (no left neighbour) apart, so the pieces' loops test nothing but
    // their index.
    val first = Math.min(row.length, 3)
    if filter == 1 then System.arraycopy(row, 0, out, at, first)
    inPieces(if filter == 1 then first else 0, row.length) { (from, until) =>
      if filter == 1 then subPiece(row, out, at, from, until)
      else upPiece(row, above, out, at, from, until)
    }

  /** Bytes `from` until `until` (from 3 on) of `row` filtered with Sub into `out` from `at`. */
  private def subPiece(row: Array[Byte], out: Array[Byte], at: Int, from: Int, until: Int): Unit =
    // Perf: a loop of its own for each filter, rather than the filter's and the neighbours' tests
    // on every byte (JFR: applyFilter took 4% of a 3840×2160 run's samples). Bytes wrap, so
    // x − a is the same byte signed or not.
    var i = from
    while i < until do
      out(at + i) = (row(i) - row(i - 3)).toByte
      i += 1

  /** Bytes `from` until `until` of `row` filtered with Up into `out` from `at`. */
  private def upPiece(
      row: Array[Byte],
      above: Array[Byte],
      out: Array[Byte],
      at: Int,
      from: Int,
      until: Int
  ): Unit =
    // Perf: as subPiece.
    var i = from
    while i < until do
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
