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
  def cross(insides: List[Int], i: Int, ior: Int => Double): (Double, List[Int]) =
    crossing(insides, i, ior)((_, _))

  /** [[cross]]'s ratio and objects beyond handed to `k`, the same values.
    *
    * Perf: `inline` with inline arguments, so the shading's crossing of a clear surface makes no
    * tuple, boxed ratio or closure for `ior` (only the list of objects beyond, when it changes);
    * docs/performance.md, round 38.
    */
  inline def crossing[A](insides: List[Int], i: Int, inline ior: Int => Double)(
      inline k: (Double, List[Int]) => A
  ): A = insides match
    case Nil          => k(1 / ior(i), List(i))
    case `i` :: outer =>
      val beyond = if outer.contains(i) then withoutOutermost(insides, i) else outer
      k(ior(i) / (if beyond.isEmpty then 1.0 else ior(beyond.head)), beyond)
    case _ if insides.contains(i) => k(1.0, withoutOutermost(insides, i)) // leaving an overlap
    case innermost :: _           => k(ior(innermost) / ior(i), i :: insides)

  /** `insides` without its outermost (last) `i`: POV-Ray's `Ray::RemoveInterior` takes out the
    * first of its list, which runs outermost first. An object is in a ray's list twice only when
    * the ray started inside two parts of a glass union ([[World.containing]]); leaving it then
    * leaves the ray inside it still, so the ray goes on straight (η = 1), as in POV-Ray.
    */
  private[render] def withoutOutermost(insides: List[Int], i: Int): List[Int] =
    val last = insides.lastIndexOf(i)
    insides.take(last) ++ insides.drop(last + 1)

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

  /** [[refract]] on doubles, bit for bit: `bent` on the new direction's components, or `total`
    * for total internal reflection.
    *
    * Perf: `inline` with inline bodies, so the shading's refracted ray makes no `Vec3` or
    * `Option`, before C2's escape analysis as after it (steady state unchanged: solids 1645 →
    * 1643 ms a frame; docs/performance.md, round 16).
    */
  inline def refracted[A](
      dx: Double,
      dy: Double,
      dz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      eta: Double
  )(inline bent: (Double, Double, Double) => A)(inline total: => A): A =
    val cosine = dx * nx + dy * ny + dz * nz
    // The normal on the side the ray comes from, and the cosine of the angle of incidence.
    val front = cosine <= 0
    val fx    = if front then nx else -nx
    val fy    = if front then ny else -ny
    val fz    = if front then nz else -nz
    val cos   = if front then -cosine else cosine
    val k     = 1 + eta * eta * (cos * cos - 1)
    if k >= 0 then
      val m   = eta * cos - Math.sqrt(k)
      val ux  = dx * eta + fx * m
      val uy  = dy * eta + fy * m
      val uz  = dz * eta + fz * m
      val len = Math.sqrt(ux * ux + uy * uy + uz * uz)
      if len > 0 && len < Double.PositiveInfinity then bent(ux / len, uy / len, uz / len)
      else bent(dx, dy, dz)
    else total

  /** The mirror direction of `direction` about `normal`: Rd − 2(rn · Rd)rn (equation 44). */
  inline def reflect(direction: Vec3, normal: Vec3): Vec3 =
    direction - normal * (2 * normal.dot(direction))
