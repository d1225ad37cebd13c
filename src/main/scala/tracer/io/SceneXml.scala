package tracer.io

import scala.collection.mutable
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3
import tracer.scene.*

/** Reads scenes in the XML format of `scene-format.md` into [[tracer.scene.Scene]] values. */
object SceneXml:

  /** Loads the image a `<texture file="…">` names, or says why it cannot. */
  type TextureLoader = String => Either[String, Bitmap]

  /** Loads the OBJ file a `<mesh file="…">` names, or says why it cannot. */
  type MeshLoader = String => Either[String, ObjMesh]

  /** Parses a scene document. Every error names the element, its line and what is wrong;
    * textures and meshes are read through `sources`, each distinct file once.
    */
  def parse(text: String, sources: SceneSources): Either[SceneError, Scene] =
    val reader = SceneReader(sources)
    XmlDocument.read(text, reader).flatMap(_ => reader.scene)

  /** Parses a scene document whose textures come from `loadTexture` (meshes from files relative
    * to the working directory).
    */
  def parse(text: String, loadTexture: TextureLoader): Either[SceneError, Scene] =
    parse(text, SceneSources(loadTexture, MeshFiles.loader()))

  /** Parses a scene document from its bytes (the encoding comes from its XML declaration). */
  def parse(bytes: Array[Byte], sources: SceneSources): Either[SceneError, Scene] =
    val reader = SceneReader(sources)
    XmlDocument.read(bytes, reader).flatMap(_ => reader.scene)

  /** Reads the scene file `path`, its textures and meshes resolved against `base` (by default
    * the working directory, as the command line does).
    */
  def load(
      path: java.nio.file.Path,
      base: java.nio.file.Path = java.nio.file.Path.of("").toAbsolutePath
  ): Either[String, Scene] =
    val bytes =
      try Right(java.nio.file.Files.readAllBytes(path))
      catch case e: java.io.IOException => Left(s"cannot read $path: $e")
    bytes.flatMap(b => parse(b, SceneSources.files(base)).left.map(e => s"$path: ${e.describe}"))

/** Builds the scene from the document's elements as they stream past, stopping at the first
  * error in document order.
  */
private final class SceneReader(sources: SceneSources) extends XmlVisitor:
  import Decimal.show
  private type Result[A] = Either[SceneError, A]
  private val textures = mutable.Map.empty[String, Result[Texture]]

  // Perf: the parts found so far, gathered as each child of <scene> ends; nothing else of the
  // document is kept (docs/performance.md, loading big scenes).
  private var document: Option[Element] = None
  private var found: Option[Camera]     = None
  private var backdrop: Option[Colour]  = None
  private val lights                    = Vector.newBuilder[Light]
  private val objects                   = Vector.newBuilder[SceneObject]

  /** The `<scene>` element: the right name, no attributes. */
  def root(e: Element): Result[Unit] =
    document = Some(e)
    if e.name != "scene" then e.fail("the root element must be <scene>")
    else
      unknownAttribute(e, Vocabulary.NoNames).fold(Right(()))(key =>
        e.fail(s"unknown attribute $key")
      )

  /** A child of `<scene>`, read into the scene's parts. */
  def child(e: Element): Result[Unit] = e.name match
    case "camera" =>
      if found.isDefined then e.fail("<scene> may have only one <camera>")
      else camera(e).map(c => found = Some(c))
    case "background" =>
      if backdrop.isDefined then e.fail("<scene> may have only one <background>")
      else colour(e, 1).map(c => backdrop = Some(c))
    case "light"                         => light(e).map(lights += _)
    case name if Vocabulary.Shapes(name) => sceneObjects(e).map(objects ++= _)
    case _                               => e.fail("unknown element inside <scene>")

  /** Text between the children of `<scene>`: an error at its own line. */
  def rootText(text: StrayText): Result[Unit] =
    Left(SceneError(text.line, "scene", s"unexpected text '${text.text.take(20)}'"))

  /** The end of the document: there must have been a camera. */
  def end(): Result[Unit] = scene.map(_ => ())

  /** The scene the document described, once it has been read whole. */
  def scene: Result[Scene] =
    (document, found) match
      case (Some(_), Some(camera)) =>
        Right(Scene(camera, backdrop.getOrElse(Colour.Black), lights.result(), objects.result()))
      case (Some(root), None) => root.fail("missing <camera>")
      case (None, _)          => Left(SceneError(None, "", "the document has no root element"))

  private def camera(e: Element): Result[Camera] =
    for
      children <- contents(e, Vocabulary.CameraAttributes, Vocabulary.CameraChildren)
      zoom     <- positive(e, "zoom", Camera.DefaultZoom)
      width    <- positive(e, "width", Camera.DefaultWidth)
      height   <- positive(e, "height", Camera.DefaultHeight)
      location <- requiredVector(e, children, "location")
      lookAt   <- requiredVector(e, children, "lookat")
      up       <- optionalVector(e, children, Vec3.UnitY, "up")
      _        <-
        if location != lookAt then Right(())
        else e.fail(s"<lookat> must differ from <location>, both are $location")
      _ <-
        if up.cross(lookAt - location).normalised.isDefined then Right(())
        else e.fail(s"<up> $up is parallel to the viewing direction ${lookAt - location}")
    yield Camera(location, lookAt, up, zoom, width, height)

  private def light(e: Element): Result[Light] =
    for
      children <- contents(e, Vocabulary.NoNames, Vocabulary.LightChildren)
      location <- requiredVector(e, children, "location")
      colour   <- atMostOne(e, children, "colour", "color").flatMap(
        _.fold(Right(Colour.White))(lightColour)
      )
      area <- atMostOne(e, children, "area").flatMap(traverseOption(_)(areaLight))
    yield Light(location, colour, area)

  /** An `<area samples-a samples-b>` with its axes `<a>` and `<b>` (scene-format-v2). */
  private def areaLight(e: Element): Result[AreaLight] =
    for
      children <- contents(e, Vocabulary.AreaAttributes, Vocabulary.AreaChildren)
      samplesA <- samples(e, "samples-a")
      samplesB <- samples(e, "samples-b")
      a        <- requiredVector(e, children, "a")
      b        <- requiredVector(e, children, "b")
      _        <-
        if a.cross(b).normalised.isDefined then Right(())
        else e.fail(s"the axes <a> $a and <b> $b must be non-zero and not parallel")
    yield AreaLight(a, b, samplesA, samplesB)

  /** A required whole number of sub-lights, 1 to [[AreaLight.MaxSamples]]. */
  private def samples(e: Element, key: String): Result[Int] =
    requiredNumber(e, key).flatMap { v =>
      if v.isWhole && v >= 1 && v <= AreaLight.MaxSamples then Right(v.toInt)
      else
        e.fail(
          s"attribute $key must be a whole number from 1 to ${AreaLight.MaxSamples}, got ${show(v)}"
        )
    }

  private def sceneObjects(e: Element): Result[List[SceneObject]] = e.name match
    case "sphere" => sphere(e).map(List(_))
    case "plane"  => plane(e).map(List(_))
    case "mesh"   => mesh(e)
    case _        => triangle(e).map(List(_))

  /** A `<mesh>`: the OBJ file's triangles scaled, rotated (x, then y, then z) and translated;
    * with `smooth="true"`, faces whose corners all have normals shade with them interpolated.
    */
  private def mesh(e: Element): Result[List[SceneObject]] =
    for
      children  <- contents(e, Vocabulary.MeshAttributes, Vocabulary.MeshChildren)
      file      <- e.attribute("file").filter(_.nonEmpty).toRight(e.error("missing attribute file"))
      scale     <- positive(e, "scale", 1.0)
      smooth    <- boolean(e, "smooth", default = false)
      rotate    <- optionalVector(e, children, Vec3.Zero, "rotate")
      translate <- optionalVector(e, children, Vec3.Zero, "translate")
      surface   <- surface(e, children, texturable = true, refractive = false)
      obj       <- sources.mesh(file).left.map(why => e.error(s"cannot read mesh file: $why"))
      _ <- if obj.triangles.nonEmpty then Right(()) else e.fail(s"mesh file $file has no faces")
    yield
      val place = MeshTransform(scale, rotate, translate)
      // Normals turn with the mesh; a face with a zero normal at a corner stays flat.
      def normals(t: ObjTriangle): Option[(Vec3, Vec3, Vec3)] =
        for
          (n0, n1, n2) <- t.normals if smooth
          a            <- place.turn(n0).normalised
          b            <- place.turn(n1).normalised
          c            <- place.turn(n2).normalised
        yield (a, b, c)
      val placed              = obj.triangles.map(t => (place(t.a), place(t.b), place(t.c), t))
      val (proper, collinear) = placed.partition((a, b, c, _) => Triangle.isProper(a, b, c))
      if obj.skippedKinds.nonEmpty then
        sources.warn(s"$file: skipped unsupported statements: ${obj.skippedKinds.mkString(", ")}")
      if collinear.nonEmpty then
        val faces = if collinear.length == 1 then "face" else "faces"
        sources.warn(s"$file: skipped ${collinear.length} $faces whose corners are collinear")
      proper.map((a, b, c, t) => SceneObject(Triangle(a, b, c, t.uv, normals(t)), surface)).toList

  private def sphere(e: Element): Result[SceneObject] =
    for
      children <- contents(e, Vocabulary.SphereAttributes, Vocabulary.SphereChildren)
      radius   <- requiredNumber(e, "radius")
      _        <-
        if radius > 0 then Right(())
        else e.fail(s"attribute radius must be greater than 0, got ${show(radius)}")
      centre <- atMostOne(e, children, "centre", "center")
        .flatMap(required(e, _, "<centre>"))
        .flatMap(vector)
      pole    <- optionalNonZero(e, children, Vec3.UnitY, "pole")
      equator <- optionalNonZero(e, children, Vec3.UnitZ, "equator")
      _       <-
        val cosine = Math.abs(pole.normalised.get.dot(equator.normalised.get))
        if cosine <= Sphere.RightAngleTolerance then Right(())
        else
          e.fail(s"<pole> $pole and <equator> $equator must be at right angles (|cos| = $cosine)")
      surface <- surface(e, children, texturable = true, refractive = true)
    yield SceneObject(Sphere(centre, radius, pole, equator), surface)

  private def plane(e: Element): Result[SceneObject] =
    for
      children <- contents(e, Vocabulary.PlaneAttributes, Vocabulary.PlaneChildren)
      normal   <- requiredVector(e, children, "normal")
      _        <-
        if normal.normalised.isDefined then Right(())
        else e.fail("<normal> must not be the zero vector")
      point    <- atMostOne(e, children, "point")
      distance <- number(e, "distance")
      plane    <- (point, distance) match
        case (Some(p), None)    => vector(p).map(Plane.through(_, normal))
        case (None, Some(d))    => Right(Plane.at(normal, d))
        case (Some(_), Some(_)) => e.fail("give either a <point> or a distance attribute, not both")
        case (None, None)       => e.fail("needs a <point> or a distance attribute")
      surface <- surface(e, children, texturable = false, refractive = false)
    yield SceneObject(plane, surface)

  private def triangle(e: Element): Result[SceneObject] =
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
      _ <-
        if Triangle.isProper(t0, t1, t2) then Right(())
        else e.fail(s"the corners $t0, $t1, $t2 are collinear")
      surface <- surface(e, children, texturable = true, refractive = false)
    yield SceneObject(Triangle(t0, t1, t2), surface)

  private def surface(
      owner: Element,
      siblings: List[Element],
      texturable: Boolean,
      refractive: Boolean
  ): Result[Surface] =
    atMostOne(owner, siblings, "surface").flatMap {
      case None    => Right(Surface())
      case Some(e) =>
        for
          children   <- contents(e, Vocabulary.SurfaceAttributes, Vocabulary.SurfaceChildren)
          diffuse    <- bounded(e, "diffuse", 1.0, atLeastZero)
          reflection <- bounded(e, "reflection", 0.0, zeroToOne)
          phong      <- bounded(e, "phong", 0.0, atLeastZero)
          phongSize  <- positive(e, "phong-size", Surface.DefaultPhongSize)
          specular   <- bounded(e, "specular", 0.0, atLeastZero)
          roughness  <- bounded(e, "roughness", Surface.DefaultRoughness, aboveZeroToOne)
          transmit   <- bounded(e, "transmit", 0.0, zeroToOne)
          ior        <- positive(e, "ior", 1.0)
          _          <-
            if refractive || e.attribute("ior").isEmpty then Right(())
            else e.fail(s"attribute ior is allowed on spheres only, not <${owner.name}>")
          colour <- atMostOne(e, children, "colour", "color").flatMap(
            _.fold(Right(Colour.White))(colour(_, 1))
          )
          texture <- atMostOne(e, children, "texture").flatMap(
            traverseOption(_)(texture(_, owner, texturable))
          )
        yield Surface(
          diffuse,
          reflection,
          texture.fold(Pigment.Solid(colour))(Pigment.Textured(_)),
          phong,
          phongSize,
          specular,
          roughness,
          transmit,
          ior
        )
    }

  /** A range rule for a number: a test and the words that describe it in errors. */
  private final case class Range(accepts: Double => Boolean, describe: String)
  private val atLeastZero    = Range(_ >= 0, "at least 0")
  private val zeroToOne      = Range(v => v >= 0 && v <= 1, "from 0 to 1")
  private val aboveZeroToOne = Range(v => v > 0 && v <= 1, "greater than 0 and at most 1")

  /** Optional attribute `key` of `e`, `default` when absent, else within `range`. */
  private def bounded(e: Element, key: String, default: Double, range: Range): Result[Double] =
    number(e, key).flatMap {
      case None                        => Right(default)
      case Some(v) if range.accepts(v) => Right(v)
      case Some(v) => e.fail(s"attribute $key must be ${range.describe}, got ${show(v)}")
    }

  /** Optional attribute `key` of `e`: `true` or `false`, `default` when absent. */
  private def boolean(e: Element, key: String, default: Boolean): Result[Boolean] =
    e.attribute(key) match
      case None          => Right(default)
      case Some("true")  => Right(true)
      case Some("false") => Right(false)
      case Some(other)   => e.fail(s"attribute $key must be true or false, got '$other'")

  private def texture(e: Element, owner: Element, texturable: Boolean): Result[Texture] =
    for
      _ <- contents(e, Vocabulary.TextureAttributes, Vocabulary.NoNames)
      _ <-
        if texturable then Right(())
        else e.fail(s"textures are allowed on spheres and triangles only, not <${owner.name}>")
      file    <- e.attribute("file").filter(_.nonEmpty).toRight(e.error("missing attribute file"))
      texture <- textures.getOrElseUpdate(
        file,
        sources
          .texture(file)
          .map(Texture(_, file))
          .left
          .map(why => e.error(s"cannot read texture file '$file': $why"))
      )
    yield texture

  private def vector(e: Element): Result[Vec3] =
    for
      _ <- contents(e, Vocabulary.VectorAttributes, Vocabulary.NoNames)
      x <- requiredNumber(e, "x")
      y <- requiredNumber(e, "y")
      z <- requiredNumber(e, "z")
    yield Vec3(x, y, z)

  /** A colour element with channels from 0 to `max`. */
  private def colour(e: Element, max: Double): Result[Colour] =
    for
      _        <- contents(e, Vocabulary.ColourAttributes, Vocabulary.NoNames)
      channels <- traverse(List("r", "g", "b")) { key =>
        requiredNumber(e, key).flatMap { c =>
          if c >= 0 && c <= max then Right(c)
          else
            val range = if max.isInfinite then "at least 0" else s"from 0 to ${show(max)}"
            e.fail(s"attribute $key must be $range, got ${show(c)}")
        }
      }
    yield Colour(channels(0), channels(1), channels(2))

  /** A light's colour: channels at least 0, with no upper limit. */
  private def lightColour(e: Element): Result[Colour] = colour(e, Double.PositiveInfinity)

  private def requiredVector(owner: Element, children: List[Element], name: String): Result[Vec3] =
    atMostOne(owner, children, name).flatMap(required(owner, _, s"<$name>")).flatMap(vector)

  private def optionalVector(
      owner: Element,
      children: List[Element],
      default: Vec3,
      name: String
  ): Result[Vec3] =
    atMostOne(owner, children, name).flatMap(_.fold(Right(default))(vector))

  private def optionalNonZero(
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

  /** Checks `e`'s attributes and child elements against the allowed names and returns the
    * children in document order. Text other than whitespace is an error.
    */
  private def contents(
      e: Element,
      attributes: Set[String],
      children: Set[String]
  ): Result[List[Element]] =
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

  /** The one child named by any of `names` (aliases), if there is one; two is an error. */
  private def atMostOne(
      owner: Element,
      children: List[Element],
      names: String*
  ): Result[Option[Element]] =
    children.filter(c => names.contains(c.name)) match
      case Nil              => Right(None)
      case one :: Nil       => Right(Some(one))
      case _ :: second :: _ =>
        second.fail(s"<${owner.name}> may have only one <${names.mkString("> or <")}>")

  private def required[A](owner: Element, value: Option[A], what: => String): Result[A] =
    value.toRight(owner.error(s"missing $what"))

  private def number(e: Element, key: String): Result[Option[Double]] =
    traverseOption(e.attribute(key)) { raw =>
      val text  = raw.trim
      val value = Decimal.parse(text)
      if value.isFinite then Right(value)
      else Left(e.error(s"attribute $key must be a finite decimal number, got '$raw'"))
    }

  private def requiredNumber(e: Element, key: String): Result[Double] =
    number(e, key).flatMap(required(e, _, s"attribute $key"))

  private def positive(e: Element, key: String, default: Double): Result[Double] =
    number(e, key).flatMap {
      case None             => Right(default)
      case Some(v) if v > 0 => Right(v)
      case Some(v)          => e.fail(s"attribute $key must be greater than 0, got ${show(v)}")
    }

  /** The first attribute of `e` not among `allowed`, in alphabetical order (so the message does
    * not depend on the parser's attribute order).
    */
  private def unknownAttribute(e: Element, allowed: Set[String]): Option[String] =
    e.attributes.keysIterator.filterNot(allowed).minOption

  /** `f` applied to each item in order, stopping at the first error. */
  private def traverse[A, B](items: List[A])(f: A => Result[B]): Result[List[B]] =
    items
      .foldLeft[Result[List[B]]](Right(Nil))((done, item) =>
        done.flatMap(bs => f(item).map(_ :: bs))
      )
      .map(_.reverse)

  private def traverseOption[A, B](item: Option[A])(f: A => Result[B]): Result[Option[B]] =
    item.fold[Result[Option[B]]](Right(None))(a => f(a).map(Some(_)))

/** The names each element of the scene format allows: its attributes and its child elements. */
private object Vocabulary:
  /** No names at all: for an element without attributes, or without children. */
  val NoNames: Set[String] = Set()

  /** The elements that are shapes. */
  val Shapes: Set[String] = Set("sphere", "plane", "triangle", "mesh")

  /** What `<scene>` may hold. */
  val SceneChildren: Set[String] = Set("camera", "background", "light") ++ Shapes

  /** `<camera>`'s attributes. */
  val CameraAttributes: Set[String] = Set("zoom", "width", "height")

  /** `<camera>`'s children. */
  val CameraChildren: Set[String] = Set("location", "lookat", "up")

  /** `<light>`'s children. */
  val LightChildren: Set[String] = Set("location", "colour", "color", "area")

  /** `<area>`'s attributes. */
  val AreaAttributes: Set[String] = Set("samples-a", "samples-b")

  /** `<area>`'s children. */
  val AreaChildren: Set[String] = Set("a", "b")

  /** `<mesh>`'s attributes. */
  val MeshAttributes: Set[String] = Set("file", "scale", "smooth")

  /** `<mesh>`'s children. */
  val MeshChildren: Set[String] = Set("rotate", "translate", "surface")

  /** `<sphere>`'s attributes. */
  val SphereAttributes: Set[String] = Set("radius")

  /** `<sphere>`'s children. */
  val SphereChildren: Set[String] = Set("centre", "center", "pole", "equator", "surface")

  /** `<plane>`'s attributes. */
  val PlaneAttributes: Set[String] = Set("distance")

  /** `<plane>`'s children. */
  val PlaneChildren: Set[String] = Set("normal", "point", "surface")

  /** `<triangle>`'s children. */
  val TriangleChildren: Set[String] = Set("corner", "origin", "a", "b", "surface")

  /** `<surface>`'s attributes, versions 1 and 2. */
  val SurfaceAttributes: Set[String] =
    Set("diffuse", "reflection", "phong", "phong-size", "specular", "roughness", "transmit", "ior")

  /** `<surface>`'s children. */
  val SurfaceChildren: Set[String] = Set("colour", "color", "texture")

  /** `<texture>`'s attributes. */
  val TextureAttributes: Set[String] = Set("file")

  /** A vector element's attributes. */
  val VectorAttributes: Set[String] = Set("x", "y", "z")

  /** A colour element's attributes. */
  val ColourAttributes: Set[String] = Set("r", "g", "b")
