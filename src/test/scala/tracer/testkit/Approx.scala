package tracer.testkit

import munit.{Assertions, Location}
import tracer.math.Vec3

/** Assertions for computed doubles and vectors, with tolerances scaled by magnitude. */
trait Approx:
  self: Assertions =>

  /** Asserts that `obtained` is within `tolerance` of `expected` in every component. */
  def assertVecClose(obtained: Vec3, expected: Vec3, tolerance: Double = 1e-9)(using
      Location
  ): Unit =
    assert(
      (obtained - expected).length <= tolerance,
      s"$obtained is not within $tolerance of $expected"
    )

  /** Asserts |obtained − expected| ≤ tolerance·max(1, |expected|), a relative test for large values. */
  def assertRelClose(obtained: Double, expected: Double, tolerance: Double)(using Location): Unit =
    assert(
      Math.abs(obtained - expected) <= tolerance * Math.max(1.0, Math.abs(expected)),
      s"$obtained is not within relative $tolerance of $expected"
    )
