package tracer.image

import tracer.math.Pow

/** The 8-bit sample of an encoded channel, `Colour.quantise(encoding.encode(c), 255)`, found
  * from a table of where each sample begins instead of a `StrictMath.pow` a channel: the same
  * sample for every c (`ByteLevelsProperties`).
  *
  * The encodings are increasing in c, so the sample is a step function of c, stepping up to k
  * where encode(c)·255 + ½ reaches k. Around each step the table keeps a narrow band
  * [lower(k), upper(k)], its edges the inverse of the encoding a hair (10⁻⁹) on either side of
  * the step and checked against `encode` itself to lie at least 10⁻¹⁰ of a sample away from it.
  * Between the bands the sample is known (the encodings' rounding errors, some 10⁻¹⁶, are far
  * smaller than the margins); inside a band, and outside [0, 1], the sample is computed as it is
  * without the table. When a check fails (an encoding so steep that two bands would meet) the
  * table is not used at all.
  *
  * @param encoding a channel's encoding; [[Encoding.Linear]] has no table
  */
final class ByteLevels(encoding: Encoding):
  private val lower = new Array[Double](256)
  private val upper = new Array[Double](256)

  /** True when the table holds (else every sample is computed). */
  val tabled: Boolean =
    val inverse: Option[Double => Double] = encoding match
      case Encoding.Linear       => None
      case Encoding.Power(gamma) => Some(v => Pow.pow(v, gamma))
      case Encoding.Srgb         =>
        Some(v => if v <= 0.04045 then v / 12.92 else Pow.pow((v + 0.055) / 1.055, 2.4))
    inverse.exists { f =>
      (1 to 255).foreach { k =>
        lower(k) = f((k - 0.5 - ByteLevels.Band) / 255)
        upper(k) = f((k - 0.5 + ByteLevels.Band) / 255)
      }
      (1 to 255).forall { k =>
        encoding.encode(lower(k)) * 255 + 0.5 < k - ByteLevels.Margin &&
        encoding.encode(upper(k)) * 255 + 0.5 > k + ByteLevels.Margin &&
        lower(k) > 0 && lower(k) < upper(k) && upper(k) <= 1 &&
        (k == 255 || upper(k) < lower(k + 1))
      }
    }

  /** The sample 0..255 of the channel value c: `Colour.quantise(encoding.encode(c), 255)`. */
  def sample(c: Double): Int =
    if !tabled || !(c >= 0 && c <= 1) then direct(c)
    else
      // Perf: a binary search for the first band that starts above c, eight comparisons in
      // place of a StrictMath.pow (JFR of the gallery's showcase at -g srgb: a quarter of the
      // render was Encoding.encode; docs/performance.md, round 7).
      var lo = 1
      var hi = 256
      while lo < hi do
        val mid = (lo + hi) >>> 1
        if lower(mid) <= c then lo = mid + 1 else hi = mid
      val k = lo - 1
      if k >= 1 && c <= upper(k) then direct(c) else k

  /** The channel value c encoded, as a value that a bitmap of maxval 255 stores as
    * [[sample]] of c, over 255.
    */
  def encoded(c: Double): Double = sample(c) / 255.0

  private def direct(c: Double): Int = Colour.quantise(encoding.encode(c), 255)

/** The margins of [[ByteLevels]]. */
object ByteLevels:
  /** How far from a step, in samples, a band's edges are put. */
  val Band: Double = 1e-9

  /** How far from a step, in samples, a band's edge must be found to be. */
  val Margin: Double = 1e-10
