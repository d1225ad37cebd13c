package tracer.image

import java.nio.charset.StandardCharsets.US_ASCII
import munit.ScalaCheckSuite
import org.scalacheck.Prop.forAll
import tracer.testkit.Generators.given

/** PPM round trips, the reader's tolerance of legal layouts, and its errors for malformed files. */
class PpmSuite extends ScalaCheckSuite:

  private def ascii(text: String): Array[Byte]               = text.getBytes(US_ASCII)
  private def bytes(header: String, data: Int*): Array[Byte] = ascii(header) ++ data.map(_.toByte)

  property("a bitmap written as P6 reads back equal"):
    forAll((b: Bitmap) => assertEquals(Ppm.read(Ppm.encode(b, PpmFormat.Binary)), Right(b)))

  property("a bitmap written as P3 reads back equal"):
    forAll((b: Bitmap) => assertEquals(Ppm.read(Ppm.encode(b, PpmFormat.Ascii)), Right(b)))

  property("no P3 line is longer than 70 characters"):
    forAll { (b: Bitmap) =>
      val lines = String(Ppm.encode(b, PpmFormat.Ascii), US_ASCII).split('\n')
      assert(lines.forall(_.length <= 70), lines.maxBy(_.length))
    }

  test("the course text's ASCII example reads as written"):
    val example = """P3
      |# CREATOR: ray tracer
      |4 4
      |255
      |90 120 50 70 70 70 70 70 70 70 70
      |90 120 50 90 120 50 70 70 70 70 70
      |90 120 50 90 120 50 90 120 50 70 70
      |70 70 70 70 70 70 70 70 70 70 70
      |""".stripMargin
    // The example in the text has 44 samples, not 48: it is one pixel short, so it is truncated.
    assert(Ppm.read(ascii(example)).left.exists(_.contains("truncated")))
    val complete = example + "1 2 3 4 5 6 7 8 9 10 11 12\n"
    val bitmap   = Ppm.read(ascii(complete)).toOption.get
    assertEquals(
      (bitmap.sample(0, 0, 0), bitmap.sample(0, 0, 1), bitmap.sample(0, 0, 2)),
      (90, 120, 50)
    )

  test("P6 writes the header and one byte per sample"):
    val encoded = Ppm.encode(Bitmap.fill(2, 1, Colour(1, 0, 0.2)))
    val header  = "P6\n# CREATOR: tracer\n2 1\n255\n"
    assertEquals(String(encoded.take(header.length), US_ASCII), header)
    assertEquals(encoded.drop(header.length).map(_ & 0xff).toVector, Vector(255, 0, 51, 255, 0, 51))

  test("comments and any whitespace may stand between header fields"):
    val text = "P3#c\n\t2 # width\r\n#\n 1\n\n255\n1 2 3 # first pixel\n4\t5 6"
    assertEquals(Ppm.read(ascii(text)).map(b => b.sample(1, 0, 2)), Right(6))

  test("P6 with a small maxval scales samples by 1/maxval"):
    assertEquals(Ppm.read(bytes("P6 1 1 3\n", 3, 0, 1)).map(_(0, 0)), Right(Colour(1, 0, 1.0 / 3)))

  test("P6 with maxval above 255 has two bytes a sample, most significant first"):
    val read = Ppm.read(bytes("P6 1 1 65535\n", 0xff, 0xff, 0x01, 0x00, 0x00, 0x01))
    assertEquals(read.map(b => (0 until 3).map(b.sample(0, 0, _))), Right(Vector(65535, 256, 1)))

  test("P6 data may begin with a byte that looks like whitespace"):
    assertEquals(
      Ppm.read(bytes("P6 1 1 255\n", '\n', ' ', '#')).map(_.sample(0, 0, 2)),
      Right('#'.toInt)
    )

  test("anything after the last sample is ignored"):
    assert(Ppm.read(bytes("P6 1 1 255\n", 1, 2, 3, 4, 5)).isRight)

  private def assertFails(input: Array[Byte], expected: String*)(using munit.Location): Unit =
    Ppm.read(input) match
      case Right(b)      => fail(s"read $b from malformed input")
      case Left(message) =>
        expected.foreach(e => assert(message.contains(e), s"'$message' does not mention '$e'"))

  test("a bad magic number is an error"):
    assertFails(ascii("P5 1 1 255\n..."), "magic number P3 or P6")
    assertFails(ascii(""), "magic number")
    assertFails(ascii("GIF89a"), "magic number")

  test("a missing field is an error naming the field"):
    assertFails(ascii("P3 2 "), "height", "end of the file")
    assertFails(ascii("P6\n2 2\n"), "maxval")

  test("a negative field is an error naming the field and where"):
    assertFails(ascii("P3 -2 2 255\n"), "width", "line 1", "'-'")
    assertFails(ascii("P3\n2\n-2 255\n"), "height", "line 3")

  test("a zero width is an error"):
    assertFails(ascii("P3 0 2 255\n"), "width", "at least 1")

  test("maxval 0 or above 65535 is an error"):
    assertFails(ascii("P3 1 1 0\n0 0 0"), "maxval", "at least 1")
    assertFails(ascii("P3 1 1 65536\n0 0 0"), "maxval", "above 65535")

  test("a sample above maxval is an error naming the sample"):
    assertFails(ascii("P3 2 1 100\n1 2 3 4 101 6"), "sample 5", "(pixel 1, 0)", "101")
    assertFails(bytes("P6 1 1 100\n", 1, 200, 3), "sample 2", "200")

  test("truncated data is an error"):
    assertFails(bytes("P6 2 2 255\n", 1, 2, 3), "12 bytes", "found 3", "truncated")
    assertFails(ascii("P3 2 1 255\n1 2 3 4 5    "), "truncated")
    assertFails(bytes("P6 1 1 65535\n", 1, 2, 3), "6 bytes", "truncated")

  test("trailing garbage in a header field is an error"):
    assertFails(ascii("P3 2x 1 255\n1 2 3 4 5 6"), "width", "'x'")
    assertFails(ascii("P3 2 1 255z\n1 2 3 4 5 6"), "maxval", "'z'")
    assertFails(ascii("P3x 2 1 255\n1 2 3 4 5 6"), "whitespace before the width", "'x'")

  test("garbage among P3 samples is an error naming the sample"):
    assertFails(ascii("P3 1 1 255\n1 2a 3"), "sample 2", "'a'")
    assertFails(ascii("P3 1 1 255\n1 -2 3"), "sample 2")

  test("a header that asks for more pixels than can exist is an error, not an allocation"):
    assertFails(ascii("P6 100000 100000 255\n"), "more than")
    assertFails(ascii("P3 99999999999 1 255\n"), "width")
