package tracer.render

import tracer.math.Vec3

/** How a ray crosses the surface of a transparent object, as POV-Ray 3.7 does it
  * (docs/rendering.md, Transmission; POV-Ray's `Trace::ComputeRefraction`).
  *
  * A ray carries the objects it is inside, innermost first. Crossing a surface either enters the
  * object or leaves it, and the ratio of indices η = n₁/n₂ follows from that list: space outside
  * every object has index 1, and an object nested in another counts as if the outer one were not
  * there.
  */
object Refraction:

  /** |η − 1| below this is no refraction at all: the ray goes straight on (POV-Ray's EPSILON). */
  val SameIndex: Double = 1e-10

  /** Crossing the surface of object `i` from inside `insides` (innermost first), with `ior` each
    * object's index of refraction: the ratio η = n₁/n₂ and the objects the ray is inside beyond.
    */
  def cross(insides: List[Int], i: Int, ior: Int => Double): (Double, List[Int]) = insides match
    case Nil                      => (1 / ior(i), List(i))
    case `i` :: outer             => (ior(i) / outer.headOption.fold(1.0)(ior), outer)
    case _ if insides.contains(i) => (1.0, insides.filterNot(_ == i)) // leaving an overlap
    case innermost :: _           => (ior(innermost) / ior(i), i :: insides)

  /** The direction of a ray going `direction` (unit) after crossing a surface whose unit normal is
    * `normal` with ratio `eta` (Heckbert's formula), or `None` for total internal reflection.
    */
  def refract(direction: Vec3, normal: Vec3, eta: Double): Option[Vec3] =
    val cosine = direction.dot(normal)
    // The normal on the side the ray comes from, and the cosine of the angle of incidence.
    val (facing, cos) = if cosine <= 0 then (normal, -cosine) else (-normal, cosine)
    val k             = 1 + eta * eta * (cos * cos - 1)
    Option.when(k >= 0)(
      (direction * eta + facing * (eta * cos - Math.sqrt(k))).normalisedOr(direction)
    )

  /** The mirror direction of `direction` about `normal`: Rd − 2(rn · Rd)rn (equation 44). */
  inline def reflect(direction: Vec3, normal: Vec3): Vec3 =
    direction - normal * (2 * normal.dot(direction))
