package tracer.geometry

/** Constructive solid geometry's crossings on plain doubles, for [[Kernel]]: the reference's
  * `Combination` rules (each child's crossings kept where the others' inside tests put them on
  * the whole's surface) into a [[CrossingBuffer]], with each child's padded box tested first.
  *
  * Perf: as [[Kernel]]'s, the reference's arithmetic operation for operation on plain doubles,
  * with no allocation (`KernelProperties` compares them bit for bit; `SolidsBench`).
  */
private[geometry] object CsgKernel:

  /** Combination.crossings: each child's crossings kept where the others' inside tests say the
    * point is on the whole's surface (the whole counted `inversions` times inverted:
    * [[Combination.rule]]), normals of subtracted children turned round, leaves renumbered, all
    * sorted by t (stably, children in order). A child whose box the ray misses has no crossings
    * and contains none of the others' ([[reach]]), so it is skipped.
    */
  private[geometry] def combination(
      c: Csg,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int,
      normals: Boolean,
      inversions: Int = Combination.Plain
  ): Int =
    val ix   = 1 / dx
    val iy   = 1 / dy
    val iz   = 1 / dz
    val mask = reach(c, ox, oy, oz, ix, iy, iz, Double.PositiveInfinity)
    if !whole(c, mask, inversions) then from
    else
      // Perf: the children's crossings are written after the kept ones and compacted in place.
      var kept = from
      var i    = 0
      while i < c.parts.length do
        if met(c, mask, i, ox, oy, oz, ix, iy, iz, Double.PositiveInfinity) then
          val flip = Combination.inverts(c, i)
          val end  =
            Kernel.collect(
              c.parts(i),
              ox,
              oy,
              oz,
              dx,
              dy,
              dz,
              buffer,
              kept,
              normals,
              Combination.childInversions(c, i, inversions)
            )
          val first = c.partLeaves(i)
          var k     = kept
          while k < end do
            val t = buffer.t(k)
            if keeps(c, i, mask, ox + dx * t, oy + dy * t, oz + dz * t, inversions) then
              if k != kept then buffer.move(k, kept)
              if flip then
                buffer.nx(kept) = -buffer.nx(kept)
                buffer.ny(kept) = -buffer.ny(kept)
                buffer.nz(kept) = -buffer.nz(kept)
              buffer.leaf(kept) = buffer.leaf(kept) + first
              kept += 1
            k += 1
        i += 1
      buffer.sort(from, kept)
      kept

  /** The first of [[combination]]'s crossings at t ≤ `limit`, written at `from` (returns
    * `from + 1`), or none (returns `from`): each child's crossings in increasing t up to its first
    * kept one or the best so far, so later crossings need no inside tests and nothing is sorted.
    * Of equal ts the first child's wins, as in the stable sort. A kept crossing at t with
    * t / `stretch` < `below` ends the search there ([[Kernel.blocks]]; by default none does).
    */
  private[geometry] def first(
      c: Csg,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int,
      limit: Double,
      normals: Boolean,
      below: Double = Double.NegativeInfinity,
      stretch: Double = 1.0
  ): Int =
    val ix   = 1 / dx
    val iy   = 1 / dy
    val iz   = 1 / dz
    val mask = reach(c, ox, oy, oz, ix, iy, iz, limit)
    if !whole(c, mask, Combination.Plain) then from
    else
      // Perf: the best crossing so far at `from`, each child's crossings after it (SolidsBench).
      var best = Double.PositiveInfinity
      var i    = 0
      while i < c.parts.length do
        // A child entered beyond the best so far cannot hold a nearer crossing (until one is
        // found, the mask, made with the limit, says all there is).
        val bound = if best < limit then best else Double.PositiveInfinity
        if met(c, mask, i, ox, oy, oz, ix, iy, iz, bound) then
          val end = Kernel.collect(
            c.parts(i),
            ox,
            oy,
            oz,
            dx,
            dy,
            dz,
            buffer,
            from + 1,
            normals,
            Combination.childInversions(c, i, Combination.Plain)
          )
          var k = from + 1
          while k < end && buffer.t(k) < best && buffer.t(k) <= limit do
            val t = buffer.t(k)
            if keeps(c, i, mask, ox + dx * t, oy + dy * t, oz + dz * t, Combination.Plain) then
              best = t
              buffer.move(k, from)
              if Combination.inverts(c, i) then
                buffer.nx(from) = -buffer.nx(from)
                buffer.ny(from) = -buffer.ny(from)
                buffer.nz(from) = -buffer.nz(from)
              buffer.leaf(from) = buffer.leaf(from) + c.partLeaves(i)
              k = end
              // A shadow ray's test needs no nearer crossing than one below its limit.
              if t / stretch < below then i = c.parts.length
            else k += 1
        i += 1
      if best < Double.PositiveInfinity then from + 1 else from

  /** Which children's boxes the ray (origin o, inverse direction i) meets at 0 ≤ t ≤ `limit`: bit
    * j set for child j (children from 64 on: always set, tested by [[met]] instead). A child
    * whose box the ray misses has no crossing there, and no point of the ray there is inside it:
    * the boxes are the children's bounds widened by far more than the rounding of a crossing's
    * point or an inside test's tolerance ([[paddedBoxes]]).
    */
  private def reach(
      c: Csg,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      limit: Double
  ): Long =
    // Perf: one box test a child a ray, a bit each, no array (SolidsBench).
    var mask = -1L
    var j    = 0
    val n    = Math.min(64, c.parts.length)
    while j < n do
      if boxEntry(c.partBoxes, 6 * j, ox, oy, oz, ix, iy, iz, limit) == Double.PositiveInfinity
      then mask &= ~(1L << j)
      j += 1
    mask

  /** True when the ray may cross the whole (counted `k` times inverted): always, unless it keeps
    * a child's crossings only inside every other child ([[Combination.rule]]) and a child whose
    * own points count there (every child of an intersection, the first of a difference, none of
    * an inverted union's) is missed.
    */
  private inline def whole(c: Csg, mask: Long, k: Int): Boolean =
    Combination.rule(c, k) != Combination.KeepInsideOthers || (c.operation match
      case CsgOperation.Union        => true
      case CsgOperation.Intersection => mask == -1L
      case CsgOperation.Difference   => (mask & 1L) != 0)

  /** Child `i` may have crossings at t ≤ `limit`: its bit of `mask` (from [[reach]] with a limit
    * at least this one), and its box entered by then when the limit is lower or `i` ≥ 64.
    */
  private inline def met(
      c: Csg,
      mask: Long,
      i: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      limit: Double
  ): Boolean =
    (i >= 64 || (mask & (1L << i)) != 0) &&
      (i < 64 && limit == Double.PositiveInfinity ||
        boxEntry(c.partBoxes, 6 * i, ox, oy, oz, ix, iy, iz, limit) < Double.PositiveInfinity)

  /** Combination.keeps: a crossing of child `i` at p is on the surface of the whole, counted `k`
    * times inverted; a child whose bit in `mask` is clear does not contain p.
    */
  private def keeps(
      c: Csg,
      i: Int,
      mask: Long,
      px: Double,
      py: Double,
      pz: Double,
      k: Int
  ): Boolean =
    val rule = Combination.rule(c, k)
    rule == Combination.KeepAll ||
    others(c, i, mask, px, py, pz, k, inside = rule == Combination.KeepInsideOthers)

  /** True when p's inside test of every child but `i` is `inside`, each child counted as
    * [[Combination.childInversions]] says (its complement's test when that is odd). A child whose
    * bit in `mask` is clear does not contain p: unless it holds a triangle, p is then inside its
    * complement only, and it is not tested.
    */
  private def others(
      c: Csg,
      i: Int,
      mask: Long,
      px: Double,
      py: Double,
      pz: Double,
      k: Int,
      inside: Boolean
  ): Boolean =
    // Why: a plain loop over the children's array (SolidsBench).
    val oddWhole = k == Combination.Inverted
    var j        = 0
    while j < c.parts.length && (j == i || {
        val odd = Combination.inverts(c, j) != oddWhole
        val in  =
          if j < 64 && ((mask | c.patchParts) & (1L << j)) == 0 then odd
          else if odd then Kernel.insideComplement(c.parts(j), px, py, pz)
          else Kernel.inside(c.parts(j), px, py, pz)
        in == inside
      })
    do j += 1
    j == c.parts.length

  /** The distance at which the ray (origin o, inverse direction i) enters the box of six doubles
    * at `b` of `boxes`, or +∞ when it misses it at 0 ≤ t ≤ `limit` (Bvh.entry's slab test).
    */
  private[geometry] inline def boxEntry(
      boxes: Array[Double],
      b: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      limit: Double
  ): Double =
    // Perf: local doubles narrowed in place; a NaN (an origin on a plane of a slab it runs
    // along) narrows nothing, so such a ray counts as inside that slab.
    var tmin = 0.0
    var tmax = limit
    val ax   = (boxes(b) - ox) * ix
    val bx   = (boxes(b + 3) - ox) * ix
    if ix >= 0 then
      if ax > tmin then tmin = ax
      if bx < tmax then tmax = bx
    else
      if bx > tmin then tmin = bx
      if ax < tmax then tmax = ax
    val ay = (boxes(b + 1) - oy) * iy
    val by = (boxes(b + 4) - oy) * iy
    if iy >= 0 then
      if ay > tmin then tmin = ay
      if by < tmax then tmax = by
    else
      if by > tmin then tmin = by
      if ay < tmax then tmax = ay
    val az = (boxes(b + 2) - oz) * iz
    val bz = (boxes(b + 5) - oz) * iz
    if iz >= 0 then
      if az > tmin then tmin = az
      if bz < tmax then tmax = bz
    else
      if bz > tmin then tmin = bz
      if az < tmax then tmax = az
    if tmin <= tmax then tmin else Double.PositiveInfinity

  /** The children's boxes for [[Csg.partBoxes]]: [[Shape.bounds]] widened on every side by 10⁻⁷
    * of its largest coordinate and extent, or ±∞ for an unbounded child.
    */
  private[geometry] def paddedBoxes(parts: Array[Shape]): Array[Double] =
    val out = new Array[Double](6 * parts.length)
    parts.indices.foreach { i =>
      Shape.bounds(parts(i)) match
        case Some(b) =>
          val coords = Seq(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z)
          val extent = Seq(b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z).map(Math.abs).max
          val pad    = 1e-7 * (coords.map(Math.abs).max + extent) + Double.MinPositiveValue
          out(6 * i) = b.lo.x - pad; out(6 * i + 1) = b.lo.y - pad; out(6 * i + 2) = b.lo.z - pad
          out(6 * i + 3) = b.hi.x + pad; out(6 * i + 4) = b.hi.y + pad
          out(6 * i + 5) = b.hi.z + pad
        case None =>
          out(6 * i) = Double.NegativeInfinity; out(6 * i + 1) = Double.NegativeInfinity
          out(6 * i + 2) = Double.NegativeInfinity; out(6 * i + 3) = Double.PositiveInfinity
          out(6 * i + 4) = Double.PositiveInfinity; out(6 * i + 5) = Double.PositiveInfinity
    }
    out
