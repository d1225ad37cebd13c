package tracer.geometry

/** A torus's crossings on plain doubles, for [[Kernel]]: the reference's `Solids.torusCrossings`
  * (the quartic's roots by [[Polynomial.rootsInto]]), bit for bit, with a quick test for rays
  * that pass clear of the tube.
  *
  * Perf: as [[Kernel]]'s, the reference's arithmetic operation for operation on plain doubles,
  * with no allocation (`KernelProperties` compares them bit for bit; `SolidsBench`).
  */
private[geometry] object TorusKernel:

  /** Solids.torusCrossings: the quartic's roots on the part of the ray inside the bounding
    * sphere, from a point moved up to it, found by [[Polynomial.rootsInto]]; with `firstOnly`,
    * the first crossing alone (Perf: a distance or a first crossing looks for no later root;
    * docs/performance.md, round 16).
    */
  private[geometry] def torus(
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
