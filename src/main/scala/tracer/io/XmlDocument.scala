package tracer.io

import java.io.{ByteArrayInputStream, StringReader}
import java.util.IdentityHashMap
import javax.xml.parsers.SAXParserFactory
import org.xml.sax.{Attributes, InputSource, Locator, SAXException, SAXParseException}
import scala.xml.parsing.NoBindingFactoryAdapter
import scala.xml.{Elem, MetaData, NamespaceBinding, Node, Text}

/** An XML document parsed safely, with the line of every element's start tag and of the first
  * non-blank character of every text between elements.
  *
  * @param root the document element
  * @param lines where each element or text starts, by identity
  */
final class XmlDocument private (val root: Elem, lines: IdentityHashMap[Node, Int]):

  /** The line of `node`'s start tag, or of a text node's first non-blank character, if it came
    * from this document.
    */
  def lineOf(node: Node): Option[Int] = Option(lines.get(node))

/** Parses XML with scala-xml and a hardened SAX parser. */
object XmlDocument:

  /** Parses `text`, refusing any `<!DOCTYPE>` before anything in it is expanded or fetched. */
  def parse(text: String): Either[SceneError, XmlDocument] = parse(InputSource(StringReader(text)))

  /** Parses the bytes of a document, honouring the encoding its XML declaration names. */
  def parse(bytes: Array[Byte]): Either[SceneError, XmlDocument] =
    parse(InputSource(ByteArrayInputStream(bytes)))

  private def parse(source: InputSource): Either[SceneError, XmlDocument] =
    val adapter = LineRecordingAdapter()
    try
      val document = adapter.loadDocument(source, hardenedReader())
      document.docElem match
        case root: Elem => Right(XmlDocument(root, adapter.lines))
        case _          => Left(SceneError(None, "", "the document has no root element"))
    catch
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

  /** scala-xml's tree builder, noting the line of each start tag and of the first non-blank
    * character of each text as the SAX locator reports them.
    */
  private final class LineRecordingAdapter extends NoBindingFactoryAdapter:
    val lines: IdentityHashMap[Node, Int] = IdentityHashMap()
    private var locator: Option[Locator]  = None
    private var openLines: List[Int]      = Nil
    private var textLine: Option[Int]     = None

    /** Notes where the text gathered so far first shows a non-blank character: the locator
      * stands at the end of the chunk, so count back the line breaks after that character.
      */
    override def characters(ch: Array[Char], start: Int, length: Int): Unit =
      if textLine.isEmpty then
        val first = (start until start + length).find(i => !Character.isWhitespace(ch(i)))
        first.foreach { i =>
          val breaksAfter = (i until start + length).count(ch(_) == '\n')
          textLine = locator.map(_.getLineNumber - breaksAfter).filter(_ > 0)
        }
      super.characters(ch, start, length)

    override def createText(text: String): Text =
      val node = super.createText(text)
      textLine.foreach(line => lines.put(node, line))
      textLine = None
      node

    override def setDocumentLocator(l: Locator): Unit = locator = Some(l)

    override def startElement(
        uri: String,
        local: String,
        qname: String,
        attributes: Attributes
    ): Unit =
      openLines = locator.fold(0)(_.getLineNumber) :: openLines
      super.startElement(uri, local, qname, attributes)

    override def createNode(
        prefix: String,
        label: String,
        attributes: MetaData,
        scope: NamespaceBinding,
        children: List[Node]
    ): Elem =
      val element = super.createNode(prefix, label, attributes, scope, children)
      openLines match
        case line :: rest =>
          if line > 0 then lines.put(element, line)
          openLines = rest
        case Nil => ()
      element
