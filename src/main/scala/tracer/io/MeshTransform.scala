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

  /** A direction (a normal) as placed: rotated only, since the scale is uniform. */
  def turn(d: Vec3): Vec3 =
    val rx = Vec3(d.x, d.y * cx - d.z * sx, d.y * sx + d.z * cx)
    val ry = Vec3(rx.x * cy + rx.z * sy, rx.y, -rx.x * sy + rx.z * cy)
    Vec3(ry.x * cz - ry.y * sz, ry.x * sz + ry.y * cz, ry.z)
