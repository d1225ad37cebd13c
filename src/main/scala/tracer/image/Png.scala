package tracer.image

import java.awt.image.{BufferedImage, DataBuffer}
import java.io.{ByteArrayInputStream, ByteArrayOutputStream, OutputStream}
import javax.imageio.ImageIO

/** Reads PNG images with [[PngReader]] (the JDK's image I/O for the rest), and writes them with
  * [[PngWriter]].
  */
object Png:

  /** Writes `bitmap` as an 8-bit RGB PNG (deeper bitmaps are scaled to 8 bits), encoding it on up
    * to `threads` threads (the same bytes for any number).
    */
  def write(bitmap: Bitmap, out: OutputStream, threads: Int): Unit =
    PngWriter.write(bitmap, out, threads)

  /** The encoder's threads when the caller names none ([[encode]], `Images.save`): one a
    * processor.
    */
  def defaultThreads: Int = Runtime.getRuntime.availableProcessors

  /** The bytes of `bitmap` as a PNG file. */
  def encode(bitmap: Bitmap): Array[Byte] =
    val out = ByteArrayOutputStream()
    write(bitmap, out, defaultThreads)
    out.toByteArray

  /** Decodes a PNG: 16-bit images keep their depth (maxval 65535), others become 8-bit RGB;
    * alpha is ignored.
    *
    * Perf: the common kinds of file through [[PngReader]], the rest (and every damaged file, for
    * its message) through the JDK's image I/O, which decodes them to the same samples.
    */
  def read(bytes: Array[Byte]): Either[String, Bitmap] =
    PngReader.read(bytes).toRight(()).left.flatMap(_ => ViaImageIo.read(bytes))

  /** Decodes a PNG through the JDK's image I/O alone, as [[read]] did before [[PngReader]]: the
    * reference `PngReaderProperties` holds the decoder to.
    */
  private[image] def readWithImageIo(bytes: Array[Byte]): Either[String, Bitmap] =
    ViaImageIo.read(bytes)

/** The JDK's image I/O, in an object of its own so that its classes load only when it is used. */
private object ViaImageIo:

  /** Decodes a PNG with image I/O (see [[Png.read]]). */
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
