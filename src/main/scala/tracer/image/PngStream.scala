package tracer.image

import java.io.OutputStream
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.atomic.{
  AtomicInteger,
  AtomicIntegerArray,
  AtomicLong,
  AtomicReferenceArray
}
import tracer.image.PngWriter.{
  Band,
  BandRows,
  bandCount,
  bandEnd,
  encodeBand,
  firstRead,
  writeBands
}

/** A PNG of the bitmap that `picture` is building, its bands filtered and deflated while the
  * bitmap is filled: once half of its rows are stored, each band as soon as every row it reads
  * is ([[rowsDone]]), on a thread that reports rows. [[write]] then writes the file, encoding any
  * band not yet encoded. The file is the same bytes as [[Png.write]] makes of the finished
  * bitmap, whatever the order in which the rows were stored.
  *
  * Perf: a render's rows are finished a few at a time on the pool's threads, so most of the
  * picture is encoded before the last row is, by code the JIT has compiled by then, instead of
  * after it in code mostly not yet compiled (a 3840×2160 picture took about 150 ms to encode
  * then, 62 compiled). Not before half of the rows: the encoder's code then reaches the JIT
  * after the render's own (1280×720 mesh-80000: 52 ms slower with bands encoded from the first
  * row, 2 ms with them from the middle; docs/performance.md, round 38).
  */
final class PngStream(picture: Bitmap.Builder):
  private val image =
    PngWriter.Picture(picture.width, picture.height, picture.maxval, picture.samples)
  private val bands = bandCount(image.height)
  // How many of the rows each band reads are not yet stored; a band is encoded when its count
  // reaches 0, by the thread that brought it there (the atomic count orders the rows' stores,
  // from whichever thread, before the band's reads of them).
  private val waiting =
    AtomicIntegerArray(Array.tabulate(bands)(b => bandEnd(image, b) - firstRead(image, b)))
  private val encoded = AtomicReferenceArray[Band](bands)
  // The bands whose rows are all stored and which no thread has taken to encode yet.
  private val ready = ConcurrentLinkedQueue[Integer]()
  // How many rows are stored.
  private val stored = AtomicInteger()
  // Perf: bands are encoded only once this many rows are stored (those ready by then at once),
  // so the encoder's code is not compiled while the render's own code is (the JIT's window at a
  // render's start); see PngWriter.Piece.
  private val from = image.height / 2
  // The nanoseconds spent encoding bands in rowsDone, on all threads.
  private val spent = AtomicLong()

  /** Reports rows `at` until `at + count` of the bitmap stored (each row once), and encodes
    * every band that needed only those rows more.
    */
  def rowsDone(at: Int, count: Int): Unit =
    val until = at + count
    // Why: the bands whose reads may take in these rows, from the band holding `at` on.
    var b = at / BandRows
    while b < bands && firstRead(image, b) < until do
      val met = Math.min(until, bandEnd(image, b)) - Math.max(at, firstRead(image, b))
      if met > 0 && waiting.addAndGet(b, -met) == 0 then ready.add(b): Unit
      b += 1
    if stored.addAndGet(count) >= from then
      // Why: the next band some thread has left ready, until none is.
      var next = Option(ready.poll())
      while next.nonEmpty do
        val start = System.nanoTime
        next.foreach(b => encoded.set(b, encodeBand(image, b)))
        spent.addAndGet(System.nanoTime - start): Unit
        next = Option(ready.poll())

  /** The time the threads that report rows have spent encoding bands so far, in nanoseconds,
    * summed over the threads: what the render's own time leaves out (`-t` times the rendering
    * alone).
    */
  def encodingNanos: Long = spent.get()

  /** Writes the PNG to `out`, encoding the bands not yet encoded on up to `workers` threads
    * besides this one, as [[Png.write]] does. Call it once every row is stored.
    */
  def write(out: OutputStream, workers: Int): Unit =
    writeBands(image, out, workers)(b => Option(encoded.get(b)))
