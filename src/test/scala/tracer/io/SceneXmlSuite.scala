package tracer.io

import java.nio.file.Files
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.Scenes.firstShape

/** The XML scene format of scene-format.md: what it accepts and how it reports what it does not. */
class SceneXmlSuite extends munit.FunSuite:

  private val checker =
    Bitmap.tabulate(2, 2)((x, y) => if (x + y) % 2 == 0 then Colour.White else Colour.Black)
  private val loaded                           = collection.mutable.ListBuffer.empty[String]
  private val textures: SceneXml.TextureLoader = name =>
    loaded += name
    if name.startsWith("missing") then Left("no such file") else Right(checker)

  override def beforeEach(context: BeforeEach): Unit = loaded.clear()

  private def parse(xml: String)        = SceneXml.parse(xml, textures)
  private def scene(xml: String): Scene = parse(xml).fold(e => fail(e.describe), identity)
  private val camera                    =
    """<camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>"""
  private def withCamera(body: String) = s"<scene>$camera$body</scene>"

  private def assertError(xml: String, line: Option[Int], element: String, expected: String*)(using
      munit.Location
  ): Unit =
    parse(xml) match
      case Right(s) => fail(s"parsed $s")
      case Left(e)  =>
        assertEquals(e.line, line, e.describe)
        assertEquals(e.element, element, e.describe)
        expected.foreach(x =>
          assert(e.describe.contains(x), s"'${e.describe}' does not mention '$x'")
        )

  test("the example document of scene-format.md parses completely"):
    val xml =
      new String(getClass.getResourceAsStream("/scenes/format-example.xml").readAllBytes(), "UTF-8")
    val s = scene(xml)
    assertEquals(s.camera, Camera(Vec3(0, 1, -6), Vec3.Zero, Vec3.UnitY, 1.0, 1.0, 0.75))
    assertEquals(s.background, Colour(0, 0, 0.1))
    assertEquals(s.lights, List(Light(Vec3(-10, 10, -10), Colour.White)))
    assertEquals(s.objects.length, 6)
    assertEquals(
      s.objects(0),
      SceneObject(Sphere(Vec3.Zero, 1), Surface(0.8, 0.2, Pigment.Solid(Colour(1, 0.2, 0.2))))
    )
    assertEquals(s.objects(1).shape, Sphere(Vec3(1.5, -0.5, 0), 0.5, Vec3.UnitY, Vec3.UnitZ))
    assertEquals(
      s.objects(1).surface.pigment,
      Pigment.Textured(Texture(checker, "textures/earth.ppm"))
    )
    assertEquals(
      s.objects(2),
      SceneObject(Plane(Vec3.UnitY, -1), Surface(1, 0.5, Pigment.Solid(Colour.grey(0.5))))
    )
    assertEquals(s.objects(3), SceneObject(Plane(-Vec3.UnitZ, 20)))
    assertEquals(s.objects(4).shape, Triangle(Vec3(-2, -1, 1), Vec3(-1, -1, 1), Vec3(-2, 0, 1)))
    assertEquals(s.objects(5).shape, Triangle(Vec3(1, -1, 2), Vec3(2, -1, 2), Vec3(1, 0, 2)))
    assertEquals(loaded.toList, List("textures/earth.ppm", "textures/checker.ppm"))

  test(
    "defaults: camera zoom 1, width 1, height 0.75, up +y; black background; white lights and surfaces"
  ):
    val s = scene(
      withCamera(
        """<light><location x="1" y="2" z="3"/></light><sphere radius="1"><centre x="0" y="0" z="0"/></sphere>"""
      )
    )
    assertEquals(s.camera, Camera(Vec3(0, 0, -5), Vec3.Zero))
    assertEquals(s.background, Colour.Black)
    assertEquals(s.lights, List(Light(Vec3(1, 2, 3), Colour.White)))
    assertEquals(s.objects.head.surface, Surface(1.0, 0.0, Pigment.Solid(Colour.White)))

  test("an empty scene with only a camera is valid"):
    assertEquals(scene(withCamera("")).objects, Nil)

  test("colour and color, centre and center are the same"):
    val british = scene(
      withCamera(
        """<sphere radius="1"><centre x="1" y="0" z="0"/><surface><colour r="1" g="0" b="0"/></surface></sphere>"""
      )
    )
    val american = scene(
      withCamera(
        """<sphere radius="1"><center x="1" y="0" z="0"/><surface><color r="1" g="0" b="0"/></surface></sphere>"""
      )
    )
    assertEquals(british, american)

  test("children may come in any order; comments and an XML declaration are allowed"):
    val xml = """<?xml version="1.0" encoding="UTF-8"?>
      |<!-- a comment -->
      |<scene>
      |  <sphere radius="2"><surface diffuse="0.5"/><!-- here too --><centre x="0" y="0" z="1"/></sphere>
      |  <camera><lookat x="0" y="0" z="0"/><location x="0" y="0" z="-5"/></camera>
      |</scene>""".stripMargin
    assertEquals(scene(xml).objects.head.shape, Sphere(Vec3(0, 0, 1), 2))

  test("numbers may be written as -1, 0.25, .5, 3. and 2.5e-3"):
    val s = scene(
      withCamera(
        """<light><location x="-1" y="0.25" z=".5"/><colour r="3." g="2.5e-3" b="1E2"/></light>"""
      )
    )
    assertEquals(s.lights.head, Light(Vec3(-1, 0.25, 0.5), Colour(3, 0.0025, 100)))

  test("a plane takes a point or a distance; a triangle three corners or origin and legs"):
    val s = scene(
      withCamera(
        """<plane><normal x="0" y="2" z="0"/><point x="5" y="-1" z="7"/></plane>
        |<plane distance="-1"><normal x="0" y="3" z="0"/></plane>
        |<triangle><origin x="0" y="0" z="0"/><a x="1" y="0" z="0"/><b x="0" y="1" z="0"/></triangle>
        |<triangle><corner x="0" y="0" z="0"/><corner x="1" y="0" z="0"/><corner x="0" y="1" z="0"/></triangle>""".stripMargin
      )
    )
    assertEquals(s.objects(0).shape, s.objects(1).shape)
    assertEquals(s.objects(2).shape, s.objects(3).shape)

  test("pole and equator are normalised"):
    val s = scene(
      withCamera(
        """<sphere radius="1"><centre x="0" y="0" z="0"/><pole x="0" y="0" z="3"/><equator x="2" y="0" z="0"/></sphere>"""
      )
    )
    val sphere = s.firstShape[Sphere]
    assertEquals((sphere.unitPole, sphere.unitEquator), (Vec3.UnitZ, Vec3.UnitX))

  test("the first error in document order is the one reported"):
    assertError(withCamera("<light/>\n<light/>"), Some(1), "light", "missing <location>")

  test("a texture file is loaded once however many shapes use it"):
    val tex = """<surface><texture file="t.ppm"/></surface>"""
    scene(
      withCamera(
        s"""<sphere radius="1"><centre x="0" y="0" z="0"/>$tex</sphere><sphere radius="1"><centre x="3" y="0" z="0"/>$tex</sphere>"""
      )
    ): Unit
    assertEquals(loaded.toList, List("t.ppm"))

  // Errors: each names the element, its line and what is wrong.

  test("the root must be <scene>"):
    assertError("<world/>", Some(1), "world", "root element must be <scene>")

  test("a scene needs exactly one camera"):
    assertError("<scene>\n</scene>", Some(1), "scene", "missing <camera>")
    assertError(s"<scene>$camera\n$camera</scene>", Some(2), "camera", "only one <camera>")

  test("an unknown element is an error naming it and its parent"):
    assertError(withCamera("\n<cube/>"), Some(2), "cube", "unknown element inside <scene>")
    assertError(
      withCamera(
        """<sphere radius="1"><centre x="0" y="0" z="0"/><colour r="1" g="1" b="1"/></sphere>"""
      ),
      Some(1),
      "colour",
      "inside <sphere>"
    )

  test("an unknown attribute is an error naming it"):
    assertError(
      withCamera("""<sphere radius="1" size="2"><centre x="0" y="0" z="0"/></sphere>"""),
      Some(1),
      "sphere",
      "unknown attribute size"
    )
    assertError(
      withCamera("""<light><location x="0" y="0" z="0" w="1"/></light>"""),
      Some(1),
      "location",
      "unknown attribute w"
    )

  test("text inside an element is an error"):
    assertError(
      withCamera("<light>bright<location x=\"0\" y=\"0\" z=\"0\"/></light>"),
      Some(1),
      "light",
      "unexpected text 'bright'"
    )

  test("stray text is reported at its own line, not its element's"):
    assertError(
      s"<scene>\n$camera\n   stray words\n</scene>",
      Some(3),
      "scene",
      "unexpected text 'stray words'"
    )
    assertError(
      s"<scene>$camera<light>\n\n\n  <location x=\"0\" y=\"0\" z=\"0\"/>\n  lamp\n  \n</light></scene>",
      Some(5),
      "light",
      "unexpected text 'lamp'"
    )

  test("a missing required element or attribute is an error"):
    assertError(
      "<scene><camera><location x=\"0\" y=\"0\" z=\"-5\"/></camera></scene>",
      Some(1),
      "camera",
      "missing <lookat>"
    )
    assertError(
      withCamera("<sphere><centre x=\"0\" y=\"0\" z=\"0\"/></sphere>"),
      Some(1),
      "sphere",
      "missing attribute radius"
    )
    assertError(withCamera("<sphere radius=\"1\"/>"), Some(1), "sphere", "missing <centre>")
    assertError(withCamera("<light/>"), Some(1), "light", "missing <location>")
    assertError(
      withCamera("<light><location x=\"0\" y=\"0\"/></light>"),
      Some(1),
      "location",
      "missing attribute z"
    )
    assertError(
      withCamera("<background r=\"0\" g=\"0\"/>"),
      Some(1),
      "background",
      "missing attribute b"
    )

  test("a repeated child is an error at the repeat"):
    assertError(
      withCamera("<background r=\"0\" g=\"0\" b=\"0\"/>\n<background r=\"0\" g=\"0\" b=\"0\"/>"),
      Some(2),
      "background",
      "only one <background>"
    )
    assertError(
      withCamera(
        "<sphere radius=\"1\"><centre x=\"0\" y=\"0\" z=\"0\"/>\n<center x=\"0\" y=\"0\" z=\"0\"/></sphere>"
      ),
      Some(2),
      "center",
      "only one <centre> or <center>"
    )

  test("numbers must be finite decimals"):
    for bad <- List("NaN", "Infinity", "", "1,5", "0x10", "1e999", "one", "--1") do
      assertError(
        withCamera(s"""<sphere radius="$bad"><centre x="0" y="0" z="0"/></sphere>"""),
        Some(1),
        "sphere",
        "radius must be a finite decimal number"
      )

  test("out-of-range values are errors"):
    def sphere(attrs: String, surface: String = "") =
      withCamera(s"""<sphere $attrs><centre x="0" y="0" z="0"/>$surface</sphere>""")
    assertError(sphere("radius=\"0\""), Some(1), "sphere", "radius must be greater than 0, got 0")
    assertError(
      sphere("radius=\"1\"", "<surface diffuse=\"-0.1\"/>"),
      Some(1),
      "surface",
      "diffuse must be at least 0"
    )
    assertError(
      sphere("radius=\"1\"", "<surface reflection=\"1.5\"/>"),
      Some(1),
      "surface",
      "reflection must be from 0 to 1"
    )
    assertError(
      sphere("radius=\"1\"", "<surface><colour r=\"1.2\" g=\"0\" b=\"0\"/></surface>"),
      Some(1),
      "colour",
      "r must be from 0 to 1, got 1.2"
    )
    assertError(
      withCamera("<background r=\"0\" g=\"-1\" b=\"0\"/>"),
      Some(1),
      "background",
      "g must be at least 0, got -1"
    )
    assertError(
      withCamera(
        "<light><location x=\"0\" y=\"0\" z=\"0\"/><colour r=\"0\" g=\"0\" b=\"-2\"/></light>"
      ),
      Some(1),
      "colour",
      "b must be at least 0"
    )
    assertError(
      "<scene><camera zoom=\"0\"><location x=\"0\" y=\"0\" z=\"-5\"/><lookat x=\"0\" y=\"0\" z=\"0\"/></camera></scene>",
      Some(1),
      "camera",
      "zoom must be greater than 0"
    )
    assertError(
      "<scene><camera height=\"-1\"><location x=\"0\" y=\"0\" z=\"-5\"/><lookat x=\"0\" y=\"0\" z=\"0\"/></camera></scene>",
      Some(1),
      "camera",
      "height must be greater than 0"
    )

  test("light colours may exceed 1"):
    assertEquals(
      scene(
        withCamera(
          "<light><location x=\"0\" y=\"0\" z=\"0\"/><colour r=\"5\" g=\"0\" b=\"0\"/></light>"
        )
      ).lights.head.colour,
      Colour(5, 0, 0)
    )

  test("a degenerate camera is an error"):
    assertError(
      "<scene><camera><location x=\"1\" y=\"1\" z=\"1\"/><lookat x=\"1\" y=\"1\" z=\"1\"/></camera></scene>",
      Some(1),
      "camera",
      "must differ from <location>"
    )
    assertError(
      "<scene><camera><location x=\"0\" y=\"0\" z=\"0\"/><lookat x=\"0\" y=\"5\" z=\"0\"/></camera></scene>",
      Some(1),
      "camera",
      "parallel to the viewing direction"
    )

  test("pole and equator must be non-zero and at right angles"):
    def sphere(pole: String, equator: String) = withCamera(
      s"""<sphere radius="1"><centre x="0" y="0" z="0"/><pole $pole/><equator $equator/></sphere>"""
    )
    assertError(
      sphere("x=\"0\" y=\"1\" z=\"0\"", "x=\"0\" y=\"1\" z=\"1\""),
      Some(1),
      "sphere",
      "at right angles"
    )
    assertError(
      sphere("x=\"0\" y=\"0\" z=\"0\"", "x=\"1\" y=\"0\" z=\"0\""),
      Some(1),
      "pole",
      "zero vector"
    )
    assert(
      parse(sphere("x=\"0\" y=\"1\" z=\"0\"", "x=\"1\" y=\"1e-7\" z=\"0\"")).isRight,
      "1e-7 off a right angle is within 1e-6"
    )

  test("a plane needs a non-zero normal and exactly one of point and distance"):
    assertError(
      withCamera("<plane distance=\"1\"><normal x=\"0\" y=\"0\" z=\"0\"/></plane>"),
      Some(1),
      "plane",
      "zero vector"
    )
    assertError(
      withCamera("<plane><normal x=\"0\" y=\"1\" z=\"0\"/></plane>"),
      Some(1),
      "plane",
      "needs a <point> or a distance"
    )
    assertError(
      withCamera(
        "<plane distance=\"1\"><normal x=\"0\" y=\"1\" z=\"0\"/><point x=\"0\" y=\"0\" z=\"0\"/></plane>"
      ),
      Some(1),
      "plane",
      "not both"
    )

  test("a triangle needs one complete form and corners that are not collinear"):
    val c = "<corner x=\"0\" y=\"0\" z=\"0\"/>"
    assertError(
      withCamera(s"<triangle>$c$c</triangle>"),
      Some(1),
      "triangle",
      "exactly three <corner>"
    )
    assertError(
      withCamera(
        "<triangle><origin x=\"0\" y=\"0\" z=\"0\"/><a x=\"1\" y=\"0\" z=\"0\"/></triangle>"
      ),
      Some(1),
      "triangle",
      "<origin>, <a> and <b>"
    )
    assertError(
      withCamera(s"<triangle>$c<origin x=\"0\" y=\"0\" z=\"0\"/></triangle>"),
      Some(1),
      "triangle",
      "not both"
    )
    assertError(
      withCamera(
        "<triangle><corner x=\"0\" y=\"0\" z=\"0\"/><corner x=\"1\" y=\"1\" z=\"1\"/><corner x=\"2\" y=\"2\" z=\"2\"/></triangle>"
      ),
      Some(1),
      "triangle",
      "collinear"
    )

  test("textures are for spheres and triangles only"):
    assertError(
      withCamera(
        "<plane distance=\"0\"><normal x=\"0\" y=\"1\" z=\"0\"/><surface><texture file=\"t.ppm\"/></surface></plane>"
      ),
      Some(1),
      "texture",
      "spheres and triangles only"
    )

  test("a texture that cannot be loaded is an error naming the file"):
    assertError(
      withCamera(
        "<sphere radius=\"1\"><centre x=\"0\" y=\"0\" z=\"0\"/>\n<surface><texture file=\"missing.ppm\"/></surface></sphere>"
      ),
      Some(2),
      "texture",
      "'missing.ppm'",
      "no such file"
    )

  test("malformed XML is an error with its line"):
    assertError("<scene>\n<camera>\n</scene>", Some(3), "", "malformed XML")
    assertError("", Some(1), "", "malformed XML")

  test("a DOCTYPE is rejected before an external entity is read"):
    val secret = Files.createTempFile("tracer-secret", ".txt")
    Files.writeString(secret, "TOP-SECRET")
    try
      val xxe = s"""<?xml version="1.0"?>
        |<!DOCTYPE scene [<!ENTITY leak SYSTEM "file://$secret">]>
        |<scene>$camera<light><location x="0" y="0" z="0"/>&leak;</light></scene>""".stripMargin
      assertError(xxe, Some(2), "", "<!DOCTYPE> is not allowed")
      assert(!parse(xxe).left.exists(_.describe.contains("TOP-SECRET")))
    finally Files.delete(secret)

  test("a DOCTYPE is rejected before any entity is expanded (billion laughs)"):
    val entities =
      (1 to 9).map(i => s"""<!ENTITY lol$i "${s"&lol${i - 1};" * 10}">""").mkString("\n")
    val bomb = s"""<?xml version="1.0"?>
      |<!DOCTYPE scene [<!ENTITY lol0 "lol">
      |$entities]>
      |<scene>&lol9;</scene>""".stripMargin
    assertError(bomb, Some(2), "", "<!DOCTYPE> is not allowed")

  test("errors describe themselves on one line: line, element, what is wrong"):
    assertEquals(
      SceneError(Some(12), "sphere", "radius must be greater than 0, got -1").describe,
      "line 12: <sphere>: radius must be greater than 0, got -1"
    )

  test("numbers: exactly the decimals of the format, nothing else"):
    for good <- List("1", "-1", "+2", "0.25", ".5", "5.", "2.5e-3", "1E+2", "-0.0", "007") do
      assert(Decimal.matches(good), good)
    for bad <- List(
        "",
        "+",
        "-",
        ".",
        "e3",
        "1e",
        "1e+",
        "1.2.3",
        "0x10",
        "NaN",
        "Infinity",
        "1 2",
        "1f",
        "--1"
      )
    do assert(!Decimal.matches(bad), bad)
