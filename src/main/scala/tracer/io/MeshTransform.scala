package tracer.io

import tracer.math.Vec3

/** A mesh's placement: p ↦ T(Rz(Ry(Rx(scale·p)))), angles in degrees, as POV-Ray's `rotate`. */
private[io] final case class MeshTransform(scale: Double, degrees: Vec3, translation: Vec3):
  private val (sx, cx) =
    (StrictMath.sin(Math.toRadians(degrees.x)), StrictMath.cos(Math.toRadians(degrees.x)))
  private val (sy, cy) =
    (StrictMath.sin(Math.toRadians(degrees.y)), StrictMath.cos(Math.toRadians(degrees.y)))
  private val (sz, cz) =
    (StrictMath.sin(Math.toRadians(degrees.z)), StrictMath.cos(Math.toRadians(degrees.z)))

  /** The placed point. */
  def apply(p: Vec3): Vec3 = turn(p * scale) + translation

  /** [[apply]] of the point (x, y, z), written to `out` at `at` (x), `at + 1` and `at + 2`: the
    * same operations in the same order, so the same doubles.
    *
    * Perf: no `Vec3` a step (six a vertex through [[apply]]: 10 MB of garbage for a mesh of
    * 40,000 vertices, made while the reader's code is still cold; docs/performance.md, round 37).
    */
  def placeInto(x: Double, y: Double, z: Double, out: Array[Double], at: Int): Unit =
    val px  = x * scale
    val py  = y * scale
    val pz  = z * scale
    val rxy = py * cx - pz * sx
    val rxz = py * sx + pz * cx
    val ryx = px * cy + rxz * sy
    val ryz = -px * sy + rxz * cy
    out(at) = ryx * cz - rxy * sz + translation.x
    out(at + 1) = ryx * sz + rxy * cz + translation.y
    out(at + 2) = ryz + translation.z

  /** A direction (a normal) as placed: rotated only, since the scale is uniform. */
  def turn(d: Vec3): Vec3 =
    val rx = Vec3(d.x, d.y * cx - d.z * sx, d.y * sx + d.z * cx)
    val ry = Vec3(rx.x * cy + rx.z * sy, rx.y, -rx.x * sy + rx.z * cy)
    Vec3(ry.x * cz - ry.y * sz, ry.x * sz + ry.y * cz, ry.z)
