package tracer.io

import java.math.BigInteger

/** The nearest double to w × 10^q for an exact decimal mantissa w, by the Eisel–Lemire algorithm
  * (Lemire, "Number parsing at a gigabyte per second", 2021; as Go's `strconv` writes it): one
  * 64 × 128-bit product with a truncated power of ten, and an answer only when that product
  * decides the rounding. Where it cannot (a halfway case, or a product too close to one), or the
  * result would be subnormal or infinite, it answers NaN and the caller asks `parseDouble`.
  *
  * Perf: the scene files that tools write (Java's `Double.toString`, our own [[SceneWriter]])
  * carry up to 17 significant digits, beyond Clinger's exact fast path in [[Decimal]]; each then
  * went to `parseDouble`, whose exact big-number arithmetic runs cold while a scene is read (500
  * spheres: about 4,500 such numbers, some 15 ms of the read; docs/performance.md, round 26).
  */
private[io] object EiselLemire:

  /** The least and greatest power of ten the table holds; beyond them [[toDouble]] answers NaN. */
  val MinPower: Int = -100

  /** See [[MinPower]]. */
  val MaxPower: Int = 100

  /** For each power q from [[MinPower]], at 2(q − MinPower): the 128 significant bits of 10^q,
    * rounded down (its top bit set), as two words, the high one first.
    */
  private val powers: Array[Long] =
    val table = new Array[Long](2 * (MaxPower - MinPower + 1))
    val mask  = BigInteger.ONE.shiftLeft(64).subtract(BigInteger.ONE)
    // Why: one row of the table a power, written in place.
    var q = MinPower
    while q <= MaxPower do
      val ten  = BigInteger.TEN.pow(Math.abs(q))
      val bits =
        if q >= 0 then
          val shift = ten.bitLength - 128
          if shift >= 0 then ten.shiftRight(shift) else ten.shiftLeft(-shift)
        else BigInteger.ONE.shiftLeft(ten.bitLength + 127).divide(ten)
      table(2 * (q - MinPower)) = bits.shiftRight(64).longValue
      table(2 * (q - MinPower) + 1) = bits.and(mask).longValue
      q += 1
    table

  /** The high word of the unsigned 128-bit product of `a` and `b` (JDK 17 has only the signed
    * `multiplyHigh`; the correction adds b when a's top bit is set, and a when b's is).
    */
  private inline def unsignedHigh(a: Long, b: Long): Long =
    Math.multiplyHigh(a, b) + ((a >> 63) & b) + ((b >> 63) & a)

  /** True when `a` < `b` as unsigned 64-bit numbers. */
  private inline def below(a: Long, b: Long): Boolean = java.lang.Long.compareUnsigned(a, b) < 0

  /** The double nearest to `mantissa` × 10^`power` (ties to even), for 0 < `mantissa` < 2⁶³, or NaN
    * when this algorithm cannot tell it (see [[EiselLemire]]) or the mantissa is not positive.
    */
  def toDouble(mantissa: Long, power: Int): Double =
    if mantissa <= 0 || power < MinPower || power > MaxPower then Double.NaN
    else
      val zeros = java.lang.Long.numberOfLeadingZeros(mantissa)
      val w     = mantissa << zeros
      // Why: the product and the exponent are corrected in place, step by step, as Go's
      // strconv.eiselLemire64 corrects them. The exponent starts as floor(power × log₂ 10) + 64 +
      // the bias, less the normalising shift.
      var exponent = ((217706 * power) >> 16) + 64 + 1023 - zeros
      val row      = 2 * (power - MinPower)
      var hi       = unsignedHigh(w, powers(row))
      var lo       = w * powers(row)
      var decided  = true
      // Where the bits below the 54 kept are all ones, the truncated power's next word decides.
      if (hi & 0x1ff) == 0x1ff && below(lo + w, w) then
        val nextHi = unsignedHigh(w, powers(row + 1))
        val nextLo = w * powers(row + 1)
        val low    = lo + nextHi
        val high   = if below(low, lo) then hi + 1 else hi
        if (high & 0x1ff) == 0x1ff && low + 1 == 0 && below(nextLo + w, w) then decided = false
        hi = high
        lo = low
      val top    = (hi >>> 63).toInt
      var bits54 = hi >>> (top + 9)
      exponent -= 1 ^ top
      val halfway = lo == 0 && (hi & 0x1ff) == 0 && (bits54 & 3) == 1
      // Round the 54 bits to 53, half up (a halfway case is refused below, as are the undecided).
      bits54 += bits54 & 1
      bits54 >>>= 1
      if (bits54 >>> 53) > 0 then
        bits54 >>>= 1
        exponent += 1
      if !decided || halfway || exponent <= 0 || exponent >= 0x7ff then Double.NaN
      else java.lang.Double.longBitsToDouble(exponent.toLong << 52 | (bits54 & 0xfffffffffffffL))
