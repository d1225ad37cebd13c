package tracer.geometry

/** A cone's (and a cylinder's) crossings and nearest distance on plain doubles, for [[Kernel]]:
  * the side's quadratic and the two discs of the reference's `Solids.coneCrossings`, bit for bit.
  *
  * Perf: as [[Kernel]]'s, the reference's arithmetic operation for operation on plain doubles,
  * with no allocation (`KernelProperties` compares them bit for bit; `SolidsBench`).
  */
private[geometry] object ConeKernel:

  /** Solids.coneCrossings: the side's quadratic and, unless open, the two discs, sorted by t. */
  private[geometry] def cone(
      c: Cone,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int,
      normals: Boolean
  ): Int =
    coneRoots(c, ox, oy, oz, dx, dy, dz) { (roots, r1, r2, wa, da, wx, wy, wz) =>
      // Why: the crossings written so far.
      var end = from
      if roots >= 1 then end = coneSide(c, r1, wa, da, wx, wy, wz, dx, dy, dz, buffer, end, normals)
      if roots == 2 then end = coneSide(c, r2, wa, da, wx, wy, wz, dx, dy, dz, buffer, end, normals)
      if !c.open && da != 0 then
        end = coneDisc(0.0, c.baseRadius, -1.0, c, wa, da, wx, wy, wz, dx, dy, dz, buffer, end)
        end = coneDisc(c.height, c.capRadius, 1.0, c, wa, da, wx, wy, wz, dx, dy, dz, buffer, end)
      buffer.sort(from, end)
      end
    }

  /** The first of [[cone]]'s crossings' ts, or +∞: the least t of the side's roots on the frustum
    * and the discs met (Perf: no buffer, no sort, for a distance; SolidsBench).
    */
  private[geometry] def coneDistance(
      c: Cone,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    coneRoots(c, ox, oy, oz, dx, dy, dz) { (roots, r1, r2, wa, da, wx, wy, wz) =>
      // Why: the least t so far; the roots come in increasing order, so the first on the side wins.
      var best = Double.PositiveInfinity
      if roots >= 1 && onSide(c, r1, wa, da) then best = r1
      else if roots == 2 && onSide(c, r2, wa, da) then best = r2
      if !c.open && da != 0 then
        val base = discT(0.0, c.baseRadius, c, wa, da, wx, wy, wz, dx, dy, dz)
        if base < best then best = base
        val cap = discT(c.height, c.capRadius, c, wa, da, wx, wy, wz, dx, dy, dz)
        if cap < best then best = cap
      best
    }

  /** Runs `body` on the real roots of the cone's quadratic (their number, 0 to 2, and the roots in
    * increasing order) with the ray's origin w from the base and its heights along the axis: wa
    * of the origin, da of the direction.
    *
    * Perf: `inline` with an inline body: the values stay local doubles (as Bvh.walk). For an axis
    * along x, y or z ([[Cone.axial]]) the products with its zero coordinates are left out, which
    * changes no root (below).
    */
  private inline def coneRoots[A](
      c: Cone,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  )(inline body: (Int, Double, Double, Double, Double, Double, Double, Double) => A): A =
    val wx = ox - c.base.x; val wy = oy - c.base.y; val wz = oz - c.base.z
    val k  = shortcut(c, wx, wy, wz)
    if k < 0 then
      val ax  = c.axis.x; val ay      = c.axis.y; val az      = c.axis.z
      val wa  = wx * ax + wy * ay + wz * az
      val da  = dx * ax + dy * ay + dz * az
      val wrx = wx - ax * wa; val wry = wy - ay * wa; val wrz = wz - az * wa
      val drx = dx - ax * da; val dry = dy - ay * da; val drz = dz - az * da
      quadratic(c, wa, da, wx, wy, wz)(
        drx * drx + dry * dry + drz * drz,
        wrx * drx + wry * dry + wrz * drz,
        wrx * wrx + wry * wry + wrz * wrz
      )(body)
    else
      // Why exact: with the axis s·e_k (s = ±1, the rest 0) and w finite, the general arithmetic
      // above gives wa = s·w_k and da = s·d_k, and w's and d's parts across the axis (w_u, w_v) and (d_u, d_v)
      // with 0 at k, all equal as numbers (a product with 0 is ±0, which adds nothing to a
      // non-zero; only zeros' signs may differ). Its sums of squares have the same bits (a square
      // is never −0, so the term at k adds +0; the others come in the same order); its sum of
      // products, b, may differ only in a zero's sign, which no step below tells apart (b != 0,
      // b · b, b >= 0, and b + root). And a, q and both roots are the same bits, as are the
      // checks on wa and da the callers make (comparisons, z − wa, da != 0).
      val s  = along(k, c.axis.x, c.axis.y, c.axis.z)
      val wa = s * along(k, wx, wy, wz)
      val da = s * along(k, dx, dy, dz)
      across(k, wx, wy, wz) { (wu, wv) =>
        across(k, dx, dy, dz) { (du, dv) =>
          quadratic(c, wa, da, wx, wy, wz)(du * du + dv * dv, wu * du + wv * dv, wu * wu + wv * wv)(
            body
          )
        }
      }

  /** The axis's index ([[Cone.axial]]) when the shortcut that leaves out the products with its
    * zero coordinates applies to the offset w from the base, else −1: also when w overflows, where
    * the general arithmetic's 0 · ∞ gives NaN (and so no crossing, and not inside).
    */
  private[geometry] inline def shortcut(c: Cone, wx: Double, wy: Double, wz: Double): Int =
    if Math.abs(wx) + Math.abs(wy) + Math.abs(wz) < Double.PositiveInfinity then c.axial else -1

  /** Coordinate `k` (0, 1 or 2) of (x, y, z). */
  private[geometry] inline def along(k: Int, x: Double, y: Double, z: Double): Double =
    if k == 0 then x else if k == 1 then y else z

  /** Runs `body` on the two coordinates of (x, y, z) across axis `k`, in x, y, z order. */
  private[geometry] inline def across[A](k: Int, x: Double, y: Double, z: Double)(
      inline body: (Double, Double) => A
  ): A =
    body(if k == 0 then y else x, if k == 2 then y else z)

  /** [[coneRoots]]' quadratic, given the squared length of d across the axis (`dd`), the product
    * of w's and d's parts across it (`wd`) and the squared length of w's (`ww`).
    */
  private inline def quadratic[A](
      c: Cone,
      wa: Double,
      da: Double,
      wx: Double,
      wy: Double,
      wz: Double
  )(dd: Double, wd: Double, ww: Double)(
      inline body: (Int, Double, Double, Double, Double, Double, Double, Double) => A
  ): A =
    val k  = c.slope
    val rO = c.baseRadius + k * wa
    val a  = dd - k * k * da * da
    val b  = 2 * (wd - k * rO * da)
    val q  = ww - rO * rO
    // The quadratic's real roots in increasing order (Solids.quadratic).
    // Why: zero, one or two roots, set by the branches below.
    var roots = 0
    // Why: as roots.
    var r1 = 0.0
    // Why: as roots.
    var r2 = 0.0
    if a == 0 then
      if b != 0 then
        roots = 1; r1 = -q / b
    else
      val disc = b * b - 4 * a * q
      if disc >= 0 then
        val root = Math.sqrt(disc)
        val m    = -0.5 * (b + (if b >= 0 then root else -root))
        val x1   = if m == 0 then 0.0 else m / a
        val x2   = if m == 0 then 0.0 else q / m
        roots = 2
        if x1 <= x2 then
          r1 = x1; r2 = x2
        else
          r1 = x2; r2 = x1
    body(roots, r1, r2, wa, da, wx, wy, wz)

  /** A root t of the cone's quadratic lies on the frustum, at t > 0. */
  private inline def onSide(c: Cone, t: Double, wa: Double, da: Double): Boolean =
    val z = wa + t * da
    t > 0 && z >= 0 && z <= c.height && c.baseRadius + c.slope * z >= 0

  /** A root of the cone's quadratic as a crossing of its side, if it lies on the frustum. */
  private def coneSide(
      c: Cone,
      t: Double,
      wa: Double,
      da: Double,
      wx: Double,
      wy: Double,
      wz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      k: Int,
      normals: Boolean
  ): Int =
    if !onSide(c, t, wa, da) then k
    else if !normals then
      buffer.put(k, t, 0, 0, 0, 0)
      k + 1
    else
      val ax = c.axis.x; val ay     = c.axis.y; val az     = c.axis.z
      val px = wx + dx * t; val py  = wy + dy * t; val pz  = wz + dz * t
      val pa = px * ax + py * ay + pz * az
      val rx = px - ax * pa; val ry = py - ay * pa; val rz = pz - az * pa
      val f  = (c.baseRadius + c.slope * pa) * c.slope
      val nx = rx - ax * f; val ny  = ry - ay * f; val nz  = rz - az * f
      val l  = Math.sqrt(nx * nx + ny * ny + nz * nz)
      if l > 0 && l < Double.PositiveInfinity then buffer.put(k, t, nx / l, ny / l, nz / l, 0)
      else buffer.put(k, t, ax, ay, az, 0)
      k + 1

  /** A cone's disc at height `z` along the axis as a crossing, if the ray meets it inside. */
  private def coneDisc(
      z: Double,
      radius: Double,
      side: Double,
      c: Cone,
      wa: Double,
      da: Double,
      wx: Double,
      wy: Double,
      wz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      k: Int
  ): Int =
    val t = discT(z, radius, c, wa, da, wx, wy, wz, dx, dy, dz)
    if t == Double.PositiveInfinity then k
    else
      // The reference's -axis for the base (negative zeros included), axis for the cap.
      val a = c.axis
      if side < 0 then buffer.put(k, t, -a.x, -a.y, -a.z, 0) else buffer.put(k, t, a.x, a.y, a.z, 0)
      k + 1

  /** Where the ray meets a cone's disc at height `z` along the axis inside its radius, at t > 0,
    * or +∞.
    */
  private inline def discT(
      z: Double,
      radius: Double,
      c: Cone,
      wa: Double,
      da: Double,
      wx: Double,
      wy: Double,
      wz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val ax = c.axis.x; val ay             = c.axis.y; val az             = c.axis.z
    val t  = (z - wa) / da
    val px = wx + dx * t - ax * z; val py = wy + dy * t - ay * z; val pz = wz + dz * t - az * z
    if t > 0 && radius > 0 && px * px + py * py + pz * pz <= radius * radius then t
    else Double.PositiveInfinity
