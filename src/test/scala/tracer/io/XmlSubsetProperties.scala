package tracer.io

import java.nio.charset.StandardCharsets.{ISO_8859_1, UTF_16, UTF_8}
import java.nio.file.{Files, Path}
import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAllNoShrink
import scala.jdk.CollectionConverters.*

/** [[XmlSubset]] against the SAX reader of [[XmlDocument]]: the same visitor calls with the same
  * elements (names, attributes, children, lines) on every scene of the project and on random
  * documents; `None` (so SAX reads it) for everything outside the subset.
  */
class XmlSubsetProperties extends ScalaCheckSuite:

  /** What a visitor was told, in order. */
  private enum Event:
    case Root(e: Element)
    case Child(e: Element)
    case RootText(t: StrayText)
    case End

  /** Records every call; answers the `failAt`-th call (from 0) with an error. */
  private final class Recorder(failAt: Int = -1) extends XmlVisitor:
    val events        = Vector.newBuilder[Event]
    private var calls = 0 // Why: counts the calls to fail at one of them
    private def note(e: Event): Either[SceneError, Unit] =
      events += e
      calls += 1
      if calls - 1 == failAt then Left(SceneError(None, "test", s"stop at $failAt")) else Right(())
    def root(e: Element): Either[SceneError, Unit]       = note(Event.Root(e))
    def child(e: Element): Either[SceneError, Unit]      = note(Event.Child(e))
    def rootText(t: StrayText): Either[SceneError, Unit] = note(Event.RootText(t))
    def end(): Either[SceneError, Unit]                  = note(Event.End)

  private type Outcome = (Either[SceneError, Unit], Vector[Event])

  private def sax(bytes: Array[Byte], failAt: Int = -1): Outcome =
    val r = Recorder(failAt)
    (XmlDocument.read(bytes, r), r.events.result())

  private def fast(bytes: Array[Byte], failAt: Int = -1): Option[Outcome] =
    val r = Recorder(failAt)
    XmlSubset.read(bytes, r).map((_, r.events.result()))

  private def fastText(text: String): Option[Outcome] =
    val r = Recorder()
    XmlSubset.read(text, r).map((_, r.events.result()))

  /** The fast reader read `bytes` itself, exactly as SAX does. */
  private def assertSame(bytes: Array[Byte], clue: => String): Unit =
    val expected = sax(bytes)
    assert(expected._1.isRight, s"SAX refused it: ${expected._1} $clue")
    assertEquals(fast(bytes), Some(expected), clue)

  /** Every `.xml` file under `dir`. */
  private def scenes(dir: Path): List[Path] =
    if !Files.isDirectory(dir) then Nil
    else
      Files
        .walk(dir)
        .iterator
        .asScala
        .filter(p => p.toString.endsWith(".xml") && !p.toString.contains("/bench/"))
        .toList
        .sorted

  test("every scene of the project and the test resources reads as SAX reads it"):
    val files = List("scenes", "launcher/training", "src/test/resources")
      .flatMap(d => scenes(Path.of(d)))
    assert(files.size >= 20, files.toString)
    for file <- files do assertSame(Files.readAllBytes(file), file.toString)

  test(
    "thousands of distinct names and values (its table of texts made before overflows) read as SAX reads them"
  ):
    // Names and values share the table that makes each repeated text once: with 3,000 of each
    // many land on a slot another holds, and a repeat after its slot was taken must still read
    // as itself, and a repeated attribute still be refused.
    val items = (0 until 3000).map { k =>
      s"""<e$k a$k="v$k" b="${k % 7}" c="${"x" * (k % 30)}" d="-$k.000000"/>"""
    }
    val doc = s"""<scene>${items.mkString("\n")}\n${items.reverse.mkString("\n")}</scene>"""
    assertSame(doc.getBytes(UTF_8), "3000 names")
    val twice = (0 until 3000).map(k => s"""<e a$k="1" b="2" a$k="3"/>""")
    assertEquals(fast(s"<scene>${twice.mkString}</scene>".getBytes(UTF_8)), None)

  test("a visitor's error stops both readers at the same call"):
    val bytes = Files.readAllBytes(Path.of("scenes/showcase.xml"))
    for failAt <- List(0, 1, 3, 7) do
      val expected = sax(bytes, failAt)
      assert(expected._1.isLeft)
      assertEquals(fast(bytes, failAt), Some(expected), failAt.toString)

  // Random documents: trees of elements with attributes, comments, whitespace and references.

  private val nameStart = Gen.oneOf(('a' to 'z') ++ ('A' to 'Z') ++ "_:")
  private val nameChar  = Gen.oneOf(('a' to 'z') ++ ('0' to '9') ++ "-._:")
  private val name      =
    for s <- nameStart; n <- Gen.choose(0, 6); r <- Gen.listOfN(n, nameChar) yield (s :: r).mkString

  private val space =
    Gen
      .choose(1, 4)
      .flatMap(n => Gen.listOfN(n, Gen.oneOf(" ", "\n", "\t", "\r\n", "\r")))
      .map(_.mkString)
  private val maybeSpace = Gen.frequency(3 -> Gen.const(""), 1 -> space)

  private val valuePart: Gen[String] = Gen.frequency(
    10 -> Gen.oneOf("0", "-1.5", "2.5e-3", "x", "true", "a b", ".", "-", "=", ">", "/"),
    2  -> Gen.oneOf(" ", "\t", "\n", "\r\n", "\r", "  "),
    2  -> Gen.oneOf("&lt;", "&gt;", "&amp;", "&apos;", "&quot;"),
    2  -> Gen.oneOf("&#10;", "&#13;", "&#9;", "&#x41;", "&#x1F600;", "&#0065;", "&#xe9;", "&#x3C;"),
    1  -> Gen.oneOf("é", "漢", "\u00a0")
  )
  private val value = Gen.choose(0, 5).flatMap(n => Gen.listOfN(n, valuePart)).map(_.mkString)

  private val comment =
    Gen.oneOf("<!---->", "<!-- a comment -->", "<!--\nline\r\nbreaks\n-->", "<!-- é - x -->")

  /** Whitespace and comments between tags. */
  private val misc = Gen.frequency(
    4 -> maybeSpace,
    1 -> (for a <- maybeSpace; c <- comment; b <- maybeSpace yield a + c + b)
  )

  private def attributes: Gen[String] =
    for
      n     <- Gen.choose(0, 4)
      keys  <- Gen.listOfN(n, name).map(_.distinct)
      parts <- Gen.sequence[List[String], String](keys.map { k =>
        for
          s     <- space
          e1    <- maybeSpace
          e2    <- maybeSpace
          quote <- Gen.oneOf('"', '\'')
          v     <- value
        yield
          val other = if quote == '"' then "'" else "\""
          val text  = v.replace(quote.toString, if quote == '"' then "&quot;" else "&apos;")
          s"$s$k$e1=$e2$quote$text$other$quote"
      })
    yield parts.mkString

  private def element(depth: Int): Gen[String] =
    for
      n     <- name
      attrs <- attributes
      s     <- maybeSpace
      kids  <-
        if depth <= 0 then Gen.const(Nil)
        else Gen.choose(0, 3).flatMap(k => Gen.listOfN(k, element(depth - 1)))
      gaps  <- Gen.listOfN(kids.size + 1, misc)
      empty <- Gen.oneOf(true, false)
      close <- maybeSpace
    yield
      if kids.isEmpty && empty then s"<$n$attrs$s/>"
      else
        val inside = kids.zip(gaps).map((k, g) => g + k).mkString + gaps.last
        s"<$n$attrs$s>$inside</$n$close>"

  private val declaration = Gen.oneOf(
    "",
    "<?xml version=\"1.0\"?>",
    "<?xml version='1.0' encoding='UTF-8'?>",
    "<?xml version=\"1.0\" encoding=\"utf-8\" ?>\n",
    "<?xml\tversion = \"1.0\"  ?>\r\n"
  )

  private val document: Gen[String] =
    for d <- declaration; a <- misc; root <- element(3); b <- misc yield d + a + root + b

  property("random documents in the subset read as SAX reads them, as bytes and as text"):
    forAllNoShrink(document) { doc =>
      val bytes = doc.getBytes(UTF_8)
      assertSame(bytes, doc)
      assertEquals(fastText(doc), Some(sax(bytes)), doc)
    }

  property("whatever the fast reader accepts of a damaged document, SAX reads the same"):
    val damaged =
      for
        doc <- document
        at  <- Gen.choose(0, doc.length)
        cut <- Gen.choose(0, 3)
        put <- Gen.oneOf(
          "",
          "<",
          ">",
          "&",
          "&x;",
          "/",
          "\"",
          "'",
          "--",
          "x",
          "<!",
          "<?",
          "]]>",
          "\u0001",
          "=",
          " "
        )
      yield doc.take(at) + put + doc.drop(math.min(doc.length, at + cut))
    forAllNoShrink(damaged) { doc =>
      val bytes = doc.getBytes(UTF_8)
      fast(bytes).foreach(outcome => assertEquals(outcome, sax(bytes), doc))
    }

  // The cases outside the subset: each one goes to SAX.

  private val camera =
    """<camera><location x="0" y="0" z="0"/><lookat x="0" y="0" z="1"/><up x="0" y="1" z="0"/></camera>"""

  private def outside(clue: String, doc: String): Unit = outsideBytes(clue, doc.getBytes(UTF_8))

  private def outsideBytes(clue: String, bytes: Array[Byte]): Unit =
    assertEquals(fast(bytes), None, clue)

  test("a DOCTYPE goes to SAX (which refuses it before expanding anything)"):
    outside(
      "doctype",
      s"""<?xml version="1.0"?>\n<!DOCTYPE scene [<!ENTITY a "b">]>\n<scene>$camera</scene>"""
    )
    outside("doctype", s"""<!DOCTYPE scene>\n<scene>$camera</scene>""")

  test("a CDATA section goes to SAX"):
    outside("cdata", s"<scene>$camera<![CDATA[ ]]></scene>")

  test("a processing instruction other than the declaration goes to SAX"):
    outside("pi", s"""<?xml version="1.0"?><?tracer fast?><scene>$camera</scene>""")
    outside("pi inside", s"<scene><?tracer fast?>$camera</scene>")
    outside("declaration not first", s"""\n<?xml version="1.0"?><scene>$camera</scene>""")
    outside("standalone", s"""<?xml version="1.0" standalone="yes"?><scene>$camera</scene>""")
    outside("version 1.1", s"""<?xml version="1.1"?><scene>$camera</scene>""")
    outside("a line break in the declaration", s"""<?xml\nversion="1.0"?><scene>$camera</scene>""")

  test("an entity other than the five predefined ones, or a reference in text, goes to SAX"):
    outside("nbsp", s"""<scene>$camera<light a="&nbsp;"/></scene>""")
    outside("unterminated", s"""<scene>$camera<light a="&amp"/></scene>""")
    outside("reference in text", s"<scene>$camera&amp;</scene>")
    outside("bad character reference", s"""<scene>$camera<light a="&#0;"/></scene>""")
    outside("upper-case X", s"""<scene>$camera<light a="&#X41;"/></scene>""")

  test("text that is not blank goes to SAX"):
    outside("root text", s"<scene>$camera hello</scene>")
    outside("nested text", s"<scene><camera>x</camera></scene>")
    outside("before the root", s"x<scene>$camera</scene>")
    outside("after the root", s"<scene>$camera</scene>x")

  test("malformed markup of any kind goes to SAX"):
    for (clue, doc) <- List(
        "mismatched end tag"          -> s"<scene>$camera</scen>",
        "unclosed"                    -> s"<scene>$camera",
        "empty"                       -> "",
        "two roots"                   -> s"<scene/><scene/>",
        "duplicate attribute"         -> s"""<scene a="1" a="2">$camera</scene>""",
        "no space between attributes" -> s"""<scene a="1"b="2">$camera</scene>""",
        "< in a value"                -> s"""<scene a="<">$camera</scene>""",
        "unquoted value"              -> s"""<scene a=1>$camera</scene>""",
        "-- in a comment"             -> s"<scene><!-- a -- b -->$camera</scene>",
        "unclosed comment"            -> s"<scene><!-- a $camera</scene>",
        "control character"           -> s"<scene>\u0001$camera</scene>",
        "non-ASCII name"              -> s"<scène>$camera</scène>"
      )
    do outside(clue, doc)

  test("an encoding other than UTF-8, a byte order mark or invalid UTF-8 goes to SAX"):
    val doc = s"""<?xml version="1.0" encoding="ISO-8859-1"?><scene a="é">$camera</scene>"""
    outsideBytes("latin-1", doc.getBytes(ISO_8859_1))
    outsideBytes("utf-16", s"<scene>$camera</scene>".getBytes(UTF_16))
    outsideBytes(
      "bom",
      Array[Byte](0xef.toByte, 0xbb.toByte, 0xbf.toByte) ++ s"<scene>$camera</scene>".getBytes(
        UTF_8
      )
    )
    outsideBytes(
      "invalid utf-8",
      s"<scene a='".getBytes(UTF_8) ++ Array(0xff.toByte) ++ s"'>$camera</scene>".getBytes(UTF_8)
    )

  test("SceneXml gives SAX's message for a document outside the subset"):
    val doc      = s"""<?xml version="1.0"?>\n<!DOCTYPE scene>\n<scene>$camera</scene>"""
    val expected = Left(
      SceneError(Some(2), "", "a <!DOCTYPE> is not allowed in a scene (no entities are expanded)")
    )
    assertEquals(
      SceneXml
        .parse(doc.getBytes(UTF_8), SceneSources(_ => Left("no"), _ => Left("no")))
        .map(_ => ()),
      expected
    )
