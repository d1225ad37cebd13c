package tracer.image

import java.io.ByteArrayOutputStream
import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.forAll

/** [[PngWriter]]'s banded encoding: pictures of many bands (each deflated on its own, with the rows
  * before as its dictionary) decode to their pixels, here and in the JDK's image I/O, and the file
  * is the same bytes for any number of encoder threads.
  */
class PngWriterProperties extends ScalaCheckSuite:

  // Fewer tries than the default hundred: the widest pictures are a third of a megapixel.
  override def scalaCheckTestParameters =
    super.scalaCheckTestParameters.withMinSuccessfulTests(30)

  /** A picture with repeats across rows and bands, so the deflater's matches reach back into the
    * dictionary: a tiling of `tile` random colours, and some noise.
    */
  private def picture(w: Int, h: Int, seed: Long): Bitmap =
    val random = scala.util.Random(seed)
    val period = 1 + random.nextInt(40)
    val tile   =
      Array.fill(period)(Colour(random.nextDouble(), random.nextDouble(), random.nextDouble()))
    val noise = random.nextDouble()
    Bitmap.tabulate(w, h, 255) { (x, y) =>
      val c = tile((x + 7 * y) % period)
      if random.nextDouble() < noise then Colour(random.nextDouble(), c.g, c.b) else c
    }

  private def encoded(bitmap: Bitmap, workers: Int): Array[Byte] =
    val out = ByteArrayOutputStream()
    PngWriter.write(bitmap, out, workers)
    out.toByteArray

  // Widths from one pixel (a band far smaller than the 32 KiB window) to wider than the window.
  private val sizes = for
    w <- Gen.oneOf(Gen.choose(1, 40), Gen.choose(300, 400), Gen.choose(10900, 11100))
    h <- Gen.choose(33, 100)
  yield (w, h)

  property("many bands: decoded here and by image I/O to the picture written") {
    forAll(sizes, Gen.long) { case ((w, h), seed) =>
      val bitmap = picture(w, h, seed)
      val bytes  = encoded(bitmap, 2)
      val ours   = Png.read(bytes)
      Prop(ours == Right(bitmap)) :| s"$w×$h decoded here differently" &&
      Prop(Png.readWithImageIo(bytes) == ours) :| "image I/O disagrees"
    }
  }

  property("the same bytes for one, two or five encoder threads") {
    forAll(sizes, Gen.long) { case ((w, h), seed) =>
      val bitmap = picture(w, h, seed)
      val one    = encoded(bitmap, 1)
      Prop(encoded(bitmap, 2).sameElements(one)) && Prop(encoded(bitmap, 5).sameElements(one))
    }
  }

  /** Filter type `filter` (1 Sub, 2 Up) of byte `i` of `row` as the PNG specification (§9.2)
    * defines it: the byte less its predictor, the neighbour left (`a`, 0 before the row's start)
    * for Sub, the one above (`b`) for Up.
    */
  private def specified(filter: Int, row: Array[Byte], above: Array[Byte], i: Int): Byte =
    val x         = row(i) & 0xff
    val a         = if i >= 3 then row(i - 3) & 0xff else 0
    val b         = above(i) & 0xff
    val predicted = if filter == 1 then a else b
    (x - predicted).toByte

  property("Sub and Up write the bytes the PNG specification defines, first pixel and pieces too") {
    val rows = for
      n     <- Gen.oneOf(Gen.choose(1, 40), Gen.choose(160, 400)).map(3 * _)
      row   <- Gen.listOfN(n, Gen.choose(Byte.MinValue, Byte.MaxValue))
      above <- Gen.listOfN(n, Gen.choose(Byte.MinValue, Byte.MaxValue))
    yield (row.toArray, above.toArray)
    forAll(rows, Gen.choose(1, 2), Gen.choose(0, 5)) { case ((row, above), filter, at) =>
      val out = Array.fill[Byte](at + row.length + 2)(7)
      PngWriter.applyFilter(filter, row, above, out, at)
      val expected = Array.fill[Byte](at)(7) ++ row.indices.map(specified(filter, row, above, _)) ++
        Array.fill[Byte](2)(7)
      Prop(out.sameElements(expected)) :| s"filter $filter"
    }
  }

  test("magnitude is |v| of every byte taken as signed"):
    for v <- -255 to 255 do assertEquals(PngWriter.magnitude(v.toByte), Math.abs(v.toByte.toInt), v)

  property("each row's filter is Sub or Up, whichever's bytes have the smaller sum of magnitudes"):
    val rows = for
      n <- Gen.oneOf(Gen.choose(1, 60), Gen.choose(160, 400)).map(3 * _)
      // Smooth rows and noisy rows, rows like the one above and unlike it, so that each wins.
      step  <- Gen.choose(0, 40)
      row   <- Gen.listOfN(n, Gen.choose(0, step)).map(_.scanLeft(100)(_ + _).tail)
      above <- Gen.listOfN(n, Gen.choose(Byte.MinValue, Byte.MaxValue))
      same  <- Gen.prob(0.3)
    yield (row.map(_.toByte).toArray, if same then row.map(_.toByte).toArray else above.toArray)
    forAll(rows) { (row, above) =>
      val sums =
        Seq(1, 2).map(f => row.indices.map(i => Math.abs(specified(f, row, above, i).toInt)).sum)
      val best = if sums(0) <= sums(1) then 1 else 2
      Prop(PngWriter.bestFilter(row, above) == best) :| s"sums $sums"
    }

  test("a tie between Sub and Up is Sub: all-zero rows, and one pixel with sums of 30 each"):
    for n <- List(3, 30, 1536) do
      assertEquals(PngWriter.bestFilter(new Array[Byte](n), new Array[Byte](n)), 1, s"$n zeros")
    val row = Array[Byte](10, 10, 10)
    assertEquals(PngWriter.bestFilter(row, Array[Byte](0, 0, 0)), 1, "Sub 30, Up 30")
    assertEquals(PngWriter.bestFilter(row, Array[Byte](1, 0, 0)), 2, "Sub 30, Up 29")
    assertEquals(PngWriter.bestFilter(row, Array[Byte](-1, 0, 0)), 1, "Sub 30, Up 31")

  property("a tie between Sub and Up is Sub: a row below itself moved one pixel right"):
    // Under (0, 0, 0) and then the row itself moved right by a pixel, Up subtracts from each byte
    // what Sub does (0 from the first pixel's, the byte three before from each other), so the two
    // sums are equal, over one piece or several.
    val rows = for
      n   <- Gen.oneOf(Gen.choose(1, 60), Gen.choose(160, 400)).map(3 * _)
      row <- Gen.listOfN(n, Gen.choose(Byte.MinValue, Byte.MaxValue))
    yield row.toArray
    forAll(rows) { row =>
      val above = Array[Byte](0, 0, 0) ++ row.dropRight(3)
      val same = row.indices.forall(i => specified(1, row, above, i) == specified(2, row, above, i))
      Prop(same) :| "not a tie" && Prop(PngWriter.bestFilter(row, above) == 1) :| "Up chosen"
    }
