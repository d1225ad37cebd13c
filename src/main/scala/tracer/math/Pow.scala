package tracer.math

import java.lang.Double.{doubleToRawLongBits, longBitsToDouble, parseDouble}

/** xʸ as `StrictMath.pow` gives it, bit for bit, without allocating: fdlibm's `e_pow.c` (the
  * algorithm `StrictMath.pow` is specified to follow), with its constants and steps as they are.
  *
  * Perf: JDK 21 and later compute `StrictMath.pow` in Java (`FdLibm.Pow`), whose main path makes
  * three small arrays of constants a call: a `new double[]` that C2 cannot remove, as they are
  * indexed by a variable. The shading's highlights call it for every lit point, and those arrays
  * were 61 of the 116 MB the gallery's `solids.xml` allocated at 960×540 (JFR allocation samples;
  * docs/performance.md, round 38). The same constants here are fields, read, not made.
  * `PowProperties` compares every result with `StrictMath.pow`'s bits.
  *
  * The algorithm and its constants: fdlibm 5.3, e_pow.c, "Copyright (C) 2004 by Sun
  * Microsystems, Inc. All rights reserved. Permission to use, copy, modify, and distribute this
  * software is freely granted, provided that this notice is preserved."
  */
object Pow:

  /** xʸ, the same double as `StrictMath.pow(x, y)` for every x and y. */
  def pow(x: Double, y: Double): Double =
    if y == 0.0 then 1.0
    else if java.lang.Double.isNaN(x) || java.lang.Double.isNaN(y) then x + y
    else
      val yAbs = Math.abs(y)
      val xAbs = Math.abs(x)
      if y == 2.0 then x * x
      else if y == 0.5 && x >= -Double.MaxValue then Math.sqrt(x + 0.0)
      else if yAbs == 1.0 then (if y == 1.0 then x else 1.0 / x)
      else if yAbs == Double.PositiveInfinity then
        if xAbs == 1.0 then y - y
        else if xAbs > 1.0 then (if y >= 0 then y else 0.0)
        else if y < 0 then -y
        else 0.0
      else general(x, y, xAbs, yAbs)

  // fdlibm's words of a double.
  private inline def hi(x: Double): Int                  = (doubleToRawLongBits(x) >> 32).toInt
  private inline def lo(x: Double): Int                  = doubleToRawLongBits(x).toInt
  private inline def withLo(x: Double, low: Int): Double =
    longBitsToDouble((doubleToRawLongBits(x) & 0xffffffff00000000L) | (low & 0xffffffffL))
  private inline def withHi(x: Double, high: Int): Double =
    longBitsToDouble((doubleToRawLongBits(x) & 0xffffffffL) | (high.toLong << 32))

  /** fdlibm's constants, read from their exact hexadecimal forms. */
  private def hex(s: String): Double = parseDouble(s)

  private val Bp1     = 1.5
  private val DpH1    = hex("0x1.2b8034p-1")
  private val DpL1    = hex("0x1.cfdeb43cfd006p-27")
  private val L1      = hex("0x1.3333333333303p-1")
  private val L2      = hex("0x1.b6db6db6fabffp-2")
  private val L3      = hex("0x1.55555518f264dp-2")
  private val L4      = hex("0x1.17460a91d4101p-2")
  private val L5      = hex("0x1.d864a93c9db65p-3")
  private val L6      = hex("0x1.a7e284a454eefp-3")
  private val P1      = hex("0x1.555555555553ep-3")
  private val P2      = hex("-0x1.6c16c16bebd93p-9")
  private val P3      = hex("0x1.1566aaf25de2cp-14")
  private val P4      = hex("-0x1.bbd41c5d26bf1p-20")
  private val P5      = hex("0x1.6376972bea4d0p-25")
  private val Lg2     = hex("0x1.62e42fefa39efp-1")
  private val Lg2H    = hex("0x1.62e43p-1")
  private val Lg2L    = hex("-0x1.05c610ca86c39p-29")
  private val Ovt     = 8.0085662595372944372e-17
  private val Cp      = hex("0x1.ec709dc3a03fdp-1")
  private val CpH     = hex("0x1.ec709ep-1")
  private val CpL     = hex("-0x1.e2fe0145b01f5p-28")
  private val InvLn2  = hex("0x1.71547652b82fep0")
  private val InvLn2H = hex("0x1.715476p0")
  private val InvLn2L = hex("0x1.4ae0bf85ddf44p-26")

  /** [[pow]] past its special values of y: e_pow.c from its special values of x on. */
  private def general(x: Double, y: Double, xAbs: Double, yAbs: Double): Double =
    val hx = hi(x)
    val ix = hx & 0x7fffffff
    // 0: y is not an integer; 1: an odd one; 2: an even one (asked only when x < 0).
    val yIsInt =
      if hx >= 0 then 0
      else if yAbs >= 9.007199254740992e15 then 2
      else if yAbs >= 1.0 then
        val whole = yAbs.toLong
        if whole.toDouble == yAbs then 2 - (whole & 1L).toInt else 0
      else 0
    if xAbs == 0.0 || xAbs == Double.PositiveInfinity || xAbs == 1.0 then
      // Why: z as e_pow.c builds it for x ±0, ±∞ or ±1.
      var z = xAbs
      if y < 0.0 then z = 1.0 / z
      if hx < 0 then
        if ((ix - 0x3ff00000) | yIsInt) == 0 then z = (z - z) / (z - z)
        else if yIsInt == 1 then z = -1.0 * z
      z
    else
      val n0 = (hx >> 31) + 1
      if (n0 | yIsInt) == 0 then (x - x) / (x - x)
      else
        val s = if (n0 | (yIsInt - 1)) == 0 then -1.0 else 1.0
        if yAbs <= HugeY then fromLog(s, y, xAbs, ix)
        else if xAbs < BelowOne then (if y < 0.0 then s * Double.PositiveInfinity else s * 0.0)
        else if xAbs > AboveOne then (if y > 0.0 then s * Double.PositiveInfinity else s * 0.0)
        else
          // |1 − x| ≤ 2⁻²⁰: log2 |x| from x − x²/2 + x³/3 − x⁴/4.
          val t  = xAbs - 1.0
          val w  = (t * t) * (0.5 - t * (0.3333333333333333333333 - t * 0.25))
          val u  = InvLn2H * t
          val v  = t * InvLn2L - w * InvLn2
          val t1 = withLo(u + v, 0)
          exp2(s, y, t1, v - (t1 - u))

  /** |y| above this (about 2³¹) is huge: xʸ is 0 or ∞ unless x is within 2⁻²⁰ of 1. */
  private val HugeY = hex("0x1.00000ffffffffp31")

  /** The bounds of "x within 2⁻²⁰ of 1" for a huge |y|. */
  private val BelowOne = hex("0x1.fffff00000000p-1")
  private val AboveOne = hex("0x1.00000ffffffffp0")

  /** s · |x|ʸ for a |y| that is not huge: log2 |x| (ix its high word) as t1 + t2, by e_pow.c's
    * polynomial on the interval of |x|'s significand, then [[exp2]].
    */
  private def fromLog(s: Double, y: Double, xAbs0: Double, ix0: Int): Double =
    // Why: fdlibm's working values, each reassigned as its steps say.
    var xAbs = xAbs0
    var ix   = ix0
    var n    = 0
    if ix < 0x00100000 then
      xAbs *= 9007199254740992.0
      n -= 53
      ix = hi(xAbs)
    n += (ix >> 20) - 0x3ff
    val j = ix & 0x000fffff
    ix = j | 0x3ff00000
    // Why: k picks the interval (0: |x| < √(3/2), 1: |x| < √3), n may step up.
    var k = 0
    if j > 0x3988e then
      if j < 0xbb67a then k = 1
      else
        n += 1
        ix -= 0x00100000
    xAbs = withHi(xAbs, ix)
    val bp  = if k == 0 then 1.0 else Bp1
    val dpH = if k == 0 then 0.0 else DpH1
    val dpL = if k == 0 then 0.0 else DpL1
    val u0  = xAbs - bp
    val v0  = 1.0 / (xAbs + bp)
    val ss  = u0 * v0
    val sH  = withLo(ss, 0)
    val tH0 = withHi(0.0, ((ix >> 1) | 0x20000000) + 0x00080000 + (k << 18))
    val tL0 = xAbs - (tH0 - bp)
    val sL  = v0 * ((u0 - sH * tH0) - sH * tL0)
    val s20 = ss * ss
    val r0  = s20 * s20 * (L1 + s20 * (L2 + s20 * (L3 + s20 * (L4 + s20 * (L5 + s20 * L6)))))
    val r   = r0 + sL * (sH + ss)
    val s2  = sH * sH
    val tH  = withLo(3.0 + s2 + r, 0)
    val tL  = r - ((tH - 3.0) - s2)
    val u   = sH * tH
    val v   = sL * tH + tL * ss
    val pH  = withLo(u + v, 0)
    val pL  = v - (pH - u)
    val zH  = CpH * pH
    val zL  = CpL * pH + pL * Cp + dpL
    val t   = n.toDouble
    val t1  = withLo(((zH + zL) + dpH) + t, 0)
    exp2(s, y, t1, zL - (((t1 - t) - dpH) - zH))

  /** s · 2^(y · (t1 + t2)): the last part of e_pow.c, with its overflow and underflow. */
  private def exp2(s: Double, y: Double, t1: Double, t2: Double): Double =
    val y1 = withLo(y, 0)
    val pL = (y - y1) * t1 + y * t2
    // Why: p_h, reduced by the whole part below.
    var pH = y1 * t1
    val z0 = pL + pH
    val j0 = hi(z0)
    val i0 = lo(z0)
    if j0 >= 0x40900000 && (((j0 - 0x40900000) | i0) != 0 || pL + Ovt > z0 - pH) then
      s * Double.PositiveInfinity
    else if (j0 & 0x7fffffff) >= 0x4090cc00 && (((j0 - 0xc090cc00) | i0) != 0 || pL <= z0 - pH)
    then s * 0.0
    else
      val i = j0 & 0x7fffffff
      // Why: e_pow.c's k and n, the whole part of z taken out when |z| > 0.5.
      var k = (i >> 20) - 0x3ff
      var n = 0
      if i > 0x3fe00000 then
        n = j0 + (0x00100000 >> (k + 1))
        k = ((n & 0x7fffffff) >> 20) - 0x3ff
        val t = withHi(0.0, n & ~(0x000fffff >> k))
        n = ((n & 0x000fffff) | 0x00100000) >> (20 - k)
        if j0 < 0 then n = -n
        pH -= t
      val t      = withLo(pL + pH, 0)
      val u      = t * Lg2H
      val v      = (pL - (t - pH)) * Lg2 + t * Lg2L
      val z      = u + v
      val w      = v - (z - u)
      val tt     = z * z
      val t1     = z - tt * (P1 + tt * (P2 + tt * (P3 + tt * (P4 + tt * P5))))
      val r      = (z * t1) / (t1 - 2.0) - (w + z * w)
      val z1     = 1.0 - (r - z)
      val j      = hi(z1) + (n << 20)
      val scaled =
        if (j >> 20) <= 0 then Math.scalb(z1, n)
        else withHi(z1, hi(z1) + (n << 20))
      s * scaled
