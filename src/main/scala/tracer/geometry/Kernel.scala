package tracer.geometry

/** A thread's scratch space for the [[Kernel]]'s crossings: parallel arrays of t, the outward
  * normal's three components and the leaf (the interval lists of pbrt's and the Ray Tracer
  * Challenge's CSG), grown when a deep combination needs more, and the root finder's scratch.
  * Not thread-safe: each render task has its own (`tracer.render.Query`), and [[Shape.hitAt]]
  * one per thread.
  */
final class CrossingBuffer:
  // Why: scratch arrays, reused by every query of one thread and grown (rarely) in place.
  private[geometry] var t: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var nx: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var ny: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var nz: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var leaf: Array[Int] = new Array[Int](CrossingBuffer.Initial)

  /** The root finder's scratch: four levels of coefficients, roots and ends (Polynomial). */
  private[geometry] val roots = new Array[Double](Polynomial.ScratchSize)

  /** The distance t of crossing `k`, as [[Kernel.collect]] wrote it. */
  def distanceAt(k: Int): Double = t(k)

  /** The leaf of crossing `k` (see [[Hit.leaf]]), as [[Kernel.collect]] wrote it. */
  def leafAt(k: Int): Int = leaf(k)

  /** Room for crossings up to index `n` (exclusive). */
  private[geometry] def ensure(n: Int): Unit =
    if n > t.length then
      val size = Math.max(n, 2 * t.length)
      t = java.util.Arrays.copyOf(t, size)
      nx = java.util.Arrays.copyOf(nx, size)
      ny = java.util.Arrays.copyOf(ny, size)
      nz = java.util.Arrays.copyOf(nz, size)
      leaf = java.util.Arrays.copyOf(leaf, size)

  /** Writes crossing `k`. */
  private[geometry] inline def put(
      k: Int,
      at: Double,
      x: Double,
      y: Double,
      z: Double,
      l: Int
  ): Unit =
    ensure(k + 1)
    t(k) = at; nx(k) = x; ny(k) = y; nz(k) = z; leaf(k) = l

  /** Copies crossing `from` to `to`. */
  private[geometry] def move(from: Int, to: Int): Unit =
    t(to) = t(from); nx(to) = nx(from); ny(to) = ny(from); nz(to) = nz(from)
    leaf(to) = leaf(from)

  /** Sorts crossings `from until end` by t, stably (as `List.sortBy` does): insertion sort, for
    * the handful a combination gives.
    */
  private[geometry] def sort(from: Int, end: Int): Unit =
    // Perf: an insertion sort on the parallel arrays, no Crossing objects (SolidsBench).
    var i = from + 1
    while i < end do
      val ti = t(i); val xi = nx(i); val yi = ny(i); val zi = nz(i); val li = leaf(i)
      // Why: the hole moves left past every strictly greater t, which keeps equal ts in order.
      var j = i - 1
      while j >= from && t(j) > ti do
        move(j, j + 1)
        j -= 1
      t(j + 1) = ti; nx(j + 1) = xi; ny(j + 1) = yi; nz(j + 1) = zi; leaf(j + 1) = li
      i += 1

/** Sizes of [[CrossingBuffer]]. */
object CrossingBuffer:
  /** Crossings a buffer holds before it grows. */
  val Initial: Int = 32

/** The solids' and combinations' ray tests on plain doubles, into a [[CrossingBuffer]]: the fast
  * path behind [[Shape.distance]], [[Shape.crossings]] and [[Shape.inside]] for version 3's
  * shapes, which stay the reference.
  *
  * Perf: every function here repeats the reference's arithmetic operation for operation, in the
  * same order on the same values, so the distances, normals and leaves are the same bit for bit
  * (`KernelProperties` compares them on random shapes and rays; `BvhProperties` compares the
  * tree that uses them with testing every shape), but makes no `Vec3`, `Ray`, `Crossing`, list,
  * tuple or option: the reference allocated about 300 young collections in one render of the
  * gallery's solids (docs/performance.md, round 5; `SolidsBench`).
  */
object Kernel:

  /** Each thread's buffer for [[Shape.hitAt]], which has no query to carry one. */
  private[geometry] val scratch: ThreadLocal[CrossingBuffer] =
    ThreadLocal.withInitial(() => CrossingBuffer())

  /** [[Shape.distance]] of `shape` along the ray from (ox, oy, oz) in unit direction
    * (dx, dy, dz), bit for bit, when that distance is at most `cutoff`: the nearest t > 0, or +∞.
    * A shape farther than `cutoff` may be reported at any distance beyond it (+∞ or its own), so
    * a caller that keeps only hits up to the cutoff (the hierarchy's best so far, a shadow ray's
    * reach) gets the reference's answer (Perf: a combination stops at its first crossing).
    */
  def distance(
      shape: Shape,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      cutoff: Double = Double.PositiveInfinity
  ): Double = shape match
    case s: Sphere   => sphereDistance(s, ox, oy, oz, dx, dy, dz)
    case p: Plane    => planeDistance(p, ox, oy, oz, dx, dy, dz)
    case t: Triangle => triangleDistance(t, ox, oy, oz, dx, dy, dz)
    case m: Mesh     =>
      // Perf: every face on the mesh's arrays, as the reference's fold of `min` (a mesh inside a
      // combination; at the top of a scene a mesh has a tree of its own, render.MeshTree).
      var best = Double.PositiveInfinity
      var f    = 0
      while f < m.faceCount do
        best = Math.min(best, Mesh.distanceTo(m, f, best, ox, oy, oz, dx, dy, dz))
        f += 1
      best
    case c: Csg if c.operation == CsgOperation.Union =>
      // Perf: the reference's foldLeft of `min`, as a loop; a child whose box the ray misses, or
      // enters beyond the best so far, cannot lower it (SolidsBench).
      val ix   = 1 / dx
      val iy   = 1 / dy
      val iz   = 1 / dz
      var best = Double.PositiveInfinity
      var i    = 0
      while i < c.parts.length do
        val limit = Math.min(best, cutoff)
        if boxEntry(c.partBoxes, 6 * i, ox, oy, oz, ix, iy, iz, limit) < Double.PositiveInfinity
        then best = Math.min(best, distance(c.parts(i), ox, oy, oz, dx, dy, dz, buffer, limit))
        i += 1
      best
    case p: Placed =>
      ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
        distance(p.shape, lox, loy, loz, ldx, ldy, ldz, buffer, within(cutoff, s)) / s
      }
    case c: Cone => coneDistance(c, ox, oy, oz, dx, dy, dz)
    case c: Csg  =>
      if first(c, ox, oy, oz, dx, dy, dz, buffer, 0, cutoff, normals = false) > 0 then buffer.t(0)
      else Double.PositiveInfinity
    case t: Torus =>
      if torus(t, ox, oy, oz, dx, dy, dz, buffer, 0, normals = false, firstOnly = true) > 0 then
        buffer.t(0)
      else Double.PositiveInfinity
    case b: Box =>
      if collect(b, ox, oy, oz, dx, dy, dz, buffer, 0, normals = false) > 0 then buffer.t(0)
      else Double.PositiveInfinity

  /** True when [[distance]] of `shape` with cutoff `limit` is below `limit` (a shadow ray's
    * test): the same answer, but a union stops at its first child below the limit, and a
    * combination (placed or not) at its first crossing found below it, not the nearest: a kept
    * crossing is on the whole's surface, so the nearest is no farther (Perf: round 16).
    */
  def blocks(
      shape: Shape,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      limit: Double
  ): Boolean = shape match
    case c: Csg if c.operation == CsgOperation.Union =>
      // Perf: distance's loop over the children, ending at the first below the limit.
      val ix = 1 / dx
      val iy = 1 / dy
      val iz = 1 / dz
      var i  = 0
      while i < c.parts.length &&
        !(boxEntry(c.partBoxes, 6 * i, ox, oy, oz, ix, iy, iz, limit) < Double.PositiveInfinity &&
          blocks(c.parts(i), ox, oy, oz, dx, dy, dz, buffer, limit))
      do i += 1
      i < c.parts.length
    case c: Csg =>
      first(c, ox, oy, oz, dx, dy, dz, buffer, 0, limit, normals = false, limit, 1.0) > 0 &&
      buffer.t(0) < limit
    case p: Placed =>
      p.shape match
        case c: Csg if c.operation != CsgOperation.Union =>
          ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
            val cut = within(limit, s)
            first(c, lox, loy, loz, ldx, ldy, ldz, buffer, 0, cut, normals = false, limit, s) > 0 &&
            buffer.t(0) / s < limit
          }
        case _ => distance(p, ox, oy, oz, dx, dy, dz, buffer, limit) < limit
    case other => distance(other, ox, oy, oz, dx, dy, dz, buffer, limit) < limit

  /** The first of [[Shape.crossings]] of `shape` (the one [[Shape.hitAt]] reports: its t, outward
    * normal and leaf, bit for bit) written into `buffer` at `from`; returns `from + 1`, or `from`
    * when the ray crosses nothing. Crossing `from + 1` on may be overwritten.
    *
    * Perf: a combination's children are scanned for their first crossing on the whole's surface,
    * not collected and sorted whole (SolidsBench).
    */
  def firstCrossing(
      shape: Shape,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int
  ): Int = shape match
    case c: Csg =>
      first(c, ox, oy, oz, dx, dy, dz, buffer, from, Double.PositiveInfinity, normals = true)
    case p: Placed =>
      ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
        val end = firstCrossing(p.shape, lox, loy, loz, ldx, ldy, ldz, buffer, from)
        broughtBack(p.back, s, buffer, from, end, normals = true)
      }
    case t: Torus =>
      if torus(t, ox, oy, oz, dx, dy, dz, buffer, from, normals = true, firstOnly = true) > from
      then from + 1
      else from
    case other: (Sphere | Plane | Triangle | Mesh | Box | Cone) =>
      if collect(other, ox, oy, oz, dx, dy, dz, buffer, from) > from then from + 1 else from

  /** [[Shape.crossings]] of `shape` written into `buffer` from index `from`, in increasing t;
    * returns the index after the last. The same crossings bit for bit as the reference's list;
    * with `normals` false their normals are left unset (Perf: a distance needs only the ts, and
    * the cone's, torus's and placement's normals cost a square root each).
    */
  def collect(
      shape: Shape,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int,
      normals: Boolean = true
  ): Int = shape match
    case s: Sphere =>
      val ocx  = s.centre.x - ox
      val ocy  = s.centre.y - oy
      val ocz  = s.centre.z - oz
      val tca  = ocx * dx + ocy * dy + ocz * dz
      val t2hc = s.radiusSquared - (ocx * ocx + ocy * ocy + ocz * ocz) + tca * tca
      if t2hc < 0 then from
      else
        val half = Math.sqrt(t2hc)
        val k    = sphereCrossing(s, tca - half, ox, oy, oz, dx, dy, dz, buffer, from, normals)
        sphereCrossing(s, tca + half, ox, oy, oz, dx, dy, dz, buffer, k, normals)
    case p: Plane =>
      val t = planeDistance(p, ox, oy, oz, dx, dy, dz)
      if t < Double.PositiveInfinity then
        buffer.put(from, t, p.normal.x, p.normal.y, p.normal.z, 0); from + 1
      else from
    case tr: Triangle =>
      val t = triangleDistance(tr, ox, oy, oz, dx, dy, dz)
      if t < Double.PositiveInfinity then
        buffer.put(from, t, tr.normal.x, tr.normal.y, tr.normal.z, 0); from + 1
      else from
    case m: Mesh =>
      // Perf: each face's crossing on the mesh's arrays, its leaf the face, sorted stably by t.
      var end = from
      var f   = 0
      while f < m.faceCount do
        val t = Mesh.distanceTo(m, f, Double.PositiveInfinity, ox, oy, oz, dx, dy, dz)
        if t < Double.PositiveInfinity then
          val p = m.planes
          buffer.put(end, t, p(4 * f), p(4 * f + 1), p(4 * f + 2), f)
          end += 1
        f += 1
      buffer.sort(from, end)
      end
    case b: Box    => box(b, ox, oy, oz, dx, dy, dz, buffer, from)
    case c: Cone   => cone(c, ox, oy, oz, dx, dy, dz, buffer, from, normals)
    case t: Torus  => torus(t, ox, oy, oz, dx, dy, dz, buffer, from, normals)
    case p: Placed =>
      ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
        val end = collect(p.shape, lox, loy, loz, ldx, ldy, ldz, buffer, from, normals)
        broughtBack(p.back, s, buffer, from, end, normals)
      }
    case c: Csg => combination(c, ox, oy, oz, dx, dy, dz, buffer, from, normals)

  /** Runs `body` on the ray taken into `p`'s own space (Shape.ownSpace on doubles): its origin,
    * its unit direction and the stretch s by which its distances are longer there.
    *
    * Perf: `inline` with an inline body, so no tuple or ray is made (as Bvh.walk).
    */
  private inline def ownSpace[A](
      p: Placed,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  )(inline body: (Double, Double, Double, Double, Double, Double, Double) => A): A =
    val m  = p.back
    val lx = m(0) * dx + m(1) * dy + m(2) * dz
    val ly = m(3) * dx + m(4) * dy + m(5) * dz
    val lz = m(6) * dx + m(7) * dy + m(8) * dz
    val s  = Math.sqrt(lx * lx + ly * ly + lz * lz)
    val qx = ox - m(9)
    val qy = oy - m(10)
    val qz = oz - m(11)
    body(
      m(0) * qx + m(1) * qy + m(2) * qz,
      m(3) * qx + m(4) * qy + m(5) * qz,
      m(6) * qx + m(7) * qy + m(8) * qz,
      lx / s,
      ly / s,
      lz / s,
      s
    )

  /** A cutoff in the world taken into a placement's own space, where distances are `s` times
    * longer, widened so that every crossing within the world's cutoff is within it.
    */
  private inline def within(cutoff: Double, s: Double): Double = cutoff * s * (1 + 1e-9)

  /** The crossings `from until end`, found in a placement's own space, brought back: t divided by
    * the stretch `s`, the normal by (M⁻¹)ᵀ, normalised. Returns `end`.
    */
  private def broughtBack(
      m: Array[Double],
      s: Double,
      buffer: CrossingBuffer,
      from: Int,
      end: Int,
      normals: Boolean
  ): Int =
    // Why: a loop over the crossings just written, in place.
    var k = from
    while k < end do
      buffer.t(k) = buffer.t(k) / s
      if normals then
        val nx = buffer.nx(k); val ny = buffer.ny(k); val nz = buffer.nz(k)
        val wx = m(0) * nx + m(3) * ny + m(6) * nz
        val wy = m(1) * nx + m(4) * ny + m(7) * nz
        val wz = m(2) * nx + m(5) * ny + m(8) * nz
        val l  = Math.sqrt(wx * wx + wy * wy + wz * wz)
        if l > 0 && l < Double.PositiveInfinity then
          buffer.nx(k) = wx / l; buffer.ny(k) = wy / l; buffer.nz(k) = wz / l
      k += 1
    end

  /** [[Shape.inside]] on the point (px, py, pz), with the reference's tolerances. */
  def inside(shape: Shape, px: Double, py: Double, pz: Double): Boolean = shape match
    case s: Sphere =>
      val x = px - s.centre.x; val y = py - s.centre.y; val z = pz - s.centre.z
      x * x + y * y + z * z < s.radiusSquared
    case p: Plane =>
      px * p.normal.x + py * p.normal.y + pz * p.normal.z < p.distance + Solids.InsideTolerance
    case _: Triangle => false
    case _: Mesh     => false
    case b: Box      =>
      val lo = b.extent.lo; val hi = b.extent.hi
      px >= lo.x && px <= hi.x && py >= lo.y && py <= hi.y && pz >= lo.z && pz <= hi.z
    case c: Cone =>
      val margin = if c.open then Solids.InsideTolerance else -Solids.InsideTolerance
      val wx     = px - c.base.x; val wy = py - c.base.y; val wz = pz - c.base.z
      val a      = c.axis
      val z      = wx * a.x + wy * a.y + wz * a.z
      val r      = c.baseRadius + c.slope * z
      val scale  = Math.max(c.baseRadius, c.capRadius)
      val along  = z / c.height
      val rx     = wx - a.x * z; val ry  = wy - a.y * z; val rz  = wz - a.z * z
      along >= -margin && along <= 1 + margin &&
      (rx * rx + ry * ry + rz * rz) / (scale * scale) <= (r * r) / (scale * scale) + margin
    case t: Torus =>
      val ring = Math.sqrt(px * px + pz * pz) - t.major
      ring * ring + py * py <= t.minor * t.minor
    case p: Placed =>
      val m  = p.back
      val qx = px - m(9); val qy = py - m(10); val qz = pz - m(11)
      inside(
        p.shape,
        m(0) * qx + m(1) * qy + m(2) * qz,
        m(3) * qx + m(4) * qy + m(5) * qz,
        m(6) * qx + m(7) * qy + m(8) * qz
      )
    case c: Csg =>
      // Perf: Combination.inside as loops over the children's array.
      val parts = c.parts
      c.operation match
        case CsgOperation.Union =>
          var i = 0
          while i < parts.length && !inside(parts(i), px, py, pz) do i += 1
          i < parts.length
        case CsgOperation.Intersection =>
          var i = 0
          while i < parts.length && inside(parts(i), px, py, pz) do i += 1
          i == parts.length
        case CsgOperation.Difference =>
          inside(parts(0), px, py, pz) && {
            var i = 1
            while i < parts.length && !inside(parts(i), px, py, pz) do i += 1
            i == parts.length
          }

  /** A sphere's crossing at t if t > 0, with the reference's normal (ri − Sc)·(1/Sr). */
  private def sphereCrossing(
      s: Sphere,
      t: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      k: Int,
      normals: Boolean
  ): Int =
    if t > 0 && !normals then
      buffer.put(k, t, 0, 0, 0, 0)
      k + 1
    else if t > 0 then
      val inv = 1 / s.radius
      buffer.put(
        k,
        t,
        (ox + dx * t - s.centre.x) * inv,
        (oy + dy * t - s.centre.y) * inv,
        (oz + dz * t - s.centre.z) * inv,
        0
      )
      k + 1
    else k

  /** Solids.boxCrossings: the slab method, the face of each crossing from the slab that decided
    * it; the first of equal entries (or exits) wins, in the total order `maxBy` and `minBy` use.
    */
  private def box(
      b: Box,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int
  ): Int =
    val lo = b.extent.lo
    val hi = b.extent.hi
    // Why: the entry and exit narrowed slab by slab, with the axis that set each.
    var enter     = slabNear(ox, dx, lo.x, hi.x)
    var leave     = slabFar(ox, dx, lo.x, hi.x)
    var enterAxis = 0
    var leaveAxis = 0
    val ny        = slabNear(oy, dy, lo.y, hi.y)
    val fy        = slabFar(oy, dy, lo.y, hi.y)
    if java.lang.Double.compare(ny, enter) > 0 then
      enter = ny; enterAxis = 1
    if java.lang.Double.compare(fy, leave) < 0 then
      leave = fy; leaveAxis = 1
    val nz = slabNear(oz, dz, lo.z, hi.z)
    val fz = slabFar(oz, dz, lo.z, hi.z)
    if java.lang.Double.compare(nz, enter) > 0 then
      enter = nz; enterAxis = 2
    if java.lang.Double.compare(fz, leave) < 0 then
      leave = fz; leaveAxis = 2
    if enter > leave then from
    else
      val k = boxFace(enter, enterAxis, entering = true, dx, dy, dz, buffer, from)
      boxFace(leave, leaveAxis, entering = false, dx, dy, dz, buffer, k)

  /** The near end of the interval inside a slab (the reference's `slab`, first half). */
  private inline def slabNear(o: Double, d: Double, l: Double, h: Double): Double =
    if d == 0 then if o >= l && o <= h then Double.NegativeInfinity else Double.PositiveInfinity
    else
      val a = (l - o) / d
      val c = (h - o) / d
      if a < c then a else c

  /** The far end of the interval inside a slab (the reference's `slab`, second half). */
  private inline def slabFar(o: Double, d: Double, l: Double, h: Double): Double =
    if d == 0 then if o >= l && o <= h then Double.PositiveInfinity else Double.NegativeInfinity
    else
      val a = (l - o) / d
      val c = (h - o) / d
      if a < c then c else a

  /** A box face's crossing at t if t > 0: the axis against the ray on entry, along it on leaving
    * (as the reference's `-axis`, with its negative zeros).
    */
  private def boxFace(
      t: Double,
      axis: Int,
      entering: Boolean,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      k: Int
  ): Int =
    if t > 0 then
      val along = (if axis == 0 then dx else if axis == 1 then dy else dz) > 0
      val sign  = if along == entering then -1.0 else 1.0
      val zero  = if along == entering then -0.0 else 0.0
      buffer.put(
        k,
        t,
        if axis == 0 then sign else zero,
        if axis == 1 then sign else zero,
        if axis == 2 then sign else zero,
        0
      )
      k + 1
    else k

  /** Solids.coneCrossings: the side's quadratic and, unless open, the two discs, sorted by t. */
  private def cone(
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
  private def coneDistance(
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
    * Perf: `inline` with an inline body: the values stay local doubles (as Bvh.walk).
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
    val ax  = c.axis.x; val ay      = c.axis.y; val az      = c.axis.z
    val wx  = ox - c.base.x; val wy = oy - c.base.y; val wz = oz - c.base.z
    val wa  = wx * ax + wy * ay + wz * az
    val da  = dx * ax + dy * ay + dz * az
    val wrx = wx - ax * wa; val wry = wy - ay * wa; val wrz = wz - az * wa
    val drx = dx - ax * da; val dry = dy - ay * da; val drz = dz - az * da
    val k   = c.slope
    val rO  = c.baseRadius + k * wa
    val a   = (drx * drx + dry * dry + drz * drz) - k * k * da * da
    val b   = 2 * ((wrx * drx + wry * dry + wrz * drz) - k * rO * da)
    val q   = (wrx * wrx + wry * wry + wrz * wrz) - rO * rO
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

  /** Solids.torusCrossings: the quartic's roots on the part of the ray inside the bounding
    * sphere, from a point moved up to it, found by [[Polynomial.rootsInto]]; with `firstOnly`,
    * the first crossing alone (Perf: a distance or a first crossing looks for no later root;
    * docs/performance.md, round 16).
    */
  private def torus(
      tr: Torus,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer,
      from: Int,
      normals: Boolean,
      firstOnly: Boolean = false
  ): Int =
    val outer = tr.major + tr.minor
    val tca   = -(ox * dx + oy * dy + oz * dz)
    val miss  = (ox * ox + oy * oy + oz * oz) - tca * tca - outer * outer
    if miss > 0 then from
    else
      val half  = Math.sqrt(-miss)
      val shift = Math.max(0.0, tca - half)
      val stop  = tca + half - shift
      val px    = ox + dx * shift; val py = oy + dy * shift; val pz = oz + dz * shift
      if stop <= 0 || clear(tr, px, py, pz, dx, dy, dz, stop) then from
      else
        val r2 = tr.major * tr.major
        val h  = 2 * (px * dx + py * dy + pz * dz)
        val i  = (px * px + py * py + pz * pz) + r2 - tr.minor * tr.minor
        val j  = dx * dx + dz * dz
        val kk = 2 * (px * dx + pz * dz)
        val l  = px * px + pz * pz
        val c  = buffer.roots
        c(0) = i * i - 4 * r2 * l
        c(1) = 2 * h * i - 4 * r2 * kk
        c(2) = h * h + 2 * i - 4 * r2 * j
        c(3) = 2 * h
        c(4) = 1.0
        val level = Polynomial.ScratchLevel
        val first = if firstOnly then Polynomial.rootsInto(c, 0, 5, 0, stop, level, 1) else 0
        // A first root at t = 0 (the ray starts on the torus) is no crossing: all are looked for.
        val n =
          if firstOnly && (first == 0 || c(level + Polynomial.RootsAt) + shift > 0) then first
          else Polynomial.rootsInto(c, 0, 5, 0, stop, level)
        // Why: a loop over the roots just found, written as crossings in order.
        var out = from
        var m   = 0
        while m < n do
          val t = c(Polynomial.ScratchLevel + Polynomial.RootsAt + m) + shift
          if t > 0 && !normals then
            buffer.put(out, t, 0, 0, 0, 0)
            out += 1
          else if t > 0 then
            val qx     = ox + dx * t; val qy = oy + dy * t; val qz = oz + dz * t
            val ring   = Math.sqrt(qx * qx + qz * qz)
            val scale  = if ring > 0 then tr.major / ring else 0.0
            val cx     = if ring > 0 then qx * scale else 0.0
            val cy     = if ring > 0 then 0 * scale else 0.0
            val cz     = if ring > 0 then qz * scale else 0.0
            val nx     = qx - cx; val ny     = qy - cy; val nz     = qz - cz
            val length = Math.sqrt(nx * nx + ny * ny + nz * nz)
            if length > 0 && length < Double.PositiveInfinity then
              buffer.put(out, t, nx / length, ny / length, nz / length, 0)
            else buffer.put(out, t, 0, 1, 0, 0)
            out += 1
          m += 1
        out

  /** True when the segment from p along unit d for 0 ≤ t ≤ `stop` stays more than 1.1 minor
    * radii from the torus's tube circle: above or below the slab |y| ≤ 1.1r, or within it inside
    * the hole or outside the ring. Such a segment crosses nothing, and the root finder finds
    * nothing on it: the quartic there, (ρ² − r²)(ρ′² − r²) with ρ′ ≥ ρ > 1.1r the distances to
    * the circle's nearer and farther points, is above 0.04r⁴, orders of magnitude above its
    * rounding, so it has the same sign at every end the finder tries.
    *
    * Perf: the finder's bisections cost thousands of operations a ray (SolidsBench).
    */
  private def clear(
      tr: Torus,
      px: Double,
      py: Double,
      pz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      stop: Double
  ): Boolean =
    val w = 1.1 * tr.minor
    // The part of the segment inside the slab, [t1, t2].
    val a  = if dy == 0 then Double.NegativeInfinity else (-w - py) / dy
    val b  = if dy == 0 then Double.PositiveInfinity else (w - py) / dy
    val t1 = Math.max(0.0, Math.min(a, b))
    val t2 = Math.min(stop, Math.max(a, b))
    if dy == 0 && Math.abs(py) > w || t1 > t2 then true
    else
      // s²(t) = x² + z², convex in t: largest at an end, least at its vertex or an end.
      inline def s2(t: Double) =
        val x = px + dx * t; val z = pz + dz * t
        x * x + z * z
      val hole = tr.major - w
      val ring = tr.major + w
      val j    = dx * dx + dz * dz
      val tv   = if j > 0 then Math.max(t1, Math.min(t2, -(px * dx + pz * dz) / j)) else t1
      hole > 0 && s2(t1) < hole * hole && s2(t2) < hole * hole || s2(tv) > ring * ring

  /** Combination.crossings: each child's crossings kept where the others' inside tests say the
    * point is on the whole's surface, normals of subtracted children turned round, leaves
    * renumbered, all sorted by t (stably, children in order). A child whose box the ray misses
    * has no crossings and contains none of the others' ([[reach]]), so it is skipped.
    */
  private def combination(
      c: Csg,
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
    val ix   = 1 / dx
    val iy   = 1 / dy
    val iz   = 1 / dz
    val mask = reach(c, ox, oy, oz, ix, iy, iz, Double.PositiveInfinity)
    if !whole(c, mask) then from
    else
      // Perf: the children's crossings are written after the kept ones and compacted in place.
      var kept = from
      var i    = 0
      while i < c.parts.length do
        if met(c, mask, i, ox, oy, oz, ix, iy, iz, Double.PositiveInfinity) then
          val end   = collect(c.parts(i), ox, oy, oz, dx, dy, dz, buffer, kept, normals)
          val flip  = c.operation == CsgOperation.Difference && i > 0
          val first = c.partLeaves(i)
          var k     = kept
          while k < end do
            val t = buffer.t(k)
            if keeps(c, i, mask, ox + dx * t, oy + dy * t, oz + dz * t) then
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
    * t / `stretch` < `below` ends the search there ([[blocks]]; by default none does).
    */
  private def first(
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
    if !whole(c, mask) then from
    else
      // Perf: the best crossing so far at `from`, each child's crossings after it (SolidsBench).
      var best = Double.PositiveInfinity
      var i    = 0
      while i < c.parts.length do
        // A child entered beyond the best so far cannot hold a nearer crossing (until one is
        // found, the mask, made with the limit, says all there is).
        val bound = if best < limit then best else Double.PositiveInfinity
        if met(c, mask, i, ox, oy, oz, ix, iy, iz, bound) then
          val end = collect(c.parts(i), ox, oy, oz, dx, dy, dz, buffer, from + 1, normals)
          var k   = from + 1
          while k < end && buffer.t(k) < best && buffer.t(k) <= limit do
            val t = buffer.t(k)
            if keeps(c, i, mask, ox + dx * t, oy + dy * t, oz + dz * t) then
              best = t
              buffer.move(k, from)
              if c.operation == CsgOperation.Difference && i > 0 then
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

  /** True when the ray may cross the whole: every child of an intersection met, the first child
    * of a difference met (a union: always).
    */
  private inline def whole(c: Csg, mask: Long): Boolean = c.operation match
    case CsgOperation.Union        => true
    case CsgOperation.Intersection => mask == -1L
    case CsgOperation.Difference   => (mask & 1L) != 0

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

  /** Combination.keeps: a crossing of child `i` at p is on the surface of the whole; a child
    * whose bit in `mask` is clear does not contain p.
    */
  private def keeps(c: Csg, i: Int, mask: Long, px: Double, py: Double, pz: Double): Boolean =
    // Perf: `forall` over the children as loops on their array (SolidsBench).
    c.operation match
      case CsgOperation.Union        => true
      case CsgOperation.Intersection =>
        // A clear bit makes the whole a miss ([[whole]]), so every child is tested here.
        var j = 0
        while j < c.parts.length && (j == i || inside(c.parts(j), px, py, pz)) do j += 1
        j == c.parts.length
      case CsgOperation.Difference =>
        // Inside the first child and outside every later one, child i aside.
        (i == 0 || inside(c.parts(0), px, py, pz)) && {
          var j = 1
          while j < c.parts.length &&
            (j == i || j < 64 && (mask & (1L << j)) == 0 || !inside(c.parts(j), px, py, pz))
          do j += 1
          j == c.parts.length
        }

  /** The distance at which the ray (origin o, inverse direction i) enters the box of six doubles
    * at `b` of `boxes`, or +∞ when it misses it at 0 ≤ t ≤ `limit` (Bvh.entry's slab test).
    */
  private inline def boxEntry(
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

  /** Shape.sphereDistance on doubles. */
  private def sphereDistance(
      s: Sphere,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val ocx  = s.centre.x - ox
    val ocy  = s.centre.y - oy
    val ocz  = s.centre.z - oz
    val l2oc = ocx * ocx + ocy * ocy + ocz * ocz
    val tca  = ocx * dx + ocy * dy + ocz * dz
    val t2hc = s.radiusSquared - l2oc + tca * tca
    if l2oc < s.radiusSquared then tca + Math.sqrt(t2hc)
    else if tca < 0 || t2hc < 0 then Double.PositiveInfinity
    else
      val t = tca - Math.sqrt(t2hc)
      if t > 0 then t else Double.PositiveInfinity

  /** Shape.planeDistance on doubles. */
  private def planeDistance(
      p: Plane,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double = planeT(p.normal.x, p.normal.y, p.normal.z, p.distance, ox, oy, oz, dx, dy, dz)

  private inline def planeT(
      nx: Double,
      ny: Double,
      nz: Double,
      d: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val vd = nx * dx + ny * dy + nz * dz
    if vd == 0 then Double.PositiveInfinity
    else
      val t = (d - (nx * ox + ny * oy + nz * oz)) / vd
      if t > 0 then t else Double.PositiveInfinity

  /** Shape.triangleDistance on doubles. */
  private def triangleDistance(
      tr: Triangle,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val n = tr.normal
    val t = planeT(n.x, n.y, n.z, tr.distance, ox, oy, oz, dx, dy, dz)
    if t == Double.PositiveInfinity then t
    else
      val qx = ox + dx * t - tr.t0.x
      val qy = oy + dy * t - tr.t0.y
      val qz = oz + dz * t - tr.t0.z
      val qa = qx * tr.a.x + qy * tr.a.y + qz * tr.a.z
      val qb = qx * tr.b.x + qy * tr.b.y + qz * tr.b.z
      val u  = (tr.bb * qa - tr.ab * qb) / tr.denominator
      val v  = (qb - u * tr.ab) / tr.bb
      if u >= 0 && v >= 0 && u + v <= 1 then t else Double.PositiveInfinity
