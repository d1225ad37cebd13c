package tracer.io

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import scala.xml.{Elem, XML}
import tracer.testkit.{SceneDocuments, SceneSchema}

/** `docs/scene.xsd`, the scene format as an XML Schema, agrees with the reader: every scene the
  * project holds (the gallery, the test resources, the examples of the docs) is valid, every scene
  * of a corpus of wrong ones is refused by both, and where only the reader can refuse (a rule
  * XML Schema 1.0 cannot state) the test says so.
  */
class SceneSchemaSuite extends munit.FunSuite with SceneDocuments:

  private def files(dir: String): List[Path] =
    Files.list(Path.of(dir)).iterator.asScala.filter(_.toString.endsWith(".xml")).toList.sorted

  private def assertValid(xml: String, what: String)(using munit.Location): Unit =
    SceneSchema.validate(xml).left.foreach(why => fail(s"$what is not valid: $why"))

  private def assertInvalid(xml: String, what: String)(using munit.Location): Unit =
    assert(SceneSchema.validate(xml).isLeft, s"the schema accepts $what")

  private val face = ObjReader.parse(
    java.io.BufferedReader(java.io.StringReader("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")),
    "face.obj"
  )

  private val resources = List(
    "scenes",
    "src/test/resources/scenes",
    "src/test/resources/povray",
    "src/test/resources/samples"
  )

  test("the schema is itself a valid XML Schema 1.0 that the JDK reads"):
    assertValid(withCamera(""), "a scene with a camera alone")

  test("every gallery scene and every scene file of the tests is valid, and the reader reads it"):
    val all = resources.flatMap(files)
    assert(all.length >= 15, all.toString)
    all.foreach { path =>
      val xml = Files.readString(path)
      assertValid(xml, path.toString)
      // Files from the scene's directory; a texture or mesh that a suite writes only while it
      // runs is the white texel or a one-face mesh.
      val sources = SceneSources.files(path.toAbsolutePath.getParent)
      val read    = SceneXml.parse(
        Files.readAllBytes(path),
        SceneSources(
          file => sources.texture(file).orElse(Right(texel)),
          file => sources.mesh(file).orElse(face)
        )
      )
      assert(read.isRight, s"the reader refuses $path: $read")
    }

  test("the gallery's scenes name the schema, by a path that leads to it from scenes/"):
    files("scenes").foreach { path =>
      val root = XML.loadFile(path.toFile)
      val at   = root.attributes.asAttrMap.get("xsi:noNamespaceSchemaLocation")
      assertEquals(at, Some("../docs/scene.xsd"), path.toString)
      assert(Files.isRegularFile(path.getParent.resolve(at.getOrElse(""))), path.toString)
    }

  /** The ```xml blocks of a page: whole scenes as they are, fragments after a camera. */
  private def examples(page: String): List[String] =
    val text = Files.readString(Path.of(page))
    "(?s)```xml\n(.*?)```".r
      .findAllMatchIn(text)
      .map(_.group(1))
      .map(block =>
        if block.startsWith("<?xml") || block.startsWith("<scene") then block
        else withCamera(block)
      )
      .toList

  private val pages =
    "README.md" :: Files
      .list(Path.of("docs"))
      .iterator
      .asScala
      .map(_.toString)
      .toList
      .sorted
      .filter(_.endsWith(".md"))

  test("the scene format's pages have XML examples to check"):
    for page <- List("docs/scene-format.md", "docs/guide.md") do
      assert(examples(page).length >= 4, page)

  for page <- pages do
    test(s"every XML example of $page is valid"):
      examples(page).zipWithIndex.foreach((xml, i) => assertValid(xml, s"$page's example ${i + 1}"))

  private val sphere  = """<sphere radius="1"><centre x="0" y="0" z="0"/></sphere>"""
  private val corners =
    """<corner x="0" y="0" z="0"/><corner x="1" y="0" z="0"/><corner x="0" y="1" z="0"/>"""

  /** Scenes wrong in a way XML Schema can say: (what, the scene after a camera, what the reader's
    * message holds).
    */
  private val wrong = List(
    ("an unknown element", "<cube/>", "unknown element inside <scene>"),
    (
      "an unknown attribute",
      """<sphere radius="1" colour="red"><centre x="0" y="0" z="0"/></sphere>""",
      "unknown attribute colour"
    ),
    (
      "an element under the wrong parent",
      """<centre x="0" y="0" z="0"/>""",
      "unknown element inside <scene>"
    ),
    (
      "a vector under a light's area's wrong parent",
      """<light><location x="0" y="0" z="0"/><a x="1" y="0" z="0"/></light>""",
      "unknown element inside <light>"
    ),
    (
      "a missing required attribute",
      """<sphere><centre x="0" y="0" z="0"/></sphere>""",
      "missing attribute radius"
    ),
    ("a missing required element", """<sphere radius="1"/>""", "missing <centre>"),
    (
      "a missing coordinate",
      """<sphere radius="1"><centre x="0" y="0"/></sphere>""",
      "missing attribute z"
    ),
    (
      "a second camera",
      """<camera><location x="0" y="0" z="1"/><lookat x="0" y="0" z="0"/></camera>""",
      "only one <camera>"
    ),
    (
      "a second background",
      """<background r="0" g="0" b="0"/><background r="0" g="0" b="0"/>""",
      "only one <background>"
    ),
    (
      "a centre and a center",
      """<sphere radius="1"><centre x="0" y="0" z="0"/><center x="0" y="0" z="0"/></sphere>""",
      "only one <centre> or <center>"
    ),
    (
      "a light with a colour and a color",
      """<light><location x="0" y="0" z="0"/><colour r="1" g="1" b="1"/><color r="1" g="1" b="1"/></light>""",
      "only one <colour> or <color>"
    ),
    (
      "a second rotate on a CSG element",
      s"""<union>$sphere<rotate x="0" y="1" z="0"/><rotate x="0" y="2" z="0"/></union>""",
      "only one <rotate>"
    ),
    (
      "a second surface on a CSG element",
      s"""<union><surface/>$sphere<surface/></union>""",
      "only one <surface>"
    ),
    (
      "a second surface on a triangle",
      s"""<triangle><surface/>$corners<surface/></triangle>""",
      "only one <surface>"
    ),
    ("a CSG element without a shape", "<union><surface/></union>", "at least one shape"),
    (
      "a triangle in a difference",
      s"""<difference>$sphere<triangle>$corners</triangle></difference>""",
      "allowed in a <union> only"
    ),
    (
      "a texture on a box",
      """<box><corner1 x="0" y="0" z="0"/><corner2 x="1" y="1" z="1"/><surface><texture file="t.ppm"/></surface></box>""",
      "textures are allowed on spheres and triangles only"
    ),
    (
      "ior on a child of a CSG element",
      """<union><sphere radius="1"><centre x="0" y="0" z="0"/><surface ior="1.5"/></sphere></union>""",
      "attribute ior is not allowed on a child of <union>"
    ),
    (
      "ior on a plane",
      """<plane distance="0"><normal x="0" y="1" z="0"/><surface ior="1.5"/></plane>""",
      "attribute ior is allowed on spheres, closed solids and CSG elements only"
    ),
    (
      "a placement on a sphere at the top",
      """<sphere radius="1"><centre x="0" y="0" z="0"/><rotate x="0" y="0" z="0"/></sphere>""",
      "unknown element inside <sphere>"
    ),
    ("text between elements", "hello", "unexpected text 'hello'"),
    (
      "a number that is not a number",
      """<sphere radius="one"><centre x="0" y="0" z="0"/></sphere>""",
      "finite decimal"
    ),
    ("NaN", """<sphere radius="NaN"><centre x="0" y="0" z="0"/></sphere>""", "finite decimal"),
    ("INF", """<sphere radius="INF"><centre x="0" y="0" z="0"/></sphere>""", "finite decimal"),
    (
      "a number too big to be finite",
      """<sphere radius="1e400"><centre x="0" y="0" z="0"/></sphere>""",
      "finite decimal"
    ),
    (
      "an empty number",
      """<sphere radius=""><centre x="0" y="0" z="0"/></sphere>""",
      "finite decimal"
    ),
    (
      "a negative radius",
      """<sphere radius="-1"><centre x="0" y="0" z="0"/></sphere>""",
      "greater than 0"
    ),
    (
      "a zero torus tube",
      """<torus major="1" minor="0"/>""",
      "greater than 0"
    ),
    (
      "a negative cone radius",
      """<cone base-radius="-1" cap-radius="1"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cone>""",
      "at least 0"
    ),
    (
      "a reflection above 1",
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface reflection="1.5"/></sphere>""",
      "from 0 to 1"
    ),
    (
      "a surface colour above 1",
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface><colour r="2" g="0" b="0"/></surface></sphere>""",
      "from 0 to 1"
    ),
    (
      "a negative light colour",
      """<light><location x="0" y="0" z="0"/><colour r="-1" g="0" b="0"/></light>""",
      "at least 0"
    ),
    (
      "a roughness of 0",
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface roughness="0"/></sphere>""",
      "greater than 0 and at most 1"
    ),
    (
      "65 area-light samples",
      """<light><location x="0" y="0" z="0"/><area samples-a="65" samples-b="1"><a x="1" y="0" z="0"/><b x="0" y="0" z="1"/></area></light>""",
      "whole number from 1 to 64"
    ),
    (
      "a bad boolean",
      """<cylinder radius="1" open="yes"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cylinder>""",
      "must be true or false, got 'yes'"
    ),
    (
      "a boolean written as 1",
      """<cylinder radius="1" open="1"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cylinder>""",
      "must be true or false, got '1'"
    ),
    (
      "a bad smooth",
      """<mesh file="m.obj" smooth="yes"/>""",
      "must be true, false or auto, got 'yes'"
    ),
    ("a mesh without a file", """<mesh file=""/>""", "missing attribute file"),
    (
      "a checker with one colour",
      s"""<plane distance="0"><normal x="0" y="1" z="0"/><surface><checker><colour r="1" g="1" b="1"/></checker></surface></plane>""",
      "exactly two <colour>"
    )
  )

  for (what, body, words) <- wrong do
    test(s"the schema and the reader both refuse $what"):
      val xml = withCamera(body)
      assertInvalid(xml, what)
      parse(xml) match
        case Right(s) => fail(s"the reader accepts $what: $s")
        case Left(e)  => assert(e.describe.contains(words), s"'${e.describe}' lacks '$words'")

  test(
    "the schema and the reader both refuse a root other than <scene>, and a scene without a camera"
  ):
    List("<scenery/>", "<scene/>", """<scene><background r="0" g="0" b="0"/></scene>""").foreach {
      xml =>
        assertInvalid(xml, xml)
        assert(parse(xml).isLeft, xml)
    }

  /** Scenes only the reader refuses, each for a rule XML Schema 1.0 cannot state: (what, the scene
    * after a camera, why the schema cannot say it).
    */
  private val readerOnly = List(
    (
      "a pole not at right angles to the equator",
      """<sphere radius="1"><centre x="0" y="0" z="0"/><pole x="0" y="1" z="0"/><equator x="0" y="1" z="1"/></sphere>""",
      "a relation between two elements' values"
    ),
    (
      "collinear corners",
      """<triangle><corner x="0" y="0" z="0"/><corner x="1" y="1" z="1"/><corner x="2" y="2" z="2"/></triangle>""",
      "a relation between three elements' values"
    ),
    (
      "two corners instead of three",
      """<triangle><corner x="0" y="0" z="0"/><corner x="1" y="0" z="0"/></triangle>""",
      "three corners or origin, a and b, in any order, is a choice between two interleavings"
    ),
    (
      "a point and a distance on a plane",
      """<plane distance="1"><normal x="0" y="1" z="0"/><point x="0" y="0" z="0"/></plane>""",
      "a choice between an element and an attribute"
    ),
    (
      "a colour and a checker",
      """<plane distance="0"><normal x="0" y="1" z="0"/><surface><colour r="1" g="1" b="1"/><checker><colour r="1" g="1" b="1"/><colour r="0" g="0" b="0"/></checker></surface></plane>""",
      "exclusion between children of an xs:all"
    ),
    (
      "a box with equal corners in one coordinate",
      """<box><corner1 x="0" y="0" z="0"/><corner2 x="1" y="0" z="1"/></box>""",
      "a relation between two elements' values"
    ),
    (
      "a cone with both radii 0",
      """<cone base-radius="0" cap-radius="0"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cone>""",
      "a relation between two attributes"
    ),
    (
      "2.5 area-light samples",
      """<light><location x="0" y="0" z="0"/><area samples-a="2.5" samples-b="1"><a x="1" y="0" z="0"/><b x="0" y="0" z="1"/></area></light>""",
      "the reader allows any spelling of a whole number (5, 5.0, 5e0): no pattern says them all"
    ),
    (
      "ior on an open cylinder",
      """<cylinder radius="1" open="true"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/><surface ior="1.5"/></cylinder>""",
      "an attribute allowed by another attribute's value"
    ),
    (
      "a zero normal",
      """<plane distance="0"><normal x="0" y="0" z="0"/></plane>""",
      "a relation between three attributes"
    )
  )

  private val blind =
    """<scene><camera><location x="0" y="0" z="0"/><lookat x="0" y="0" z="0"/></camera></scene>"""

  for (what, xml, why) <- readerOnly.map((w, b, y) => (w, withCamera(b), y)) :+ (
      "a camera looking at its own location",
      blind,
      "a relation between two elements' values"
    )
  do
    test(s"only the reader refuses $what (beyond XML Schema 1.0: $why)"):
      assertValid(xml, what)
      assert(parse(xml).isLeft, s"the reader accepts $what")

  /** Version 4's additions (`<emission>`, a light's fade, a background above 1): the schema's side
    * (the reader's is in SceneXmlVersion4Suite).
    */
  private val version4 = List(
    """<background r="4" g="2.5" b="1"/>""",
    s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface><emission r="5" g="4" b="0"/></surface></sphere>""",
    """<box><corner1 x="0" y="0" z="0"/><corner2 x="1" y="1" z="1"/><surface diffuse="0"><emission r="1" g="1" b="1"/><colour r="1" g="1" b="1"/></surface></box>""",
    """<light fade-distance="2" fade-power="2"><location x="0" y="0" z="0"/></light>"""
  )

  test("the schema accepts version 4's emission, fade and bright background"):
    version4.foreach(body => assertValid(withCamera(body), body))

  test("the schema refuses version 4's values out of range and a second emission"):
    List(
      """<background r="-1" g="0" b="0"/>""",
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface><emission r="-1" g="0" b="0"/></surface></sphere>""",
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface><emission r="1" g="0" b="0"/><emission r="1" g="0" b="0"/></surface></sphere>""",
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface><emission r="1" g="0"/></surface></sphere>""",
      """<light fade-distance="0" fade-power="2"><location x="0" y="0" z="0"/></light>""",
      """<light fade-distance="2" fade-power="-1"><location x="0" y="0" z="0"/></light>""",
      """<light fade-distance="INF" fade-power="1"><location x="0" y="0" z="0"/></light>"""
    ).foreach(body => assertInvalid(withCamera(body), body))

  // The reader refuses fade-distance because fade-power is missing; a reader that took it would
  // fail here.
  test(
    "a light's fade-distance without fade-power: only the reader can refuse it (both or neither)"
  ):
    assertValid(
      withCamera("""<light fade-distance="2"><location x="0" y="0" z="0"/></light>"""),
      "fade-distance alone"
    )
    assert(
      parse(withCamera("""<light fade-distance="2"><location x="0" y="0" z="0"/></light>""")).isLeft
    )

  private val named =
    """<scene xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="scene.xsd">"""

  test("a scene may name its schema, and the reader accepts exactly xmlns:xsi and the location"):
    val xml = withCamera("").replace("<scene>", named)
    assertValid(xml, "a scene naming its schema")
    assert(parse(xml).isRight, parse(xml).toString)
    val declared = withCamera("")
      .replace("<scene>", """<scene xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">""")
    assert(parse(declared).isRight, parse(declared).toString)

  test("the reader refuses other xsi attributes, a wrong namespace and an undeclared prefix"):
    def refused(root: String, words: String) =
      parse(withCamera("").replace("<scene>", root)) match
        case Right(_) => fail(s"accepted $root")
        case Left(e)  => assert(e.describe.contains(words), e.describe)
    refused(
      named.replace("noNamespaceSchemaLocation", "schemaLocation"),
      "unknown attribute xsi:schemaLocation"
    )
    refused(
      """<scene xmlns:xsi="urn:other" xsi:noNamespaceSchemaLocation="scene.xsd">""",
      "xmlns:xsi must be http://www.w3.org/2001/XMLSchema-instance"
    )
    refused("""<scene xsi:noNamespaceSchemaLocation="scene.xsd">""", "needs xmlns:xsi")
    refused("""<scene xmlns="urn:scene">""", "unknown attribute xmlns")
    val onSphere = withCamera(
      """<sphere radius="1" xsi:noNamespaceSchemaLocation="x"><centre x="0" y="0" z="0"/></sphere>"""
    )
    assert(parse(onSphere).isLeft, "the location belongs on <scene> only")

  test("the schema names exactly the elements and attributes the reader knows"):
    val xsd                    = XML.loadFile(SceneSchema.file.toFile)
    def declared(kind: String) = xsd.descendant.collect {
      case e: Elem if e.label == kind && e.attributes.asAttrMap.contains("name") =>
        e.attributes.asAttrMap("name")
    }.toSet
    val schemaElements   = declared("element")
    val schemaAttributes = declared("attribute")
    val v                = Vocabulary
    val readerElements   = Set("scene", "camera", "background", "light") ++ v.Shapes ++
      v.CameraChildren ++ v.LightChildren ++ v.AreaChildren ++ v.MeshChildren ++
      v.SphereChildren ++ v.PlaneChildren ++ v.TriangleChildren ++ v.BoxChildren ++
      v.AxisChildren ++ v.PlacementChildren ++ v.SurfaceChildren ++ v.CheckerChildren
    val readerAttributes = v.CameraAttributes ++ v.AreaAttributes ++ v.MeshAttributes ++
      v.SphereAttributes ++ v.PlaneAttributes ++ v.CylinderAttributes ++ v.ConeAttributes ++
      v.TorusAttributes ++ v.SurfaceAttributes ++ v.CheckerAttributes ++ v.TextureAttributes ++
      v.VectorAttributes ++ v.ColourAttributes ++ v.LightAttributes + "scale"
    assertEquals(readerElements -- schemaElements, Set.empty[String])
    assertEquals(readerAttributes -- schemaAttributes, Set.empty[String])
    assertEquals(schemaElements -- readerElements, Set.empty[String])
    assertEquals(schemaAttributes -- readerAttributes, Set.empty[String])
