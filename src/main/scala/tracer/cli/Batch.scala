package tracer.cli

import tracer.Eithers

/** One frame of a batch: the scene file to read and the picture to write, as the list names them.
  *
  * @param line   the frame's line in the list, for messages
  * @param scene  the scene file (relative paths in it resolve against its own directory)
  * @param output the picture to write
  * @param band   the rows to render, as `-R a:b` would give them; the whole picture when absent
  * @param options render options of this frame alone (`-m path -s 4`), applied on top of the
  *   command line's; none when the line gives none
  */
final case class BatchFrame(
    line: Int,
    scene: String,
    output: String,
    band: Option[Range] = None,
    options: List[String] = Nil
)

/** The list that `tracer --batch LIST` renders in one process (docs/cli.md, Batches). */
object Batch:

  /** The frames of a batch list: one a line, `SCENE<TAB>OUTPUT`, then optionally `<TAB>a:b` (the
    * rows of a band, as `-R a:b`) and `<TAB>OPTIONS` (render options of that frame alone,
    * separated by spaces, starting with `-`); blank lines and lines starting with `#` are skipped.
    * A line of any other shape is an error naming it; a list without frames is an error too.
    */
  def parse(text: String): Either[String, List[BatchFrame]] =
    val lines  = text.linesIterator.zipWithIndex.map((l, i) => (l.stripSuffix("\r"), i + 1)).toList
    val frames = lines.filterNot((l, _) => l.isBlank || l.startsWith("#"))
    Eithers.traverse(frames) { (text, n) =>
      def rows(field: String) = Options.band(field).left.map(why => s"line $n: $why").map(Some(_))
      def options(field: String) = field.trim.split(" +").toList
      text.split("\t", -1).toList match
        case scene :: output :: rest if scene.nonEmpty && output.nonEmpty =>
          val fields: Either[String, (Option[Range], List[String])] = rest match
            case Nil                                      => Right((None, Nil))
            case List(more) if more.startsWith("-")       => Right((None, options(more)))
            case List(band)                               => rows(band).map((_, Nil))
            case List(band, more) if more.startsWith("-") =>
              rows(band).map((_, options(more)))
            case _ => Left(shape(n, text))
          fields.map((band, more) => BatchFrame(n, scene, output, band, more))
        case _ => Left(shape(n, text))
    } match
      case Right(Nil) => Left("the list names no frames")
      case other      => other

  private def shape(n: Int, text: String): String =
    s"line $n: expected SCENE<TAB>OUTPUT[<TAB>a:b][<TAB>OPTIONS], got '${text.take(60)}'"
