package tracer.render

import tracer.geometry.{
  Box,
  Cone,
  Csg,
  FirstCrossing,
  Mesh,
  Placed,
  Plane,
  Shape,
  Sphere,
  Torus,
  Triangle
}

/** The hit of a ray on a shape as plain doubles in a [[Query]]: what [[Shape.hitAt]] and
  * [[Shape.shadingNormal]] give, bit for bit (the same operations in the same order on the same
  * values; `HitsProperties`), without a `Ray`, a `Hit` or a `Vec3`. `Shape.hitAt` stays the model
  * a reader sees and the tests' oracle; this is the shading's fast path.
  */
private[render] object Hits:

  /** Writes into `query` (its `px` … `front`) the hit at distance `t` along the ray from
    * (ox, oy, oz) in unit direction (dx, dy, dz) on `shape`: as `Shape.hitAt(shape, ray, t)`
    * with `Shape.shadingNormal` of it (for a mesh, `Shape.hitOnFace` on the face the last
    * nearest query found, `query.face`, its normal from the mesh's `tree` when it has one). A `t`
    * at which a general shape has no crossing is a caller's bug: `IllegalArgumentException`, as
    * from `Shape.hitAt`.
    */
  def record(
      shape: Shape,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      t: Double,
      query: Query,
      tree: Option[MeshTree] = None
  ): Unit =
    // Perf: PrimaryRayBench (bytes per primary ray): the hit's values straight into the query.
    shape match
      case s: Sphere =>
        // Equation 23: the outward normal, flipped for a ray that starts inside.
        val px  = ox + dx * t
        val py  = oy + dy * t
        val pz  = oz + dz * t
        val inv = 1 / s.radius
        val ux  = (px - s.centre.x) * inv
        val uy  = (py - s.centre.y) * inv
        val uz  = (pz - s.centre.z) * inv
        val cx  = s.centre.x - ox
        val cy  = s.centre.y - oy
        val cz  = s.centre.z - oz
        val in  = cx * cx + cy * cy + cz * cz < s.radiusSquared
        query.px = px; query.py = py; query.pz = pz
        if in then
          query.nx = -ux; query.ny = -uy; query.nz = -uz
        else
          query.nx = ux; query.ny = uy; query.nz = uz
        query.leaf = 0
        query.front = !in
        flat(query)
      case p: Plane =>
        facing(ox + dx * t, oy + dy * t, oz + dz * t, p.normal.x, p.normal.y, p.normal.z, 0)(
          dx,
          dy,
          dz,
          query
        )
        flat(query)
      case tr: Triangle =>
        facing(ox + dx * t, oy + dy * t, oz + dz * t, tr.normal.x, tr.normal.y, tr.normal.z, 0)(
          dx,
          dy,
          dz,
          query
        )
        tr.cornerNormals match
          case Some((n0, n1, n2)) => smooth(tr, n0, n1, n2, dx, dy, dz, query)
          case None               => flat(query)
      case m: Mesh =>
        // Shape.hitOnFace: the face the kernel found (query.face) is the leaf; its plane's Pn is
        // the outward normal. A smooth face blends its corners' normals as its Triangle does.
        // Perf: the face's normal from the mesh's tree, which holds the planes; derived from
        // its corners (Mesh.plane) for a mesh without one, which holds no array of planes.
        val f = query.face
        tree match
          case Some(faces) =>
            faces.faceNormal(f) { (nx, ny, nz) =>
              facing(ox + dx * t, oy + dy * t, oz + dz * t, nx, ny, nz, f)(dx, dy, dz, query)
            }
          case None =>
            Mesh.plane(m.vertices, m.corners, f) { (nx, ny, nz, _) =>
              facing(ox + dx * t, oy + dy * t, oz + dz * t, nx, ny, nz, f)(dx, dy, dz, query)
            }
        if m.smoothFace(f) then
          val tr = m.face(f)
          tr.cornerNormals match
            case Some((n0, n1, n2)) => smooth(tr, n0, n1, n2, dx, dy, dz, query)
            case None               => flat(query)
        else flat(query)
      case other: (Box | Cone | Torus | Placed | Csg) =>
        // The general route: the nearest crossing again, for its normal and leaf, into the
        // query's own crossing buffer (Shape.hitAt uses the thread's).
        val buffer = query.crossings
        if FirstCrossing.find(other, ox, oy, oz, dx, dy, dz, buffer) then
          val first = FirstCrossing.t(buffer)
          facing(
            ox + dx * first,
            oy + dy * first,
            oz + dz * first,
            FirstCrossing.nx(buffer),
            FirstCrossing.ny(buffer),
            FirstCrossing.nz(buffer),
            FirstCrossing.leaf(buffer)
          )(dx, dy, dz, query)
          if Shape.hasSmoothLeaf(other) then smoothLeaf(other, dx, dy, dz, query)
          else flat(query)
        else
          // Why: as in Shape.hitAt, a t from the distance always has a crossing; none is a bug.
          throw IllegalArgumentException(s"Hits.record: no crossing of $other (t = $t)")

  /** Shape.shadingNormal on a combination or placed shape that holds a smooth leaf: that leaf's
    * blend ([[Shape.smoothLeafNormal]]) normalised (else the geometric normal), facing the ray;
    * the geometric normal on a flat leaf.
    */
  private def smoothLeaf(shape: Shape, dx: Double, dy: Double, dz: Double, query: Query): Unit =
    Shape.smoothLeafNormal(shape, query.leaf, tracer.math.Vec3(query.px, query.py, query.pz)) match
      case Some(blended) =>
        val n = blended.normalisedOr(tracer.math.Vec3(query.nx, query.ny, query.nz))
        orient(n.x, n.y, n.z, dx, dy, dz, query)
      case None => flat(query)

  /** Shape.facingHit: the point, and the outward normal (ux, uy, uz) facing the ray. */
  private inline def facing(
      px: Double,
      py: Double,
      pz: Double,
      ux: Double,
      uy: Double,
      uz: Double,
      leaf: Int
  )(dx: Double, dy: Double, dz: Double, query: Query): Unit =
    val front = ux * dx + uy * dy + uz * dz < 0
    query.px = px; query.py = py; query.pz = pz
    if front then
      query.nx = ux; query.ny = uy; query.nz = uz
    else
      query.nx = -ux; query.ny = -uy; query.nz = -uz
    query.leaf = leaf
    query.front = front

  /** The shading normal of a flat hit: the geometric one. */
  private inline def flat(query: Query): Unit =
    query.sx = query.nx; query.sy = query.ny; query.sz = query.nz

  /** Shape.shadingNormal on a smooth triangle: the corners' normals blended by the barycentric
    * weights of the hit point (equations 33–34), normalised (else the face's normal), facing the
    * ray.
    */
  private def smooth(
      tr: Triangle,
      n0: tracer.math.Vec3,
      n1: tracer.math.Vec3,
      n2: tracer.math.Vec3,
      dx: Double,
      dy: Double,
      dz: Double,
      query: Query
  ): Unit =
    val qx  = query.px - tr.t0.x
    val qy  = query.py - tr.t0.y
    val qz  = query.pz - tr.t0.z
    val qa  = qx * tr.a.x + qy * tr.a.y + qz * tr.a.z
    val qb  = qx * tr.b.x + qy * tr.b.y + qz * tr.b.z
    val u   = (tr.bb * qa - tr.ab * qb) / tr.denominator
    val v   = (qb - u * tr.ab) / tr.bb
    val w   = 1 - u - v
    val bx  = n0.x * w + n1.x * u + n2.x * v
    val by  = n0.y * w + n1.y * u + n2.y * v
    val bz  = n0.z * w + n1.z * u + n2.z * v
    val len = Math.sqrt(bx * bx + by * by + bz * bz)
    if len > 0 && len < Double.PositiveInfinity then
      orient(bx / len, by / len, bz / len, dx, dy, dz, query)
    else orient(query.nx, query.ny, query.nz, dx, dy, dz, query)

  /** Shape.facing: (x, y, z) when it faces the ray (its dot with d below 0), else its opposite. */
  private inline def orient(
      x: Double,
      y: Double,
      z: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      query: Query
  ): Unit =
    if x * dx + y * dy + z * dz < 0 then
      query.sx = x; query.sy = y; query.sz = z
    else
      query.sx = -x; query.sy = -y; query.sz = -z
