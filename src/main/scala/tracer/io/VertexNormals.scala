package tracer.io

import tracer.math.Vec3

/** Normals for the corners of a mesh whose file gives none (scene format v3, `smooth="auto"`):
  * at each vertex, the sum over the faces that use it of the face's unit normal times the face's
  * angle at that vertex, normalised. Faces whose corners are collinear count for nothing.
  */
private[io] object VertexNormals:

  /** The normal of every vertex of `mesh` in the file's coordinates, by vertex number, or `None`
    * where the sum is zero (an unused vertex, say): the faces' angle-weighted normals
    * added up in face order on arrays, one sum per vertex.
    */
  def of(mesh: ObjMesh): IArray[Option[Vec3]] =
    val n    = mesh.vertices.length / 3
    val sums = new Array[Double](3 * n)
    // Perf: a counted loop over the faces adding into the sums' array (a Map of sums took a
    // tuple, a list and a map node per corner; docs/performance.md, round 6).
    var f = 0
    while f < mesh.faceCount do
      val (i, j, k) = (mesh.corners(3 * f), mesh.corners(3 * f + 1), mesh.corners(3 * f + 2))
      val (a, b, c) = (mesh.vertex(i), mesh.vertex(j), mesh.vertex(k))
      (b - a).cross(c - a).normalised.foreach { unit =>
        add(sums, i, unit * angle(b - a, c - a))
        add(sums, j, unit * angle(c - b, a - b))
        add(sums, k, unit * angle(a - c, b - c))
      }
      f += 1
    IArray.tabulate(n)(v => Vec3(sums(3 * v), sums(3 * v + 1), sums(3 * v + 2)).normalised)

  /** Adds `w` to the sum of vertex `v`, as `Vec3`'s + would. */
  private def add(sums: Array[Double], v: Int, w: Vec3): Unit =
    sums(3 * v) = sums(3 * v) + w.x
    sums(3 * v + 1) = sums(3 * v + 1) + w.y
    sums(3 * v + 2) = sums(3 * v + 2) + w.z

  /** The angle between two non-zero vectors, in radians (atan2 form: accurate near 0 and π). */
  private def angle(u: Vec3, v: Vec3): Double = StrictMath.atan2(u.cross(v).length, u.dot(v))
