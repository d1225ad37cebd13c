package tracer.render

import tracer.geometry.{Ray, Shape}

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
      // distance so far (WorldBench.nearest, 20k triangles: 68 ns, 5000× faster than every shape).
      slabs(ray) { (ox, oy, oz, ix, iy, iz) =>
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
      }

  /** True when some indexed shape is hit by `ray` at a distance below `limit`; stops at the first. */
  def occluded(ray: Ray, limit: Double, stack: Array[Int]): Boolean =
    if order.isEmpty then false
    else
      // Perf: any hit will do, so no ordering and an early exit (shadow rays).
      slabs(ray) { (ox, oy, oz, ix, iy, iz) =>
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
      }

  /** Runs `walk` on the ray's origin and inverse direction as six plain doubles.
    *
    * Perf: `inline` with an inline function: the lambda's body is spliced in, so there is no tuple
    * or object to allocate (a tuple of doubles is boxed) and no call.
    */
  private inline def slabs[A](
      ray: Ray
  )(inline walk: (Double, Double, Double, Double, Double, Double) => A): A =
    walk(
      ray.origin.x,
      ray.origin.y,
      ray.origin.z,
      1 / ray.direction.x,
      1 / ray.direction.y,
      1 / ray.direction.z
    )

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
  def isBounded(shape: Shape): Boolean = Shape.bounds(shape).isDefined

  /** Top-down binned-SAH construction (Wald 2007), kept local: the arrays it fills become the
    * immutable tree.
    *
    * Perf: primitive arrays and while loops throughout. The first version used Scala collections
    * here and took 0.5 s (cold) for 20,000 triangles; this one takes about a tenth of that
    * (docs/performance.md, step 4).
    */
  private final class Builder(shapes: IndexedSeq[Shape]):
    private val prims = shapes.indices.filter(i => isBounded(shapes(i))).toArray
    // Each primitive's box (padded so flat boxes, like a triangle in a plane, have depth) and centroid.
    private val boxLo  = new Array[Double](3 * shapes.length)
    private val boxHi  = new Array[Double](3 * shapes.length)
    private val centre = new Array[Double](3 * shapes.length)
    prims.foreach(bound)

    // The nodes, grown as needed.
    private var size  = 0
    private var lo    = new Array[Double](3 * 64)
    private var hi    = new Array[Double](3 * 64)
    private var child = new Array[Int](64)
    private var first = new Array[Int](64)
    private var count = new Array[Int](64)

    // Scratch space for one split: per-bin counts and boxes, and the sweeps' results.
    private val binCount = new Array[Int](Bins)
    private val binLo    = new Array[Double](3 * Bins)
    private val binHi    = new Array[Double](3 * Bins)
    private val leftCost = new Array[Double](Bins)
    private val box      = new Array[Double](6)

    def build(): (Array[Double], Array[Double], Array[Int], Array[Int], Array[Int], Array[Int]) =
      if prims.nonEmpty then split(newNode(), 0, prims.length, 0)
      (
        lo.take(3 * size),
        hi.take(3 * size),
        child.take(size),
        first.take(size),
        count.take(size),
        prims
      )

    private def bound(i: Int): Unit =
      Shape.bounds(shapes(i)).foreach { b =>
        setBox(i, 0, b.lo.x, b.hi.x)
        setBox(i, 1, b.lo.y, b.hi.y)
        setBox(i, 2, b.lo.z, b.hi.z)
      }

    private def setBox(i: Int, axis: Int, low: Double, high: Double): Unit =
      val pad = 1e-9 * (1 + Math.abs(low) + Math.abs(high))
      boxLo(3 * i + axis) = low - pad
      boxHi(3 * i + axis) = high + pad
      centre(3 * i + axis) = (low + high) / 2

    private def newNode(): Int =
      if size == child.length then
        lo = java.util.Arrays.copyOf(lo, 6 * size); hi = java.util.Arrays.copyOf(hi, 6 * size)
        child = java.util.Arrays.copyOf(child, 2 * size);
        first = java.util.Arrays.copyOf(first, 2 * size)
        count = java.util.Arrays.copyOf(count, 2 * size)
      size += 1
      size - 1

    /** The surface area of the box with low corner b(l..l+2) and high corner b(h..h+2). */
    private def area(b: Array[Double], l: Int, h: Int): Double =
      val dx = b(h) - b(l)
      val dy = b(h + 1) - b(l + 1)
      val dz = b(h + 2) - b(l + 2)
      if dx < 0 then 0 else 2 * (dx * dy + dy * dz + dz * dx)

    /** Fills node `node` with prims(start until end), splitting it while that pays. */
    private def split(node: Int, start: Int, end: Int, depth: Int): Unit =
      // The node's box, and the box of the primitives' centroids.
      var cl0, cl1, cl2 = Double.PositiveInfinity
      var ch0, ch1, ch2 = Double.NegativeInfinity
      for a <- 0 until 3 do
        lo(3 * node + a) = Double.PositiveInfinity; hi(3 * node + a) = Double.NegativeInfinity
      var k = start
      while k < end do
        val i = prims(k)
        var a = 0
        while a < 3 do
          lo(3 * node + a) = lo(3 * node + a) min boxLo(3 * i + a)
          hi(3 * node + a) = hi(3 * node + a) max boxHi(3 * i + a)
          a += 1
        cl0 = cl0 min centre(3 * i); cl1 = cl1 min centre(3 * i + 1);
        cl2 = cl2 min centre(3 * i + 2)
        ch0 = ch0 max centre(3 * i); ch1 = ch1 max centre(3 * i + 1);
        ch2 = ch2 max centre(3 * i + 2)
        k += 1
      val n = end - start
      // Split along the axis where the centroids spread most.
      val (axis, low, extent) =
        if ch0 - cl0 >= ch1 - cl1 && ch0 - cl0 >= ch2 - cl2 then (0, cl0, ch0 - cl0)
        else if ch1 - cl1 >= ch2 - cl2 then (1, cl1, ch1 - cl1)
        else (2, cl2, ch2 - cl2)
      def leaf(): Unit =
        child(node) = -1; first(node) = start; count(node) = n
      if n <= MaxLeaf / 2 || extent <= 0 || depth >= StackSize / 2 then leaf()
      else
        def bin(i: Int): Int =
          Math.min(Bins - 1, ((centre(3 * i + axis) - low) / extent * Bins).toInt)
        // Bin the primitives along the axis.
        java.util.Arrays.fill(binCount, 0)
        java.util.Arrays.fill(binLo, Double.PositiveInfinity)
        java.util.Arrays.fill(binHi, Double.NegativeInfinity)
        k = start
        while k < end do
          val i = prims(k)
          val b = bin(i)
          binCount(b) += 1
          var a = 0
          while a < 3 do
            binLo(3 * b + a) = binLo(3 * b + a) min boxLo(3 * i + a)
            binHi(3 * b + a) = binHi(3 * b + a) max boxHi(3 * i + a)
            a += 1
          k += 1
        // Sweep from the left: leftCost(s) = count · area of bins 0..s.
        sweepStart()
        var c = 0
        var s = 0
        while s < Bins - 1 do
          c += binCount(s)
          grow(s)
          leftCost(s) = c * area(box, 0, 3)
          s += 1
        // Sweep from the right, keeping the cheapest split.
        sweepStart()
        c = 0
        var best     = 0
        var bestCost = Double.PositiveInfinity
        s = Bins - 1
        while s > 0 do
          c += binCount(s)
          grow(s)
          val cost = leftCost(s - 1) + c * area(box, 0, 3)
          if cost < bestCost then
            bestCost = cost
            best = s - 1
          s -= 1
        if n <= MaxLeaf && bestCost >= n * nodeArea(node) then leaf()
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

    private def nodeArea(node: Int): Double =
      val dx = hi(3 * node) - lo(3 * node)
      val dy = hi(3 * node + 1) - lo(3 * node + 1)
      val dz = hi(3 * node + 2) - lo(3 * node + 2)
      2 * (dx * dy + dy * dz + dz * dx)

    private def sweepStart(): Unit =
      java.util.Arrays.fill(box, 0, 3, Double.PositiveInfinity)
      java.util.Arrays.fill(box, 3, 6, Double.NegativeInfinity)

    private def grow(b: Int): Unit =
      var a = 0
      while a < 3 do
        box(a) = box(a) min binLo(3 * b + a)
        box(3 + a) = box(3 + a) max binHi(3 * b + a)
        a += 1
