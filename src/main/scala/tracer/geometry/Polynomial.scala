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
        // Take Newton's step when it stays well inside the bracket, else halve the bracket.
        x =
          if newton > a && newton < b && Math.abs(newton - x) < 0.5 * (b - a) then newton
          else 0.5 * (a + b)
      steps += 1
    if a == b then a else x

  private def slopeAt(c: IArray[Double], n: Int, x: Double): Double =
    // Perf: Horner's loop for p', as in value.
    var k   = n
    var sum = 0.0
    while k >= 1 do
      sum = sum * x + c(k) * k
      k -= 1
    sum
