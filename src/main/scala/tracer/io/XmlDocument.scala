package tracer.io

import java.io.{ByteArrayInputStream, StringReader}
import javax.xml.parsers.SAXParserFactory
import org.xml.sax.helpers.DefaultHandler
import org.xml.sax.{Attributes, InputSource, Locator, SAXException, SAXParseException}
import scala.collection.mutable.ListBuffer
import scala.util.control.NoStackTrace

/** One element of a scene document, as much of it as the scene reader needs.
  *
  * @param name       the element's name
  * @param attributes its attributes, by name
  * @param children   its child elements, in document order
  * @param strayText  the first text inside it that is not blank, if any (the format has none)
  * @param line       the line of its start tag
  */
private[io] final case class Element(
    name: String,
    attributes: Map[String, String],
    children: List[Element],
    strayText: Option[StrayText],
    line: Option[Int]
):
  /** An error about this element. */
  def error(message: String): SceneError = SceneError(line, name, message)

  /** A failed result with an error about this element. */
  def fail[A](message: String): Either[SceneError, A] = Left(error(message))

  /** The raw text of attribute `key`, if present. */
  def attribute(key: String): Option[String] = attributes.get(key)

/** Text found between elements, trimmed (and cut short), with the line where it starts. */
private[io] final case class StrayText(text: String, line: Option[Int])

/** What a scene document is read into, element by element, as the parser streams it. Each call
  * returns an error to stop reading, the first one found in document order.
  */
private[io] trait XmlVisitor:
  /** The document element's start tag (its children and text still to come). */
  def root(element: Element): Either[SceneError, Unit]

  /** A child of the document element, whole, as soon as its end tag is read. */
  def child(element: Element): Either[SceneError, Unit]

  /** Text between the document element's children that is not blank. */
  def rootText(text: StrayText): Either[SceneError, Unit]

  /** The end of the document. */
  def end(): Either[SceneError, Unit]

/** Reads XML with the JDK's SAX parser, hardened, as a stream: the document element's children
  * are handed over one by one and then forgotten, so a big scene is never held as a whole tree
  * (docs/performance.md, loading big scenes). Scenes are first given to [[XmlSubset]], which
  * reads the XML scene files use faster and hands everything else here.
  */
private[io] object XmlDocument:

  /** Reads `text`, refusing any `<!DOCTYPE>` before anything in it is expanded or fetched. */
  def read(text: String, visitor: XmlVisitor): Either[SceneError, Unit] =
    read(InputSource(StringReader(text)), visitor)

  /** Reads the bytes of a document, honouring the encoding its XML declaration names. */
  def read(bytes: Array[Byte], visitor: XmlVisitor): Either[SceneError, Unit] =
    read(InputSource(ByteArrayInputStream(bytes)), visitor)

  private def read(source: InputSource, visitor: XmlVisitor): Either[SceneError, Unit] =
    val handler = StreamingHandler(visitor)
    try
      val reader = hardenedReader()
      reader.setContentHandler(handler)
      reader.setErrorHandler(handler)
      reader.parse(source)
      visitor.end()
    catch
      case Stop(error)          => Left(error)
      case Stopped(error)       => Left(error)
      case e: SAXParseException =>
        val line    = Option(e.getLineNumber).filter(_ > 0)
        val text    = Option(e.getMessage).getOrElse("malformed XML")
        val message =
          if text.contains("DOCTYPE") then
            "a <!DOCTYPE> is not allowed in a scene (no entities are expanded)"
          else s"malformed XML: $text"
        Left(SceneError(line, "", message))
      case e: SAXException => Left(SceneError(None, "", s"malformed XML: ${e.getMessage}"))

  private def hardenedReader() =
    val factory = SAXParserFactory.newInstance()
    factory.setNamespaceAware(false)
    factory.setValidating(false)
    factory.setXIncludeAware(false)
    // No DTD at all: this stops entity expansion ("billion laughs") and external entities at once.
    factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true)
    factory.setFeature("http://xml.org/sax/features/external-general-entities", false)
    factory.setFeature("http://xml.org/sax/features/external-parameter-entities", false)
    factory.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false)
    factory.newSAXParser().getXMLReader

  /** The visitor's error, when the parser wrapped the [[Stop]] that carried it. */
  private def stopped(e: Throwable): Option[SceneError] =
    Iterator
      .unfold[Throwable, Option[Throwable]](Some(e))(_.map(t => (t, Option(t.getCause))))
      .take(10)
      .collectFirst { case Stop(error) => error }

  /** A SAX exception that wrapped a [[Stop]]: the visitor's error it carried. */
  private object Stopped:
    /** The visitor's error inside `e`, if `e` wrapped a [[Stop]]. */
    def unapply(e: SAXException): Option[SceneError] = stopped(e)

  /** Carries the visitor's error out of the parser's callbacks. */
  private final case class Stop(error: SceneError) extends Exception with NoStackTrace

  /** The most of a stray text kept for its message. */
  private val StrayTextKept = 64

  /** Builds each child of the document element as a small tree, with the line of every start tag
    * and of every stray text, and hands it to the visitor when it ends.
    *
    * Perf: mutable builders, one per open element, never seen outside this handler.
    */
  private final class StreamingHandler(visitor: XmlVisitor) extends DefaultHandler:
    private var locator: Option[Locator] = None
    private var open: List[Open]         = Nil

    /** An element whose end tag is still to come. */
    private final class Open(
        val name: String,
        val attributes: Map[String, String],
        val line: Option[Int]
    ):
      val children                    = ListBuffer.empty[Element]
      var stray: Option[StrayText]    = None
      var text: Option[StringBuilder] = None // the stray text being gathered, from its first letter
      var textLine: Option[Int]       = None

    override def setDocumentLocator(l: Locator): Unit = locator = Some(l)

    override def startElement(uri: String, local: String, qname: String, attrs: Attributes): Unit =
      settleText()
      val attributes =
        (0 until attrs.getLength).map(i => attrs.getQName(i) -> attrs.getValue(i)).toMap
      val element = Open(qname, attributes, locator.map(_.getLineNumber).filter(_ > 0))
      if open.isEmpty then check(visitor.root(Element(qname, attributes, Nil, None, element.line)))
      open = element :: open

    override def endElement(uri: String, local: String, qname: String): Unit =
      settleText()
      val closing = open.head
      open = open.tail
      val element = Element(
        closing.name,
        closing.attributes,
        closing.children.toList,
        closing.stray,
        closing.line
      )
      open match
        case Nil         => ()
        case _ :: Nil    => check(visitor.child(element)) // a child of the root: handed over
        case parent :: _ => parent.children += element

    /** Gathers the first non-blank text of the innermost open element. The locator stands at the
      * end of the chunk, so the text's line counts back the line breaks after its first letter.
      */
    override def characters(ch: Array[Char], start: Int, length: Int): Unit =
      open.headOption.filter(_.stray.isEmpty).foreach { element =>
        val end = start + length
        element.text match
          case None =>
            var i = start
            while i < end && Character.isWhitespace(ch(i)) do i += 1
            if i < end then
              val text = StringBuilder()
              element.text = Some(text)
              element.textLine = locator.map(_.getLineNumber - (i until end).count(ch(_) == '\n'))
              text.appendAll(ch, i, Math.min(end - i, StrayTextKept))
          case Some(text) =>
            if text.length < StrayTextKept then
              text.appendAll(ch, start, Math.min(length, StrayTextKept - text.length))
      }

    /** Ends the text gathered since the last tag: the first such text is the element's stray text. */
    private def settleText(): Unit =
      open.headOption.foreach { element =>
        element.text.foreach { text =>
          val stray = StrayText(text.toString.trim, element.textLine.filter(_ > 0))
          element.text = None
          element.stray = Some(stray)
          if open.tail.isEmpty then check(visitor.rootText(stray))
        }
      }

    private def check(result: Either[SceneError, Unit]): Unit =
      result.left.foreach(error => throw Stop(error))
