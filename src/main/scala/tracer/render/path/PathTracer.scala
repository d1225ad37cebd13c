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
  * @param strategy   how lights found both ways are counted: the power heuristic (always, but
  *   for tests), or by one of the two ways alone
  */
final class PathTracer(
    scene: Scene,
    private[path] val world: World,
    private[path] val projection: Projection,
    settings: Integrator.Path,
    private[path] val depth: Int,
    strategy: PathTracer.Strategy = PathTracer.Strategy.Both
):
  private[path] val emitters = Emitters(scene, world)
  private[path] val sampler  = Sampler(settings.sampler, settings.seed, settings.samples)
  private val samples        = settings.samples

  // True when shadow rays must walk through clear surfaces.
  private[path] val clear = Visibility.anyClear(scene)

  // The scattering function of every shape whose surface is the same at every point (one plain
  // colour, no surfaces per leaf), made once.
  private[path] val bsdfs: IArray[Option[Bsdf]] = IArray.from(scene.objects.map { o =>
    o.surface.pigment match
      case Pigment.Solid(c) if o.leafSurfaces.isEmpty => Some(Bsdf.of(o.surface, c, o.surface.ior))
      case _                                          => None
  })

  /** A tracer for one row task: it keeps scratch space, so no two threads share one. */
  def task(): PathTracer.Task = PathTracer.Task(this)

  /** The sampled emitters (for tests). */
  def lights: Emitters = emitters

  /** The weight of light found by a path after a smooth bounce of density `path`, where
    * next-event estimation would draw it with density `light` (> 0).
    */
  private[path] def pathWeight(path: Double, light: Double): Double = strategy match
    case PathTracer.Strategy.Both       => PathTracer.powerHeuristic(path, light)
    case PathTracer.Strategy.LightsOnly => 0.0
    case PathTracer.Strategy.PathsOnly  => 1.0

  /** The weight of light found by next-event estimation with density `light` (> 0), where a
    * bounce would draw it with density `path`.
    */
  private[path] def lightWeight(light: Double, path: Double): Double = strategy match
    case PathTracer.Strategy.Both       => PathTracer.powerHeuristic(light, path)
    case PathTracer.Strategy.LightsOnly => 1.0
    case PathTracer.Strategy.PathsOnly  => 0.0

  /** Pixel (x, y) of the whole picture: the mean of its N samples, as they are. */
  private def pixel(task: PathTracer.Task, x: Int, y: Int): Colour =
    // Perf: the sum in three locals, no Colour per sample kept.
    var r  = 0.0
    var g  = 0.0
    var b  = 0.0
    val at = sampler.pixel(x, y)
    var j  = 0
    while j < samples do
      task.trace(x, y, at, j)
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

  /** How light that both next-event estimation and the paths can find is counted. */
  enum Strategy:
    /** Both ways, weighted by the power heuristic: the renderer's way. */
    case Both

    /** Next-event estimation alone (the paths find only what it cannot: point lights aside,
      * light after a mirror or glass, glowing planes, solids and combinations).
      */
    case LightsOnly

    /** The paths alone (next-event estimation only for point lights, which no path can find). */
    case PathsOnly

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
    private val visibility = Visibility(world, query, tracer.clear)
    // Why: the last path's radiance, read by the pixel loop (see the class's Perf note).
    private[path] var r = 0.0
    private[path] var g = 0.0
    private[path] var b = 0.0

    /** Pixel (x, y) of the whole picture: the mean of its N samples, as they are. */
    def pixel(x: Int, y: Int): Colour = tracer.pixel(this, x, y)

    /** Sample j of pixel (x, y), whose sampler hash is `at`: the radiance one path brings back,
      * left in r, g, b.
      */
    private[path] def trace(x: Int, y: Int, at: Long, j: Int): Unit =
      val offset = sampler.pairAt(at, j, 0)
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
              tracer.pathWeight(lastDensity, emitters.skyDensity)
            else 1.0
          r += tr * sky.r * w
          g += tg * sky.g * w
          b += tb * sky.b * w
          going = false
        else
          val shape   = world.shape(i)
          val hit     = world.hitAt(i, ray, query)
          val surface = world.surface(i, hit.leaf)
          if hit.front && surface.emits then
            val e     = surface.emission
            val light =
              if lastDensity > 0 then emitters.density(i, lastPoint, hit.point, hit.leaf) else 0.0
            val w = if light > 0 then tracer.pathWeight(lastDensity, light) else 1.0
            r += tr * e.r * w
            g += tg * e.g * w
            b += tb * e.b * w
          val bsdf = tracer.bsdfs(i) match
            case Some(fixed) => fixed
            case None        => Bsdf.of(surface, tracer.pigment(i, hit), world.surface(i).ior)
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
              nextEvent(at, j, base, hit, normal, wi, bsdf, tr, tg, tb)
            val uv      = sampler.pairAt(at, j, base + 4)
            val fresnel = if bsdf.glass then sampler.uniformAt(at, j, base + 7) else 0.0
            val choice  = sampler.uniformAt(at, j, base + 3)
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
                lastPoint = ray.origin
                val most = Math.max(tr, Math.max(tg, tb))
                if most <= 0 then going = false
                else if bounces >= RouletteDepth then
                  val survive = Math.min(most * eta * eta, MostSurvival)
                  if sampler.uniformAt(at, j, base + 6) >= survive then going = false
                  else
                    tr /= survive
                    tg /= survive
                    tb /= survive

    /** Next-event estimation at a bounce: one emitter sampled, its light through the smooth
      * lobes, weighted by the power heuristic against the lobes' own sampling, times the share
      * of it that the shadow ray lets through; added to r, g, b.
      */
    private def nextEvent(
        at: Long,
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
      val choice = sampler.uniformAt(at, j, base)
      val point  = sampler.pairAt(at, j, base + 1)
      // The smooth lobes reflect on the path's side only: the light is sought from S0, just off
      // the face's own plane on that side (as Whitted's shadow rays, so that a point light gives
      // exactly Whitted's direct light), and the shadow ray stops short of a glowing shape's
      // point so as not to meet that shape itself.
      val from  = hit.point + hit.normal * Shading.Epsilon
      val light = emitters.sample(from, choice, Sampler.first(point), Sampler.second(point))
      if !light.dark then
        val f = bsdf.evaluate(normal, wi, light.direction)
        if f.max > 0 then
          val reach =
            if light.density == 0 || light.distance.isInfinite then light.distance
            else light.distance - 2 * Shading.Epsilon
          val share = visibility.along(from, light.direction, reach)
          if share > 0 then
            val w =
              if light.density == 0 then share
              else
                share * tracer.lightWeight(light.density, bsdf.density(normal, wi, light.direction))
            r += tr * f.r * light.value.r * w
            g += tg * f.g * light.value.g * w
            b += tb * f.b * light.value.b * w
