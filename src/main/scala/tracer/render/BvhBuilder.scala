package tracer.render

import scala.concurrent.duration.Duration
import scala.concurrent.{Await, ExecutionContext, Future}
import tracer.geometry.{Mesh, Shape}

/** A built hierarchy of `size` nodes as flat arrays: node n's box at `boxes(6n until 6n + 6)` (low x, y, z, then
  * high x, y, z; floats, being the primitives' float boxes' minima and maxima), and `links(2n)`, `links(2n + 1)`: for an inner node its left child (the right
  * one follows it) and 0, for a leaf the first of its primitives and their count (≥ 1).
  * `order` lists the indexed shapes' indices in leaf order; `unbounded` the indices, in order,
  * of the shapes left out for having no bounds (planes), which the builder found as it asked
  * every shape for its bounds (so `World` need not ask again; none for a mesh's faces).
  */
private[render] final class Tree(
    val size: Int,
    val boxes: Array[Float],
    val links: Array[Int],
    val order: Array[Int],
    val unbounded: Array[Int]
)

/** Top-down binned-SAH construction (Wald 2007) of a [[Tree]] over primitives given by their
  * boxes: the shapes that have [[tracer.geometry.Bounds]] ([[BvhBuilder.apply]]) or the faces of
  * a mesh ([[BvhBuilder.faces]]).
  *
  * Perf: primitive arrays and while loops throughout; the arrays it fills become the immutable
  * tree. The first version used Scala collections and took 0.5 s (cold) for 20,000 triangles;
  * this one takes about a tenth of that (docs/performance.md, step 4). Every subtree owns a range
  * of node numbers fixed by its number of primitives alone (a subtree of n primitives makes at
  * most 2n − 1 nodes), so subtrees can be built at once on different threads ([[build]] with a
  * pool) and the tree is the same, node for node, however they are scheduled.
  *
  * Perf: the primitives' boxes are floats rounded outwards: a third less memory and traffic than
  * doubles (the 1.3M-face mesh's build; docs/performance.md, round 7). The tree's boxes are their
  * minima and maxima, floats exactly (kept as floats), so the wide tree's rounding leaves them
  * as they are, and every ray that
  * meets a primitive still meets every box above it. The centres stay doubles: they choose the
  * splits, and a float has no room for a scene's far-apart shapes (BvhProperties' chain).
  *
  * @param boxLo  each primitive's padded low corner at 3k..3k+2, rounded down to a float, moved
  *   with it by the partitions
  * @param boxHi  its high corner, rounded up, likewise
  * @param centre its box's centre, in double precision, likewise
  * @param prims  the primitives' numbers, reordered into leaf order
  * @param without the shapes left out for having no bounds, in order (see [[Tree.unbounded]])
  * @param whole  the most primitives a node holds that is made a leaf without weighing a split
  *   ([[BvhBuilder.wholeLeaf]])
  * @param largest the most primitives a node holds that is made a leaf when splitting it would
  *   cost more ([[BvhBuilder.MaxLeaf]], or [[BvhBuilder.MaxFaceLeaf]] for a mesh's faces)
  * @param visit  what visiting a node costs, in tests of a primitive, in that weighing (0, or
  *   [[BvhBuilder.FaceVisit]] for a mesh's faces)
  */
private[render] final class BvhBuilder private (
    boxLo: Array[Float],
    boxHi: Array[Float],
    centre: Array[Double],
    prims: Array[Int],
    without: Array[Int],
    whole: Int,
    largest: Int = BvhBuilder.MaxLeaf,
    visit: Double = 0
):
  import BvhBuilder.*

  // Perf: each primitive's bin along the node's split axis, found once by the binning pass and
  // read again by the partition (no second division per primitive); a subtree's range is its own.
  private val bins = new Array[Byte](prims.length)

  // The nodes: a binary tree with n leaves has 2n − 1 nodes, so the arrays never grow.
  private val capacity = Math.max(1, 2 * prims.length - 1)
  // Perf: floats, exactly: every node's box is a minimum and maximum of the primitives' float
  // boxes (half the 1.3M-face mesh's largest array, 124 → 62 MB; docs/performance.md, round 8).
  private val boxes = new Array[Float](6 * capacity)
  private val links = new Array[Int](2 * capacity)

  /** Builds the tree, on `pool` when one is given (the render's threads, each node's subtrees as
    * tasks of their own: [[task]]) and on this thread alone otherwise; a coarse one (leaves of
    * [[LinearLeaf]] or more) in Morton order instead ([[LinearBuild]]). Its arrays may be longer
    * than its nodes (`Tree.size` says how many are used; unused numbers are never linked).
    */
  def build(pool: Option[ExecutionContext] = None): Tree =
    if prims.isEmpty then Tree(0, boxes, links, prims, without)
    else if whole >= LinearLeaf then
      LinearBuild(boxLo, boxHi, centre, prims, without, whole, boxes, links, pool)
    else
      pool match
        case Some(context) if prims.length >= ParallelFrom =>
          given ExecutionContext = context
          val made = Await.result(task(Task(0, 0, prims.length, 0, 1, Known.None)), Duration.Inf)
          Tree(made, boxes, links, prims, without)
        case _ =>
          Tree(
            split(0, 0, prims.length, 0, 1, Scratch(), 0, Vector.newBuilder),
            boxes,
            links,
            prims,
            without
          )

  /** The subtree of `t` built on the pool, its number of nodes when done: a node of more than
    * [[Grain]] primitives is split alone and its two children are tasks of their own, a smaller
    * one is built whole on one thread.
    *
    * Perf: only the root is split on one thread; every level below it runs on the pool (the
    * top three levels ran on one thread, a fifth of the 1.3M-face mesh's build, and six subtrees
    * of uneven sizes kept the threads unevenly busy; docs/performance.md, round 8).
    */
  private def task(t: Task)(using ExecutionContext): Future[Int] =
    Future {
      val below = Vector.newBuilder[Task]
      val big   = t.end - t.start > Grain
      val made  =
        divide(
          t.node,
          t.start,
          t.end,
          t.depth,
          t.free,
          Scratch(),
          if big then Int.MaxValue else 0,
          below,
          t.known
        )
      (made, below.result())
    }.flatMap { (made, below) =>
      if below.isEmpty then Future.successful(made)
      else Future.traverse(below)(t => task(t)).map(made + _.sum)
    }

  /** The surface area of the box with low corner b(l..l+2) and high corner b(h..h+2). */
  private def area(b: Array[Float], l: Int, h: Int): Double =
    surface(
      b(h).toDouble - b(l),
      b(h + 1).toDouble - b(l + 1),
      b(h + 2).toDouble - b(l + 2)
    )

  /** The surface area of a box of sides dx, dy and dz (0 for an empty one: dx < 0). */
  private def surface(dx: Double, dy: Double, dz: Double): Double =
    if dx < 0 then 0 else 2 * (dx * dy + dy * dz + dz * dx)

  /** Fills node `node` with prims(start until end), splitting it while that pays; its children
    * are numbered from `free` on (the subtree's own range: 2(end − start) − 2 numbers). A node
    * of at most `grain` primitives (and more than 0) is not built but handed to `tasks`, to be
    * built by [[build]]'s pool. Returns the number of nodes made, `node` included.
    */
  private def split(
      node: Int,
      start: Int,
      end: Int,
      depth: Int,
      free: Int,
      s: Scratch,
      grain: Int,
      tasks: scala.collection.mutable.Builder[Task, Vector[Task]],
      known: Known = Known.None
  ): Int =
    val n = end - start
    if n <= grain && node > 0 then
      tasks += Task(node, start, end, depth, free, known)
      0
    else divide(node, start, end, depth, free, s, grain, tasks, known)

  private def divide(
      node: Int,
      start: Int,
      end: Int,
      depth: Int,
      free: Int,
      s: Scratch,
      grain: Int,
      tasks: scala.collection.mutable.Builder[Task, Vector[Task]],
      known: Known
  ): Int =
    // The node's box, and the box of the primitives' centroids: from the parent's bins when it
    // had them (Perf: a pass over the primitives saved at every level), else from the primitives.
    val cs  = if known.found then known else enclose(node, start, end)
    val cl0 = cs.lo0; val cl1 = cs.lo1; val cl2 = cs.lo2
    val ch0 = cs.hi0; val ch1 = cs.hi1; val ch2 = cs.hi2
    val n   = end - start
    // Split along the axis where the centroids spread most.
    // Perf: the axis, its low end and extent as three values, no tuple (boxed) per node.
    val axis =
      if ch0 - cl0 >= ch1 - cl1 && ch0 - cl0 >= ch2 - cl2 then 0
      else if ch1 - cl1 >= ch2 - cl2 then 1
      else 2
    val low         = if axis == 0 then cl0 else if axis == 1 then cl1 else cl2
    val extent      = if axis == 0 then ch0 - cl0 else if axis == 1 then ch1 - cl1 else ch2 - cl2
    def leaf(): Int =
      links(2 * node) = start; links(2 * node + 1) = n
      1
    if n <= whole || extent <= 0 || depth >= MaxDepth then leaf()
    else
      // Perf: as many bins as primitives below Bins: a node's fixed cost (clearing the bins, the
      // two sweeps) is per bin, and most nodes are small (the 1.3M-face mesh's build spent more
      // in the sweeps of 16 bins than on its primitives; docs/performance.md, round 7).
      val nb = Math.min(Bins, n)
      binAll(start, end, axis, low, extent, nb, s)
      val best = cheapest(nb, s)
      val here = area(boxes, 6 * node, 6 * node + 3)
      if n <= largest && s.bestCost + visit * here >= n * here then leaf()
      else
        // Bins 0..best to the left.
        val i      = partition(start, end, best)
        val binned = i != start && i != end
        val mid    = if binned then i else (start + end) / 2
        val left   = free // the right child at left + 1; then the left subtree's range, the right's
        links(2 * node) = left; links(2 * node + 1) = 0
        // Split by the bins, each child's box and centroids' box are its bins' (min and max are
        // exact, so the same as from its primitives); a median split finds them itself.
        // Both before the left subtree is built: it reuses the scratch bins.
        val leftKnown  = s.side(binned, 0, best, 6 * left, boxes)
        val rightKnown = s.side(binned, best + 1, nb - 1, 6 * (left + 1), boxes)
        val l          = split(left, start, mid, depth + 1, free + 2, s, grain, tasks, leftKnown)
        val r          =
          split(
            left + 1,
            mid,
            end,
            depth + 1,
            free + 2 * (mid - start),
            s,
            grain,
            tasks,
            rightKnown
          )
        1 + l + r

  // Perf: each pass over a node's primitives or bins is a method of its own, so `divide` has no
  // loop: a loop written out in that large method ran in its on-stack compilations, which C2
  // took 120–180 ms to make for each, while the build waited in the interpreter or in C1; a
  // small method is compiled in a few milliseconds (docs/performance.md, round 28 and 29).

  /** Writes the box of prims(start until end) as node `node`'s and returns their centroids' box. */
  private def enclose(node: Int, start: Int, end: Int): Known =
    // Why: the centroids' box, narrowed in a counted loop.
    var cl0, cl1, cl2 = Double.PositiveInfinity
    // Why: as cl0.
    var ch0, ch1, ch2 = Double.NegativeInfinity
    val nb            = 6 * node
    java.util.Arrays.fill(boxes, nb, nb + 3, Float.PositiveInfinity)
    java.util.Arrays.fill(boxes, nb + 3, nb + 6, Float.NegativeInfinity)
    var k = start
    while k < end do
      var a = 0
      while a < 3 do
        boxes(nb + a) = boxes(nb + a) min boxLo(3 * k + a)
        boxes(nb + 3 + a) = boxes(nb + 3 + a) max boxHi(3 * k + a)
        a += 1
      cl0 = cl0 min centre(3 * k); cl1 = cl1 min centre(3 * k + 1)
      cl2 = cl2 min centre(3 * k + 2)
      ch0 = ch0 max centre(3 * k); ch1 = ch1 max centre(3 * k + 1)
      ch2 = ch2 max centre(3 * k + 2)
      k += 1
    Known(true, cl0, cl1, cl2, ch0, ch1, ch2)

  /** Drops prims(start until end) into `nb` bins along `axis` by their centroids, which start at
    * `low` and span `extent` there: the scratch bins' counts, boxes and centroids' boxes.
    */
  private def binAll(
      start: Int,
      end: Int,
      axis: Int,
      low: Double,
      extent: Double,
      nb: Int,
      s: Scratch
  ): Unit =
    java.util.Arrays.fill(s.binCount, 0, nb, 0)
    java.util.Arrays.fill(s.binLo, 0, 3 * nb, Double.PositiveInfinity)
    java.util.Arrays.fill(s.binHi, 0, 3 * nb, Double.NegativeInfinity)
    java.util.Arrays.fill(s.binCLo, 0, 3 * nb, Double.PositiveInfinity)
    java.util.Arrays.fill(s.binCHi, 0, 3 * nb, Double.NegativeInfinity)
    var k = start
    while k < end do
      binOne(k, Math.min(nb - 1, ((centre(3 * k + axis) - low) / extent * nb).toInt), s)
      k += 1

  /** The last bin of the cheapest split of the `nb` scratch bins into bins 0..best and the rest
    * (0 when none is cheaper than +∞), with that split's cost left in `s.bestCost`: the surface
    * area heuristic, each side's primitive count times its box's area.
    */
  private def cheapest(nb: Int, s: Scratch): Int =
    val binCount = s.binCount
    val binLo    = s.binLo
    val binHi    = s.binHi
    // Sweep from the left: leftCost(s) = count · area of bins 0..s.
    // Perf: each sweep's box in six locals (registers), not in the scratch array: the sweeps
    // were a quarter of the 1.3M-face mesh's build (docs/performance.md, round 8). The same
    // minima, maxima and area as before, so the same costs bit for bit.
    val leftCost   = s.leftCost
    var x0, y0, z0 = Double.PositiveInfinity
    var x1, y1, z1 = Double.NegativeInfinity
    var c          = 0
    var step       = 0
    while step < nb - 1 do
      c += binCount(step)
      val at = 3 * step
      x0 = x0 min binLo(at); y0 = y0 min binLo(at + 1); z0 = z0 min binLo(at + 2)
      x1 = x1 max binHi(at); y1 = y1 max binHi(at + 1); z1 = z1 max binHi(at + 2)
      leftCost(step) = c * surface(x1 - x0, y1 - y0, z1 - z0)
      step += 1
    // Sweep from the right, keeping the cheapest split.
    x0 = Double.PositiveInfinity; y0 = Double.PositiveInfinity; z0 = Double.PositiveInfinity
    x1 = Double.NegativeInfinity; y1 = Double.NegativeInfinity; z1 = Double.NegativeInfinity
    c = 0
    var best     = 0
    var bestCost = Double.PositiveInfinity
    step = nb - 1
    while step > 0 do
      c += binCount(step)
      val at = 3 * step
      x0 = x0 min binLo(at); y0 = y0 min binLo(at + 1); z0 = z0 min binLo(at + 2)
      x1 = x1 max binHi(at); y1 = y1 max binHi(at + 1); z1 = z1 max binHi(at + 2)
      val cost = leftCost(step - 1) + c * surface(x1 - x0, y1 - y0, z1 - z0)
      if cost < bestCost then
        bestCost = cost
        best = step - 1
      step -= 1
    s.bestCost = bestCost
    best

  /** Moves the primitives of start until end whose bin is at most `best` before the others, in
    * place, and returns where the others begin.
    */
  private def partition(start: Int, end: Int, best: Int): Int =
    // Why: the two ends of the unsorted middle move towards each other.
    var i = start
    var j = end - 1
    while i <= j do
      if bins(i) <= best then i += 1
      else
        swap(i, j)
        j -= 1
    i

  /** Puts primitive k into bin b of the scratch bins: its number, count, box and centroid.
    *
    * Perf: one primitive's binning a call, a small method that C1 compiles within milliseconds
    * and C2 in 8, where the loop written out in `divide` ran in that large method's on-stack
    * versions (C2 spent 120–180 ms on each); mesh-80000 at 1280×720 4–5% faster in whole runs
    * (docs/performance.md, round 28).
    */
  private def binOne(k: Int, b: Int, s: Scratch): Unit =
    bins(k) = b.toByte
    s.binCount(b) += 1
    var a = 0
    while a < 3 do
      s.binLo(3 * b + a) = s.binLo(3 * b + a) min boxLo(3 * k + a)
      s.binHi(3 * b + a) = s.binHi(3 * b + a) max boxHi(3 * k + a)
      s.binCLo(3 * b + a) = s.binCLo(3 * b + a) min centre(3 * k + a)
      s.binCHi(3 * b + a) = s.binCHi(3 * b + a) max centre(3 * k + a)
      a += 1

  /** Exchanges the primitives at positions i and j, with their boxes and centroids. */
  private def swap(i: Int, j: Int): Unit =
    val p = prims(i); prims(i) = prims(j); prims(j) = p
    val b = bins(i); bins(i) = bins(j); bins(j) = b
    var a = 0
    while a < 3 do
      exchange(boxLo, 3 * i + a, 3 * j + a)
      exchange(boxHi, 3 * i + a, 3 * j + a)
      exchangeCentre(3 * i + a, 3 * j + a)
      a += 1

  private def exchange(xs: Array[Float], i: Int, j: Int): Unit =
    val x = xs(i); xs(i) = xs(j); xs(j) = x

  private def exchangeCentre(i: Int, j: Int): Unit =
    val x = centre(i); centre(i) = centre(j); centre(j) = x

/** Construction constants of [[BvhBuilder]], and its two sources of primitives. */
private[render] object BvhBuilder:
  /** The builder over the shapes of `shapes` that have bounds (the others are left out). */
  def apply(shapes: IndexedSeq[Shape], rays: Long = Long.MaxValue): BvhBuilder =
    val all    = shapes.toArray
    val boxLo  = new Array[Float](3 * all.length)
    val boxHi  = new Array[Float](3 * all.length)
    val centre = new Array[Double](3 * all.length)
    // The shapes with bounds from the start, those without from the end (in reverse), found on
    // one pass: Shape.bounds is asked once a shape.
    val found = new Array[Int](all.length)
    // Perf: the shapes with bounds, their boxes written as they are found, so no Bounds outlives
    // its shape's turn (a million-triangle mesh kept 140 MB of them alive; docs/performance.md).
    // The loop's body is one call: a loop of fewer turns than the JIT's on-stack threshold
    // (60,000) runs in the interpreter throughout, a method is compiled after a few hundred calls
    // (the 5 MB scene's 20,000 triangles: 36 -> 14 ms; docs/performance.md, round 22).
    var i = 0
    var k = 0
    while i < all.length do
      if boxed(all(i), boxLo, boxHi, centre, k) then
        found(k) = i
        k += 1
      else found(all.length - 1 - (i - k)) = i
      i += 1
    val without = java.util.Arrays.copyOfRange(found, k, all.length).reverse
    new BvhBuilder(
      boxLo,
      boxHi,
      centre,
      java.util.Arrays.copyOf(found, k),
      without,
      wholeLeaf(k, rays)
    )

  /** Writes the box of `shape` as primitive `k` and answers true, if it has bounds. */
  private def boxed(
      shape: Shape,
      boxLo: Array[Float],
      boxHi: Array[Float],
      centre: Array[Double],
      k: Int
  ): Boolean =
    Shape.bounds(shape) match
      case Some(b) =>
        setBox(boxLo, boxHi, centre, k, 0, b.lo.x, b.hi.x)
        setBox(boxLo, boxHi, centre, k, 1, b.lo.y, b.hi.y)
        setBox(boxLo, boxHi, centre, k, 2, b.lo.z, b.hi.z)
        true
      case None => false

  /** The builder over the faces of `mesh`, each boxed by its three corners, on `pool` when one
    * is given (in parts, as [[inParts]]), for a tree that about `rays` rays will walk.
    */
  def faces(
      mesh: Mesh,
      pool: Option[ExecutionContext] = None,
      rays: Long = Long.MaxValue
  ): BvhBuilder =
    val n      = mesh.faceCount
    val boxLo  = new Array[Float](3 * n)
    val boxHi  = new Array[Float](3 * n)
    val centre = new Array[Double](3 * n)
    inParts(n, pool)((from, to) => boxFaces(mesh, boxLo, boxHi, centre, from, to))
    new BvhBuilder(
      boxLo,
      boxHi,
      centre,
      Array.range(0, n),
      Array.emptyIntArray,
      wholeLeaf(n, rays, MaxFaceLeaf),
      MaxFaceLeaf,
      FaceVisit
    )

  /** Runs `part(from, to)` over consecutive ranges covering 0 until n: on `pool`, when one is
    * given and n is at least [[ParallelFrom]], in parts of [[Part]], and waits for them all; else
    * once on this thread. The parts must write disjoint places.
    *
    * Perf: the passes over a big mesh's faces before and after its build ran on one thread, cold
    * (a tenth of the 1.3M-face mesh's whole run); in parts they run on both threads, and the
    * method that does a part is compiled after the first few (docs/performance.md, round 8).
    */
  def inParts(n: Int, pool: Option[ExecutionContext])(part: (Int, Int) => Unit): Unit =
    pool match
      case Some(context) if n >= ParallelFrom =>
        given ExecutionContext = context
        val parts = (0 until n by Part).map(from => Future(part(from, Math.min(n, from + Part))))
        Await.result(Future.sequence(parts), Duration.Inf): Unit
      case _ => part(0, n)

  /** Writes the boxes of `mesh`'s faces from until to. */
  private def boxFaces(
      mesh: Mesh,
      boxLo: Array[Float],
      boxHi: Array[Float],
      centre: Array[Double],
      from: Int,
      to: Int
  ): Unit =
    val v = mesh.vertices
    val c = mesh.corners
    // Perf: one pass over the faces on the mesh's arrays, no Bounds or Triangle per face.
    var f = from
    while f < to do
      val i0 = 3 * c(3 * f); val i1 = 3 * c(3 * f + 1); val i2 = 3 * c(3 * f + 2)
      var a  = 0
      while a < 3 do
        val x0 = v(i0 + a); val x1 = v(i1 + a); val x2 = v(i2 + a)
        setBox(
          boxLo,
          boxHi,
          centre,
          f,
          a,
          Math.min(Math.min(x0, x1), x2),
          Math.max(Math.max(x0, x1), x2)
        )
        a += 1
      f += 1

  /** Primitive k's extent along `axis`, padded so flat boxes (a triangle in a plane) have depth,
    * its box rounded outwards to floats.
    */
  private def setBox(
      boxLo: Array[Float],
      boxHi: Array[Float],
      centre: Array[Double],
      k: Int,
      axis: Int,
      low: Double,
      high: Double
  ): Unit =
    val pad = 1e-9 * (1 + Math.abs(low) + Math.abs(high))
    boxLo(3 * k + axis) = WideTree.down(low - pad)
    boxHi(3 * k + axis) = WideTree.up(high + pad)
    centre(3 * k + axis) = (low + high) / 2

  /** A subtree left for the pool: its node, primitives, depth, first free node number and what
    * its parent's bins told of it.
    */
  private final case class Task(
      node: Int,
      start: Int,
      end: Int,
      depth: Int,
      free: Int,
      known: Known
  )

  /** A node's centroids' box from its parent's bins (its own box then written already), when
    * `found`.
    */
  private final case class Known(
      found: Boolean,
      lo0: Double,
      lo1: Double,
      lo2: Double,
      hi0: Double,
      hi1: Double,
      hi2: Double
  )

  private object Known:
    /** Nothing known: the node finds its boxes from its primitives. */
    val None: Known = Known(false, 0, 0, 0, 0, 0, 0)

  /** One thread's scratch space for a split: per-bin counts and boxes, and the sweeps' results. */
  private final class Scratch:
    val binCount = new Array[Int](Bins)
    val binLo    = new Array[Double](3 * Bins)
    val binHi    = new Array[Double](3 * Bins)
    val leftCost = new Array[Double](Bins)
    val binCLo   = new Array[Double](3 * Bins)
    val binCHi   = new Array[Double](3 * Bins)

    /** The cost of the split [[BvhBuilder.cheapest]] found last. */
    // Why: written by each node's sweep and read back at once by the same thread.
    var bestCost = Double.PositiveInfinity

    /** When `binned`: writes the box of bins `from` to `to` into `boxes` at `at` and returns
      * their centroids' box; else [[Known.None]].
      */
    def side(binned: Boolean, from: Int, to: Int, at: Int, boxes: Array[Float]): Known =
      if !binned then Known.None
      else
        // Why: the bins' boxes gathered in a counted loop.
        var l0, l1, l2, c0, c1, c2 = Double.PositiveInfinity
        // Why: as l0.
        var h0, h1, h2, d0, d1, d2 = Double.NegativeInfinity
        var b                      = from
        while b <= to do
          l0 = Math.min(l0, binLo(3 * b)); l1 = Math.min(l1, binLo(3 * b + 1))
          l2 = Math.min(l2, binLo(3 * b + 2))
          h0 = Math.max(h0, binHi(3 * b)); h1 = Math.max(h1, binHi(3 * b + 1))
          h2 = Math.max(h2, binHi(3 * b + 2))
          c0 = Math.min(c0, binCLo(3 * b)); c1 = Math.min(c1, binCLo(3 * b + 1))
          c2 = Math.min(c2, binCLo(3 * b + 2))
          d0 = Math.max(d0, binCHi(3 * b)); d1 = Math.max(d1, binCHi(3 * b + 1))
          d2 = Math.max(d2, binCHi(3 * b + 2))
          b += 1
        // The bins' boxes are the primitives' floats, so these conversions are exact.
        boxes(at) = l0.toFloat; boxes(at + 1) = l1.toFloat; boxes(at + 2) = l2.toFloat
        boxes(at + 3) = h0.toFloat; boxes(at + 4) = h1.toFloat; boxes(at + 5) = h2.toFloat
        Known(true, c0, c1, c2, d0, d1, d2)

  /** The fewest primitives worth building on a pool. */
  val ParallelFrom = 65536

  /** The faces of one part of [[inParts]]: many more parts than threads. */
  val Part = 32768

  /** The most primitives of a subtree built whole by one task on a pool: many more subtrees
    * than threads (about a hundred for the 1.3M-face mesh), so they keep the threads evenly busy.
    */
  val Grain = 16384

  /** The most shapes a leaf holds when splitting would cost more. */
  val MaxLeaf = 4

  /** The most faces a mesh's leaf holds when splitting would cost more.
    *
    * Perf: with [[FaceVisit]], a mesh's tree has fewer, larger leaves where the faces are close
    * together: fewer nodes to visit (each about 30 ns, more deep in a large tree, whose lower
    * levels miss the caches) for more face tests, read in order. Whole runs (docs/performance.md,
    * round 32): 1280×720 mesh-5000 631 → 611 ms, mesh-80000 1036 → 992, 3840×2160 mesh-20000 2816
    * → 2773. The scene's own tree keeps [[MaxLeaf]] and no visit cost: the gallery's solids, whose
    * leaves hold costly shapes, ran 1170 → 1229 with them.
    */
  val MaxFaceLeaf = 8

  /** What visiting a node of a mesh's tree costs, in face tests, when a split is weighed. */
  val FaceVisit = 2.0

  /** The most primitives a node of a tree over `n` primitives holds that is made a leaf without
    * weighing a split, when about `rays` rays will walk the tree and a leaf holds at most
    * `largest` when a split is weighed: `largest` / 2 when the rays are as many as the primitives
    * or more, else about n / rays, up to [[CoarseLeaf]].
    *
    * Perf: a tree's last levels are most of its build (every primitive binned once a level, and
    * seven in eight of its nodes), and they pay only when enough rays walk them: a picture of 8 × 8
    * pixels of the 1.3M-face mesh built it to leaves of 4 faces; with leaves up to 64 its world is
    * made in 30% less time and 110 MB less memory (docs/performance.md, round 24). The answers
    * are the same whatever the leaves (`BvhProperties`).
    */
  def wholeLeaf(n: Int, rays: Long, largest: Int = MaxLeaf): Int =
    Math.max(largest / 2, Math.min(CoarseLeaf.toLong, n / Math.max(1L, rays)).toInt)

  /** The largest leaf [[wholeLeaf]] makes for a short render of many primitives. */
  val CoarseLeaf = 64

  /** The smallest leaves that [[BvhBuilder.build]] builds in Morton order ([[LinearBuild]]):
    * a render of at most an eighth as many rays as primitives.
    */
  val LinearLeaf = 8

  /** SAH bins per split. */
  val Bins = 16

  /** The deepest a leaf may lie below the root; a node there is a leaf, however many it holds. */
  val MaxDepth = 128

/** A [[Tree]] collapsed into a 4-wide tree (Wald et al. 2008, "Getting rid of packets"): each
  * node holds up to four children, each either a node or a leaf's range of primitives, with the
  * four child boxes in single precision, rounded outwards so that every ray that meets a double
  * box meets its float one, in structure-of-arrays order: node n's floats at 24n, the low x of
  * its four children first, then low y, low z, high x, high y, high z. `child(4n + c)` is the
  * node or first primitive of child c and `count(4n + c)` its number of primitives (0 for a
  * node, −1 for an empty slot). Node 0 is the root.
  */
private[render] final class WideTree(
    val size: Int,
    val boxes: Array[Float],
    val child: Array[Int],
    val count: Array[Int]
)

/** Collapsing a binary [[Tree]] into a [[WideTree]]. */
private[render] object WideTree:
  /** Children per node. */
  val Width = 4

  /** The wide tree of `tree`: each node takes its binary node's two children and opens the child
    * of largest surface area that is not a leaf, until it has four or only leaves. On `pool`,
    * when one is given and the tree is big, the subtrees below the root's node are counted and
    * filled as tasks of their own, each at the numbers the walk on one thread gives them (the
    * same arrays, `MeshProperties`).
    */
  def collapse(tree: Tree, pool: Option[ExecutionContext] = None): WideTree =
    val gather = Gather(tree)
    // Perf: a first walk counts the wide nodes, so the arrays are sized exactly (sized as if
    // every binary node became a wide one, they held three times the nodes made: 128 MB too
    // many for the 1.3M-face mesh; docs/performance.md, round 7), then filled once. On a pool
    // both walks run on the threads, a subtree a task (they were a twentieth of the 1.3M-face
    // mesh's whole run on one thread; round 8).
    if tree.size == 0 then
      WideTree(0, new Array[Float](24), new Array[Int](Width), new Array[Int](Width))
    else
      pool match
        case Some(context) if tree.size >= BvhBuilder.ParallelFrom =>
          given ExecutionContext = context
          val kids               = new Array[Int](Width)
          val top                = java.util.Arrays.copyOf(kids, gather(0, kids))
          val sizes              = Await.result(
            Future.traverse(top.toVector)(b =>
              Future(if gather.isLeaf(b) then 0 else gather.count(b))
            ),
            Duration.Inf
          )
          // The number of each inner child's wide node: its subtree follows the earlier ones'.
          val starts = sizes.scanLeft(1)(_ + _)
          val fill   = Fill(tree, gather, starts.last)
          fill.slots(0, top)
          top.indices.foreach(c => fill.link(0, c, top(c), starts(c)))
          val inner = top.indices.filter(c => !gather.isLeaf(top(c))).toVector
          Await.result(
            Future.traverse(inner)(c => Future(fill.make(top(c), starts(c)))),
            Duration.Inf
          ): Unit
          WideTree(starts.last, fill.boxes, fill.child, fill.count)
        case _ =>
          val n    = gather.count(0)
          val fill = Fill(tree, gather, n)
          val _    = fill.make(0, 0)
          WideTree(n, fill.boxes, fill.child, fill.count)

  /** The arrays of a wide tree of `n` nodes over `tree`, and the walk that fills them. */
  private final class Fill(tree: Tree, gather: Gather, n: Int):
    val boxes = new Array[Float](24 * n)
    val child = new Array[Int](Width * n)
    val count = new Array[Int](Width * n)

    /** Fills wide node `w` for binary node `binary` and the nodes below it, numbered from w + 1
      * on in the order they are met (depth first, children in order); returns the first number
      * after them.
      */
    def make(binary: Int, w: Int): Int =
      val kids = new Array[Int](Width)
      val mine = java.util.Arrays.copyOf(kids, gather(binary, kids))
      slots(w, mine)
      // Why: the next free number, advanced by each inner child's subtree, in a counted loop.
      var next = w + 1
      var c    = 0
      while c < mine.length do
        val b = mine(c)
        link(w, c, b, next)
        if !gather.isLeaf(b) then next = make(b, next)
        c += 1
      next

    /** Writes wide node w's child boxes for the binary nodes `mine`, rounded outwards, and marks
      * the slots past them empty.
      */
    def slots(w: Int, mine: Array[Int]): Unit =
      // Why: loops over the slots and their axes.
      var c = 0
      while c < Width do
        val at = 24 * w + c
        if c < mine.length then
          val b = mine(c)
          var a = 0
          while a < 3 do
            boxes(at + 4 * a) = down(tree.boxes(6 * b + a))
            boxes(at + 12 + 4 * a) = up(tree.boxes(6 * b + 3 + a))
            a += 1
        else
          var a = 0
          while a < 3 do
            boxes(at + 4 * a) = Float.PositiveInfinity
            boxes(at + 12 + 4 * a) = Float.NegativeInfinity
            a += 1
          count(Width * w + c) = -1
        c += 1

    /** Writes slot c of wide node w: binary node b's leaf range, or (an inner node) the wide node
      * numbered `at`.
      */
    def link(w: Int, c: Int, b: Int, at: Int): Unit =
      if gather.isLeaf(b) then
        child(Width * w + c) = tree.links(2 * b)
        count(Width * w + c) = tree.links(2 * b + 1)
      else
        child(Width * w + c) = at
        count(Width * w + c) = 0

  /** The choice of a wide node's children in `tree`, shared by the counting and filling walks. */
  private final class Gather(tree: Tree):
    /** True when binary node `b` is a leaf. */
    def isLeaf(b: Int): Boolean = tree.links(2 * b + 1) > 0

    private def area(b: Int) =
      // In double precision, as when the binary tree's boxes were doubles.
      val x = tree.boxes(6 * b + 3).toDouble - tree.boxes(6 * b)
      val y = tree.boxes(6 * b + 4).toDouble - tree.boxes(6 * b + 1)
      val z = tree.boxes(6 * b + 5).toDouble - tree.boxes(6 * b + 2)
      x * y + y * z + z * x

    /** Writes the binary nodes that become the children of the wide node made for `binary` into
      * `kids` and returns their number: its two children, then the child of largest surface
      * area that is not a leaf opened, until four or only leaves.
      */
    def apply(binary: Int, kids: Array[Int]): Int =
      // Why: the children gathered by opening the largest inner child, a loop on local arrays.
      var m = 0
      if isLeaf(binary) then
        kids(0) = binary; m = 1
      else
        kids(0) = tree.links(2 * binary); kids(1) = kids(0) + 1; m = 2
      // Why: as m.
      var open = true
      while m < Width && open do
        // Why: the best inner child so far, a scan of the few gathered.
        var best = -1
        var k    = 0
        while k < m do
          if !isLeaf(kids(k)) && (best < 0 || area(kids(k)) > area(kids(best))) then best = k
          k += 1
        if best < 0 then open = false
        else
          val left = tree.links(2 * kids(best))
          kids(best) = left
          kids(m) = left + 1
          m += 1
      m

    /** The number of wide nodes the wide node made for `binary` and its descendants take. */
    def count(binary: Int): Int =
      val kids = new Array[Int](Width)
      val m    = apply(binary, kids)
      // Why: a counted loop over the few children.
      var total = 1
      var c     = 0
      while c < m do
        if !isLeaf(kids(c)) then total += count(kids(c))
        c += 1
      total

  /** The largest float at or below `x`. */
  def down(x: Double): Float =
    val f = x.toFloat
    if f.toDouble > x then Math.nextDown(f) else f

  /** The smallest float at or above `x`. */
  def up(x: Double): Float =
    val f = x.toFloat
    if f.toDouble < x then Math.nextUp(f) else f
