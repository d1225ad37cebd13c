package tracer.io

import java.nio.ByteBuffer
import java.nio.charset.{CharacterCodingException, CodingErrorAction, StandardCharsets}
import scala.util.control.NoStackTrace

/** A reader for the part of XML that scene files use, on the document's characters in tight
  * loops, streaming the same [[Element]]s (with the same lines) to the same [[XmlVisitor]] calls
  * as [[XmlDocument]]'s SAX reader.
  *
  * The subset: UTF-8 (or ASCII) text, an XML declaration of version 1.0 (encoding UTF-8, if
  * named) at the very start, elements with ASCII names, attributes in `'` or `"` whose values
  * may hold the five predefined entities and numeric character references, comments, and
  * whitespace between tags. Anything else (a DOCTYPE, CDATA, a processing instruction, another
  * entity, text that is not blank, another encoding, a byte order mark, a character XML
  * forbids, malformed markup of any kind) is answered with `None`, and the caller hands the whole
  * document to SAX, so every message and every refusal stays SAX's (docs/architecture.md, Scene
  * reading). Whatever the subset accepts, SAX accepts as the same tree: `XmlSubsetProperties`
  * holds the two to that.
  */
private[io] object XmlSubset:

  /** The visitor's answer to `bytes`, or `None` when the document is outside the subset (then
    * the visitor may have seen its first elements; the caller starts again with a fresh one).
    */
  def read(bytes: Array[Byte], visitor: XmlVisitor): Option[Either[SceneError, Unit]] =
    decode(bytes).flatMap((chars, end) => Scanner(chars, end, visitor).document())

  /** [[read]] of a document given as text (its declared encoding must still be UTF-8). */
  def read(text: String, visitor: XmlVisitor): Option[Either[SceneError, Unit]] =
    val chars = text.toCharArray
    if allowed(chars, chars.length) then Scanner(chars, chars.length, visitor).document()
    else None

  /** The characters of UTF-8 `bytes` and their count, or `None` when they are not strict UTF-8
    * or hold a character the subset leaves to SAX.
    */
  private def decode(bytes: Array[Byte]): Option[(Array[Char], Int)] =
    val decoder = StandardCharsets.UTF_8
      .newDecoder()
      .onMalformedInput(CodingErrorAction.REPORT)
      .onUnmappableCharacter(CodingErrorAction.REPORT)
    try
      val buffer = decoder.decode(ByteBuffer.wrap(bytes))
      val chars  = buffer.array
      val end    = buffer.limit
      if buffer.arrayOffset == 0 && allowed(chars, end) then Some((chars, end)) else None
    catch case _: CharacterCodingException => None

  /** True when `chars(0 until end)` holds only characters the subset reads itself: no control
    * character but tab and line breaks, no surrogate, no U+FFFE or U+FFFF, no byte order mark.
    *
    * Perf: one scan over the document (SceneLoadBench; scripts/bench.sh --loading).
    */
  private def allowed(chars: Array[Char], end: Int): Boolean =
    var i  = 0
    var ok = !(end > 0 && chars(0) == '\uFEFF')
    while ok && i < end do
      val c = chars(i)
      if c < ' ' then ok = c == '\n' || c == '\r' || c == '\t'
      else if c >= '\uD800' then ok = c > '\uDFFF' && c < '\uFFFE'
      i += 1
    ok

  /** Leaves the subset: the document goes to SAX. */
  private object Outside extends Exception with NoStackTrace

  /** Carries the visitor's error out of the scan. */
  private final class Stopped(val error: SceneError) extends Exception with NoStackTrace

  /** The scan of one document: a cursor, the line it stands on and the open elements.
    *
    * Perf: a cursor over a char array, mutable fields and while loops, so the interpreter and C1
    * run few bytecodes per character while the scene file is read cold (scripts/bench.sh
    * --loading; docs/performance.md, round 7). Nothing of it is seen outside [[read]].
    */
  private final class Scanner(chars: Array[Char], end: Int, visitor: XmlVisitor):
    private var i    = 0
    private var line = 1
    // The open elements, innermost at depth - 1: name, attributes, line, children (reversed).
    private var depth    = 0
    private var names    = new Array[String](16)
    private var attrs    = new Array[Map[String, String]](16)
    private var lines    = new Array[Int](16)
    private var children = new Array[List[Element]](16)
    // The start tag being read: its attributes' names and values, in document order.
    private var keys   = new Array[String](8)
    private var values = new Array[String](8)
    // Perf: names and short values already made, by a hash of their characters; a scene repeats
    // a few dozen names and many values (colours, grid coordinates), and each repeat is the
    // same String instead of a new one: the 5 MB scene allocated about 100 MB, one young
    // collection (docs/performance.md, round 24).
    // An empty slot holds "", which only the empty text matches, and is that text.
    private val known = Array.fill(XmlSubset.KnownSlots)("")
    // Perf: the last line's Some, shared by the elements that start on it, and its line as an
    // Int (comparing with the Option's would box).
    private var lastLine              = 0
    private var lastSome: Option[Int] = Some(0)

    /** The whole document: `Some` of the visitor's answer, or `None` outside the subset. */
    def document(): Option[Either[SceneError, Unit]] =
      try
        declaration()
        misc()
        if at('<') && i + 1 < end && isNameStart(chars(i + 1)) then element() else throw Outside
        misc()
        if i != end then throw Outside
        Some(visitor.end())
      catch
        case Outside    => None
        case s: Stopped => Some(Left(s.error))

    private def at(c: Char): Boolean = i < end && chars(i) == c

    private def startsWith(s: String): Boolean =
      s.length <= end - i && {
        var k = 0
        while k < s.length && chars(i + k) == s.charAt(k) do k += 1
        k == s.length
      }

    private def expect(s: String): Unit =
      if startsWith(s) then i += s.length else throw Outside

    /** `<?xml version="1.0" encoding="UTF-8"?>` at the very start, if there, on one line (SAX
      * does not count the line breaks inside a declaration, so one with any goes to it).
      */
    private def declaration(): Unit =
      if startsWith("<?xml") && i + 5 < end && isBlank(chars(i + 5)) then
        i += 5
        blanks()
        expect("version")
        equals()
        if quoted() != "1.0" then throw Outside
        val before = i
        blanks()
        if i > before && startsWith("encoding") then
          i += "encoding".length
          equals()
          if !quoted().equalsIgnoreCase("UTF-8") then throw Outside
          blanks()
        expect("?>")

    /** Spaces and tabs inside the declaration. */
    private def blanks(): Unit =
      while i < end && isBlank(chars(i)) do i += 1

    private def isBlank(c: Char): Boolean = c == ' ' || c == '\t'

    private def equals(): Unit =
      blanks()
      expect("=")
      blanks()

    /** A quoted literal of the declaration (letters, digits, `.`, `-`, `_`), without its quotes. */
    private def quoted(): String =
      if !(at('"') || at('\'')) then throw Outside
      val quote = chars(i)
      val start = i + 1
      i += 1
      while i < end && chars(i) != quote && isNameChar(chars(i)) do i += 1
      if !at(quote) then throw Outside
      i += 1
      String(chars, start, i - 1 - start)

    /** Whitespace, if any, counting its lines. */
    private def space(): Unit =
      while i < end && isSpace(chars(i)) do
        newline(chars(i))
        i += 1

    /** Counts a line for `c` at `i`: a line feed, or a carriage return not followed by one. */
    private def newline(c: Char): Unit =
      if c == '\n' || (c == '\r' && !(i + 1 < end && chars(i + 1) == '\n')) then line += 1

    /** Whitespace and comments, outside the document element or between tags inside it. */
    private def misc(): Unit =
      var more = true
      while more do
        space()
        if startsWith("<!--") then comment() else more = false

    /** A comment, from its `<!--`: no `--` inside, and `-->` at its end. */
    private def comment(): Unit =
      i += 4
      while i < end && !(chars(i) == '-' && i + 1 < end && chars(i + 1) == '-') do
        newline(chars(i))
        i += 1
      if i + 2 < end && chars(i + 2) == '>' then i += 3 else throw Outside

    /** An element from its `<`, handed to the visitor as SAX would: the document element at its
      * start tag, each of its children whole at its end tag.
      */
    private def element(): Unit =
      startTag()
      var open = depth > 0
      while open do
        misc()
        if !at('<') || i + 1 >= end then throw Outside
        val next = chars(i + 1)
        if next == '/' then
          endTag()
          open = depth > 0
        else if isNameStart(next) then startTag()
        else throw Outside

    /** A start tag from its `<`: opens the element, or (`/>`) opens and closes it. */
    private def startTag(): Unit =
      i += 1
      val name  = readName()
      var count = 0
      var more  = true
      var empty = false
      while more do
        val before = i
        space()
        val spaced = i > before
        if at('>') then
          i += 1
          more = false
        else if at('/') && i + 1 < end && chars(i + 1) == '>' then
          i += 2
          more = false
          empty = true
        else if spaced && i < end && isNameStart(chars(i)) then
          val key = readName()
          space()
          expect("=")
          space()
          val value = attributeValue()
          if repeated(key, count) then throw Outside
          if count == keys.length then
            keys = java.util.Arrays.copyOf(keys, 2 * count)
            values = java.util.Arrays.copyOf(values, 2 * count)
          keys(count) = key
          values(count) = value
          count += 1
        else throw Outside
      val attributes = attributeMap(count)
      push(name, attributes, line)
      if depth == 1 then stop(visitor.root(Element(name, attributes, Nil, None, lineSome(line))))
      if empty then pop()

    /** True when `key` is among the tag's first `count` attribute names. */
    private def repeated(key: String, count: Int): Boolean =
      var k = 0
      while k < count && keys(k) != key do k += 1
      k < count

    /** The tag's `count` attributes as the map a chain of `updated` would make (Perf: the small
      * maps made once, not one per attribute).
      */
    private def attributeMap(count: Int): Map[String, String] = count match
      case 0 => Map.empty
      case 1 => Map.Map1(keys(0), values(0))
      case 2 => Map.Map2(keys(0), values(0), keys(1), values(1))
      case 3 => Map.Map3(keys(0), values(0), keys(1), values(1), keys(2), values(2))
      case 4 =>
        Map.Map4(keys(0), values(0), keys(1), values(1), keys(2), values(2), keys(3), values(3))
      case _ =>
        var map = Map.empty[String, String]
        var k   = 0
        while k < count do
          map = map.updated(keys(k), values(k))
          k += 1
        map

    /** `Some(n)`, the same one for the elements that start on one line. */
    private def lineSome(n: Int): Option[Int] =
      if n != lastLine then
        lastLine = n
        lastSome = Some(n)
      lastSome

    /** An end tag from its `<`: it must close the innermost open element. */
    private def endTag(): Unit =
      i += 2
      val start = i
      val name  = names(depth - 1)
      while i < end && isNameChar(chars(i)) do i += 1
      if !sameName(start, name) then throw Outside
      space()
      expect(">")
      pop()

    /** True when `chars(start until i)` is `name`. */
    private def sameName(start: Int, name: String): Boolean =
      i - start == name.length && {
        var k = 0
        while k < name.length && chars(start + k) == name.charAt(k) do k += 1
        k == name.length
      }

    private def readName(): String =
      val start = i
      if !(i < end && isNameStart(chars(i))) then throw Outside
      var hash = chars(i).toInt
      i += 1
      while i < end && isNameChar(chars(i)) do
        hash = 31 * hash + chars(i)
        i += 1
      shared(start, hash)

    /** The text `chars(start until i)` (whose characters hash to `hash`) as a String: the one
      * made before for the same characters when the table still holds it.
      */
    private def shared(start: Int, hash: Int): String =
      val slot = (hash ^ (hash >>> 7)) & (XmlSubset.KnownSlots - 1)
      val seen = known(slot)
      if sameName(start, seen) then seen
      else
        val made = String(chars, start, i - start)
        known(slot) = made
        made

    /** An attribute's value in quotes, normalised as XML does: each whitespace character (a
      * `\r\n` pair as one) a space, references replaced.
      */
    private def attributeValue(): String =
      if !(at('"') || at('\'')) then throw Outside
      val quote = chars(i)
      i += 1
      val start = i
      var hash  = 0
      while i < end && chars(i) != quote && chars(i) > ' ' && chars(i) != '<' && chars(i) != '&'
      do
        hash = 31 * hash + chars(i)
        i += 1
      if at(quote) then
        val value =
          if i - start <= XmlSubset.KnownLength then shared(start, hash)
          else String(chars, start, i - start)
        i += 1
        value
      else
        // Why: the rare value with whitespace or a reference goes through a builder (first the
        // plain part already scanned).
        val text = java.lang.StringBuilder()
        text.append(chars, start, i - start)
        while i < end && chars(i) != quote do
          val c = chars(i)
          if c == '<' then throw Outside
          else if c == '&' then reference(text)
          else if isSpace(c) then
            newline(c)
            if !(c == '\r' && i + 1 < end && chars(i + 1) == '\n') then text.append(' '): Unit
            i += 1
          else
            text.append(c)
            i += 1
        if !at(quote) then throw Outside
        i += 1
        text.toString

    /** A reference from its `&`: one of the five predefined entities or a character reference. */
    private def reference(text: java.lang.StringBuilder): Unit =
      if startsWith("&lt;") then
        text.append('<'); i += 4
      else if startsWith("&gt;") then
        text.append('>'); i += 4
      else if startsWith("&amp;") then
        text.append('&'); i += 5
      else if startsWith("&apos;") then
        text.append('\''); i += 6
      else if startsWith("&quot;") then
        text.append('"'); i += 6
      else if startsWith("&#x") then
        i += 3
        text.appendCodePoint(codePoint(16)): Unit
      else if startsWith("&#") then
        i += 2
        text.appendCodePoint(codePoint(10)): Unit
      else throw Outside

    /** The digits of a character reference up to its `;`: a character XML allows. */
    private def codePoint(radix: Int): Int =
      val start = i
      var value = 0
      while i < end && Character.digit(chars(i), radix) >= 0 && value <= 0x10ffff do
        value = value * radix + Character.digit(chars(i), radix)
        i += 1
      val char =
        value == 0x9 || value == 0xa || value == 0xd || (value >= 0x20 && value <= 0xd7ff) ||
          (value >= 0xe000 && value <= 0xfffd) || (value >= 0x10000 && value <= 0x10ffff)
      if i == start || !at(';') || !char || !plainDigits(start, radix) then throw Outside
      i += 1
      value

    /** True when `chars(start until i)` are ASCII digits of `radix` (Character.digit takes more). */
    private def plainDigits(start: Int, radix: Int): Boolean =
      var k  = start
      var ok = true
      while k < i do
        val c = chars(k)
        ok = ok && ((c >= '0' && c <= '9') ||
          (radix == 16 && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))))
        k += 1
      ok

    private def push(name: String, attributes: Map[String, String], at: Int): Unit =
      if depth == names.length then
        names = java.util.Arrays.copyOf(names, depth * 2)
        attrs = java.util.Arrays.copyOf(attrs, depth * 2)
        lines = java.util.Arrays.copyOf(lines, depth * 2)
        children = java.util.Arrays.copyOf(children, depth * 2)
      names(depth) = name
      attrs(depth) = attributes
      lines(depth) = at
      children(depth) = Nil
      depth += 1

    /** Closes the innermost element: a child of the root goes to the visitor, deeper ones to
      * their parent.
      */
    private def pop(): Unit =
      depth -= 1
      if depth > 0 then
        val element =
          Element(names(depth), attrs(depth), children(depth).reverse, None, lineSome(lines(depth)))
        if depth == 1 then stop(visitor.child(element))
        else children(depth - 1) = element :: children(depth - 1)

    private def stop(result: Either[SceneError, Unit]): Unit =
      result match
        case Left(error) => throw Stopped(error)
        case Right(_)    => ()

  /** Slots of a scan's table of names and values already made (a power of two). */
  private val KnownSlots = 1024

  /** The longest attribute value looked up in that table: numbers and short words. */
  private val KnownLength = 24

  private def isSpace(c: Char): Boolean = c == ' ' || c == '\n' || c == '\r' || c == '\t'

  private def isNameStart(c: Char): Boolean =
    (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':'

  private def isNameChar(c: Char): Boolean =
    isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'
