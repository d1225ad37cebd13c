package tracer.render

/** A triangle's outline on a face of a [[LightBuffer]]'s cube, and the cells it may meet: how a
  * buffer bins a triangle by its own shape rather than its box's.
  *
  * A triangle (a mesh's face, or a `<triangle>`) whose box lies on one face of the cube seen from
  * the buffer's centre projects there to the triangle of its corners' projections, widened by a
  * margin that covers the rays' rounding and the box's widening; [[column]] finds, a column of
  * cells at a time, the rows that outline reaches. A terrain's faces seen obliquely fill a half
  * to a third of the cells their boxes would (docs/performance.md, round 32).
  */
private[render] object Outlines:
  /** Writes item `from`'s corners (from `absolute`, at 9 an item) relative to the light into
    * `corners` at 10i, and how far its box was widened at 10i + 9; NaN at 10i for an item that
    * is not a triangle.
    */
  def relativeCorners(
      absolute: Array[Double],
      from: Int,
      lx: Double,
      ly: Double,
      lz: Double,
      corners: Array[Double],
      i: Int
  ): Unit =
    if java.lang.Double.isNaN(absolute(9 * from)) then corners(10 * i) = Double.NaN
    else
      // Perf: a call an item, as LightBuffer.build's loops.
      var largest = 0.0
      var j       = 0
      while j < 9 do
        val x = absolute(9 * from + j)
        largest = Math.max(largest, Math.abs(x))
        corners(10 * i + j) = x - (if j % 3 == 0 then lx else if j % 3 == 1 then ly else lz)
        j += 1
      // World.widen's margin, from the same largest coordinate (the box's, before widening).
      corners(10 * i + 9) = 1e-7 * (1 + largest)

  /** For sorted item `i` on face `f` (or on none, or several: `f` < 0) of corners `corners`
    * (from [[relativeCorners]]), when it is a triangle on that face: writes its corners' (u, v)
    * there at 7i of `outlines` and its margin at 7i + 6, and narrows its part (at 4i of `parts`:
    * low u, high u, low v, high v) to them; else NaN at 7i.
    *
    * Why exact: a point seen from the light at (x, y, z) relative to it, with a > 0 its coordinate
    * along the face's axis, lies at (y / a, z / a) on the face (for the face's own two axes), so
    * the triangle's points lie in the triangle of its corners' (u, v): central projection keeps
    * straight lines straight. The margin takes [[LightBuffer.Slack]] for the ray's rounding
    * and, for the points the face test may accept up to the box's widening δ off the triangle,
    * 3δ / a over the least a of the corners (a shift δ moves u by at most δ (1 + |u|) / (a − δ),
    * and a ≥ 10δ).
    */
  def outline(
      corners: Array[Double],
      f: Int,
      i: Int,
      parts: Array[Double],
      outlines: Array[Double]
  ): Unit =
    outlines(7 * i) = Double.NaN
    if f >= 0 && !java.lang.Double.isNaN(corners(10 * i)) then
      val a     = f >> 1
      val b     = (a + 1) % 3
      val c     = (a + 2) % 3
      val sign  = if (f & 1) == 1 then -1.0 else 1.0
      val delta = corners(10 * i + 9)
      val a0    = sign * corners(10 * i + a)
      val a1    = sign * corners(10 * i + 3 + a)
      val a2    = sign * corners(10 * i + 6 + a)
      val least = Math.min(a0, Math.min(a1, a2))
      if least > 10 * delta then
        val m     = LightBuffer.Slack + 3 * delta / least
        val u0    = corners(10 * i + b) / a0; val v0     = corners(10 * i + c) / a0
        val u1    = corners(10 * i + 3 + b) / a1; val v1 = corners(10 * i + 3 + c) / a1
        val u2    = corners(10 * i + 6 + b) / a2; val v2 = corners(10 * i + 6 + c) / a2
        val uLow  = Math.max(parts(4 * i), Math.min(u0, Math.min(u1, u2)) - m)
        val uHigh = Math.min(parts(4 * i + 1), Math.max(u0, Math.max(u1, u2)) + m)
        val vLow  = Math.max(parts(4 * i + 2), Math.min(v0, Math.min(v1, v2)) - m)
        val vHigh = Math.min(parts(4 * i + 3), Math.max(v0, Math.max(v1, v2)) + m)
        // Both parts hold every direction that matters, so their overlap does; it is empty only
        // by rounding, and then the box's part stands alone.
        if uLow <= uHigh && vLow <= vHigh then
          parts(4 * i) = uLow; parts(4 * i + 1) = uHigh
          parts(4 * i + 2) = vLow; parts(4 * i + 3) = vHigh
          outlines(7 * i) = u0; outlines(7 * i + 1) = v0
          outlines(7 * i + 2) = u1; outlines(7 * i + 3) = v1
          outlines(7 * i + 4) = u2; outlines(7 * i + 5) = v2
          outlines(7 * i + 6) = m

  /** The cells along v, from `cv0` to `cv1`, that outlined item `i`'s triangle (its outline,
    * widened by its margin) may meet in column `cu` of face `f`: the first in the high 32 bits,
    * the last in the low (none when the first is greater). An item without an outline takes all
    * of them, without a call ([[LightBuffer]]'s `count`, which keeps each answer for its `place`).
    *
    * Why exact: the triangle's part within the column's strip of u (widened by the margin) is a
    * convex polygon whose corners are the triangle's corners inside the strip and the points
    * where its edges cross the strip's two sides, so its v lies between their least and
    * greatest. A crossing's v is computed to within about 4·10⁻¹⁵ (coordinates below 2 in size);
    * the range is widened by the margin and 10⁻¹³, and its cells are found by the lookup's own
    * arithmetic ([[LightBuffer.index]]).
    *
    * Perf: a range a column, not a test a cell: the three edges' test on each cell of the part
    * made the 1280×720 render of mesh-80000 slower as a whole (median 1110 → 1196 ms), this even
    * (1018 → 1023; docs/performance.md, round 32).
    */
  def column(
      outlines: Array[Double],
      i: Int,
      windows: Array[Double],
      sizes: Array[Int],
      f: Int,
      cu: Int,
      cv0: Int,
      cv1: Int
  ): Long =
    val o     = 7 * i
    val m     = outlines(o + 6)
    val nu    = sizes(3 * f)
    val from  = cellEdge(windows(4 * f), windows(4 * f + 2), nu, cu) - m
    val to    = cellEdge(windows(4 * f), windows(4 * f + 2), nu, cu + 1) + m
    var least = Double.PositiveInfinity
    var most  = Double.NegativeInfinity
    var k     = 0
    while k < 6 do
      val u = outlines(o + k)
      val v = outlines(o + k + 1)
      if u >= from && u <= to then
        least = Math.min(least, v); most = Math.max(most, v)
      val n  = if k == 4 then 0 else k + 2
      val un = outlines(o + n)
      val vn = outlines(o + n + 1)
      if u < from && un > from || u > from && un < from then
        val w = crossing(u, v, un, vn, from)
        least = Math.min(least, w); most = Math.max(most, w)
      if u < to && un > to || u > to && un < to then
        val w = crossing(u, v, un, vn, to)
        least = Math.min(least, w); most = Math.max(most, w)
      k += 2
    if !(least <= most) then span(1, 0)
    else
      val nv = sizes(3 * f + 1)
      val lo = LightBuffer.index(least - m - 1e-13, windows(4 * f + 1), windows(4 * f + 3), nv)
      val hi = LightBuffer.index(most + m + 1e-13, windows(4 * f + 1), windows(4 * f + 3), nv)
      span(Math.max(lo, cv0), Math.min(hi, cv1))

  /** The v where the edge from (u, v) to (un, vn) crosses u = x (x strictly between u and un). */
  private inline def crossing(u: Double, v: Double, un: Double, vn: Double, x: Double): Double =
    v + (x - u) / (un - u) * (vn - v)

  /** A range of cells, first and last, as [[column]] answers it. */
  inline def span(first: Int, last: Int): Long =
    (first.toLong << 32) | (last.toLong & 0xffffffffL)

  /** Where cell boundary `k` of a side lies (window from `low`, `scale` cells a unit, `n` cells):
    * the first and last cells reach beyond the face (±2), as the lookup clamps to them.
    */
  private inline def cellEdge(low: Double, scale: Double, n: Int, k: Int): Double =
    if k <= 0 then -2.0 else if k >= n then 2.0 else low + k / scale
