package tracer.cli

import java.nio.file.Path
import tracer.Eithers
import tracer.image.Bitmap
import tracer.io.{Images, OutputFile, TextureFiles}

/** `--stack`: pictures joined one below the other, as `scripts/still.sh` joins its bands. */
private[cli] object Stack:

  /** Writes `output` as the images `bands`, read in order, one below the other; all must share
    * a width and depth. The output is written whole or not at all.
    */
  def write(bands: List[String], output: String, cwd: Path): Either[String, Unit] =
    val target = cwd.resolve(output)
    for
      _      <- OutputFile.checkWritable(target)
      images <- Eithers.traverse(bands)(name =>
        TextureFiles.read(cwd.resolve(name)).left.map(why => s"--stack: cannot read $name: $why")
      )
      joined <- images match
        case first :: rest
            if rest.forall(b => b.width == first.width && b.maxval == first.maxval) =>
          Right(Bitmap.stack(first :: rest))
        case _ => Left(s"--stack: the images ${bands.mkString(", ")} differ in width or depth")
      _ <- Images.save(joined, target)
    yield ()
