package tracer.render

import scala.concurrent.ExecutionContext
import tracer.geometry.{Mesh, Shape, Triangle}
import tracer.math.Vec3

/** A bounding volume hierarchy over the bounded shapes of a scene, built once with the binned
  * surface area heuristic ([[BvhBuilder]]) and stored as flat arrays, with its primitives in leaf
  * order ([[Primitives]]): the ray kernel.
  *
  * It is an immutable value after construction. Queries take their scratch space from the caller
  * (a [[Query]] per render task), so that tracing a ray allocates nothing.
  *
  * @param shapes the shapes it indexes; those without bounds (planes) are left out
  * @param pool   where to build it and its meshes' trees: the render's threads, or the calling
  *   thread for `None`
  * @param lanes  whether a tree of so many wide nodes walks with the Vector API's four-box test
  *   ([[BvhLanes]]): the same answers (`BvhProperties`); by default [[LaneSupport.choose]]. Its
  *   meshes choose for themselves.
  * @param known  the trees already built for some of its meshes (another hierarchy's), reused
  * @param rays   about how many rays the render will trace: a tree (or a mesh's) of many more
  *   primitives gets coarser leaves ([[BvhBuilder.wholeLeaf]]); by default the finest
  */
final class Bvh(
    shapes: IndexedSeq[Shape],
    pool: Option[ExecutionContext] = None,
    lanes: Int => Boolean = LaneSupport.choose,
    known: Mesh => Option[MeshTree] = _ => None,
    rays: Long = Long.MaxValue
):
  private val tree  = BvhBuilder(shapes, rays).build(pool)
  private val boxes = tree.boxes
  private val links = tree.links
  private val prims = Primitives(shapes, tree.order, pool, known, rays)
  private val wide  = WideTree.collapse(tree)
  private val wb    = wide.boxes
  private val wc    = wide.child
  private val wn    = wide.count
  // The walks with four boxes at a time, when asked for (a class of their own, loaded only then:
  // no function names it, whose class would load it, and the start-up cache keeps neither, since
  // it needs the Vector API's module; docs/performance.md, round 23).
  private val fast: Option[BvhLanes] =
    if lanes(wide.size) then Some(BvhLanes(wide, prims)) else None

  /** The tree built for each of the `count` shapes that is one of this hierarchy's meshes, by
    * the shape's index (see [[Primitives.treesByShape]]).
    */
  private[render] def meshTrees(count: Int): Array[Option[MeshTree]] = prims.treesByShape(count)

  /** The tree built for `mesh`, one of this hierarchy's shapes (see [[Primitives.treeOf]]). */
  private[render] def meshTree(mesh: Mesh): Option[MeshTree] = prims.treeOf(mesh)

  /** The indices, in order, of the shapes left out of the hierarchy for having no bounds. */
  val unbounded: Array[Int] = tree.unbounded

  /** The number of nodes of the 4-wide tree the queries walk, for tests and benchmarks. */
  def wideNodeCount: Int = wide.size

  /** The number of nodes, for tests and benchmarks. */
  def nodeCount: Int = tree.size

  /** The number of nodes on the longest path from the root to a leaf (0 for no tree), for tests. */
  def depth: Int =
    def below(n: Int): Int =
      if links(2 * n + 1) > 0 then 1 else 1 + Math.max(below(links(2 * n)), below(links(2 * n) + 1))
    if tree.size == 0 then 0 else below(0)

  /** The index in `shapes` of the shape the ray from (ox, oy, oz) in unit direction (dx, dy, dz)
    * hits first, competing with a candidate already found: shape `limitIndex` at distance `limit`
    * (use `Int.MaxValue` and +∞ for none). Ties go to the lower index, as in a plain loop over all
    * shapes. The winner's distance is left in `query.distance`, and when it is a mesh, the face
    * hit in `query.face`.
    */
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
    if prims.size == 1 then nearestOfOne(ox, oy, oz, dx, dy, dz, limit, limitIndex, query)
    else
      fast match
        case Some(lanes) => lanes.nearest(ox, oy, oz, dx, dy, dz, limit, limitIndex, query)
        case None        =>
          BvhWalk.nearest(
            wide.size,
            wc,
            wn,
            prims,
            ox,
            oy,
            oz,
            dx,
            dy,
            dz,
            limit,
            limitIndex,
            query
          ) { (node, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
            WideWalk.push(
              wb,
              wn,
              node,
              sp,
              stack,
              entries,
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

  /** [[nearest]] in a tree of one primitive (a scene's one bounded shape, such as a mesh over
    * a plane): the primitive's own test, without the tree's box.
    *
    * Perf: a box only leaves out rays that cannot meet what it holds, so the answer is the
    * walk's, without its box test and its three divisions (a mesh's walk makes its own; 3% of
    * the 4K mesh scenes' samples; docs/performance.md, round 50).
    */
  private def nearestOfOne(
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
    val t = Primitives.distance(prims, 0, limit, ox, oy, oz, dx, dy, dz, query)
    val i = prims.index(0)
    if t <= limit && t < Double.PositiveInfinity && (t < limit || i < limitIndex) then
      query.distance = t
      query.face = query.meshFace
      i
    else
      query.distance = limit
      query.face = -1
      limitIndex

  /** True when some indexed shape is hit by the ray (origin o, unit direction d) at a distance
    * below `limit`; stops at the first.
    */
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
    fast match
      case Some(lanes) => lanes.occluded(ox, oy, oz, dx, dy, dz, limit, query)
      case None        =>
        BvhWalk.occluded(wide.size, wc, wn, prims, ox, oy, oz, dx, dy, dz, limit, query) {
          (node, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
            WideWalk.push(
              wb,
              wn,
              node,
              sp,
              stack,
              entries,
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

  /** True when primitive `k` (in leaf order, as [[occluded]] leaves a blocker in
    * `query.blocker`) is met by the ray at a t below `limit`: [[Primitives.blocks]], except that
    * a mesh is walked from node `node` of its own tree down ([[MeshTree.occludedBelow]]). A
    * shadow ray's guess, tested before the walk ([[Shadows.pointToward]]).
    */
  def blocks(
      k: Int,
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
    if prims.kind(k) == Primitives.MeshKind then
      prims
        .meshes(prims.data(Primitives.Stride * k).toInt)
        .occludedBelow(node, ox, oy, oz, dx, dy, dz, limit, query)
    else Primitives.blocks(prims, k, limit, ox, oy, oz, dx, dy, dz, query)

  // Each shape's place in leaf order (−1 for one left out, unbounded), for ownBlocks.
  private val slots: Array[Int] =
    val places = new Array[Int](shapes.length)
    java.util.Arrays.fill(places, -1)
    // Why: a plain loop, run once per tree (no closure to interpret per shape).
    var k = 0
    while k < prims.size do
      places(prims.index(k)) = k
      k += 1
    places

  /** True when shape `i` (its face `face` when it is a mesh: the face a nearest query named) is
    * met by the ray at a t below `limit`, tested as the walks test it ([[Primitives.blocks]], a
    * mesh's face by [[MeshTree.faceBlocks]]); false for a shape the tree does not hold. A shadow
    * ray's first test of the surface it leaves ([[Shadows.pointToward]]).
    */
  def ownBlocks(
      i: Int,
      face: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    val k = slots(i)
    if k < 0 then false
    else if prims.kind(k) == Primitives.MeshKind then
      val mesh = prims.meshes(prims.data(Primitives.Stride * k).toInt)
      mesh.faceBlocks(mesh.leafFace(face), limit, ox, oy, oz, dx, dy, dz)
    else Primitives.blocks(prims, k, limit, ox, oy, oz, dx, dy, dz, query)

  /** The number of primitives in the tree's leaves, for tests. */
  def primitiveCount: Int = prims.size

  /** The number of [[BufferItems]] of its primitives: each mesh counts its faces. */
  val itemCount: Long =
    // Perf: counted once, in a plain loop: World asks for it several times while it is built,
    // cold, and 20,000 triangles' boxed sums showed in the loading row's profile (round 21).
    var count = 0L
    var k     = 0
    while k < prims.size do
      count +=
        (if prims.kind(k) == Primitives.MeshKind then
           prims.meshes(prims.data(Primitives.Stride * k).toInt).faceCount.toLong
         else 1L)
      k += 1
    count

  /** Its primitives as [[BufferItems]] for the [[LightBuffer]]s and the [[EyeBuffer]]: each that is not a
    * mesh, and each face of each mesh, with its box widened by 10⁻⁷ of its size, and with
    * `outlines` each triangle's corners.
    */
  def bufferItems(outlines: Boolean): BufferItems =
    val n       = itemCount.toInt
    val boxes   = new Array[Double](6 * n)
    val owner   = new Array[Int](n)
    val face    = new Array[Int](n)
    val corners = if outlines then new Array[Double](9 * n) else Array.emptyDoubleArray
    // Why: the next item's number.
    var i = 0
    // Perf: counted loops over the primitives, no `Range` closure boxing each number (4 MB of
    // `Integer`s for 80,000 faces, made while this code is still cold), and a big mesh's faces in
    // parts on the pool, as the tree's passes over them (18 ms on one thread, cold, for 80,000
    // faces, while the pool waited; docs/performance.md, round 37).
    var k = 0
    while k < prims.size do
      if prims.kind(k) == Primitives.MeshKind then
        val mesh  = prims.meshes(prims.data(Primitives.Stride * k).toInt)
        val first = i
        BvhBuilder.inParts(mesh.faceCount, pool)((from, to) =>
          Bvh.faceItems(mesh, k, first, from, to, boxes, owner, face, corners)
        )
        i += mesh.faceCount
      else
        // The tree holds only bounded shapes; a box without bounds would be tested on every ray.
        val inf      = Double.PositiveInfinity
        val shape    = prims.all(prims.index(k))
        val (lo, hi) = Shape
          .bounds(shape)
          .fold((Vec3(-inf, -inf, -inf), Vec3(inf, inf, inf)))(b => (b.lo, b.hi))
        boxes(6 * i) = lo.x; boxes(6 * i + 1) = lo.y; boxes(6 * i + 2) = lo.z
        boxes(6 * i + 3) = hi.x; boxes(6 * i + 4) = hi.y; boxes(6 * i + 5) = hi.z
        World.widen(boxes, 6 * i)
        shape match
          case t: Triangle if outlines =>
            for (c, j) <- Seq(t.t0, t.t1, t.t2).zipWithIndex do
              corners(9 * i + 3 * j) = c.x; corners(9 * i + 3 * j + 1) = c.y
              corners(9 * i + 3 * j + 2) = c.z
          case _ => if outlines then corners(9 * i) = Double.NaN
        owner(i) = k; face(i) = -1
        i += 1
      k += 1
    BufferItems(boxes, owner, face, corners)

  /** True when one of the items `list(from until to)` of light buffer `buffer` (built over
    * [[bufferItems]]) is met by the ray at a t below `limit` ([[itemBlocks]]); stops at the
    * first, and leaves it in `query.blockingItem`. The ray runs toward the buffer's light and
    * `limit` is its distance from there, so an item whose gap exceeds `limit` lies beyond the
    * ray's start and is skipped; the others are tested farthest from the light first, as a
    * shading point's blockers mostly lie near it.
    */
  private[render] def anyBlocks(
      buffer: LightBuffer,
      list: Array[Int],
      from: Int,
      to: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    // Perf: a plain loop over the cell's items, the hot loop of a shadow ray toward a point light
    // with a buffer (docs/performance.md, rounds 19 and 27). The list is in increasing order of
    // gap: the items beyond the start are its tail.
    val gaps = buffer.gaps
    var i    = to - 1
    while i >= from && gaps(list(i)) > limit do i -= 1
    while i >= from && !itemBlocks(buffer, list(i), ox, oy, oz, dx, dy, dz, limit, query) do i -= 1
    if i >= from then query.blockingItem = list(i)
    i >= from

  /** True when item `item` of light buffer `buffer` is met by the ray at a t below `limit`: with
    * the test the any-hit walk gives it ([[Primitives.blocks]], or the face's own test for a
    * mesh's face).
    */
  private[render] def itemBlocks(
      buffer: LightBuffer,
      item: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    val k = buffer.owner(item)
    val f = buffer.face(item)
    if f >= 0 then
      prims
        .meshes(prims.data(Primitives.Stride * k).toInt)
        .faceBlocks(f, limit, ox, oy, oz, dx, dy, dz)
    else Primitives.blocks(prims, k, limit, ox, oy, oz, dx, dy, dz, query)

  /** The index in `shapes` of the shape that the ray meets first among the items `list(from
    * until to)` (item i: primitive `owner(i)`, and its face `face(i)` when that is a mesh, as in
    * [[bufferItems]]; nondecreasing in `gaps`, each item's box's distance from a centre, rounded
    * down, that the ray starts no more than `behind` beyond), competing with shape
    * `best` at `query.distance` (its face in `query.face`, −1 for a shape that is not a mesh):
    * [[nearest]]'s answer among them, the distance and face left in the query. Ties go to the
    * lower index, then the lower face.
    */
  private[render] def nearestAmong(
      owner: Array[Int],
      face: Array[Int],
      gaps: Array[Float],
      list: Array[Int],
      from: Int,
      to: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      behind: Double,
      best: Int,
      query: Query
  ): Int =
    // Perf: a plain loop over a cell's items, nearest box first, stopping at the first box beyond
    // the best hit: the hot loop of a ray from the eye (docs/performance.md, round 20).
    var bestT = query.distance
    var bestI = best
    var bestF = query.face
    var i     = from
    while i < to && gaps(list(i)) <= bestT + behind do
      val item  = list(i)
      val k     = owner(item)
      val f     = face(item)
      val shape = prims.index(k)
      if f >= 0 then
        val mesh = prims.meshes(prims.data(Primitives.Stride * k).toInt)
        val t    = mesh.faceDistance(f, bestT, ox, oy, oz, dx, dy, dz)
        if t <= bestT && t < Double.PositiveInfinity then
          val number = mesh.faceNumber(f)
          if t < bestT || shape < bestI || shape == bestI && number < bestF then
            bestT = t; bestI = shape; bestF = number
      else
        val t = Primitives.distance(prims, k, bestT, ox, oy, oz, dx, dy, dz, query)
        if t <= bestT && t < Double.PositiveInfinity && (t < bestT || shape < bestI) then
          bestT = t; bestI = shape; bestF = -1
      i += 1
    query.distance = bestT
    query.face = bestF
    bestI

  /** True when some walk takes more than one node (of this tree or a mesh's): only then can a
    * shadow ray's guess ([[blocks]]) save a walk more than it costs.
    */
  val deep: Boolean = wide.size > 1 || prims.meshes.exists(_.nodeCount > 1)

  /** The index in `shapes` of primitive `k` (leaf order), for tests. */
  private[render] def shapeOf(k: Int): Int = prims.index(k)

  /** [[nearest]] on the binary tree the wide one was collapsed from: the same answers, kept to
    * measure what the wide tree gains (`WorldBench`).
    */
  def nearestBinary(
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
    // Perf: an iterative walk with an explicit stack, nearer child first, each child's entry
    // distance kept beside it so a popped node is pruned without a second box test, and the leaf
    // tests on flat arrays (docs/performance.md, round 4).
    val stack   = query.nodes
    val entries = query.entries
    var best    = limitIndex
    var bestT   = limit
    // Why: the face of the best hit so far, when that is a mesh's (Primitives.distance says).
    var face = -1
    WideWalk.walk(dx, dy, dz) { (ix, iy, iz, sx, sy, sz) =>
      var sp = 0
      val t0 =
        if tree.size == 0 then Double.PositiveInfinity
        else entry(0, ox, oy, oz, ix, iy, iz, sx, sy, sz, bestT)
      if t0 < Double.PositiveInfinity then
        stack(0) = 0; entries(0) = t0; sp = 1
      while sp > 0 do
        sp -= 1
        val node = stack(sp)
        // A node entered beyond the best hit so far cannot hold a nearer one (ties still count).
        if entries(sp) <= bestT then
          val count = links(2 * node + 1)
          if count > 0 then
            var k   = links(2 * node)
            val end = k + count
            while k < end do
              val t = Primitives.distance(prims, k, bestT, ox, oy, oz, dx, dy, dz, query)
              if t <= bestT && t < Double.PositiveInfinity then
                val i = prims.index(k)
                if t < bestT || i < best then
                  bestT = t
                  best = i
                  face = query.meshFace
              k += 1
          else
            val left = links(2 * node)
            val tl   = entry(left, ox, oy, oz, ix, iy, iz, sx, sy, sz, bestT)
            val tr   = entry(left + 1, ox, oy, oz, ix, iy, iz, sx, sy, sz, bestT)
            // Push the farther child first so the nearer one is visited next.
            if tl <= tr then
              if tr < Double.PositiveInfinity then
                stack(sp) = left + 1; entries(sp) = tr; sp += 1
              if tl < Double.PositiveInfinity then
                stack(sp) = left; entries(sp) = tl; sp += 1
            else
              if tl < Double.PositiveInfinity then
                stack(sp) = left; entries(sp) = tl; sp += 1
              if tr < Double.PositiveInfinity then
                stack(sp) = left + 1; entries(sp) = tr; sp += 1
    }
    query.distance = bestT
    query.face = face
    best

  /** [[occluded]] on the binary tree, as [[nearestBinary]]. */
  def occludedBinary(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    // Perf: any hit will do, so no ordering and an early exit (shadow rays); children are tested
    // before they are pushed, so a popped node is never tested twice.
    val stack = query.nodes
    WideWalk.walk(dx, dy, dz) { (ix, iy, iz, sx, sy, sz) =>
      var hit = false
      var sp  = 0
      if tree.size > 0 && entry(
          0,
          ox,
          oy,
          oz,
          ix,
          iy,
          iz,
          sx,
          sy,
          sz,
          limit
        ) < Double.PositiveInfinity
      then
        stack(0) = 0; sp = 1
      while sp > 0 && !hit do
        sp -= 1
        val node  = stack(sp)
        val count = links(2 * node + 1)
        if count > 0 then
          var k   = links(2 * node)
          val end = k + count
          while k < end && !hit do
            hit = Primitives.blocks(prims, k, limit, ox, oy, oz, dx, dy, dz, query)
            k += 1
        else
          val left = links(2 * node)
          if entry(left, ox, oy, oz, ix, iy, iz, sx, sy, sz, limit) < Double.PositiveInfinity then
            stack(sp) = left; sp += 1
          if entry(left + 1, ox, oy, oz, ix, iy, iz, sx, sy, sz, limit) < Double.PositiveInfinity
          then
            stack(sp) = left + 1; sp += 1
      hit
    }

  /** The distance at which a ray enters node `n`'s box, or +∞ when it misses it before `limit`.
    *
    * The slab test with near and far planes chosen by the direction's sign (`sx`: the near
    * corner's offset). An origin exactly on a slab's plane with a zero direction component gives
    * 0·∞ = NaN, which the comparisons ignore: such a ray counts as inside that slab, as it is.
    */
  private inline def entry(
      n: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double
  ): Double =
    // Perf: the slab test on the flat box array in local doubles, narrowed in place: a Bounds or a
    // pair of distances per node visited would allocate in the innermost loop.
    val b    = 6 * n
    var tmin = 0.0
    var tmax = limit
    val nx   = (boxes(b + sx) - ox) * ix
    val fx   = (boxes(b + 3 - sx) - ox) * ix
    if nx > tmin then tmin = nx
    if fx < tmax then tmax = fx
    val ny = (boxes(b + 1 + sy) - oy) * iy
    val fy = (boxes(b + 4 - sy) - oy) * iy
    if ny > tmin then tmin = ny
    if fy < tmax then tmax = fy
    val nz = (boxes(b + 2 + sz) - oz) * iz
    val fz = (boxes(b + 5 - sz) - oz) * iz
    if nz > tmin then tmin = nz
    if fz < tmax then tmax = fz
    if tmin <= tmax then tmin else Double.PositiveInfinity

/** The two walks down the scene's [[WideTree]], written once for both ways of testing a node's
  * child boxes, as [[MeshWalk]]'s.
  */
private[render] object BvhWalk:
  /** [[Bvh.nearest]] on the tree of `size` nodes (children `wc`, counts `wn`) over `prims`. */
  inline def nearest(
      size: Int,
      wc: Array[Int],
      wn: Array[Int],
      prims: Primitives,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      limitIndex: Int,
      query: Query
  )(
      inline push: (
          Int,
          Int,
          Array[Int],
          Array[Double],
          Double,
          Double,
          Double,
          Int,
          Int,
          Int,
          Double
      ) => Int
  ): Int =
    // Perf: the 4-wide tree, ordered: a node's four child boxes are tested together, the ones hit
    // pushed farthest first with their entry distances, so the nearest is walked next and a popped
    // slot beyond the best hit is dropped untested; leaves test the double-precision primitives
    // (docs/performance.md, round 5; WorldBench).
    val stack   = query.nodes
    val entries = query.entries
    var best    = limitIndex
    var bestT   = limit
    // Why: the face of the best hit so far, when that is a mesh's (Primitives.distance says).
    var face = -1
    WideWalk.walk(dx, dy, dz) { (ix, iy, iz, sx, sy, sz) =>
      var sp = WideWalk.seed(size, stack, entries)
      while sp > 0 do
        sp -= 1
        val slot = stack(sp)
        // A slot entered beyond the best hit so far cannot hold a nearer one (ties still count).
        if entries(sp) <= bestT then
          val count = WideWalk.count(wn, slot)
          if count > 0 then
            var k   = wc(slot)
            val end = k + count
            while k < end do
              val t = Primitives.distance(prims, k, bestT, ox, oy, oz, dx, dy, dz, query)
              if t <= bestT && t < Double.PositiveInfinity then
                val i = prims.index(k)
                if t < bestT || i < best then
                  bestT = t
                  best = i
                  face = query.meshFace
              k += 1
          else sp = push(WideWalk.node(wc, slot), sp, stack, entries, ix, iy, iz, sx, sy, sz, bestT)
    }
    query.distance = bestT
    query.face = face
    best

  /** [[Bvh.occluded]] on the tree, as [[nearest]]. */
  inline def occluded(
      size: Int,
      wc: Array[Int],
      wn: Array[Int],
      prims: Primitives,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  )(
      inline push: (
          Int,
          Int,
          Array[Int],
          Array[Double],
          Double,
          Double,
          Double,
          Int,
          Int,
          Int,
          Double
      ) => Int
  ): Boolean =
    // Perf: any hit will do (shadow rays): the 4-wide tree without ordering, and an early exit.
    val stack   = query.nodes
    val entries = query.entries
    WideWalk.walk(dx, dy, dz) { (ix, iy, iz, sx, sy, sz) =>
      var hit = false
      var sp  = WideWalk.seed(size, stack, entries)
      while sp > 0 && !hit do
        sp -= 1
        val slot  = stack(sp)
        val count = WideWalk.count(wn, slot)
        if count > 0 then
          var k   = wc(slot)
          val end = k + count
          while k < end && !hit do
            hit = Primitives.blocks(prims, k, limit, ox, oy, oz, dx, dy, dz, query)
            k += 1
          if hit then query.blocker = k - 1
        else sp = push(WideWalk.node(wc, slot), sp, stack, entries, ix, iy, iz, sx, sy, sz, limit)
      hit
    }

/** Construction constants of [[Bvh]]. */
object Bvh:
  /** Writes faces `from` until `to` of `mesh`, primitive `k` of a tree, as [[Bvh.bufferItems]]'
    * items `first + from` until `first + to`: each face's widened box, owner and face, and its
    * corners when `corners` is not empty.
    */
  private def faceItems(
      mesh: MeshTree,
      k: Int,
      first: Int,
      from: Int,
      to: Int,
      boxes: Array[Double],
      owner: Array[Int],
      face: Array[Int],
      corners: Array[Double]
  ): Unit =
    // Perf: a counted loop over one part of the faces.
    var f = from
    while f < to do
      val i = first + f
      mesh.faceBox(f, boxes, 6 * i)
      World.widen(boxes, 6 * i)
      if corners.length > 0 then mesh.faceCorners(f, corners, 9 * i)
      owner(i) = k; face(i) = f
      f += 1

  /** The scratch stack size a query needs: a wide node pushes at most four slots for the one it
    * pops, at most [[BvhBuilder.MaxDepth]] + 1 deep, so 3 × 129 + 4 slots at most.
    */
  val StackSize: Int = 512

/** Scratch space for one thread's queries of a [[World]] or [[Bvh]], and the distance of the last
  * nearest hit found with it. Not thread-safe: each render task makes its own (`World.newQuery`).
  */
final class Query:
  private[render] val nodes   = new Array[Int](Bvh.StackSize)
  private[render] val entries = new Array[Double](Bvh.StackSize)

  /** The stack of a walk down a mesh's own tree ([[MeshTree]]), taken while a walk down the
    * scene's tree uses [[nodes]].
    */
  private[render] val meshNodes   = new Array[Int](Bvh.StackSize)
  private[render] val meshEntries = new Array[Double](Bvh.StackSize)

  /** Four entry distances of a node's children, for a walk with [[Lanes]]. */
  private[render] val lanes = new Array[Double](4)

  /** The primitive (leaf order) that the last [[Bvh.occluded]] walk found blocking the ray;
    * written only when it finds one.
    */
  // Why: a second result of the any-hit walk, the shadow rays' guess for the next ray.
  private[render] var blocker: Int = -1

  /** The item of a light buffer that the last [[Bvh.anyBlocks]] found blocking the ray; written
    * only when it finds one.
    */
  // Why: as blocker, for a shadow ray answered by a light buffer.
  private[render] var blockingItem: Int = -1

  /** The node of a mesh's tree whose children hold the face the last [[MeshTree.occluded]] walk
    * found blocking the ray; written only when it finds one.
    */
  // Why: as blocker, for a mesh.
  private[render] var blockerNode: Int = 0

  /** The face the last mesh test met first ([[MeshTree.nearest]]). */
  // Why: the second result of a mesh's test, written instead of allocating a pair per test.
  private[render] var meshFace: Int = -1

  /** When the last nearest hit found is on a mesh, the face it is on (see [[World.hitAt]]). */
  // Why: as meshFace, the third result of `nearest`.
  var face: Int = -1

  /** Scratch for the general route's crossings (the solids' and combinations' kernel). */
  private[render] val crossings = tracer.geometry.CrossingBuffer()

  /** The distance along the ray of the last nearest hit found (+∞ for none). */
  // Why: the second result of `nearest`, written instead of allocating a pair per ray.
  var distance: Double = Double.PositiveInfinity

  // Perf: the hit at `distance`, written by `Hits.record` for shading, as fields of the row
  // task's scratch rather than a Hit, a Vec3 per value and a Ray a shaded point
  // (PrimaryRayBench: bytes per primary ray): the point p; the unit normal n facing the side the
  // ray came from; the normal s that shades it (Shape.shadingNormal: a smooth face's blend, else
  // n); the leaf of a combination and whether the ray arrived on the outward side (Hit's).
  private[render] var px: Double     = 0.0
  private[render] var py: Double     = 0.0
  private[render] var pz: Double     = 0.0
  private[render] var nx: Double     = 0.0
  private[render] var ny: Double     = 0.0
  private[render] var nz: Double     = 0.0
  private[render] var sx: Double     = 0.0
  private[render] var sy: Double     = 0.0
  private[render] var sz: Double     = 0.0
  private[render] var leaf: Int      = 0
  private[render] var front: Boolean = true
