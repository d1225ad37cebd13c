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
  * @param stack the BVH walk's scratch space, from `world.newStack()`
  */
final class Shadows(world: World, stack: Array[Int]):
  // Perf: the area lights' grid of samples, reused for every shading point (a sample is computed
  // once and shared by the cells that have it as a corner; −1 marks one not yet computed). Sized
  // for the scene's largest area light: a Shading is made per row, so a full 64 × 64 grid for a
  // scene without area lights was 32 KB a row (JFR allocation samples, docs/performance.md).
  private var grid = new Array[Double](world.largestAreaLight)

  /** The share of a point light at distance `reach` in unit direction `toward` from `from`: the
    * product of the `transmit` of every surface crossed at 0 < t < reach (0 at an opaque one).
    */
  def point(from: Vec3, toward: Vec3, reach: Double): Double =
    if !world.transmits then if world.occluded(Ray(from, toward), reach, stack) then 0.0 else 1.0
    else transmittance(from, toward, reach)

  /** The share of an area light centred at `centre` that reaches `from`, as POV-Ray 3.7 computes
    * it without `adaptive` (`Trace::TraceAreaLightSubsetShadowRay`): the grid's four corners are
    * sampled, and a cell wider than one step is split at its middle sample into four cells (the
    * middle row and column shared when the count is odd); the result is the mean of the four parts.
    */
  def area(from: Vec3, centre: Vec3, light: AreaLight): Double =
    val samples = light.samplesA * light.samplesB
    if grid.length < samples then grid = new Array[Double](samples) // a light not of this world
    java.util.Arrays.fill(grid, 0, samples, -1.0)
    cell(from, centre, light, 0, 0, light.samplesA - 1, light.samplesB - 1)

  private def cell(
      from: Vec3,
      centre: Vec3,
      light: AreaLight,
      u1: Int,
      v1: Int,
      u2: Int,
      v2: Int
  ): Double =
    if u2 - u1 > 1 || v2 - v1 > 1 then
      val (lowU, highU) = ((u1 + u2) / 2, (u1 + u2 + 1) / 2)
      val (lowV, highV) = ((v1 + v2) / 2, (v1 + v2 + 1) / 2)
      (cell(from, centre, light, u1, v1, lowU, lowV) +
        cell(from, centre, light, highU, v1, u2, lowV) +
        cell(from, centre, light, u1, highV, lowU, v2) +
        cell(from, centre, light, highU, highV, u2, v2)) * 0.25
    else
      (sample(from, centre, light, u1, v1) + sample(from, centre, light, u2, v1) +
        sample(from, centre, light, u1, v2) + sample(from, centre, light, u2, v2)) * 0.25

  /** The share of sub-light (u, v) that reaches `from`, computed once per shading point. */
  private def sample(from: Vec3, centre: Vec3, light: AreaLight, u: Int, v: Int): Double =
    val k = u * light.samplesB + v
    if grid(k) < 0 then
      val toLight = centre + light.offset(u, v) - from
      val reach   = toLight.length
      grid(k) = if reach > 0 then point(from, toLight / reach, reach) else 1.0
    grid(k)

  /** The product of the `transmit` of every surface the ray (from, toward) crosses before
    * `reach`, walking from hit to hit; 0 as soon as an opaque one is found.
    */
  private def transmittance(from: Vec3, toward: Vec3, reach: Double): Double =
    var origin = from
    var left   = reach
    var share  = 1.0
    while share > 0 && left > 0 do
      val ray = Ray(origin, toward)
      val i   = world.nearest(ray, stack)
      val t   = if i < 0 then Double.PositiveInfinity else Shape.distance(world.shape(i), ray)
      if t < left then
        val leaf = if world.hasLeafSurfaces(i) then Shape.hitAt(world.shape(i), ray, t).leaf else 0
        share *= world.surface(i, leaf).transmit
        // Step just past the surface, so the next query does not find it again.
        origin = ray.at(t + Shading.Epsilon)
        left -= t + Shading.Epsilon
      else left = 0
    share
