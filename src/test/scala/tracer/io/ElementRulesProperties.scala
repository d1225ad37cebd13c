package tracer.io

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.{Placement, Vec3}

/** The direct paths of the element readers ([[ElementRules.vector]], [[ElementRules.colour]],
  * [[ShapeReader.triangle]] and the identity placement) against the general rules they skip: the
  * same value or the same error on random elements, most of them the usual shape, many of them
  * wrong in one way (a missing, extra or malformed attribute, text, a child, another order).
  */
class ElementRulesProperties extends ScalaCheckSuite:

  private val numbers: Gen[String] = Gen.frequency(
    6 -> Gen.choose(-5.0, 5.0).map(_.toString),
    2 -> Gen.oneOf("0", "1", "-0", "0.5", " 2 ", "1e400", "-1e400", "1.5e-3", "1.0000001"),
    1 -> Gen.oneOf("", "x", "NaN", "Infinity", "1..2", "+", "2e")
  )

  private val line: Gen[Option[Int]] = Gen.option(Gen.choose(1, 9))

  private val stray: Gen[Option[StrayText]] =
    Gen.frequency(9 -> Gen.const(None), 1 -> Gen.const(Some(StrayText("oops", Some(3)))))

  /** An element named `name` with the attributes `keys` (usually all, sometimes one dropped or
    * another added), rarely with text or a child.
    */
  private def element(name: String, keys: List[String]): Gen[Element] =
    for
      chosen <- Gen.frequency(
        8 -> Gen.const(keys),
        1 -> Gen.choose(0, keys.length - 1).map(i => keys.patch(i, Nil, 1)),
        1 -> Gen.oneOf("w", "radius", keys.head).map(keys :+ _)
      )
      values   <- Gen.listOfN(chosen.length, numbers)
      text     <- stray
      children <- Gen.frequency(
        9 -> Gen.const(Nil),
        1 -> Gen.const(List(Element("x", Map.empty, Nil, None, Some(2))))
      )
      at <- line
    yield Element(name, chosen.zip(values).toMap, children, text, at)

  private val vectors = element("corner", List("x", "y", "z"))

  private val colours = element("colour", List("r", "g", "b"))

  property("a vector element reads as the general rules read it"):
    forAll(vectors)(e => assertEquals(ElementRules.vector(e), ElementRules.vectorChecked(e)))

  property("a colour element reads as the general rules read it, for either bound"):
    forAll(colours, Gen.oneOf(1.0, Double.PositiveInfinity)) { (e, max) =>
      assertEquals(ElementRules.colour(e, max), ElementRules.colourChecked(e, max))
    }

  private val surface =
    Element(
      "surface",
      Map("diffuse" -> "0.7"),
      List(Element("colour", Map("r" -> "0.2", "g" -> "0.5", "b" -> "1"), Nil, None, Some(4))),
      None,
      Some(4)
    )

  /** A `<triangle>`: usually three corners and a surface, sometimes another child or order. */
  private val triangles: Gen[Element] =
    for
      corners <- Gen.frequency(
        6 -> Gen.listOfN(3, vectors),
        1 -> Gen.choose(0, 4).flatMap(Gen.listOfN(_, vectors)),
        1 -> Gen.listOfN(3, element("corner", List("x", "y", "z")).map(_.copy(name = "origin")))
      )
      more <- Gen.frequency(
        4 -> Gen.const(List(surface)),
        2 -> Gen.const(Nil),
        1 -> Gen.const(List(surface, surface)),
        1 -> Gen.const(List(surface.copy(name = "rotate")))
      )
      first      <- Gen.oneOf(true, true, true, false)
      attributes <- Gen.frequency(
        9 -> Gen.const(Map.empty[String, String]),
        1 -> Gen.const(Map("scale" -> "2"))
      )
      text <- stray
      at   <- line
    yield Element(
      "triangle",
      attributes,
      if first then corners ++ more else more ++ corners,
      text,
      at
    )

  /** A shape reader whose sources are never asked for anything (triangles load no file). */
  private def reader() =
    val sources = SceneSources(_ => Left("no textures"), _ => Left("no meshes"))
    ShapeReader(sources, SurfaceReader((e, _) => e.fail("no textures")))

  property("a triangle reads as the general rules read it, at the top and inside CSG"):
    val parent = Element("union", Map.empty, Nil, None, Some(1))
    val inside = Enclosure(List(Placement(2, Vec3(0, 30, 0), Vec3.Zero)), None, Some(parent))
    forAll(triangles, Gen.oneOf(Enclosure.Top, inside)) { (e, at) =>
      assertEquals(reader().triangle(e, at), reader().triangleChecked(e, at))
    }

  test("the usual elements take the direct path and give their values"):
    val corner = Element("corner", Map("x" -> "1", "y" -> " -2.5 ", "z" -> "0"), Nil, None, None)
    assertEquals(ElementRules.vector(corner), Right(Vec3(1, -2.5, 0)))
    val placed = reader().placement(Element("sphere", Map.empty, Nil, None, None), Nil)
    assert(placed.exists(_ eq Placement.Identity), placed)
    assertEquals(Placement.Identity, Placement(1.0, Vec3.Zero, Vec3.Zero))
