package tracer.image

import java.io.ByteArrayOutputStream
import java.nio.file.{Files, Path}
import java.nio.{ByteBuffer, ByteOrder}
import tracer.testkit.{Processes, Tools}

/** OpenEXR files: what the tracer writes is read back by OpenEXR's own `exrheader` and by
  * ImageMagick, and by our reader; our reader reads ImageMagick's half-float ZIP and ZIPS files.
  */
class ExrSuite extends munit.FunSuite:

  // A 3 × 2 picture with values above 1, in 0..1 and exact in halves.
  private val picture = Raster.fromChannels(
    3,
    2,
    Array(0.25f, 0.5f, 1f, 2f, 0.125f, 0f, 0.75f, 3.5f, 0.0625f, 1f, 1f, 1f, 0f, 0f, 0f, 10f, 0.5f,
      0.25f)
  )

  private def bytes(raster: Raster): Array[Byte] =
    val out = ByteArrayOutputStream()
    Exr.write(raster, out)
    out.toByteArray

  private val dir = FunFixture[Path](
    _ => Files.createTempDirectory("tracer-exr"),
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
  )

  test("a written file reads back as the same raster, values above 1 included"):
    assertEquals(Exr.read(bytes(picture)), Right(picture))
    val wide = Raster.tabulate(17, 5)((x, y) => Colour(x * 1.5, y + 0.125, 1e4))
    assertEquals(Exr.read(bytes(wide)), Right(wide))

  test("the layout: magic, version 2, the header, an offset table, one chunk a line in B, G, R"):
    val file = ByteBuffer.wrap(bytes(picture)).order(ByteOrder.LITTLE_ENDIAN)
    assertEquals(file.getInt(0), 20000630)
    assertEquals(file.getInt(4), 2)
    val text = String(file.array, java.nio.charset.StandardCharsets.ISO_8859_1)
    for name <- List(
        "channels",
        "compression",
        "dataWindow",
        "displayWindow",
        "lineOrder",
        "pixelAspectRatio",
        "screenWindowCenter",
        "screenWindowWidth"
      )
    do assert(text.contains(s"$name\u0000"), s"no $name attribute")
    // The header ends with a zero byte before the table, whose first entry points just past it.
    val table = text.indexOf("screenWindowWidth\u0000float\u0000") + 18 + 6 + 4 + 4 + 1
    val first = file.getLong(table)
    assertEquals(first, table + 8L * 2)
    assertEquals(file.getLong(table + 8), first + 8 + 36)
    // Line 1: its number, 36 bytes, then blue 1, 0, 0.25, green 1, 0, 0.5, red 1, 0, 10.
    val line = file.position(file.getLong(table + 8).toInt).slice().order(ByteOrder.LITTLE_ENDIAN)
    assertEquals((line.getInt(), line.getInt()), (1, 36))
    assertEquals(
      (0 until 9).map(_ => line.getFloat()).toList,
      List(1f, 0f, 0.25f, 1f, 0f, 0.5f, 1f, 0f, 10f)
    )
    assertEquals(file.limit, (first + 2 * (8 + 36)).toInt)

  dir.test("OpenEXR's exrheader reads our header: B, G, R as 32-bit floats, no compression"): d =>
    val exrheader = Tools.require("exrheader", "apt-get install openexr")
    Files.write(d.resolve("p.exr"), bytes(picture))
    val r = Processes.run(Seq(exrheader.toString, "p.exr"), d)
    assertEquals(r.status, 0, r.err)
    for expected <- List(
        "file format version: 2, flags 0x0",
        "B, 32-bit floating-point, sampling 1 1",
        "G, 32-bit floating-point, sampling 1 1",
        "R, 32-bit floating-point, sampling 1 1",
        "compression (type compression): none",
        "dataWindow (type box2i): (0 0) - (2 1)",
        "displayWindow (type box2i): (0 0) - (2 1)",
        "lineOrder (type lineOrder): increasing y"
      )
    do assert(r.out.contains(expected), s"exrheader's output lacks '$expected':\n${r.out}")

  dir.test("ImageMagick reads our pixels: each value in 0..1 as its 16-bit quantum"): d =>
    val convert = Tools.require("convert", "apt-get install imagemagick")
    // Values ImageMagick's 16-bit build keeps (it clips above 1).
    val unit = Raster.tabulate(3, 2)((x, y) => Colour(x / 4.0, y / 2.0, (x + y) / 8.0))
    Files.write(d.resolve("u.exr"), bytes(unit))
    val r = Processes.run(Seq(convert.toString, "u.exr", "-depth", "16", "txt:-"), d)
    assertEquals(r.status, 0, r.err)
    val pixel = """(\d+),(\d+): \((\d+),(\d+),(\d+)""".r
    val found = r.out.linesIterator
      .flatMap(pixel.findPrefixMatchOf(_))
      .map { m =>
        (m.group(1).toInt, m.group(2).toInt) -> (3 to 5).map(i => m.group(i).toInt).toList
      }
      .toMap
    assertEquals(found.size, 6, r.out)
    for x <- 0 until 3; y <- 0 until 2 do
      val c = unit(x, y)
      assertEquals(found((x, y)), List(c.r, c.g, c.b).map(Colour.quantise(_, 65535)), r.out)

  // Made by ImageMagick 6.9.11 (OpenEXR 3.1.5) from a PFM of the picture above with
  // `convert c.pfm -compress Zip …` and `-compress ZipS`: 16-bit halves, values above 1 clipped.
  for (name, kind) <- List(("zip", "ZIP"), ("zips", "ZIPS")) do
    test(s"ImageMagick's half-float $kind file is read, each value as its half"):
      val file =
        getClass.getResourceAsStream(s"/exr/imagemagick-$name-half.exr").readAllBytes()
      val clipped = Raster.tabulate(3, 2)((x, y) =>
        val c = picture(x, y)
        Colour(Math.min(c.r, 1), Math.min(c.g, 1), Math.min(c.b, 1))
      )
      assertEquals(Exr.read(file), Right(clipped))

  test("halves: normal, subnormal, zero, negative and the largest, exactly"):
    val cases = List(
      0x3c00 -> 1f,
      0x4000 -> 2f,
      0x3555 -> 0.333251953125f,
      0x0001 -> Math.scalb(1f, -24),
      0x8000 -> -0f,
      0xc100 -> -2.5f,
      0x7bff -> 65504f
    )
    for (bits, value) <- cases do
      assertEquals(Exr.halfToFloat(bits.toShort), value, bits.toHexString)
    assert(Exr.halfToFloat(0x7c00.toShort).isInfinite && Exr.halfToFloat(0x7e00.toShort).isNaN)

  test("what the reader refuses: not OpenEXR, tiled, other compressions, cut short"):
    def refused(file: Array[Byte], words: String) =
      Exr.read(file) match
        case Left(why) => assert(why.contains(words), s"'$why' lacks '$words'")
        case Right(r)  => fail(s"read $r")
    val good = bytes(picture)
    refused("PF\n".getBytes, "not an OpenEXR file")
    val tiled = good.clone(); tiled(5) = 0x02
    refused(tiled, "tiled")
    val piz = good.clone()
    val at  = String(good, "ISO-8859-1").indexOf("compression\u0000compression\u0000") + 28
    piz(at) = 4
    refused(piz, "compression PIZ is not supported")
    refused(good.take(good.length - 5), "runs past the file")
    refused(good.take(40), "channels has a bad size 55")
    refused(good.take(8), "truncated")
