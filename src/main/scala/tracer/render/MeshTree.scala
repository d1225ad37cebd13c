package tracer.render

import scala.concurrent.ExecutionContext
import tracer.geometry.Mesh

/** A mesh's own ray kernel: a 4-wide bounding volume hierarchy over its faces (built by
  * [[BvhBuilder.faces]], on the render's pool when one is given), with each face's plane and
  * corners' places in leaf order. The scene's [[Bvh]] holds the mesh as one primitive and asks
  * this tree when a ray reaches its box (a two-level hierarchy, as pbrt's instances).
  *
  * Perf: a face takes 4 doubles (its plane) and 3 ints (its corners' offsets into the mesh's
  * shared vertex array) here, against 16 doubles and a `Triangle` of six `Vec3`s when every face
  * was a shape of its own; the rest of the face's constants are derived from its corners by
  * [[tracer.geometry.Mesh.faceDistance]], the same operations as the `Triangle`'s, so the
  * distances are the same bit for bit (`MeshProperties`; docs/performance.md, round 6;
  * `MeshBench`).
  *
  * @param mesh the mesh
  * @param pool where to build the tree: the render's threads, or this one for `None`
  * @param lanes whether a tree of so many wide nodes walks with the Vector API's four-box test
  *   ([[MeshLanes]]) instead of one box at a time: the same answers (`MeshProperties`); by
  *   default [[LaneSupport.choose]]
  * @param rays  about how many rays the render will trace: a mesh of many more faces gets a
  *   coarser tree ([[BvhBuilder.wholeLeaf]]); by default as many as it takes for the finest
  */
final class MeshTree(
    mesh: Mesh,
    pool: Option[ExecutionContext] = None,
    lanes: Int => Boolean = LaneSupport.choose,
    rays: Long = Long.MaxValue
):
  // The binary tree is dropped once collapsed: the queries walk the wide one.
  private val (wide, faces) = MeshTree.wideTree(mesh, pool, rays)
  private val wb            = wide.boxes
  private val wc            = wide.child
  private val wn            = wide.count
  private val vertices      = mesh.vertices
  // Leaf order: face k of the leaves is face `faces(k)` of the mesh, its plane at 4k, the
  // offsets of its corners in `vertices` at 3k.
  private val (planes, at, leafOf) = MeshTree.leafOrder(mesh, faces, pool)
  // The walks with four boxes at a time, when asked for (a class of their own, loaded only then:
  // no function names it, as in Bvh).
  private val fast: Option[MeshLanes] =
    if lanes(wide.size) then Some(MeshLanes(wide, faces, planes, at, vertices)) else None

  /** The number of nodes of the tree, for tests and benchmarks. */
  def nodeCount: Int = wide.size

  /** The number of faces. */
  def faceCount: Int = faces.length

  /** Writes the box of leaf-order face `k` (low x, y, z, then high) into `out` from `to`. */
  private[render] def faceBox(k: Int, out: Array[Double], to: Int): Unit =
    var axis = 0
    while axis < 3 do
      val a = vertices(at(3 * k) + axis)
      val b = vertices(at(3 * k + 1) + axis)
      val c = vertices(at(3 * k + 2) + axis)
      out(to + axis) = Math.min(a, Math.min(b, c))
      out(to + 3 + axis) = Math.max(a, Math.max(b, c))
      axis += 1

  /** Writes leaf-order face `k`'s corners (x, y, z of each, in the face's order) into `out` from
    * `to`.
    */
  private[render] def faceCorners(k: Int, out: Array[Double], to: Int): Unit =
    var j = 0
    while j < 9 do
      out(to + j) = vertices(at(3 * k + j / 3) + j % 3)
      j += 1

  /** True when leaf-order face `k` is met by the ray at a t below `limit`: the test of the face
    * that [[occludedBelow]] makes, on its own (for a [[LightBuffer]]'s cell).
    */
  private[render] def faceBlocks(
      k: Int,
      limit: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Boolean = faceDistance(k, limit, ox, oy, oz, dx, dy, dz) < limit

  /** The distance to leaf-order face `k` as [[nearest]] tests it, +∞ on a miss (or on a hit
    * beyond `cutoff`, which it need not finish).
    */
  private[render] def faceDistance(
      k: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double = MeshWalk.face(planes, at, vertices, k, cutoff, ox, oy, oz, dx, dy, dz)

  /** The mesh's number of leaf-order face `k`: the face [[nearest]] names. */
  private[render] def faceNumber(k: Int): Int = faces(k)

  /** The leaf-order number of the mesh's face `f` (the inverse of [[faceNumber]]). */
  private[render] def leafFace(f: Int): Int = leafOf(f)

  /** The unit normal of the mesh's face `f` (its plane's Pn, with `Mesh.plane`'s bits), read from
    * the tree's planes and passed to `body`.
    *
    * Perf: `inline` with an inline body, as `Mesh.plane`: three loads where the corners' cross
    * product, its square root and three divisions were (docs/performance.md, round 50).
    */
  private[render] inline def faceNormal[A](f: Int)(inline body: (Double, Double, Double) => A): A =
    val k = 4 * leafOf(f)
    body(planes(k), planes(k + 1), planes(k + 2))

  /** The distance along the ray from (ox, oy, oz) in unit direction (dx, dy, dz) to the mesh's
    * nearest face at a t ≤ `limit` (+∞ when there is none), the face itself left in
    * `query.meshFace`: the lowest-numbered of the faces at that distance, as a loop over the faces
    * in order would find it.
    */
  def nearest(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Double =
    fast match
      case Some(lanes) => lanes.nearest(ox, oy, oz, dx, dy, dz, limit, query)
      case None        =>
        MeshWalk.nearest(
          wide.size,
          wc,
          wn,
          faces,
          planes,
          at,
          vertices,
          ox,
          oy,
          oz,
          dx,
          dy,
          dz,
          limit,
          query
        ) { (node, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
          WideWalk.push(
            wb,
            wn,
            node,
            sp,
            stack,
            entries,
            ox,
            oy,
            oz,
            ix,
            iy,
            iz,
            sx,
            sy,
            sz,
            bound,
            true
          )
        }

  /** True when some face is met by the ray at a t below `limit` (a shadow test); stops at the
    * first, and leaves the node whose children hold it in `query.blockerNode`.
    */
  def occluded(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean = occludedBelow(0, ox, oy, oz, dx, dy, dz, limit, query)

  /** [[occluded]] among the faces below node `node` of the tree (0: the root, all of them). */
  def occludedBelow(
      node: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    fast match
      case Some(lanes) => lanes.occludedBelow(node, ox, oy, oz, dx, dy, dz, limit, query)
      case None        =>
        MeshWalk.occludedBelow(
          wide.size,
          wc,
          wn,
          planes,
          at,
          vertices,
          node,
          ox,
          oy,
          oz,
          dx,
          dy,
          dz,
          limit,
          query
        ) { (n, sp, stack, entries, ix, iy, iz, sx, sy, sz, bound) =>
          WideWalk.push(
            wb,
            wn,
            n,
            sp,
            stack,
            entries,
            ox,
            oy,
            oz,
            ix,
            iy,
            iz,
            sx,
            sy,
            sz,
            bound,
            false
          )
        }

/** The two walks down a mesh's [[WideTree]], written once for both ways of testing a node's child
  * boxes: `push` pushes the children of a node that the ray enters ([[WideWalk.push]] or
  * [[Lanes.push]]), given the node, the stack's size, slots and entries, the ray's inverse
  * direction and signs and the limit, and returns the stack's new size.
  */
private[render] object MeshWalk:
  /** [[MeshTree.nearest]] on the tree of `size` nodes (children `wc`, counts `wn`) over the faces
    * `faces` in leaf order, with their planes and corner offsets `at` into `vertices`.
    */
  inline def nearest(
      size: Int,
      wc: Array[Int],
      wn: Array[Int],
      faces: Array[Int],
      planes: Array[Double],
      at: Array[Int],
      vertices: IArray[Double],
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  )(
      inline push: (
          Int,
          Int,
          Array[Int],
          Array[Double],
          Double,
          Double,
          Double,
          Int,
          Int,
          Int,
          Double
      ) => Int
  ): Double =
    // Perf: Bvh.nearest's ordered walk of a 4-wide tree on the query's second stack (the scene's
    // walk is still under way on the first), face tests on the leaf-order arrays.
    val stack   = query.meshNodes
    val entries = query.meshEntries
    var best    = Int.MaxValue
    var bestT   = limit
    WideWalk.walk(dx, dy, dz) { (ix, iy, iz, sx, sy, sz) =>
      var sp = WideWalk.seed(size, stack, entries)
      while sp > 0 do
        sp -= 1
        val slot = stack(sp)
        if entries(sp) <= bestT then
          val count = WideWalk.count(wn, slot)
          if count > 0 then
            var k   = wc(slot)
            val end = k + count
            while k < end do
              val t = face(planes, at, vertices, k, bestT, ox, oy, oz, dx, dy, dz)
              if t <= bestT && t < Double.PositiveInfinity then
                val f = faces(k)
                if t < bestT || f < best then
                  bestT = t
                  best = f
              k += 1
          else sp = push(WideWalk.node(wc, slot), sp, stack, entries, ix, iy, iz, sx, sy, sz, bestT)
    }
    query.meshFace = best
    if best == Int.MaxValue then Double.PositiveInfinity else bestT

  /** [[MeshTree.occludedBelow]] on the tree, as [[nearest]]. */
  inline def occludedBelow(
      size: Int,
      wc: Array[Int],
      wn: Array[Int],
      planes: Array[Double],
      at: Array[Int],
      vertices: IArray[Double],
      node: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  )(
      inline push: (
          Int,
          Int,
          Array[Int],
          Array[Double],
          Double,
          Double,
          Double,
          Int,
          Int,
          Int,
          Double
      ) => Int
  ): Boolean =
    // Perf: Bvh.occluded's any-hit walk, unordered, with an early exit.
    val stack   = query.meshNodes
    val entries = query.meshEntries
    WideWalk.walk(dx, dy, dz) { (ix, iy, iz, sx, sy, sz) =>
      var hit = false
      var sp  = WideWalk.seed(size, stack, entries, node)
      while sp > 0 && !hit do
        sp -= 1
        val slot  = stack(sp)
        val count = WideWalk.count(wn, slot)
        if count > 0 then
          var k   = wc(slot)
          val end = k + count
          while k < end && !hit do
            hit = face(planes, at, vertices, k, limit, ox, oy, oz, dx, dy, dz) < limit
            k += 1
          if hit then query.blockerNode = slot / WideTree.Width
        else sp = push(WideWalk.node(wc, slot), sp, stack, entries, ix, iy, iz, sx, sy, sz, limit)
      hit
    }

  /** The distance to leaf-order face k ([[tracer.geometry.Mesh.faceDistance]]). */
  inline def face(
      planes: Array[Double],
      at: Array[Int],
      vertices: IArray[Double],
      k: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    Mesh.faceDistance(
      planes(4 * k),
      planes(4 * k + 1),
      planes(4 * k + 2),
      planes(4 * k + 3),
      vertices,
      at(3 * k),
      at(3 * k + 1),
      at(3 * k + 2),
      cutoff,
      ox,
      oy,
      oz,
      dx,
      dy,
      dz
    )

/** Building a mesh's tree and laying its faces out for it. */
private object MeshTree:
  /** The wide tree over `mesh`'s faces and their numbers in leaf order.
    *
    * Perf: in a method of its own, so that the builder's arrays and the binary tree are garbage
    * once it returns (the constructor runs interpreted, and a dead local of its frame would keep
    * them reachable while the leaf-order arrays are made: 238 MB for the 1.3M-face mesh).
    */
  def wideTree(mesh: Mesh, pool: Option[ExecutionContext], rays: Long): (WideTree, Array[Int]) =
    val tree = BvhBuilder.faces(mesh, pool, rays).build(pool)
    (WideTree.collapse(tree, pool), tree.order)

  /** The planes (4 doubles a face, as [[tracer.geometry.Mesh.planes]] holds them) and corner
    * offsets (3 ints) of `mesh`'s faces `order`, and each face's place in that order, on `pool`
    * when one is given (in parts: [[BvhBuilder.inParts]]).
    */
  def leafOrder(
      mesh: Mesh,
      order: Array[Int],
      pool: Option[ExecutionContext]
  ): (Array[Double], Array[Int], Array[Int]) =
    val planes = new Array[Double](4 * order.length)
    val at     = new Array[Int](3 * order.length)
    val places = new Array[Int](order.length)
    BvhBuilder.inParts(order.length, pool)((from, to) =>
      lay(mesh, order, planes, at, places, from, to)
    )
    (planes, at, places)

  /** Writes the planes, corner offsets and places of leaf-order faces from until to. */
  private def lay(
      mesh: Mesh,
      order: Array[Int],
      planes: Array[Double],
      at: Array[Int],
      places: Array[Int],
      from: Int,
      to: Int
  ): Unit =
    // Perf: one call a face, so the face's work is compiled after a few hundred faces rather than
    // interpreted until the loop is compiled on stack (round 22's pattern; mesh-80000 at
    // 1280×720 had 51 interpreted samples here; docs/performance.md, round 27).
    val vertices = mesh.vertices
    val corners  = mesh.corners
    var k        = from
    while k < to do
      layFace(vertices, corners, order, planes, at, places, k)
      k += 1

  /** Writes leaf-order face `k`'s plane, computed from its corners (Mesh.plane: the mesh keeps no
    * copy of its own, docs/performance.md, round 7), its corner offsets, and its place k.
    */
  private def layFace(
      vertices: IArray[Double],
      corners: IArray[Int],
      order: Array[Int],
      planes: Array[Double],
      at: Array[Int],
      places: Array[Int],
      k: Int
  ): Unit =
    val f = order(k)
    places(f) = k
    Mesh.plane(vertices, corners, f) { (nx, ny, nz, d) =>
      planes(4 * k) = nx; planes(4 * k + 1) = ny; planes(4 * k + 2) = nz; planes(4 * k + 3) = d
    }
    at(3 * k) = 3 * corners(3 * f); at(3 * k + 1) = 3 * corners(3 * f + 1)
    at(3 * k + 2) = 3 * corners(3 * f + 2)
