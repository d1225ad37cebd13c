package tracer.render

import tracer.geometry.{Hit, Ray, Shape}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.{Pigment, Surface}

/** The colour a ray brings back from the world (docs/rendering.md, Colour of a hit): the course's
  * Whitted model, with version 2's highlights, transmission and area lights as POV-Ray 3.7 adds
  * them. A surface without version 2 attributes shades exactly as version 1.
  *
  * Not thread-safe: it keeps scratch space for its queries, so each render task makes its own.
  */
final class Shading(world: World, mode: ShadingMode):
  private val query   = world.newQuery()
  private val shadows = Shadows(world, query)

  /** The colour seen along `ray`, allowing `depth` more reflections or refractions. */
  def colour(ray: Ray, depth: Int): Colour = trace(ray, depth, Nil)

  /** The colour seen along `ray` from inside the objects `insides` (innermost first). */
  private def trace(ray: Ray, depth: Int, insides: List[Int]): Colour =
    val i = world.nearest(ray, query)
    if i < 0 then world.background
    else
      val shape  = world.shape(i)
      val hit    = world.hitAt(i, ray, query)
      val normal = Shape.shadingNormal(shape, hit, ray)
      mode match
        case ShadingMode.Quick => pigment(i, hit) * Math.abs(normal.dot(ray.direction))
        case ShadingMode.Full  =>
          // Equations 40 and 43: shadow and reflected rays start just off the surface, on the
          // side the ray came from (the geometric side, even where a smooth normal leans).
          val s0      = hit.point + hit.normal * Shading.Epsilon
          val surface = world.surface(i, hit.leaf)
          val shaded  =
            lit(surface, pigment(i, hit), normal, normal != hit.normal, s0, hit.point, ray) +
              beyond(i, surface, hit, normal, s0, ray, depth, insides)
          // Version 4: a glowing surface adds its emission where it is seen from the side it
          // emits from (its outward side), after shading; it lights nothing else.
          if surface.emits && hit.front then shaded + surface.emission else shaded

  /** The light the surface sends back from every light that reaches S0: diffuse
    * C ⊙ colour(L) · diffuse · (1 − transmit) · |rn · Sd| and white highlights colour(L) ·
    * (phong + specular terms), each light scaled by the share of it that reaches S0 and by its
    * fade A(d) (version 4), d the distance from the hit `point` to the light (an area light's
    * centre), as POV-Ray measures it.
    *
    * `leaning` says that `normal` is a smooth mesh's interpolated normal, not the face's own.
    *
    * Perf: inline, with the channels summed in locals: no Colour or closure per light, and the
    * hit's values stay in one compiled method (RenderBench; docs/performance.md, steps 2 and 9).
    */
  private inline def lit(
      surface: Surface,
      colour: Colour,
      normal: Vec3,
      leaning: Boolean,
      s0: Vec3,
      point: Vec3,
      ray: Ray
  ) =
    val diffuse  = surface.diffuse * (1 - surface.transmit)
    val oneSided = leaning || surface.transmit > 0
    var r        = 0.0
    var g        = 0.0
    var b        = 0.0
    var k        = 0
    while k < world.lights.length do
      val light   = world.lights(k)
      val toLight = light.location - s0
      val reach   = toLight.length
      // Equation 41; a light exactly at S0 shines straight along the normal.
      val sd  = if reach > 0 then toLight / reach else normal
      val cos = normal.dot(sd)
      // POV-Ray ignores a light behind the shading normal. A flat opaque surface shadows such a
      // point light by itself; transmitting surfaces, smooth normals and area lights (lit from
      // off-centre sub-lights) need the rule said out loud.
      val behind = cos < Shading.FarSide && (oneSided || light.area.isDefined)
      if !behind then
        val share = light.area match
          case None       => shadows.point(s0, sd, reach)
          case Some(area) => shadows.area(s0, light.location, area)
        if share > 0 then
          // Without fade the share is used as it is (the same bits as before version 4).
          val reaching =
            if light.fade.isEmpty then share
            else share * light.attenuation((light.location - point).length)
          val lr     = light.colour.r * reaching
          val lg     = light.colour.g * reaching
          val lb     = light.colour.b * reaching
          val facing = Math.abs(cos)
          r += colour.r * lr * diffuse * facing
          g += colour.g * lg * diffuse * facing
          b += colour.b * lb * diffuse * facing
          if surface.highlighted && cos >= Shading.FarSide then
            val h = Shading.highlight(surface, normal, ray.direction, sd)
            r += lr * h
            g += lg * h
            b += lb * h
      k += 1
    Colour(r, g, b)

  /** What the surface passes on from further rays: the mirror image, and through a transmitting
    * surface the light from behind it (or, past the critical angle, the internal reflection).
    */
  private inline def beyond(
      i: Int,
      surface: Surface,
      hit: Hit,
      normal: Vec3,
      s0: Vec3,
      ray: Ray,
      depth: Int,
      insides: List[Int]
  ): Colour =
    if depth <= 0 then Colour.Black
    else if surface.transmit <= 0 then mirror(surface.reflection, normal, s0, ray, depth, insides)
    else transmitted(i, surface, hit, normal, s0, ray, depth, insides)

  /** reflection · colour(reflected ray, depth − 1) (equations 43–44), black for no mirror. */
  private def mirror(
      reflection: Double,
      normal: Vec3,
      s0: Vec3,
      ray: Ray,
      depth: Int,
      insides: List[Int]
  ): Colour =
    if reflection <= 0 then Colour.Black
    else trace(Ray(s0, Refraction.reflect(ray.direction, normal)), depth - 1, insides) * reflection

  /** transmit · colour(ray through the surface) + the mirror term; the ray goes straight on where
    * the indices match (not counted against the depth, as POV-Ray continues such rays), and is
    * bent by Heckbert's formula where they differ. Past the critical angle the internal
    * reflection is added whole, in place of the transmitted and the mirror terms (POV-Ray).
    */
  private def transmitted(
      i: Int,
      surface: Surface,
      hit: Hit,
      normal: Vec3,
      s0: Vec3,
      ray: Ray,
      depth: Int,
      insides: List[Int]
  ): Colour =
    val (eta, beyondInsides) = Refraction.cross(insides, i, world.surface(_).ior)
    val behind               = hit.point - hit.normal * Shading.Epsilon
    def through(direction: Vec3, depthBeyond: Int) =
      trace(Ray(behind, direction), depthBeyond, beyondInsides) * surface.transmit +
        mirror(surface.reflection, normal, s0, ray, depth, insides)
    if Math.abs(eta - 1) < Refraction.SameIndex then through(ray.direction, depth)
    else
      Refraction.refract(ray.direction, normal, eta) match
        case Some(direction) => through(direction, depth - 1)
        case None            =>
          trace(Ray(s0, Refraction.reflect(ray.direction, normal)), depth - 1, insides)

  /** The surface colour C at the hit: the texel or checker cell there, or the plain colour. */
  private def pigment(i: Int, hit: Hit): Colour = world.surface(i, hit.leaf).pigment match
    case Pigment.Solid(c)          => c
    case Pigment.Textured(texture) =>
      val uv = Shape.surfaceCoordinates(world.shape(i), hit.point, hit.leaf)
      texture.colourAt(uv.u, uv.v)
    case checker: Pigment.Checker => Pigment.checkerColour(checker, hit.point)

/** Constants and pure terms of the shading model. */
object Shading:
  /** ε, the offset of shadow and reflected ray origins from the surface (world units). */
  val Epsilon: Double = 1e-4

  /** rn · Sd below this puts a light behind the surface (POV-Ray's EPSILON). */
  val FarSide: Double = 1e-10

  /** The highlight a light in unit direction `toLight` puts on a surface with unit normal
    * `normal` (facing the viewer) seen along unit `direction`, per unit of light colour:
    * phong · (R · Sd)^phong-size with R the mirror direction of the view (POV-Ray keeps it only
    * above 0.0008 when phong-size ≥ 60), plus specular · (rn · H)^(1/roughness) with H the
    * half-way vector between the light and the eye (POV-Ray's `ComputePhongColour` and
    * `ComputeSpecularColour`).
    */
  def highlight(surface: Surface, normal: Vec3, direction: Vec3, toLight: Vec3): Double =
    val phong =
      if surface.phong <= 0 then 0.0
      else
        val cos = Refraction.reflect(direction, normal).dot(toLight)
        if cos > 0 && (surface.phongSize < 60 || cos > 0.0008) then
          surface.phong * Math.pow(cos, surface.phongSize)
        else 0.0
    val specular =
      if surface.specular <= 0 then 0.0
      else
        val halfway = (toLight - direction) * 0.5
        val length  = halfway.length
        val cos     = if length > 0 then halfway.dot(normal) / length else 0.0
        if cos > 0 then surface.specular * Math.pow(cos, 1 / surface.roughness) else 0.0
    phong + specular
