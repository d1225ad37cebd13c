package tracer.geometry

import tracer.math.Vec3

/** A half-line R(t) = origin + direction·t for t > 0 (course text, equation 7).
  *
  * @param origin    where the ray starts (R0)
  * @param direction which way it goes (Rd); unit length wherever a distance t is read as a length
  */
final case class Ray(origin: Vec3, direction: Vec3):

  /** The point at parameter `t` along the ray. */
  inline def at(t: Double): Vec3 = origin + direction * t
