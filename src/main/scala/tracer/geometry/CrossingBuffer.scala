package tracer.geometry

/** A thread's scratch space for the [[Kernel]]'s crossings: parallel arrays of t, the outward
  * normal's three components and the leaf (the interval lists of pbrt's and the Ray Tracer
  * Challenge's CSG), grown when a deep combination needs more, and the root finder's scratch.
  * Not thread-safe: each render task has its own (`tracer.render.Query`), and [[Shape.hitAt]]
  * one per thread.
  */
final class CrossingBuffer:
  // Why: scratch arrays, reused by every query of one thread and grown (rarely) in place.
  private[geometry] var t: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var nx: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var ny: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var nz: Array[Double] = new Array[Double](CrossingBuffer.Initial)
  // Why: as t.
  private[geometry] var leaf: Array[Int] = new Array[Int](CrossingBuffer.Initial)

  /** The root finder's scratch: four levels of coefficients, roots and ends (Polynomial). */
  private[geometry] val roots = new Array[Double](Polynomial.ScratchSize)

  /** The distance t of crossing `k`, as [[Kernel.collect]] wrote it. */
  def distanceAt(k: Int): Double = t(k)

  /** The leaf of crossing `k` (see [[Hit.leaf]]), as [[Kernel.collect]] wrote it. */
  def leafAt(k: Int): Int = leaf(k)

  /** Room for crossings up to index `n` (exclusive). */
  private[geometry] def ensure(n: Int): Unit =
    if n > t.length then
      val size = Math.max(n, 2 * t.length)
      t = java.util.Arrays.copyOf(t, size)
      nx = java.util.Arrays.copyOf(nx, size)
      ny = java.util.Arrays.copyOf(ny, size)
      nz = java.util.Arrays.copyOf(nz, size)
      leaf = java.util.Arrays.copyOf(leaf, size)

  /** Writes crossing `k`. */
  private[geometry] inline def put(
      k: Int,
      at: Double,
      x: Double,
      y: Double,
      z: Double,
      l: Int
  ): Unit =
    ensure(k + 1)
    t(k) = at; nx(k) = x; ny(k) = y; nz(k) = z; leaf(k) = l

  /** Copies crossing `from` to `to`. */
  private[geometry] def move(from: Int, to: Int): Unit =
    t(to) = t(from); nx(to) = nx(from); ny(to) = ny(from); nz(to) = nz(from)
    leaf(to) = leaf(from)

  /** Sorts crossings `from until end` by t, stably (as `List.sortBy` does): insertion sort, for
    * the handful a combination gives.
    */
  private[geometry] def sort(from: Int, end: Int): Unit =
    // Perf: an insertion sort on the parallel arrays, no Crossing objects (SolidsBench).
    var i = from + 1
    while i < end do
      val ti = t(i); val xi = nx(i); val yi = ny(i); val zi = nz(i); val li = leaf(i)
      // Why: the hole moves left past every strictly greater t, which keeps equal ts in order.
      var j = i - 1
      while j >= from && t(j) > ti do
        move(j, j + 1)
        j -= 1
      t(j + 1) = ti; nx(j + 1) = xi; ny(j + 1) = yi; nz(j + 1) = zi; leaf(j + 1) = li
      i += 1

/** Sizes of [[CrossingBuffer]]. */
object CrossingBuffer:
  /** Crossings a buffer holds before it grows. */
  val Initial: Int = 32
