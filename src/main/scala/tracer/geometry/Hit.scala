package tracer.geometry

import tracer.math.Vec3

/** Where a ray meets a shape (course text, section 3.1).
  *
  * @param t      the distance along the ray, > 0
  * @param point  the intersection point ri
  * @param normal the unit surface normal rn, facing the side the ray came from
  * @param leaf   on a [[Csg]] combination, which of its primitives was hit (depth-first from 0);
  *   0 on any other shape
  */
final case class Hit(t: Double, point: Vec3, normal: Vec3, leaf: Int = 0)

/** Texture coordinates on a surface, each in [0, 1]: u across, v up (v = 1 is the image's top). */
final case class SurfaceCoordinates(u: Double, v: Double)
