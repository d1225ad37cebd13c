package tracer.image

import java.io.ByteArrayOutputStream
import java.util.zip.Adler32
import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.forAll
import scala.concurrent.duration.Duration
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

  /** The PNG of the picture stored run by run in the order of `order`, on `threads` threads. */
  private def streamed(w: Int, h: Int, seed: Long, order: Seq[(Int, Int)], threads: Int) =
    val picture                          = Bitmap.Builder(w, h)
    val png                              = PngStream(picture)
    def store(at: Int, count: Int): Unit =
      for y <- at until at + count; x <- 0 until w do picture.put(x, y, colour(seed, x, y))
      png.rowsDone(at, count)
    if threads == 1 then order.foreach(store.tupled)
    else
      given ExecutionContext = ExecutionContext.global
      val parts              = order.grouped(Math.max(1, order.size / threads)).toSeq
      Await.result(Future.traverse(parts)(p => Future(p.foreach(store.tupled))), Duration.Inf): Unit
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
    val a                         = Array.fill(100000)(0xff.toByte)
    val b                         = Array.fill(70000)(0xfe.toByte)
    def adler(bytes: Array[Byte]) =
      val sum = Adler32()
      sum.update(bytes)
      sum.getValue
    assertEquals(Adler.combine(adler(a), adler(b), b.length), adler(a ++ b))
  }
