package tracer.image

import java.awt.Transparency
import java.awt.color.ColorSpace
import java.awt.image.{BufferedImage, ComponentColorModel, DataBuffer, IndexColorModel}
import java.io.ByteArrayOutputStream
import java.nio.file.{Files, Path}
import javax.imageio.{IIOImage, ImageIO, ImageWriteParam}
import munit.ScalaCheckSuite
import scala.jdk.CollectionConverters.*
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.{forAll, forAllNoShrink}

/** [[PngReader]] gives the bitmaps the JDK's image I/O gives ([[Png.readWithImageIo]]), on files
  * of every colour type and bit depth image I/O writes, on the project's own PNGs, and on damaged
  * files (where both give the same message); and it takes the kinds it claims.
  */
class PngReaderProperties extends ScalaCheckSuite:

  /** An image I/O colour model and sample layout to write, by name. */
  private final case class Kind(name: String, make: (Int, Int) => BufferedImage, ours: Boolean)

  private def custom(space: Int, alpha: Boolean)(w: Int, h: Int): BufferedImage =
    val model = ComponentColorModel(
      ColorSpace.getInstance(space),
      alpha,
      false,
      if alpha then Transparency.TRANSLUCENT else Transparency.OPAQUE,
      DataBuffer.TYPE_USHORT
    )
    // nosemgrep: no-null — the JDK's constructor takes null for "no properties"
    BufferedImage(model, model.createCompatibleWritableRaster(w, h), false, null)

  private def indexed(bits: Int, entries: Int, seed: Int)(w: Int, h: Int): BufferedImage =
    val random    = scala.util.Random(seed)
    def channel   = Array.fill(entries)(random.nextInt(256).toByte)
    val (r, g, b) = (channel, channel, channel)
    val model     = IndexColorModel(bits, entries, r, g, b)
    val kind = if bits == 8 then BufferedImage.TYPE_BYTE_INDEXED else BufferedImage.TYPE_BYTE_BINARY
    BufferedImage(w, h, kind, model)

  private def ramp(bits: Int)(w: Int, h: Int): BufferedImage =
    val n     = 1 << bits
    val grey  = Array.tabulate(n)(i => (i * 255 / (n - 1)).toByte)
    val model = IndexColorModel(bits, n, grey, grey, grey)
    BufferedImage(w, h, BufferedImage.TYPE_BYTE_BINARY, model)

  private val kinds = List(
    Kind("RGB 8", BufferedImage(_, _, BufferedImage.TYPE_3BYTE_BGR), ours = true),
    Kind("RGB 8 from int", BufferedImage(_, _, BufferedImage.TYPE_INT_RGB), ours = true),
    Kind("RGBA 8", BufferedImage(_, _, BufferedImage.TYPE_4BYTE_ABGR), ours = true),
    Kind("RGB 16", custom(ColorSpace.CS_sRGB, alpha = false), ours = true),
    Kind("RGBA 16", custom(ColorSpace.CS_sRGB, alpha = true), ours = true),
    Kind("grey 16", BufferedImage(_, _, BufferedImage.TYPE_USHORT_GRAY), ours = true),
    Kind("grey-alpha 16", custom(ColorSpace.CS_GRAY, alpha = true), ours = true),
    Kind("grey 8", BufferedImage(_, _, BufferedImage.TYPE_BYTE_GRAY), ours = false),
    Kind("grey 1", ramp(1), ours = true),
    Kind("grey 2", ramp(2), ours = true),
    Kind("grey 4", ramp(4), ours = true),
    Kind("palette 1", indexed(1, 2, 1), ours = true),
    Kind("palette 2", indexed(2, 4, 2), ours = true),
    Kind("palette 2 of 3", indexed(2, 3, 3), ours = true),
    Kind("palette 4", indexed(4, 16, 4), ours = true),
    Kind("palette 4 of 11", indexed(4, 11, 5), ours = true),
    Kind("palette 8", indexed(8, 256, 6), ours = true),
    Kind("palette 8 of 100", indexed(8, 100, 7), ours = true)
  )

  /** `image` filled from `seed`, every sample of every band random (indices within the palette). */
  private def filled(image: BufferedImage, seed: Long): BufferedImage =
    val random = scala.util.Random(seed)
    val raster = image.getRaster
    val limit  = image.getColorModel match
      case m: IndexColorModel => m.getMapSize
      case _                  => Int.MaxValue
    for
      y <- 0 until image.getHeight
      x <- 0 until image.getWidth
      b <- 0 until raster.getNumBands
    do
      val bits = raster.getSampleModel.getSampleSize(b)
      // Smooth runs as well as noise, so the writer's filters all get chosen.
      val value = if random.nextInt(3) == 0 then (x * 7 + y * 3) else random.nextInt(1 << bits)
      raster.setSample(x, y, b, Math.min(value & ((1 << bits) - 1), limit - 1))
    image

  private def written(image: BufferedImage, interlaced: Boolean): Array[Byte] =
    val out    = ByteArrayOutputStream()
    val writer = ImageIO.getImageWritersByFormatName("png").next()
    val stream = ImageIO.createImageOutputStream(out)
    writer.setOutput(stream)
    val param = writer.getDefaultWriteParam
    if interlaced then param.setProgressiveMode(ImageWriteParam.MODE_DEFAULT)
    else param.setProgressiveMode(ImageWriteParam.MODE_DISABLED)
    // nosemgrep: no-null — image I/O takes null for "no stream metadata, thumbnails or metadata"
    writer.write(null, IIOImage(image, null, null), param)
    stream.close()
    writer.dispose()
    out.toByteArray

  /** What `read` gives, or the exception it throws (image I/O may throw on a damaged file). */
  private def outcome(read: Array[Byte] => Either[String, Bitmap], bytes: Array[Byte]) =
    scala.util.Try(read(bytes)).toEither.left.map(_.toString)

  private def sameAsImageIo(bytes: Array[Byte]): Prop =
    val (ours, theirs) = (outcome(Png.read, bytes), outcome(Png.readWithImageIo, bytes))
    Prop(ours == theirs) :| s"ours $ours, image I/O's $theirs"

  private val sizes = for
    w <- Gen.choose(1, 37)
    h <- Gen.choose(1, 19)
  yield (w, h)

  kinds.foreach { kind =>
    property(s"${kind.name}: the same bitmap as image I/O, and decoded here when claimed") {
      forAll(sizes, Gen.long) { case ((w, h), seed) =>
        val bytes = written(filled(kind.make(w, h), seed), interlaced = false)
        val ours  = PngReader.read(bytes)
        Prop(ours.isDefined == kind.ours) && sameAsImageIo(bytes)
      }
    }
    property(s"${kind.name}, interlaced: left to image I/O") {
      forAll(sizes, Gen.long) { case ((w, h), seed) =>
        val bytes = written(filled(kind.make(w, h), seed), interlaced = true)
        Prop(PngReader.read(bytes).isEmpty) && sameAsImageIo(bytes)
      }
    }
  }

  property("our own writer's files: decoded here, the same as image I/O") {
    forAll(sizes, Gen.long, Gen.oneOf(255, 65535, 1000)) { case ((w, h), seed, maxval) =>
      val random = scala.util.Random(seed)
      val bitmap = Bitmap.tabulate(w, h, maxval)((_, _) =>
        Colour(random.nextDouble(), random.nextDouble(), random.nextDouble())
      )
      val bytes = Png.encode(bitmap)
      Prop(PngReader.read(bytes).isDefined) && sameAsImageIo(bytes)
    }
  }

  // Not shrunk: each try is an image I/O read, and a counterexample is clearest as found.
  property("damaged files (cut short, a byte changed): the same result as image I/O") {
    val valid = kinds.map(k => written(filled(k.make(13, 7), 42L), interlaced = false))
    forAllNoShrink(Gen.oneOf(valid), Gen.choose(0, 10000), Gen.choose(0, 255), Gen.prob(0.5)) {
      (bytes, where, value, cut) =>
        val at      = where % bytes.length
        val damaged =
          if cut then bytes.take(at) else bytes.updated(at, value.toByte)
        sameAsImageIo(damaged)
    }
  }

  test("every byte of a small file changed, and every cut: the same result as image I/O") {
    // A changed byte in the stream's last bytes (its checksum) once decoded here while image I/O
    // refused the file: the rows must be followed by the stream's verified end.
    for kind <- kinds.filter(k => Set("RGB 8", "grey 1", "palette 4 of 11")(k.name)) do
      val bytes = written(filled(kind.make(13, 7), 42L), interlaced = false)
      for at <- bytes.indices do
        val changed = bytes.updated(at, (bytes(at) ^ 1).toByte)
        assertEquals(
          outcome(Png.read, changed),
          outcome(Png.readWithImageIo, changed),
          s"${kind.name}, byte $at"
        )
        val cut = bytes.take(at)
        assertEquals(
          outcome(Png.read, cut),
          outcome(Png.readWithImageIo, cut),
          s"${kind.name}, cut at $at"
        )
  }

  test("the project's PNG files: decoded here, the same as image I/O") {
    val roots = List(Path.of("scenes"), Path.of("src/test/resources"))
    val files = roots.flatMap { root =>
      val stream = Files.walk(root)
      try stream.iterator.asScala.filter(_.toString.endsWith(".png")).toList
      finally stream.close()
    }
    assert(files.exists(_.endsWith("textures/marble.png")), files)
    files.foreach { file =>
      val bytes = Files.readAllBytes(file)
      assert(PngReader.read(bytes).isDefined, file)
      assertEquals(Png.read(bytes), Png.readWithImageIo(bytes), file)
    }
  }
