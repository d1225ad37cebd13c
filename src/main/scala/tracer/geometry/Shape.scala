package tracer.geometry

import tracer.math.{Placement, Transform, Vec3}

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
    // Why: a broken invariant, as with require: the scene reader rejects a zero vector first.
    pole.normalised.getOrElse(throw IllegalArgumentException("the pole is the zero vector"))

  /** The unit equator Se. */
  val unitEquator: Vec3 =
    // Why: a broken invariant, as with require: the scene reader rejects a zero vector first.
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
    // Why: a broken invariant, as with require: the scene reader rejects a zero normal first.
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
  *   shading interpolates (docs/scene-format.md, Version 2, Smooth meshes); without them the face is flat
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
      // Why: a broken invariant, as with require: the scene and OBJ readers check
      // Triangle.isProper first.
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

  /** This triangle where `placement` takes it: its corners moved and its corner normals turned,
    * its texture coordinates kept (the format never places a triangle; a placed union's are read
    * so, and written so).
    */
  def placed(placement: Placement): Triangle =
    val m             = placement.transform
    def turn(n: Vec3) = m.normal(n).normalisedOr(n)
    Triangle(
      m.point(t0),
      m.point(t1),
      m.point(t2),
      textureCorners,
      cornerNormals.map((a, b, c) => (turn(a), turn(b), turn(c)))
    )

/** Constructors for [[Triangle]]. */
object Triangle:
  /** The triangle with corner `origin` and legs `a` and `b`. */
  def fromLegs(origin: Vec3, a: Vec3, b: Vec3): Triangle = Triangle(origin, origin + a, origin + b)

  /** True when three points span a triangle: |(T1 − T0) × (T2 − T0)| > 0. */
  def isProper(t0: Vec3, t1: Vec3, t2: Vec3): Boolean =
    (t1 - t0).cross(t2 - t0).normalised.isDefined

/** A triangle mesh (the `mesh` element): one shape whose faces share an array of vertices, each
  * face an index triple, with optional shared normals and texture coordinates (issue 23).
  *
  * Face f is the triangle [[face]](f), with exactly the values a [[Triangle]] of its corners has;
  * every total function on shapes treats the mesh as the union of its faces, face f as leaf f
  * (as a [[Csg]] union of the faces would number them), and a tie between faces goes to the lower
  * face, as one between the triangles of a scene goes to the earlier one. The faces' planes
  * (Pn, D) are computed once, here; the rest of a face's constants are derived from its corners
  * when a ray meets it (`Mesh.faceDistance`).
  *
  * @param vertices      3 doubles a vertex: x, y, z, in the space the mesh is placed in
  * @param corners       3 vertex numbers a face, in the file's corner order; every face proper
  *   ([[Triangle.isProper]])
  * @param normals       3 doubles a unit normal, shared by the corners that name it
  * @param cornerNormals 3 normal numbers a face, or −1 three times for a flat face; empty when
  *   every face is flat
  * @param uvs           2 doubles a texture coordinate (u, v)
  * @param cornerUvs     3 texture coordinate numbers a face, or −1 three times for a face
  *   without them; empty when no face has them
  */
final class Mesh(
    val vertices: IArray[Double],
    val corners: IArray[Int],
    val normals: IArray[Double] = IArray.empty[Double],
    val cornerNormals: IArray[Int] = IArray.empty[Int],
    val uvs: IArray[Double] = IArray.empty[Double],
    val cornerUvs: IArray[Int] = IArray.empty[Int]
) extends Shape:
  /** The number of faces, ≥ 1. */
  val faceCount: Int = corners.length / 3
  require(
    faceCount > 0 && corners.length == 3 * faceCount,
    s"a mesh needs at least one face of three corners, got ${corners.length} corners"
  )
  require(
    cornerNormals.isEmpty || cornerNormals.length == corners.length,
    "a mesh's corner normals must be given for every face or for none"
  )
  require(
    cornerUvs.isEmpty || cornerUvs.length == corners.length,
    "a mesh's corner texture coordinates must be given for every face or for none"
  )

  /** The smallest box around the faces' corners (every face checked proper on the way). */
  val extent: Bounds = Mesh.extentOf(vertices, corners)

  /** Each face's plane: Pn (x, y, z) and D at 4f, computed as [[Triangle]] computes them.
    *
    * Perf: made on first use only, by the general path (a mesh inside a placement or a CSG
    * element): a mesh at the top of a scene is tested by its own tree, which keeps the planes in
    * its leaf order, and shading reads a face's normal from there, so
    * a 1.3M-face mesh does not hold a second 41 MB copy (docs/performance.md, round 7).
    */
  lazy val planes: IArray[Double] = Mesh.planesOf(vertices, corners)

  /** Vertex `i` as a point. */
  def vertex(i: Int): Vec3 = Vec3(vertices(3 * i), vertices(3 * i + 1), vertices(3 * i + 2))

  /** The unit normal of face `f` (its plane's Pn, derived from its corners as [[planes]] is). */
  def faceNormal(f: Int): Vec3 =
    Mesh.plane(vertices, corners, f)((nx, ny, nz, _) => Vec3(nx, ny, nz))

  /** True when face `f` shades with its corners' normals interpolated. */
  def smoothFace(f: Int): Boolean = cornerNormals.length > 0 && cornerNormals(3 * f) >= 0

  /** True when face `f` has texture coordinates at its corners. */
  def texturedFace(f: Int): Boolean = cornerUvs.length > 0 && cornerUvs(3 * f) >= 0

  /** Face `f` as the triangle it stands for: its corners, texture coordinates and normals. */
  def face(f: Int): Triangle =
    def normal(k: Int) =
      val at = 3 * cornerNormals(3 * f + k)
      Vec3(normals(at), normals(at + 1), normals(at + 2))
    def uv(k: Int) =
      val at = 2 * cornerUvs(3 * f + k)
      SurfaceCoordinates(uvs(at), uvs(at + 1))
    Triangle(
      vertex(corners(3 * f)),
      vertex(corners(3 * f + 1)),
      vertex(corners(3 * f + 2)),
      Option.when(texturedFace(f))((uv(0), uv(1), uv(2))),
      Option.when(smoothFace(f))((normal(0), normal(1), normal(2)))
    )

  /** Every face, in order, as [[face]] gives it. */
  def faces: Iterator[Triangle] = Iterator.range(0, faceCount).map(face)

  /** The mesh with its vertices moved and its normals turned by `m` (normalised, as a placed
    * triangle's are); the same faces.
    */
  def transformed(m: Transform): Mesh =
    def each(xs: IArray[Double], f: Vec3 => Vec3): IArray[Double] =
      IArray.from(Iterator.range(0, xs.length / 3).flatMap { i =>
        val v = f(Vec3(xs(3 * i), xs(3 * i + 1), xs(3 * i + 2)))
        Iterator(v.x, v.y, v.z)
      })
    Mesh(
      each(vertices, m.point),
      corners,
      each(normals, n => m.normal(n).normalisedOr(n)),
      cornerNormals,
      uvs,
      cornerUvs
    )

  override def equals(that: Any): Boolean = that match
    case m: Mesh =>
      vertices.sameElements(m.vertices) && corners.sameElements(m.corners) &&
      normals.sameElements(m.normals) && cornerNormals.sameElements(m.cornerNormals) &&
      uvs.sameElements(m.uvs) && cornerUvs.sameElements(m.cornerUvs)
    case _ => false

  override def hashCode: Int = (faceCount, vertices.length, extent).hashCode

  override def toString: String = s"Mesh($faceCount faces, ${vertices.length / 3} vertices)"

/** The face test shared by the mesh's reference path and the ray kernel. */
object Mesh:
  /** The planes of the faces `corners` on `vertices` (see [[Mesh.planes]]). */
  private def planesOf(vertices: IArray[Double], corners: IArray[Int]): IArray[Double] =
    val faceCount = corners.length / 3
    val out       = new Array[Double](4 * faceCount)
    // Perf: a counted loop over the faces on plain doubles, once per mesh, in a method of its own
    // (compiled on its own: in the constructor the loop ran interpreted for seconds on a million
    // faces).
    var f = 0
    while f < faceCount do
      plane(vertices, corners, f) { (nx, ny, nz, d) =>
        out(4 * f) = nx; out(4 * f + 1) = ny; out(4 * f + 2) = nz; out(4 * f + 3) = d
      }
      f += 1
    IArray.unsafeFromArray(out)

  /** Runs `body` on the plane of face `f` (Pn's x, y, z and D; see [[Mesh.planes]]), computed
    * with the arithmetic of [[Triangle]]'s normal (a × b, `Vec3.normalised`) and distance
    * (T0 · Pn), operation for operation. The face must be proper.
    *
    * Perf: `inline` with an inline body, so the four doubles need no tuple or array.
    */
  inline def plane[A](vertices: IArray[Double], corners: IArray[Int], f: Int)(
      inline body: (Double, Double, Double, Double) => A
  ): A =
    val i0 = 3 * corners(3 * f)
    cross(vertices, corners, f) { (cx, cy, cz, len) =>
      val nx = cx / len; val ny = cy / len; val nz = cz / len
      body(nx, ny, nz, vertices(i0) * nx + vertices(i0 + 1) * ny + vertices(i0 + 2) * nz)
    }

  /** Runs `body` on face `f`'s cross product (T1 − T0) × (T2 − T0) and its length, with the
    * arithmetic of `Vec3.cross` and `Vec3.length`, operation for operation.
    *
    * Perf: `inline` with an inline body, as [[plane]]: plain doubles, no `Vec3`.
    */
  inline def cross[A](vertices: IArray[Double], corners: IArray[Int], f: Int)(
      inline body: (Double, Double, Double, Double) => A
  ): A =
    val i0 = 3 * corners(3 * f); val i1 = 3 * corners(3 * f + 1); val i2 = 3 * corners(3 * f + 2)
    val x0 = vertices(i0); val y0       = vertices(i0 + 1); val z0       = vertices(i0 + 2)
    val ax = vertices(i1) - x0; val ay  = vertices(i1 + 1) - y0; val az  = vertices(i1 + 2) - z0
    val bx = vertices(i2) - x0; val by  = vertices(i2 + 1) - y0; val bz  = vertices(i2 + 2) - z0
    val cx = ay * bz - az * by; val cy  = az * bx - ax * bz; val cz      = ax * by - ay * bx
    body(cx, cy, cz, Math.sqrt(cx * cx + cy * cy + cz * cz))

  /** True when face `f`'s corners span a triangle: [[Triangle.isProper]] on the mesh's arrays
    * (the cross product's length finite and above 0).
    */
  def isProperFace(vertices: IArray[Double], corners: IArray[Int], f: Int): Boolean =
    cross(vertices, corners, f)((_, _, _, len) => len > 0 && len < Double.PositiveInfinity)

  /** The box around the corners `corners` name in `vertices`; every face must be proper. */
  private def extentOf(vertices: IArray[Double], corners: IArray[Int]): Bounds =
    // Perf: min and max over the corners' coordinates (low x, y, z, then high, in `box`), no
    // Bounds per face; each face's cross product checked on the way (the planes themselves are
    // made later, or by the tree). One call a face, so the face's work is compiled after a few
    // hundred faces rather than interpreted until the loop is compiled on stack (mesh-80000 at
    // 1280×720 had 32 interpreted samples here; docs/performance.md, round 27).
    val box = Array.fill(6)(Double.PositiveInfinity)
    box(3) = Double.NegativeInfinity; box(4) = Double.NegativeInfinity
    box(5) = Double.NegativeInfinity
    var f = 0
    while f < corners.length / 3 do
      extendByFace(vertices, corners, f, box)
      f += 1
    Bounds(Vec3(box(0), box(1), box(2)), Vec3(box(3), box(4), box(5)))

  /** Widens `box` (low x, y, z, then high) to take face `f`'s corners, after checking the face
    * proper.
    */
  private def extendByFace(
      vertices: IArray[Double],
      corners: IArray[Int],
      f: Int,
      box: Array[Double]
  ): Unit =
    if !isProperFace(vertices, corners, f) then
      // Why: a broken invariant, as with require: the mesh reader keeps proper faces only.
      throw IllegalArgumentException(s"face $f of a mesh has collinear corners")
    // Perf: the face's three corners, each coordinate against both ends of the box.
    var k = 3 * f
    while k < 3 * f + 3 do
      val at = 3 * corners(k)
      box(0) = Math.min(box(0), vertices(at)); box(3) = Math.max(box(3), vertices(at))
      box(1) = Math.min(box(1), vertices(at + 1)); box(4) = Math.max(box(4), vertices(at + 1))
      box(2) = Math.min(box(2), vertices(at + 2)); box(5) = Math.max(box(5), vertices(at + 2))
      k += 1

  /** The distance along the ray from (ox, oy, oz) in unit direction (dx, dy, dz) to the face with
    * plane (nx, ny, nz, d) and corners at `vertices(i0)`, `vertices(i1)`, `vertices(i2)` (each
    * the first of three doubles), or +∞ on a miss; a hit beyond `cutoff` may be reported as a
    * miss. Bit for bit `Shape.distance` of the face's [[Triangle]]: the plane test (equations
    * 24–27), then equations 32–34 with a = T1 − T0, b = T2 − T0 and the constants a · a, b · b,
    * a · b and (a · a)(b · b) − (a · b)² formed as [[Triangle]] forms them.
    */
  inline def faceDistance(
      nx: Double,
      ny: Double,
      nz: Double,
      d: Double,
      vertices: IArray[Double],
      i0: Int,
      i1: Int,
      i2: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val t = Kernel.planeT(nx, ny, nz, d, ox, oy, oz, dx, dy, dz)
    // Perf: a hit beyond the cutoff cannot count, so its barycentric test is skipped, as the
    // kernel's triangles do (Primitives.triangle).
    if t == Double.PositiveInfinity || t > cutoff then Double.PositiveInfinity
    else
      val x0 = vertices(i0); val y0      = vertices(i0 + 1); val z0      = vertices(i0 + 2)
      val ax = vertices(i1) - x0; val ay = vertices(i1 + 1) - y0; val az = vertices(i1 + 2) - z0
      val bx = vertices(i2) - x0; val by = vertices(i2 + 1) - y0; val bz = vertices(i2 + 2) - z0
      val qx = ox + dx * t - x0
      val qy = oy + dy * t - y0
      val qz = oz + dz * t - z0
      val qa = qx * ax + qy * ay + qz * az
      val qb = qx * bx + qy * by + qz * bz
      val bb = bx * bx + by * by + bz * bz
      val ab = ax * bx + ay * by + az * bz
      val aa = ax * ax + ay * ay + az * az
      val u  = (bb * qa - ab * qb) / (aa * bb - ab * ab)
      if !(u >= 0) then Double.PositiveInfinity
      else
        val v = (qb - u * ab) / bb
        if v >= 0 && u + v <= 1 then t else Double.PositiveInfinity

  /** [[faceDistance]] of face `f` of `mesh`, from its own arrays. */
  inline def distanceTo(
      mesh: Mesh,
      f: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val p = mesh.planes
    val c = mesh.corners
    faceDistance(
      p(4 * f),
      p(4 * f + 1),
      p(4 * f + 2),
      p(4 * f + 3),
      mesh.vertices,
      3 * c(3 * f),
      3 * c(3 * f + 1),
      3 * c(3 * f + 2),
      cutoff,
      ox,
      oy,
      oz,
      dx,
      dy,
      dz
    )

/** A box with faces parallel to the axes, between two opposite corners (scene format v3; POV-Ray's
  * `box`).
  *
  * @param corner1 one corner
  * @param corner2 the opposite corner, differing from `corner1` in every coordinate
  */
final case class Box(corner1: Vec3, corner2: Vec3) extends Shape:
  require(
    corner1.x != corner2.x && corner1.y != corner2.y && corner1.z != corner2.z,
    s"a box's corners must differ in every coordinate, got $corner1 and $corner2"
  )

  /** The box's extent: its smallest and largest coordinates. */
  val extent: Bounds = Bounds.around(Seq(corner1, corner2))

/** A cone's frustum from a base disc to a cap disc (scene format v3; POV-Ray's `cone`), or with
  * both radii equal a cylinder. A radius may be 0 (a point), but not both.
  *
  * @param base       the centre of the base disc
  * @param baseRadius the base disc's radius, ≥ 0
  * @param cap        the centre of the cap disc, not `base`
  * @param capRadius  the cap disc's radius, ≥ 0
  * @param open       true for the side alone, without the discs: then the shape has no inside
  */
final case class Cone(
    base: Vec3,
    baseRadius: Double,
    cap: Vec3,
    capRadius: Double,
    open: Boolean = false
) extends Shape:
  require(
    baseRadius >= 0 && capRadius >= 0 && baseRadius + capRadius > 0,
    s"a cone's radii must be at least 0 and not both 0, got $baseRadius and $capRadius"
  )

  /** The distance from base to cap. */
  val height: Double = base.distance(cap)
  require(height > 0, s"a cone's base and cap must differ, both are $base")

  /** The unit axis from base to cap. */
  val axis: Vec3 = (cap - base) / height

  /** How fast the radius grows along the axis: (capRadius − baseRadius) / height. */
  val slope: Double = (capRadius - baseRadius) / height

  /** 0, 1 or 2 when the axis is exactly ±x, ±y or ±z (one coordinate ±1, the others 0), else
    * −1: the kernel's tests then skip the products with the zero coordinates, to the same
    * results ([[ConeKernel]]).
    */
  private[geometry] val axial: Int =
    if Math.abs(axis.x) == 1 && axis.y == 0 && axis.z == 0 then 0
    else if axis.x == 0 && Math.abs(axis.y) == 1 && axis.z == 0 then 1
    else if axis.x == 0 && axis.y == 0 && Math.abs(axis.z) == 1 then 2
    else -1

/** Constructors of cylinders, which are [[Cone]]s with equal radii. */
object Cylinder:
  /** The cylinder of `radius` (> 0) from `base` to `cap`; `open` leaves out its end discs. */
  def apply(base: Vec3, cap: Vec3, radius: Double, open: Boolean = false): Cone =
    require(radius > 0, s"a cylinder's radius must be greater than 0, got $radius")
    Cone(base, radius, cap, radius, open)

/** A torus around the y axis, centred on the origin (scene format v3; POV-Ray's `torus`).
  *
  * @param major the distance from the origin to the centre of the tube, > 0
  * @param minor the tube's radius, > 0
  */
final case class Torus(major: Double, minor: Double) extends Shape:
  require(major > 0 && minor > 0, s"a torus's radii must be greater than 0, got $major and $minor")

/** A shape scaled, rotated and moved (docs/scene-format.md, Placement). Rays are taken into the
  * shape's own space, met there, and their distances and normals brought back (pbrt's
  * transformed primitives).
  *
  * @param shape     the shape in its own space
  * @param placement from the shape's own space to the space around it
  */
final case class Placed(shape: Shape, placement: Placement) extends Shape:
  /** The placement's map. */
  def transform: Transform = placement.transform

  /** M⁻¹ (row-major) and t of the placement, for the kernel's ray transform on plain doubles. */
  private[geometry] val back: Array[Double] = Array.from(transform.backEntries)

  /** True when some leaf is a smooth triangle or a mesh with a smooth face. */
  val smooth: Boolean = Shape.hasSmoothLeaf(shape)

/** How a [[Csg]] combines its children. */
enum CsgOperation:
  /** Every child: all their surfaces, inner ones included (POV-Ray's `union`, not `merge`). */
  case Union

  /** The points inside every child. */
  case Intersection

  /** The points inside the first child and outside every later one. */
  case Difference

/** Constructive solid geometry: children combined by an operation (docs/rendering.md,
  * Constructive solid geometry). The primitives in the tree are its leaves, numbered depth-first
  * from 0; a hit says which leaf it is on, so that each can have its own surface.
  *
  * @param operation how the children combine
  * @param children  at least one; triangles (which have no inside) only in a union
  */
final case class Csg(operation: CsgOperation, children: Vector[Shape]) extends Shape:
  require(children.nonEmpty, "a CSG combination needs at least one child")

  /** The number of leaves below each child, in order. */
  val leafCounts: Vector[Int] = children.map(Shape.leafCount)

  /** The number of the first leaf of each child. */
  val firstLeaves: Vector[Int] = leafCounts.scanLeft(0)(_ + _).init

  /** True when some leaf is a smooth triangle or a mesh with a smooth face. */
  val smooth: Boolean = children.exists(Shape.hasSmoothLeaf)

  /** The children and their first leaves as arrays, for the kernel's loops. */
  private[geometry] val parts: Array[Shape]    = children.toArray
  private[geometry] val partLeaves: Array[Int] = firstLeaves.toArray

  /** Each child's bounds, widened a little, six doubles a child (low corner, high corner; ±∞ for
    * an unbounded child): the kernel skips a child whose box a ray misses (Kernel.reach).
    */
  private[geometry] val partBoxes: Array[Double] = CsgKernel.paddedBoxes(parts)

  /** Bit j set when child j (of the first 64) holds a triangle or mesh, whose complement the
    * kernel tests even where a ray misses its box ([[Shape.holdsPatch]]).
    */
  private[geometry] val patchParts: Long =
    parts.indices
      .take(64)
      .foldLeft(0L)((m, j) => if Shape.holdsPatch(parts(j)) then m | 1L << j else m)

/** The total functions on shapes: intersection distance, hit details and texture coordinates. */
object Shape:

  /** The distance t > 0 along `ray` to the nearest intersection with `shape`, or
    * `Double.PositiveInfinity` when the ray misses. `ray.direction` must be a unit vector.
    *
    * This is the hot test of the tracer: it allocates nothing the JIT cannot remove, except on a
    * mesh, where it is the reference (each face as its [[Triangle]]) and the ray kernel's mesh
    * tree the fast path.
    */
  def distance(shape: Shape, ray: Ray): Double = shape match
    case s: Sphere   => sphereDistance(s, ray)
    case p: Plane    => planeDistance(p.normal, p.distance, ray)
    case t: Triangle => triangleDistance(t, ray)
    case m: Mesh     => m.faces.foldLeft(Miss)((best, face) => best min triangleDistance(face, ray))
    case c: Csg if c.operation == CsgOperation.Union =>
      c.children.foldLeft(Double.PositiveInfinity)((best, child) => best min distance(child, ray))
    case p: Placed =>
      val (local, stretch) = ownSpace(p, ray)
      distance(p.shape, local) / stretch
    case other: (Box | Cone | Torus | Csg) => crossings(other, ray).headOption.fold(Miss)(_.t)

  /** The full intersection of `ray` with `shape`, if it has one. */
  def intersect(shape: Shape, ray: Ray): Option[Hit] =
    val t = distance(shape, ray)
    Option.when(t < Double.PositiveInfinity)(hitAt(shape, ray, t))

  /** The hit at distance `t` (from [[distance]]) along `ray`: the point and the normal facing the
    * ray, and for a combination the leaf it is on. A `t` at which a box, cone, torus, placed shape
    * or combination has no crossing is a caller's bug: `IllegalArgumentException`.
    */
  def hitAt(shape: Shape, ray: Ray, t: Double): Hit =
    val point = ray.at(t)
    shape match
      case s: Sphere =>
        // Equation 23: the outward normal, flipped for a ray that starts inside.
        val outward = (point - s.centre) * (1 / s.radius)
        val inside  = startsInside(s, ray)
        Hit(t, point, if inside then -outward else outward, front = !inside)
      case p: Plane     => facingHit(t, point, p.normal, 0, ray)
      case tr: Triangle => facingHit(t, point, tr.normal, 0, ray)
      case m: Mesh      =>
        // The reference: the first face at distance t, as the first of the faces' triangles.
        val f = (0 until m.faceCount).indexWhere(f => triangleDistance(m.face(f), ray) == t)
        if f < 0 then
          // Why: a t that is no face's distance is a caller's bug, as on the general path below.
          throw IllegalArgumentException(s"Shape.hitAt: no face of $m at t = $t along $ray")
        facingHit(t, point, m.faceNormal(f), f, ray)
      case other: (Box | Cone | Torus | Placed | Csg) =>
        // The general path: the nearest crossing again, for its normal and leaf: the first of
        // `crossings`, here from the kernel on this thread's buffer, which finds it without a
        // list or the crossings behind it (Kernel.firstCrossing; docs/performance.md, round 5).
        val buffer = Kernel.scratch.get()
        val o      = ray.origin
        val d      = ray.direction
        if Kernel.firstCrossing(other, o.x, o.y, o.z, d.x, d.y, d.z, buffer, 0) > 0 then
          val first = buffer.t(0)
          val n     = Vec3(buffer.nx(0), buffer.ny(0), buffer.nz(0))
          facingHit(first, ray.at(first), n, buffer.leaf(0), ray)
        else
          // Why: distance is the first crossing, so a t from it always has one (ShapeProperties);
          // none means a caller's t that is not a hit, a bug a made-up normal would only hide.
          throw IllegalArgumentException(s"Shape.hitAt: no crossing of $other along $ray (t = $t)")

  /** The hit at distance `t` along `ray` on face `face` of `mesh`, which the ray meets there (the
    * face the ray kernel found): what [[hitAt]] gives when that face is the first at t, without
    * looking for it.
    */
  def hitOnFace(mesh: Mesh, face: Int, ray: Ray, t: Double): Hit =
    facingHit(t, ray.at(t), mesh.faceNormal(face), face, ray)

  /** Every crossing of `ray` with the surface of `shape` at t > 0, in increasing t: what
    * constructive solid geometry combines. `ray.direction` must be a unit vector. With
    * `inversions` (0, the default: none; 1 an odd number; 2 an even number, at least two), the
    * crossings of the shape as POV-Ray rebuilds it when it inverts a later child of a
    * difference: the same for a primitive, none for a mesh of more than one face inverted (a
    * union of triangles, each of whose complements is empty: [[insideComplement]]), a
    * combination's as [[Combination.crossings]] says.
    */
  def crossings(shape: Shape, ray: Ray, inversions: Int = 0): List[Crossing] = shape match
    case s: Sphere =>
      val oc   = s.centre - ray.origin
      val tca  = oc.dot(ray.direction)
      val t2hc = s.radiusSquared - oc.dot(oc) + tca * tca
      if t2hc < 0 then Nil
      else
        val half = Math.sqrt(t2hc)
        List(tca - half, tca + half)
          .filter(_ > 0)
          .map(t => Crossing(t, (ray.at(t) - s.centre) * (1 / s.radius), 0))
    case p: Plane =>
      val t = planeDistance(p.normal, p.distance, ray)
      if t < Miss then List(Crossing(t, p.normal, 0)) else Nil
    case tr: Triangle =>
      val t = triangleDistance(tr, ray)
      if t < Miss then List(Crossing(t, tr.normal, 0)) else Nil
    // The complement of a mesh of many faces has no surface: each face's crossing would have to
    // lie inside the others' complements, which are empty (its POV-Ray twin is a union of its
    // triangles, and POV-Ray inverts a union into the intersection of its children's complements).
    case m: Mesh if inversions == Combination.Inverted && m.faceCount > 1 => Nil
    case m: Mesh                                                          =>
      (0 until m.faceCount).toList
        .flatMap(f => crossings(m.face(f), ray).map(_.copy(leaf = f)))
        .sortBy(_.t)
    case b: Box    => Solids.boxCrossings(b, ray)
    case c: Cone   => Solids.coneCrossings(c, ray)
    case t: Torus  => Solids.torusCrossings(t, ray)
    case p: Placed =>
      val (local, stretch) = ownSpace(p, ray)
      crossings(p.shape, local, inversions).map(c =>
        Crossing(c.t / stretch, p.transform.normal(c.normal).normalisedOr(c.normal), c.leaf)
      )
    case c: Csg => Combination.crossings(c, ray, inversions)

  /** True when `point` is inside the solid `shape` (POV-Ray's inside tests, their tolerances
    * included): for a plane, the side its normal points away from; triangles have no inside.
    */
  def inside(shape: Shape, point: Vec3): Boolean = shape match
    case s: Sphere   => (point - s.centre).lengthSquared < s.radiusSquared
    case p: Plane    => point.dot(p.normal) < p.distance + Solids.InsideTolerance
    case _: Triangle => false
    case _: Mesh     => false
    case b: Box      => Solids.insideBox(b, point)
    case c: Cone     => Solids.insideCone(c, point)
    case t: Torus    => Solids.insideTorus(t, point)
    case p: Placed   => inside(p.shape, p.transform.pointBack(point))
    case c: Csg      => Combination.inside(c, point)

  /** True when `point` is inside the complement of `shape` as POV-Ray inverts a later child of a
    * difference: outside it, for a solid; a triangle or mesh, which has no inside, has no inside
    * when inverted either (POV-Ray's patch objects), and a combination's complement follows De
    * Morgan's rules over its children's ([[Combination.insideComplement]]). So a complement
    * holding a triangle is not the outside of the shape: the complement of a union holding one
    * is empty.
    */
  def insideComplement(shape: Shape, point: Vec3): Boolean = shape match
    case _: (Triangle | Mesh) => false
    case p: Placed            => insideComplement(p.shape, p.transform.pointBack(point))
    case c: Csg               => Combination.insideComplement(c, point)
    case _: (Sphere | Plane | Box | Cone | Torus) => !inside(shape, point)

  /** True when some leaf of `shape` is a triangle or a mesh: then its complement's inside is not
    * its outside ([[insideComplement]]).
    */
  def holdsPatch(shape: Shape): Boolean = shape match
    case _: (Triangle | Mesh)                     => true
    case p: Placed                                => holdsPatch(p.shape)
    case c: Csg                                   => c.children.exists(holdsPatch)
    case _: (Sphere | Plane | Box | Cone | Torus) => false

  /** The number of primitives in `shape`: 1, for a mesh its faces, for a combination the sum over
    * its children.
    */
  def leafCount(shape: Shape): Int = shape match
    case c: Csg                                              => c.leafCounts.sum
    case m: Mesh                                             => m.faceCount
    case p: Placed                                           => leafCount(p.shape)
    case _: (Sphere | Plane | Triangle | Box | Cone | Torus) => 1

  /** The smallest axis-aligned box around `shape` (for an intersection or difference holding a
    * triangle or mesh, the box around all its children, which it needs when it cuts), or `None`
    * when it is unbounded (a plane, or a combination that keeps all of one).
    */
  def bounds(shape: Shape): Option[Bounds] = shape match
    case s: Sphere =>
      val r = Vec3(s.radius, s.radius, s.radius)
      Some(Bounds(s.centre - r, s.centre + r))
    case _: Plane => None
    // Perf: the corners' box directly, no list folded box by box: the hierarchy asks every
    // triangle of a scene once, cold (the 5 MB scene's 20,000; docs/performance.md, round 21).
    case t: Triangle => Some(Bounds.of(t.t0, t.t1, t.t2))
    case m: Mesh     => Some(m.extent)
    case b: Box      => Some(b.extent)
    case c: Cone => Some(disc(c.base, c.baseRadius, c.axis).union(disc(c.cap, c.capRadius, c.axis)))
    case t: Torus =>
      val (r, h) = (t.major + t.minor, t.minor)
      Some(Bounds(Vec3(-r, -h, -r), Vec3(r, h, r)))
    case p: Placed => bounds(p.shape).map(b => Bounds.around(b.corners.map(p.transform.point)))
    case c: Csg    =>
      val inner = c.children.map(bounds)
      def all   = if inner.forall(_.isDefined) then Some(inner.flatten.reduce(_.union(_))) else None
      // Why: inverted (cutting, as a later child of a difference), an intersection or difference
      // is the merge of its children's complements, and a patch's complement is empty: its other
      // children's surfaces are then kept beyond the box they share, so it takes all of theirs.
      c.operation match
        case CsgOperation.Union                 => all
        case _ if c.children.exists(holdsPatch) => all
        case CsgOperation.Intersection          => inner.flatten.reduceOption(_.intersection(_))
        case CsgOperation.Difference            => inner.head

  /** The box around a disc of `radius` centred at `centre` at right angles to unit `axis`. */
  private def disc(centre: Vec3, radius: Double, axis: Vec3): Bounds =
    def reach(a: Double) = radius * Math.sqrt(Math.max(0.0, 1 - a * a))
    val r                = Vec3(reach(axis.x), reach(axis.y), reach(axis.z))
    Bounds(centre - r, centre + r)

  /** `ray` taken into `p`'s own space with a unit direction, and the factor by which its
    * distances are longer there than in the world (a distance t there is t / factor here).
    */
  private def ownSpace(p: Placed, ray: Ray): (Ray, Double) =
    val direction = p.transform.directionBack(ray.direction)
    val stretch   = direction.length
    (Ray(p.transform.pointBack(ray.origin), direction / stretch), stretch)

  /** The normal that shades the hit `hit` of `ray` on `shape`, facing the side the ray came from:
    * the geometric normal, except on a smooth triangle or a mesh's smooth face (also as a leaf of
    * a combination or placed shape, turned by the placements), where it is the corners' normals
    * interpolated with the hit's barycentric weights and normalised (POV-Ray's `smooth_triangle`).
    */
  def shadingNormal(shape: Shape, hit: Hit, ray: Ray): Vec3 = shape match
    case tr: Triangle =>
      tr.cornerNormals match
        case Some((n0, n1, n2)) =>
          val (u, v)  = triangleCoordinates(tr, hit.point - tr.t0)
          val blended = n0 * (1 - u - v) + n1 * u + n2 * v
          facing(blended.normalisedOr(hit.normal), ray)
        case None => hit.normal
    case m: Mesh =>
      // A mesh's hit names its face as its leaf.
      if m.smoothFace(hit.leaf) then shadingNormal(m.face(hit.leaf), hit, ray) else hit.normal
    case _: (Placed | Csg) =>
      // A smooth leaf of a combination or a placed shape: its own blend, carried into the world.
      smoothLeafNormal(shape, hit.leaf, hit.point).fold(hit.normal)(blended =>
        facing(blended.normalisedOr(hit.normal), ray)
      )
    case _: (Sphere | Plane | Box | Cone | Torus) => hit.normal

  /** True when some leaf of `shape` is a smooth triangle or a mesh with a smooth face. */
  def hasSmoothLeaf(shape: Shape): Boolean = shape match
    case tr: Triangle                             => tr.cornerNormals.isDefined
    case m: Mesh                                  => m.cornerNormals.exists(_ >= 0)
    case p: Placed                                => p.smooth
    case c: Csg                                   => c.smooth
    case _: (Sphere | Plane | Box | Cone | Torus) => false

  /** The corners' normals of leaf `leaf` of `shape` blended at `point` (equations 33–34) and
    * carried into the world by the placements above it, not normalised, when that leaf is a
    * smooth triangle or a mesh's smooth face; None for any other leaf (scene-format.md, "Which
    * normal": the child's own).
    */
  def smoothLeafNormal(shape: Shape, leaf: Int, point: Vec3): Option[Vec3] = shape match
    case tr: Triangle =>
      tr.cornerNormals.map { (n0, n1, n2) =>
        val (u, v) = triangleCoordinates(tr, point - tr.t0)
        n0 * (1 - u - v) + n1 * u + n2 * v
      }
    case m: Mesh =>
      if m.smoothFace(leaf) then smoothLeafNormal(m.face(leaf), 0, point) else None
    case p: Placed =>
      if !p.smooth then None
      else smoothLeafNormal(p.shape, leaf, p.transform.pointBack(point)).map(p.transform.normal)
    case c: Csg =>
      if !c.smooth then None
      else
        val i = c.firstLeaves.lastIndexWhere(_ <= leaf)
        smoothLeafNormal(c.children(i), leaf - c.firstLeaves(i), point)
    case _: (Sphere | Plane | Box | Cone | Torus) => None

  /** The texture coordinates of `point` on `shape` (rendering.md, Textures); `leaf` says which
    * primitive of a combination the point is on.
    *
    * Sphere: equations 35–38 with the outward normal. Triangle: the (u, v) of equations 33–34, or
    * for a mesh triangle its corners' coordinates interpolated at (u, v) and wrapped into [0, 1);
    * a mesh: those of its face number `leaf`.
    * A placed shape: those of the point taken back into its own space. Shapes that take no
    * texture (planes and the version 3 solids): (0, 0).
    */
  def surfaceCoordinates(shape: Shape, point: Vec3, leaf: Int = 0): SurfaceCoordinates =
    shape match
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
      case m: Mesh   => surfaceCoordinates(m.face(leaf), point)
      case p: Placed => surfaceCoordinates(p.shape, p.transform.pointBack(point), leaf)
      case c: Csg    =>
        val i = c.firstLeaves.lastIndexWhere(_ <= leaf)
        surfaceCoordinates(c.children(i), point, leaf - c.firstLeaves(i))
      case _: (Plane | Box | Cone | Torus) => SurfaceCoordinates(0, 0)

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

  /** Equations 35–38 with rn the outward unit normal; arccos arguments clamped against rounding.
    * `StrictMath`'s arccos and sine, so a texture is looked up at the same texel on every machine
    * (`Math.sin` may be a processor's own).
    */
  private def sphereCoordinates(s: Sphere, point: Vec3): SurfaceCoordinates =
    val rn  = (point - s.centre) * (1 / s.radius)
    val phi = StrictMath.acos(clamp(-rn.dot(s.unitPole)))
    val v   = phi / Math.PI
    if v == 0 || v == 1 then SurfaceCoordinates(0, v)
    else
      val theta =
        StrictMath.acos(clamp(s.unitEquator.dot(rn) / StrictMath.sin(phi))) / (2 * Math.PI)
      SurfaceCoordinates(if s.seamSide.dot(rn) > 0 then theta else 1 - theta, v)

  private def startsInside(s: Sphere, ray: Ray): Boolean =
    val oc = s.centre - ray.origin
    oc.dot(oc) < s.radiusSquared

  /** The hit whose outward normal is `outward`: equation 29's normal facing the ray, and whether
    * the ray arrived on the outward side.
    */
  private inline def facingHit(t: Double, point: Vec3, outward: Vec3, leaf: Int, ray: Ray): Hit =
    val front = outward.dot(ray.direction) < 0
    Hit(t, point, if front then outward else -outward, leaf, front)

  /** Equation 29: Pn when vd < 0, else −Pn. */
  private inline def facing(normal: Vec3, ray: Ray): Vec3 =
    if normal.dot(ray.direction) < 0 then normal else -normal

  private inline def positive(t: Double): Double = if t > 0 then t else Double.PositiveInfinity

  /** The distance of a miss. */
  private inline val Miss = Double.PositiveInfinity

  private inline def clamp(x: Double): Double = Math.max(-1.0, Math.min(1.0, x))
