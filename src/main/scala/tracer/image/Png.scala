package tracer.image

import java.awt.image.{BufferedImage, DataBuffer}
import java.io.{ByteArrayInputStream, ByteArrayOutputStream, OutputStream}
import javax.imageio.ImageIO

/** Reads and writes PNG images through the JDK's image I/O. */
object Png:

  /** Writes `bitmap` as an 8-bit RGB PNG (deeper bitmaps are scaled to 8 bits). */
  def write(bitmap: Bitmap, out: OutputStream): Unit =
    val image = BufferedImage(bitmap.width, bitmap.height, BufferedImage.TYPE_INT_RGB)
    val rgb   = Array.tabulate(bitmap.width * bitmap.height) { i =>
      val (x, y)          = (i % bitmap.width, i / bitmap.width)
      def channel(c: Int) = to8Bit(bitmap.sample(x, y, c), bitmap.maxval)
      (channel(0) << 16) | (channel(1) << 8) | channel(2)
    }
    image.setRGB(0, 0, bitmap.width, bitmap.height, rgb, 0, bitmap.width)
    if !ImageIO.write(image, "png", out) then
      throw IllegalStateException("no PNG writer in this JDK")

  /** The bytes of `bitmap` as a PNG file. */
  def encode(bitmap: Bitmap): Array[Byte] =
    val out = ByteArrayOutputStream()
    write(bitmap, out)
    out.toByteArray

  /** Decodes a PNG: 16-bit images keep their depth (maxval 65535), others become 8-bit RGB;
    * alpha is ignored.
    */
  def read(bytes: Array[Byte]): Either[String, Bitmap] =
    val decoded =
      try Option(ImageIO.read(ByteArrayInputStream(bytes))).toRight("not a readable PNG image")
      catch case e: java.io.IOException => Left(s"not a readable PNG image (${e.getMessage})")
    decoded.map(fromImage)

  private def fromImage(image: BufferedImage): Bitmap =
    val (w, h) = (image.getWidth, image.getHeight)
    val raster = image.getRaster
    val bands  = raster.getNumBands
    val deep   = raster.getDataBuffer.getDataType == DataBuffer.TYPE_USHORT
    if deep then
      // 16-bit grey (1–2 bands) or RGB (3–4 bands): the first band, or the first three, are colour.
      Bitmap.tabulate(w, h, 65535) { (x, y) =>
        def band(b: Int) = raster.getSample(x, y, if bands < 3 then 0 else b)
        Colour.fromSamples(band(0), band(1), band(2), 65535)
      }
    else
      Bitmap.tabulate(w, h, 255) { (x, y) =>
        val rgb = image.getRGB(x, y)
        Colour.fromSamples((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff, 255)
      }

  private def to8Bit(sample: Int, maxval: Int): Int =
    if maxval == 255 then sample else Colour.quantise(sample.toDouble / maxval, 255)
