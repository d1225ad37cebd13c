package tracer.bench

import java.nio.file.{Files, Path}
import tracer.demo.Models

/** Writes a big OBJ mesh and a scene that shows it, for timing loading (docs/performance.md,
  * round 4): a torus-knot tube of 2 · segments · sides triangles, by default 3600 × 180 =
  * 1,296,000 triangles (about 49 MB; never committed).
  *
  * `./sbt "bench/runMain tracer.bench.BigMesh DIR [SEGMENTS SIDES]"`, then
  * `cd DIR && tracer -x 8 -y 8 o.png < knot.xml`.
  */
object BigMesh:
  /** Writes `knot.obj` and `knot.xml` into the directory named by the first argument. */
  def main(args: Array[String]): Unit =
    val dir      = Path.of(args.headOption.getOrElse("target/big-mesh"))
    val segments = args.lift(1).map(_.toInt).getOrElse(3600)
    val sides    = args.lift(2).map(_.toInt).getOrElse(180)
    Files.createDirectories(dir)
    // Positions and faces only, as the 49 MB mesh.
    val model =
      Models.torusKnot(2, 3, segments, sides, 0.25).copy(uvs = Vector.empty, normals = Vector.empty)
    val _ = Files.writeString(
      dir.resolve("knot.obj"),
      Models.obj(model, s"a torus knot of ${2 * segments * sides} triangles")
    )
    val _ = Files.writeString(dir.resolve("knot.xml"), scene)

  /** The scene: the knot in front of the camera, one light. */
  val scene: String =
    """<?xml version="1.0" encoding="UTF-8"?>
      |<scene>
      |  <camera zoom="1" width="1.6" height="0.9">
      |    <location x="0" y="3" z="-4"/><lookat x="0" y="0" z="0"/><up x="0" y="1" z="0"/>
      |  </camera>
      |  <light><location x="-5" y="8" z="-6"/><colour r="1" g="1" b="1"/></light>
      |  <mesh file="knot.obj"><surface diffuse="0.9"><colour r="0.75" g="0.6" b="0.35"/></surface></mesh>
      |</scene>
      |""".stripMargin
