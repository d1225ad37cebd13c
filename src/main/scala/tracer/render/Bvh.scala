package tracer.render

import scala.collection.mutable.ArrayBuffer
import tracer.geometry.{Plane, Ray, Shape, Sphere, Triangle}

/** A bounding volume hierarchy over the bounded shapes of a scene (spheres and triangles), built
  * once with the binned surface area heuristic and stored as flat arrays.
  *
  * It is an immutable value after construction. Queries take a scratch stack from the caller (one
  * per render task), so that tracing a ray allocates nothing.
  *
  * @param shapes the shapes it indexes; entries that are planes are ignored
  */
final class Bvh(shapes: IndexedSeq[Shape]):
  import Bvh.*

  // Perf: nodes as parallel arrays (no object per node): bounds, then either the index of the
  // left child (the right one follows it) or, for a leaf, a range of `order`.
  private val (lo, hi, child, first, count, order) = Builder(shapes).build()

  /** The number of nodes, for tests and benchmarks. */
  def nodeCount: Int = child.length

  /** The index in `shapes` of the shape `ray` hits first, competing with a candidate already
    * found: shape `limitIndex` at distance `limit` (use `Int.MaxValue` and +∞ for none). Ties go to
    * the lower index, as in a plain loop over all shapes. `stack` is scratch space of at least
    * [[Bvh.StackSize]] entries.
    */
  def nearest(ray: Ray, limit: Double, limitIndex: Int, stack: Array[Int]): Int =
    if order.isEmpty then limitIndex
    else
      // Perf: an iterative walk with an explicit stack, nearer child first, pruned by the best
      // distance so far (RenderBench.mesh: 1700× faster than the flat loop on 20k triangles).
      // Perf: six separate vals, not tuples (a tuple of doubles is allocated and boxed).
      val ox    = ray.origin.x
      val oy    = ray.origin.y
      val oz    = ray.origin.z
      val ix    = 1 / ray.direction.x
      val iy    = 1 / ray.direction.y
      val iz    = 1 / ray.direction.z
      var best  = limitIndex
      var bestT = limit
      var sp    = 0
      stack(sp) = 0
      sp += 1
      while sp > 0 do
        sp -= 1
        val node = stack(sp)
        if entry(node, ox, oy, oz, ix, iy, iz, bestT) < Double.PositiveInfinity then
          val left = child(node)
          if left < 0 then
            var k   = first(node)
            val end = k + count(node)
            while k < end do
              val i = order(k)
              val t = Shape.distance(shapes(i), ray)
              if t < bestT || (t == bestT && t < Double.PositiveInfinity && i < best) then
                bestT = t
                best = i
              k += 1
          else
            // Push the farther child first so the nearer one is visited next.
            val tl = entry(left, ox, oy, oz, ix, iy, iz, bestT)
            val tr = entry(left + 1, ox, oy, oz, ix, iy, iz, bestT)
            if tl <= tr then
              if tr < Double.PositiveInfinity then
                stack(sp) = left + 1; sp += 1
              if tl < Double.PositiveInfinity then
                stack(sp) = left; sp += 1
            else
              if tl < Double.PositiveInfinity then
                stack(sp) = left; sp += 1
              if tr < Double.PositiveInfinity then
                stack(sp) = left + 1; sp += 1
      best

  /** True when some indexed shape is hit by `ray` at a distance below `limit`; stops at the first. */
  def occluded(ray: Ray, limit: Double, stack: Array[Int]): Boolean =
    if order.isEmpty then false
    else
      // Perf: any hit will do, so no ordering and an early exit (shadow rays).
      // Perf: six separate vals, not tuples (a tuple of doubles is allocated and boxed).
      val ox  = ray.origin.x
      val oy  = ray.origin.y
      val oz  = ray.origin.z
      val ix  = 1 / ray.direction.x
      val iy  = 1 / ray.direction.y
      val iz  = 1 / ray.direction.z
      var hit = false
      var sp  = 0
      stack(sp) = 0
      sp += 1
      while sp > 0 && !hit do
        sp -= 1
        val node = stack(sp)
        if entry(node, ox, oy, oz, ix, iy, iz, limit) < Double.PositiveInfinity then
          val left = child(node)
          if left < 0 then
            var k   = first(node)
            val end = k + count(node)
            while k < end && !hit do
              hit = Shape.distance(shapes(order(k)), ray) < limit
              k += 1
          else
            stack(sp) = left
            stack(sp + 1) = left + 1
            sp += 2
      hit

  /** The distance at which a ray enters node `n`'s box, or +∞ when it misses it before `limit`.
    *
    * The slab test with near and far planes chosen by the direction's sign. An origin exactly on a
    * slab's plane with a zero direction component gives 0·∞ = NaN, which the comparisons ignore:
    * such a ray counts as inside that slab, as it is.
    */
  private inline def entry(
      n: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      limit: Double
  ): Double =
    val b    = 3 * n
    var tmin = 0.0
    var tmax = limit
    val nx   = ((if ix >= 0 then lo(b) else hi(b)) - ox) * ix
    val fx   = ((if ix >= 0 then hi(b) else lo(b)) - ox) * ix
    if nx > tmin then tmin = nx
    if fx < tmax then tmax = fx
    val ny = ((if iy >= 0 then lo(b + 1) else hi(b + 1)) - oy) * iy
    val fy = ((if iy >= 0 then hi(b + 1) else lo(b + 1)) - oy) * iy
    if ny > tmin then tmin = ny
    if fy < tmax then tmax = fy
    val nz = ((if iz >= 0 then lo(b + 2) else hi(b + 2)) - oz) * iz
    val fz = ((if iz >= 0 then hi(b + 2) else lo(b + 2)) - oz) * iz
    if nz > tmin then tmin = nz
    if fz < tmax then tmax = fz
    if tmin <= tmax then tmin else Double.PositiveInfinity

/** Construction constants and the builder of [[Bvh]]. */
object Bvh:
  /** The scratch stack size a query needs: deeper than any tree the builder makes. */
  val StackSize: Int = 256

  /** The most shapes a leaf holds when splitting would cost more. */
  private val MaxLeaf = 4

  /** SAH bins per split. */
  private val Bins = 16

  /** True for the shapes the hierarchy indexes: everything with finite bounds. */
  def isBounded(shape: Shape): Boolean = !shape.isInstanceOf[Plane]

  /** Top-down binned-SAH construction (Wald 2007), kept local: the arrays it fills become the
    * immutable tree.
    */
  private final class Builder(shapes: IndexedSeq[Shape]):
    private val prims = shapes.indices.filter(i => isBounded(shapes(i))).toArray
    // Each primitive's box and centroid, padded so flat boxes (a triangle in a plane) have depth.
    private val boxLo = new Array[Double](3 * shapes.length)
    private val boxHi = new Array[Double](3 * shapes.length)
    prims.foreach(i => bounds(shapes(i), i))

    private val lo    = ArrayBuffer.empty[Double]
    private val hi    = ArrayBuffer.empty[Double]
    private val child = ArrayBuffer.empty[Int]
    private val first = ArrayBuffer.empty[Int]
    private val count = ArrayBuffer.empty[Int]

    def build(): (Array[Double], Array[Double], Array[Int], Array[Int], Array[Int], Array[Int]) =
      if prims.nonEmpty then
        newNode()
        split(0, 0, prims.length, 0)
      (lo.toArray, hi.toArray, child.toArray, first.toArray, count.toArray, prims)

    private def bounds(shape: Shape, i: Int): Unit =
      val (l, h) = shape match
        case s: Sphere =>
          (
            Array(s.centre.x - s.radius, s.centre.y - s.radius, s.centre.z - s.radius),
            Array(s.centre.x + s.radius, s.centre.y + s.radius, s.centre.z + s.radius)
          )
        case t: Triangle =>
          (
            Array(
              t.t0.x min t.t1.x min t.t2.x,
              t.t0.y min t.t1.y min t.t2.y,
              t.t0.z min t.t1.z min t.t2.z
            ),
            Array(
              t.t0.x max t.t1.x max t.t2.x,
              t.t0.y max t.t1.y max t.t2.y,
              t.t0.z max t.t1.z max t.t2.z
            )
          )
        case _: Plane =>
          (Array.fill(3)(Double.NegativeInfinity), Array.fill(3)(Double.PositiveInfinity))
      for a <- 0 until 3 do
        val pad = 1e-9 * (1 + Math.abs(l(a)) + Math.abs(h(a)))
        boxLo(3 * i + a) = l(a) - pad
        boxHi(3 * i + a) = h(a) + pad

    private def newNode(): Int =
      lo ++= Seq(0.0, 0.0, 0.0); hi ++= Seq(0.0, 0.0, 0.0)
      child += -1; first += 0; count += 0
      child.length - 1

    private def centroid(i: Int, a: Int): Double = (boxLo(3 * i + a) + boxHi(3 * i + a)) / 2

    private def area(l: Array[Double], h: Array[Double]): Double =
      val (dx, dy, dz) = (h(0) - l(0), h(1) - l(1), h(2) - l(2))
      if dx < 0 then 0 else 2 * (dx * dy + dy * dz + dz * dx)

    /** Fills node `node` with prims(start until end), splitting it while that pays. */
    private def split(node: Int, start: Int, end: Int, depth: Int): Unit =
      val nl = Array.fill(3)(Double.PositiveInfinity)
      val nh = Array.fill(3)(Double.NegativeInfinity)
      val cl = Array.fill(3)(Double.PositiveInfinity)
      val ch = Array.fill(3)(Double.NegativeInfinity)
      for k <- start until end; a <- 0 until 3 do
        val i = prims(k)
        nl(a) = nl(a) min boxLo(3 * i + a); nh(a) = nh(a) max boxHi(3 * i + a)
        cl(a) = cl(a) min centroid(i, a); ch(a) = ch(a) max centroid(i, a)
      for a <- 0 until 3 do
        lo(3 * node + a) = nl(a); hi(3 * node + a) = nh(a)
      val n            = end - start
      val axis         = (0 until 3).maxBy(a => ch(a) - cl(a))
      val extent       = ch(axis) - cl(axis)
      def leaf(): Unit =
        child(node) = -1; first(node) = start; count(node) = n
      if n <= MaxLeaf / 2 || extent <= 0 || depth >= StackSize / 2 then leaf()
      else
        // Bin the centroids along the widest axis and cost every split between bins.
        def bin(i: Int) = Math.min(Bins - 1, ((centroid(i, axis) - cl(axis)) / extent * Bins).toInt)
        val binCount    = new Array[Int](Bins)
        val binLo       = Array.fill(Bins, 3)(Double.PositiveInfinity)
        val binHi       = Array.fill(Bins, 3)(Double.NegativeInfinity)
        for k <- start until end do
          val i = prims(k)
          val b = bin(i)
          binCount(b) += 1
          for a <- 0 until 3 do
            binLo(b)(a) = binLo(b)(a) min boxLo(3 * i + a);
            binHi(b)(a) = binHi(b)(a) max boxHi(3 * i + a)
        def sweep(bins: Range): Array[(Int, Double)] =
          val l = Array.fill(3)(Double.PositiveInfinity);
          val h = Array.fill(3)(Double.NegativeInfinity)
          var c = 0
          bins.map { b =>
            c += binCount(b)
            for a <- 0 until 3 do
              l(a) = l(a) min binLo(b)(a); h(a) = h(a) max binHi(b)(a)
            (c, area(l, h))
          }.toArray
        val leftSide  = sweep(0 until Bins - 1)
        val rightSide = sweep(Bins - 1 until 0 by -1).reverse
        val costs     = (0 until Bins - 1).map(s =>
          leftSide(s)._1 * leftSide(s)._2 + rightSide(s)._1 * rightSide(s)._2
        )
        val best     = costs.indices.minBy(costs)
        val leafCost = n * area(nl, nh)
        if n <= MaxLeaf && costs(best) >= leafCost then leaf()
        else
          // Partition in place: bins 0..best to the left.
          var i = start
          var j = end - 1
          while i <= j do
            if bin(prims(i)) <= best then i += 1
            else
              val swap = prims(i); prims(i) = prims(j); prims(j) = swap
              j -= 1
          val mid  = if i == start || i == end then (start + end) / 2 else i
          val left = newNode()
          newNode()
          child(node) = left
          split(left, start, mid, depth + 1)
          split(left + 1, mid, end, depth + 1)
