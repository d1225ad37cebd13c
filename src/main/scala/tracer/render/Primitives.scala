package tracer.render

import scala.concurrent.ExecutionContext
import tracer.geometry.{
  Box,
  Cone,
  CrossingBuffer,
  Csg,
  Kernel,
  Mesh,
  Placed,
  Plane,
  Shape,
  Sphere,
  Torus,
  Triangle
}

/** Which way a shape is traced: the ray kernel's fast paths or the general one. */
enum Route:
  /** A sphere, tested from its centre and Sr² in the kernel's flat arrays. */
  case FastSphere

  /** A triangle, tested from its precomputed constants in the kernel's flat arrays. */
  case FastTriangle

  /** A plane (unbounded: tested on every ray), from its normal and D in flat arrays. */
  case FastPlane

  /** A mesh, tested by its own tree of faces ([[MeshTree]]). */
  case FastMesh

  /** Any other shape, tested with [[tracer.geometry.Shape.distance]]; it joins the hierarchy when
    * [[tracer.geometry.Shape.bounds]] gives it bounds and is tested on every ray otherwise.
    */
  case General

/** The route of each shape. */
object Route:
  /** The route `shape` takes: the one place that decides between the kernel and the general path. */
  def of(shape: Shape): Route = shape match
    case _: Sphere                              => FastSphere
    case _: Triangle                            => FastTriangle
    case _: Plane                               => FastPlane
    case _: Mesh                                => FastMesh
    case _: (Box | Cone | Torus | Placed | Csg) => General

/** Shapes as flat primitive arrays (the bounded ones in the hierarchy's leaf order, the unbounded
  * ones in a list of their own): the data
  * of primitive k at `Primitives.Stride * k` (see [[Primitives.store]]), its route, and its index
  * among the scene's shapes. Immutable after construction.
  *
  * @param shapes all the scene's shapes
  * @param order  the indices in `shapes` of the primitives, in leaf order
  * @param pool   where to build the meshes' trees (see [[MeshTree]])
  * @param known  a mesh's tree when one was built already (by another [[Primitives]] of the same
  *   world), so it is not built twice
  * @param rays   about how many rays the render will trace, for the meshes' trees (see
  *   [[MeshTree]])
  */
final class Primitives(
    shapes: IndexedSeq[Shape],
    order: Array[Int],
    pool: Option[ExecutionContext] = None,
    known: Mesh => Option[MeshTree] = _ => None,
    rays: Long = Long.MaxValue
):
  // Perf: everything a leaf test reads, contiguous per primitive: no Shape object is reached on
  // the fast paths (docs/performance.md, round 4).
  private[render] val data  = new Array[Double](Primitives.Stride * order.length)
  private[render] val kind  = new Array[Byte](order.length)
  private[render] val index = order
  private[render] val all   = shapes

  // The meshes whose trees these are, in the same order.
  private val owners = Array.newBuilder[Mesh]

  /** The meshes' trees; a mesh primitive's first double is the number of its tree here. */
  private[render] val meshes: Array[MeshTree] =
    val trees = Array.newBuilder[MeshTree]
    val all   = shapes.toArray
    // Perf: a plain loop filling the arrays, once per world, its body one call (compiled after a
    // few hundred turns: a shorter loop than the JIT's on-stack threshold runs interpreted
    // throughout; BvhBuilder.apply, docs/performance.md, round 22).
    var k = 0
    var m = 0
    while k < order.length do
      m = lay(all(order(k)), k, m, trees)
      k += 1
    trees.result()

  /** Writes primitive `k`, `shape`, into the arrays; a mesh gets its tree as number `m` in
    * `trees`. Returns the number of the next mesh's tree.
    */
  private def lay(
      shape: Shape,
      k: Int,
      m: Int,
      trees: scala.collection.mutable.ArrayBuilder[MeshTree]
  ): Int =
    kind(k) = Primitives.store(shape, data, Primitives.Stride * k).ordinal.toByte
    shape match
      case mesh: Mesh =>
        trees += known(mesh).getOrElse(MeshTree(mesh, pool, rays = rays))
        owners += mesh
        data(Primitives.Stride * k) = m
        m + 1
      case _ => m

  private val meshOwners = owners.result()

  /** The tree built here for `mesh` (the very object), if it is one of these primitives. */
  private[render] def treeOf(mesh: Mesh): Option[MeshTree] =
    val i = meshOwners.indexWhere(_ eq mesh)
    if i < 0 then None else Some(meshes(i))

  /** The number of primitives. */
  def size: Int = order.length

  /** The tree built here for each of the scene's `count` shapes that is one of these primitives'
    * meshes, by the shape's index; None for every other shape.
    */
  private[render] def treesByShape(count: Int): Array[Option[MeshTree]] =
    val trees = Array.fill[Option[MeshTree]](count)(None)
    kind.indices.foreach { k =>
      if kind(k) == Primitives.MeshKind then
        trees(index(k)) = Some(meshes(data(Primitives.Stride * k).toInt))
    }
    trees

/** The layout of [[Primitives]] and its leaf tests. */
object Primitives:
  /** Doubles per primitive. */
  val Stride: Int = 16

  private[render] val SphereKind: Byte   = Route.FastSphere.ordinal.toByte
  private[render] val TriangleKind: Byte = Route.FastTriangle.ordinal.toByte
  private[render] val PlaneKind: Byte    = Route.FastPlane.ordinal.toByte
  private[render] val MeshKind: Byte     = Route.FastMesh.ordinal.toByte
  private[render] val GeneralKind: Byte  = Route.General.ordinal.toByte

  /** Writes what the leaf test of `shape` reads into `data` from `at`, and returns its route.
    *
    * A sphere: Sc, Sr². A plane: Pn, D. A triangle: Pn, D, T0, a, b, b · b, a · b and the denominator, copied from
    * the [[tracer.geometry.Triangle]] so the kernel computes with exactly its values. A mesh and a
    * shape of the general route store nothing here (their case is `()`): a mesh's test reads its
    * tree (the [[Primitives]] that hold it number it), the general one the shape itself.
    */
  def store(shape: Shape, data: Array[Double], at: Int): Route =
    val route = Route.of(shape)
    shape match
      case s: Sphere =>
        data(at) = s.centre.x; data(at + 1) = s.centre.y; data(at + 2) = s.centre.z
        data(at + 3) = s.radiusSquared
      case t: Triangle =>
        data(at) = t.normal.x; data(at + 1) = t.normal.y; data(at + 2) = t.normal.z
        data(at + 3) = t.distance
        data(at + 4) = t.t0.x; data(at + 5) = t.t0.y; data(at + 6) = t.t0.z
        data(at + 7) = t.a.x; data(at + 8) = t.a.y; data(at + 9) = t.a.z
        data(at + 10) = t.b.x; data(at + 11) = t.b.y; data(at + 12) = t.b.z
        data(at + 13) = t.bb; data(at + 14) = t.ab; data(at + 15) = t.denominator
      case p: Plane =>
        data(at) = p.normal.x; data(at + 1) = p.normal.y; data(at + 2) = p.normal.z
        data(at + 3) = p.distance
      case _: (Mesh | Box | Cone | Torus | Placed | Csg) => ()
    route

  /** The distance along the ray (origin o, unit direction d) to primitive `k`, or +∞ on a miss:
    * bit for bit what [[tracer.geometry.Shape.distance]] gives for its shape, the same operations
    * in the same order on the same values. A triangle, a mesh's faces or a general shape farther
    * than `cutoff` may be reported as a miss without finishing its test; a mesh counts hits at t ≤
    * `cutoff` only, and leaves the face hit in `query.meshFace` ([[MeshTree.nearest]]). The
    * general route takes its scratch from `query`.
    */
  inline def distance(
      p: Primitives,
      k: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      query: Query
  ): Double =
    val kd = p.kind(k)
    if kd == TriangleKind then triangle(p.data, Stride * k, cutoff, ox, oy, oz, dx, dy, dz)
    else if kd == SphereKind then sphere(p.data, Stride * k, ox, oy, oz, dx, dy, dz)
    else if kd == PlaneKind then plane(p.data, Stride * k, ox, oy, oz, dx, dy, dz)
    else if kd == MeshKind then
      p.meshes(p.data(Stride * k).toInt).nearest(ox, oy, oz, dx, dy, dz, cutoff, query)
    else general(p.all(p.index(k)), cutoff, ox, oy, oz, dx, dy, dz, query.crossings)

  /** True when primitive `k` is met by the ray at a t below `limit`: [[distance]] `< limit`,
    * with a mesh's any-hit test ([[MeshTree.occluded]]) in place of its nearest face.
    */
  inline def blocks(
      p: Primitives,
      k: Int,
      limit: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      query: Query
  ): Boolean =
    val kd = p.kind(k)
    if kd == MeshKind then
      p.meshes(p.data(Stride * k).toInt).occluded(ox, oy, oz, dx, dy, dz, limit, query)
    else if kd == GeneralKind then
      generalBlocks(p.all(p.index(k)), limit, ox, oy, oz, dx, dy, dz, query.crossings)
    else distance(p, k, limit, ox, oy, oz, dx, dy, dz, query) < limit

  /** The general route's shadow test: [[tracer.geometry.Kernel.blocks]] (the same answer as
    * [[general]] `< limit`, a combination stopping at its first crossing below the limit).
    */
  private def generalBlocks(
      shape: Shape,
      limit: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer
  ): Boolean = Kernel.blocks(shape, ox, oy, oz, dx, dy, dz, buffer, limit)

  /** The general route: [[tracer.geometry.Shape.distance]], bit for bit, from the solids' kernel
    * on plain doubles ([[tracer.geometry.Kernel]]): no `Ray`, list or tuple per test; a shape
    * farther than `cutoff` may be reported as a miss.
    */
  private def general(
      shape: Shape,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      buffer: CrossingBuffer
  ): Double = Kernel.distance(shape, ox, oy, oz, dx, dy, dz, buffer, cutoff)

  /** Shape.planeDistance on flat data: equations 24–27. */
  private inline def plane(
      data: Array[Double],
      at: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    Kernel.planeT(data(at), data(at + 1), data(at + 2), data(at + 3), ox, oy, oz, dx, dy, dz)

  /** Shape.sphereDistance on flat data: equations 17–21. */
  private inline def sphere(
      data: Array[Double],
      at: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    val ocx  = data(at) - ox
    val ocy  = data(at + 1) - oy
    val ocz  = data(at + 2) - oz
    val r2   = data(at + 3)
    val l2oc = ocx * ocx + ocy * ocy + ocz * ocz
    val tca  = ocx * dx + ocy * dy + ocz * dz
    val t2hc = r2 - l2oc + tca * tca
    if l2oc < r2 then tca + Math.sqrt(t2hc)
    else if tca < 0 || t2hc < 0 then Double.PositiveInfinity
    else
      val t = tca - Math.sqrt(t2hc)
      if t > 0 then t else Double.PositiveInfinity

  /** Shape.triangleDistance on flat data: the plane test, then equations 32–34. */
  private inline def triangle(
      data: Array[Double],
      at: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    // The triangle's plane is stored as a plane's is (Pn, D first), so its test is the plane's.
    val t = plane(data, at, ox, oy, oz, dx, dy, dz)
    // Perf: a hit beyond the cutoff cannot count, so its barycentric test is skipped; the test of
    // a hit that counts is unchanged (u's sign is final before v is computed).
    if t == Double.PositiveInfinity || t > cutoff then Double.PositiveInfinity
    else
      val qx = ox + dx * t - data(at + 4)
      val qy = oy + dy * t - data(at + 5)
      val qz = oz + dz * t - data(at + 6)
      val qa = qx * data(at + 7) + qy * data(at + 8) + qz * data(at + 9)
      val qb = qx * data(at + 10) + qy * data(at + 11) + qz * data(at + 12)
      val bb = data(at + 13)
      val ab = data(at + 14)
      val u  = (bb * qa - ab * qb) / data(at + 15)
      if !(u >= 0) then Double.PositiveInfinity
      else
        val v = (qb - u * ab) / bb
        if v >= 0 && u + v <= 1 then t else Double.PositiveInfinity
