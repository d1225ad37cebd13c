package tracer.render

import tracer.geometry.{Ray, Shape}
import tracer.math.Vec3
import tracer.scene.AreaLight

/** How much of a light reaches a point: 1 in full light, 0 in full shadow, and in between behind
  * transmitting surfaces and in an area light's penumbra (docs/rendering.md, Shadows).
  *
  * Not thread-safe: it keeps scratch space, so each [[Shading]] makes its own.
  *
  * @param world the scene
  * @param query the queries' scratch space, from `world.newQuery()`
  */
final class Shadows(world: World, query: Query):
  // Perf: the area lights' grid of samples, reused for every shading point (a sample is computed
  // once and shared by the cells that have it as a corner; −1 marks one not yet computed). Sized
  // for the scene's largest area light: a Shading is made per row, so a full 64 × 64 grid for a
  // scene without area lights was 32 KB a row (JFR allocation samples, docs/performance.md).
  private val grid = new Array[Double](world.largestAreaLight)

  /** The share of a point light at distance `reach` in unit direction `toward` from `from`: the
    * product of the `transmit` of every surface crossed at 0 < t < reach (0 at an opaque one).
    */
  def point(from: Vec3, toward: Vec3, reach: Double): Double =
    pointAlong(from.x, from.y, from.z, toward.x, toward.y, toward.z, reach)

  /** The share of the world's light `k`, an area light, that reaches `from`, as POV-Ray 3.7
    * computes it without `adaptive` (`Trace::TraceAreaLightSubsetShadowRay`): the grid's four
    * corners are sampled, and a cell wider than one step is split at its middle sample into four
    * cells (the middle row and column shared when the count is odd); the result is the mean of
    * the four parts. For a point light, [[point]] toward it.
    */
  def area(from: Vec3, k: Int): Double = areaFrom(from.x, from.y, from.z, k)

  /** [[area]] from the point (fx, fy, fz). */
  def areaFrom(fx: Double, fy: Double, fz: Double, k: Int): Double =
    val light = world.lights(k)
    light.area match
      case Some(area) =>
        java.util.Arrays.fill(grid, 0, area.samplesA * area.samplesB, -1.0)
        cell(fx, fy, fz, world.subLights(k), area, 0, 0, area.samplesA - 1, area.samplesB - 1)
      case None =>
        val tx    = light.location.x - fx
        val ty    = light.location.y - fy
        val tz    = light.location.z - fz
        val reach = Math.sqrt(tx * tx + ty * ty + tz * tz)
        if reach > 0 then pointAlong(fx, fy, fz, tx / reach, ty / reach, tz / reach, reach) else 1.0

  private def cell(
      fx: Double,
      fy: Double,
      fz: Double,
      positions: IArray[Double],
      light: AreaLight,
      u1: Int,
      v1: Int,
      u2: Int,
      v2: Int
  ): Double =
    if u2 - u1 > 1 || v2 - v1 > 1 then
      val lowU  = (u1 + u2) / 2
      val highU = (u1 + u2 + 1) / 2
      val lowV  = (v1 + v2) / 2
      val highV = (v1 + v2 + 1) / 2
      (cell(fx, fy, fz, positions, light, u1, v1, lowU, lowV) +
        cell(fx, fy, fz, positions, light, highU, v1, u2, lowV) +
        cell(fx, fy, fz, positions, light, u1, highV, lowU, v2) +
        cell(fx, fy, fz, positions, light, highU, highV, u2, v2)) * 0.25
    else
      (sample(fx, fy, fz, positions, light, u1, v1) + sample(fx, fy, fz, positions, light, u2, v1) +
        sample(fx, fy, fz, positions, light, u1, v2) +
        sample(fx, fy, fz, positions, light, u2, v2)) * 0.25

  /** The share of sub-light (u, v) that reaches `from`, computed once per shading point. */
  private def sample(
      fx: Double,
      fy: Double,
      fz: Double,
      positions: IArray[Double],
      light: AreaLight,
      u: Int,
      v: Int
  ): Double =
    val k = u * light.samplesB + v
    if grid(k) < 0 then
      // toLight = (centre + offset) − from, its length and its direction, in plain doubles.
      val tx    = positions(3 * k) - fx
      val ty    = positions(3 * k + 1) - fy
      val tz    = positions(3 * k + 2) - fz
      val reach = Math.sqrt(tx * tx + ty * ty + tz * tz)
      grid(k) =
        if reach > 0 then pointAlong(fx, fy, fz, tx / reach, ty / reach, tz / reach, reach)
        else 1.0
    grid(k)

  /** [[point]] from (fx, fy, fz) in unit direction (dx, dy, dz). */
  def pointAlong(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if !world.transmits then
      if world.occludedAlong(fx, fy, fz, dx, dy, dz, reach, query) then 0.0 else 1.0
    else transmittance(fx, fy, fz, dx, dy, dz, reach)

  /** The product of the `transmit` of every surface the ray from `from` in direction d crosses
    * before `reach`, walking from hit to hit; 0 as soon as an opaque one is found.
    */
  private def transmittance(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    // Perf: the walk's state in local doubles, no Vec3 or Ray per step: the origin moves past
    // each surface crossed.
    var ox    = fx
    var oy    = fy
    var oz    = fz
    var left  = reach
    var share = 1.0
    while share > 0 && left > 0 do
      // Only hits before what is left of the way count (t ≤ left, then t < left below).
      val i = world.nearestAlong(ox, oy, oz, dx, dy, dz, left, query)
      val t = query.distance
      if i >= 0 && t < left then
        share *= world.surface(i, leafAt(i, ox, oy, oz, dx, dy, dz, t)).transmit
        // Step just past the surface, so the next query does not find it again.
        val step = t + Shading.Epsilon
        ox = ox + dx * step
        oy = oy + dy * step
        oz = oz + dz * step
        left -= step
      else left = 0
    share

  /** Which leaf of shape `i` the ray from (ox, oy, oz) along d meets at `t`: 0 unless the shape
    * shows a surface per leaf (a CSG combination), which takes the general path's full hit.
    */
  private def leafAt(
      i: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      t: Double
  ): Int =
    if !world.hasLeafSurfaces(i) then 0
    else Shape.hitAt(world.shape(i), Ray(Vec3(ox, oy, oz), Vec3(dx, dy, dz)), t).leaf
