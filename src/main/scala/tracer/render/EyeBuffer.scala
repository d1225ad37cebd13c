package tracer.render

/** The camera's item buffer (after Weghorst, Hooper and Greenberg, 1984, and POV-Ray's vista
  * buffer): a [[LightBuffer]]'s cells around the eye, over the items sorted by their distance from
  * it. A ray that leaves the eye looks up its direction's cell and tests that cell's few items,
  * nearest box first, stopping at the first box that lies beyond the best hit so far, in place of
  * the nearest-hit walk down the tree ([[World.nearestAlong]]). Immutable after
  * [[EyeBuffer.build]].
  *
  * Why exact: a ray from the eye meets an item only at a point of the item's widened box, and that
  * point's direction from the eye is the ray's own, so the item is binned in the ray's cell (the
  * light buffer's argument; here the ray starts at the buffer's centre itself, so its direction
  * carries no error from a far end). The point is no nearer the eye than the box, so an item whose
  * box lies beyond the best hit cannot win; one at exactly that distance is still tested, as a tie
  * goes to the lower index. Each item is tested as the walk tests it, so the answer is the walk's
  * bit for bit (`EyeBufferProperties`).
  *
  * @param x      the eye's x: the buffer answers the rays that start exactly there
  * @param y      the eye's y
  * @param z      the eye's z
  * @param cells  the cells, over [[items]]: each cell's items (and the ones tested on every ray)
  *   in increasing order, so nearest box first
  * @param items  the items, sorted by [[gaps]]
  * @param gaps   item i's box's distance from the eye, rounded down: nondecreasing in i
  */
final class EyeBuffer private (
    val x: Double,
    val y: Double,
    val z: Double,
    private[render] val cells: LightBuffer,
    private[render] val items: BufferItems,
    private[render] val gaps: Array[Float]
):
  /** True when a ray from (ox, oy, oz) starts at the eye, so this buffer answers it. */
  inline def answers(ox: Double, oy: Double, oz: Double): Boolean =
    ox == x && oy == y && oz == z

  /** The cell of the ray from the eye in unit direction (dx, dy, dz): as [[LightBuffer.cell]]. */
  def cell(dx: Double, dy: Double, dz: Double): Int =
    // The light buffer is looked up by a shadow ray's direction toward its centre, −e.
    cells.cell(-dx, -dy, -dz, 0.0)

/** Building an [[EyeBuffer]]. */
object EyeBuffer:
  /** Rays from the eye a bounded item must expect for the buffer to pay for itself: below this
    * [[World]] walks the tree.
    */
  val RaysPerItem: Long = 4

  /** The buffer of the eye at (ex, ey, ez) over `items`, or None when it has nothing to bin. */
  def build(ex: Double, ey: Double, ez: Double, items: BufferItems): Option[EyeBuffer] =
    val n = items.size
    // Perf: as LightBuffer.build, plain loops on flat arrays (run cold, once a picture). Each
    // item's key: its box's distance from the eye as a float rounded down (a lower bound still),
    // whose bits order as the distances do, above its number; one sort of longs orders them.
    val keys = new Array[Long](n)
    var i    = 0
    while i < n do
      val gap = distance(items.boxes, 6 * i, ex, ey, ez)
      keys(i) = (java.lang.Float.floatToRawIntBits(gap).toLong << 32) | i
      i += 1
    java.util.Arrays.sort(keys)
    val boxes = new Array[Double](6 * n)
    val owner = new Array[Int](n)
    val face  = new Array[Int](n)
    val gaps  = new Array[Float](n)
    i = 0
    while i < n do
      val from = (keys(i) & 0xffffffffL).toInt
      System.arraycopy(items.boxes, 6 * from, boxes, 6 * i, 6)
      owner(i) = items.owner(from)
      face(i) = items.face(from)
      gaps(i) = java.lang.Float.intBitsToFloat((keys(i) >>> 32).toInt)
      i += 1
    val sorted = BufferItems(boxes, owner, face)
    LightBuffer
      .build(ex, ey, ez, sorted)
      .map(cells => new EyeBuffer(ex, ey, ez, cells, sorted, gaps))

  /** The distance from (ex, ey, ez) to the box at `at` of `boxes`, as a float no greater than it
    * (0 for a box that holds the point or is not finite: every ray tests it first).
    */
  private def distance(boxes: Array[Double], at: Int, ex: Double, ey: Double, ez: Double): Float =
    val gx = Math.max(0.0, Math.max(boxes(at) - ex, ex - boxes(at + 3)))
    val gy = Math.max(0.0, Math.max(boxes(at + 1) - ey, ey - boxes(at + 4)))
    val gz = Math.max(0.0, Math.max(boxes(at + 2) - ez, ez - boxes(at + 5)))
    // The box is widened far beyond these roundings already; the factor keeps the bound a bound.
    val gap = Math.sqrt(gx * gx + gy * gy + gz * gz) * (1 - 1e-9)
    if !(gap < Double.PositiveInfinity) then 0f
    else
      val f = gap.toFloat
      if f > gap then Math.nextDown(f) else f
