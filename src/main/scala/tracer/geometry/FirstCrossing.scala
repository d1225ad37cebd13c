package tracer.geometry

/** The nearest crossing of a ray with a shape of the general route, on the ray's six doubles:
  * what [[Shape.hitAt]] takes from the first of [[Shape.crossings]] (its t, outward normal and
  * leaf), for shading that makes no `Ray` or `Hit` (`tracer.render.Hits`).
  */
object FirstCrossing:

  /** Collects the crossings of the ray from (ox, oy, oz) in unit direction (dx, dy, dz) with
    * `shape` into `buffer` ([[Kernel.collect]]); true when there is one, whose values [[t]],
    * [[nx]], [[ny]], [[nz]] and [[leaf]] then read.
    */
  def find(
      shape: Shape,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer
  ): Boolean = Kernel.collect(shape, ox, oy, oz, dx, dy, dz, buffer, 0) > 0

  /** The first crossing's distance t. */
  def t(buffer: CrossingBuffer): Double = buffer.t(0)

  /** The x of the first crossing's outward normal. */
  def nx(buffer: CrossingBuffer): Double = buffer.nx(0)

  /** The y of the first crossing's outward normal. */
  def ny(buffer: CrossingBuffer): Double = buffer.ny(0)

  /** The z of the first crossing's outward normal. */
  def nz(buffer: CrossingBuffer): Double = buffer.nz(0)

  /** The leaf the first crossing is on. */
  def leaf(buffer: CrossingBuffer): Int = buffer.leaf(0)
