package tracer.io

import tracer.image.Colour
import tracer.math.Placement
import tracer.scene.{Pigment, Surface, Texture}

/** Where a `<surface>` stands, which decides what it may hold.
  *
  * @param texturable true where a `<texture>` may be mapped (spheres, triangles, meshes)
  * @param iorRefusal why `ior` is not allowed here, or `None` where it is
  * @param space      the placements that take the pattern's space to the world, innermost first
  *   (see [[tracer.scene.Pigment.Checker]])
  */
private[io] final case class SurfacePlace(
    texturable: Boolean,
    iorRefusal: Option[String],
    space: List[Placement]
)

/** Reads `<surface>` with its colour, texture or checker pattern. Textures are loaded through
  * `loadTexture`, which reports a file it cannot read as an error on the `<texture>` element.
  */
private[io] final class SurfaceReader(
    loadTexture: (Element, String) => ElementRules.Result[Texture]
):
  import ElementRules.*

  // Perf: the last surface read without error, with its element and place. Generated scenes
  // give every object the same <surface>, and reading it again cold was a fifth of loading the
  // 5 MB <triangle> scene (scripts/bench.sh --loading; docs/performance.md, round 7).
  private var last: Option[(Element, SurfacePlace, Surface)] = None

  /** The one `<surface>` among `siblings` (the children of `owner`), if there is one. */
  def optional(
      owner: Element,
      siblings: List[Element],
      place: SurfacePlace
  ): Result[Option[Surface]] =
    atMostOne(owner, siblings, "surface").flatMap(traverseOption(_)(remembered(owner, _, place)))

  /** [[surface]], or the last surface read when `e` says the same at the same place: a
    * surface's value depends on its element's names, attributes and children and on its place
    * only (its owner and lines appear in errors alone, which are never remembered).
    */
  private def remembered(owner: Element, e: Element, place: SurfacePlace): Result[Surface] =
    last match
      case Some((element, at, surface)) if at == place && sameContent(element, e) => Right(surface)
      case _                                                                      =>
        val read = surface(owner, e, place)
        read.foreach(s => last = Some((e, place, s)))
        read

  /** True when `a` and `b` have the same names, attributes and children, whatever their lines. */
  private def sameContent(a: Element, b: Element): Boolean =
    a.name == b.name && a.attributes == b.attributes && a.strayText.map(_.text) ==
      b.strayText.map(_.text) && a.children.corresponds(b.children)(sameContent)

  /** A `<surface>`: the usual one read directly ([[usual]]), anything else by the general rules
    * ([[surfaceChecked]]), which give the same surface or the error.
    */
  def surface(owner: Element, e: Element, place: SurfacePlace): Result[Surface] =
    usual(e, place).fold(surfaceChecked(owner, e, place))(Right(_))

  /** [[surfaceChecked]]'s surface for the usual `<surface>`: no text, numbers within their
    * ranges (`ior` only where it is allowed), and no child but a `<colour>`; `None` for anything
    * else.
    *
    * Perf: the general rules' chain of eight attribute checks and four child searches ran cold
    * for every surface of a scene whose surfaces differ (the 500 spheres'; docs/performance.md,
    * round 21; `ElementRulesProperties` holds the two equal).
    */
  private def usual(e: Element, place: SurfacePlace): Option[Surface] =
    val a = e.attributes
    // Why: how many of the attributes below were given, to find any other by the count.
    var present = 0

    def read(key: String, default: Double, range: Range): Double =
      a.get(key) match
        case None      => default
        case Some(raw) =>
          present += 1
          val v = Decimal.parse(raw.trim)
          if v.isFinite && range.accepts(v) then v else Double.NaN
    val diffuse    = read("diffuse", 1.0, AtLeastZero)
    val reflection = read("reflection", 0.0, ZeroToOne)
    val phong      = read("phong", 0.0, AtLeastZero)
    val phongSize  = read("phong-size", Surface.DefaultPhongSize, AboveZero)
    val specular   = read("specular", 0.0, AtLeastZero)
    val roughness  = read("roughness", Surface.DefaultRoughness, AboveZeroToOne)
    val transmit   = read("transmit", 0.0, ZeroToOne)
    val ior        = read("ior", 1.0, AboveZero)
    val pigment    = e.children match
      case Nil                                                 => Some(Colour.White)
      case c :: Nil if c.name == "colour" || c.name == "color" => ElementRules.colour(c, 1).toOption
      case _                                                   => None
    val numbers = List(diffuse, reflection, phong, phongSize, specular, roughness, transmit, ior)
    val inRange = !numbers.exists(java.lang.Double.isNaN)
    val plain   = e.strayText.isEmpty && present == a.size && inRange &&
      (place.iorRefusal.isEmpty || !a.contains("ior"))
    for colour <- pigment if plain
    yield Surface(
      diffuse,
      reflection,
      Pigment.Solid(colour),
      phong,
      phongSize,
      specular,
      roughness,
      transmit,
      ior,
      Colour.Black
    )

  /** [[surface]] by the general rules, each failing with its own error. */
  def surfaceChecked(owner: Element, e: Element, place: SurfacePlace): Result[Surface] =
    for
      children   <- contents(e, Vocabulary.SurfaceAttributes, Vocabulary.SurfaceChildren)
      diffuse    <- bounded(e, "diffuse", 1.0, AtLeastZero)
      reflection <- bounded(e, "reflection", 0.0, ZeroToOne)
      phong      <- bounded(e, "phong", 0.0, AtLeastZero)
      phongSize  <- positive(e, "phong-size", Surface.DefaultPhongSize)
      specular   <- bounded(e, "specular", 0.0, AtLeastZero)
      roughness  <- bounded(e, "roughness", Surface.DefaultRoughness, AboveZeroToOne)
      transmit   <- bounded(e, "transmit", 0.0, ZeroToOne)
      ior        <- positive(e, "ior", 1.0)
      _        <- place.iorRefusal.filter(_ => e.attribute("ior").isDefined).fold(Right(()))(e.fail)
      colour   <- atMostOne(e, children, "colour", "color")
      texture  <- atMostOne(e, children, "texture")
      checker  <- atMostOne(e, children, "checker")
      glow     <- atMostOne(e, children, "emission")
      emission <- glow.fold(Right(Colour.Black))(ElementRules.colour(_, Double.PositiveInfinity))
      _        <- (colour, texture, checker) match
        case (Some(_), _, Some(c)) => c.fail("give a <colour> or a <checker>, not both")
        case (_, Some(_), Some(c)) => c.fail("give a <texture> or a <checker>, not both")
        case _                     => Right(())
      pigment <- (texture, checker) match
        case (Some(t), _) => this.texture(t, owner, place).map(Pigment.Textured(_))
        case (_, Some(c)) => this.checker(c, place)
        case (None, None) =>
          colour.fold(Right(Colour.White))(ElementRules.colour(_, 1)).map(Pigment.Solid(_))
    yield Surface(
      diffuse,
      reflection,
      pigment,
      phong,
      phongSize,
      specular,
      roughness,
      transmit,
      ior,
      emission
    )

  private def texture(e: Element, owner: Element, place: SurfacePlace): Result[Texture] =
    for
      _ <- contents(e, Vocabulary.TextureAttributes, Vocabulary.NoNames)
      _ <- check(
        place.texturable,
        e,
        s"textures are allowed on spheres and triangles only, not <${owner.name}>"
      )
      file    <- e.attribute("file").filter(_.nonEmpty).toRight(e.error("missing attribute file"))
      texture <- loadTexture(e, file)
    yield texture

  /** A `<checker size>` with its two colours (scene-format v3, The checker pattern). */
  private def checker(e: Element, place: SurfacePlace): Result[Pigment] =
    for
      children <- contents(e, Vocabulary.CheckerAttributes, Vocabulary.CheckerChildren)
      size     <- positive(e, "size", 1.0)
      colours  <- traverse(children)(ElementRules.colour(_, 1))
      pigment  <- colours match
        case List(first, second) => Right(Pigment.Checker(first, second, size, place.space))
        case _ => e.fail(s"needs exactly two <colour> elements, got ${colours.length}")
    yield pigment
