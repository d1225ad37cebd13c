package tracer.image

import java.io.OutputStream

/** The image file formats the tracer reads and writes. */
enum ImageFormat:
  /** Portable pixmap, binary (P6) when written. */
  case Ppm

  /** Portable Network Graphics. */
  case Png

/** Recognises image files by their content and writes them by format. */
object ImageFile:

  /** The format an output file name asks for: `.png` in any case is PNG, anything else PPM. */
  def formatFor(fileName: String): ImageFormat =
    if fileName.toLowerCase(java.util.Locale.ROOT).endsWith(".png") then ImageFormat.Png
    else ImageFormat.Ppm

  /** Decodes a PPM (P3 or P6) or PNG image recognised by its first bytes, not by a file name. */
  def decode(bytes: Array[Byte]): Either[String, Bitmap] =
    if bytes.length >= 2 && bytes(0) == 'P' && (bytes(1) == '3' || bytes(1) == '6') then
      Ppm.read(bytes)
    else if bytes.length >= 8 && bytes.take(8).sameElements(PngSignature) then Png.read(bytes)
    else Left("not a PPM (P3 or P6) or PNG image")

  /** Writes `bitmap` to `out` in `format` (binary P6 for PPM). */
  def write(bitmap: Bitmap, format: ImageFormat, out: OutputStream): Unit = format match
    case ImageFormat.Ppm => Ppm.write(bitmap, out, PpmFormat.Binary)
    case ImageFormat.Png => Png.write(bitmap, out)

  private val PngSignature = Array[Byte](0x89.toByte, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n')
