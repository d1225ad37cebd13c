package tracer.render.path

import tracer.geometry.{Ray, Shape}
import tracer.math.Vec3
import tracer.render.{Query, Refraction, Shading, World}

/** Which worlds need [[Visibility]]'s walk. */
object Visibility:
  /** True when some surface of `scene` is clear (transmit > 0 with η = 1). */
  def anyClear(scene: tracer.scene.Scene): Boolean =
    scene.objects.exists(o =>
      o.surfaces.exists(s => s.transmit > 0 && Math.abs(o.surface.ior - 1) < Refraction.SameIndex)
    )

/** How much of a light reaches a point along a shadow ray in path mode: the product of the
  * `transmit` t of every clear (η = 1) surface crossed, 0 as soon as an opaque surface or
  * refracting glass (η ≠ 1) is met (a path reaches a light through glass only by refraction,
  * which the paths themselves sample).
  *
  * Not thread-safe: it uses `query`, the thread's scratch space.
  *
  * @param clear true when some surface of the world is clear, so that shadow rays must walk
  *   through them; without, any hit blocks the light (glass included)
  */
final class Visibility(world: World, query: Query, clear: Boolean):

  /** The share of light from `from` along unit `direction` that crosses every surface before
    * `reach` (+∞ for the sky).
    */
  def along(from: Vec3, direction: Vec3, reach: Double): Double =
    alongFrom(from.x, from.y, from.z, direction.x, direction.y, direction.z, reach)

  /** [[along]] from (fx, fy, fz) along unit (dx, dy, dz). */
  def alongFrom(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if !clear then if world.occludedAlong(fx, fy, fz, dx, dy, dz, reach, query) then 0.0 else 1.0
    else walk(fx, fy, fz, dx, dy, dz, reach)

  /** The walk from surface to surface for a world where some surface transmits.
    *
    * Perf: the walk's state in locals; the origin moves past each clear surface crossed.
    */
  private def walk(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    var ox    = fx
    var oy    = fy
    var oz    = fz
    var left  = reach
    var share = 1.0
    while share > 0 && left > 0 do
      val i = world.nearestAlong(ox, oy, oz, dx, dy, dz, left, query)
      val t = query.distance
      if i >= 0 && t < left then
        val leaf =
          if world.hasLeafSurfaces(i) then
            Shape.hitAt(world.shape(i), Ray(Vec3(ox, oy, oz), Vec3(dx, dy, dz)), t).leaf
          else 0
        val surface = world.surface(i, leaf)
        val clear   = Math.abs(world.surface(i).ior - 1) < Refraction.SameIndex
        share = if clear then share * surface.transmit else 0.0
        val step = t + Shading.Epsilon
        ox = ox + dx * step
        oy = oy + dy * step
        oz = oz + dz * step
        left -= step
      else left = 0
    share
