package tracer.render.path

import tracer.geometry.Shape
import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.{Hits, Integrator, Projection, Shading, World}
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
  // Perf: a plain array (a generic IArray's element is read through ScalaRunTime.array_apply).
  private[path] val bsdfs: Array[Option[Bsdf]] = Array.from(scene.objects.map { o =>
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

  /** The surface colour C at `point` on leaf `leaf` of shape i: the texel or checker cell there,
    * or the plain colour.
    */
  private[path] def pigment(i: Int, point: Vec3, leaf: Int): Colour =
    world.surface(i, leaf).pigment match
      case Pigment.Solid(c)          => c
      case Pigment.Textured(texture) =>
        val uv = Shape.surfaceCoordinates(world.shape(i), point, leaf)
        texture.colourAt(uv.u, uv.v)
      case checker: Pigment.Checker => Pigment.checkerColour(checker, point)

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
      * light after a mirror or glass, glowing planes, tori and combinations).
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
    private val scratch    = Scratch()
    // Why: the last path's radiance, read by the pixel loop (see the class's Perf note).
    private[path] var r = 0.0
    private[path] var g = 0.0
    private[path] var b = 0.0

    /** Pixel (x, y) of the whole picture: the mean of its N samples, as they are. */
    def pixel(x: Int, y: Int): Colour = tracer.pixel(this, x, y)

    /** Sample j of pixel (x, y), whose sampler hash is `at`: the radiance one path brings back,
      * left in r, g, b.
      *
      * Perf: the ray, the hit and the throughput in local doubles, the scattering and the light
      * samples in the task's [[Scratch]]: no Ray, Hit, vector, colour or sample per vertex
      * (PathBench: 104 MB a frame before). The arithmetic is Shape.hitAt's, Bsdf's and
      * Emitters' own, in the same order, so the pictures are the same bytes.
      */
    private[path] def trace(x: Int, y: Int, at: Long, j: Int): Unit =
      val offset = sampler.pairAt(at, j, 0)
      val camera =
        tracer.projection.ray(x + Sampler.first(offset), y + Sampler.second(offset))
      val out = scratch
      // The ray.
      var ox = camera.origin.x
      var oy = camera.origin.y
      var oz = camera.origin.z
      var dx = camera.direction.x
      var dy = camera.direction.y
      var dz = camera.direction.z
      // The throughput, what the path has gathered, and its state.
      var tr          = 1.0
      var tg          = 1.0
      var tb          = 1.0
      var eta         = 1.0 // the product of the index ratios crossed, for Russian roulette
      var bounces     = 0
      var vertex      = 0   // every surface met, clear passes included: which dimensions to use
      var lastDensity = 0.0 // the last bounce's direction density; 0 after the camera or a delta
      var lx          = ox  // the last bounce's point
      var ly          = oy
      var lz          = oz
      var going       = true
      r = 0; g = 0; b = 0
      while going do
        val i = world.nearestAlong(ox, oy, oz, dx, dy, dz, Double.PositiveInfinity, query)
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
          // The hit as Shape.hitAt and Shape.shadingNormal give it (a mesh's on the face the query
          // found), written into the query's fields and read out at once: no Ray or Hit a vertex.
          Hits.record(
            world.shape(i),
            ox,
            oy,
            oz,
            dx,
            dy,
            dz,
            query.distance,
            query,
            world.treeOf(i)
          )
          val px      = query.px
          val py      = query.py
          val pz      = query.pz
          val nx      = query.nx // the normal facing the ray
          val ny      = query.ny
          val nz      = query.nz
          val sx      = query.sx // the shading normal
          val sy      = query.sy
          val sz      = query.sz
          val front   = query.front
          val leaf    = query.leaf
          val surface = world.surface(i, leaf)
          if front && surface.emits then
            val e     = surface.emission
            val light =
              if lastDensity > 0 then
                emitters.densityAt(i, lx, ly, lz, px, py, pz, leaf, nx, ny, nz)
              else 0.0
            val w = if light > 0 then tracer.pathWeight(lastDensity, light) else 1.0
            r += tr * e.r * w
            g += tg * e.g * w
            b += tb * e.b * w
          val bsdf = tracer.bsdfs(i) match
            case Some(fixed) => fixed
            case None        =>
              Bsdf.of(surface, tracer.pigment(i, Vec3(px, py, pz), leaf), world.surface(i).ior)
          val base = 2 + Sampler.Dimensions * vertex
          vertex += 1
          if bounces >= tracer.depth then
            // No bounce is left, but a clear surface still lets the path through unbent.
            if bsdf.clear then
              tr *= bsdf.transmit
              tg *= bsdf.transmit
              tb *= bsdf.transmit
              ox = px - nx * Shading.Epsilon
              oy = py - ny * Shading.Epsilon
              oz = pz - nz * Shading.Epsilon
            else going = false
          else
            val ix = -dx
            val iy = -dy
            val iz = -dz
            if bsdf.smooth && !emitters.isEmpty then
              nextEvent(
                at,
                j,
                base,
                px,
                py,
                pz,
                nx,
                ny,
                nz,
                sx,
                sy,
                sz,
                ix,
                iy,
                iz,
                bsdf,
                tr,
                tg,
                tb
              )
            val uv      = sampler.pairAt(at, j, base + 4)
            val fresnel = if bsdf.glass then sampler.uniformAt(at, j, base + 7) else 0.0
            val choice  = sampler.uniformAt(at, j, base + 3)
            bsdf.sampleInto(
              out,
              sx,
              sy,
              sz,
              ix,
              iy,
              iz,
              front,
              choice,
              Sampler.first(uv),
              Sampler.second(uv),
              fresnel
            )
            if out.absorbed then going = false
            else
              tr *= out.wr
              tg *= out.wg
              tb *= out.wb
              // The new ray starts off the face's own plane on the side it goes to, as Mitsuba's
              // spawn_ray does: on a smooth mesh a bounce about the shading normal may go behind
              // the face's plane, and passes it (on a flat face, the side a reflection stays on).
              val side = Shading.sideToward(nx, ny, nz, out.sx, out.sy, out.sz)
              ox = px + nx * side
              oy = py + ny * side
              oz = pz + nz * side
              dx = out.sx
              dy = out.sy
              dz = out.sz
              if out.bounce then
                bounces += 1
                eta *= out.eta
                lastDensity = out.density
                lx = ox; ly = oy; lz = oz
                val most = Math.max(tr, Math.max(tg, tb))
                if most <= 0 then going = false
                else if bounces >= RouletteDepth then
                  val survive = Math.min(most * eta * eta, MostSurvival)
                  if sampler.uniformAt(at, j, base + 6) >= survive then going = false
                  else
                    tr /= survive
                    tg /= survive
                    tb /= survive

    /** Next-event estimation at a bounce at p (geometric normal n, shading normal s, ωi): one
      * emitter sampled, its light through the smooth lobes, weighted by the power heuristic
      * against the lobes' own sampling, times the share of it that the shadow ray lets through;
      * added to r, g, b.
      */
    private def nextEvent(
        at: Long,
        j: Int,
        base: Int,
        px: Double,
        py: Double,
        pz: Double,
        nx: Double,
        ny: Double,
        nz: Double,
        sx: Double,
        sy: Double,
        sz: Double,
        ix: Double,
        iy: Double,
        iz: Double,
        bsdf: Bsdf,
        tr: Double,
        tg: Double,
        tb: Double
    ): Unit =
      val out    = scratch
      val choice = sampler.uniformAt(at, j, base)
      val point  = sampler.pairAt(at, j, base + 1)
      // The smooth lobes reflect on the path's side only: the light is sought from S0, just off
      // the face's own plane on that side (as Whitted's shadow rays, so that a point light gives
      // exactly Whitted's direct light), and the shadow ray stops short of a glowing shape's
      // point so as not to meet that shape itself. A light behind the face's plane (which a
      // smooth mesh's shading normal may still see) is sought through the face: its shadow ray
      // starts just off the plane on the far side, as Mitsuba's spawn_ray_to.
      val fx = px + nx * Shading.Epsilon
      val fy = py + ny * Shading.Epsilon
      val fz = pz + nz * Shading.Epsilon
      emitters.sampleInto(
        out,
        fx,
        fy,
        fz,
        choice,
        Sampler.first(point),
        Sampler.second(point),
        px,
        py,
        pz
      )
      if !out.isDark then
        bsdf.evaluateInto(out, sx, sy, sz, ix, iy, iz, out.lx, out.ly, out.lz)
        if Math.max(out.fr, Math.max(out.fg, out.fb)) > 0 then
          val density = out.lightDensity
          val reach   =
            if density == 0 || java.lang.Double.isInfinite(out.distance) then out.distance
            else out.distance - 2 * Shading.Epsilon
          val side  = Shading.sideToward(nx, ny, nz, out.lx, out.ly, out.lz)
          val share =
            if side > 0 then visibility.alongFrom(fx, fy, fz, out.lx, out.ly, out.lz, reach)
            else beyond(px + nx * side, py + ny * side, pz + nz * side, fx, fy, fz, density)
          if share > 0 then
            val w =
              if density == 0 then share
              else
                share * tracer.lightWeight(
                  density,
                  bsdf.densityAt(sx, sy, sz, ix, iy, iz, out.lx, out.ly, out.lz)
                )
            r += tr * out.fr * out.lr * w
            g += tg * out.fg * out.lg * w
            b += tb * out.fb * out.lb * w

    /** The share of the light just sampled into `scratch` from S0 = (fx, fy, fz) that reaches a
      * shadow ray starting at o = (ox, oy, oz) beyond the face: aimed from o at the sampled
      * point itself (S0 + l·distance), as Mitsuba's `spawn_ray_to`, and stopping 2ε short of it
      * on a glowing shape (`density` > 0). Aimed along S0's direction from 2ε away, a ray
      * grazing a glowing ball met the ball before the reach (a smooth quad lit from behind its
      * plane lost 26% of its light). A light at infinity keeps its direction.
      */
    private def beyond(
        ox: Double,
        oy: Double,
        oz: Double,
        fx: Double,
        fy: Double,
        fz: Double,
        density: Double
    ): Double =
      val out = scratch
      if java.lang.Double.isInfinite(out.distance) then
        visibility.alongFrom(ox, oy, oz, out.lx, out.ly, out.lz, out.distance)
      else
        val tx   = fx + out.lx * out.distance - ox
        val ty   = fy + out.ly * out.distance - oy
        val tz   = fz + out.lz * out.distance - oz
        val span = Math.sqrt(tx * tx + ty * ty + tz * tz)
        // Why 1: nothing lies within 2ε of the sampled point on the far side of the face.
        if !(span > 2 * Shading.Epsilon) then 1.0
        else
          val reach = if density == 0 then span else span - 2 * Shading.Epsilon
          visibility.alongFrom(ox, oy, oz, tx / span, ty / span, tz / span, reach)
