package tracer.testkit

import org.scalacheck.{Arbitrary, Gen}
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3

/** ScalaCheck generators for the tracer's value types, with bounded, finite components. */
object Generators:

  /** A coordinate in a range wide enough for scenes and small enough that products stay exact-ish. */
  val coordinate: Gen[Double] = Gen.choose(-1e3, 1e3)

  /** Any vector with bounded components (zero included). */
  val vec: Gen[Vec3] = for x <- coordinate; y <- coordinate; z <- coordinate yield Vec3(x, y, z)

  /** A vector at least 1e-3 long, so that it has a direction. */
  val nonZeroVec: Gen[Vec3] = vec.retryUntil(_.length > 1e-3)

  /** A vector of length 1, uniformly over directions. */
  val unitVec: Gen[Vec3] =
    (for x <- Gen.choose(-1.0, 1.0); y <- Gen.choose(-1.0, 1.0); z <- Gen.choose(-1.0, 1.0)
    yield Vec3(x, y, z)).retryUntil(v => v.length > 0.1 && v.length <= 1).map(v => v / v.length)

  /** A scale factor, sometimes negative. */
  val scalar: Gen[Double] = Gen.choose(-1e3, 1e3)

  /** A channel value as light adds it up: mostly in 0..1, sometimes far above. */
  val channel: Gen[Double] = Gen.frequency(3 -> Gen.choose(0.0, 1.0), 1 -> Gen.choose(0.0, 50.0))

  /** A colour whose channels may exceed 1. */
  val colour: Gen[Colour] = for r <- channel; g <- channel; b <- channel yield Colour(r, g, b)

  /** A PPM maxval: mostly 255, sometimes small or 16-bit. */
  val maxval: Gen[Int] = Gen.frequency(3 -> Gen.const(255), 1 -> Gen.choose(1, 65535))

  /** A small bitmap of random samples at a random maxval. */
  val bitmap: Gen[Bitmap] =
    for
      w       <- Gen.choose(1, 12)
      h       <- Gen.choose(1, 12)
      m       <- maxval
      samples <- Gen.listOfN(3 * w * h, Gen.choose(0, m))
    yield Bitmap.fromSamples(w, h, m, samples.toIndexedSeq)

  given Arbitrary[Vec3]   = Arbitrary(vec)
  given Arbitrary[Colour] = Arbitrary(colour)
  given Arbitrary[Bitmap] = Arbitrary(bitmap)
