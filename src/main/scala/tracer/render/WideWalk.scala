package tracer.render

/** The steps of a walk down a [[WideTree]], shared by the scene's [[Bvh]] and each mesh's
  * [[MeshTree]]: all `inline`, so each walk is compiled as if written out in place.
  */
private[render] object WideWalk:

  /** Runs `body` on the ray's inverse direction and, per axis, the offset (0 or 3) of a box's
    * near corner within its six coordinates.
    *
    * Perf: `inline` with an inline function: the lambda's body is spliced in, so there is no tuple
    * or object to allocate (a tuple of doubles is boxed) and no call.
    */
  inline def walk[A](dx: Double, dy: Double, dz: Double)(
      inline body: (Double, Double, Double, Int, Int, Int) => A
  ): A =
    val ix = 1 / dx
    val iy = 1 / dy
    val iz = 1 / dz
    body(
      ix,
      iy,
      iz,
      if ix >= 0 then 0 else 3,
      if iy >= 0 then 0 else 3,
      if iz >= 0 then 0 else 3
    )

  /** The stack slot that stands for the root node, which no slot of the tree links to. */
  final val Root = -1

  /** The stack slot that stands for node `node` itself ([[Root]] for node 0): a negative slot,
    * which no slot of the tree is, so a walk can start below the root.
    */
  inline def slotOf(node: Int): Int = Root - node

  /** Seeds the stack of a walk down a tree of `size` nodes with node `from` (the [[Root]] by
    * default) at entry distance 0 and returns its size (0 for an empty tree): that node's
    * children are then pushed by the walk's one [[push]] site, as every other node's.
    *
    * Perf: one inlined push per walk instead of two (the root's and the inner nodes'), so C2 has
    * half the push code to compile in each (docs/performance.md, round 9, vector). The seed's
    * entry 0 passes the walk's `entries(sp) <= best` test exactly when the old first push could
    * push anything (a slot's entry is at least 0 and at most the limit).
    */
  inline def seed(size: Int, stack: Array[Int], entries: Array[Double], from: Int = 0): Int =
    if size == 0 then 0
    else
      stack(0) = slotOf(from)
      entries(0) = 0.0
      1

  /** The primitive count of stack slot `slot` (0, an inner node, for a seeded node). */
  inline def count(wn: Array[Int], slot: Int): Int = if slot < 0 then 0 else wn(slot)

  /** The node or first primitive of stack slot `slot` (the node itself for a seeded one). */
  inline def node(wc: Array[Int], slot: Int): Int = if slot < 0 then Root - slot else wc(slot)

  /** Pushes the slots of wide node `node` (boxes `wb`, counts `wn`) whose boxes the ray enters
    * before `limit` onto the stack above `sp`, with their entry distances; `ordered`: the
    * farthest first, so the nearest is popped next. Returns the new stack size.
    */
  inline def push(
      wb: Array[Float],
      wn: Array[Int],
      node: Int,
      sp: Int,
      stack: Array[Int],
      entries: Array[Double],
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
    // Why: the stack top moves as slots are pushed; an insertion sort keeps them farthest first.
    var top = sp
    var c   = 0
    while c < WideTree.Width do
      val slot = WideTree.Width * node + c
      if wn(slot) >= 0 then
        val t = entry(wb, 24 * node + c, ox, oy, oz, ix, iy, iz, sx, sy, sz, limit)
        if t < Double.PositiveInfinity then
          var j = top
          if ordered then
            while j > sp && entries(j - 1) < t do
              stack(j) = stack(j - 1); entries(j) = entries(j - 1)
              j -= 1
          stack(j) = slot; entries(j) = t
          top += 1
      c += 1
    top

  /** The distance at which the ray enters the float box at `b` of `wb` (a child's low x; its
    * other coordinates 4 floats apart), or +∞ when it misses it before `limit`: the slab test on
    * the float box widened to double (exactly), the near plane of each axis the low one
    * when `sx` etc. is 0, the high one when it is 3.
    */
  inline def entry(
      wb: Array[Float],
      b: Int,
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
    // Perf: on four floats apart: no box object, local doubles narrowed in place. All six planes
    // are read at fixed offsets from `b` (the sign only picks which is near), so C2 can merge
    // the six index checks into two (range check smearing).
    var tmin = 0.0
    var tmax = limit
    val lx   = (wb(b).toDouble - ox) * ix
    val hx   = (wb(b + 12).toDouble - ox) * ix
    val nx   = if sx == 0 then lx else hx
    val fx   = if sx == 0 then hx else lx
    if nx > tmin then tmin = nx
    if fx < tmax then tmax = fx
    val ly = (wb(b + 4).toDouble - oy) * iy
    val hy = (wb(b + 16).toDouble - oy) * iy
    val ny = if sy == 0 then ly else hy
    val fy = if sy == 0 then hy else ly
    if ny > tmin then tmin = ny
    if fy < tmax then tmax = fy
    val lz = (wb(b + 8).toDouble - oz) * iz
    val hz = (wb(b + 20).toDouble - oz) * iz
    val nz = if sz == 0 then lz else hz
    val fz = if sz == 0 then hz else lz
    if nz > tmin then tmin = nz
    if fz < tmax then tmax = fz
    if tmin <= tmax then tmin else Double.PositiveInfinity
