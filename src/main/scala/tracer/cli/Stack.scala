package tracer.cli

import java.nio.file.Path
import tracer.Eithers
import tracer.image.{Bitmap, ImageFile, Raster}
import tracer.io.{Images, OutputFile, TextureFiles}

/** `--stack`: pictures joined one below the other, as `scripts/still.sh` joins its bands. */
private[cli] object Stack:

  /** Refuses a stack whose names mix kinds: every band and the output must all be
    * floating-point images (`.pfm`, `.exr`) or all 8- or 16-bit ones (anything else), by their
    * suffixes as an output is named.
    */
  def sameKind(bands: List[String], output: String): Either[String, Unit] =
    val float = ImageFile.formatFor(output).isFloat
    bands.find(b => ImageFile.formatFor(b).isFloat != float) match
      case None       => Right(())
      case Some(band) =>
        val (kind, other) =
          if float then ("floating-point", "8-bit") else ("8-bit", "floating-point")
        Left(
          s"--stack joins bands of one kind: $output is $kind (.pfm/.exr or not), $band is $other"
        )

  /** Writes `output` as the images `bands`, read in order, one below the other; all must share
    * a width, and a depth for 8-bit images. A `.pfm` or `.exr` output joins floating-point bands
    * (PFM or OpenEXR, by content), any other output PPM or PNG ones. The output is written whole
    * or not at all.
    */
  def write(bands: List[String], output: String, cwd: Path): Either[String, Unit] =
    val target = cwd.resolve(output)
    val float  = ImageFile.formatFor(output).isFloat
    for
      _      <- OutputFile.checkWritable(target)
      images <- Eithers.traverse(bands)(name =>
        TextureFiles
          .readTexels(cwd.resolve(name))
          .left
          .map(why => s"--stack: cannot read $name: $why")
          .map(name -> _)
      )
      _ <-
        if float then joinRasters(images).flatMap(Images.save(_, target))
        else joinBitmaps(images).flatMap(Images.save(_, target))
    yield ()

  private def joinBitmaps(images: List[(String, Bitmap | Raster)]): Either[String, Bitmap] =
    Eithers
      .traverse(images) {
        case (_, b: Bitmap)    => Right(b)
        case (name, _: Raster) =>
          Left(s"--stack: $name is a floating-point image; an 8-bit output joins PPM or PNG bands")
      }
      .flatMap {
        case first :: rest
            if rest.forall(b => b.width == first.width && b.maxval == first.maxval) =>
          Right(Bitmap.stack(first :: rest))
        case _ =>
          Left(s"--stack: the images ${images.map(_._1).mkString(", ")} differ in width or depth")
      }

  private def joinRasters(images: List[(String, Bitmap | Raster)]): Either[String, Raster] =
    Eithers
      .traverse(images) {
        case (_, r: Raster)    => Right(r)
        case (name, _: Bitmap) =>
          Left(
            s"--stack: $name is an 8-bit image; a .pfm or .exr output joins PFM or OpenEXR bands"
          )
      }
      .flatMap {
        case first :: rest if rest.forall(_.width == first.width) =>
          Right(Raster.stack(first :: rest))
        case _ => Left(s"--stack: the images ${images.map(_._1).mkString(", ")} differ in width")
      }
