package tracer.io

import java.nio.file.Path
import tracer.image.{Bitmap, ImageFile}

/** Image files by name, for the command line and the REPL. */
object Images:

  /** Writes `bitmap` to the file `name` — PNG for `.png` (any case), else binary PPM — whole or
    * not at all ([[OutputFile.write]]).
    */
  def save(bitmap: Bitmap, name: String): Either[String, Unit] = save(bitmap, Path.of(name))

  /** Writes `bitmap` to `path`, its format chosen by the file name as in [[save(bitmap:*]]. */
  def save(bitmap: Bitmap, path: Path): Either[String, Unit] =
    val format = ImageFile.formatFor(path.getFileName.toString)
    OutputFile.write(path)(ImageFile.write(bitmap, format, _))

  /** Reads a PPM or PNG file, recognised by its content. */
  def load(name: String): Either[String, Bitmap] = TextureFiles.read(Path.of(name))
