package tracer.image

/** Creating, reading and changing bitmaps. */
class BitmapSuite extends munit.FunSuite:

  test("a filled bitmap has that colour at every pixel"):
    val bitmap = Bitmap.fill(3, 2, Colour(1, 0, 0))
    for x <- 0 until 3; y <- 0 until 2 do assertEquals(bitmap(x, y), Colour(1, 0, 0))

  test("tabulate puts pixel (x, y) at column x of row y, row 0 at the top"):
    val bitmap = Bitmap.tabulate(4, 3)((x, y) => Colour(x / 255.0, y / 255.0, 0))
    assertEquals(bitmap.sample(3, 0, 0), 3)
    assertEquals(bitmap.sample(3, 2, 1), 2)

  test("updated changes one pixel and leaves the original alone"):
    val before = Bitmap.fill(2, 2, Colour.Black)
    val after  = before.updated(1, 0, Colour.White)
    assertEquals(after(1, 0), Colour.White)
    assertEquals(after(0, 0), Colour.Black)
    assertEquals(before(1, 0), Colour.Black)

  test("map transforms every pixel"):
    val inverted = Bitmap.fill(2, 1, Colour(1, 0, 0.2)).map(c => Colour(1 - c.r, 1 - c.g, 1 - c.b))
    assertEquals(inverted.sample(1, 0, 0), 0)
    assertEquals(inverted.sample(1, 0, 1), 255)
    assertEquals(inverted.sample(1, 0, 2), 204)

  test("stack places bands top to bottom"):
    val stacked =
      Bitmap.stack(Seq(Bitmap.fill(2, 1, Colour.White), Bitmap.fill(2, 2, Colour.Black)))
    assertEquals((stacked.width, stacked.height), (2, 3))
    assertEquals(stacked(1, 0), Colour.White)
    assertEquals(stacked(1, 2), Colour.Black)

  test("bitmaps are equal by content"):
    assertEquals(Bitmap.fill(2, 2, Colour.White), Bitmap.fill(2, 2, Colour.White))
    assertNotEquals(Bitmap.fill(2, 2, Colour.White), Bitmap.fill(2, 2, Colour.White, 65535))
    assertNotEquals(Bitmap.fill(2, 2, Colour.White), Bitmap.fill(2, 2, Colour.Black))

  test("a 16-bit bitmap keeps 16-bit samples"):
    val deep = Bitmap.fromSamples(1, 1, 65535, Vector(65535, 256, 1))
    assertEquals(deep(0, 0), Colour(1, 256.0 / 65535, 1.0 / 65535))

  test("width or height below 1 is a clear error"):
    assertEquals(Bitmap.checkSize(0, 5).left.map(_.contains("at least 1")), Left(true))
    assertEquals(Bitmap.checkSize(5, -1).isLeft, true)
    intercept[IllegalArgumentException](Bitmap.fill(0, 1, Colour.Black))

  test("a pixel count that overflows is a clear error, not a negative array size"):
    assertEquals(Bitmap.checkSize(100000, 100000).left.map(_.contains("more than")), Left(true))
    assertEquals(Bitmap.checkSize(Int.MaxValue, Int.MaxValue).isLeft, true)
    assertEquals(Bitmap.checkSize(3840, 2160), Right(()))

  test("reading outside the bitmap names the pixel"):
    val e = intercept[IndexOutOfBoundsException](Bitmap.fill(2, 2, Colour.Black)(2, 0))
    assert(e.getMessage.contains("(2, 0)"))

  test("a 3840×2160 bitmap fits in a flat array"):
    val big = Bitmap.fill(3840, 2160, Colour(0.5, 0.25, 1))
    assertEquals(big.sample(3839, 2159, 2), 255)
