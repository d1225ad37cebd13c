package tracer.render.path

import tracer.geometry.{Hit, Ray, Shape}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.{Integrator, Projection, Shading, World}
import tracer.scene.{Pigment, Scene}

/** Path mode's integrator (docs/rendering.md, Path tracing): a pixel is the mean of N samples,
  * each an unbiased estimate of the radiance arriving through a random point of the pixel, found
  * by following one path through the scene. At every bounce the path samples one emitter (next
  * event estimation) and then its scattering function for the next direction; where both could
  * find the same light the two estimates are weighted by the power heuristic. Russian roulette
  * ends paths from the fifth bounce on, as Mitsuba 3's `path` integrator does.
  *
  * @param scene      the scene (its lights, glowing shapes and background are the emitters)
  * @param world      the scene compiled for tracing
  * @param projection the camera's rays
  * @param settings   N, the seed and the sampler
  * @param depth      d: at most d bounces after the camera ray (a clear pass is not one)
  */
final class PathTracer(
    scene: Scene,
    private[path] val world: World,
    private[path] val projection: Projection,
    settings: Integrator.Path,
    private[path] val depth: Int
):
  private[path] val emitters = Emitters(scene)
  private[path] val sampler  = Sampler(settings.sampler, settings.seed, settings.samples)
  private val samples        = settings.samples

  /** A tracer for one row task: it keeps scratch space, so no two threads share one. */
  def task(): PathTracer.Task = PathTracer.Task(this)

  /** The sampled emitters (for tests). */
  def lights: Emitters = emitters

  /** Pixel (x, y) of the whole picture: the mean of its N samples, as they are. */
  private def pixel(task: PathTracer.Task, x: Int, y: Int): Colour =
    // Perf: the sum in three locals, no Colour per sample kept.
    var r = 0.0
    var g = 0.0
    var b = 0.0
    var j = 0
    while j < samples do
      task.trace(x, y, j)
      r += task.r
      g += task.g
      b += task.b
      j += 1
    Colour(r / samples, g / samples, b / samples)

  /** The surface colour C at the hit: the texel or checker cell there, or the plain colour. */
  private[path] def pigment(i: Int, hit: Hit): Colour = world.surface(i, hit.leaf).pigment match
    case Pigment.Solid(c)          => c
    case Pigment.Textured(texture) =>
      val uv = Shape.surfaceCoordinates(world.shape(i), hit.point, hit.leaf)
      texture.colourAt(uv.u, uv.v)
    case checker: Pigment.Checker => Pigment.checkerColour(checker, hit.point)

/** The row tasks of [[PathTracer]] and the weights it combines estimates with. */
object PathTracer:
  /** Russian roulette starts after this many bounces (Mitsuba's `rr_depth`). */
  val RouletteDepth: Int = 5

  /** The most a path survives Russian roulette with: 0.95, as Mitsuba. */
  val MostSurvival: Double = 0.95

  /** The power heuristic's weight for an estimate of density `a` beside one of density `b`. */
  inline def powerHeuristic(a: Double, b: Double): Double =
    val a2 = a * a
    a2 / (a2 + b * b)

  /** One row task's tracer: the pixel function and the scratch space of its queries.
    *
    * Perf: one path's radiance is left in three fields rather than a new Colour per sample, and
    * the loop keeps the throughput and the result in locals (docs/performance.md, path mode).
    */
  final class Task(tracer: PathTracer):
    private val world      = tracer.world
    private val emitters   = tracer.emitters
    private val sampler    = tracer.sampler
    private val query      = world.newQuery()
    private val visibility = Visibility(world, query)
    // Why: the last path's radiance, read by the pixel loop (see the class's Perf note).
    private[PathTracer] var r = 0.0
    private[PathTracer] var g = 0.0
    private[PathTracer] var b = 0.0

    /** Pixel (x, y) of the whole picture: the mean of its N samples, as they are. */
    def pixel(x: Int, y: Int): Colour = tracer.pixel(this, x, y)

    /** Sample j of pixel (x, y): the radiance one path brings back, left in r, g, b. */
    private[PathTracer] def trace(x: Int, y: Int, j: Int): Unit =
      val offset = sampler.pair(x, y, j, 0)
      var ray    =
        tracer.projection.ray(x + Sampler.first(offset), y + Sampler.second(offset))
      // The throughput, what the path has gathered, and its state.
      var tr          = 1.0
      var tg          = 1.0
      var tb          = 1.0
      var eta         = 1.0 // the product of the index ratios crossed, for Russian roulette
      var bounces     = 0
      var vertex      = 0   // every surface met, clear passes included: which dimensions to use
      var lastDensity = 0.0 // the last bounce's direction density; 0 after the camera or a delta
      var lastPoint   = ray.origin
      var going       = true
      r = 0; g = 0; b = 0
      while going do
        val i = world.nearest(ray, query)
        if i < 0 then
          // The sky: background radiance, weighted against next-event estimation's sampling.
          val sky = world.background
          val w   =
            if lastDensity > 0 && emitters.skyDensity > 0 then
              powerHeuristic(lastDensity, emitters.skyDensity)
            else 1.0
          r += tr * sky.r * w
          g += tg * sky.g * w
          b += tb * sky.b * w
          going = false
        else
          val shape   = world.shape(i)
          val hit     = Shape.hitAt(shape, ray, query.distance)
          val surface = world.surface(i, hit.leaf)
          if hit.front && surface.emits then
            val e = surface.emission
            val w =
              if lastDensity > 0 && emitters.samples(i) then
                powerHeuristic(lastDensity, emitters.density(i, lastPoint, hit.point))
              else 1.0
            r += tr * e.r * w
            g += tg * e.g * w
            b += tb * e.b * w
          val bsdf = Bsdf.of(surface, tracer.pigment(i, hit))
          val base = 2 + Sampler.Dimensions * vertex
          vertex += 1
          if bounces >= tracer.depth then
            // No bounce is left, but a clear surface still lets the path through unbent.
            if bsdf.clear then
              tr *= bsdf.transmit
              tg *= bsdf.transmit
              tb *= bsdf.transmit
              ray = Ray(hit.point - hit.normal * Shading.Epsilon, ray.direction)
            else going = false
          else
            val normal = Shape.shadingNormal(shape, hit, ray)
            val wi     = -ray.direction
            if bsdf.smooth && !emitters.isEmpty then
              nextEvent(x, y, j, base, hit, normal, wi, bsdf, tr, tg, tb)
            val uv      = sampler.pair(x, y, j, base + 4)
            val fresnel = if bsdf.glass then sampler.uniform(x, y, j, base + 7) else 0.0
            val choice  = sampler.uniform(x, y, j, base + 3)
            val s       =
              bsdf.sample(
                normal,
                wi,
                hit.front,
                choice,
                Sampler.first(uv),
                Sampler.second(uv),
                fresnel
              )
            if s.absorbed then going = false
            else
              tr *= s.weight.r
              tg *= s.weight.g
              tb *= s.weight.b
              val side = if s.transmitted then -Shading.Epsilon else Shading.Epsilon
              ray = Ray(hit.point + hit.normal * side, s.direction)
              if s.bounce then
                bounces += 1
                eta *= s.eta
                lastDensity = s.density
                lastPoint = hit.point
                val most = Math.max(tr, Math.max(tg, tb))
                if most <= 0 then going = false
                else if bounces >= RouletteDepth then
                  val survive = Math.min(most * eta * eta, MostSurvival)
                  if sampler.uniform(x, y, j, base + 6) >= survive then going = false
                  else
                    tr /= survive
                    tg /= survive
                    tb /= survive

    /** Next-event estimation at a bounce: one emitter sampled, its light through the smooth
      * lobes, weighted by the power heuristic against the lobes' own sampling, times the share
      * of it that the shadow ray lets through; added to r, g, b.
      */
    private def nextEvent(
        x: Int,
        y: Int,
        j: Int,
        base: Int,
        hit: Hit,
        normal: Vec3,
        wi: Vec3,
        bsdf: Bsdf,
        tr: Double,
        tg: Double,
        tb: Double
    ): Unit =
      val choice = sampler.uniform(x, y, j, base)
      val at     = sampler.pair(x, y, j, base + 1)
      val light  = emitters.sample(hit.point, choice, Sampler.first(at), Sampler.second(at))
      if !light.dark then
        val f = bsdf.evaluate(normal, wi, light.direction)
        if f.max > 0 then
          // The shadow ray starts off the face's own plane, on the side it leaves by; it stops
          // short of a glowing shape's point so as not to meet that shape itself.
          val side =
            if light.direction.dot(hit.normal) >= 0 then Shading.Epsilon else -Shading.Epsilon
          val from  = hit.point + hit.normal * side
          val reach =
            if light.density == 0 || light.distance.isInfinite then light.distance
            else light.distance - 2 * Shading.Epsilon
          val share = visibility.along(from, light.direction, reach)
          if share > 0 then
            val w =
              if light.density == 0 then share
              else share * powerHeuristic(light.density, bsdf.density(normal, wi, light.direction))
            r += tr * f.r * light.value.r * w
            g += tg * f.g * light.value.g * w
            b += tb * f.b * light.value.b * w
