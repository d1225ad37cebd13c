package tracer.render

/** A viewpoint's item buffer (after Weghorst, Hooper and Greenberg, 1984, and POV-Ray's vista
  * buffer): a [[LightBuffer]]'s cells around a centre, over the items sorted by their distance
  * from it. A ray whose line leaves the centre looks up its direction's cell and tests that
  * cell's few items, nearest box first, stopping at the first box that lies beyond the best hit
  * so far, in place of the nearest-hit walk down the tree ([[World.nearestAlong]]). The centre is
  * the camera's location (its primary rays start there) or the camera's mirror image in a
  * mirroring plane (the rays that plane reflects from the camera's lie on lines through it).
  * Immutable after [[EyeBuffer.build]].
  *
  * Why exact: a ray meets an item only at a point of the item's widened box. For a ray from the
  * centre, that point's direction from the centre is the ray's own; for a ray that starts at a
  * distance s beyond the centre on a line through it, within 10⁻⁹ s ([[behind]] checks), the
  * point's direction differs from the ray's by at most 10⁻⁹, far below the cells' slack of 10⁻⁷
  * (the light buffer's argument). So the item is binned in the ray's cell. And the point lies no
  * nearer the ray's start than the box's distance from the centre less s, so an item whose box
  * lies beyond the best hit plus s cannot win; one at exactly that bound is still tested, as a
  * tie goes to the lower index. Each item is tested as the walk tests it, so the answer is the
  * walk's bit for bit (`EyeBufferProperties`).
  *
  * @param x      the centre's x
  * @param y      the centre's y
  * @param z      the centre's z
  * @param cells  the cells around the centre, over the items sorted by their distance from it
  *   (their owners, faces and gaps: [[LightBuffer]]), so nearest box first in each
  */
final class EyeBuffer private (
    val x: Double,
    val y: Double,
    val z: Double,
    private[render] val cells: LightBuffer
):
  /** How far the ray from (ox, oy, oz) in unit direction (dx, dy, dz) starts beyond the centre,
    * rounded up, when this buffer answers it: 0 for a ray from the centre itself, else the
    * distance when the ray points away from the centre on a line within 10⁻⁹ of that distance
    * from it; −1 for a ray it does not answer.
    */
  def behind(ox: Double, oy: Double, oz: Double, dx: Double, dy: Double, dz: Double): Double =
    if ox == x && oy == y && oz == z then 0.0
    else
      val wx = ox - x
      val wy = oy - y
      val wz = oz - z
      // The line's distance from the centre: |w × d| for the unit d.
      val cx = wy * dz - wz * dy
      val cy = wz * dx - wx * dz
      val cz = wx * dy - wy * dx
      val w2 = wx * wx + wy * wy + wz * wz
      if wx * dx + wy * dy + wz * dz > 0 && cx * cx + cy * cy + cz * cz <= EyeBuffer.Aligned * w2
      then Math.sqrt(w2) * (1 + 1e-9)
      else -1.0

  /** The cell of the ray in unit direction (dx, dy, dz) from the centre: as [[LightBuffer.cell]]. */
  def cell(dx: Double, dy: Double, dz: Double): Int =
    // The light buffer is looked up by a shadow ray's direction toward its centre, −e.
    cells.cell(-dx, -dy, -dz, 0.0)

/** Building an [[EyeBuffer]]. */
object EyeBuffer:
  /** Rays from the eye a bounded item must expect for the buffer to pay for itself: below this
    * [[World]] walks the tree.
    */
  val RaysPerItem: Long = 4

  /** The fewest rays from a centre a render must trace for its buffer to be built.
    *
    * The buffers shorten the compiled walk (500 spheres at 1280×720: 900 → 615 ms a frame in
    * steady state), but their build and their code's compilation fall in the JIT's warm-up: whole
    * runs of 921,600 primary rays were slower with them (the 500 spheres: Tracetime median 1075
    * against 976 ms), those of 8,294,400 faster (3840×2160 quick mode: 1974 against 2818 ms). The
    * crossover lies between; 4,000,000 takes 4K pictures and antialiased smaller ones
    * (docs/performance.md, round 20).
    */
  val MinRays: Long = 4000000

  /** Rays from a centre a bounded item must expect for its buffer to pay in a render of fewer
    * than [[MinRays]] rays: a buffer over few items builds in a moment, and its shorter walks
    * then outweigh its code's compilation.
    *
    * The 500 spheres at 1280×720 (1,843 rays an item) ran faster with their buffers (14
    * alternating whole runs, wall median 1802 → 1687 ms, Tracetime 1155 → 1024), the
    * 5,000-triangle mesh at 1280×720 (184 an item) slower (2335 → 2519), the 20,000-triangle one
    * (46 an item) slower still (docs/performance.md, round 21).
    */
  val ShortRenderRaysPerItem: Long = 1000

  /** The fewest items a buffer is built over: a smaller tree is walked in a few nodes, which a
    * buffer hardly shortens. At 64, the start-up cache's training scenes of 80 and 201 shapes
    * built buffers, and a whole run of the gallery's showcase (six shapes, no buffer) was 11%
    * slower, as it was not with no buffers anywhere: the walk's profiles that the JIT starts from
    * then lacked those scenes' primary rays, we take it. At 256 it is as fast as without buffers
    * (docs/performance.md, round 20).
    */
  val MinItems: Long = 256

  /** True when `rays` rays from a centre pay for a buffer over `items` items: at least
    * [[MinRays]] and [[RaysPerItem]] an item, or [[ShortRenderRaysPerItem]] an item.
    */
  def pays(rays: Long, items: Long): Boolean =
    rays >= MinRays && rays >= RaysPerItem * items || rays >= ShortRenderRaysPerItem * items

  /** The square of the largest distance of a ray's line from the centre, relative to the ray's
    * start's distance, that [[EyeBuffer.behind]] accepts: (10⁻⁹)².
    */
  private val Aligned = 1e-18

  /** The buffer of the centre (ex, ey, ez) over `items`, or None when it has nothing to bin. */
  def build(ex: Double, ey: Double, ez: Double, items: BufferItems): Option[EyeBuffer] =
    LightBuffer.build(ex, ey, ez, items).map(cells => new EyeBuffer(ex, ey, ez, cells))
