package tracer.image

import java.io.ByteArrayOutputStream
import java.util.concurrent.{CyclicBarrier, Executors}
import java.util.zip.Adler32
import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.forAll
import scala.concurrent.duration.DurationInt
import scala.concurrent.{Await, ExecutionContext, Future}

/** [[PngStream]]: a PNG whose bands are deflated as the rows they read are stored makes the same
  * file as [[Png.write]] of the finished bitmap, whatever the order and the threads the rows come
  * in; and [[Adler]] joins two checksums into the checksum of the joined bytes.
  */
class PngStreamProperties extends ScalaCheckSuite:

  // Fewer tries than the default hundred: the widest pictures are a third of a megapixel.
  override def scalaCheckTestParameters =
    super.scalaCheckTestParameters.withMinSuccessfulTests(30)

  /** The colour of pixel (x, y) of a picture with repeats across rows, and noise. */
  private def colour(seed: Long, x: Int, y: Int): Colour =
    val r = scala.util.Random(seed * 31 + x * 7919 + y)
    if r.nextInt(4) == 0 then Colour(r.nextDouble(), r.nextDouble(), r.nextDouble())
    else Colour(((x + 3 * y) % 17) / 17.0, (y % 5) / 5.0, 0.5)

  // Widths from one pixel (a dictionary of many bands' rows) to wider than the 32 KiB window.
  private val sizes = for
    w <- Gen.oneOf(Gen.choose(1, 40), Gen.choose(300, 400), Gen.choose(10900, 11100))
    h <- Gen.choose(1, 150)
  yield (w, h)

  /** The picture's rows cut into runs of 1 to 20 rows, in an order shuffled by `seed`. */
  private def runs(h: Int, seed: Long): Seq[(Int, Int)] =
    val random = scala.util.Random(seed)
    val starts = Iterator.iterate(0)(_ + 1 + random.nextInt(20)).takeWhile(_ < h).toSeq
    random.shuffle(starts.zip(starts.drop(1) :+ h).map((at, next) => (at, next - at)))

  /** `f` of each element of `order`, in that order on this thread for one thread; else `order` cut
    * into at most `threads` parts, each on a thread of a pool of that many, all held at a barrier
    * until every part has started, so that they run at the same time.
    */
  private def inParallel[A](order: Seq[A], threads: Int)(f: A => Unit): Unit =
    if threads == 1 then order.foreach(f)
    else
      val pool = Executors.newFixedThreadPool(threads)
      try
        given ExecutionContext = ExecutionContext.fromExecutorService(pool)
        val parts = order.grouped(Math.max(1, (order.size + threads - 1) / threads)).toSeq
        val start = CyclicBarrier(parts.size)
        val all   = Future.traverse(parts) { part =>
          Future { start.await(): Unit; part.foreach(f) }
        }
        Await.result(all, 60.seconds): Unit
      finally pool.shutdownNow(): Unit

  /** The PNG of the picture stored run by run in the order of `order`, on `threads` threads. */
  private def streamed(w: Int, h: Int, seed: Long, order: Seq[(Int, Int)], threads: Int) =
    val picture                          = Bitmap.Builder(w, h)
    val png                              = PngStream(picture)
    def store(at: Int, count: Int): Unit =
      for y <- at until at + count; x <- 0 until w do picture.put(x, y, colour(seed, x, y))
      png.rowsDone(at, count)
    inParallel(order, threads)(store.tupled)
    val out = ByteArrayOutputStream()
    png.write(out, 2)
    (picture.result, out.toByteArray)

  private def written(bitmap: Bitmap): Array[Byte] =
    val out = ByteArrayOutputStream()
    Png.write(bitmap, out, 1)
    out.toByteArray

  property("rows stored in any order make the bytes of the finished bitmap's PNG") {
    forAll(sizes, Gen.long, Gen.long) { case ((w, h), seed, shuffle) =>
      val order           = runs(h, shuffle)
      val (bitmap, bytes) = streamed(w, h, seed, order, 1)
      Prop(order.map(_._2).sum == h) :| "the runs cover the picture" &&
      Prop(bytes.sameElements(written(bitmap))) :| s"$w×$h differs" &&
      Prop(Png.read(bytes) == Right(bitmap)) :| "decodes to another picture"
    }
  }

  property("rows stored on several threads at once make the same bytes") {
    forAll(sizes, Gen.long, Gen.long) { case ((w, h), seed, shuffle) =>
      val (bitmap, bytes) = streamed(w, h, seed, runs(h, shuffle), 3)
      Prop(bytes.sameElements(written(bitmap))) :| s"$w×$h differs"
    }
  }

  test("rows never reported are encoded when the file is written") {
    val picture = Bitmap.Builder(50, 70)
    for y <- 0 until 70; x <- 0 until 50 do picture.put(x, y, colour(1, x, y))
    val png = PngStream(picture)
    png.rowsDone(0, 40)
    val out = ByteArrayOutputStream()
    png.write(out, 2)
    assert(out.toByteArray.sameElements(written(picture.result)))
  }

  test("bands are encoded as their rows are reported once half of the rows are, not before") {
    val picture = Bitmap.Builder(20, 200)
    val png     = PngStream(picture)
    png.rowsDone(0, 99)
    assertEquals(png.encodingNanos, 0L, "encoded before half of the rows were stored")
    png.rowsDone(99, 1)
    val half = png.encodingNanos
    assert(half > 0, "the bands ready at the middle were not encoded")
    png.rowsDone(100, 100)
    assert(png.encodingNanos > half, "the last bands were not encoded as their rows came")
  }

  /** A colour for pixel (x, y) as [[colour]] makes them, the noise from a hash of the pixel's place
    * rather than a generator made for each pixel: the edge sizes below are up to 0.8 megapixels,
    * each stored eight times.
    */
  private def quick(x: Int, y: Int): Colour =
    val n = Integer.rotateLeft(x * 0x9e3779b1 ^ y * 0x85ebca6b, 13) * 0xc2b2ae35
    if (n & 3) == 0 then
      Colour((n >>> 24) / 255.0, ((n >>> 16) & 0xff) / 255.0, ((n >>> 8) & 0xff) / 255.0)
    else Colour(((x + 3 * y) % 17) / 17.0, (y % 5) / 5.0, 0.5)

  /** The PNG of a `w`×`h` picture of [[quick]] whose rows are stored and reported one at a time
    * in the order of `rows`, on `threads` threads ([[inParallel]]).
    */
  private def streamedRows(w: Int, h: Int, rows: Seq[Int], threads: Int): Array[Byte] =
    val picture = Bitmap.Builder(w, h)
    val png     = PngStream(picture)
    inParallel(rows, threads) { y =>
      for x <- 0 until w do picture.put(x, y, quick(x, y))
      png.rowsDone(y, 1)
    }
    val out = ByteArrayOutputStream()
    png.write(out, 2)
    out.toByteArray

  test("edge sizes, rows forward, reversed, shuffled or the middle one last, on 1 or 3 threads"):
    // One row and one column; one band and a row more (32 and 33 rows); two bands and a row more;
    // 10,923 pixels wide, where one filtered row (32,770 bytes) is longer than the 32 KiB window;
    // and two tall, narrow pictures whose later bands' dictionaries reach the window's cap.
    val sizes = List(
      (1, 1),
      (3, 1),
      (1, 32),
      (1, 33),
      (7, 64),
      (7, 65),
      (350, 100),
      (10923, 70),
      (2, 8300),
      (1, 9000)
    )
    def capped(w: Int, h: Int) =
      val picture = PngWriter.Picture(w, h, 255, Array.emptyCharArray)
      PngWriter.firstRead(picture, PngWriter.bandCount(h) - 1) > 0
    assert(sizes.exists(capped), "no size whose dictionary stops short of row 0")
    val failures = for
      (w, h) <- sizes
      reference = written(Bitmap.tabulate(w, h)(quick))
      (name, rows) <- List(
        "forward"         -> (0 until h),
        "reversed"        -> (0 until h).reverse,
        "shuffled"        -> scala.util.Random(h.toLong).shuffle(0 until h),
        "middle row last" -> ((0 until h).filter(_ != h / 2) :+ h / 2)
      )
      threads <- List(1, 3)
      if !streamedRows(w, h, rows, threads).sameElements(reference)
    yield s"$w×$h, rows $name, on $threads threads"
    assertEquals(failures, Nil)

  test("bands encoded as the rows were reported are written as they were encoded"):
    // Once every row is reported, every band has been encoded (those ready when half of the rows
    // were in, then each as its last row came), so a pixel stored afterwards is not in the file.
    val (w, h)  = (40, 100)
    val picture = Bitmap.Builder(w, h)
    val png     = PngStream(picture)
    for y <- 0 until h do
      for x <- 0 until w do picture.put(x, y, colour(5, x, y))
      png.rowsDone(y, 1)
    val before = Bitmap.tabulate(w, h)(colour(5, _, _))
    assertEquals(picture.result, before)
    picture.put(3, 5, Colour(0.1, 0.9, 0.3))
    assertNotEquals(picture.result, before, "the pixel stored afterwards changed nothing")
    val out = ByteArrayOutputStream()
    png.write(out, 2)
    assertEquals(Png.read(out.toByteArray), Right(before))
    assertEquals(Png.read(written(picture.result)), Right(picture.result))

  property("maxval 1, 1000 or 65535: each sample s written as quantise(s / maxval, 255)"):
    val pictures = for
      w      <- Gen.choose(171, 400)
      h      <- Gen.choose(33, 70)
      maxval <- Gen.oneOf(1, 1000, 65535)
      seed   <- Gen.long
    yield (w, h, maxval, seed)
    forAll(pictures) { case (w, h, maxval, seed) =>
      val random  = scala.util.Random(seed)
      val picture = Bitmap.Builder(w, h, maxval)
      val png     = PngStream(picture)
      // Each channel sample s stored as s / maxval, which the builder stores as s again.
      def channel = random.nextInt(maxval + 1).toDouble / maxval
      for (at, count) <- runs(h, seed) do
        for y <- at until at + count; x <- 0 until w do picture.put(x, y, channel, channel, channel)
        png.rowsDone(at, count)
      val streamed = ByteArrayOutputStream()
      png.write(streamed, 2)
      val bitmap   = picture.result
      val expected = Bitmap.fromSamples(
        w,
        h,
        255,
        for y <- 0 until h; x <- 0 until w; c <- 0 until 3
        yield Colour.quantise(bitmap.sample(x, y, c) / maxval.toDouble, 255)
      )
      val direct = ByteArrayOutputStream()
      Png.write(bitmap, direct, 2)
      Prop(Png.read(streamed.toByteArray) == Right(expected)) :| "PngStream's samples" &&
      Prop(Png.read(direct.toByteArray) == Right(expected)) :| "Png.write's samples"
    }

  property("Adler.combine of two checksums is the checksum of the joined bytes") {
    forAll(Gen.listOf(Gen.choose(-128, 127)), Gen.listOf(Gen.choose(-128, 127))) { (a, b) =>
      def adler(bytes: Seq[Int]) =
        val sum = Adler32()
        sum.update(bytes.map(_.toByte).toArray)
        sum.getValue
      Adler.combine(adler(a), adler(b), b.length) == adler(a ++ b)
    }
  }

  test("Adler.combine of long runs of 0xff, where the sums wrap many times") {
    val a = Array.fill(100000)(0xff.toByte)
    val b = Array.fill(70000)(0xfe.toByte)
    assertEquals(Adler.combine(adler(a), adler(b), b.length), adler(a ++ b))
  }

  /** The Adler-32 of `bytes`. */
  private def adler(bytes: Array[Byte]): Long =
    val sum = Adler32()
    sum.update(bytes)
    sum.getValue

  property("Adler.combine with a second part of 0, 1, 65521, 131042 or up to 400,000 bytes"):
    // 65521 and 131042 bytes are whole multiples of the modulus (the length's remainder is 0).
    val lengths = Gen.oneOf(Gen.oneOf(0, 1, 65521, 131042), Gen.choose(0, 400000))
    val first   = Gen.oneOf(Gen.choose(0, 300), Gen.choose(0, 200000))
    forAll(first, lengths, Gen.long, Gen.prob(0.3)) { (n, m, seed, saturated) =>
      // Random bytes, or all 0xff, whose sums wrap the modulus soonest.
      val random            = scala.util.Random(seed)
      def part(length: Int) =
        val bytes = new Array[Byte](length)
        if saturated then java.util.Arrays.fill(bytes, 0xff.toByte) else random.nextBytes(bytes)
        bytes
      val (a, b) = (part(n), part(m))
      val whole  = Adler32()
      whole.update(a)
      whole.update(b)
      Prop(Adler.combine(adler(a), adler(b), m) == whole.getValue) :| s"$n then $m bytes"
    }

  /** An Adler-32 checksum: two sums, each below the modulus 65521. */
  private val checksum =
    for high <- Gen.choose(0L, 65520L); low <- Gen.choose(0L, 65520L) yield (high << 16) | low

  property("Adler.combine(x, 1, 0) is x: nothing (whose checksum is 1) joined after x"):
    forAll(checksum)(x => Adler.combine(x, 1, 0) == x)

  property("Adler.combine(1, y, n) is y: y's n bytes joined after nothing, for any n"):
    forAll(checksum, Gen.oneOf(Gen.choose(0L, 1000000L), Gen.choose(0L, Long.MaxValue))) { (y, n) =>
      Adler.combine(1, y, n) == y
    }
