package tracer.io

import java.nio.file.Path
import tracer.image.{Bitmap, ImageFile, ImageFormat, Png, PngStream, Raster}

/** Image files by name, for the command line and the REPL. */
object Images:

  /** Writes `bitmap` to the file `name` — PNG for `.png` (any case), else binary PPM — whole or
    * not at all ([[OutputFile.write]]); a `.pfm` or `.exr` name is refused (they hold floats).
    */
  def save(bitmap: Bitmap, name: String): Either[String, Unit] = save(bitmap, Path.of(name))

  /** Writes `bitmap` to `path`, its format chosen by the file name as in [[save(bitmap:*]], a PNG
    * encoded on up to `threads` threads (`-p`: the render's).
    */
  def save(
      bitmap: Bitmap,
      path: Path,
      threads: Int = Png.defaultThreads
  ): Either[String, Unit] =
    val format = ImageFile.formatFor(path.getFileName.toString)
    if format.isFloat then Left(s"cannot write '$path': a $format file holds floats, not samples")
    else OutputFile.write(path)(ImageFile.write(bitmap, format, _, threads))

  /** Writes the PNG `png` encodes to `path` (a `.png` name), whole or not at all, encoding what
    * is left of it on up to `threads` threads.
    */
  def save(png: PngStream, path: Path, threads: Int): Either[String, Unit] =
    val format = ImageFile.formatFor(path.getFileName.toString)
    if format != ImageFormat.Png then Left(s"cannot write '$path': a PNG goes to .png, not $format")
    else OutputFile.write(path)(png.write(_, threads))

  /** Writes `raster` to `path` — Portable FloatMap for `.pfm`, OpenEXR for `.exr` (any case) —
    * whole or not at all; any other name is refused.
    */
  def save(raster: Raster, path: Path): Either[String, Unit] =
    val format = ImageFile.formatFor(path.getFileName.toString)
    if !format.isFloat then Left(s"cannot write '$path': floats go to .pfm or .exr, not $format")
    else OutputFile.write(path)(ImageFile.write(raster, format, _))

  /** Reads a PPM or PNG file, recognised by its content. */
  def load(name: String): Either[String, Bitmap] = TextureFiles.read(Path.of(name))
