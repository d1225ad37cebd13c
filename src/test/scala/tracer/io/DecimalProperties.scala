package tracer.io

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll

/** [[Decimal.parse]] reads every number exactly as `Double.parseDouble` does, and nothing else. */
class DecimalProperties extends ScalaCheckSuite:

  private val digits = Gen.choose(0, 25).flatMap(n => Gen.listOfN(n, Gen.numChar).map(_.mkString))

  /** Texts shaped like numbers, often malformed: a sign, digits, a point, an exponent. */
  private val text: Gen[String] =
    for
      sign     <- Gen.oneOf("", "-", "+")
      whole    <- digits
      point    <- Gen.oneOf("", ".")
      fraction <- digits
      exponent <- Gen.oneOf(Gen.const(""), Gen.choose(-330, 330).map(e => s"e$e"), Gen.const("E+"))
      junk     <- Gen.frequency(9 -> Gen.const(""), 1 -> Gen.oneOf("x", " ", "-", ".", "e"))
    yield sign + whole + point + fraction + exponent + junk

  private def bits(d: Double) = java.lang.Double.doubleToRawLongBits(d)

  property("a number reads bit for bit as parseDouble reads it; anything else is NaN"):
    forAll(text) { s =>
      val expected = if Decimal.matches(s) then java.lang.Double.parseDouble(s) else Double.NaN
      assertEquals(bits(Decimal.parse(s)), bits(expected), s)
    }

  property("every double's shortest decimal reads back exactly"):
    forAll { (d: Double) =>
      if d.isFinite then assertEquals(bits(Decimal.parse(d.toString)), bits(d))
    }

  property("an array of characters reads bit for bit as the same text does (the OBJ reader's)"):
    forAll(text, text, text) { (before, s, after) =>
      val chars = (before + s + after).toCharArray
      val from  = before.length
      assertEquals(bits(Decimal.parse(chars, from, from + s.length)), bits(Decimal.parse(s)), s)
    }

  property("the same on any double's shortest and OBJ-style decimals"):
    forAll { (d: Double) =>
      if d.isFinite then
        for s <- List(d.toString, String.format(java.util.Locale.ROOT, "%.6f", d), f"$d%.17e")
        do
          val chars = s"v $s 0".toCharArray
          assertEquals(bits(Decimal.parse(chars, 2, 2 + s.length)), bits(Decimal.parse(s)), s)
    }

  test("edge cases read from an array as from the text"):
    for s <- List(
        "0",
        "-0",
        "+0",
        "0.0",
        "-0.000000",
        "1",
        "9007199254740993",
        "9007199254740992",
        "123456789012345678",
        "1234567890123456789",
        "0.1",
        "1e22",
        "1e23",
        "1e-22",
        "1e-23",
        "4.9e-324",
        "2.4703282292062327e-324",
        "1.7976931348623157e308",
        "1e309",
        "-1e400",
        "00000000000000000000001.5",
        "1.000000000000000000000001",
        ".5",
        "5.",
        "1e+5",
        "1E-5",
        "",
        ".",
        "-",
        "e",
        "1e",
        "1.2.3",
        "0x1p3",
        "NaN"
      )
    do
      val chars = s" $s ".toCharArray
      assertEquals(bits(Decimal.parse(chars, 1, 1 + s.length)), bits(Decimal.parse(s)), s)

  test("a part of a longer text is read without the rest"):
    assertEquals(Decimal.parse("v 1.5 -2.25e1 3", 6, 13), -22.5)

  test("the grammar: signs, points and exponents as the scene format allows"):
    for ok <- List("1", "-1", "+.5", "1.", "0.25", "2.5e-3", "1E5", "-0") do
      assert(Decimal.matches(ok), ok)
    for bad <- List(
        "",
        ".",
        "-",
        "e5",
        "1e",
        "1e+",
        "NaN",
        "Infinity",
        "0x10",
        "1f",
        "1 ",
        " 1",
        "1..2"
      )
    do assert(!Decimal.matches(bad), bad)
