package tracer.io

import tracer.geometry.Mesh
import tracer.math.Vec3

/** An OBJ file's triangles placed as a `<mesh>` says: each vertex placed once (not once per face
  * that uses it), the faces whose placed corners are collinear left out, and the corners' normals
  * as `smooth` chooses them, each file normal and computed vertex normal turned once.
  *
  * @param obj    the file's triangles
  * @param place  the mesh's placement
  * @param smooth which faces shade with interpolated normals
  */
private[io] final class MeshBuilder(obj: ObjMesh, place: MeshTransform, smooth: Smooth):

  /** The mesh, or `None` when every face is collinear once placed. */
  def build(): Option[Mesh] =
    val vertices = placed()
    val proper   = properFaces(vertices)
    Option.when(proper.nonEmpty) {
      val (normals, cornerNormals) = smoothNormals(proper)
      val textured                 =
        obj.textureCorners.nonEmpty && proper.exists(f => obj.textureCorners(3 * f) >= 0)
      Mesh(
        vertices,
        pick(obj.corners, proper),
        normals,
        cornerNormals,
        if textured then obj.texture else IArray.empty[Double],
        if textured then pick(obj.textureCorners, proper) else IArray.empty[Int]
      )
    }

  /** Every vertex placed, 3 doubles a vertex. */
  private def placed(): IArray[Double] =
    val out = new Array[Double](obj.vertices.length)
    // Perf: a counted loop over the vertices, once each, on the file's doubles.
    val in = obj.vertices
    var i  = 0
    while i < out.length do
      place.placeInto(in(i), in(i + 1), in(i + 2), out, i)
      i += 3
    IArray.unsafeFromArray(out)

  /** The numbers of the faces whose placed corners span a triangle, in order. */
  private def properFaces(vertices: IArray[Double]): Array[Int] =
    val c   = obj.corners
    val out = new Array[Int](obj.faceCount)
    // Why: the number of proper faces found so far.
    var n = 0
    // Perf: Triangle.isProper's test on plain doubles (Mesh.isProperFace) in a counted loop: no
    // Vec3 or Option per face (a sixth of the 1.3M-face mesh's reading; docs/performance.md,
    // round 7).
    var f = 0
    while f < obj.faceCount do
      if Mesh.isProperFace(vertices, c, f) then
        out(n) = f
        n += 1
      f += 1
    if n == out.length then out else java.util.Arrays.copyOf(out, n)

  /** The three numbers of each face of `faces` in `corners` (`corners` itself when `faces` are
    * all of them, as they usually are: no copy).
    */
  private def pick(corners: IArray[Int], faces: Array[Int]): IArray[Int] =
    if 3 * faces.length == corners.length then corners else picked(corners, faces)

  private def picked(corners: IArray[Int], faces: Array[Int]): IArray[Int] =
    val out = new Array[Int](3 * faces.length)
    // Perf: a counted loop copying three numbers a face.
    var k = 0
    while k < faces.length do
      val f = faces(k)
      out(3 * k) = corners(3 * f); out(3 * k + 1) = corners(3 * f + 1)
      out(3 * k + 2) = corners(3 * f + 2)
      k += 1
    IArray.unsafeFromArray(out)

  /** The mesh's normals and each face's three numbers among them (−1 three times for a flat
    * face); both empty when every face is flat. The normals: the file's `vn`s turned with the
    * mesh and normalised, then (under auto) the computed vertex normals, likewise; a face is
    * smooth when the normals it takes are all defined, each as a `Triangle`'s corner normals
    * were (scene-format.md, Smooth meshes).
    */
  private def smoothNormals(faces: Array[Int]): (IArray[Double], IArray[Int]) =
    if smooth == Smooth.Off then (IArray.empty[Double], IArray.empty[Int])
    else
      val files    = obj.normals.length / 3
      val computed =
        if smooth == Smooth.Auto then VertexNormals.of(obj) else IArray.empty[Option[Vec3]]
      val turned: IndexedSeq[Option[Vec3]] =
        (0 until files).map(j =>
          place
            .turn(Vec3(obj.normals(3 * j), obj.normals(3 * j + 1), obj.normals(3 * j + 2)))
            .normalised
        ) ++ computed.map(_.flatMap(n => place.turn(n).normalised))
      val fromFile = obj.normalCorners
      val numbers  = new Array[Int](3 * faces.length)
      // Why: set once a face takes its normals, to leave the arrays out when none does.
      var any = false
      // Perf: a counted loop over the faces, three numbers each.
      var k = 0
      while k < faces.length do
        val f = faces(k)
        // The file's normals where the face has them, else (auto) the computed ones.
        val source =
          if fromFile.length > 0 && fromFile(3 * f) >= 0 then
            Some((fromFile(3 * f), fromFile(3 * f + 1), fromFile(3 * f + 2)))
          else if smooth == Smooth.Auto then
            val (i, j, l) = (obj.corners(3 * f), obj.corners(3 * f + 1), obj.corners(3 * f + 2))
            Option.when(computed(i).isDefined && computed(j).isDefined && computed(l).isDefined)(
              (files + i, files + j, files + l)
            )
          else None
        source.filter((a, b, c) =>
          turned(a).isDefined && turned(b).isDefined && turned(c).isDefined
        ) match
          case Some((a, b, c)) =>
            numbers(3 * k) = a; numbers(3 * k + 1) = b; numbers(3 * k + 2) = c
            any = true
          case None =>
            numbers(3 * k) = -1; numbers(3 * k + 1) = -1; numbers(3 * k + 2) = -1
        k += 1
      if !any then (IArray.empty[Double], IArray.empty[Int])
      else
        val values = IArray.from(
          turned.iterator.flatMap(n =>
            n.fold(Iterator(0.0, 0.0, 0.0))(v => Iterator(v.x, v.y, v.z))
          )
        )
        (values, IArray.unsafeFromArray(numbers))
