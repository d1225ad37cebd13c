package tracer.image

import munit.ScalaCheckSuite
import org.scalacheck.Prop.forAll
import tracer.testkit.Generators.{*, given}

/** The colour operations and the hue-keeping conversion to samples. */
class ColourLaws extends ScalaCheckSuite:

  property("an in-range colour keeps its hue: channel ratios are unchanged"):
    forAll { (c: Colour) =>
      val k = c.inRange
      assert(k.max <= 1.0 + 1e-15, s"$k exceeds 1")
      if c.max > 0 then
        val scale = k.max / c.max
        assertEqualsDouble(k.r, c.r * scale, 1e-12)
        assertEqualsDouble(k.g, c.g * scale, 1e-12)
        assertEqualsDouble(k.b, c.b * scale, 1e-12)
    }

  property("a colour already in range is left alone"):
    forAll { (c: Colour) =>
      val inside = Colour(Math.min(c.r, 1), Math.min(c.g, 1), Math.min(c.b, 1))
      assertEquals(inside.inRange, inside)
    }

  property("every sample lies in 0..maxval"):
    forAll(colour, maxval) { (c, m) =>
      val bitmap = Bitmap.fill(1, 1, c, m)
      (0 until 3).foreach(ch => assert((0 to m).contains(bitmap.sample(0, 0, ch))))
    }

  property("the brightest channel of an over-bright colour becomes maxval"):
    forAll { (c: Colour) =>
      val bitmap    = Bitmap.fill(1, 1, c)
      val brightest = (0 until 3).map(bitmap.sample(0, 0, _)).max
      if c.max > 1 then assertEquals(brightest, 255)
    }

  property("sum and scaling distribute: (a + b)·s ≈ a·s + b·s"):
    forAll(colour, colour, scalar) { (a, b, s) =>
      val (l, r) = ((a + b) * s, a * s + b * s)
      assertEqualsDouble(l.r, r.r, 1e-9); assertEqualsDouble(l.g, r.g, 1e-9);
      assertEqualsDouble(l.b, r.b, 1e-9)
    }

  test("the channel-wise product multiplies each channel"):
    assertEquals(Colour(0.5, 1, 0.25) * Colour(0.5, 0.5, 2), Colour(0.25, 0.5, 0.5))

  test("samples are round(255·c) with halves rounding up"):
    assertEquals(Colour.quantise(0.5, 255), 128) // 127.5 rounds up
    assertEquals(Colour.quantise(1.0, 255), 255)
    assertEquals(Colour.quantise(0.0, 255), 0)
    assertEquals(Colour.quantise(0.2, 255), 51)
    assertEquals(Colour.quantise(1.5 / 255, 255), 2)

  property("a sample is the floor of maxval·c + ½, clamped, for every double c"):
    val anyDouble = org.scalacheck.Gen.oneOf(
      org.scalacheck.Arbitrary.arbitrary[Double],
      org.scalacheck.Gen.choose(-2.0, 2.0),
      // Just below 0 at maxval 255, where flooring c · maxval + ½ and truncating it differ.
      org.scalacheck.Gen.choose(-1.5, 0.0).map(_ / 255),
      org.scalacheck.Gen.oneOf(
        Double.NaN,
        Double.PositiveInfinity,
        Double.NegativeInfinity,
        -0.0,
        0.5 / 255,
        -0.5 / 255,
        254.5 / 255,
        -1.0 / 255,
        Double.MinPositiveValue
      )
    )
    forAll(anyDouble, maxval) { (c, m) =>
      assertEquals(Colour.quantise(c, m), Math.min(m, Math.max(0, Math.floor(c * m + 0.5).toInt)))
    }

  property("a sample of −0.9 / maxval is 0, not −1 or 1: maxval · c + ½ is −0.4"):
    forAll(maxval)(m => assertEquals(Colour.quantise(-0.9 / m, m), 0))

  test("an over-bright colour is divided by its largest channel, not clipped"):
    val bitmap = Bitmap.fill(1, 1, Colour(2, 1, 0.5))
    assertEquals((0 until 3).map(bitmap.sample(0, 0, _)), Vector(255, 128, 64))
