package tracer.io

import scala.collection.mutable
import tracer.image.{Colour, Texels}
import tracer.scene.*

/** Reads scenes in the XML format of `scene-format.md` into [[tracer.scene.Scene]] values. */
object SceneXml:

  /** Loads the image a `<texture file="…">` names (8-bit or floating-point), or says why it
    * cannot.
    */
  type TextureLoader = String => Either[String, Texels]

  /** Loads the OBJ file a `<mesh file="…">` names, or says why it cannot. */
  type MeshLoader = String => Either[String, ObjMesh]

  /** Parses a scene document. Every error names the element, its line and what is wrong;
    * textures and meshes are read through `sources`, each distinct file once.
    */
  def parse(text: String, sources: SceneSources): Either[SceneError, Scene] =
    read(sources, XmlSubset.read(text, _), XmlDocument.read(text, _))

  /** Parses a scene document whose textures come from `loadTexture` (meshes from files relative
    * to the working directory).
    */
  def parse(text: String, loadTexture: TextureLoader): Either[SceneError, Scene] =
    parse(text, SceneSources(loadTexture, MeshFiles.loader()))

  /** Parses a scene document from its bytes (the encoding comes from its XML declaration). */
  def parse(bytes: Array[Byte], sources: SceneSources): Either[SceneError, Scene] =
    read(sources, XmlSubset.read(bytes, _), XmlDocument.read(bytes, _))

  /** The scene read by `fast` ([[XmlSubset]]) or, when the document is outside its subset, by
    * `sax` ([[XmlDocument]]) from the start with a fresh reader. The fast reader's warnings are
    * held until it has finished, so a document read twice warns once.
    */
  private def read(
      sources: SceneSources,
      fast: XmlVisitor => Option[Either[SceneError, Unit]],
      sax: XmlVisitor => Either[SceneError, Unit]
  ): Either[SceneError, Scene] =
    val held  = mutable.ListBuffer.empty[String]
    val first = SceneReader(sources.copy(warn = held += _))
    fast(first) match
      case Some(result) =>
        held.foreach(sources.warn)
        result.flatMap(_ => first.scene)
      case None =>
        val reader = SceneReader(sources)
        sax(reader).flatMap(_ => reader.scene)

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
  * error in document order. Each concern has a reader of its own: [[LightsReader]] (camera and
  * lights), [[SurfaceReader]] (surfaces and patterns), [[ShapeReader]] (the shapes) and
  * [[CsgReader]] (constructive solid geometry and placement).
  */
private final class SceneReader(sources: SceneSources) extends XmlVisitor:
  import ElementRules.*
  private val textures = mutable.Map.empty[String, Result[Texture]]
  private val surfaces = SurfaceReader(texture)
  private val shapes   = CsgReader(ShapeReader(sources, surfaces), surfaces)

  // Perf: the parts found so far, gathered as each child of <scene> ends; nothing else of the
  // document is kept (docs/performance.md, loading big scenes).
  private var document: Option[Element] = None
  private var found: Option[Camera]     = None
  private var backdrop: Option[Colour]  = None
  private val lights                    = Vector.newBuilder[Light]
  private val objects                   = Vector.newBuilder[SceneObject]

  /** The `<scene>` element: the right name, and no attributes but those that name its schema
    * (`xmlns:xsi` for XML Schema's instance namespace, and `xsi:noNamespaceSchemaLocation`).
    */
  def root(e: Element): Result[Unit] =
    document = Some(e)
    val instance = Vocabulary.SchemaInstance
    if e.name != "scene" then e.fail("the root element must be <scene>")
    else
      (unknownAttribute(e, Vocabulary.SceneAttributes), e.attribute("xmlns:xsi")) match
        case (Some(key), _)                           => e.fail(s"unknown attribute $key")
        case (None, Some(other)) if other != instance =>
          e.fail(s"attribute xmlns:xsi must be $instance, got '$other'")
        case (None, None) if e.attribute(Vocabulary.SchemaLocation).isDefined =>
          e.fail(s"attribute ${Vocabulary.SchemaLocation} needs xmlns:xsi=\"$instance\"")
        case _ => Right(())

  /** A child of `<scene>`, read into the scene's parts. */
  def child(e: Element): Result[Unit] = e.name match
    case "camera" =>
      if found.isDefined then e.fail("<scene> may have only one <camera>")
      else LightsReader.camera(e).map(c => found = Some(c))
    case "background" =>
      if backdrop.isDefined then e.fail("<scene> may have only one <background>")
      // Version 4: a sky may be brighter than 1 (radiance, as a light's colour is an intensity).
      else colour(e, Double.PositiveInfinity).map(c => backdrop = Some(c))
    case "light"                         => LightsReader.light(e).map(lights += _)
    case name if Vocabulary.Shapes(name) => shapes.sceneObjects(e).map(objects ++= _)
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

  /** The texture in `file`, read once however many surfaces name it. */
  private def texture(e: Element, file: String): Result[Texture] =
    textures.getOrElseUpdate(
      file,
      sources
        .texture(file)
        .map(Texture(_, file))
        .left
        .map(why => e.error(s"cannot read texture file '$file': $why"))
    )
