package tracer.render

/** The steps of a walk down a [[WideTree]], shared by the scene's [[Bvh]] and each mesh's
  * [[MeshTree]]: all `inline`, so each walk is compiled as if written out in place.
  */
private[render] object WideWalk:

  /** Runs `body` on the ray's inverse direction and, per axis, the offset (0 or 3) of a box's
    * near corner within its six coordinates.
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

  /** The ordered nearest-hit walk of a wide tree (boxes `wb`, children `wc`, counts `wn`; `empty`
    * for a tree of no nodes) for the ray from (ox, oy, oz) with inverse direction (ix, iy, iz)
    * and near corners (sx, sy, sz) (see [[walk]]), on the scratch `stack` and `entries`: every
    * leaf entered at a distance ≤ the best so far (from `limit` on) has each of its primitives k
    * passed to `leaf(k, best)`, which returns the new best distance. Returns the last best.
    *
    * Perf: shared by [[Bvh.nearest]] and [[MeshTree.nearest]], which differ only in the leaf:
    * `inline` with an inline leaf, so each is compiled as if written out in place (the same
    * bytecode as the two copies it replaced; docs/performance.md, round 8).
    */
  inline def nearest(
      wb: Array[Float],
      wc: Array[Int],
      wn: Array[Int],
      empty: Boolean,
      stack: Array[Int],
      entries: Array[Double],
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double
  )(inline leaf: (Int, Double) => Double): Double =
    // Perf: the 4-wide tree, ordered: a node's four child boxes are tested together, the ones hit
    // pushed farthest first with their entry distances, so the nearest is walked next and a
    // popped slot beyond the best hit is dropped untested (docs/performance.md, round 5).
    // Why: the best distance so far, narrowed by the leaves.
    var bestT = limit
    // Why: the stack's size, moved by the pops and pushes below.
    var sp =
      if empty then 0
      else push(wb, wn, 0, 0, stack, entries, ox, oy, oz, ix, iy, iz, sx, sy, sz, bestT, true)
    // Perf: the walk's loop on the scratch stack: no recursion, no allocation.
    while sp > 0 do
      sp -= 1
      val slot = stack(sp)
      // A slot entered beyond the best hit so far cannot hold a nearer one (ties still count).
      if entries(sp) <= bestT then
        val count = wn(slot)
        if count > 0 then
          // Why: the leaf's primitives, one by one.
          var k   = wc(slot)
          val end = k + count
          // Perf: a plain loop over the leaf's range.
          while k < end do
            bestT = leaf(k, bestT)
            k += 1
        else
          sp = push(
            wb,
            wn,
            wc(slot),
            sp,
            stack,
            entries,
            ox,
            oy,
            oz,
            ix,
            iy,
            iz,
            sx,
            sy,
            sz,
            bestT,
            true
          )
    bestT

  /** The any-hit walk of a wide tree's node `root` and the nodes below it (as [[nearest]]'s
    * arguments, `limit` the ray's end; `root` 0 for the whole tree): true as soon as `leaf(slot, k)` says primitive k of the leaf at `slot` that the ray enters blocks
    * it.
    *
    * Perf: shared by [[Bvh.occluded]] and [[MeshTree.occluded]], as [[nearest]]; unordered (any
    * hit will do) with an early exit.
    */
  inline def any(
      wb: Array[Float],
      wc: Array[Int],
      wn: Array[Int],
      empty: Boolean,
      root: Int,
      stack: Array[Int],
      entries: Array[Double],
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double
  )(inline leaf: (Int, Int) => Boolean): Boolean =
    // Why: set by the first leaf primitive that blocks the ray, which ends the walk.
    var hit = false
    // Why: the stack's size, moved by the pops and pushes below.
    var sp =
      if empty then 0
      else push(wb, wn, root, 0, stack, entries, ox, oy, oz, ix, iy, iz, sx, sy, sz, limit, false)
    // Perf: the walk's loop on the scratch stack, stopping at the first blocker.
    while sp > 0 && !hit do
      sp -= 1
      val slot  = stack(sp)
      val count = wn(slot)
      if count > 0 then
        // Why: the leaf's primitives, one by one.
        var k   = wc(slot)
        val end = k + count
        // Perf: a plain loop over the leaf's range, stopping at the first blocker.
        while k < end && !hit do
          hit = leaf(slot, k)
          k += 1
      else
        sp = push(
          wb,
          wn,
          wc(slot),
          sp,
          stack,
          entries,
          ox,
          oy,
          oz,
          ix,
          iy,
          iz,
          sx,
          sy,
          sz,
          limit,
          false
        )
    hit

  /** Pushes the slots of wide node `node` (boxes `wb`, counts `wn`) whose boxes the ray enters
    * before `limit` onto the stack above `sp`, with their entry distances; `ordered`: the
    * farthest first, so the nearest is popped next. Returns the new stack size.
    */
  inline def push(
      wb: Array[Float],
      wn: Array[Int],
      node: Int,
      sp: Int,
      stack: Array[Int],
      entries: Array[Double],
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double,
      inline ordered: Boolean
  ): Int =
    // Why: the stack top moves as slots are pushed; an insertion sort keeps them farthest first.
    var top = sp
    var c   = 0
    while c < WideTree.Width do
      val slot = WideTree.Width * node + c
      if wn(slot) >= 0 then
        val t = entry(wb, 24 * node + c, ox, oy, oz, ix, iy, iz, sx, sy, sz, limit)
        if t < Double.PositiveInfinity then
          var j = top
          if ordered then
            while j > sp && entries(j - 1) < t do
              stack(j) = stack(j - 1); entries(j) = entries(j - 1)
              j -= 1
          stack(j) = slot; entries(j) = t
          top += 1
      c += 1
    top

  /** The distance at which the ray enters the float box at `b` of `wb` (a child's low x; its
    * other coordinates 4 floats apart), or +∞ when it misses it before `limit`: the slab test on
    * the float box widened to double (exactly), near planes chosen by `sx` etc. (0 for the low
    * side, 3 for the high: 4 × that floats on).
    */
  inline def entry(
      wb: Array[Float],
      b: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double
  ): Double =
    // Perf: on four floats apart: no box object, local doubles narrowed in place.
    var tmin = 0.0
    var tmax = limit
    val nx   = (wb(b + 4 * sx).toDouble - ox) * ix
    val fx   = (wb(b + 12 - 4 * sx).toDouble - ox) * ix
    if nx > tmin then tmin = nx
    if fx < tmax then tmax = fx
    val ny = (wb(b + 4 + 4 * sy).toDouble - oy) * iy
    val fy = (wb(b + 16 - 4 * sy).toDouble - oy) * iy
    if ny > tmin then tmin = ny
    if fy < tmax then tmax = fy
    val nz = (wb(b + 8 + 4 * sz).toDouble - oz) * iz
    val fz = (wb(b + 20 - 4 * sz).toDouble - oz) * iz
    if nz > tmin then tmin = nz
    if fz < tmax then tmax = fz
    if tmin <= tmax then tmin else Double.PositiveInfinity
