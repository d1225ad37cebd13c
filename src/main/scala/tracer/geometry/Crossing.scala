package tracer.geometry

import tracer.math.Vec3

/** One place where a ray crosses the surface of a solid: what constructive solid geometry works
  * with (docs/rendering.md, Constructive solid geometry).
  *
  * @param t      the distance along the ray, > 0
  * @param normal the surface's unit normal there, pointing out of the solid (for a plane, a
  *   triangle or a mesh face: its own normal)
  * @param leaf   which primitive of a CSG tree was crossed, counted depth-first from 0; 0 for a
  *   shape that is not a combination
  */
final case class Crossing(t: Double, normal: Vec3, leaf: Int)

/** An axis-aligned box from `lo` to `hi`: the bounds of a shape, or a box solid's extent.
  *
  * @param lo the smallest x, y and z
  * @param hi the largest x, y and z, each ≥ the matching coordinate of `lo`
  */
final case class Bounds(lo: Vec3, hi: Vec3):

  /** The box around this one and `that`. */
  def union(that: Bounds): Bounds =
    Bounds(
      Vec3(lo.x min that.lo.x, lo.y min that.lo.y, lo.z min that.lo.z),
      Vec3(hi.x max that.hi.x, hi.y max that.hi.y, hi.z max that.hi.z)
    )

  /** The common part of this box and `that` (possibly empty: some lo above its hi). */
  def intersection(that: Bounds): Bounds =
    Bounds(
      Vec3(lo.x max that.lo.x, lo.y max that.lo.y, lo.z max that.lo.z),
      Vec3(hi.x min that.hi.x, hi.y min that.hi.y, hi.z min that.hi.z)
    )

  /** The eight corners. */
  def corners: Seq[Vec3] =
    for x <- Seq(lo.x, hi.x); y <- Seq(lo.y, hi.y); z <- Seq(lo.z, hi.z) yield Vec3(x, y, z)

/** Constructors of [[Bounds]]. */
object Bounds:
  /** The smallest box holding every point of `points` (at least one). */
  def around(points: Seq[Vec3]): Bounds =
    points.tail.foldLeft(Bounds(points.head, points.head))((b, p) => b.union(Bounds(p, p)))
