package tracer.cli

import tracer.Eithers

/** One frame of a batch: the scene file to read and the picture to write, as the list names them.
  *
  * @param line   the frame's line in the list, for messages
  * @param scene  the scene file (relative paths in it resolve against its own directory)
  * @param output the picture to write
  * @param band   the rows to render, as `-R a:b` would give them; the whole picture when absent
  */
final case class BatchFrame(line: Int, scene: String, output: String, band: Option[Range] = None)

/** The list that `tracer --batch LIST` renders in one process (docs/cli.md, Batches). */
object Batch:

  /** The frames of a batch list: one a line, `SCENE<TAB>OUTPUT` or `SCENE<TAB>OUTPUT<TAB>a:b`
    * (the rows of a band, as `-R a:b`); blank lines and lines starting with `#` are skipped. A line
    * of any other shape is an error naming it; a list without frames is an error too.
    */
  def parse(text: String): Either[String, List[BatchFrame]] =
    val lines  = text.linesIterator.zipWithIndex.map((l, i) => (l.stripSuffix("\r"), i + 1)).toList
    val frames = lines.filterNot((l, _) => l.isBlank || l.startsWith("#"))
    Eithers.traverse(frames) { (text, n) =>
      text.split("\t", -1) match
        case Array(scene, output) if scene.nonEmpty && output.nonEmpty =>
          Right(BatchFrame(n, scene, output))
        case Array(scene, output, rows) if scene.nonEmpty && output.nonEmpty =>
          Options
            .band(rows)
            .left
            .map(why => s"line $n: $why")
            .map(band => BatchFrame(n, scene, output, Some(band)))
        case _ => Left(s"line $n: expected SCENE<TAB>OUTPUT[<TAB>a:b], got '${text.take(60)}'")
    } match
      case Right(Nil) => Left("the list names no frames")
      case other      => other
