package tracer.geometry

import tracer.math.Vec3

/** An axis-aligned box in world space, from its low corner to its high corner (both included).
  *
  * @param lo the corner with the smallest coordinates
  * @param hi the corner with the largest coordinates
  */
final case class Bounds(lo: Vec3, hi: Vec3):
  /** The smallest box holding this one and `that`. */
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

  /** True when `p` lies inside the box or on its surface. */
  def contains(p: Vec3): Boolean =
    p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z

/** Constructors of [[Bounds]]; the bounds of a shape are [[Shape.bounds]]. */
object Bounds:
  /** The smallest box holding every point of `points` (at least one). */
  def around(points: Seq[Vec3]): Bounds =
    points.tail.foldLeft(Bounds(points.head, points.head))((b, p) => b.union(Bounds(p, p)))

  /** The box of three points. */
  def of(a: Vec3, b: Vec3, c: Vec3): Bounds =
    Bounds(
      Vec3(a.x min b.x min c.x, a.y min b.y min c.y, a.z min b.z min c.z),
      Vec3(a.x max b.x max c.x, a.y max b.y max c.y, a.z max b.z max c.z)
    )
