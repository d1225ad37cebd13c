package tracer.math

import munit.ScalaCheckSuite
import org.scalacheck.Prop.forAll
import tracer.testkit.Approx
import tracer.testkit.Generators.{*, given}

/** The algebraic laws of [[Vec3]]: exact where IEEE arithmetic is exact, else with a stated tolerance. */
class Vec3Laws extends ScalaCheckSuite with Approx:

  // Components are at most 1e3, so products are at most ~1e6 and sums of three ~3e6; the rounding
  // error of one such sum is below 3e6 · 2^-52 ≈ 7e-10. Tolerances below allow a few of those.

  property("a + b = b + a (exact)"):
    forAll((a: Vec3, b: Vec3) => assertEquals(a + b, b + a))

  property("a · b = b · a (exact)"):
    forAll((a: Vec3, b: Vec3) => assertEquals(a.dot(b), b.dot(a)))

  property("a × b = −(b × a) (exact)"):
    forAll((a: Vec3, b: Vec3) => assertEquals(a.cross(b), -b.cross(a)))

  property("a − a = 0 and 1·a = a (exact)"):
    forAll((a: Vec3) => assertEquals(a - a, Vec3.Zero) && assertEquals(a * 1.0, a))

  property("s · a = a · s (exact)"):
    forAll(scalar, vec)((s, a) => assertEquals(s * a, a * s))

  property("(a + b) + c ≈ a + (b + c)"):
    forAll((a: Vec3, b: Vec3, c: Vec3) => assertVecClose((a + b) + c, a + (b + c), 1e-9))

  property("a · (b + c) ≈ a · b + a · c"):
    forAll((a: Vec3, b: Vec3, c: Vec3) => assertRelClose(a.dot(b + c), a.dot(b) + a.dot(c), 1e-9))

  property("a × (b + c) ≈ a × b + a × c"):
    forAll((a: Vec3, b: Vec3, c: Vec3) =>
      assertVecClose(a.cross(b + c), a.cross(b) + a.cross(c), 1e-6)
    )

  property("s(a + b) ≈ sa + sb and (s + t)a ≈ sa + ta"):
    forAll(scalar, scalar, vec, vec) { (s, t, a, b) =>
      assertVecClose((a + b) * s, a * s + b * s, 1e-6)
      assertVecClose(a * (s + t), a * s + a * t, 1e-6)
    }

  property("a × b is at right angles to a and to b"):
    forAll { (a: Vec3, b: Vec3) =>
      val c = a.cross(b)
      // Each term of (a × b) · a is about |a|²|b|, so allow 1e-12 of that.
      val tolerance = 1e-12 * (a.lengthSquared * b.length + b.lengthSquared * a.length + 1)
      assert(Math.abs(c.dot(a)) <= tolerance, s"(a × b) · a = ${c.dot(a)}")
      assert(Math.abs(c.dot(b)) <= tolerance, s"(a × b) · b = ${c.dot(b)}")
    }

  property("|a × b|² = |a|²|b|² − (a · b)² (Lagrange's identity)"):
    forAll { (a: Vec3, b: Vec3) =>
      val scale = a.lengthSquared * b.lengthSquared + 1
      assert(
        Math.abs(a.cross(b).lengthSquared - (scale - 1 - Math.pow(a.dot(b), 2))) <= 1e-12 * scale
      )
    }

  property("|normalise(a)| = 1 and normalise(a) points along a"):
    forAll(nonZeroVec) { a =>
      val n = a.normalised.get
      assertEqualsDouble(n.length, 1.0, 1e-12)
      assertEqualsDouble(n.dot(a), a.length, 1e-9 * a.length)
    }

  property("|s·a| = |s|·|a|"):
    forAll(scalar, vec)((s, a) => assertRelClose((a * s).length, Math.abs(s) * a.length, 1e-12))

  property("the distance between two points is symmetric and |a − b|"):
    forAll { (a: Vec3, b: Vec3) =>
      assertEquals(a.distance(b), b.distance(a))
      assertEquals(a.distance(b), (a - b).length)
    }

  test("normalising the zero vector is None, never NaN"):
    assertEquals(Vec3.Zero.normalised, None)
    assertEquals(Vec3.Zero.normalisedOr(Vec3.UnitY), Vec3.UnitY)

  test("normalising a vector of infinite length is None"):
    assertEquals(Vec3(Double.PositiveInfinity, 0, 0).normalised, None)
    assertEquals(Vec3(Double.NaN, 0, 0).normalised, None)

  test("the cross product follows equation 2: x × y = z"):
    assertEquals(Vec3.UnitX.cross(Vec3.UnitY), Vec3.UnitZ)
    assertEquals(Vec3(1, 2, 3).cross(Vec3(4, 5, 6)), Vec3(-3, 6, -3))

  test("dot, length and the arithmetic operators on known values"):
    assertEquals(Vec3(1, 2, 3).dot(Vec3(4, -5, 6)), 12.0)
    assertEquals(Vec3(3, 4, 12).length, 13.0)
    assertEquals(Vec3(1, 2, 3) + Vec3(1, 1, 1), Vec3(2, 3, 4))
    assertEquals(Vec3(1, 2, 3) - Vec3(1, 1, 1), Vec3(0, 1, 2))
    assertEquals(-Vec3(1, -2, 3), Vec3(-1, 2, -3))
    assertEquals(Vec3(2, 4, 6) / 2, Vec3(1, 2, 3))
