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

  property("any two doubles")(forAll(anyBits, anyBits)(same))
  property("a highlight's cosine and exponent")(forAll(cosine, exponent)(same))
  property("a fade's ratio of distances and power")(forAll(Gen.choose(0.0, 1e3), exponent)(same))
  property("bases near 1 with huge exponents")(forAll(nearOne, hugeY)(same))
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
      2.147483648e9
    )
    for x <- specials; y <- specials do
      assertEquals(
        doubleToLongBits(Pow.pow(x, y)),
        doubleToLongBits(StrictMath.pow(x, y)),
        s"$x ** $y"
      )
