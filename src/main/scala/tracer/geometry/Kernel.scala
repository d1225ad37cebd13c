package tracer.geometry

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
        if CsgKernel.boxEntry(
            c.partBoxes,
            6 * i,
            ox,
            oy,
            oz,
            ix,
            iy,
            iz,
            limit
          ) < Double.PositiveInfinity
        then best = Math.min(best, distance(c.parts(i), ox, oy, oz, dx, dy, dz, buffer, limit))
        i += 1
      best
    case p: Placed =>
      ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
        distance(p.shape, lox, loy, loz, ldx, ldy, ldz, buffer, within(cutoff, s)) / s
      }
    case c: Cone => ConeKernel.coneDistance(c, ox, oy, oz, dx, dy, dz)
    case c: Csg  =>
      if CsgKernel.first(c, ox, oy, oz, dx, dy, dz, buffer, 0, cutoff, normals = false) > 0 then
        buffer.t(0)
      else Double.PositiveInfinity
    case t: Torus =>
      if TorusKernel.torus(
          t,
          ox,
          oy,
          oz,
          dx,
          dy,
          dz,
          buffer,
          0,
          normals = false,
          firstOnly = true
        ) > 0
      then buffer.t(0)
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
        !(CsgKernel.boxEntry(
          c.partBoxes,
          6 * i,
          ox,
          oy,
          oz,
          ix,
          iy,
          iz,
          limit
        ) < Double.PositiveInfinity &&
          blocks(c.parts(i), ox, oy, oz, dx, dy, dz, buffer, limit))
      do i += 1
      i < c.parts.length
    case c: Csg =>
      CsgKernel.first(
        c,
        ox,
        oy,
        oz,
        dx,
        dy,
        dz,
        buffer,
        0,
        limit,
        normals = false,
        limit,
        1.0
      ) > 0 &&
      buffer.t(0) < limit
    case p: Placed =>
      p.shape match
        case c: Csg if c.operation != CsgOperation.Union =>
          ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
            val cut = within(limit, s)
            CsgKernel.first(
              c,
              lox,
              loy,
              loz,
              ldx,
              ldy,
              ldz,
              buffer,
              0,
              cut,
              normals = false,
              limit,
              s
            ) > 0 &&
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
      CsgKernel.first(
        c,
        ox,
        oy,
        oz,
        dx,
        dy,
        dz,
        buffer,
        from,
        Double.PositiveInfinity,
        normals = true
      )
    case p: Placed =>
      ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
        val end = firstCrossing(p.shape, lox, loy, loz, ldx, ldy, ldz, buffer, from)
        broughtBack(p.back, s, buffer, from, end, normals = true)
      }
    case t: Torus =>
      if TorusKernel.torus(
          t,
          ox,
          oy,
          oz,
          dx,
          dy,
          dz,
          buffer,
          from,
          normals = true,
          firstOnly = true
        ) > from
      then from + 1
      else from
    case other: (Sphere | Plane | Triangle | Mesh | Box | Cone) =>
      if collect(other, ox, oy, oz, dx, dy, dz, buffer, from) > from then from + 1 else from

  /** [[Shape.crossings]] of `shape` written into `buffer` from index `from`, in increasing t;
    * returns the index after the last. The same crossings bit for bit as the reference's list;
    * with `normals` false their normals are left unset (Perf: a distance needs only the ts, and
    * the cone's, torus's and placement's normals cost a square root each); `inversions` counts
    * how often POV-Ray has inverted the shape ([[Combination.Plain]] and the others, as
    * [[Shape.crossings]] takes them).
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
      normals: Boolean = true,
      inversions: Int = Combination.Plain
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
    // As Shape.crossings: the complement of a mesh of many faces has no surface.
    case m: Mesh if inversions == Combination.Inverted && m.faceCount > 1 => from
    case m: Mesh                                                          =>
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
    case b: Box    => BoxKernel.box(b, ox, oy, oz, dx, dy, dz, buffer, from)
    case c: Cone   => ConeKernel.cone(c, ox, oy, oz, dx, dy, dz, buffer, from, normals)
    case t: Torus  => TorusKernel.torus(t, ox, oy, oz, dx, dy, dz, buffer, from, normals)
    case p: Placed =>
      ownSpace(p, ox, oy, oz, dx, dy, dz) { (lox, loy, loz, ldx, ldy, ldz, s) =>
        val end =
          collect(p.shape, lox, loy, loz, ldx, ldy, ldz, buffer, from, normals, inversions)
        broughtBack(p.back, s, buffer, from, end, normals)
      }
    case c: Csg =>
      CsgKernel.combination(c, ox, oy, oz, dx, dy, dz, buffer, from, normals, inversions)

  /** Runs `body` on the point (px, py, pz) taken back into the placed shape's own space,
    * A⁻¹(p − T), as [[ownSpace]] takes a ray's origin (the same operations).
    */
  private inline def pointBack[A](p: Placed, px: Double, py: Double, pz: Double)(
      inline body: (Double, Double, Double) => A
  ): A =
    val m  = p.back
    val qx = px - m(9); val qy = py - m(10); val qz = pz - m(11)
    body(
      m(0) * qx + m(1) * qy + m(2) * qz,
      m(3) * qx + m(4) * qy + m(5) * qz,
      m(6) * qx + m(7) * qy + m(8) * qz
    )

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
      // Perf: for an axis along x, y or z the products with its zero coordinates are left out: z
      // and r are the same numbers, the squared distance from the axis the same bits, so every
      // comparison is the same (the argument of ConeKernel.coneRoots, under the same condition:
      // ConeKernel.shortcut).
      val k = ConeKernel.shortcut(c, wx, wy, wz)
      val z =
        if k < 0 then wx * a.x + wy * a.y + wz * a.z
        else ConeKernel.along(k, a.x, a.y, a.z) * ConeKernel.along(k, wx, wy, wz)
      val across =
        if k < 0 then
          val rx = wx - a.x * z; val ry = wy - a.y * z; val rz = wz - a.z * z
          rx * rx + ry * ry + rz * rz
        else ConeKernel.across(k, wx, wy, wz)((u, v) => u * u + v * v)
      val r     = c.baseRadius + c.slope * z
      val scale = Math.max(c.baseRadius, c.capRadius)
      val along = z / c.height
      along >= -margin && along <= 1 + margin &&
      across / (scale * scale) <= (r * r) / (scale * scale) + margin
    case t: Torus =>
      val ring = Math.sqrt(px * px + pz * pz) - t.major
      ring * ring + py * py <= t.minor * t.minor
    case p: Placed => pointBack(p, px, py, pz)(inside(p.shape, _, _, _))
    case c: Csg    =>
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
            while i < parts.length && insideComplement(parts(i), px, py, pz) do i += 1
            i == parts.length
          }

  /** [[Shape.insideComplement]] on the point (px, py, pz): as [[inside]], negated for a solid. */
  def insideComplement(shape: Shape, px: Double, py: Double, pz: Double): Boolean = shape match
    case _: (Triangle | Mesh) => false
    case p: Placed            => pointBack(p, px, py, pz)(insideComplement(p.shape, _, _, _))
    case c: Csg               =>
      // Perf: Combination.insideComplement as loops over the children's array.
      val parts = c.parts
      c.operation match
        case CsgOperation.Union =>
          var i = 0
          while i < parts.length && insideComplement(parts(i), px, py, pz) do i += 1
          i == parts.length
        case CsgOperation.Intersection =>
          var i = 0
          while i < parts.length && !insideComplement(parts(i), px, py, pz) do i += 1
          i < parts.length
        case CsgOperation.Difference =>
          insideComplement(parts(0), px, py, pz) || {
            var i = 1
            while i < parts.length && !inside(parts(i), px, py, pz) do i += 1
            i < parts.length
          }
    case _: (Sphere | Plane | Box | Cone | Torus) => !inside(shape, px, py, pz)

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

  /** The distance along the ray from (ox, oy, oz) in direction (dx, dy, dz) to the plane of unit
    * normal (nx, ny, nz) and distance `d` (equations 24–27: (D − Pn·O) / (Pn·d) when positive),
    * else +∞: the one plane test on doubles, shared by the planes and triangles here, the scene's
    * kernel (`render.Primitives`) and the meshes' faces ([[Mesh.faceDistance]]).
    */
  inline def planeT(
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
    val vd  = nx * dx + ny * dy + nz * dz
    val gap = d - (nx * ox + ny * oy + nz * oz)
    // Perf: gap / vd > 0 needs both of one sign, so a plane behind the ray, parallel to it (vd
    // zero) or a NaN is refused before the division, as the division's sign would refuse it: a
    // ray leaving a mesh's face tests the other faces of its leaf, most of whose planes lie
    // behind it (docs/performance.md, round 36).
    if !((gap > 0 && vd > 0) || (gap < 0 && vd < 0)) then Double.PositiveInfinity
    else
      val t = gap / vd
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
