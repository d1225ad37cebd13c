package tracer.render

import scala.concurrent.duration.Duration
import scala.concurrent.{Await, ExecutionContext, Future}

/** A quick build of a coarse [[Tree]] for a short render of many primitives: the primitives in
  * the order of the Morton codes of their centres (a linear BVH, Lauterbach et al. 2009), each
  * node split where its range's codes first differ, down to leaves of at most `whole`
  * primitives, each node's box the union of its children's.
  *
  * Perf: a sort and a pass a level over integers, where the binned SAH bins every primitive's
  * box at every level: the tree is worse for many rays, so [[BvhBuilder]] builds it only for
  * renders that trace far fewer rays than there are primitives ([[BvhBuilder.LinearLeaf]]); the
  * answers are the same whatever the tree (`BvhProperties`). The 1.3M-face mesh at 8 × 8 pixels
  * (docs/performance.md, round 24).
  */
private[render] object LinearBuild:

  /** Cells of the grid along each axis that the codes quantise the centres to (10 bits). */
  private val Cells = 1024

  /** The tree over the primitives `prims` (their boxes at 3k in `boxLo` and `boxHi`, their
    * centres at 3k in `centre`), its nodes written into `boxes` and `links` (sized for 2n − 1
    * nodes, as [[BvhBuilder]]'s), its order replacing `prims`' in place; on `pool` when one is
    * given (the passes over the primitives in parts, the subtrees below [[BvhBuilder.Grain]]
    * primitives as tasks), to the same tree.
    */
  def apply(
      boxLo: Array[Float],
      boxHi: Array[Float],
      centre: Array[Double],
      prims: Array[Int],
      without: Array[Int],
      whole: Int,
      boxes: Array[Float],
      links: Array[Int],
      pool: Option[ExecutionContext] = None
  ): Tree =
    val n    = prims.length
    val keys = sortedKeys(centre, n, pool)
    val tree = Nodes(boxLo, boxHi, keys, whole, boxes, links)
    val made = pool match
      case Some(context) if n >= BvhBuilder.ParallelFrom => tree.onPool(n)(using context)
      case _                                             => tree.node(0, 0, n, 0, 1)
    // The primitives in leaf order: position k of the leaves holds the primitive that was at
    // the low half of its key.
    val order = new Array[Int](n)
    BvhBuilder.inParts(n, pool)((from, to) => ordered(prims, keys, order, from, to))
    System.arraycopy(order, 0, prims, 0, n)
    Tree(made, boxes, links, prims, without)

  /** Writes positions from until to of the leaf order. */
  private def ordered(
      prims: Array[Int],
      keys: Array[Long],
      order: Array[Int],
      from: Int,
      to: Int
  ): Unit =
    var k = from // Why: a plain loop over the positions.
    while k < to do
      order(k) = prims(keys(k).toInt)
      k += 1

  /** Each primitive's key, its Morton code above its position, in increasing order. */
  private def sortedKeys(
      centre: Array[Double],
      n: Int,
      pool: Option[ExecutionContext]
  ): Array[Long] =
    // The centres' box: each part's, then theirs.
    val parts = (n + BvhBuilder.Part - 1) / BvhBuilder.Part
    // A part that the work did not come to (one thread does them all as the first) stays empty.
    val box = Array.tabulate(6 * parts)(j =>
      if j % 6 < 3 then Double.PositiveInfinity else Double.NegativeInfinity
    )
    BvhBuilder.inParts(n, pool)((from, to) =>
      centreBox(centre, from, to, box, from / BvhBuilder.Part)
    )
    // Why: the box of the parts' boxes, widened by each.
    var lx, ly, lz = Double.PositiveInfinity
    // Why: as lx.
    var hx, hy, hz = Double.NegativeInfinity
    var p          = 0
    while p < parts do
      lx = Math.min(lx, box(6 * p)); ly = Math.min(ly, box(6 * p + 1))
      lz = Math.min(lz, box(6 * p + 2)); hx = Math.max(hx, box(6 * p + 3))
      hy = Math.max(hy, box(6 * p + 4)); hz = Math.max(hz, box(6 * p + 5))
      p += 1
    val keys = new Array[Long](n)
    val grid = Array(lx, ly, lz, hx, hy, hz)
    BvhBuilder.inParts(n, pool)((from, to) => codes(centre, grid, keys, from, to))
    byCode(keys)

  /** Writes the box of the centres from until to at 6p of `box` (lows, then highs). */
  private def centreBox(
      centre: Array[Double],
      from: Int,
      to: Int,
      box: Array[Double],
      p: Int
  ): Unit =
    // Perf: the box in locals, widened in a plain loop over the centres.
    // Why: the box of the centres, widened by each.
    var lx, ly, lz = Double.PositiveInfinity
    // Why: as lx.
    var hx, hy, hz = Double.NegativeInfinity
    var k          = from
    while k < to do
      lx = Math.min(lx, centre(3 * k)); hx = Math.max(hx, centre(3 * k))
      ly = Math.min(ly, centre(3 * k + 1)); hy = Math.max(hy, centre(3 * k + 1))
      lz = Math.min(lz, centre(3 * k + 2)); hz = Math.max(hz, centre(3 * k + 2))
      k += 1
    box(6 * p) = lx; box(6 * p + 1) = ly; box(6 * p + 2) = lz
    box(6 * p + 3) = hx; box(6 * p + 4) = hy; box(6 * p + 5) = hz

  /** Writes the keys of the primitives from until to, their centres placed on the grid over the
    * box `grid` (lows, then highs).
    */
  private def codes(
      centre: Array[Double],
      grid: Array[Double],
      keys: Array[Long],
      from: Int,
      to: Int
  ): Unit =
    var k = from // Why: a plain loop over the primitives.
    while k < to do
      val code = spread(cell(centre(3 * k), grid(0), grid(3))) << 2 |
        spread(cell(centre(3 * k + 1), grid(1), grid(4))) << 1 |
        spread(cell(centre(3 * k + 2), grid(2), grid(5)))
      keys(k) = code << 32 | k
      k += 1

  /** `keys` sorted by their codes (bits 32 to 61), those of equal codes in the order given: a
    * radix sort of three passes of ten bits.
    *
    * Perf: three counting passes over the keys, where `java.util.Arrays.sort` took a third of the
    * 1.3M-face mesh's build (docs/performance.md, round 24).
    */
  private def byCode(keys: Array[Long]): Array[Long] =
    // Why: each pass moves the keys from one array to the other, counting in `count`.
    var from  = keys
    var to    = new Array[Long](keys.length)
    val count = new Array[Int](Cells)
    var shift = 32
    while shift < 62 do
      java.util.Arrays.fill(count, 0)
      var k = 0
      while k < from.length do
        count(((from(k) >>> shift) & (Cells - 1)).toInt) += 1
        k += 1
      var sum = 0
      var d   = 0
      while d < Cells do
        val c = count(d)
        count(d) = sum
        sum += c
        d += 1
      k = 0
      while k < from.length do
        val digit = ((from(k) >>> shift) & (Cells - 1)).toInt
        to(count(digit)) = from(k)
        count(digit) += 1
        k += 1
      val done = to
      to = from
      from = done
      shift += 10
    from

  /** The cell of `x` along an axis whose centres span lo..hi (0 when they do not spread). */
  private def cell(x: Double, lo: Double, hi: Double): Int =
    if !(hi > lo) then 0 else Math.min(Cells - 1, ((x - lo) / (hi - lo) * Cells).toInt)

  /** The ten bits of `v` spread to every third bit (bit i to bit 3i). */
  private def spread(v: Int): Long =
    var x = v.toLong & 0x3ff // Why: the bits moved apart in four steps.
    x = (x | (x << 16)) & 0x30000ffL
    x = (x | (x << 8)) & 0x300f00fL
    x = (x | (x << 4)) & 0x30c30c3L
    x = (x | (x << 2)) & 0x9249249L
    x

  /** The nodes' writer over the sorted keys. */
  private final class Nodes(
      boxLo: Array[Float],
      boxHi: Array[Float],
      keys: Array[Long],
      whole: Int,
      boxes: Array[Float],
      links: Array[Int]
  ):
    /** Fills node `node` with leaf positions start until end, its children numbered from `free`
      * (the subtree's own range, as [[BvhBuilder]] numbers them). Returns the nodes made.
      */
    def node(node: Int, start: Int, end: Int, depth: Int, free: Int): Int =
      val n = end - start
      if n <= whole || depth >= BvhBuilder.MaxDepth then
        links(2 * node) = start; links(2 * node + 1) = n
        leafBox(6 * node, start, end)
        1
      else
        val mid  = middle(start, end)
        val left = free
        links(2 * node) = left; links(2 * node + 1) = 0
        val l = this.node(left, start, mid, depth + 1, free + 2)
        val r = this.node(left + 1, mid, end, depth + 1, free + 2 * (mid - start))
        union(node, left)
        1 + l + r

    /** [[node]] of the root over all `n` positions, with each subtree of at most
      * [[BvhBuilder.Grain]] positions built by a task of its own on the pool: the same tree.
      */
    def onPool(n: Int)(using ExecutionContext): Int =
      val tasks = Vector.newBuilder[(Int, Int, Int, Int, Int)]
      val above = Vector.newBuilder[(Int, Int)]
      plan(0, 0, n, 0, 1, tasks, above)
      val below =
        Future.traverse(tasks.result())((node, start, end, depth, free) =>
          Future(this.node(node, start, end, depth, free))
        )
      val made = Await.result(below, Duration.Inf).sum
      // The nodes above the tasks, children before parents: each box from its children's.
      val linked = above.result()
      linked.foreach(union.tupled)
      linked.size + made

    /** Links the nodes above the tasks (subtrees of more than [[BvhBuilder.Grain]] positions)
      * as [[node]] does, handing each subtree below to `tasks` and each node linked, with its
      * left child, to `above`, after its children.
      */
    private def plan(
        node: Int,
        start: Int,
        end: Int,
        depth: Int,
        free: Int,
        tasks: scala.collection.mutable.Builder[(Int, Int, Int, Int, Int), ?],
        above: scala.collection.mutable.Builder[(Int, Int), ?]
    ): Unit =
      if end - start <= BvhBuilder.Grain || depth >= BvhBuilder.MaxDepth then
        tasks += ((node, start, end, depth, free))
      else
        val mid  = middle(start, end)
        val left = free
        links(2 * node) = left; links(2 * node + 1) = 0
        plan(left, start, mid, depth + 1, free + 2, tasks, above)
        plan(left + 1, mid, end, depth + 1, free + 2 * (mid - start), tasks, above)
        above += ((node, left))

    /** Writes the box of inner node `node`: the union of its children's, at `left` and after. */
    private def union(node: Int, left: Int): Unit =
      var a = 0 // Why: the box's six numbers, the children's lows and highs.
      while a < 3 do
        boxes(6 * node + a) = Math.min(boxes(6 * left + a), boxes(6 * left + 6 + a))
        boxes(6 * node + 3 + a) = Math.max(boxes(6 * left + 3 + a), boxes(6 * left + 9 + a))
        a += 1

    /** Where positions start until end split: the first whose code has the highest bit in which
      * the range's codes differ, or the middle when they are all the same.
      */
    private def middle(start: Int, end: Int): Int =
      val first = keys(start) >>> 32
      val last  = keys(end - 1) >>> 32
      if first == last then (start + end) >>> 1
      else
        val bit = 63 - java.lang.Long.numberOfLeadingZeros(first ^ last)
        // Why: a binary search for the first code with the bit set (the range shares the bits
        // above it, so those without it come first).
        var lo = start + 1
        var hi = end - 1
        while lo < hi do
          val m = (lo + hi) >>> 1
          if ((keys(m) >>> 32) >>> bit & 1L) != 0 then hi = m else lo = m + 1
        lo

    /** The box of the primitives at positions start until end, written at `at` of `boxes`. */
    private def leafBox(at: Int, start: Int, end: Int): Unit =
      // Why: the box, widened by each primitive's in a loop over the range.
      var x0, y0, z0 = Float.PositiveInfinity
      // Why: as x0.
      var x1, y1, z1 = Float.NegativeInfinity
      var k          = start
      while k < end do
        val p = 3 * keys(k).toInt
        x0 = Math.min(x0, boxLo(p)); y0 = Math.min(y0, boxLo(p + 1));
        z0 = Math.min(z0, boxLo(p + 2))
        x1 = Math.max(x1, boxHi(p)); y1 = Math.max(y1, boxHi(p + 1));
        z1 = Math.max(z1, boxHi(p + 2))
        k += 1
      boxes(at) = x0; boxes(at + 1) = y0; boxes(at + 2) = z0
      boxes(at + 3) = x1; boxes(at + 4) = y1; boxes(at + 5) = z1
