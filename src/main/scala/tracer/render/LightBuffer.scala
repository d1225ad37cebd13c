package tracer.render

/** A point light's light buffer (Haines and Greenberg, 1986): the directions around the light as
  * the six faces of a cube, the part of each face that the scene covers cut into cells, and in
  * each cell the items (a bounded shape, or one face of a mesh: [[BufferItems]]) whose boxes
  * some direction of the cell meets (a triangle's own outline, when it lies on one face of the
  * cube), nearest the light first. Immutable after [[LightBuffer.build]].
  *
  * A shadow ray from a point toward the light keeps one direction as seen from the light along
  * its whole length (each of its points lies on the line from the light back through the point),
  * so only the items of that direction's cell can block it: a grid lookup and a few tests of
  * those items in place of a walk down the tree, with the same test of each, so the same answer
  * (`LightBufferProperties`). And every point of the ray lies no farther from the light than the
  * ray's start, so the items whose boxes lie farther ([[gaps]]), the tail of the cell's list,
  * can only lie behind the shading point and are skipped ([[Bvh.anyBlocks]]).
  *
  * Why exact: an item's cells are those of its box widened by 10⁻⁷ of its size (as the tree's
  * float boxes are rounded outwards), its part of a face widened by [[LightBuffer.Slack]] in the
  * face's coordinates, and each face also takes the items whose points lie within a relative
  * 10⁻⁶ of its edges. A triangle on one face keeps, of those cells, the ones its corners'
  * outline on the face meets, widened by the same slack and the box's widening as seen from the
  * light ([[Outlines]]). A ray's direction from the light differs from the true one by rounding,
  * about 6·10⁻¹⁶ (r / s + 1) for a ray of length r and a point at distance s from the light; the
  * items nearer the light than a ten-thousandth of the scene's size are tested on every ray, and
  * a ray longer than [[reachLimit]] takes the tree instead, so that error stays far below the
  * slack. An item's gap is its widened box's distance from the light less 10⁻⁹ of it, rounded
  * down to a float, and a ray's points lie within about 10⁻¹⁵ of its length farther from the
  * light than its start: a gap beyond the length is beyond every point.
  *
  * The [[EyeBuffer]] uses the same cells around the camera: a ray from there meets a cell's items
  * in the order of their gaps.
  *
  * @param windows     per face f, at 4f: the face's covered window's low u and v, and cells per
  *   unit of u and of v
  * @param highs       per face f, at 2f: the window's high u and v
  * @param sizes       per face f, at 3f: its cells along u and along v, and its first cell's number
  * @param start       cell c's items are `items(start(c) until start(c + 1))`
  * @param items       the cells' items, numbers of the sorted items below, in increasing order in
  *   each cell (so nearest the light, or the eye buffer's centre, first)
  * @param always      the items tested on every ray (those too near the light or too large), in
  *   increasing order
  * @param owner       sorted item i's primitive, in the tree's leaf order ([[BufferItems.owner]])
  * @param face        sorted item i's face in its mesh's leaf order, or −1 ([[BufferItems.face]])
  * @param gaps        sorted item i's box's distance from the light, rounded down: nondecreasing
  *   in i (0 for a box that holds the light or is not finite)
  * @param reachLimit  the longest shadow ray the buffer answers
  */
final class LightBuffer private (
    windows: Array[Double],
    highs: Array[Double],
    sizes: Array[Int],
    private[render] val start: Array[Int],
    private[render] val items: Array[Int],
    private[render] val always: Array[Int],
    private[render] val owner: Array[Int],
    private[render] val face: Array[Int],
    private[render] val gaps: Array[Float],
    reachLimit: Double
):
  /** The number of cells, for tests and benchmarks. */
  def cellCount: Int = start.length - 1

  /** The number of items in all the cells (an item counted once per cell it is in). */
  def entryCount: Int = items.length

  /** The cell of the shadow ray in unit direction (dx, dy, dz) toward the light, `reach` long:
    * a cell's number, [[LightBuffer.Outside]] for a direction no cell covers (only [[always]]
    * may block it) or [[LightBuffer.Walk]] for a ray the buffer does not answer.
    */
  def cell(dx: Double, dy: Double, dz: Double, reach: Double): Int =
    if !(reach <= reachLimit) then LightBuffer.Walk
    else
      // The direction from the light back to the ray's points: e = −d.
      val ax = Math.abs(dx)
      val ay = Math.abs(dy)
      val az = Math.abs(dz)
      // Perf: one division and two products, not two divisions: a cell need only be found within
      // Slack, far above the product's extra rounding (docs/performance.md, round 50).
      if ax >= ay && ax >= az then
        val r = 1 / ax
        face(if dx > 0 then 1 else 0, -dy * r, -dz * r)
      else if ay >= az then
        val r = 1 / ay
        face(if dy > 0 then 3 else 2, -dz * r, -dx * r)
      else
        val r = 1 / az
        face(if dz > 0 then 5 else 4, -dx * r, -dy * r)

  /** The cell of face `f` at (u, v), or [[LightBuffer.Outside]]. */
  private def face(f: Int, u: Double, v: Double): Int =
    val nu = sizes(3 * f)
    val ru = (u - windows(4 * f)) * windows(4 * f + 2)
    val rv = (v - windows(4 * f + 1)) * windows(4 * f + 3)
    if java.lang.Double.isNaN(ru) || java.lang.Double.isNaN(rv) then LightBuffer.Walk
    else if nu == 0 || ru < 0 || rv < 0 || u > highs(2 * f) || v > highs(2 * f + 1) then
      LightBuffer.Outside
    else
      val nv = sizes(3 * f + 1)
      sizes(3 * f + 2) + Math.min(ru.toInt, nu - 1) * nv + Math.min(rv.toInt, nv - 1)

/** Building a [[LightBuffer]]. */
object LightBuffer:
  /** [[LightBuffer.cell]]'s answer for a direction no cell covers. */
  val Outside: Int = -1

  /** [[LightBuffer.cell]]'s answer for a ray the buffer does not answer: walk the tree. */
  val Walk: Int = -2

  /** How far an item's part of a face is widened, in the face's coordinates (u = tan of the angle
    * off the face's centre): 10⁻⁷, far above a direction's rounding error and far below a cell.
    */
  val Slack: Double = 1e-7

  /** How far beyond its edges a face takes items, relative: points whose direction is within
    * this of the next face's are counted on both.
    */
  private val Relax = 1e-6

  /** About how many cells a face has for each item on it. */
  private val CellsPerItem = 4

  /** The most cells along a face's side. */
  private val MaxSide = 4096

  /** Shadow rays a bounded item must expect for a buffer to pay for itself: below this
    * [[World]] walks the tree (a small render of a big mesh would spend longer building it).
    */
  val RaysPerItem: Long = 4

  /** Rays a buffer's item must expect for the buffer to bin its triangles by their outlines
    * rather than their boxes' parts ([[BufferItems.corners]]): an outline costs more to bin and
    * saves tests on every ray of its cells.
    *
    * Measured (docs/performance.md, round 32): 415 rays an item (3840×2160, mesh-20000) gained 5%
    * of the whole run, 11.5 (1280×720, mesh-80000) came out even or 3% ahead, and 6.4
    * (3840×2160, the 1.3M-face mesh, whose build is most of its run) lost: its buffers took 1,133
    * samples to build by boxes and 1,615 by outlines, for 256 saved in the rows.
    */
  val OutlineRaysPerItem: Long = 8

  /** The buffer of the light at (lx, ly, lz) over `items`, or None when it has nothing to bin. */
  def build(lx: Double, ly: Double, lz: Double, items: BufferItems): Option[LightBuffer] =
    val n = items.size
    // Perf: the build's loops run once a light, before the render, over up to millions of items,
    // in the JIT's window: plain loops on flat arrays, no closure, range or boxed double per
    // item (a first version with them took 250 ms of a 720p render of mesh-20000; round 19).
    // Each item's key: its box's distance from the light as a float rounded down (a lower bound
    // still), whose bits order as the distances do, above its number; sorted by the distance's
    // bits, in a stable sort, they are in the order a sort of the longs would give.
    val keys = new Array[Long](n)
    var i    = 0
    while i < n do
      val gap = distance(items.boxes, 6 * i, lx, ly, lz)
      keys(i) = (java.lang.Float.floatToRawIntBits(gap).toLong << 32) | i
      i += 1
    sortByHigh(keys)
    val rel   = new Array[Double](6 * n)
    val owner = new Array[Int](n)
    val face  = new Array[Int](n)
    val gaps  = new Array[Float](n)
    // A triangle's corners relative to the light at 10i, and at 10i + 9 how far its box was
    // widened (World.widen); NaN at 10i for an item that is not a triangle (none at all for
    // items without corners).
    val corners =
      if items.corners.length == 0 then Array.emptyDoubleArray else new Array[Double](10 * n)
    // Perf: as above. The sorted boxes relative to the light, and the scene's size seen from
    // it: the farthest finite box corner.
    var extent = 0.0
    i = 0
    while i < n do
      val e = sorted(items, keys(i), i, lx, ly, lz, rel, owner, face, gaps, corners)
      if e > extent then extent = e
      i += 1
    if !(extent > 0) then None
    else Some(binned(rel, corners, n, 1e-4 * extent, owner, face, gaps))

  /** Writes the item of sorted key `key` (from [[build]]) as sorted item `i`: its owner, face
    * and gap, its box relative to the light at 6i of `rel` and its corners at 10i of `corners`
    * (when there are any); returns the box's farthest finite coordinate from the light, or 0.
    */
  private def sorted(
      items: BufferItems,
      key: Long,
      i: Int,
      lx: Double,
      ly: Double,
      lz: Double,
      rel: Array[Double],
      owner: Array[Int],
      face: Array[Int],
      gaps: Array[Float],
      corners: Array[Double]
  ): Double =
    // Perf: as build; a call an item, compiled after a few hundred, where the loop written out
    // in build ran interpreted until compiled on stack (round 35).
    val from = (key & 0xffffffffL).toInt
    owner(i) = items.owner(from)
    face(i) = items.face(from)
    gaps(i) = java.lang.Float.intBitsToFloat((key >>> 32).toInt)
    var extent = 0.0
    var j      = 0
    while j < 6 do
      val d = items.boxes(6 * from + j) - (if j % 3 == 0 then lx else if j % 3 == 1 then ly else lz)
      rel(6 * i + j) = d
      val e = Math.abs(d)
      if e > extent && e < Double.PositiveInfinity then extent = e
      j += 1
    if corners.length > 0 then Outlines.relativeCorners(items.corners, from, lx, ly, lz, corners, i)
    extent

  /** Sorts `keys`, each a non-negative `Int` in its high 32 bits above its index in `keys` in its
    * low 32, into increasing order: a stable radix sort of the high bits, a byte a pass (a pass
    * skipped where every key has the same byte), so keys of equal high bits stay in index order.
    *
    * Perf: the JDK's sort of the longs ran cold, 11–19 ms of a buffer's first build over 80,000
    * faces (4–9 compiled); these plain passes take 1–9 ms (0.3–2 compiled; docs/performance.md,
    * round 35).
    */
  private[render] def sortByHigh(keys: Array[Long]): Unit =
    val n      = keys.length
    var from   = keys
    var to     = new Array[Long](n)
    val counts = new Array[Int](257)
    var shift  = 32
    while shift < 64 && n > 1 do
      java.util.Arrays.fill(counts, 0)
      var i = 0
      while i < n do
        counts(((from(i) >>> shift) & 0xff).toInt + 1) += 1
        i += 1
      // A pass whose byte is the same in every key moves nothing.
      if counts(((from(0) >>> shift) & 0xff).toInt + 1) != n then
        var b = 0
        while b < 256 do
          counts(b + 1) += counts(b)
          b += 1
        i = 0
        while i < n do
          val byte = ((from(i) >>> shift) & 0xff).toInt
          to(counts(byte)) = from(i)
          counts(byte) += 1
          i += 1
        val swap = from; from = to; to = swap
      shift += 8
    if !(from eq keys) then System.arraycopy(from, 0, keys, 0, n)

  /** The distance from (cx, cy, cz) to the box at `at` of `boxes`, as a float no greater than it
    * (0 for a box that holds the point or is not finite: every ray tests it first).
    */
  private def distance(boxes: Array[Double], at: Int, cx: Double, cy: Double, cz: Double): Float =
    val gx = Math.max(0.0, Math.max(boxes(at) - cx, cx - boxes(at + 3)))
    val gy = Math.max(0.0, Math.max(boxes(at + 1) - cy, cy - boxes(at + 4)))
    val gz = Math.max(0.0, Math.max(boxes(at + 2) - cz, cz - boxes(at + 5)))
    // The box is widened far beyond these roundings already; the factor keeps the bound a bound.
    val gap = Math.sqrt(gx * gx + gy * gy + gz * gz) * (1 - 1e-9)
    if !(gap < Double.PositiveInfinity) then 0f
    else
      val f = gap.toFloat
      if f > gap then Math.nextDown(f) else f

  /** What [[binned]] knows of an item that does not lie on exactly one face: on none. */
  private val OnNone: Byte = -1

  /** An item near an edge of the cube, on several faces: its parts are found again when needed. */
  private val OnSeveral: Byte = -2

  /** An item tested on every ray: too near the light, not finite, or in too many cells. */
  private val OnAlways: Byte = -3

  /** The buffer of `n` items, boxes `rel` relative to the light, those nearer than `near` (or
    * without finite bounds) tested on every ray; `owner`, `face` and `gaps` as the buffer's.
    */
  private def binned(
      rel: Array[Double],
      corners: Array[Double],
      n: Int,
      near: Double,
      owner: Array[Int],
      face: Array[Int],
      gaps: Array[Float]
  ): LightBuffer =
    // Each item's face (0 to 5) and its part of it (u0, u1, v0, v1 at 4i) when it lies on one
    // face only, as most do; else OnNone, OnSeveral or OnAlways.
    val on    = new Array[Byte](n)
    val parts = new Array[Double](4 * n)
    // A triangle on one face: its corners' (u, v) at 7i, and its margin at 7i + 6
    // (Outlines.outline); NaN at 7i for any other item, binned by its box's part alone (none at
    // all without corners).
    val outlines = if corners.length == 0 then Array.emptyDoubleArray else new Array[Double](7 * n)
    // Perf: as build; an item's one part is found once, not in each of the three passes. Each
    // pass's work on one item is a small method of its own, called once an item: a method is
    // compiled after a few hundred calls, where these loops written out in one method of 6.8 KB
    // of bytecode ran interpreted until each was compiled on stack, one at a time (a 1280×720
    // render of mesh-80000: 481 of the 1 ms samples of binned interpreted, 19 compiled; round 27).
    var i = 0
    while i < n do
      classify(rel, gaps, i, near, on, parts)
      if outlines.length > 0 then Outlines.outline(corners, on(i), i, parts, outlines)
      i += 1
    val (windows, highs, sizes) = grids(rel, n, on, parts)
    val cells                   = sizes(18)
    // An item in more cells than a sixteenth of them (or 64) is tested on every ray instead.
    val widest = Math.max(64L, cells / 16L)
    // Perf: as build: count each cell's items (refusing the widest), prefix sums, then place
    // them: flat arrays for up to millions of entries (a mesh's faces each in several cells).
    // The count pass keeps each outlined item's cells of each column (Outlines.column's answer,
    // the costly part) in `columns`, and the place pass reads them back in the same order: the
    // place pass took 10–26 ms of a compiled build over 80,000 faces finding them again, 3–8
    // reading them; listing every cell instead cost as many ints as the buffer's entries (57 a
    // face of the 1.3M-face mesh at 3840×2160; docs/performance.md, round 35).
    val start   = new Array[Int](cells + 1)
    val columns = Columns(if outlines.length == 0 then 0 else 4 * n)
    i = 0
    while i < n do
      count(rel, on, parts, outlines, i, windows, sizes, widest, start, columns)
      i += 1
    var c = 0
    while c < cells do
      start(c + 1) += start(c)
      c += 1
    val items  = new Array[Int](start(cells))
    val next   = java.util.Arrays.copyOf(start, cells)
    var always = 0
    i = 0
    while i < n do
      if on(i) == OnAlways then always += 1
      else place(rel, on, parts, outlines, i, windows, sizes, items, next, columns)
      i += 1
    // Why: the place pass must have read back every answer the count pass kept, in step.
    assert(columns.allRead, "a light buffer's place pass read its columns out of step")
    val everyRay = new Array[Int](always)
    always = 0
    i = 0
    while i < n do
      if on(i) == OnAlways then
        everyRay(always) = i
        always += 1
      i += 1
    // Why 10⁷ near: a ray's direction error is about 6·10⁻¹⁶ (r / s + 1), s ≥ near, so a ray of
    // that length errs by less than a twentieth of the slack.
    new LightBuffer(windows, highs, sizes, start, items, everyRay, owner, face, gaps, 1e7 * near)

  /** Sets `on(i)` to item `i`'s one face, its part of it at `parts(4i)`; or to [[OnAlways]] for
    * an item whose gap (`gaps(i)`, its distance from the light rounded down) is below `near`, or
    * whose box is not finite; [[OnNone]] for one on no face, [[OnSeveral]] for one on several.
    */
  private def classify(
      rel: Array[Double],
      gaps: Array[Float],
      i: Int,
      near: Double,
      on: Array[Byte],
      parts: Array[Double]
  ): Unit =
    if !(gaps(i) >= near) || !finite(rel, 6 * i) then on(i) = OnAlways
    else
      // Perf: as binned; the faces the item lies on, counted over the six (an item on one face
      // keeps its part where partOn wrote it; one on several has its parts found again).
      var faces = 0
      var f     = 0
      while f < 6 do
        if partOn(rel, i, f, parts) then
          if faces == 0 then on(i) = f.toByte
          faces += 1
        f += 1
      if faces == 0 then on(i) = OnNone else if faces > 1 then on(i) = OnSeveral

  /** True when item `i` is binned by its triangle's outline ([[Outlines.outline]]), not its box's
    * part: [[count]] and [[place]] ask the same.
    */
  private inline def outlined(outlines: Array[Double], i: Int): Boolean =
    outlines.length > 0 && !java.lang.Double.isNaN(outlines(7 * i))

  /** Counts item `i` into each of its cells (cell c's count at `start(c + 1)`), keeping an
    * outlined item's cells of each column in `columns`, or when it covers more than `widest`
    * cells, sets `on(i)` to [[OnAlways]] instead; an item tested on every ray or on no face is
    * left alone.
    */
  private def count(
      rel: Array[Double],
      on: Array[Byte],
      parts: Array[Double],
      outlines: Array[Double],
      i: Int,
      windows: Array[Double],
      sizes: Array[Int],
      widest: Long,
      start: Array[Int],
      columns: Columns
  ): Unit =
    if on(i) != OnAlways && on(i) != OnNone then
      // Perf: as binned; the cells an item covers, summed, then each counted.
      var span = 0L
      cellsOf(rel, on, parts, i, windows, sizes)((cu0, cu1, cv0, cv1, _, _, _) =>
        span += (cu1 - cu0 + 1).toLong * (cv1 - cv0 + 1)
      )
      if span > widest then on(i) = OnAlways
      else
        eachCell(rel, on, parts, i, windows, sizes) { (f, cu, cv0, cv1) =>
          if outlined(outlines, i) then
            columns.keep(Outlines.column(outlines, i, windows, sizes, f, cu, cv0, cv1))
          else Outlines.span(cv0, cv1)
        }(cell => start(cell + 1) += 1)

  /** Places item `i` in each of its cells, at `next(c)` of `items` for cell c, and moves each such
    * `next` on, an outlined item's cells of each column read back from `columns` in the order
    * [[count]] kept them; an item on no face is left out.
    */
  private def place(
      rel: Array[Double],
      on: Array[Byte],
      parts: Array[Double],
      outlines: Array[Double],
      i: Int,
      windows: Array[Double],
      sizes: Array[Int],
      items: Array[Int],
      next: Array[Int],
      columns: Columns
  ): Unit =
    if on(i) != OnNone then
      eachCell(rel, on, parts, i, windows, sizes) { (_, _, cv0, cv1) =>
        if outlined(outlines, i) then columns.next() else Outlines.span(cv0, cv1)
      } { cell =>
        items(next(cell)) = i
        next(cell) += 1
      }

  /** Runs `body` on each cell of item `i`, column by column of each part of a face it covers:
    * the cells along v of column `cu` of face `f` are those `column(f, cu, cv0, cv1)` answers
    * (first in the high 32 bits, last in the low), within the part's `cv0` to `cv1`.
    *
    * Perf: both inline, so [[count]] and [[place]] each compile to plain loops, as written out.
    */
  private inline def eachCell(
      rel: Array[Double],
      on: Array[Byte],
      parts: Array[Double],
      i: Int,
      windows: Array[Double],
      sizes: Array[Int]
  )(inline column: (Int, Int, Int, Int) => Long)(inline body: Int => Unit): Unit =
    cellsOf(rel, on, parts, i, windows, sizes) { (cu0, cu1, cv0, cv1, base, nv, f) =>
      // Perf: as binned.
      var cu = cu0
      while cu <= cu1 do
        val cells = column(f, cu, cv0, cv1)
        var cv    = (cells >> 32).toInt
        while cv <= cells.toInt do
          body(base + cu * nv + cv)
          cv += 1
        cu += 1
    }

  /** The outlined items' cells of each column, as [[Outlines.column]] answers them: kept in
    * order by [[count]], read back in the same order by [[place]].
    */
  private final class Columns(capacity: Int):
    /** The answers kept. */
    // Perf: a build's list of a few answers an outlined item, kept in place (binned's loops).
    private var spans: Array[Long] = new Array[Long](Math.max(16, capacity))

    /** The number kept. */
    // Perf: as spans.
    private var size: Int = 0

    /** The next to read back. */
    // Perf: as spans.
    private var read: Int = 0

    /** Keeps `span` at the end and returns it; doubles the room when it is full. */
    inline def keep(span: Long): Long =
      if size == spans.length then grow()
      spans(size) = span
      size += 1
      span

    /** Reads back the next answer kept. */
    inline def next(): Long =
      val span = spans(read)
      read += 1
      span

    /** True when every answer kept has been read back. */
    def allRead: Boolean = read == size

    /** Doubles the room. */
    private def grow(): Unit =
      spans = java.util.Arrays.copyOf(spans, Math.min(Int.MaxValue - 8L, 2L * spans.length).toInt)

  /** Runs `body` on each part of a face that item `i` covers: the face and the part's low and
    * high u and v (from `parts` for an item on one face; found again for one on several, each
    * into the item's own four slots of `parts`, which such an item leaves unused).
    *
    * Perf: `body` spliced in once, and the part of an item on several faces found by a call
    * ([[partOn]]): the six faces' footprints written out in place twice over made [[count]] 3.8
    * KB of bytecode and [[place]] 1.9 KB, which C2 took 58 and 30 ms to compile while the first
    * buffers were built in slower code; now 1.0 and 0.6 KB (docs/performance.md, round 36).
    */
  private inline def partsOf(rel: Array[Double], on: Array[Byte], parts: Array[Double], i: Int)(
      inline body: (Int, Double, Double, Double, Double) => Unit
  ): Unit =
    val o = on(i)
    // Why: the faces to visit, an item's one face, all six for one on several, none for one on
    // no face or tested on every ray (OnNone and OnAlways are negative).
    var f    = if o == OnSeveral then 0 else o.toInt
    val last = if o == OnSeveral then 5 else o.toInt
    while f >= 0 && f <= last do
      if o >= 0 || partOn(rel, i, f, parts) then
        body(f, parts(4 * i), parts(4 * i + 1), parts(4 * i + 2), parts(4 * i + 3))
      f += 1

  /** True when the box of item `i` covers part of face `f`; that part is then written at
    * `parts(4i)` (low u, high u, low v, high v), where an item on one face keeps it
    * ([[classify]]).
    */
  private def partOn(rel: Array[Double], i: Int, f: Int, parts: Array[Double]): Boolean =
    // Why: set by the footprint's body, which runs at most once.
    var found = false
    footprint(rel, 6 * i, f) { (u0, u1, v0, v1) =>
      parts(4 * i) = u0; parts(4 * i + 1) = u1; parts(4 * i + 2) = v0; parts(4 * i + 3) = v1
      found = true
    }
    found

  /** The six faces' windows (low u and v, cells per unit of each, at 4f), their high ends (at
    * 2f) and sizes (cells along u and v, first cell, at 3f; the number of cells at 18): each
    * face's window the union of its items' parts, cut into about [[CellsPerItem]] cells an item,
    * shaped as the window.
    */
  private def grids(
      rel: Array[Double],
      n: Int,
      on: Array[Byte],
      parts: Array[Double]
  ): (Array[Double], Array[Double], Array[Int]) =
    val windows = new Array[Double](24)
    val highs   = Array.fill(12)(Double.NegativeInfinity)
    val low     = Array.fill(12)(Double.PositiveInfinity)
    val perFace = new Array[Int](6)
    // Perf: as binned, an item a call.
    var i = 0
    while i < n do
      widen(rel, on, parts, i, low, highs, perFace)
      i += 1
    val sizes = new Array[Int](19)
    sizes(18) = (0 until 6).foldLeft(0) { (first, f) =>
      if perFace(f) == 0 then first
      else
        val wu     = Math.max(Slack, highs(2 * f) - low(2 * f))
        val wv     = Math.max(Slack, highs(2 * f + 1) - low(2 * f + 1))
        val target = CellsPerItem.toDouble * perFace(f)
        val nu     = Math.max(1, Math.min(MaxSide, Math.round(Math.sqrt(target * wu / wv)).toInt))
        val nv     = Math.max(1, Math.min(MaxSide, Math.round(target / nu).toInt))
        sizes(3 * f) = nu; sizes(3 * f + 1) = nv; sizes(3 * f + 2) = first
        windows(4 * f) = low(2 * f); windows(4 * f + 1) = low(2 * f + 1)
        windows(4 * f + 2) = nu / wu; windows(4 * f + 3) = nv / wv
        first + nu * nv
    }
    (windows, highs, sizes)

  /** Widens the windows of the faces item `i` lies on (their low u and v at 2f of `low`, high
    * at 2f of `highs`) to take its parts, and counts it on each of them (`perFace`).
    */
  private def widen(
      rel: Array[Double],
      on: Array[Byte],
      parts: Array[Double],
      i: Int,
      low: Array[Double],
      highs: Array[Double],
      perFace: Array[Int]
  ): Unit =
    partsOf(rel, on, parts, i) { (f, u0, u1, v0, v1) =>
      low(2 * f) = Math.min(low(2 * f), u0); low(2 * f + 1) = Math.min(low(2 * f + 1), v0)
      highs(2 * f) = Math.max(highs(2 * f), u1); highs(2 * f + 1) = Math.max(highs(2 * f + 1), v1)
      perFace(f) += 1
    }

  /** Runs `body` on each range of cells (u first, then v, inclusive) that item `i` covers, with
    * the face's first cell, its cells along v and the face.
    */
  private inline def cellsOf(
      rel: Array[Double],
      on: Array[Byte],
      parts: Array[Double],
      i: Int,
      windows: Array[Double],
      sizes: Array[Int]
  )(inline body: (Int, Int, Int, Int, Int, Int, Int) => Unit): Unit =
    partsOf(rel, on, parts, i) { (f, u0, u1, v0, v1) =>
      val nu = sizes(3 * f)
      val nv = sizes(3 * f + 1)
      body(
        index(u0, windows(4 * f), windows(4 * f + 2), nu),
        index(u1, windows(4 * f), windows(4 * f + 2), nu),
        index(v0, windows(4 * f + 1), windows(4 * f + 3), nv),
        index(v1, windows(4 * f + 1), windows(4 * f + 3), nv),
        sizes(3 * f + 2),
        nv,
        f
      )
    }

  /** The cell along one side of coordinate `u` (window from `low`, `scale` cells a unit, `n`
    * cells), clamped to the window: the arithmetic of [[LightBuffer.cell]]'s lookup, which is
    * monotonic, so a coordinate between two others falls between their cells.
    */
  private[render] inline def index(u: Double, low: Double, scale: Double, n: Int): Int =
    val r = (u - low) * scale
    if !(r > 0) then 0 else Math.min(r.toInt, n - 1)

  /** True when all six coordinates of the box at `at` of `rel` are finite. */
  private def finite(rel: Array[Double], at: Int): Boolean =
    Math.abs(rel(at)) < Double.PositiveInfinity &&
      Math.abs(rel(at + 1)) < Double.PositiveInfinity &&
      Math.abs(rel(at + 2)) < Double.PositiveInfinity &&
      Math.abs(rel(at + 3)) < Double.PositiveInfinity &&
      Math.abs(rel(at + 4)) < Double.PositiveInfinity &&
      Math.abs(rel(at + 5)) < Double.PositiveInfinity

  /** Runs `body` on the part of face `f` (2a for the directions whose axis a coordinate is the
    * largest and positive, 2a + 1 negative) that the box at `at` of `rel` covers: its low and high
    * u (axis a + 1 over axis a, mod 3) and v (a + 2 over a), widened by [[Slack]]; nothing when
    * none of the box's directions lies on the face (within [[Relax]]).
    */
  private inline def footprint(rel: Array[Double], at: Int, f: Int)(
      inline body: (Double, Double, Double, Double) => Unit
  ): Unit =
    val a       = f >> 1
    val b       = (a + 1) % 3
    val c       = (a + 2) % 3
    val negated = (f & 1) == 1
    // The box's range along the face's axis, counted outwards from the light.
    val aLow  = if negated then -rel(at + 3 + a) else rel(at + a)
    val aHigh = if negated then -rel(at + a) else rel(at + 3 + a)
    // A direction lies on the face when its axis a part is the largest: the box's points come
    // no nearer the face's axis than m.
    val m = Math.max(nearest(rel(at + b), rel(at + 3 + b)), nearest(rel(at + c), rel(at + 3 + c)))
    val floor = m * (1 - Relax)
    if aHigh > 0 && aHigh >= floor then
      val aFrom = Math.max(aLow, floor)
      if aFrom > 0 then
        val u0 = low(rel(at + b), aFrom, aHigh)
        val u1 = high(rel(at + 3 + b), aFrom, aHigh)
        val v0 = low(rel(at + c), aFrom, aHigh)
        val v1 = high(rel(at + 3 + c), aFrom, aHigh)
        if u0 <= u1 && v0 <= v1 then body(u0, u1, v0, v1)
      else body(-1 - Slack, 1 + Slack, -1 - Slack, 1 + Slack)

  /** The least |x| over [lo, hi]. */
  private inline def nearest(lo: Double, hi: Double): Double =
    if lo <= 0 && hi >= 0 then 0.0 else Math.min(Math.abs(lo), Math.abs(hi))

  /** The least of x / a for a in [aFrom, aHigh] (0 < aFrom), the low end of a box's coordinate
    * x, widened and clamped to the face.
    */
  private inline def low(x: Double, aFrom: Double, aHigh: Double): Double =
    Math.max(-1 - Slack, Math.min(x / aFrom, x / aHigh) - Slack)

  /** As [[low]] for the greatest, from the high end x. */
  private inline def high(x: Double, aFrom: Double, aHigh: Double): Double =
    Math.min(1 + Slack, Math.max(x / aFrom, x / aHigh) + Slack)
