package tracer.image

import java.io.OutputStream

/** The image file formats the tracer reads and writes. */
enum ImageFormat:
  /** Portable pixmap, binary (P6) when written. */
  case Ppm

  /** Portable Network Graphics. */
  case Png

  /** Portable FloatMap: linear 32-bit floats (version 4). */
  case Pfm

  /** OpenEXR, scanline, 32-bit floats (version 4). */
  case Exr

  /** True for the formats that hold linear floating-point values, not 8- or 16-bit samples. */
  def isFloat: Boolean = this == Pfm || this == Exr

/** Recognises image files by their content and writes them by format. */
object ImageFile:

  /** The format an output file name asks for: `.png`, `.pfm` and `.exr` in any case are PNG,
    * Portable FloatMap and OpenEXR; anything else is PPM.
    */
  def formatFor(fileName: String): ImageFormat =
    val name = fileName.toLowerCase(java.util.Locale.ROOT)
    if name.endsWith(".png") then ImageFormat.Png
    else if name.endsWith(".pfm") then ImageFormat.Pfm
    else if name.endsWith(".exr") then ImageFormat.Exr
    else ImageFormat.Ppm

  /** Decodes a PPM (P3 or P6) or PNG image recognised by its first bytes, not by a file name. */
  def decode(bytes: Array[Byte]): Either[String, Bitmap] =
    if isPpm(bytes) then Ppm.read(bytes)
    else if isPng(bytes) then Png.read(bytes)
    else if isFloat(bytes) then Left("a floating-point image (PFM or OpenEXR), not a PPM or PNG")
    else Left("not a PPM (P3 or P6) or PNG image")

  /** Decodes any image the tracer reads, recognised by its first bytes: a PFM (`PF` or `Pf`) or
    * an OpenEXR file as a [[Raster]] of its values as they are, a PPM or PNG as a [[Bitmap]].
    */
  def decodeTexels(bytes: Array[Byte]): Either[String, Texels] =
    if bytes.length >= 2 && bytes(0) == 'P' && (bytes(1) == 'F' || bytes(1) == 'f') then
      Pfm.read(bytes)
    else if bytes.length >= 4 && bytes.take(4).sameElements(Exr.Magic) then Exr.read(bytes)
    else if isPpm(bytes) || isPng(bytes) then decode(bytes)
    else Left("not a PPM (P3 or P6), PNG, PFM or OpenEXR image")

  private def isPpm(bytes: Array[Byte]): Boolean =
    bytes.length >= 2 && bytes(0) == 'P' && (bytes(1) == '3' || bytes(1) == '6')

  private def isPng(bytes: Array[Byte]): Boolean =
    bytes.length >= 8 && bytes.take(8).sameElements(PngSignature)

  private def isFloat(bytes: Array[Byte]): Boolean =
    (bytes.length >= 2 && bytes(0) == 'P' && (bytes(1) == 'F' || bytes(1) == 'f')) ||
      (bytes.length >= 4 && bytes.take(4).sameElements(Exr.Magic))

  /** Writes `bitmap` to `out` in `format` (binary P6 for PPM), which must not be a
    * floating-point format; a PNG is encoded on up to `threads` threads.
    */
  def write(bitmap: Bitmap, format: ImageFormat, out: OutputStream, threads: Int): Unit =
    format match
      case ImageFormat.Ppm                   => Ppm.write(bitmap, out, PpmFormat.Binary)
      case ImageFormat.Png                   => Png.write(bitmap, out, threads)
      case ImageFormat.Pfm | ImageFormat.Exr =>
        // Why: a caller's bug: every caller chooses the raster writer for these formats.
        throw IllegalArgumentException(s"$format holds floats: write a Raster")

  /** Writes `raster` to `out` in the floating-point `format` (PFM or OpenEXR). */
  def write(raster: Raster, format: ImageFormat, out: OutputStream): Unit = format match
    case ImageFormat.Pfm                   => Pfm.write(raster, out)
    case ImageFormat.Exr                   => Exr.write(raster, out)
    case ImageFormat.Ppm | ImageFormat.Png =>
      // Why: a caller's bug: every caller chooses the bitmap writer for these formats.
      throw IllegalArgumentException(s"$format holds 8- or 16-bit samples: write a Bitmap")

  private val PngSignature = Array[Byte](0x89.toByte, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n')
