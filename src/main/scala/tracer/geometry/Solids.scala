package tracer.geometry

import tracer.math.Vec3

/** Where rays cross the solids, and which points are inside them. */
private[geometry] object Solids:

  /** Every crossing of `ray` (unit direction) with box `b` at t > 0: the slab method, with the
    * face of each crossing from the slab that decided it.
    */
  def boxCrossings(b: Box, ray: Ray): List[Crossing] =
    val lo = b.extent.lo
    val hi = b.extent.hi
    // The interval inside each slab; a ray parallel to a slab is inside it for every t or none.
    def slab(o: Double, d: Double, l: Double, h: Double): (Double, Double) =
      if d == 0 then
        if o >= l && o <= h then (Double.NegativeInfinity, Double.PositiveInfinity)
        else (Double.PositiveInfinity, Double.NegativeInfinity)
      else
        val (a, c) = ((l - o) / d, (h - o) / d)
        if a < c then (a, c) else (c, a)
    val slabs = List(
      (slab(ray.origin.x, ray.direction.x, lo.x, hi.x), Vec3.UnitX),
      (slab(ray.origin.y, ray.direction.y, lo.y, hi.y), Vec3.UnitY),
      (slab(ray.origin.z, ray.direction.z, lo.z, hi.z), Vec3.UnitZ)
    )
    val ((enter, _), enterAxis) = slabs.maxBy(_._1._1)
    val ((_, leave), leaveAxis) = slabs.minBy(_._1._2)
    if enter > leave then Nil
    else
      // A face's outward normal is the axis against the ray on entry, along it on leaving.
      def outward(axis: Vec3, entering: Boolean) =
        val along = axis.dot(ray.direction) > 0
        if along == entering then -axis else axis
      List(
        Crossing(enter, outward(enterAxis, entering = true), 0),
        Crossing(leave, outward(leaveAxis, entering = false), 0)
      ).filter(_.t > 0)

  /** True when `p` is inside box `b` or on its surface (POV-Ray's `Box::Inside`). */
  def insideBox(b: Box, p: Vec3): Boolean =
    val (lo, hi) = (b.extent.lo, b.extent.hi)
    p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z

  /** Every crossing of `ray` with cone `c` at t > 0: the side where r(z) = baseRadius + slope·z
    * for 0 ≤ z ≤ height along the axis, and unless open the two discs.
    */
  def coneCrossings(c: Cone, ray: Ray): List[Crossing] =
    val w  = ray.origin - c.base
    val wz = w.dot(c.axis)
    val dz = ray.direction.dot(c.axis)
    val wr = w - c.axis * wz
    val dr = ray.direction - c.axis * dz
    // |wr + t·dr|² = (r0 + k·(wz + t·dz))², a quadratic a·t² + b·t + q = 0.
    val k      = c.slope
    val rAtO   = c.baseRadius + k * wz
    val a      = dr.dot(dr) - k * k * dz * dz
    val b      = 2 * (wr.dot(dr) - k * rAtO * dz)
    val q      = wr.dot(wr) - rAtO * rAtO
    val sideTs = quadratic(a, b, q)
    val onSide = sideTs.filter { t =>
      val z = wz + t * dz
      t > 0 && z >= 0 && z <= c.height && c.baseRadius + k * z >= 0
    }
    val side = onSide.map { t =>
      val p      = w + ray.direction * t
      val z      = p.dot(c.axis)
      val radial = p - c.axis * z
      val normal = (radial - c.axis * ((c.baseRadius + k * z) * k)).normalisedOr(c.axis)
      Crossing(t, normal, 0)
    }
    val discs =
      if c.open || dz == 0 then Nil
      else
        List((0.0, c.baseRadius, -c.axis), (c.height, c.capRadius, c.axis)).flatMap {
          (z, radius, normal) =>
            val t = (z - wz) / dz
            val p = w + ray.direction * t - c.axis * z
            Option.when(t > 0 && radius > 0 && p.dot(p) <= radius * radius)(Crossing(t, normal, 0))
        }
    (side ++ discs).sortBy(_.t)

  /** True when `p` is inside cone `c` (POV-Ray's `Cone::Inside`): an open cone still bounds the
    * same solid; a closed one excludes its surface by a hair, an open one includes it.
    */
  def insideCone(c: Cone, p: Vec3): Boolean =
    val margin = if c.open then InsideTolerance else -InsideTolerance
    val w      = p - c.base
    val z      = w.dot(c.axis)
    val r      = c.baseRadius + c.slope * z
    val scale  = Math.max(c.baseRadius, c.capRadius)
    // POV-Ray compares in a space where the wider disc has radius 1 and the height is 1.
    val along = z / c.height
    along >= -margin && along <= 1 + margin &&
    (w - c.axis * z).lengthSquared / (scale * scale) <= (r * r) / (scale * scale) + margin

  /** POV-Ray's EPSILON in its inside tests. */
  val InsideTolerance: Double = 1e-10

  /** Every crossing of `ray` (unit direction) with torus `tr` at t > 0: the real roots of
    * (|p|² + R² − r²)² = 4R²(x² + z²) along the ray, found on the part of the ray inside the
    * torus's bounding sphere, from a point moved up to that sphere for accuracy.
    */
  def torusCrossings(tr: Torus, ray: Ray): List[Crossing] =
    val outer = tr.major + tr.minor
    val tca   = -ray.origin.dot(ray.direction)
    val miss  = ray.origin.lengthSquared - tca * tca - outer * outer
    if miss > 0 then Nil
    else
      val half  = Math.sqrt(-miss)
      val shift = Math.max(0.0, tca - half)
      val end   = tca + half - shift
      if end <= 0 then Nil
      else
        val o  = ray.at(shift)
        val d  = ray.direction
        val r2 = tr.major * tr.major
        val h  = 2 * o.dot(d)
        val i  = o.lengthSquared + r2 - tr.minor * tr.minor
        val j  = d.x * d.x + d.z * d.z
        val kk = 2 * (o.x * d.x + o.z * d.z)
        val l  = o.x * o.x + o.z * o.z
        val c  = IArray(
          i * i - 4 * r2 * l,
          2 * h * i - 4 * r2 * kk,
          h * h + 2 * i - 4 * r2 * j,
          2 * h,
          1.0
        )
        Polynomial.roots(c, 0, end).map(_ + shift).filter(_ > 0).map { t =>
          Crossing(t, torusNormal(tr, ray.at(t)), 0)
        }

  /** True when `p` is inside torus `tr` or on its surface (POV-Ray's `Torus::Inside`). */
  def insideTorus(tr: Torus, p: Vec3): Boolean =
    val ring = Math.sqrt(p.x * p.x + p.z * p.z) - tr.major
    ring * ring + p.y * p.y <= tr.minor * tr.minor

  /** The torus's outward unit normal at `p` on its surface: the direction from the nearest point
    * of the tube's centre circle.
    */
  def torusNormal(tr: Torus, p: Vec3): Vec3 =
    val ring   = Math.sqrt(p.x * p.x + p.z * p.z)
    val centre = if ring > 0 then Vec3(p.x, 0, p.z) * (tr.major / ring) else Vec3.Zero
    (p - centre).normalisedOr(Vec3.UnitY)

  /** The real roots of a·t² + b·t + q in increasing order (none, or two possibly equal). */
  private def quadratic(a: Double, b: Double, q: Double): List[Double] =
    if a == 0 then if b == 0 then Nil else List(-q / b)
    else
      val disc = b * b - 4 * a * q
      if disc < 0 then Nil
      else
        // The numerically stable form: no cancellation between -b and √disc.
        val root     = Math.sqrt(disc)
        val m        = -0.5 * (b + (if b >= 0 then root else -root))
        val (x1, x2) = if m == 0 then (0.0, 0.0) else (m / a, q / m)
        if x1 <= x2 then List(x1, x2) else List(x2, x1)
