package tracer.render

import jdk.incubator.vector.{DoubleVector, VectorOperators, VectorSpecies}

/** A wide node's four child boxes tested at once with the Vector API (JDK 16 and newer, with
  * `--add-modules jdk.incubator.vector`): the walks' second way of pushing a node's children,
  * beside [[WideWalk.push]]. Everything that touches the module's classes is in this file, and
  * its classes are loaded only when [[LaneSupport.enabled]] (or a test) asks for them.
  *
  * Each lane is the scalar slab test's arithmetic on the same doubles, in the same order: the
  * float boxes widened to double once, when the tree is built (exactly), `(plane − origin) ×
  * inverse direction` per plane, and the nearest and farthest planes taken by a compare and a
  * blend per plane in the scalar test's order, not by `min` and `max` (which differ on NaN, from
  * 0 × ∞, and on −0.0). So every entry distance is the scalar test's bit for bit, and the hit
  * children are pushed in the scalar loop's order: the walks give the same answers
  * (`BvhProperties`, `MeshProperties`).
  *
  * Perf: a node's 24 plane tests in six vector subtractions and multiplications and the twelve
  * steps of the nearest and farthest planes in compares and blends, instead of four rounds of the
  * scalar test's 65 instructions: `scripts/ab.sh` on 1280×720 mesh-20000, 1501 → 846 ms a frame in
  * steady state (docs/performance.md, round 15).
  */
private[render] object Lanes:
  /** Four doubles. */
  val Species: VectorSpecies[java.lang.Double] = DoubleVector.SPECIES_256

  /** True when the processor's vectors hold four doubles (otherwise the Vector API would emulate
    * them, far slower than the scalar test).
    */
  def wideEnough: Boolean = DoubleVector.SPECIES_PREFERRED.length() >= 4

  /** The boxes of a wide tree (floats) as the doubles they are, in the same order. */
  def widen(boxes: Array[Float]): Array[Double] =
    val wide = new Array[Double](boxes.length)
    // Perf: once per tree, a counted loop.
    var i = 0
    while i < boxes.length do
      wide(i) = boxes(i).toDouble
      i += 1
    wide

  /** [[WideWalk.push]] with the four child boxes of wide node `node` tested at once: the boxes as
    * doubles `wd` (in [[WideTree]]'s layout), `scratch` four doubles of the query's.
    */
  inline def push(
      wd: Array[Double],
      node: Int,
      sp: Int,
      stack: Array[Int],
      entries: Array[Double],
      scratch: Array[Double],
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
    val b  = 24 * node
    val nx = DoubleVector.fromArray(Species, wd, b + 4 * sx).sub(ox).mul(ix)
    val fx = DoubleVector.fromArray(Species, wd, b + 12 - 4 * sx).sub(ox).mul(ix)
    val ny = DoubleVector.fromArray(Species, wd, b + 4 + 4 * sy).sub(oy).mul(iy)
    val fy = DoubleVector.fromArray(Species, wd, b + 16 - 4 * sy).sub(oy).mul(iy)
    val nz = DoubleVector.fromArray(Species, wd, b + 8 + 4 * sz).sub(oz).mul(iz)
    val fz = DoubleVector.fromArray(Species, wd, b + 20 - 4 * sz).sub(oz).mul(iz)
    // As WideWalk.entry: `if n > tmin then tmin = n`, `if f < tmax then tmax = f`, x, y, z.
    val t0   = DoubleVector.zero(Species)
    val t1   = t0.blend(nx, nx.compare(VectorOperators.GT, t0))
    val t2   = t1.blend(ny, ny.compare(VectorOperators.GT, t1))
    val near = t2.blend(nz, nz.compare(VectorOperators.GT, t2))
    val u0   = DoubleVector.broadcast(Species, limit)
    val u1   = u0.blend(fx, fx.compare(VectorOperators.LT, u0))
    val u2   = u1.blend(fy, fy.compare(VectorOperators.LT, u1))
    val far  = u2.blend(fz, fz.compare(VectorOperators.LT, u2))
    // An empty slot's box is inverted (+∞ low, −∞ high), so no ray enters it.
    // Why: the hit children left to push, lowest first, as the scalar loop meets them.
    var hits = near.compare(VectorOperators.LE, far).toLong
    // Why: the stack top, moved by each push.
    var top = sp
    if hits != 0 then
      if ordered then near.intoArray(scratch, 0)
      while hits != 0 do
        val c = java.lang.Long.numberOfTrailingZeros(hits)
        hits &= hits - 1
        val slot = WideTree.Width * node + c
        if ordered then
          // As WideWalk.push: an insertion sort keeps the slots farthest first.
          val t = scratch(c)
          var j = top
          while j > sp && entries(j - 1) < t do
            stack(j) = stack(j - 1); entries(j) = entries(j - 1)
            j -= 1
          stack(j) = slot; entries(j) = t
        else stack(top) = slot
        top += 1
    top

/** A [[MeshTree]]'s walks with [[Lanes.push]]: the same answers as its own. */
private[render] final class MeshLanes(
    wide: WideTree,
    faces: Array[Int],
    planes: Array[Double],
    at: Array[Int],
    vertices: IArray[Double]
):
  private val wd = Lanes.widen(wide.boxes)
  private val wc = wide.child
  private val wn = wide.count

  /** [[MeshTree.nearest]]. */
  def nearest(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Double =
    MeshWalk.nearest(
      wide.size,
      wc,
      wn,
      faces,
      planes,
      at,
      vertices,
      ox,
      oy,
      oz,
      dx,
      dy,
      dz,
      limit,
      query
    ) { (node, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
      Lanes.push(
        wd,
        node,
        sp,
        stack,
        entries,
        query.lanes,
        ox,
        oy,
        oz,
        ix,
        iy,
        iz,
        sx,
        sy,
        sz,
        bound,
        true
      )
    }

  /** [[MeshTree.occludedBelow]]. */
  def occludedBelow(
      node: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    MeshWalk.occludedBelow(
      wide.size,
      wc,
      wn,
      planes,
      at,
      vertices,
      node,
      ox,
      oy,
      oz,
      dx,
      dy,
      dz,
      limit,
      query
    ) { (n, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
      Lanes.push(
        wd,
        n,
        sp,
        stack,
        entries,
        query.lanes,
        ox,
        oy,
        oz,
        ix,
        iy,
        iz,
        sx,
        sy,
        sz,
        bound,
        false
      )
    }

/** A [[Bvh]]'s walks with [[Lanes.push]]: the same answers as its own. */
private[render] final class BvhLanes(wide: WideTree, prims: Primitives):
  private val wd = Lanes.widen(wide.boxes)
  private val wc = wide.child
  private val wn = wide.count

  /** [[Bvh.nearest]]. */
  def nearest(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      limitIndex: Int,
      query: Query
  ): Int =
    BvhWalk.nearest(wide.size, wc, wn, prims, ox, oy, oz, dx, dy, dz, limit, limitIndex, query) {
      (node, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
        Lanes.push(
          wd,
          node,
          sp,
          stack,
          entries,
          query.lanes,
          ox,
          oy,
          oz,
          ix,
          iy,
          iz,
          sx,
          sy,
          sz,
          bound,
          true
        )
    }

  /** [[Bvh.occluded]]. */
  def occluded(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    BvhWalk.occluded(wide.size, wc, wn, prims, ox, oy, oz, dx, dy, dz, limit, query) {
      (node, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
        Lanes.push(
          wd,
          node,
          sp,
          stack,
          entries,
          query.lanes,
          ox,
          oy,
          oz,
          ix,
          iy,
          iz,
          sx,
          sy,
          sz,
          bound,
          false
        )
    }
