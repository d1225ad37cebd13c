package tracer.io

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.{Placement, Vec3}

/** The direct paths of the element readers ([[ElementRules.vector]], [[ElementRules.colour]],
  * [[ShapeReader.triangle]], [[ShapeReader.sphere]], [[SurfaceReader.surface]] and the identity
  * placement) against the general rules they skip: the
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

  /** A number usually from 0 to 1 (within most surface ranges, a fine radius), sometimes 0 or
    * 1 exactly or just outside, sometimes any of [[numbers]].
    */
  private val fractions: Gen[String] = Gen.frequency(
    6 -> Gen.choose(0.0, 1.0).map(_.toString),
    2 -> Gen.oneOf("0", "1", "1.5", "-0.5"),
    1 -> numbers
  )

  private val surfaceKeys =
    List("diffuse", "reflection", "phong", "phong-size", "specular", "roughness", "transmit", "ior")

  /** A `<surface>`: some of its numbers (in range or not, sometimes an unknown one), usually a
    * colour alone, sometimes another child, two, or text.
    */
  private val surfaces: Gen[Element] =
    for
      keys   <- Gen.someOf(surfaceKeys)
      extra  <- Gen.frequency(9 -> Gen.const(Nil), 1 -> Gen.const(List("glow")))
      values <- Gen.listOfN(keys.length + extra.length, fractions)
      colour <- Gen.oneOf("colour", "color").flatMap(n => colours.map(_.copy(name = n)))
      other  <- Gen
        .oneOf("texture", "checker", "emission", "pattern")
        .map(n =>
          Element(n, Map("file" -> "t.png", "r" -> "1", "g" -> "1", "b" -> "1"), Nil, None, None)
        )
      children <- Gen.frequency(
        6 -> Gen.const(List(colour)),
        2 -> Gen.const(Nil),
        1 -> Gen.const(List(colour, colour)),
        1 -> Gen.const(List(other)),
        1 -> Gen.const(List(colour, other))
      )
      text <- stray
      at   <- line
    yield Element("surface", (keys.toList ++ extra).zip(values).toMap, children, text, at)

  /** A direction: usually the default pole or equator, sometimes another or the zero vector. */
  private def direction(name: String, usual: (String, String, String)): Gen[Element] =
    Gen
      .frequency(
        6 -> Gen.const(Map("x" -> usual._1, "y" -> usual._2, "z" -> usual._3)),
        1 -> Gen.const(Map("x" -> "0", "y" -> "0", "z" -> "0")),
        2 -> element(name, List("x", "y", "z")).map(_.attributes)
      )
      .map(Element(name, _, Nil, None, Some(5)))

  /** A `<sphere>`: usually a radius, a centre, a pole, an equator and a surface in that order,
    * sometimes without some, in another order, with a second centre, a wrong radius or more.
    */
  private val spheres: Gen[Element] =
    for
      radius <- Gen.frequency(
        8 -> fractions.map(r => Map("radius" -> r)),
        1 -> Gen.const(Map.empty[String, String]),
        1 -> numbers.map(r => Map("radius" -> r, "scale" -> "2"))
      )
      centre  <- Gen.oneOf("centre", "center").flatMap(n => vectors.map(_.copy(name = n)))
      pole    <- Gen.option(direction("pole", ("0", "1", "0")))
      equator <- Gen.option(direction("equator", ("0", "0", "1")))
      surface <- Gen.option(surfaces)
      ordered = List(Some(centre), pole, equator, surface).flatten
      children <- Gen.frequency(
        8 -> Gen.const(ordered),
        1 -> Gen.const(ordered.reverse),
        1 -> Gen.const(ordered :+ centre),
        1 -> Gen.const(ordered :+ Element("rotate", Map("y" -> "1"), Nil, None, None))
      )
      text <- stray
      at   <- line
    yield Element("sphere", radius, children, text, at)

  property("a sphere reads as the general rules read it, at the top and inside CSG"):
    val parent = Element("difference", Map.empty, Nil, None, Some(1))
    val inside = Enclosure(Nil, None, Some(parent))
    forAll(spheres, Gen.oneOf(Enclosure.Top, inside)) { (e, at) =>
      assertEquals(reader().sphere(e, at), reader().sphereChecked(e, at))
    }

  property("a surface reads as the general rules read it, where ior is allowed or not"):
    val owner   = Element("sphere", Map.empty, Nil, None, Some(1))
    val surface = SurfaceReader((e, _) => e.fail("no textures"))
    val places  = Gen
      .oneOf(None, Some("ior is not allowed here"))
      .flatMap(refusal => Gen.oneOf(true, false).map(SurfacePlace(_, refusal, Nil)))
    forAll(surfaces, places) { (e, place) =>
      assertEquals(surface.surface(owner, e, place), surface.surfaceChecked(owner, e, place))
    }

  test("the usual elements take the direct path and give their values"):
    val corner = Element("corner", Map("x" -> "1", "y" -> " -2.5 ", "z" -> "0"), Nil, None, None)
    assertEquals(ElementRules.vector(corner), Right(Vec3(1, -2.5, 0)))
    val placed = reader().placement(Element("sphere", Map.empty, Nil, None, None), Nil)
    assert(placed.exists(_ eq Placement.Identity), placed)
    assertEquals(Placement.Identity, Placement(1.0, Vec3.Zero, Vec3.Zero))
