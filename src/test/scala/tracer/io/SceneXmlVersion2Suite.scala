package tracer.io

import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.SceneDocuments

/** Version 2 of the scene format (docs/scene-format.md, Version 2): the new surface attributes,
  * area lights and `smooth`, read exactly and refused with a line number when out of range.
  */
class SceneXmlVersion2Suite extends SceneDocuments:

  private def sphere(surface: String) =
    withCamera(s"""<sphere radius="1"><centre x="0" y="0" z="0"/>\n$surface</sphere>""")
  private def triangle(surface: String) = withCamera(
    s"""<triangle><corner x="0" y="0" z="0"/><corner x="1" y="0" z="0"/><corner x="0" y="1" z="0"/>\n$surface</triangle>"""
  )
  private def light(area: String) =
    withCamera(s"""<light><location x="0" y="5" z="0"/>\n$area</light>""")

  private def assertError(xml: String, line: Int, element: String, expected: String*)(using
      munit.Location
  ): Unit = assertRefused(xml, line, element, expected*)

  test("a version 1 surface has every version 2 attribute at its default"):
    val s = scene(sphere("""<surface diffuse="0.5"/>""")).objects.head.surface
    assertEquals(s, Surface(diffuse = 0.5))
    assertEquals(
      (s.phong, s.phongSize, s.specular, s.roughness, s.transmit, s.ior),
      (0.0, 40.0, 0.0, 0.05, 0.0, 1.0)
    )

  test("every surface attribute of version 2 is read"):
    val s = scene(
      sphere(
        """<surface phong="0.8" phong-size="80" specular="0.3" roughness="0.01" transmit="0.9" ior="1.5"/>"""
      )
    ).objects.head.surface
    assertEquals(
      (s.phong, s.phongSize, s.specular, s.roughness, s.transmit, s.ior),
      (0.8, 80.0, 0.3, 0.01, 0.9, 1.5)
    )

  test("transmit applies to textured surfaces too"):
    val s = scene(triangle("""<surface transmit="0.25"><texture file="t.ppm"/></surface>"""))
    assertEquals(s.objects.head.surface.transmit, 0.25)

  test("out-of-range surface attributes are errors naming the attribute and the line"):
    assertError(sphere("""<surface transmit="1.5"/>"""), 4, "surface", "transmit", "from 0 to 1")
    assertError(sphere("""<surface transmit="-0.1"/>"""), 4, "surface", "transmit")
    assertError(sphere("""<surface phong="-1"/>"""), 4, "surface", "phong", "at least 0")
    assertError(
      sphere("""<surface phong-size="0"/>"""),
      4,
      "surface",
      "phong-size",
      "greater than 0"
    )
    assertError(sphere("""<surface specular="-0.5"/>"""), 4, "surface", "specular")
    assertError(sphere("""<surface roughness="0"/>"""), 4, "surface", "roughness")
    assertError(sphere("""<surface roughness="1.5"/>"""), 4, "surface", "roughness", "at most 1")
    assertError(sphere("""<surface ior="0"/>"""), 4, "surface", "ior", "greater than 0")
    assertError(sphere("""<surface ior="NaN"/>"""), 4, "surface", "ior", "finite decimal")

  test("ior is allowed on spheres, closed solids and CSG elements only"):
    assertError(
      triangle("""<surface ior="1.5"/>"""),
      4,
      "surface",
      "ior",
      "spheres, closed solids and CSG elements only",
      "<triangle>"
    )
    assertError(
      withCamera("""<plane distance="0"><normal x="0" y="1" z="0"/>
                   |<surface transmit="0.5" ior="1.3"/></plane>""".stripMargin),
      4,
      "surface",
      "spheres, closed solids and CSG elements only"
    )
    assertEquals(scene(triangle("""<surface transmit="0.5"/>""")).objects.head.surface.ior, 1.0)

  test("an area light is read with its axes and sample counts"):
    val l = scene(
      light(
        """<area samples-a="5" samples-b="3"><a x="1.5" y="0" z="0"/><b x="0" y="0" z="2"/></area>"""
      )
    ).lights.head
    assertEquals(l.area, Some(AreaLight(Vec3(1.5, 0, 0), Vec3(0, 0, 2), 5, 3)))
    assertEquals(scene(light("")).lights.head.area, None)

  test("bad area lights are errors naming the element and the line"):
    val axes = """<a x="1" y="0" z="0"/><b x="0" y="0" z="1"/>"""
    assertError(
      light(s"""<area samples-a="0" samples-b="3">$axes</area>"""),
      4,
      "area",
      "samples-a",
      "1 to 64"
    )
    assertError(
      light(s"""<area samples-a="65" samples-b="3">$axes</area>"""),
      4,
      "area",
      "samples-a"
    )
    assertError(
      light(s"""<area samples-a="2.5" samples-b="3">$axes</area>"""),
      4,
      "area",
      "whole number"
    )
    assertError(
      light(s"""<area samples-a="2">$axes</area>"""),
      4,
      "area",
      "missing attribute samples-b"
    )
    assertError(
      light(
        """<area samples-a="2" samples-b="2"><a x="1" y="0" z="0"/><b x="2" y="0" z="0"/></area>"""
      ),
      4,
      "area",
      "not parallel"
    )
    assertError(
      light(
        """<area samples-a="2" samples-b="2"><a x="0" y="0" z="0"/><b x="0" y="0" z="1"/></area>"""
      ),
      4,
      "area",
      "non-zero"
    )
    assertError(
      light("""<area samples-a="2" samples-b="2"><a x="1" y="0" z="0"/></area>"""),
      4,
      "area",
      "missing <b>"
    )
    assertError(
      light(
        s"""<area samples-a="2" samples-b="2">$axes</area><area samples-a="2" samples-b="2">$axes</area>"""
      ),
      4,
      "area",
      "only one"
    )

  test("smooth must be true, false or auto"):
    val mesh    = (smooth: String) => withCamera(s"""<mesh file="m.obj" smooth="$smooth"/>""")
    val sources = SceneSources(_ => Right(texel), _ => Left("not read"))
    SceneXml.parse(mesh("yes"), sources) match
      case Left(e)  => assert(e.describe.contains("smooth must be true, false or auto"), e.describe)
      case Right(s) => fail(s"parsed $s")
