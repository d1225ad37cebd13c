package tracer.geometry

/** A box's crossings on plain doubles, for [[Kernel]]: the slab method of the reference's
  * `Solids.boxCrossings`, bit for bit.
  *
  * Perf: as [[Kernel]]'s, the reference's arithmetic operation for operation on plain doubles,
  * with no allocation (`KernelProperties` compares them bit for bit; `SolidsBench`).
  */
private[geometry] object BoxKernel:

  /** Solids.boxCrossings: the slab method, the face of each crossing from the slab that decided
    * it; the first of equal entries (or exits) wins, in the total order `maxBy` and `minBy` use.
    */
  private[geometry] def box(
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
