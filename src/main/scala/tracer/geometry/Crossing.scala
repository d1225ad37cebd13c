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
