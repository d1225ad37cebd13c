package tracer.math

/** An immutable vector of three doubles: a point, a direction or a normal in world space.
  *
  * The coordinate system is left-handed (x right, y up, z into the screen), but the formulas are
  * the usual ones (course text, section 3.1); handedness only decides how a picture is read.
  */
final case class Vec3(x: Double, y: Double, z: Double):

  /** The sum of this vector and `that`, component by component. */
  inline def +(that: Vec3): Vec3 = Vec3(x + that.x, y + that.y, z + that.z)

  /** The difference of this vector and `that`, component by component. */
  inline def -(that: Vec3): Vec3 = Vec3(x - that.x, y - that.y, z - that.z)

  /** This vector scaled by `s` (equation 4). */
  inline def *(s: Double): Vec3 = Vec3(x * s, y * s, z * s)

  /** This vector divided by `s`; the caller keeps `s` non-zero. */
  inline def /(s: Double): Vec3 = Vec3(x / s, y / s, z / s)

  /** The vector pointing the opposite way. */
  inline def unary_- : Vec3 = Vec3(-x, -y, -z)

  /** The dot product `x·x' + y·y' + z·z'` (equation 1). */
  inline def dot(that: Vec3): Double = x * that.x + y * that.y + z * that.z

  /** The cross product (equation 2): at right angles to both vectors, |a||b|sin θ long. */
  inline def cross(that: Vec3): Vec3 =
    Vec3(y * that.z - z * that.y, z * that.x - x * that.z, x * that.y - y * that.x)

  /** The squared Euclidean length, `this · this`. */
  inline def lengthSquared: Double = dot(this)

  /** The Euclidean length (equation 5). */
  inline def length: Double = Math.sqrt(lengthSquared)

  /** The distance between the points this vector and `that` stand for. */
  inline def distance(that: Vec3): Double = (this - that).length

  /** This vector scaled to length 1 (equation 6), or `None` for a vector of zero or non-finite length.
    *
    * Normalising can fail, so the result says so: no NaN ever leaks out of a zero vector.
    */
  def normalised: Option[Vec3] =
    val len = length
    if len > 0 && len < Double.PositiveInfinity then Some(this / len) else None

  /** This vector scaled to length 1, or `fallback` when it has zero or non-finite length.
    *
    * The form for hot loops, where the caller knows a sensible answer for the degenerate case.
    */
  inline def normalisedOr(inline fallback: Vec3): Vec3 =
    val len = length
    if len > 0 && len < Double.PositiveInfinity then this / len else fallback

  /** A compact `(x, y, z)` rendering for messages. */
  override def toString: String = s"($x, $y, $z)"

/** Constants and constructors for [[Vec3]]. */
object Vec3:
  /** The zero vector. */
  val Zero: Vec3 = Vec3(0, 0, 0)

  /** The unit vector along x. */
  val UnitX: Vec3 = Vec3(1, 0, 0)

  /** The unit vector along y. */
  val UnitY: Vec3 = Vec3(0, 1, 0)

  /** The unit vector along z. */
  val UnitZ: Vec3 = Vec3(0, 0, 1)

/** A scalar on the left of a vector: `s * v`. */
extension (s: Double) inline def *(v: Vec3): Vec3 = v * s
