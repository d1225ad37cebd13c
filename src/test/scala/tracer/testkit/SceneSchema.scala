package tracer.testkit

import java.io.StringReader
import java.nio.file.Path
import javax.xml.XMLConstants
import javax.xml.transform.stream.StreamSource
import javax.xml.validation.SchemaFactory
import org.xml.sax.SAXParseException

/** The scene format's XML Schema, `docs/scene.xsd`, read once with the JDK's validator. */
object SceneSchema:

  /** Where the schema lives in the repository (the tests run from its top). */
  val file: Path = Path.of("docs/scene.xsd")

  private lazy val schema =
    SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI).newSchema(file.toFile)

  /** `Right(())` when `xml` is valid against the schema, else the validator's first complaint
    * with its line.
    */
  def validate(xml: String): Either[String, Unit] =
    val validator = schema.newValidator()
    // The schema is local: a scene must not make the validator fetch anything.
    validator.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "")
    validator.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "")
    try Right(validator.validate(StreamSource(StringReader(xml))))
    catch case e: SAXParseException => Left(s"line ${e.getLineNumber}: ${e.getMessage}")
