package tracer.math

import java.lang.Double.{doubleToLongBits, longBitsToDouble}
import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.forAll

/** [[Pow.pow]] is `StrictMath.pow`, bit for bit (every NaN counting as one value): on every kind
  * of double, on the highlights' cosines and exponents, near 1 with huge exponents, on negative
  * bases with whole exponents, and on every pair of special values.
  */
class PowProperties extends ScalaCheckSuite:

  override def scalaCheckTestParameters =
    super.scalaCheckTestParameters.withMinSuccessfulTests(20000)

  private def same(x: Double, y: Double): Prop =
    val (ours, theirs) = (Pow.pow(x, y), StrictMath.pow(x, y))
    Prop(doubleToLongBits(ours) == doubleToLongBits(theirs)) :| s"pow($x, $y) = $ours, not $theirs"

  // Any bit pattern: NaNs, infinities, subnormals, both zeros, every exponent.
  private val anyBits   = Gen.long.map(longBitsToDouble)
  private val cosine    = Gen.choose(0.0, 1.0)
  private val exponent  = Gen.oneOf(Gen.choose(0.0, 300.0), Gen.choose(1.0, 100.0).map(1 / _))
  private val nearOne   = Gen.choose(-1e-6, 1e-6).map(1 + _)
  private val hugeY     = Gen.oneOf(Gen.choose(2.2e9, 1e300), Gen.choose(-1e300, -2.2e9))
  private val wholeY    = Gen.choose(-2000L, 2000L).map(_.toDouble)
  private val negative  = Gen.oneOf(Gen.choose(-1e3, -1e-3), anyBits.map(x => -Math.abs(x)))
  private val subnormal = Gen.choose(1L, (1L << 52) - 1).map(longBitsToDouble)

  /** e_pow.c's bound on |y| (about 2³¹ + 2¹¹): past it, xʸ comes from the series for log2 x near
    * 1, or is 0 or ∞.
    */
  private val HugeY = 2147485696.0

  /** A base within 3·10⁻⁷ of 1 (either side) and an exponent past [[HugeY]] that makes xʸ about
    * 2^z, for z from −1100 to 1100: overflow, finite results, subnormals and underflow, all from
    * the near-1 branch (a uniform huge y gives there only 0 or ∞). Some exponents are rounded to
    * an odd whole number and the base negated, for a negative result.
    */
  private val nearOneFinite =
    val pairs = for
      t    <- Gen.choose(1e-12, 3e-7)
      sign <- Gen.oneOf(1.0, -1.0)
      z    <- Gen.choose(-1100.0, 1100.0)
      odd  <- Gen.prob(0.3)
    yield
      val x = 1 + sign * t
      val y = z / (Math.log(x) / Math.log(2))
      // Math.round(y) | 1 is odd for either sign; |y| < 2⁵³ here, so the result is exact.
      if odd then (-x, (Math.round(y) | 1L).toDouble) else (x, y)
    pairs.suchThat((_, y) => Math.abs(y) > HugeY)

  property("any two doubles")(forAll(anyBits, anyBits)(same))
  property("a highlight's cosine and exponent")(forAll(cosine, exponent)(same))
  property("a fade's ratio of distances and power")(forAll(Gen.choose(0.0, 1e3), exponent)(same))
  property("bases near 1 with huge exponents")(forAll(nearOne, hugeY)(same))
  property("bases near 1 with huge exponents whose powers are finite, either sign")(
    forAll(nearOneFinite)(same)
  )

  test("the near-1 pairs reach finite, non-zero powers, negative ones too"):
    val seed    = org.scalacheck.rng.Seed(20250101L)
    val params  = Gen.Parameters.default
    val samples = Iterator
      .iterate(seed)(_.next)
      .take(2000)
      .flatMap(s => nearOneFinite(params, s))
      .toList
    val finite = samples.count((x, y) =>
      val p = StrictMath.pow(x, y)
      p != 0 && !p.isInfinite
    )
    assert(samples.size > 1000, s"only ${samples.size} of 2000 draws kept")
    assert(finite > samples.size / 2, s"$finite of ${samples.size} finite and non-zero")
    assert(samples.exists((x, y) => x < 0 && StrictMath.pow(x, y) < 0), "no negative result")

  property("negative bases with whole exponents, odd and even")(forAll(negative, wholeY)(same))
  property("negative bases with fractions")(forAll(negative, Gen.choose(-10.0, 10.0))(same))
  property("subnormal bases")(forAll(subnormal, Gen.choose(-3.0, 3.0))(same))
  property("results that overflow or underflow")(
    forAll(Gen.choose(1.0, 1e10), Gen.choose(-1e4, 1e4))(same)
  )

  test("every pair of special values"):
    val specials = List(
      0.0,
      -0.0,
      1.0,
      -1.0,
      0.5,
      -0.5,
      2.0,
      -2.0,
      3.0,
      -3.0,
      Double.NaN,
      Double.PositiveInfinity,
      Double.NegativeInfinity,
      Double.MinPositiveValue,
      -Double.MinPositiveValue,
      Double.MaxValue,
      -Double.MaxValue,
      9.007199254740992e15,
      -9.007199254740993e15,
      1e-310,
      0.99999952316284,
      1.0000002384185791,
      2.147483648e9,
      // The edges of overflow and underflow, and a negative base near 1 with a huge odd exponent.
      1023.9999999999999,
      1024.0,
      1025.0,
      1075.0,
      -1075.0,
      -(1 + 1e-9),
      3000000001.0
    )
    for x <- specials; y <- specials do
      assertEquals(
        doubleToLongBits(Pow.pow(x, y)),
        doubleToLongBits(StrictMath.pow(x, y)),
        s"$x ** $y"
      )
