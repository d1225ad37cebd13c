package tracer.io

/** Why a scene could not be read: the element, its line in the file, and what is wrong.
  *
  * @param line    the line of the element's start tag, when known
  * @param element the element's name, without brackets; empty for errors in the XML itself
  * @param message what is wrong, as a clause ("radius must be greater than 0, got -1")
  */
final case class SceneError(line: Option[Int], element: String, message: String):

  /** The one-line description: `line 12: <sphere>: radius must be greater than 0, got -1`. */
  def describe: String =
    val at = line.fold("")(l => s"line $l: ")
    val in = if element.isEmpty then "" else s"<$element>: "
    s"$at$in$message"
