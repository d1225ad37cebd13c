package tracer.io

import tracer.geometry.*
import tracer.image.Colour
import tracer.math.{Placement, Vec3}
import tracer.scene.*
import tracer.testkit.SceneDocuments

/** Version 3 of the scene format (docs/scene-format.md, Version 3): solids, placement, CSG,
  * the checker pattern and `smooth="auto"`, read exactly, and every rule a scene can break
  * refused with the element and its line.
  */
class SceneXmlVersion3Suite extends SceneDocuments:

  private def objects(body: String) = scene(withCamera(body)).objects

  private def assertError(body: String, line: Int, element: String, expected: String*)(using
      munit.Location
  ): Unit = assertRefused(withCamera(body), line, element, expected*)

  private val unitBox  = """<corner1 x="-1" y="-1" z="-1"/><corner2 x="1" y="1" z="1"/>"""
  private val unitBall = """<sphere radius="1"><centre x="0" y="0" z="0"/></sphere>"""

  test("CSG nests up to 200 deep; the element beyond is refused with its line, not a crash"):
    def nested(n: Int) = "<union>\n" * n + unitBall + "</union>" * n
    // Read without the schema check: the JDK's validator stops at 100 levels of its own.
    assertEquals(parse(withCamera(nested(CsgReader.MaxNesting))).map(_.objects.length), Right(1))
    // withCamera puts the body on line 3: union k (from 1) stands on line 2 + k.
    assertError(
      nested(CsgReader.MaxNesting + 1),
      3 + CsgReader.MaxNesting,
      "union",
      "CSG elements nested more than 200 deep"
    )

  test("the four solids are read with their parts"):
    val read = objects(
      s"""<box>$unitBox</box>
         |<cylinder radius="0.5" open="true"><base x="0" y="0" z="0"/><cap x="0" y="2" z="0"/></cylinder>
         |<cone base-radius="1" cap-radius="0"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cone>
         |<torus major="2" minor="0.25"/>""".stripMargin
    ).map(_.shape)
    assertEquals(
      read,
      Vector(
        Box(Vec3(-1, -1, -1), Vec3(1, 1, 1)),
        Cylinder(Vec3.Zero, Vec3(0, 2, 0), 0.5, open = true),
        Cone(Vec3.Zero, 1, Vec3(0, 1, 0), 0),
        Torus(2, 0.25)
      )
    )

  test("placement: scale, then rotate, then translate, on solids and CSG elements"):
    val read = objects(
      """<torus major="2" minor="0.25" scale="1.5"><translate x="1" y="2" z="3"/><rotate x="90" y="0" z="0"/></torus>"""
    )
    assertEquals(
      read.map(_.shape),
      Vector(Placed(Torus(2, 0.25), Placement(1.5, Vec3(90, 0, 0), Vec3(1, 2, 3))))
    )

  test("a difference keeps its children's order and surfaces; children without one inherit"):
    val read = objects(
      s"""<difference>
         |  <box>$unitBox</box>
         |  <sphere radius="1.3"><centre x="0" y="0" z="0"/><surface diffuse="0.5"/></sphere>
         |  <surface diffuse="0.9" ior="1.5" transmit="0.5"/>
         |</difference>""".stripMargin
    )
    assertEquals(read.length, 1)
    val o = read.head
    assertEquals(
      o.shape,
      Csg(
        CsgOperation.Difference,
        Vector(Box(Vec3(-1, -1, -1), Vec3(1, 1, 1)), Sphere(Vec3.Zero, 1.3))
      )
    )
    assertEquals(o.surface.ior, 1.5)
    assertEquals(o.surfaceOf(0), Surface(diffuse = 0.9, transmit = 0.5, ior = 1.5))
    assertEquals(o.surfaceOf(1), Surface(diffuse = 0.5))

  test("an object lets light through where a surface it shows does: its own, or its parts'"):
    val ball = Sphere(Vec3.Zero, 1)
    assert(!SceneObject(ball).transmits)
    assert(SceneObject(ball, Surface(transmit = 0.4)).transmits)
    // A combination shows its parts' surfaces, not its own.
    assert(SceneObject(ball, Surface(), Vector(Surface(), Surface(transmit = 0.2))).transmits)
    assert(!SceneObject(ball, Surface(transmit = 0.3), Vector(Surface(), Surface())).transmits)

  test(
    "nested combinations inherit from the nearest enclosing surface; none anywhere is the default"
  ):
    val read = objects(
      s"""<intersection>
         |  <union><box>$unitBox</box>$unitBall<surface diffuse="0.3"/></union>
         |  $unitBall
         |  <surface diffuse="0.7"/>
         |</intersection>
         |<intersection>$unitBall$unitBall</intersection>""".stripMargin
    )
    assertEquals((0 until 3).map(read.head.surfaceOf(_).diffuse), Vector(0.3, 0.3, 0.7))
    assertEquals(read(1).surface, Surface())

  test("a top-level union without ior is split into its children, each placed by the union"):
    val read = objects(
      s"""<union>$unitBall<box>$unitBox<surface diffuse="0.2"/></box>
         |  <surface diffuse="0.6"/><translate x="5" y="0" z="0"/></union>""".stripMargin
    )
    val moved = Placement(translate = Vec3(5, 0, 0))
    assertEquals(
      read,
      Vector(
        SceneObject(Placed(Sphere(Vec3.Zero, 1), moved), Surface(diffuse = 0.6)),
        SceneObject(Placed(Box(Vec3(-1, -1, -1), Vec3(1, 1, 1)), moved), Surface(diffuse = 0.2))
      )
    )

  test("a union with ior stays one object, so its interior is one"):
    val read = objects(s"""<union>$unitBall$unitBall<surface transmit="0.9" ior="1.5"/></union>""")
    assertEquals(read.length, 1)
    assertEquals(read.head.surface.ior, 1.5)

  test("triangles and meshes in a union; a mesh's triangles moved with the union when it is split"):
    val read = objects(
      """<union><triangle><corner x="0" y="0" z="0"/><corner x="1" y="0" z="0"/><corner x="0" y="1" z="0"/></triangle>
        |<translate x="0" y="0" z="2"/></union>""".stripMargin
    )
    assertEquals(read.map(_.shape), Vector(Triangle(Vec3(0, 0, 2), Vec3(1, 0, 2), Vec3(0, 1, 2))))

  test("the checker pattern: colours in order, size, and the space of the element that carries it"):
    val read = objects(
      """<box scale="2"><corner1 x="0" y="0" z="0"/><corner2 x="1" y="1" z="1"/>
        |<surface><checker size="0.5"><colour r="1" g="0" b="0"/><color r="0" g="0" b="1"/></checker></surface>
        |<translate x="1" y="0" z="0"/></box>
        |<plane distance="0"><normal x="0" y="1" z="0"/>
        |<surface><checker><colour r="1" g="1" b="1"/><colour r="0" g="0" b="0"/></checker></surface></plane>""".stripMargin
    )
    val placement = Placement(2, Vec3.Zero, Vec3(1, 0, 0))
    assertEquals(
      read.map(_.surface.pigment),
      Vector(
        Pigment.Checker(Colour(1, 0, 0), Colour(0, 0, 1), 0.5, List(placement)),
        Pigment.Checker(Colour.White, Colour.Black, 1, Nil)
      )
    )

  test("the checker's parity: first colour where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, cells of side size"):
    val c = new Pigment.Checker(Colour.White, Colour.Black, 2)
    assertEquals(Pigment.checkerColour(c, Vec3(0.5, 0.5, 0.5)), Colour.White)
    assertEquals(Pigment.checkerColour(c, Vec3(2.5, 0.5, 0.5)), Colour.Black)
    assertEquals(Pigment.checkerColour(c, Vec3(-0.5, 0.5, 0.5)), Colour.Black)
    assertEquals(Pigment.checkerColour(c, Vec3(-2.5, -2.5, 0.5)), Colour.White)
    // On a boundary, a point a hair below it (rounding) counts as beyond it: POV-Ray's ε.
    assertEquals(Pigment.checkerColour(c, Vec3(2 - 1e-11, 0.5, 0.5)), Colour.Black)
    assertEquals(Pigment.checkerColour(c, Vec3(2 - 1e-9, 0.5, 0.5)), Colour.White)
    // The pattern moves with its element: a cell's corner at the placed origin.
    val moved = c.copy(space = List(Placement(translate = Vec3(1, 0, 0))))
    assertEquals(Pigment.checkerColour(moved, Vec3(1.5, 0.5, 0.5)), Colour.White)
    assertEquals(Pigment.checkerColour(moved, Vec3(0.5, 0.5, 0.5)), Colour.Black)

  test("each broken rule of the solids is one error naming the element and its line"):
    assertError("<box><corner1 x=\"0\" y=\"0\" z=\"0\"/></box>", 3, "box", "missing <corner2>")
    assertError(
      """<box><corner1 x="0" y="0" z="0"/><corner2 x="1" y="0" z="1"/></box>""",
      3,
      "box",
      "differ in every coordinate"
    )
    assertError(
      """<cylinder radius="0"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cylinder>""",
      3,
      "cylinder",
      "radius must be greater than 0"
    )
    assertError(
      """<cylinder radius="1"><base x="0" y="0" z="0"/><cap x="0" y="0" z="0"/></cylinder>""",
      3,
      "cylinder",
      "must differ"
    )
    assertError(
      """<cylinder><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cylinder>""",
      3,
      "cylinder",
      "missing attribute radius"
    )
    assertError(
      """<cone base-radius="0" cap-radius="0"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cone>""",
      3,
      "cone",
      "not both be 0"
    )
    assertError(
      """<cone base-radius="-1" cap-radius="1"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cone>""",
      3,
      "cone",
      "base-radius must be at least 0"
    )
    assertError("""<torus major="1" minor="0"/>""", 3, "torus", "minor must be greater than 0")
    assertError("""<torus minor="1"/>""", 3, "torus", "missing attribute major")
    assertError(
      """<cylinder radius="1" open="yes"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/></cylinder>""",
      3,
      "cylinder",
      "open must be true or false"
    )

  test(
    "placement rules: scale > 0, rotate and translate at most once, not on version 1 shapes at the top"
  ):
    assertError(
      """<torus major="1" minor="0.5" scale="0"/>""",
      3,
      "torus",
      "scale must be greater than 0"
    )
    assertError(
      """<torus major="1" minor="0.5"><rotate x="0" y="0" z="0"/>
        |<rotate x="0" y="0" z="0"/></torus>""".stripMargin,
      4,
      "rotate",
      "only one <rotate>"
    )
    assertError(
      """<sphere radius="1"><centre x="0" y="0" z="0"/>
        |<translate x="0" y="0" z="0"/></sphere>""".stripMargin,
      4,
      "translate",
      "unknown element inside <sphere>"
    )

  test("CSG rules: a child at its own line; triangles only in a union; at least one shape"):
    assertError(
      s"""<intersection>
         |  <box>$unitBox</box>
         |  <triangle><corner x="0" y="0" z="0"/><corner x="1" y="0" z="0"/><corner x="0" y="1" z="0"/></triangle>
         |</intersection>""".stripMargin,
      5,
      "triangle",
      "allowed in a <union> only"
    )
    assertError(
      s"""<difference>
         |  <box>$unitBox</box>
         |  <union>
         |    <torus major="1" minor="-1"/>
         |  </union>
         |</difference>""".stripMargin,
      6,
      "torus",
      "minor"
    )
    assertError("""<union><surface/></union>""", 3, "union", "at least one shape")
    assertError(
      s"""<union><light><location x="0" y="0" z="0"/></light>$unitBall</union>""",
      3,
      "light",
      "unknown element inside <union>"
    )

  test("ior: on spheres, closed solids and CSG elements; not on open ones, nor on a CSG child"):
    assertEquals(objects(s"""<box>$unitBox<surface ior="1.5"/></box>""").head.surface.ior, 1.5)
    assertError(
      """<cylinder radius="1" open="true"><base x="0" y="0" z="0"/><cap x="0" y="1" z="0"/>
        |<surface ior="1.5"/></cylinder>""".stripMargin,
      4,
      "surface",
      "not allowed on an open <cylinder>"
    )
    assertError(
      s"""<difference>
         |  <box>$unitBox<surface ior="1.5"/></box>
         |  $unitBall
         |</difference>""".stripMargin,
      4,
      "surface",
      "not allowed on a child of <difference>"
    )

  test(
    "surface rules: one of colour, texture and checker; two colours in a checker; no texture on solids"
  ):
    assertError(
      s"""<box>$unitBox<surface><colour r="1" g="1" b="1"/><checker><colour r="1" g="1" b="1"/><colour r="0" g="0" b="0"/></checker></surface></box>""",
      3,
      "checker",
      "not both"
    )
    assertError(
      s"""<box>$unitBox<surface><checker size="1"><colour r="1" g="1" b="1"/></checker></surface></box>""",
      3,
      "checker",
      "exactly two <colour>"
    )
    assertError(
      s"""<box>$unitBox<surface><checker size="-1"><colour r="1" g="1" b="1"/><colour r="1" g="1" b="1"/></checker></surface></box>""",
      3,
      "checker",
      "size must be greater than 0"
    )
    assertError(
      s"""<box>$unitBox<surface><texture file="t.ppm"/></surface></box>""",
      3,
      "texture",
      "spheres and triangles only, not <box>"
    )
