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

  /** The exact decimal `text` as an integer mantissa and a power of ten, when the mantissa has at
    * most 18 digits (what the scan gathers).
    */
  private def decimal(text: String): Option[(Long, Int)] =
    val exact = BigDecimal(text).bigDecimal.stripTrailingZeros
    val m     = exact.unscaledValue
    Option.when(m.signum > 0 && m.bitLength < 63 && m.toString.length <= 18)(
      (m.longValue, -exact.scale)
    )

  /** Decimals of 16 to 18 digits just below, at or just above the midpoint between a double and
    * the next: the hard cases, where the product's bits below the kept 54 are all ones or zeros.
    */
  private val nearHalfway: Gen[(Long, Int)] =
    for
      e      <- Gen.choose(-90.0, 90.0)
      digits <- Gen.choose(16, 18)
      step   <- Gen.choose(-2, 2)
    yield
      val d   = Math.pow(10, e)
      val mid = BigDecimal(d).bigDecimal
        .add(BigDecimal(Math.nextUp(d)).bigDecimal)
        .divide(
          java.math.BigDecimal.valueOf(2)
        )
      val near = mid.round(java.math.MathContext(digits, java.math.RoundingMode.DOWN))
      val w    = near.unscaledValue.add(java.math.BigInteger.valueOf(step))
      (w.longValue, -near.scale)

  property("Eisel-Lemire: the double nearest w × 10^q, or NaN (then parseDouble decides)"):
    val mantissas = Gen.oneOf(
      Gen.choose(1L, 999999999999999999L),
      Gen.choose(1000000000000000L, 99999999999999999L), // 16 and 17 digits, as tools write
      Gen.choose(1L << 53, (1L << 53) + 1000)            // near 2⁵³: halfway when q = 0
    )
    val powers = Gen.choose(EiselLemire.MinPower - 3, EiselLemire.MaxPower + 3)
    // Integers of 54 to 63 bits exactly halfway between two doubles: ties go to the even one.
    val halfway = for
      k <- Gen.choose(53, 62)
      m <- Gen.choose(0L, (1L << 52) - 1)
    yield ((1L << k) + ((2 * m + 1) << (k - 53)), 0)
    // Halfway values m / 2ᵏ (m odd, of 54 bits) written as m·5ᵏ × 10⁻ᵏ: a power of ten the table
    // holds truncated, so the product's low bits are all ones and the next word must decide.
    val halfwayInexact = for
      k <- Gen.choose(1, 3)
      m <- Gen.choose(1L << 52, (1L << 53) - 1)
    yield ((2 * m + 1) * Math.pow(5, k).toLong, -k)
    forAll(Gen.oneOf(Gen.zip(mantissas, powers), nearHalfway, halfway, halfwayInexact)) { (w, q) =>
      val fast = EiselLemire.toDouble(w, q)
      if !fast.isNaN then assertEquals(bits(fast), bits(java.lang.Double.parseDouble(s"${w}e$q")))
    }

  property("Eisel-Lemire decides the shortest decimals of doubles of ordinary size"):
    // The shortest decimal of a double reads back as it. The algorithm refuses halfway cases and
    // exact decimals whose truncated power of ten leaves the product's low bits all ones (such as
    // 117802331821777.25, 1 to 5 in 200 of these): so nearly all must be decided, each one right.
    val ordinary = Gen.choose(-80.0, 80.0).map(e => Math.pow(10, e))
    forAll(Gen.listOfN(200, ordinary)) { ds =>
      val read = ds.flatMap(d => decimal(d.toString).map((w, q) => d -> EiselLemire.toDouble(w, q)))
      val decided = read.filterNot(_._2.isNaN)
      decided.foreach((d, fast) => assertEquals(bits(fast), bits(d), d.toString))
      assert(decided.size >= read.size - 10, s"${read.size - decided.size} of ${read.size} refused")
      assert(read.size > 150, s"only ${read.size} decimals of at most 18 digits")
    }

  test("Eisel-Lemire declines what it does not take: no positive mantissa, a power off its table"):
    for (w, q) <- List(
        (0L, 5),
        (-5L, 0),
        (Long.MinValue, 0),
        (1L, EiselLemire.MaxPower + 1),
        (1L, EiselLemire.MinPower - 1)
      )
    do assert(EiselLemire.toDouble(w, q).isNaN, s"$w e$q")
    assertEquals(EiselLemire.toDouble(1L, EiselLemire.MaxPower), 1e100)
    assertEquals(EiselLemire.toDouble(1L, EiselLemire.MinPower), 1e-100)
