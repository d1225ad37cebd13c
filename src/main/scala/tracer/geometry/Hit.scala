package tracer.geometry

import tracer.math.Vec3

/** Where a ray meets a shape (course text, section 3.1).
  *
  * @param t      the distance along the ray, > 0
  * @param point  the intersection point ri
  * @param normal the unit surface normal rn, facing the side the ray came from
  * @param leaf   on a [[Csg]] combination, which of its primitives was hit (depth-first from 0);
  *   0 on any other shape
  * @param front  true when the ray arrives on the side the shape's outward normal points to (the
  *   outside of a solid or a combination, the side of a plane or triangle its normal Pn faces):
  *   the side a surface emits from (version 4), and the outside of glass. The outward normal is
  *   `normal` when `front`, `-normal` otherwise.
  */
final case class Hit(t: Double, point: Vec3, normal: Vec3, leaf: Int = 0, front: Boolean = true):

  /** The shape's outward normal at the hit, whichever side the ray came from. */
  def outward: Vec3 = if front then normal else -normal

/** Texture coordinates on a surface, each in [0, 1]: u across, v up (v = 1 is the image's top). */
final case class SurfaceCoordinates(u: Double, v: Double)
