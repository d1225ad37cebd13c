package tracer.image

/** PNG round trips and recognising image files by their content. */
class ImageFileSuite extends munit.FunSuite:

  private val picture = Bitmap.tabulate(5, 3)((x, y) => Colour(x / 4.0, y / 2.0, 0.5))

  test("an 8-bit bitmap written as PNG reads back equal"):
    assertEquals(Png.read(Png.encode(picture)), Right(picture))

  test("a 16-bit bitmap is written as 8-bit PNG, rounded to the nearest level"):
    val deep = Bitmap.fromSamples(1, 1, 65535, Vector(65535, 32896, 0))
    assertEquals(
      Png.read(Png.encode(deep)).map(b => (0 until 3).map(b.sample(0, 0, _))),
      Right(Vector(255, 128, 0))
    )

  test("decode recognises PPM and PNG by content, whatever the file is called"):
    assertEquals(ImageFile.decode(Png.encode(picture)), Right(picture))
    assertEquals(ImageFile.decode(Ppm.encode(picture, PpmFormat.Ascii)), Right(picture))
    assertEquals(ImageFile.decode(Ppm.encode(picture)), Right(picture))

  test("decode refuses other content"):
    assert(ImageFile.decode("hello".getBytes).isLeft)
    assert(ImageFile.decode(Array[Byte]()).isLeft)

  test("a broken PNG is an error, not an exception"):
    assert(Png.read(Png.encode(picture).take(40)).isLeft)

  test("the output format follows the extension: .png in any case, else PPM"):
    assertEquals(ImageFile.formatFor("out.png"), ImageFormat.Png)
    assertEquals(ImageFile.formatFor("OUT.PNG"), ImageFormat.Png)
    assertEquals(ImageFile.formatFor("out.ppm"), ImageFormat.Ppm)
    assertEquals(ImageFile.formatFor("picture"), ImageFormat.Ppm)
