package tracer.image

import java.io.ByteArrayOutputStream
import java.nio.charset.StandardCharsets.US_ASCII
import java.nio.{ByteBuffer, ByteOrder}

/** Portable FloatMap files: the exact bytes the tracer writes, and what it reads. */
class PfmSuite extends munit.FunSuite:

  // A 2 × 2 picture: the top row (0.5, 2, 0) and (1, 0.25, 1e3), the bottom one greys 0 and 7.
  private val picture = Raster.fromChannels(
    2,
    2,
    Array(0.5f, 2f, 0f, 1f, 0.25f, 1000f, 0f, 0f, 0f, 7f, 7f, 7f)
  )

  private def bytes(raster: Raster): Array[Byte] =
    val out = ByteArrayOutputStream()
    Pfm.write(raster, out)
    out.toByteArray

  private def floats(order: ByteOrder, values: Float*): Array[Byte] =
    val b = ByteBuffer.allocate(4 * values.length).order(order)
    values.foreach(v => b.putFloat(v): Unit)
    b.array

  test(
    "PF, the width and height, the scale -1.0, then little-endian floats from the bottom row up"
  ):
    val expected = "PF\n2 2\n-1.0\n".getBytes(US_ASCII) ++
      floats(ByteOrder.LITTLE_ENDIAN, 0f, 0f, 0f, 7f, 7f, 7f, 0.5f, 2f, 0f, 1f, 0.25f, 1000f)
    assertEquals(bytes(picture).toList, expected.toList)

  test("a written file reads back as the same raster, values above 1 included"):
    assertEquals(Pfm.read(bytes(picture)), Right(picture))
    val wide = Raster.tabulate(5, 3)((x, y) => Colour(x * 1.5, y + 0.125, -0.5))
    assertEquals(Pfm.read(bytes(wide)), Right(wide))

  test("big-endian files (a positive scale), grey Pf files and any whitespace in the header"):
    val big = "PF\n1 1\n1.0\n".getBytes(US_ASCII) ++ floats(ByteOrder.BIG_ENDIAN, 1.5f, 2f, 3f)
    assertEquals(Pfm.read(big).map(_(0, 0)), Right(Colour(1.5, 2, 3)))
    val grey = "Pf  2\t1\r\n-4.0\n".getBytes(US_ASCII) ++ floats(ByteOrder.LITTLE_ENDIAN, 0.25f, 8f)
    assertEquals(
      Pfm.read(grey),
      Right(Raster.fromChannels(2, 1, Array(0.25f, 0.25f, 0.25f, 8f, 8f, 8f)))
    )

  test("a malformed PFM is refused with what is wrong"):
    def refused(file: Array[Byte], words: String) =
      Pfm.read(file) match
        case Left(why) => assert(why.contains(words), s"'$why' lacks '$words'")
        case Right(r)  => fail(s"read $r")
    val one = floats(ByteOrder.LITTLE_ENDIAN, 1f, 1f, 1f)
    refused("PG\n1 1\n-1.0\n".getBytes(US_ASCII) ++ one, "magic number PF or Pf")
    refused("PF\n0 1\n-1.0\n".getBytes(US_ASCII) ++ one, "width of at least 1")
    refused("PF\n1 x\n-1.0\n".getBytes(US_ASCII) ++ one, "height of at least 1")
    refused("PF\n1 1\n0\n".getBytes(US_ASCII) ++ one, "scale")
    refused("PF\n2 1\n-1.0\n".getBytes(US_ASCII) ++ one, "expected 24 bytes")
    refused("PF\n1 1".getBytes(US_ASCII), "PFM header")
    refused(
      "PF\n1 1\n-1.0\n".getBytes(US_ASCII) ++ floats(ByteOrder.LITTLE_ENDIAN, 1f, Float.NaN, 1f),
      "pixel (0, 0) is not a finite number"
    )
