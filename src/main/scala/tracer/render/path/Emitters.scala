package tracer.render.path

import tracer.geometry.{Mesh, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.World
import tracer.scene.{Light, Scene}

/** A light found by next-event estimation: where it is seen from a point, and what it gives.
  *
  * @param direction the unit direction from the point towards the light
  * @param distance  how far the light is along it (+∞ for the sky)
  * @param value     the radiance arriving, over the density of having drawn it (emitter choice
  *   included); for a point light, π·C·A(d) over the chance of choosing it, so that f·|cos θ|
  *   times this is the light's share of the estimate
  * @param density   the density per unit solid angle of having drawn this direction, emitter
  *   choice included, for multiple importance sampling; 0 for a point light (a delta)
  */
final case class LightSample(direction: Vec3, distance: Double, value: Colour, density: Double):
  /** True when the sample carries no light (a light behind its own face, a point inside a ball). */
  def dark: Boolean = value.max <= 0

/** The [[LightSample]] of no light at all. */
object LightSample:
  /** Nothing to light the point with. */
  val Dark: LightSample = LightSample(Vec3.UnitZ, 0, Colour.Black, 0)

/** One light that next-event estimation samples. */
enum Emitter:
  /** A point light, or an area light as its grid of sub-lights (version 4: each a point light of
    * colour C / (NA·NB) with the light's fade).
    */
  case Points(light: Light, positions: IArray[Vec3])

  /** A glowing sphere (shape `index` of the world), drawn by the solid angle it fills. */
  case Ball(index: Int, sphere: Sphere, emission: Colour)

  /** A glowing triangle (shape `index`, or a face of the mesh that is), drawn uniformly by area. */
  case Face(index: Int, triangle: Triangle, emission: Colour, area: Double)

  /** The background, radiance B from every direction no surface blocks, drawn uniformly over
    * the sphere of directions.
    */
  case Sky(radiance: Colour)

/** The emitters of a scene that next-event estimation samples: its point and area lights, its
  * glowing spheres, triangles and meshes' faces (top-level shapes, not inside a placement or a
  * combination; each face of a mesh an emitter of its own, as when each was a triangle), and
  * the sky when the background is not black. Each is chosen with the same chance 1/count. Glowing
  * planes, solids and combinations are found by the paths alone.
  *
  * @param world `scene` compiled: its lights' sub-lights are the world's
  */
final class Emitters(scene: Scene, world: World):

  /** Every sampled emitter, lights first, then glowing shapes in document order, then the sky. */
  val all: IArray[Emitter] =
    // Each light's sub-lights as the world computed them once (a point light: its location).
    val lights = world.lights.indices.map(k =>
      Emitter.Points(world.lights(k), IArray.from(world.subLightPositions(k)))
    )
    val shapes = scene.objects.zipWithIndex.collect {
      case (o, i) if o.leafSurfaces.isEmpty && o.surface.emits =>
        o.shape match
          case s: Sphere   => Vector(Emitter.Ball(i, s, o.surface.emission))
          case t: Triangle => Vector(face(i, t, o.surface.emission))
          case m: Mesh     => m.faces.map(face(i, _, o.surface.emission)).toVector
          case _           => Vector.empty
    }.flatten
    val sky = Option.when(scene.background.max > 0)(Emitter.Sky(scene.background))
    IArray.from(lights ++ shapes ++ sky)

  private val count = all.length

  // The emitter of each world shape that has one (a mesh: of its first face), −1 for the others.
  private val ofShape: Array[Int] =
    val slots = Array.fill(scene.objects.size)(-1)
    all.indices.reverse.foreach(k =>
      all(k) match
        case Emitter.Ball(i, _, _)    => slots(i) = k
        case Emitter.Face(i, _, _, _) => slots(i) = k
        case _                        => ()
    )
    slots

  private def face(i: Int, t: Triangle, emission: tracer.image.Colour): Emitter =
    Emitter.Face(i, t, emission, t.a.cross(t.b).length / 2)

  /** True when there is nothing to sample. */
  def isEmpty: Boolean = count == 0

  /** The chance-weighted density per unit solid angle with which [[sample]] from `from` draws
    * the sky's direction: 1 / (4π·count), or 0 when the sky is not sampled.
    */
  val skyDensity: Double =
    if all.exists { case _: Emitter.Sky => true; case _ => false } then 1 / (4 * Math.PI * count)
    else 0.0

  /** True when shape `i` of the world is a sampled emitter. */
  def samples(i: Int): Boolean = ofShape(i) >= 0

  /** The density per unit solid angle with which [[sample]] from `from` draws `point` on the
    * emitting front of shape `i` (choice included), 0 when it cannot; `leaf` is the hit's, which
    * on a mesh names the face.
    */
  def density(i: Int, from: Vec3, point: Vec3, leaf: Int = 0): Double =
    if ofShape(i) < 0 then 0.0
    else
      // A sphere's and a triangle's hits are on leaf 0; a mesh's faces follow its first in order.
      all(ofShape(i) + leaf) match
        case Emitter.Ball(_, sphere, _)  => Emitters.coneDensity(sphere, from) / count
        case Emitter.Face(_, t, _, area) =>
          val w  = point - from
          val d2 = w.lengthSquared
          val c  = -w.dot(t.normal) / Math.sqrt(d2)
          if c <= 0 then 0.0 else d2 / (area * c) / count
        case _ => 0.0

  /** A light for the point `p`, chosen by `choice` among the emitters, with a point on it (or a
    * direction) from (u1, u2), each uniform in [0, 1).
    */
  def sample(p: Vec3, choice: Double, u1: Double, u2: Double): LightSample =
    val scaled = choice * count
    val k      = Math.min(count - 1, scaled.toInt)
    val rest   = scaled - k
    all(k) match
      case Emitter.Points(light, positions) =>
        val m       = positions.length
        val at      = positions(Math.min(m - 1, (rest * m).toInt))
        val toLight = at - p
        val d       = toLight.length
        if d <= 0 then LightSample.Dark
        else
          // Sub-light C/m, chosen with chance 1/m among the grid (MitsubaSuite, lambert).
          val scale = Math.PI * light.attenuation(d) * count
          LightSample(toLight / d, d, light.colour * scale, 0)
      case Emitter.Ball(_, sphere, emission)  => Emitters.ball(sphere, emission, p, u1, u2, count)
      case Emitter.Face(_, t, emission, area) =>
        val su = Math.sqrt(u1)
        val q  = t.t0 * (1 - su) + t.t1 * (su * (1 - u2)) + t.t2 * (su * u2)
        val w  = q - p
        val d2 = w.lengthSquared
        val d  = Math.sqrt(d2)
        if d <= 0 then LightSample.Dark
        else
          val direction = w / d
          val c         = -direction.dot(t.normal)
          if c <= 0 then LightSample.Dark
          else
            val pdf = d2 / (area * c) / count
            LightSample(direction, d, emission / pdf, pdf)
      case Emitter.Sky(radiance) =>
        val z   = 1 - 2 * u1
        val r   = Math.sqrt(Math.max(0.0, 1 - z * z))
        val phi = 2 * Math.PI * u2
        val pdf = 1 / (4 * Math.PI * count)
        LightSample(
          Vec3(r * StrictMath.cos(phi), r * StrictMath.sin(phi), z),
          Double.PositiveInfinity,
          radiance / pdf,
          pdf
        )

/** Sampling spheres by solid angle. */
object Emitters:
  /** The density per unit solid angle of a direction drawn uniformly from the cone of directions
    * in which `sphere` is seen from `from`: 1 / (2π(1 − cos θmax)); 0 from inside.
    */
  def coneDensity(sphere: Sphere, from: Vec3): Double =
    val d2 = (sphere.centre - from).lengthSquared
    if d2 <= sphere.radiusSquared then 0.0
    else 1 / (2 * Math.PI * capFraction(sphere.radiusSquared / d2))

  /** 1 − cos θmax for sin²θmax = `sin2`, without cancellation for small spheres. */
  private def capFraction(sin2: Double): Double = sin2 / (1 + Math.sqrt(Math.max(0.0, 1 - sin2)))

  /** A direction towards `sphere` drawn uniformly from its cone seen from `p`, and the light
    * from the point it meets (a sphere seen from outside shows only its emitting front).
    */
  private def ball(
      sphere: Sphere,
      emission: Colour,
      p: Vec3,
      u1: Double,
      u2: Double,
      count: Int
  ): LightSample =
    val wc = sphere.centre - p
    val d2 = wc.lengthSquared
    if d2 <= sphere.radiusSquared then LightSample.Dark
    else
      val dc        = Math.sqrt(d2)
      val cap       = capFraction(sphere.radiusSquared / d2)
      val cos       = 1 - u1 * cap
      val sin       = Math.sqrt(Math.max(0.0, 1 - cos * cos))
      val phi       = 2 * Math.PI * u2
      val axis      = wc / dc
      val (s, t)    = Bsdf.tangents(axis)
      val direction =
        (s * (sin * StrictMath.cos(phi)) + t * (sin * StrictMath.sin(phi)) + axis * cos)
          .normalisedOr(axis)
      val tca  = direction.dot(wc)
      val half = Math.sqrt(Math.max(0.0, sphere.radiusSquared - (d2 - tca * tca)))
      val pdf  = 1 / (2 * Math.PI * cap) / count
      LightSample(direction, tca - half, emission / pdf, pdf)
