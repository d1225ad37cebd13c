package tracer.geometry

/** Real roots of polynomials on an interval, for the torus's quartic.
  *
  * The method is exact in its logic and needs no special cases: the roots of p' split [lo, hi]
  * into pieces on which p is monotonic, so each piece holds at most one root, found by bisection
  * with Newton steps where they stay inside the bracket. The roots of p' come the same way from
  * p'', down to a line.
  */
object Polynomial:

  /** The real roots of c(0) + c(1)·x + … + c(n)·xⁿ in [lo, hi], in increasing order. A double
    * root where p touches 0 without changing sign is found only if p is exactly 0 there.
    */
  def roots(c: IArray[Double], lo: Double, hi: Double): List[Double] =
    val n = degree(c)
    if n <= 0 then Nil
    else if n == 1 then
      val x = -c(0) / c(1)
      if x >= lo && x <= hi then List(x) else Nil
    else
      val derivative = IArray.tabulate(n)(k => c(k + 1) * (k + 1))
      val ends       = (lo :: roots(derivative, lo, hi)) :+ hi
      ends
        .zip(ends.tail)
        .flatMap((a, b) => root(c, n, a, b))
        .distinct

  /** p at `x`, by Horner's rule. */
  def value(c: IArray[Double], x: Double): Double =
    // Perf: Horner's loop without a collection, run ~60 times a root on every torus ray
    // (SolidsSuite's torus cases).
    var k   = c.length - 1
    var sum = 0.0
    while k >= 0 do
      sum = sum * x + c(k)
      k -= 1
    sum

  private def degree(c: IArray[Double]): Int = c.lastIndexWhere(_ != 0)

  /** Doubles of scratch one level of [[rootsInto]] uses: its derivative's coefficients, its roots
    * at `RootsAt`, the ends of its monotonic pieces at `EndsAt`.
    */
  val ScratchLevel: Int = 16

  /** Where a level's roots start within its scratch. */
  val RootsAt: Int = 5

  /** Where a level's piece ends start within its scratch. */
  private val EndsAt: Int = 9

  /** Scratch enough for a quartic's coefficients and its four levels. */
  val ScratchSize: Int = 6 * ScratchLevel

  /** [[roots]] on a scratch array, bit for bit: the polynomial's `len` coefficients are at
    * `s(at until at + len)`, its roots in [lo, hi] are written at `s(out + RootsAt …)` in
    * increasing order, and their number is returned; the levels below use `s` from `out` on.
    * With `wanted` below the degree, only the first `wanted` roots are looked for (the same bits).
    */
  def rootsInto(
      s: Array[Double],
      at: Int,
      len: Int,
      lo: Double,
      hi: Double,
      out: Int,
      wanted: Int = Int.MaxValue
  ): Int =
    // Perf: the recursion of `roots` without an IArray, list or option per level; run for every
    // ray that meets a torus's bounding sphere (Kernel, SolidsBench).
    var n = len - 1
    while n >= 0 && s(at + n) == 0 do n -= 1
    if n <= 0 then 0
    else if n == 1 then
      val x = -s(at) / s(at + 1)
      if x >= lo && x <= hi then
        s(out + RootsAt) = x
        1
      else 0
    else
      // Why: loops filling this level's scratch: the derivative, the pieces' ends, the roots.
      var k = 0
      while k < n do
        s(out + k) = s(at + k + 1) * (k + 1)
        k += 1
      val m    = rootsInto(s, out, n, lo, hi, out + ScratchLevel)
      val ends = out + EndsAt
      s(ends) = lo
      k = 0
      while k < m do
        s(ends + 1 + k) = s(out + ScratchLevel + RootsAt + k)
        k += 1
      s(ends + m + 1) = hi
      var found = 0
      k = 0
      while k <= m && found < wanted do
        val x = rootOn(s, at, len, n, s(ends + k), s(ends + k + 1))
        if !java.lang.Double.isNaN(x) then
          // `distinct`: a root already found is not written again. Equal as Scala's `==` on
          // doubles says, as `distinct` compares them: 0.0 and -0.0 are one root.
          var j = 0
          while j < found && s(out + RootsAt + j) != x do j += 1
          if j == found then
            s(out + RootsAt + found) = x
            found += 1
        k += 1
      found

  /** [[root]] on a scratch array: the root in [a, b], or NaN for none. */
  private def rootOn(s: Array[Double], at: Int, len: Int, n: Int, a: Double, b: Double): Double =
    val pa = valueOn(s, at, len, a)
    val pb = valueOn(s, at, len, b)
    if pa == 0 then a
    else if pb == 0 then b
    else if (pa < 0) == (pb < 0) then Double.NaN
    else bisectOn(s, at, len, n, a, b, pa < 0)

  /** [[value]] on a scratch array. */
  private def valueOn(s: Array[Double], at: Int, len: Int, x: Double): Double =
    // Perf: Horner's loop, as in value.
    var k   = len - 1
    var sum = 0.0
    while k >= 0 do
      sum = sum * x + s(at + k)
      k -= 1
    sum

  /** [[bisect]] on a scratch array, step for step. */
  private def bisectOn(
      s: Array[Double],
      at: Int,
      len: Int,
      n: Int,
      a0: Double,
      b0: Double,
      rising: Boolean
  ): Double =
    // Why: a bracketing root search is a loop over two moving ends; it is local to this call.
    var a     = a0
    var b     = b0
    var x     = 0.5 * (a + b)
    var steps = 0
    while steps < 200 && x > a && x < b do
      val p = valueOn(s, at, len, x)
      if p == 0 then
        a = x
        b = x
      else
        if (p < 0) == rising then a = x else b = x
        // Perf: Horner's loop for p', as in slopeAt.
        var k     = n
        var slope = 0.0
        while k >= 1 do
          slope = slope * x + s(at + k) * k
          k -= 1
        val newton = if slope != 0 then x - p / slope else Double.NaN
        if converged(x, newton) then
          a = Math.max(a, Math.min(b, newton))
          b = a
        x =
          if newton > a && newton < b && Math.abs(newton - x) < 0.5 * (b - a) then newton
          else 0.5 * (a + b)
      steps += 1
    if a == b then a else x

  /** The root of p in [a, b] where p is monotonic, if its ends differ in sign (or one is 0). */
  private def root(c: IArray[Double], n: Int, a: Double, b: Double): Option[Double] =
    val (pa, pb) = (value(c, a), value(c, b))
    if pa == 0 then Some(a)
    else if pb == 0 then Some(b)
    else if (pa < 0) == (pb < 0) then None
    else Some(bisect(c, n, a, b, pa < 0))

  /** Safeguarded Newton iteration in the bracket [a, b] where p(a) < 0 iff `rising`. */
  private def bisect(c: IArray[Double], n: Int, a0: Double, b0: Double, rising: Boolean): Double =
    // Why: a bracketing root search is a loop over two moving ends; it is local to this call.
    var a     = a0
    var b     = b0
    var x     = 0.5 * (a + b)
    var steps = 0
    while steps < 200 && x > a && x < b do
      val p = value(c, x)
      if p == 0 then
        a = x
        b = x
      else
        if (p < 0) == rising then a = x else b = x
        val slope  = slopeAt(c, n, x)
        val newton = if slope != 0 then x - p / slope else Double.NaN
        // A Newton step of a few units in the last place ends the search there (in the bracket).
        if converged(x, newton) then
          a = Math.max(a, Math.min(b, newton))
          b = a
        // Take Newton's step when it stays well inside the bracket, else halve the bracket.
        x =
          if newton > a && newton < b && Math.abs(newton - x) < 0.5 * (b - a) then newton
          else 0.5 * (a + b)
      steps += 1
    if a == b then a else x

  /** Newton's step from x to `newton` is at most [[Converged]] units in the last place of x: the
    * root is found to the rounding of p near it.
    *
    * Perf: without it, a step that lands on an end of the bracket left the search halving the
    * bracket down to one unit in the last place, about fifty more values of p a root, on every
    * torus ray (docs/performance.md, round 16).
    */
  private inline def converged(x: Double, newton: Double): Boolean =
    Math.abs(newton - x) <= Converged * ulp(x)

  /** `Math.ulp(x)`, bit for bit: for a normal x whose unit in the last place is normal too, the
    * bits of x's exponent less 52, one mask and one subtraction; the rest (zero, subnormals, the
    * smallest normals, ∞ and NaN) through `Math.ulp`.
    *
    * Perf: `Math.ulp` (its switch on the exponent, not an intrinsic) held 5% of the samples of
    * the gallery's solids in steady state, one call a Newton step of the torus's roots; with this,
    * steady frames 1.5% faster (docs/performance.md, round 29).
    */
  private[geometry] inline def ulp(x: Double): Double =
    val exponent = java.lang.Double.doubleToRawLongBits(x) & ExponentBits
    if exponent >= UlpNormalFrom && exponent != ExponentBits then
      java.lang.Double.longBitsToDouble(exponent - UlpShift)
    else Math.ulp(x)

  /** The exponent field of a double's bits. */
  private final val ExponentBits = 0x7ff0000000000000L

  /** 52 in the exponent field: the ulp of a normal x is x's exponent less this. */
  private final val UlpShift = 52L << 52

  /** The least exponent field whose doubles' ulp is a normal double (biased exponent 53). */
  private final val UlpNormalFrom = 53L << 52

  /** The units in the last place within which a Newton step counts as converged. */
  val Converged: Double = 4.0

  private def slopeAt(c: IArray[Double], n: Int, x: Double): Double =
    // Perf: Horner's loop for p', as in value.
    var k   = n
    var sum = 0.0
    while k >= 1 do
      sum = sum * x + c(k) * k
      k -= 1
    sum
