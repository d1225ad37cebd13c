package tracer.testkit

import tracer.image.{Bitmap, Colour}
import tracer.io.SceneXml
import tracer.scene.Scene

/** Helpers for suites that read scene documents written inline: textures are a white texel, a
  * body gets a camera, errors are checked for their line, element and words, and every scene read
  * whole is checked against the schema too.
  */
trait SceneDocuments extends munit.FunSuite:

  /** The texture every `<texture>` loads. */
  val texel: Bitmap = Bitmap.fill(1, 1, Colour.White)

  /** The document `xml`, read with every texture the white texel. */
  def parse(xml: String): Either[tracer.io.SceneError, Scene] =
    SceneXml.parse(xml, _ => Right(texel))

  /** The scene `xml` describes; the test fails if it is refused, or if `docs/scene.xsd` does not
    * find it valid (so every scene a suite reads is also a test of the schema).
    */
  def scene(xml: String)(using munit.Location): Scene =
    val read = parse(xml).fold(e => fail(e.describe), identity)
    SceneSchema.validate(xml).left.foreach(why => fail(s"docs/scene.xsd refuses the scene: $why"))
    read

  /** A document holding `body` after a camera on line 2 (so `body` starts on line 3). */
  def withCamera(body: String): String =
    s"""<scene>\n<camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>\n$body</scene>"""

  /** Checks that `xml` is refused at `line` on `element`, the message holding each of `expected`. */
  def assertRefused(xml: String, line: Int, element: String, expected: String*)(using
      munit.Location
  ): Unit =
    parse(xml) match
      case Right(s) => fail(s"parsed $s")
      case Left(e)  =>
        assertEquals((e.line, e.element), (Some(line), element), e.describe)
        expected.foreach(x => assert(e.describe.contains(x), s"'${e.describe}' lacks '$x'"))
