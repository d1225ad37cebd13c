package tracer.demo

import java.nio.file.{Files, Path}
import java.util.Locale
import tracer.math.Vec3

/** Models made by code and written as Wavefront OBJ files: the gallery's meshes.
  *
  * Each is a list of vertices (with texture coordinates, and normals where the surface is smooth)
  * and faces of 1-based vertex indices.
  */
object Models:

  /** A mesh: vertices, their texture coordinates, their unit normals (none for a faceted model),
    * and faces as 1-based vertex indices.
    */
  final case class Model(
      vertices: Vector[Vec3],
      uvs: Vector[(Double, Double)],
      faces: Vector[Seq[Int]],
      normals: Vector[Vec3] = Vector.empty
  )

  /** `v` scaled to length 1: the models' directions are never zero, so a zero one is a bug here. */
  private def unit(v: Vec3): Vec3 =
    v.normalised.get // nosemgrep: option-get — a zero direction is a bug in these generators: stop

  /** A sphere made by splitting each face of an icosahedron into four, `levels` times. */
  def icosphere(levels: Int): Model =
    val t     = (1 + Math.sqrt(5)) / 2
    val start = Vector(
      Vec3(-1, t, 0),
      Vec3(1, t, 0),
      Vec3(-1, -t, 0),
      Vec3(1, -t, 0),
      Vec3(0, -1, t),
      Vec3(0, 1, t),
      Vec3(0, -1, -t),
      Vec3(0, 1, -t),
      Vec3(t, 0, -1),
      Vec3(t, 0, 1),
      Vec3(-t, 0, -1),
      Vec3(-t, 0, 1)
    ).map(unit)
    val faces0 = Vector(
      (0, 11, 5),
      (0, 5, 1),
      (0, 1, 7),
      (0, 7, 10),
      (0, 10, 11),
      (1, 5, 9),
      (5, 11, 4),
      (11, 10, 2),
      (10, 7, 6),
      (7, 1, 8),
      (3, 9, 4),
      (3, 4, 2),
      (3, 2, 6),
      (3, 6, 8),
      (3, 8, 9),
      (4, 9, 5),
      (2, 4, 11),
      (6, 2, 10),
      (8, 6, 7),
      (9, 8, 1)
    )
    val (vertices, faces) = (0 until levels).foldLeft((start, faces0)) { case ((vs, fs), _) =>
      // Split every edge at its midpoint (shared between the two faces of the edge), pushed out.
      val midpoints = fs
        .flatMap((a, b, c) => Seq((a, b), (b, c), (c, a)))
        .map((a, b) => (a min b, a max b))
        .distinct
      val index = midpoints.zipWithIndex.map((edge, k) => edge -> (vs.length + k)).toMap
      val added = midpoints.map((a, b) => unit((vs(a) + vs(b)) * 0.5))
      def mid(a: Int, b: Int) = index((a min b, a max b))
      (
        vs ++ added,
        fs.flatMap((a, b, c) =>
          Seq(
            (a, mid(a, b), mid(c, a)),
            (b, mid(b, c), mid(a, b)),
            (c, mid(c, a), mid(b, c)),
            (mid(a, b), mid(b, c), mid(c, a))
          )
        )
      )
    }
    Model(
      vertices,
      vertices.map(v =>
        (0.5 + Math.atan2(v.x, -v.z) / (2 * Math.PI), 0.5 + Math.asin(v.y) / Math.PI)
      ),
      faces.map((a, b, c) => Seq(a + 1, b + 1, c + 1)),
      normals = vertices // on a unit sphere the normal is the point
    )

  /** A (p, q) torus knot: a tube of radius `tube` along the knot, as quads with texture coordinates. */
  def torusKnot(p: Int, q: Int, segments: Int, sides: Int, tube: Double): Model =
    def curve(s: Double): Vec3 =
      val r = 1 + 0.45 * Math.cos(q * s)
      Vec3(r * Math.cos(p * s), 0.45 * Math.sin(q * s), r * Math.sin(p * s))
    val rings = (0 until segments).map { i =>
      val s        = 2 * Math.PI * i / segments
      val centre   = curve(s)
      val tangent  = unit(curve(s + 1e-4) - curve(s - 1e-4))
      val normal   = unit(tangent.cross(Vec3.UnitY))
      val binormal = tangent.cross(normal)
      (0 until sides).map { j =>
        val a      = 2 * Math.PI * j / sides
        val radial = normal * Math.cos(a) + binormal * Math.sin(a)
        (centre + radial * tube, radial)
      }
    }
    val vertices = rings.flatten.map(_._1).toVector
    val uvs      = (for i <- 0 until segments; j <- 0 until sides
    yield (4.0 * i / segments, j.toDouble / sides)).toVector
    def at(i: Int, j: Int) = (i % segments) * sides + (j % sides) + 1
    val faces              = (for i <- 0 until segments; j <- 0 until sides
    yield Seq(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))).toVector
    Model(vertices, uvs, faces, rings.flatten.map(_._2).toVector)

  /** A rolling landscape on an n × n grid of quads over [−1, 1]², its texture stretched once. */
  def terrain(n: Int): Model =
    def height(x: Double, z: Double) =
      0.18 * Math.sin(3.1 * x + 0.5) * Math.cos(2.3 * z) + 0.07 * Math.sin(
        7.3 * x * z
      ) + 0.04 * Math.cos(11 * x - 5 * z)
    val points = for i <- 0 to n; j <- 0 to n yield
      val (x, z) = (-1 + 2.0 * i / n, -1 + 2.0 * j / n)
      (Vec3(x, height(x, z), z), (i.toDouble / n, j.toDouble / n))
    def at(i: Int, j: Int) = i * (n + 1) + j + 1
    val faces              = (for i <- 0 until n; j <- 0 until n
    yield Seq(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j))).toVector
    Model(points.map(_._1).toVector, points.map(_._2).toVector, faces)

  /** The model as OBJ text: each face corner as `v`, `v/vt`, `v//vn` or `v/vt/vn`, as far as the
    * model has texture coordinates and normals (one of each per vertex, same index).
    */
  def obj(model: Model, title: String): String =
    def n(d: Double) = String.format(Locale.ROOT, "%.6f", d)
    val b            = StringBuilder(s"# $title, generated by tracer.demo.Models\n")
    model.vertices.foreach(v => b.append(s"v ${n(v.x)} ${n(v.y)} ${n(v.z)}\n"))
    model.uvs.foreach((u, v) => b.append(s"vt ${n(u)} ${n(v)}\n"))
    model.normals.foreach(v => b.append(s"vn ${n(v.x)} ${n(v.y)} ${n(v.z)}\n"))
    val corner: Int => String = (model.uvs.nonEmpty, model.normals.nonEmpty) match
      case (false, false) => _.toString
      case (true, false)  => i => s"$i/$i"
      case (false, true)  => i => s"$i//$i"
      case (true, true)   => i => s"$i/$i/$i"
    model.faces.foreach(f => b.append(f.map(corner).mkString("f ", " ", "\n")))
    b.toString

  /** Writes the gallery's models into `dir`. */
  def writeGallery(dir: Path): Unit =
    Files.createDirectories(dir)
    Files.writeString(dir.resolve("icosphere.obj"), obj(icosphere(3), "an icosphere, 3 levels"))
    Files.writeString(
      dir.resolve("knot.obj"),
      obj(torusKnot(2, 3, 240, 12, 0.22), "a (2, 3) torus knot")
    )
    Files.writeString(dir.resolve("terrain.obj"), obj(terrain(48), "a rolling terrain")): Unit

  /** Writes the models into the directory named by the first argument (default `scenes/models`). */
  def main(args: Array[String]): Unit = writeGallery(
    Path.of(args.headOption.getOrElse("scenes/models"))
  )
