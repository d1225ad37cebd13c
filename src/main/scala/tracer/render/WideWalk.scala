package tracer.render

/** The steps of a walk down a [[WideTree]], shared by the scene's [[Bvh]] and each mesh's
  * [[MeshTree]]: all `inline`, so each walk is compiled as if written out in place. Its box test
  * is in float ([[walkFloat]], [[entryFloat]]) and may only err towards entering a box.
  */
private[render] object WideWalk:

  /** Runs `body` on the ray's inverse direction and, per axis, the offset (0 or 3) of a box's
    * near corner within its six coordinates (the binary walks' double slab test, `Bvh.entry`).
    *
    * Perf: `inline` with an inline function: the lambda's body is spliced in, so there is no tuple
    * or object to allocate (a tuple of doubles is boxed) and no call.
    */
  inline def walk[A](dx: Double, dy: Double, dz: Double)(
      inline body: (Double, Double, Double, Int, Int, Int) => A
  ): A =
    val ix = 1 / dx
    val iy = 1 / dy
    val iz = 1 / dz
    body(
      ix,
      iy,
      iz,
      if ix >= 0 then 0 else 3,
      if iy >= 0 then 0 else 3,
      if iz >= 0 then 0 else 3
    )

  /** The largest magnitude of a direction component's reciprocal the float slab test takes on
    * an axis: past it (a ray all but parallel to that axis's planes) the axis is left out of the
    * test, which then only ever enters more boxes.
    */
  inline val MaxInverse = 1099511627776.0 // 2^40

  /** The slack of the float slab test: 2^-20 of the largest magnitude it computes with, sixteen
    * times the float rounding of each of its steps (see [[walkFloat]]).
    */
  inline val Slack = 9.5367431640625e-7 // 2^-20

  /** The largest magnitude of a finite coordinate of the boxes `wb` (0 for none): the bound
    * [[walkFloat]] widens its test by.
    */
  def bound(wb: Array[Float]): Double =
    // Perf: one pass over the boxes when a tree is made.
    var m = 0.0
    var i = 0
    while i < wb.length do
      val a = Math.abs(wb(i).toDouble)
      if a < Double.PositiveInfinity && a > m then m = a
      i += 1
    m

  /** Runs `body` on the ray's constants for the float slab test ([[entryFloat]]): per axis the
    * reciprocal of the direction as a float and the negated offsets for near and far planes, then
    * per axis the offset (0 or 3) of a box's near corner within its six coordinates. `bound` is
    * the tree's [[bound]].
    *
    * The test computes a plane's distance as `fma(b, 1/d, -o/d ∓ e)`, in float, in place of
    * `(b - o) / d` in double: one instruction a plane, and no widening of the float box. Each of
    * its three roundings (1/d, the offset, the fma) is at most 2^-24 of M = (bound + |o|)·|1/d|,
    * and so is the double test's own, so with e = 2^-20·M every near plane comes out nearer and
    * every far plane farther than the double test puts them: the float test enters every box the
    * double one enters, with an entry distance no larger (a box test may only err towards
    * entering; the leaves still test the exact primitives, so the answers are the same bit for
    * bit). An axis with |1/d| > 2^40 is left out (it could overflow or lose the slack), and so
    * is one whose offsets are not finite.
    */
  inline def walkFloat[A](
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      bound: Double
  )(
      inline body: (
          Float,
          Float,
          Float,
          Float,
          Float,
          Float,
          Float,
          Float,
          Float,
          Int,
          Int,
          Int
      ) => A
  ): A =
    val ix  = 1 / dx
    val iy  = 1 / dy
    val iz  = 1 / dz
    val ex  = (bound + Math.abs(ox)) * Math.abs(ix) * Slack
    val ey  = (bound + Math.abs(oy)) * Math.abs(iy) * Slack
    val ez  = (bound + Math.abs(oz)) * Math.abs(iz) * Slack
    val okx = Math.abs(ix) <= MaxInverse && ex < 1e30
    val oky = Math.abs(iy) <= MaxInverse && ey < 1e30
    val okz = Math.abs(iz) <= MaxInverse && ez < 1e30
    body(
      if okx then ix.toFloat else 0f,
      if oky then iy.toFloat else 0f,
      if okz then iz.toFloat else 0f,
      if okx then (-(ox * ix) - ex).toFloat else Float.NegativeInfinity,
      if oky then (-(oy * iy) - ey).toFloat else Float.NegativeInfinity,
      if okz then (-(oz * iz) - ez).toFloat else Float.NegativeInfinity,
      if okx then (-(ox * ix) + ex).toFloat else Float.PositiveInfinity,
      if oky then (-(oy * iy) + ey).toFloat else Float.PositiveInfinity,
      if okz then (-(oz * iz) + ez).toFloat else Float.PositiveInfinity,
      if ix >= 0 then 0 else 3,
      if iy >= 0 then 0 else 3,
      if iz >= 0 then 0 else 3
    )

  /** The smallest float at or above `x` (+∞ stays). */
  inline def floatAbove(x: Double): Float =
    val f = x.toFloat
    if f.toDouble < x then Math.nextUp(f) else f

  /** Pushes the slots of wide node `node` (boxes `wb`, counts `wn`) whose boxes the ray enters
    * before `limit` onto the stack above `sp`, with their entry distances; `ordered`: the
    * farthest first, so the nearest is popped next. Returns the new stack size. The ray is
    * [[walkFloat]]'s constants, each box tested by [[entryFloat]]: the four tests written out one
    * after the other (straight-line code the compiler can interleave), then the ones hit pushed.
    */
  inline def pushFloat(
      wb: Array[Float],
      wn: Array[Int],
      node: Int,
      sp: Int,
      stack: Array[Int],
      entries: Array[Double],
      ix: Float,
      iy: Float,
      iz: Float,
      nx: Float,
      ny: Float,
      nz: Float,
      fx: Float,
      fy: Float,
      fz: Float,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double,
      inline ordered: Boolean
  ): Int =
    val lim  = floatAbove(limit)
    val b    = 24 * node
    val t0   = entryFloat(wb, b, ix, iy, iz, nx, ny, nz, fx, fy, fz, sx, sy, sz, lim)
    val t1   = entryFloat(wb, b + 1, ix, iy, iz, nx, ny, nz, fx, fy, fz, sx, sy, sz, lim)
    val t2   = entryFloat(wb, b + 2, ix, iy, iz, nx, ny, nz, fx, fy, fz, sx, sy, sz, lim)
    val t3   = entryFloat(wb, b + 3, ix, iy, iz, nx, ny, nz, fx, fy, fz, sx, sy, sz, lim)
    val slot = WideTree.Width * node
    val top0 = place(t0, slot, wn, sp, sp, stack, entries, ordered)
    val top1 = place(t1, slot + 1, wn, sp, top0, stack, entries, ordered)
    val top2 = place(t2, slot + 2, wn, sp, top1, stack, entries, ordered)
    place(t3, slot + 3, wn, sp, top2, stack, entries, ordered)

  /** Pushes `slot`, entered at `t` (+∞: missed, not pushed), onto the stack of `top` slots whose
    * part above `sp` is this node's; `ordered`: kept farthest first. Returns the new size.
    */
  inline def place(
      t: Float,
      slot: Int,
      wn: Array[Int],
      sp: Int,
      top: Int,
      stack: Array[Int],
      entries: Array[Double],
      inline ordered: Boolean
  ): Int =
    if t < Float.PositiveInfinity && wn(slot) >= 0 then
      val e = t.toDouble
      // Why: an insertion sort's cursor over this node's slots.
      var j = top
      if ordered then
        while j > sp && entries(j - 1) < e do
          stack(j) = stack(j - 1); entries(j) = entries(j - 1)
          j -= 1
      stack(j) = slot; entries(j) = e
      top + 1
    else top

  /** The float slab test ([[walkFloat]] says why it enters every box the double one does): the
    * distance at which the ray enters the box at `b` of `wb` (a child's low x; its other
    * coordinates 4 floats apart), or +∞ when it misses it before `limit`.
    */
  inline def entryFloat(
      wb: Array[Float],
      b: Int,
      ix: Float,
      iy: Float,
      iz: Float,
      nx: Float,
      ny: Float,
      nz: Float,
      fx: Float,
      fy: Float,
      fz: Float,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Float
  ): Float =
    // Perf: one fma a plane on floats, narrowed in place (WorldBench).
    var tmin = 0f
    var tmax = limit
    val ax   = Math.fma(wb(b + 4 * sx), ix, nx)
    val bx   = Math.fma(wb(b + 12 - 4 * sx), ix, fx)
    if ax > tmin then tmin = ax
    if bx < tmax then tmax = bx
    val ay = Math.fma(wb(b + 4 + 4 * sy), iy, ny)
    val by = Math.fma(wb(b + 16 - 4 * sy), iy, fy)
    if ay > tmin then tmin = ay
    if by < tmax then tmax = by
    val az = Math.fma(wb(b + 8 + 4 * sz), iz, nz)
    val bz = Math.fma(wb(b + 20 - 4 * sz), iz, fz)
    if az > tmin then tmin = az
    if bz < tmax then tmax = bz
    if tmin <= tmax then tmin else Float.PositiveInfinity
