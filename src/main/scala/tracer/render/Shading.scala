package tracer.render

import tracer.geometry.{Hit, Ray, Shape}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.Pigment

/** The colour a ray brings back from the world (rendering.md, Colour of a hit).
  *
  * Not thread-safe: it keeps scratch space for its queries, so each render task makes its own.
  */
final class Shading(world: World, mode: ShadingMode):
  private val stack = world.newStack()

  /** The colour seen along `ray`, allowing `depth` more reflections. */
  def colour(ray: Ray, depth: Int): Colour =
    val i = world.nearest(ray, stack)
    if i < 0 then world.background
    else
      val shape = world.shape(i)
      val hit   = Shape.hitAt(shape, ray, Shape.distance(shape, ray))
      mode match
        case ShadingMode.Quick => pigment(i, hit) * Math.abs(hit.normal.dot(ray.direction))
        case ShadingMode.Full  =>
          // Equations 40 and 43: shadow and reflected rays start just off the surface, on the
          // side the ray came from.
          val s0 = hit.point + hit.normal * Shading.Epsilon
          lit(i, hit, s0) + reflected(i, hit, s0, ray, depth)

  /** The sum over the lights visible from S0 of C ⊙ colour(L) · diffuse · |rn · Sd|.
    *
    * Perf: `lit` and `reflected` are inline, so the hit's values stay in one compiled method and
    * fewer of them escape to the heap (RenderBench: 11.0 → 9.5 MB a frame; docs/performance.md, step 9).
    */
  private inline def lit(i: Int, hit: Hit, s0: Vec3): Colour =
    val surface = world.surface(i)
    val colour  = pigment(i, hit)
    // Perf: a while loop summing channels in locals: no Colour or closure per light
    // (RenderBench.few: see docs/performance.md, step 2).
    var r = 0.0
    var g = 0.0
    var b = 0.0
    var k = 0
    while k < world.lights.length do
      val light   = world.lights(k)
      val toLight = light.location - s0
      val reach   = toLight.length
      // Equation 41; a light exactly at S0 shines straight along the normal.
      val sd = if reach > 0 then toLight / reach else hit.normal
      if !world.occluded(Ray(s0, sd), reach, stack) then
        val cos = Math.abs(hit.normal.dot(sd))
        r += colour.r * light.colour.r * surface.diffuse * cos
        g += colour.g * light.colour.g * surface.diffuse * cos
        b += colour.b * light.colour.b * surface.diffuse * cos
      k += 1
    Colour(r, g, b)

  /** reflection · colour(reflected ray, depth − 1), or black when the surface is no mirror or the
    * depth is spent (equations 43–44).
    */
  private inline def reflected(i: Int, hit: Hit, s0: Vec3, ray: Ray, depth: Int): Colour =
    val reflection = world.surface(i).reflection
    if reflection <= 0 || depth <= 0 then Colour.Black
    else
      val direction = ray.direction - hit.normal * (2 * hit.normal.dot(ray.direction))
      colour(Ray(s0, direction), depth - 1) * reflection

  /** The surface colour C at the hit: the texel there, or the plain colour. */
  private def pigment(i: Int, hit: Hit): Colour = world.surface(i).pigment match
    case Pigment.Solid(c)          => c
    case Pigment.Textured(texture) =>
      val uv = Shape.surfaceCoordinates(world.shape(i), hit.point)
      texture.colourAt(uv.u, uv.v)

/** Constants of the shading model. */
object Shading:
  /** ε, the offset of shadow and reflected ray origins from the surface (world units). */
  val Epsilon: Double = 1e-4
