package tracer.io

import java.nio.file.{Files, Path}
import tracer.image.{Bitmap, ImageFile, Texels}

/** Loads texture images from files, relative paths resolved against a base directory. */
object TextureFiles:

  /** A loader for [[SceneXml.parse]] reading PPM, PNG, PFM or OpenEXR files, relative to `base`
    * (by default the current working directory, as the scene arrives on standard input and has
    * no directory).
    */
  def loader(base: Path = Path.of("").toAbsolutePath): SceneXml.TextureLoader =
    name => readTexels(base.resolve(name))

  /** The PPM or PNG image in file `path`, recognised by its content, or why it cannot be read. */
  def read(path: Path): Either[String, Bitmap] = bytes(path).flatMap(ImageFile.decode)

  /** The image in file `path` — PPM, PNG, PFM or OpenEXR, recognised by its content — or why it
    * cannot be read.
    */
  def readTexels(path: Path): Either[String, Texels] = bytes(path).flatMap(ImageFile.decodeTexels)

  private def bytes(path: Path): Either[String, Array[Byte]] =
    val bytes =
      try
        if Files.isDirectory(path) then Left("it is a directory")
        else Right(Files.readAllBytes(path))
      catch
        case e: java.io.IOException => Left(IoFailure.reason(e))
        case _: OutOfMemoryError    => Left("the file is too large to load")
    bytes
