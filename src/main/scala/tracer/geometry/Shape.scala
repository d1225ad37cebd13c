package tracer.geometry

import tracer.math.Vec3

/** A geometric primitive: the closed set of shapes a scene can hold.
  *
  * Every operation on shapes is a total function in [[Shape$ the companion]], one `match` each,
  * so adding a shape means adding a case here and letting the compiler point at every match.
  */
sealed trait Shape

/** A sphere (course text, section 5.1) with the pole and equator that orient a texture on it.
  *
  * @param centre  the centre Sc
  * @param radius  the radius Sr, > 0
  * @param pole    the direction of the texture's top (Sp), normalised here
  * @param equator the direction of the texture's seam (Se), normalised here, at right angles to `pole`
  */
final case class Sphere(
    centre: Vec3,
    radius: Double,
    pole: Vec3 = Vec3.UnitY,
    equator: Vec3 = Vec3.UnitZ
) extends Shape:
  require(
    radius > 0 && radius.isFinite,
    s"a sphere's radius must be positive and finite, got $radius"
  )

  /** Sr², kept for the intersection test. */
  val radiusSquared: Double = radius * radius

  /** The unit pole Sp. */
  val unitPole: Vec3 =
    pole.normalised.getOrElse(throw IllegalArgumentException("the pole is the zero vector"))

  /** The unit equator Se. */
  val unitEquator: Vec3 =
    equator.normalised.getOrElse(throw IllegalArgumentException("the equator is the zero vector"))
  require(
    Math.abs(unitPole.dot(unitEquator)) <= Sphere.RightAngleTolerance,
    s"the pole $pole and equator $equator are not at right angles"
  )

  /** Se × Sp, which decides on which half of the sphere a point's u lies (equation 38). */
  val seamSide: Vec3 = unitEquator.cross(unitPole)

/** Rules shared by every [[Sphere]]. */
object Sphere:
  /** The largest |Sp · Se| (both normalised) accepted as a right angle. */
  val RightAngleTolerance: Double = 1e-6

/** An infinite plane of points p with p · normal = distance (course text, section 5.2).
  *
  * @param normal   the unit normal Pn
  * @param distance D, the signed distance of the plane from the origin along `normal`
  */
final case class Plane(normal: Vec3, distance: Double) extends Shape:
  require(
    Math.abs(normal.length - 1) < 1e-9,
    s"a plane's normal must be a unit vector, got $normal"
  )

/** Constructors for [[Plane]] from the two forms of the scene format. */
object Plane:
  /** The plane with (not necessarily unit) normal `normal` through `point`; D = point · Pn. */
  def through(point: Vec3, normal: Vec3): Plane =
    val n = unit(normal)
    Plane(n, point.dot(n))

  /** The plane of points p with p · n = `distance`, n the normalised `normal` (POV-Ray's form). */
  def at(normal: Vec3, distance: Double): Plane = Plane(unit(normal), distance)

  private def unit(normal: Vec3): Vec3 =
    normal.normalised.getOrElse(
      throw IllegalArgumentException("a plane's normal is the zero vector")
    )

/** A triangle with corners T0, T1 = T0 + a and T2 = T0 + b (course text, section 5.3).
  *
  * The derived values of equations 30–34 are computed once, here.
  *
  * @param textureCorners the texture coordinates of the three corners, for mesh triangles whose
  *   OBJ file gives them; without them a texture maps T0, T1, T2 to (0, 0), (1, 0), (0, 1)
  * @param cornerNormals  the unit normals at the three corners of a smooth mesh's face, which
  *   shading interpolates (scene-format-v2, Smooth meshes); without them the face is flat
  */
final case class Triangle(
    t0: Vec3,
    t1: Vec3,
    t2: Vec3,
    textureCorners: Option[(SurfaceCoordinates, SurfaceCoordinates, SurfaceCoordinates)] = None,
    cornerNormals: Option[(Vec3, Vec3, Vec3)] = None
) extends Shape:
  /** The leg a = T1 − T0. */
  val a: Vec3 = t1 - t0

  /** The leg b = T2 − T0. */
  val b: Vec3 = t2 - t0

  /** The unit normal Pn = normalise(a × b) (equation 30). */
  val normal: Vec3 = a
    .cross(b)
    .normalised
    .getOrElse(
      throw IllegalArgumentException(s"the corners $t0, $t1, $t2 are collinear")
    )

  /** D = T0 · Pn (equation 31). */
  val distance: Double = t0.dot(normal)

  /** a · a, b · b and a · b, the constants of equations 33–34. */
  val aa: Double = a.dot(a)

  /** b · b. */
  val bb: Double = b.dot(b)

  /** a · b. */
  val ab: Double = a.dot(b)

  /** The denominator of equation 33, (a · a)(b · b) − (a · b)²; positive for a real triangle. */
  val denominator: Double = aa * bb - ab * ab

/** Constructors for [[Triangle]]. */
object Triangle:
  /** The triangle with corner `origin` and legs `a` and `b`. */
  def fromLegs(origin: Vec3, a: Vec3, b: Vec3): Triangle = Triangle(origin, origin + a, origin + b)

  /** True when three points span a triangle: |(T1 − T0) × (T2 − T0)| > 0. */
  def isProper(t0: Vec3, t1: Vec3, t2: Vec3): Boolean =
    (t1 - t0).cross(t2 - t0).normalised.isDefined

/** The total functions on shapes: intersection distance, hit details and texture coordinates. */
object Shape:

  /** The distance t > 0 along `ray` to the nearest intersection with `shape`, or
    * `Double.PositiveInfinity` when the ray misses. `ray.direction` must be a unit vector.
    *
    * This is the hot test of the tracer: it allocates nothing the JIT cannot remove.
    */
  def distance(shape: Shape, ray: Ray): Double = shape match
    case s: Sphere   => sphereDistance(s, ray)
    case p: Plane    => planeDistance(p.normal, p.distance, ray)
    case t: Triangle => triangleDistance(t, ray)

  /** The full intersection of `ray` with `shape`, if it has one. */
  def intersect(shape: Shape, ray: Ray): Option[Hit] =
    val t = distance(shape, ray)
    Option.when(t < Double.PositiveInfinity)(hitAt(shape, ray, t))

  /** The hit at distance `t` (from [[distance]]) along `ray`: the point and the normal facing the ray. */
  def hitAt(shape: Shape, ray: Ray, t: Double): Hit =
    val point = ray.at(t)
    shape match
      case s: Sphere =>
        // Equation 23: the outward normal, flipped for a ray that starts inside.
        val outward = (point - s.centre) * (1 / s.radius)
        Hit(t, point, if startsInside(s, ray) then -outward else outward)
      case p: Plane     => Hit(t, point, facing(p.normal, ray))
      case tr: Triangle => Hit(t, point, facing(tr.normal, ray))

  /** The normal that shades the hit `hit` of `ray` on `shape`, facing the side the ray came from:
    * the geometric normal, except on a smooth triangle, where it is the corners' normals
    * interpolated with the hit's barycentric weights and normalised (POV-Ray's `smooth_triangle`).
    */
  def shadingNormal(shape: Shape, hit: Hit, ray: Ray): Vec3 = shape match
    case tr: Triangle if tr.cornerNormals.isDefined =>
      val (n0, n1, n2) = tr.cornerNormals.get
      val (u, v)       = triangleCoordinates(tr, hit.point - tr.t0)
      val blended      = n0 * (1 - u - v) + n1 * u + n2 * v
      facing(blended.normalisedOr(hit.normal), ray)
    case _ => hit.normal

  /** The texture coordinates of `point` on `shape` (rendering.md, Textures).
    *
    * Sphere: equations 35–38 with the outward normal. Triangle: the (u, v) of equations 33–34, or
    * for a mesh triangle its corners' coordinates interpolated at (u, v) and wrapped into [0, 1).
    * Plane: (0, 0), as planes take no texture.
    */
  def surfaceCoordinates(shape: Shape, point: Vec3): SurfaceCoordinates = shape match
    case s: Sphere    => sphereCoordinates(s, point)
    case tr: Triangle =>
      val (u, v) = triangleCoordinates(tr, point - tr.t0)
      tr.textureCorners match
        case None               => SurfaceCoordinates(u, v)
        case Some((c0, c1, c2)) =>
          // scene-format.md, mesh: interpolate the corners' coordinates, wrap each into [0, 1).
          def wrap(x: Double) = x - Math.floor(x)
          val w               = 1 - u - v
          SurfaceCoordinates(
            wrap(w * c0.u + u * c1.u + v * c2.u),
            wrap(w * c0.v + u * c1.v + v * c2.v)
          )
    case _: Plane => SurfaceCoordinates(0, 0)

  /** Equations 17–21: the nearer root for a ray from outside, the farther one from inside. */
  private def sphereDistance(s: Sphere, ray: Ray): Double =
    // Perf: OC = Sc − R0 in three doubles, not a Vec3: until C2 compiles this (most of a short
    // run) nothing is scalar-replaced, and a Vec3 a test is garbage (docs/performance.md, step 8).
    val ocx  = s.centre.x - ray.origin.x
    val ocy  = s.centre.y - ray.origin.y
    val ocz  = s.centre.z - ray.origin.z
    val l2oc = ocx * ocx + ocy * ocy + ocz * ocz
    val tca  = ocx * ray.direction.x + ocy * ray.direction.y + ocz * ray.direction.z
    val t2hc = s.radiusSquared - l2oc + tca * tca
    if l2oc < s.radiusSquared then tca + Math.sqrt(t2hc)
    else if tca < 0 || t2hc < 0 then Double.PositiveInfinity
    else positive(tca - Math.sqrt(t2hc))

  /** Equations 24–27: vd = 0 (a ray parallel to the plane) misses. */
  private inline def planeDistance(normal: Vec3, distance: Double, ray: Ray): Double =
    val vd = normal.dot(ray.direction)
    if vd == 0 then Double.PositiveInfinity
    else positive((distance - normal.dot(ray.origin)) / vd)

  /** The plane test, then equations 32–34: edges and corners count as hits. */
  private def triangleDistance(tr: Triangle, ray: Ray): Double =
    val t = planeDistance(tr.normal, tr.distance, ray)
    if t == Double.PositiveInfinity then t
    else
      // Perf: q = R0 + Rd·t − T0 in three doubles, as in sphereDistance.
      val qx = ray.origin.x + ray.direction.x * t - tr.t0.x
      val qy = ray.origin.y + ray.direction.y * t - tr.t0.y
      val qz = ray.origin.z + ray.direction.z * t - tr.t0.z
      val qa = qx * tr.a.x + qy * tr.a.y + qz * tr.a.z
      val qb = qx * tr.b.x + qy * tr.b.y + qz * tr.b.z
      val u  = (tr.bb * qa - tr.ab * qb) / tr.denominator
      val v  = (qb - u * tr.ab) / tr.bb
      if u >= 0 && v >= 0 && u + v <= 1 then t else Double.PositiveInfinity

  /** Equations 33–34: the coordinates (u, v) of q = u·a + v·b in the triangle's legs. */
  private def triangleCoordinates(tr: Triangle, q: Vec3): (Double, Double) =
    val qa = q.dot(tr.a)
    val qb = q.dot(tr.b)
    val u  = (tr.bb * qa - tr.ab * qb) / tr.denominator
    (u, (qb - u * tr.ab) / tr.bb)

  /** Equations 35–38 with rn the outward unit normal; arccos arguments clamped against rounding. */
  private def sphereCoordinates(s: Sphere, point: Vec3): SurfaceCoordinates =
    val rn  = (point - s.centre) * (1 / s.radius)
    val phi = Math.acos(clamp(-rn.dot(s.unitPole)))
    val v   = phi / Math.PI
    if v == 0 || v == 1 then SurfaceCoordinates(0, v)
    else
      val theta = Math.acos(clamp(s.unitEquator.dot(rn) / Math.sin(phi))) / (2 * Math.PI)
      SurfaceCoordinates(if s.seamSide.dot(rn) > 0 then theta else 1 - theta, v)

  private def startsInside(s: Sphere, ray: Ray): Boolean =
    val oc = s.centre - ray.origin
    oc.dot(oc) < s.radiusSquared

  /** Equation 29: Pn when vd < 0, else −Pn. */
  private inline def facing(normal: Vec3, ray: Ray): Vec3 =
    if normal.dot(ray.direction) < 0 then normal else -normal

  private inline def positive(t: Double): Double = if t > 0 then t else Double.PositiveInfinity

  private inline def clamp(x: Double): Double = Math.max(-1.0, Math.min(1.0, x))
