package tracer.io

import tracer.geometry.{Box, Cone, Cylinder, Mesh, Placed, Plane, Shape, Sphere, Torus, Triangle}
import tracer.math.{Placement, Vec3}
import tracer.scene.Surface

/** Where an element stands: inside which CSG elements, and what it inherits from them.
  *
  * @param placements the placements of the enclosing CSG elements, innermost first
  * @param surface    the surface of the nearest enclosing CSG element that has one
  * @param parent     the enclosing CSG element, or `None` at the top of the scene
  */
private[io] final case class Enclosure(
    placements: List[Placement],
    surface: Option[Surface],
    parent: Option[Element]
):
  /** The placements of the pattern space of a surface on an element placed by `own`. */
  def space(own: Placement): List[Placement] = (own :: placements).filterNot(_.isIdentity)

/** The enclosure of an element at the top of the scene. */
private[io] object Enclosure:
  /** No enclosing element: world space, no inherited surface. */
  val Top: Enclosure = Enclosure(Nil, None, None)

/** An element read as geometry.
  *
  * @param shape    its shape, placed
  * @param surfaces the surface of each of its leaves (one for a primitive)
  * @param whole    the surface of the whole: a primitive's own; a CSG element's own (holding the
  *   object's `ior`) or the default
  */
private[io] final case class Piece(shape: Shape, surfaces: Vector[Surface], whole: Surface)

/** How a mesh's faces are shaded: flat, with the file's normals, or with computed ones too. */
private[io] enum Smooth:
  /** Every face flat (`smooth="false"`, the default). */
  case Off

  /** Faces whose corners all have `vn` normals interpolate them (`smooth="true"`). */
  case FromFile

  /** As `FromFile`, and other faces get angle-weighted vertex normals (`smooth="auto"`). */
  case Auto

/** Reads the shapes of every version (`sphere`, `plane`, `triangle`, `mesh`, `box`, `cylinder`,
  * `cone`, `torus`) with their surfaces and, for version 3 solids, their placement.
  */
private[io] final class ShapeReader(sources: SceneSources, surfaces: SurfaceReader):
  import ElementRules.*

  /** A `<sphere>`.
    *
    * Perf: the usual element (at the top of the scene, a radius alone, no text, a `<centre>`
    * followed by at most a `<pole>`, an `<equator>` and a `<surface>`, in that order, each value
    * as the rules want it) is read without the general rules' chain of checks; anything else goes
    * through [[sphereChecked]], which gives the same piece or the same error. The 500 spheres'
    * scene spent a quarter of a second reading them, cold (`ElementRulesProperties`;
    * docs/performance.md, round 21).
    */
  def sphere(e: Element, at: Enclosure): Result[Piece] =
    e.children match
      case c :: rest
          if at.parent.isEmpty && e.strayText.isEmpty && e.attributes.size == 1 &&
            (c.name == "centre" || c.name == "center") =>
        val (pole, afterPole)       = ShapeReader.next(rest, "pole")
        val (equator, afterEquator) = ShapeReader.next(afterPole, "equator")
        val (_, end)                = ShapeReader.next(afterEquator, "surface")
        val radius = e.attributes.get("radius").fold(Double.NaN)(r => Decimal.parse(r.trim))
        val sphere =
          for
            centre  <- vector(c).toOption
            pole    <- pole.fold(Some(Vec3.UnitY))(nonZero)
            equator <- equator.fold(Some(Vec3.UnitZ))(nonZero)
            if end.isEmpty && radius > 0 && radius.isFinite &&
              Math.abs(pole.normalisedOr(Vec3.UnitY).dot(equator.normalisedOr(Vec3.UnitZ))) <=
              Sphere.RightAngleTolerance
          yield Sphere(centre, radius, pole, equator)
        sphere.fold(sphereChecked(e, at))(
          finish(e, e.children, at, _, texturable = true, solid = true)
        )
      case _ => sphereChecked(e, at)

  /** A vector element's value when it is one and not the zero vector. */
  private def nonZero(e: Element): Option[Vec3] =
    vector(e).toOption.filter(_.normalised.isDefined)

  /** [[sphere]] by the general rules, each failing with its own error. */
  def sphereChecked(e: Element, at: Enclosure): Result[Piece] =
    for
      children <- contents(
        e,
        placeableAttributes(at, Vocabulary.SphereAttributes),
        placeableChildren(at, Vocabulary.SphereChildren)
      )
      radius <- requiredNumber(e, "radius")
      _      <- check(
        radius > 0,
        e,
        s"attribute radius must be greater than 0, got ${Decimal.show(radius)}"
      )
      centre <- atMostOne(e, children, "centre", "center")
        .flatMap(required(e, _, "<centre>"))
        .flatMap(vector)
      pole    <- optionalNonZero(e, children, Vec3.UnitY, "pole")
      equator <- optionalNonZero(e, children, Vec3.UnitZ, "equator")
      cosine = Math.abs(pole.normalisedOr(Vec3.UnitY).dot(equator.normalisedOr(Vec3.UnitZ)))
      _ <- check(
        cosine <= Sphere.RightAngleTolerance,
        e,
        s"<pole> $pole and <equator> $equator must be at right angles (|cos| = $cosine)"
      )
      piece <- finish(
        e,
        children,
        at,
        Sphere(centre, radius, pole, equator),
        texturable = true,
        solid = true
      )
    yield piece

  /** A `<plane>`. */
  def plane(e: Element, at: Enclosure): Result[Piece] =
    for
      children <- contents(
        e,
        placeableAttributes(at, Vocabulary.PlaneAttributes),
        placeableChildren(at, Vocabulary.PlaneChildren)
      )
      normal   <- requiredVector(e, children, "normal")
      _        <- check(normal.normalised.isDefined, e, "<normal> must not be the zero vector")
      point    <- atMostOne(e, children, "point")
      distance <- number(e, "distance")
      plane    <- (point, distance) match
        case (Some(p), None)    => vector(p).map(Plane.through(_, normal))
        case (None, Some(d))    => Right(Plane.at(normal, d))
        case (Some(_), Some(_)) => e.fail("give either a <point> or a distance attribute, not both")
        case (None, None)       => e.fail("needs a <point> or a distance attribute")
      piece <- finish(e, children, at, plane, texturable = false, solid = false)
    yield piece

  /** A `<triangle>`, by three corners or by an origin and two legs.
    *
    * Perf: the usual element (no attributes or text, three `<corner>`s first, then at most a
    * `<surface>`) reads its corners straight away; anything else goes through
    * [[triangleChecked]], which gives the same piece or the same error (the usual element passes
    * its every check). The 5 MB `<triangle>` scene reads 20,000 of them, mostly cold
    * (`ElementRulesProperties`; docs/performance.md, round 8).
    */
  def triangle(e: Element, at: Enclosure): Result[Piece] =
    e.children match
      case c0 :: c1 :: c2 :: rest
          if e.attributes.isEmpty && e.strayText.isEmpty && isCorner(c0) && isCorner(c1) &&
            isCorner(c2) && (rest.isEmpty || (rest.tail.isEmpty && rest.head.name == "surface")) =>
        for
          t0 <- vector(c0)
          t1 <- vector(c1)
          t2 <- vector(c2)
          _  <- check(Triangle.isProper(t0, t1, t2), e, s"the corners $t0, $t1, $t2 are collinear")
          piece <- finish(e, e.children, at, Triangle(t0, t1, t2), texturable = true, solid = false)
        yield piece
      case _ => triangleChecked(e, at)

  private def isCorner(c: Element): Boolean = c.name == "corner"

  /** [[triangle]] by the general rules, each failing with its own error. */
  def triangleChecked(e: Element, at: Enclosure): Result[Piece] =
    for
      children     <- contents(e, Vocabulary.NoNames, Vocabulary.TriangleChildren)
      corners      <- traverse(children.filter(_.name == "corner"))(vector)
      legs         <- traverse(List("origin", "a", "b"))(name => atMostOne(e, children, name))
      (t0, t1, t2) <- (corners, legs) match
        case (List(t0, t1, t2), List(None, None, None)) => Right((t0, t1, t2))
        case (Nil, List(Some(o), Some(a), Some(b)))     =>
          for o <- vector(o); a <- vector(a); b <- vector(b) yield (o, o + a, o + b)
        case (Nil, _) => e.fail("needs three <corner> elements, or <origin>, <a> and <b>")
        case (_, List(None, None, None)) =>
          e.fail(s"needs exactly three <corner> elements, got ${corners.length}")
        case _ => e.fail("give three <corner> elements or <origin>, <a> and <b>, not both")
      _     <- check(Triangle.isProper(t0, t1, t2), e, s"the corners $t0, $t1, $t2 are collinear")
      piece <- finish(e, children, at, Triangle(t0, t1, t2), texturable = true, solid = false)
    yield piece

  /** A `<mesh>`: the OBJ file's triangles scaled, rotated (x, then y, then z) and translated,
    * with the mesh's surface, as one [[Mesh]] (`None` when no face is left: every one collinear).
    * With `smooth="true"`, faces whose corners all have normals shade with them interpolated;
    * with `smooth="auto"`, faces without them get computed ones ([[VertexNormals]]).
    */
  def mesh(e: Element, at: Enclosure): Result[(Option[Mesh], Surface)] =
    for
      children <- contents(e, Vocabulary.MeshAttributes, Vocabulary.MeshChildren)
      file     <- e.attribute("file").filter(_.nonEmpty).toRight(e.error("missing attribute file"))
      scale    <- positive(e, "scale", 1.0)
      smooth   <- e.attribute("smooth") match
        case None | Some("false") => Right(Smooth.Off)
        case Some("true")         => Right(Smooth.FromFile)
        case Some("auto")         => Right(Smooth.Auto)
        case Some(other) => e.fail(s"attribute smooth must be true, false or auto, got '$other'")
      rotate    <- optionalVector(e, children, Vec3.Zero, "rotate")
      translate <- optionalVector(e, children, Vec3.Zero, "translate")
      own       <- surfaces.optional(
        e,
        children,
        SurfacePlace(
          texturable = true,
          iorRefusal(e, at, solid = false),
          at.space(Placement.Identity)
        )
      )
      obj <- sources.mesh(file).left.map(why => e.error(s"cannot read mesh file: $why"))
      _   <- check(obj.faceCount > 0, e, s"mesh file $file has no faces")
    yield
      val mesh      = MeshBuilder(obj, MeshTransform(scale, rotate, translate), smooth).build()
      val collinear = obj.faceCount - mesh.fold(0)(_.faceCount)
      if obj.skippedKinds.nonEmpty then
        sources.warn(s"$file: skipped unsupported statements: ${obj.skippedKinds.mkString(", ")}")
      if collinear > 0 then
        val faces = if collinear == 1 then "face" else "faces"
        sources.warn(s"$file: skipped $collinear $faces whose corners are collinear")
      (mesh, own.orElse(at.surface).getOrElse(Surface()))

  /** A `<box>` (version 3). */
  def box(e: Element, at: Enclosure): Result[Piece] =
    for
      children <- contents(e, Set("scale"), Vocabulary.BoxChildren ++ Vocabulary.PlacementChildren)
      corner1  <- requiredVector(e, children, "corner1")
      corner2  <- requiredVector(e, children, "corner2")
      _        <- check(
        corner1.x != corner2.x && corner1.y != corner2.y && corner1.z != corner2.z,
        e,
        s"<corner1> $corner1 and <corner2> $corner2 must differ in every coordinate"
      )
      piece <- finish(e, children, at, Box(corner1, corner2), texturable = false, solid = true)
    yield piece

  /** A `<cylinder radius open>` (version 3). */
  def cylinder(e: Element, at: Enclosure): Result[Piece] =
    for
      children <- contents(e, Vocabulary.CylinderAttributes + "scale", axisChildren)
      radius   <- requiredNumber(e, "radius")
      _        <- check(
        radius > 0,
        e,
        s"attribute radius must be greater than 0, got ${Decimal.show(radius)}"
      )
      open  <- boolean(e, "open", default = false)
      ends  <- axis(e, children)
      piece <- finish(
        e,
        children,
        at,
        Cylinder(ends._1, ends._2, radius, open),
        texturable = false,
        solid = !open
      )
    yield piece

  /** A `<cone base-radius cap-radius open>` (version 3). */
  def cone(e: Element, at: Enclosure): Result[Piece] =
    for
      children   <- contents(e, Vocabulary.ConeAttributes + "scale", axisChildren)
      baseRadius <- requiredIn(e, "base-radius", AtLeastZero)
      capRadius  <- requiredIn(e, "cap-radius", AtLeastZero)
      _          <- check(
        baseRadius + capRadius > 0,
        e,
        "attributes base-radius and cap-radius must not both be 0"
      )
      open  <- boolean(e, "open", default = false)
      ends  <- axis(e, children)
      piece <- finish(
        e,
        children,
        at,
        Cone(ends._1, baseRadius, ends._2, capRadius, open),
        texturable = false,
        solid = !open
      )
    yield piece

  /** A `<torus major minor>` (version 3). */
  def torus(e: Element, at: Enclosure): Result[Piece] =
    for
      children <- contents(
        e,
        Vocabulary.TorusAttributes + "scale",
        Set("surface") ++ Vocabulary.PlacementChildren
      )
      major <- requiredIn(e, "major", ElementRules.Range(_ > 0, "greater than 0"))
      minor <- requiredIn(e, "minor", ElementRules.Range(_ > 0, "greater than 0"))
      piece <- finish(e, children, at, Torus(major, minor), texturable = false, solid = true)
    yield piece

  /** A version 3 element's placement: `scale`, then `<rotate>`, then `<translate>`. */
  def placement(e: Element, children: List[Element]): Result[Placement] =
    // Perf: with none of the three given, the identity as it is, rather than a new one (three
    // matrix products) for every element; the same value and the same transform.
    if e.attributes.get("scale").isEmpty && !children.exists(c =>
        c.name == "rotate" || c.name == "translate"
      )
    then Right(Placement.Identity)
    else
      for
        scale     <- positive(e, "scale", 1.0)
        rotate    <- optionalVector(e, children, Vec3.Zero, "rotate")
        translate <- optionalVector(e, children, Vec3.Zero, "translate")
      yield Placement(scale, rotate, translate)

  /** Why `ior` is refused on element `e` at `at`, or `None` where it is allowed: on spheres,
    * closed solids and CSG elements at the top of the scene.
    */
  def iorRefusal(e: Element, at: Enclosure, solid: Boolean): Option[String] =
    at.parent match
      case Some(p) =>
        Some(s"attribute ior is not allowed on a child of <${p.name}>: give it to the CSG element")
      case None if solid                                => None
      case None if e.attribute("open").contains("true") =>
        Some(s"attribute ior is not allowed on an open <${e.name}>")
      case None =>
        Some(
          s"attribute ior is allowed on spheres, closed solids and CSG elements only, not <${e.name}>"
        )

  /** The shape placed by `p` (left alone by the identity). */
  def placed(shape: Shape, p: Placement): Shape = if p.isIdentity then shape else Placed(shape, p)

  private val axisChildren = Vocabulary.AxisChildren ++ Vocabulary.PlacementChildren

  /** A cylinder's or cone's `<base>` and `<cap>`, which must differ. */
  private def axis(e: Element, children: List[Element]): Result[(Vec3, Vec3)] =
    for
      base <- requiredVector(e, children, "base")
      cap  <- requiredVector(e, children, "cap")
      _    <- check(base != cap, e, s"<base> and <cap> must differ, both are $base")
    yield (base, cap)

  /** A version 1 shape's attributes, with `scale` inside a CSG element (where it may be placed). */
  private def placeableAttributes(at: Enclosure, names: Set[String]): Set[String] =
    if at.parent.isEmpty then names else names + "scale"

  /** A version 1 shape's children, with `rotate` and `translate` inside a CSG element. */
  private def placeableChildren(at: Enclosure, names: Set[String]): Set[String] =
    if at.parent.isEmpty then names else names ++ Vocabulary.PlacementChildren

  /** The piece for `shape` read from `e`: placed, with its own surface or the inherited one. */
  private def finish(
      e: Element,
      children: List[Element],
      at: Enclosure,
      shape: Shape,
      texturable: Boolean,
      solid: Boolean
  ): Result[Piece] =
    for
      own     <- placement(e, children)
      surface <- surfaces.optional(
        e,
        children,
        SurfacePlace(texturable, iorRefusal(e, at, solid), at.space(own))
      )
    yield
      val shown = surface.orElse(at.surface).getOrElse(Surface())
      Piece(placed(shape, own), Vector(shown), shown)

/** What [[ShapeReader]]'s direct paths share. */
private[io] object ShapeReader:
  /** The first of `children` and the rest when it is named `name`; else nothing, and them all. */
  def next(children: List[Element], name: String): (Option[Element], List[Element]) =
    children match
      case c :: rest if c.name == name => (Some(c), rest)
      case _                           => (None, children)
