package tracer.io

import tracer.math.Vec3

/** Normals for the corners of a mesh whose file gives none (scene format v3, `smooth="auto"`):
  * at each vertex, the sum over the faces that use it of the face's unit normal times the face's
  * angle at that vertex, normalised. Faces whose corners are collinear count for nothing.
  */
private[io] object VertexNormals:

  /** The normal of every vertex index used by `faces`, or `None` where the sum is zero. */
  def of(faces: Vector[ObjTriangle]): Map[Int, Option[Vec3]] =
    val sums = faces.foldLeft(Map.empty[Int, Vec3]) { (sums, f) =>
      (f.b - f.a).cross(f.c - f.a).normalised.fold(sums) { unit =>
        val (i, j, k) = f.vertices
        List((i, f.a, f.b, f.c), (j, f.b, f.c, f.a), (k, f.c, f.a, f.b)).foldLeft(sums) {
          case (s, (v, corner, next, previous)) =>
            val weighted = unit * angle(next - corner, previous - corner)
            s.updated(v, s.getOrElse(v, Vec3.Zero) + weighted)
        }
      }
    }
    sums.view.mapValues(_.normalised).toMap

  /** The angle between two non-zero vectors, in radians (atan2 form: accurate near 0 and π). */
  private def angle(u: Vec3, v: Vec3): Double = Math.atan2(u.cross(v).length, u.dot(v))
