package tracer.io

import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.SceneDocuments

/** Version 4 of the scene format (docs/scene-format.md, Version 4): a surface's `<emission>`, a
  * light's `fade-distance` and `fade-power`, and a background brighter than 1, read exactly, and
  * every rule they can break refused with the element and its line.
  */
class SceneXmlVersion4Suite extends SceneDocuments:

  private def assertError(body: String, line: Int, element: String, expected: String*)(using
      munit.Location
  ): Unit = assertRefused(withCamera(body), line, element, expected*)

  private def ball(surface: String) =
    s"""<sphere radius="1"><centre x="0" y="0" z="0"/>\n$surface</sphere>"""

  private val lamp = """<location x="0" y="5" z="0"/>"""

  test("an <emission> is read into the surface, above 1 included; without one it is black"):
    val s = scene(
      withCamera(
        ball("""<surface diffuse="0"><emission r="2.5" g="0" b="0.25"/></surface>""") +
          ball("<surface/>")
      )
    )
    assertEquals(s.objects.map(_.surface.emission), Vector(Colour(2.5, 0, 0.25), Colour.Black))
    assert(s.objects(0).surface.emits && !s.objects(1).surface.emits)
    assertEquals(s.objects(0).surface.diffuse, 0.0)

  test("<emission> sits beside a colour, a texture or a checker, and on every kind of shape"):
    val glow = """<emission r="1" g="1" b="1"/>"""
    val s    = scene(
      withCamera(
        ball(s"""<surface><colour r="0.5" g="0.5" b="0.5"/>$glow</surface>""") +
          ball(s"""<surface>$glow<texture file="t.ppm"/></surface>""") +
          s"""<plane distance="1"><normal x="0" y="1" z="0"/><surface>$glow</surface></plane>""" +
          s"""<box><corner1 x="0" y="0" z="0"/><corner2 x="1" y="1" z="1"/><surface>$glow<checker><colour r="1" g="0" b="0"/><colour r="0" g="0" b="1"/></checker></surface></box>""" +
          s"""<difference><box><corner1 x="0" y="0" z="0"/><corner2 x="1" y="1" z="1"/></box>""" +
          s"""<sphere radius="1"><centre x="0" y="0" z="0"/><surface>$glow</surface></sphere></difference>"""
      )
    )
    assertEquals(s.objects.take(4).map(_.surface.emission), Vector.fill(4)(Colour.White))
    assertEquals(s.objects(0).surface.pigment, Pigment.Solid(Colour.grey(0.5)))
    val cut = s.objects(4)
    assertEquals(
      (cut.surfaceOf(0).emission, cut.surfaceOf(1).emission),
      (Colour.Black, Colour.White)
    )

  test("a bad <emission> is an error at its own line"):
    assertError(
      ball("""<surface><emission r="-0.5" g="0" b="0"/></surface>"""),
      4,
      "emission",
      "attribute r must be at least 0, got -0.5"
    )
    assertError(
      ball("""<surface><emission r="1" g="Infinity" b="0"/></surface>"""),
      4,
      "emission",
      "g must be a finite decimal number"
    )
    assertError(
      ball("""<surface><emission r="1" g="1"/></surface>"""),
      4,
      "emission",
      "missing attribute b"
    )
    assertError(
      ball("""<surface><emission r="1" g="1" b="1" a="1"/></surface>"""),
      4,
      "emission",
      "unknown attribute a"
    )
    assertError(
      ball(
        """<surface><emission r="1" g="1" b="1"/>
          |<emission r="1" g="1" b="1"/></surface>""".stripMargin
      ),
      5,
      "emission",
      "<surface> may have only one <emission>"
    )
    assertError(
      ball(
        """<surface><emission r="1" g="1" b="1"><colour r="1" g="1" b="1"/></emission></surface>"""
      ),
      4,
      "colour",
      "unknown element inside <emission>"
    )
    assertError(
      """<light><location x="0" y="0" z="0"/>
        |<emission r="1" g="1" b="1"/></light>""".stripMargin,
      4,
      "emission",
      "unknown element inside <light>"
    )

  test("fade-distance and fade-power are read into the light's fade, on point and area lights"):
    val s = scene(
      withCamera(
        s"""<light fade-distance="2.5" fade-power="2">$lamp</light>
           |<light fade-distance="0.5" fade-power="1.5">$lamp<area samples-a="2" samples-b="3"><a x="1" y="0" z="0"/><b x="0" y="0" z="1"/></area></light>
           |<light>$lamp</light>""".stripMargin
      )
    )
    assertEquals(s.lights.map(_.fade), Vector(Some(Fade(2.5, 2)), Some(Fade(0.5, 1.5)), None))
    assert(s.lights(1).area.isDefined)
    assertEquals(s.lights(2).attenuation(1e6), 1.0)

  test("a fade needs both attributes, each a finite number greater than 0, else its line"):
    def light(attributes: String) = s"\n<light $attributes>$lamp</light>"
    assertError(
      light("""fade-distance="2""""),
      4,
      "light",
      "fade-distance needs fade-power"
    )
    assertError(light("""fade-power="2""""), 4, "light", "fade-power needs fade-distance")
    assertError(
      light("""fade-distance="0" fade-power="2""""),
      4,
      "light",
      "attribute fade-distance must be greater than 0, got 0"
    )
    assertError(
      light("""fade-distance="1" fade-power="-1""""),
      4,
      "light",
      "attribute fade-power must be greater than 0, got -1"
    )
    assertError(
      light("""fade-distance="NaN" fade-power="2""""),
      4,
      "light",
      "fade-distance must be a finite decimal number"
    )
    assertError(
      light("""fade-distance="1" fade-power="1e999""""),
      4,
      "light",
      "fade-power must be a finite decimal number"
    )
    assertError(light("""fade="1""""), 4, "light", "unknown attribute fade")
    assertError(
      s"""\n<light>$lamp<area samples-a="2" samples-b="2" fade-power="2"><a x="1" y="0" z="0"/><b x="0" y="0" z="1"/></area></light>""",
      4,
      "area",
      "unknown attribute fade-power"
    )

  test("a background may be brighter than 1 in any channel, never below 0 or infinite"):
    assertEquals(
      scene(withCamera("""<background r="4" g="0.5" b="1e3"/>""")).background,
      Colour(4, 0.5, 1000)
    )
    assertError(
      """
        |<background r="4" g="-0.5" b="1"/>""".stripMargin,
      4,
      "background",
      "attribute g must be at least 0, got -0.5"
    )
    assertError(
      """
        |<background r="Infinity" g="0" b="1"/>""".stripMargin,
      4,
      "background",
      "r must be a finite decimal number"
    )

  test("surface colours stay in 0..1: only the emission may exceed 1"):
    assertError(
      ball("""<surface><colour r="1.5" g="0" b="0"/><emission r="1.5" g="0" b="0"/></surface>"""),
      4,
      "colour",
      "r must be from 0 to 1, got 1.5"
    )

  test("a scene without version 4's parts reads as before: no fade, no emission"):
    val s = scene(withCamera(s"<light>$lamp</light>" + ball("<surface/>")))
    assertEquals(s.lights.head, Light(Vec3(0, 5, 0)))
    assertEquals(s.objects.head.surface, Surface())
