package tracer.io

import tracer.image.Colour
import tracer.math.Vec3

/** The rules every element of the scene format is read by: its allowed attributes and children,
  * numbers, vectors, colours and booleans, each failing with a [[SceneError]] that names the
  * element and its line.
  */
private[io] object ElementRules:
  import Decimal.show

  /** A value read from the document, or the first error found. */
  type Result[A] = Either[SceneError, A]

  /** A range rule for a number: a test and the words that describe it in errors. */
  final case class Range(accepts: Double => Boolean, describe: String)

  /** Numbers ≥ 0. */
  val AtLeastZero: Range = Range(_ >= 0, "at least 0")

  /** Numbers in [0, 1]. */
  val ZeroToOne: Range = Range(v => v >= 0 && v <= 1, "from 0 to 1")

  /** Numbers > 0. */
  val AboveZero: Range = Range(_ > 0, "greater than 0")

  /** Numbers in (0, 1]. */
  val AboveZeroToOne: Range = Range(v => v > 0 && v <= 1, "greater than 0 and at most 1")

  /** Checks `e`'s attributes and child elements against the allowed names and returns the
    * children in document order. Text other than whitespace is an error.
    */
  def contents(e: Element, attributes: Set[String], children: Set[String]): Result[List[Element]] =
    val elements = e.children
    unknownAttribute(e, attributes) match
      case Some(key) => e.fail(s"unknown attribute $key")
      case None      =>
        e.strayText match
          case Some(text) =>
            // The error names the line of the text itself, not of its element.
            Left(
              SceneError(
                text.line.orElse(e.line),
                e.name,
                s"unexpected text '${text.text.take(20)}'"
              )
            )
          case None =>
            elements.find(c => !children(c.name)) match
              case Some(c) => c.fail(s"unknown element inside <${e.name}>")
              case None    => Right(elements)

  /** The first attribute of `e` not among `allowed`, in alphabetical order (so the message does
    * not depend on the parser's attribute order).
    */
  def unknownAttribute(e: Element, allowed: Set[String]): Option[String] =
    e.attributes.keysIterator.filterNot(allowed).minOption

  /** The one child named by any of `names` (aliases), if there is one; two is an error. */
  def atMostOne(owner: Element, children: List[Element], names: String*): Result[Option[Element]] =
    children.filter(c => names.contains(c.name)) match
      case Nil              => Right(None)
      case one :: Nil       => Right(Some(one))
      case _ :: second :: _ =>
        second.fail(s"<${owner.name}> may have only one <${names.mkString("> or <")}>")

  /** `value`, or an error on `owner` saying that `what` is missing. */
  def required[A](owner: Element, value: Option[A], what: => String): Result[A] =
    value.toRight(owner.error(s"missing $what"))

  /** Optional attribute `key` of `e`: a finite decimal number. */
  def number(e: Element, key: String): Result[Option[Double]] =
    traverseOption(e.attribute(key)) { raw =>
      val text  = raw.trim
      val value = Decimal.parse(text)
      if value.isFinite then Right(value)
      else Left(e.error(s"attribute $key must be a finite decimal number, got '$raw'"))
    }

  /** Required attribute `key` of `e`: a finite decimal number. */
  def requiredNumber(e: Element, key: String): Result[Double] =
    number(e, key).flatMap(required(e, _, s"attribute $key"))

  /** Optional attribute `key` of `e`, `default` when absent, else greater than 0. */
  def positive(e: Element, key: String, default: Double): Result[Double] =
    number(e, key).flatMap {
      case None             => Right(default)
      case Some(v) if v > 0 => Right(v)
      case Some(v)          => e.fail(s"attribute $key must be greater than 0, got ${show(v)}")
    }

  /** Required attribute `key` of `e`, within `range`. */
  def requiredIn(e: Element, key: String, range: Range): Result[Double] =
    requiredNumber(e, key).flatMap { v =>
      if range.accepts(v) then Right(v)
      else e.fail(s"attribute $key must be ${range.describe}, got ${show(v)}")
    }

  /** Optional attribute `key` of `e`, `default` when absent, else within `range`. */
  def bounded(e: Element, key: String, default: Double, range: Range): Result[Double] =
    number(e, key).flatMap {
      case None                        => Right(default)
      case Some(v) if range.accepts(v) => Right(v)
      case Some(v) => e.fail(s"attribute $key must be ${range.describe}, got ${show(v)}")
    }

  /** Optional attribute `key` of `e`: `true` or `false`, `default` when absent. */
  def boolean(e: Element, key: String, default: Boolean): Result[Boolean] =
    e.attribute(key) match
      case None          => Right(default)
      case Some("true")  => Right(true)
      case Some("false") => Right(false)
      case Some(other)   => e.fail(s"attribute $key must be true or false, got '$other'")

  /** A vector element: attributes x, y and z.
    *
    * Perf: the usual element (exactly x, y and z, each a finite number; no children, no text) is
    * read directly; anything else goes through [[vectorChecked]], which gives the same vector or
    * the error. Scenes of many triangles read three corners an element, and the checked path's
    * `Either` chain ran cold for most of them (`ElementRulesProperties` holds the two equal;
    * docs/performance.md, round 8).
    */
  def vector(e: Element): Result[Vec3] =
    val a = e.attributes
    if a.size == 3 && e.children.isEmpty && e.strayText.isEmpty then
      val x = direct(a, "x")
      val y = direct(a, "y")
      val z = direct(a, "z")
      if x.isFinite && y.isFinite && z.isFinite then Right(Vec3(x, y, z)) else vectorChecked(e)
    else vectorChecked(e)

  /** Attribute `key` of `a` read as [[number]] reads it, NaN when absent or not a number. */
  private def direct(a: Map[String, String], key: String): Double =
    a.get(key) match
      case Some(raw) => Decimal.parse(raw.trim)
      case None      => Double.NaN

  /** [[vector]] by the general rules, each failing with its own error. */
  def vectorChecked(e: Element): Result[Vec3] =
    for
      _ <- contents(e, Vocabulary.VectorAttributes, Vocabulary.NoNames)
      x <- requiredNumber(e, "x")
      y <- requiredNumber(e, "y")
      z <- requiredNumber(e, "z")
    yield Vec3(x, y, z)

  /** The one child vector `name` of `owner`, which must be there. */
  def requiredVector(owner: Element, children: List[Element], name: String): Result[Vec3] =
    atMostOne(owner, children, name).flatMap(required(owner, _, s"<$name>")).flatMap(vector)

  /** The one child vector `name` of `owner`, `default` when absent. */
  def optionalVector(
      owner: Element,
      children: List[Element],
      default: Vec3,
      name: String
  ): Result[Vec3] =
    atMostOne(owner, children, name).flatMap(_.fold(Right(default))(vector))

  /** The one child vector `name` of `owner`, `default` when absent, never the zero vector. */
  def optionalNonZero(
      owner: Element,
      children: List[Element],
      default: Vec3,
      name: String
  ): Result[Vec3] =
    atMostOne(owner, children, name).flatMap {
      case None    => Right(default)
      case Some(e) =>
        vector(e).flatMap(v =>
          if v.normalised.isDefined then Right(v) else e.fail("must not be the zero vector")
        )
    }

  /** A colour element with channels from 0 to `max`.
    *
    * Perf: as [[vector]], the usual element (exactly r, g and b, each within range) is read
    * directly, anything else through [[colourChecked]].
    */
  def colour(e: Element, max: Double): Result[Colour] =
    val a = e.attributes
    if a.size == 3 && e.children.isEmpty && e.strayText.isEmpty then
      val r = direct(a, "r")
      val g = direct(a, "g")
      val b = direct(a, "b")
      if inRange(r, max) && inRange(g, max) && inRange(b, max) then Right(Colour(r, g, b))
      else colourChecked(e, max)
    else colourChecked(e, max)

  /** A channel that [[colourChecked]] accepts: finite (so not NaN, which an absent or malformed
    * attribute gives), from 0 to `max`.
    */
  private def inRange(c: Double, max: Double): Boolean = c.isFinite && c >= 0 && c <= max

  /** [[colour]] by the general rules, each failing with its own error. */
  def colourChecked(e: Element, max: Double): Result[Colour] =
    for
      _        <- contents(e, Vocabulary.ColourAttributes, Vocabulary.NoNames)
      channels <- traverse(List("r", "g", "b")) { key =>
        requiredNumber(e, key).flatMap { c =>
          if c >= 0 && c <= max then Right(c)
          else
            val range =
              if java.lang.Double.isInfinite(max) then "at least 0" else s"from 0 to ${show(max)}"
            e.fail(s"attribute $key must be $range, got ${show(c)}")
        }
      }
    yield Colour(channels(0), channels(1), channels(2))

  /** `f` applied to each item in order, stopping at the first error. */
  def traverse[A, B](items: List[A])(f: A => Result[B]): Result[List[B]] =
    items
      .foldLeft[Result[List[B]]](Right(Nil))((done, item) =>
        done.flatMap(bs => f(item).map(_ :: bs))
      )
      .map(_.reverse)

  /** `f` applied to the item if there is one. */
  def traverseOption[A, B](item: Option[A])(f: A => Result[B]): Result[Option[B]] =
    item.fold[Result[Option[B]]](Right(None))(a => f(a).map(Some(_)))

  /** Right(()) when `ok`, else an error on `e` with `message`. */
  def check(ok: Boolean, e: Element, message: => String): Result[Unit] =
    if ok then Right(()) else e.fail(message)
