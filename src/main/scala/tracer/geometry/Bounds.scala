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

  /** True when `p` lies inside the box or on its surface. */
  def contains(p: Vec3): Boolean =
    p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z

/** The bounds of shapes: one total function over the [[Shape]] cases. */
object Bounds:
  /** The box of three points. */
  def of(a: Vec3, b: Vec3, c: Vec3): Bounds =
    Bounds(
      Vec3(a.x min b.x min c.x, a.y min b.y min c.y, a.z min b.z min c.z),
      Vec3(a.x max b.x max c.x, a.y max b.y max c.y, a.z max b.z max c.z)
    )

  /** The world-space box that holds all of `shape`, or `None` for an unbounded shape (a plane).
    *
    * The acceleration structure indexes exactly the shapes with bounds; the others are tested on
    * every ray.
    */
  def of(shape: Shape): Option[Bounds] = shape match
    case s: Sphere =>
      val r = Vec3(s.radius, s.radius, s.radius)
      Some(Bounds(s.centre - r, s.centre + r))
    case t: Triangle => Some(of(t.t0, t.t1, t.t2))
    case _: Plane    => None
