package tracer.render

import tracer.geometry.{Ray, Shape}
import tracer.image.Colour
import tracer.math.{Pow, Vec3}
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
  // Perf: the colour of the last `trace`, left in three fields rather than returned as a Colour,
  // and the colours of a shaded point summed in local doubles (PrimaryRayBench: bytes per
  // primary ray; RenderBench).
  private var red   = 0.0
  private var green = 0.0
  private var blue  = 0.0
  // Perf: the shaded point's direction toward each light and its distance, four doubles a
  // light, filled by `lit` for all lights before any is used (see there).
  private val toward = new Array[Double](4 * world.lights.length)

  /** The colour seen along `ray`, allowing `depth` more reflections or refractions. */
  def colour(ray: Ray, depth: Int): Colour =
    val o = ray.origin
    val d = ray.direction
    trace(o.x, o.y, o.z, d.x, d.y, d.z, depth)
    Colour(red, green, blue)

  /** [[colour]] of the ray from (ox, oy, oz) in unit direction (dx, dy, dz), left in [[r]], [[g]]
    * and [[b]] (the renderer's path: no `Ray` or `Colour` is made); `insides` are the objects
    * that let light through around the ray's start, innermost first ([[World.containing]]:
    * empty unless the camera stands inside glass).
    */
  def trace(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int,
      insides: List[Int] = Nil
  ): Unit =
    traceFrom(ox, oy, oz, dx, dy, dz, depth, insides)

  /** The red channel of the last [[trace]]. */
  def r: Double = red

  /** The green channel of the last [[trace]]. */
  def g: Double = green

  /** The blue channel of the last [[trace]]. */
  def b: Double = blue

  /** The colour seen along the ray from o in direction d from inside the objects `insides`
    * (innermost first), left in red, green and blue.
    */
  private def traceFrom(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int,
      insides: List[Int]
  ): Unit =
    val i = world.nearestAlong(ox, oy, oz, dx, dy, dz, Double.PositiveInfinity, query)
    if i < 0 then set(world.background)
    else
      // The hit as Shape.hitAt and Shape.shadingNormal give it, in the query's fields.
      Hits.record(world.shape(i), ox, oy, oz, dx, dy, dz, query.distance, query, world.treeOf(i))
      mode match
        case ShadingMode.Quick => quick(i, dx, dy, dz)
        case ShadingMode.Full  => shade(i, dx, dy, dz, depth, insides)

  /** Quick mode's colour of the hit the query holds on shape `i`: its surface colour C scaled by
    * |s · d|, left in red, green and blue.
    */
  private def quick(i: Int, dx: Double, dy: Double, dz: Double): Unit =
    val c = pigment(i, query.leaf, query.px, query.py, query.pz)
    val a = Math.abs(query.sx * dx + query.sy * dy + query.sz * dz)
    red = c.r * a
    green = c.g * a
    blue = c.b * a

  /** The full colour of the hit the query holds on shape `i`, seen along direction d. */
  private def shade(
      i: Int,
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int,
      insides: List[Int]
  ): Unit =
    // The hit, copied out of the query: shadow rays and further rays reuse it.
    val px    = query.px
    val py    = query.py
    val pz    = query.pz
    val nx    = query.nx
    val ny    = query.ny
    val nz    = query.nz
    val sx    = query.sx
    val sy    = query.sy
    val sz    = query.sz
    val leaf  = query.leaf
    val face  = query.face
    val front = query.front
    // Equation 40: shadow rays start just off the surface, on the side the ray came from (the
    // geometric side, even where a smooth normal leans); reflected rays, from the same point
    // unless they leave behind the face's plane (reflected).
    val s0x     = px + nx * Shading.Epsilon
    val s0y     = py + ny * Shading.Epsilon
    val s0z     = pz + nz * Shading.Epsilon
    val surface = world.surface(i, leaf)
    val leaning = sx != nx || sy != ny || sz != nz
    lit(i, face, surface, pigment(i, leaf, px, py, pz), sx, sy, sz, leaning, s0x, s0y, s0z)(
      px,
      py,
      pz,
      nx,
      ny,
      nz
    )(dx, dy, dz, depth)
    val litR = red
    val litG = green
    val litB = blue
    if depth <= 0 then set(Colour.Black)
    else if surface.transmit <= 0 then
      mirror(surface.reflection, sx, sy, sz, px, py, pz, nx, ny, nz, dx, dy, dz, depth, insides)
    else
      transmitted(i, surface, px, py, pz, nx, ny, nz, sx, sy, sz)(
        dx,
        dy,
        dz,
        depth,
        insides
      )
    red = litR + red
    green = litG + green
    blue = litB + blue
    // Version 4: a glowing surface adds its emission where it is seen from the side it emits
    // from (its outward side), after shading; it lights nothing else.
    if front && surface.emits then glow(surface)

  /** Adds the emission of a glowing `surface` to red, green and blue. */
  private def glow(surface: Surface): Unit =
    red = red + surface.emission.r
    green = green + surface.emission.g
    blue = blue + surface.emission.b

  /** The light the surface sends back from every light that reaches S0, left in red, green and
    * blue: diffuse C ⊙ colour(L) · diffuse · (1 − transmit) · |rn · Sd| and white highlights
    * colour(L) · (phong + specular terms), each light scaled by the share of it that reaches S0
    * and by its fade A(d) (version 4), d the distance from the hit point p to the light (an area
    * light's centre), as POV-Ray measures it. rn is the shading normal s; d the ray's direction.
    *
    * `leaning` says that s is a smooth mesh's interpolated normal, not the face's own; `i` is the
    * shape hit and `face` its face (a mesh's), tested first for a point light behind the surface
    * ([[World.ownBlocks]]).
    *
    * Perf: the channels summed in the fields, light by light in document order, each light in a
    * method of its own ([[light]]): this loop stays small, so the JIT compiles the loop, the light
    * and the shaded point apart and quickly (no large method compiled twice, on-stack and again;
    * docs/performance.md, round 9), with no Colour or closure per light.
    */
  private def lit(
      i: Int,
      face: Int,
      surface: Surface,
      colour: Colour,
      sx: Double,
      sy: Double,
      sz: Double,
      leaning: Boolean,
      s0x: Double,
      s0y: Double,
      s0z: Double
  )(px: Double, py: Double, pz: Double, nx: Double, ny: Double, nz: Double)(
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int
  ): Unit =
    val diffuse  = surface.diffuse * (1 - surface.transmit)
    val oneSided = leaning || surface.transmit > 0
    red = 0.0
    green = 0.0
    blue = 0.0
    // Perf: each light's direction is a square root and three divisions, waited on by the rest
    // of its light; computed for all lights first, in a loop whose turns do not depend on each
    // other, the processor overlaps them (profiles of mesh-20000; docs/performance.md, round 50).
    val lightPoints = world.lightPoints
    var j           = 0
    while j < world.lights.length do
      val tx    = lightPoints(3 * j) - s0x
      val ty    = lightPoints(3 * j + 1) - s0y
      val tz    = lightPoints(3 * j + 2) - s0z
      val reach = Math.sqrt(tx * tx + ty * ty + tz * tz)
      // Equation 41; a light exactly at S0 shines straight along the normal.
      toward(4 * j) = if reach > 0 then tx / reach else sx
      toward(4 * j + 1) = if reach > 0 then ty / reach else sy
      toward(4 * j + 2) = if reach > 0 then tz / reach else sz
      toward(4 * j + 3) = reach
      j += 1
    // Perf: a counted loop over the lights (see above).
    var k = 0
    while k < world.lights.length do
      light(k, i, face, surface, colour, diffuse, oneSided, leaning, sx, sy, sz, s0x, s0y, s0z)(
        px,
        py,
        pz,
        nx,
        ny,
        nz
      )(dx, dy, dz, depth)
      k += 1

  /** Adds to red, green and blue what light `k` gives the point, as [[lit]] says, from the
    * direction toward the light and its distance that [[lit]] left in `toward`.
    */
  private def light(
      k: Int,
      i: Int,
      face: Int,
      surface: Surface,
      colour: Colour,
      diffuse: Double,
      oneSided: Boolean,
      leaning: Boolean,
      sx: Double,
      sy: Double,
      sz: Double,
      s0x: Double,
      s0y: Double,
      s0z: Double
  )(px: Double, py: Double, pz: Double, nx: Double, ny: Double, nz: Double)(
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int
  ): Unit =
    val light = world.lights(k)
    val sdx   = toward(4 * k)
    val sdy   = toward(4 * k + 1)
    val sdz   = toward(4 * k + 2)
    val reach = toward(4 * k + 3)
    val cos   = sx * sdx + sy * sdy + sz * sdz
    // POV-Ray ignores a light behind the shading normal. A flat opaque surface shadows such a
    // point light by itself; transmitting surfaces, smooth normals and area lights (lit from
    // off-centre sub-lights) need the rule said out loud.
    val behind = cos < Shading.FarSide && (oneSided || light.area.isDefined)
    if !behind then
      // A point light behind the surface (cos < 0: S0 lies on the other side) is mostly
      // shadowed by the surface itself, so that is tested first (World.ownBlocks).
      val share =
        if light.area.isDefined then
          // Each sub-light from the side of the face's plane it lies on (Shadows.areaBeside).
          shadows.areaBeside(s0x, s0y, s0z, px, py, pz, nx, ny, nz, k)
        else if leaning && Shading.sideToward(nx, ny, nz, sdx, sdy, sdz) < 0 then
          // A smooth face's point light that its leaning normal faces from behind the face's own
          // plane: the shadow ray starts on the far side and passes the face.
          val e = -Shading.Epsilon
          shadows.pointToward(k, depth, px + nx * e, py + ny * e, pz + nz * e, sdx, sdy, sdz, reach)
        else if cos < 0 && world.ownBlocks(i, face, s0x, s0y, s0z, sdx, sdy, sdz, reach, query)
        then 0.0
        else shadows.pointToward(k, depth, s0x, s0y, s0z, sdx, sdy, sdz, reach)
      if share > 0 then
        // Without fade the share is used as it is (the same bits as before version 4).
        val reaching = if light.fade.isEmpty then share else faded(light, share, px, py, pz)
        val lr       = light.colour.r * reaching
        val lg       = light.colour.g * reaching
        val lb       = light.colour.b * reaching
        val facing   = Math.abs(cos)
        red = red + colour.r * lr * diffuse * facing
        green = green + colour.g * lg * diffuse * facing
        blue = blue + colour.b * lb * diffuse * facing
        if surface.highlighted && cos >= Shading.FarSide then
          val h = Shading.highlightAlong(surface, sx, sy, sz, dx, dy, dz, sdx, sdy, sdz)
          red = red + lr * h
          green = green + lg * h
          blue = blue + lb * h

  /** `share` of a fading `light` scaled by its fade A(d), d the distance from p to the light. */
  private def faded(
      light: tracer.scene.Light,
      share: Double,
      px: Double,
      py: Double,
      pz: Double
  ): Double =
    val fx = light.location.x - px
    val fy = light.location.y - py
    val fz = light.location.z - pz
    share * light.attenuation(Math.sqrt(fx * fx + fy * fy + fz * fz))

  /** reflection · colour(reflected ray, depth − 1) (equations 43–44), black for no mirror, left
    * in red, green and blue: the ray from S0, d mirrored about the shading normal s.
    */
  private def mirror(
      reflection: Double,
      sx: Double,
      sy: Double,
      sz: Double,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int,
      insides: List[Int]
  ): Unit =
    if reflection <= 0 then set(Colour.Black)
    else
      reflected(sx, sy, sz, px, py, pz, nx, ny, nz, dx, dy, dz, depth, insides)
      red = red * reflection
      green = green * reflection
      blue = blue * reflection

  /** colour(T, depth − 1) for the ray T reflected at the hit p (shading normal s, the face's own
    * normal n, both facing the ray), left in red, green and blue: T_d = R_d − 2(s·R_d)s
    * (Refraction.reflect), from S0 = p + ε·n (equation 43). On a smooth mesh T may leave behind
    * the face's own plane; it then starts at p − ε·n and passes the face, as POV-Ray's reflected
    * ray, which starts on the surface itself, does (a flat face's T never does).
    */
  private def reflected(
      sx: Double,
      sy: Double,
      sz: Double,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      depth: Int,
      insides: List[Int]
  ): Unit =
    val k       = 2 * (sx * dx + sy * dy + sz * dz)
    val tx      = dx - sx * k
    val ty      = dy - sy * k
    val tz      = dz - sz * k
    val leaning = sx != nx || sy != ny || sz != nz
    val side    = if leaning then Shading.sideToward(nx, ny, nz, tx, ty, tz) else Shading.Epsilon
    traceFrom(px + nx * side, py + ny * side, pz + nz * side, tx, ty, tz, depth - 1, insides)

  /** transmit · colour(ray through the surface) + the mirror term, left in red, green and blue;
    * the ray goes straight on where the indices match (not counted against the depth, as POV-Ray
    * continues such rays), and is bent by Heckbert's formula where they differ. Past the critical
    * angle the internal reflection is added whole, in place of the transmitted and the mirror
    * terms (POV-Ray).
    */
  private def transmitted(
      i: Int,
      surface: Surface,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      sx: Double,
      sy: Double,
      sz: Double
  )(dx: Double, dy: Double, dz: Double, depth: Int, insides: List[Int]): Unit =
    Refraction.crossing(insides, i, world.surface(_).ior) { (eta, beyondInsides) =>
      // The ray through starts just behind the surface; on a smooth mesh, a ray bent about the
      // leaning normal back to the ray's side of the face's own plane starts on that side, as
      // POV-Ray's from the surface itself does (it does not meet the face again).
      val leaning = sx != nx || sy != ny || sz != nz
      def through(ux: Double, uy: Double, uz: Double, depthBeyond: Int): Unit =
        val side = if leaning then Shading.sideToward(nx, ny, nz, ux, uy, uz) else -Shading.Epsilon
        traceFrom(
          px + nx * side,
          py + ny * side,
          pz + nz * side,
          ux,
          uy,
          uz,
          depthBeyond,
          beyondInsides
        )
        val tr = red * surface.transmit
        val tg = green * surface.transmit
        val tb = blue * surface.transmit
        mirror(surface.reflection, sx, sy, sz, px, py, pz, nx, ny, nz, dx, dy, dz, depth, insides)
        red = tr + red
        green = tg + green
        blue = tb + blue
      if Math.abs(eta - 1) < Refraction.SameIndex then through(dx, dy, dz, depth)
      else
        Refraction.refracted(dx, dy, dz, sx, sy, sz, eta)((ux, uy, uz) =>
          through(ux, uy, uz, depth - 1)
        ) {
          reflected(sx, sy, sz, px, py, pz, nx, ny, nz, dx, dy, dz, depth, insides)
        }
    }

  /** The surface colour C of leaf `leaf` of shape `i` at the point p: the texel or checker cell
    * there, or the plain colour.
    */
  private def pigment(i: Int, leaf: Int, px: Double, py: Double, pz: Double): Colour =
    world.surface(i, leaf).pigment match
      case Pigment.Solid(c) => c
      case other            => patterned(other, i, leaf, px, py, pz)

  /** [[pigment]] of a texture or a checker (out of line: the plain colour is the common path). */
  private def patterned(
      pigment: Pigment,
      i: Int,
      leaf: Int,
      px: Double,
      py: Double,
      pz: Double
  ): Colour =
    pigment match
      case Pigment.Solid(c)          => c
      case Pigment.Textured(texture) =>
        val uv = Shape.surfaceCoordinates(world.shape(i), Vec3(px, py, pz), leaf)
        texture.colourAt(uv.u, uv.v)
      case checker: Pigment.Checker => Pigment.checkerColour(checker, Vec3(px, py, pz))

  /** Leaves `c` in red, green and blue. */
  private inline def set(c: Colour): Unit =
    red = c.r
    green = c.g
    blue = c.b

/** Constants and pure terms of the shading model. */
object Shading:
  /** ε, the offset of shadow and reflected ray origins from the surface (world units). */
  val Epsilon: Double = 1e-4

  /** The offset along n, the face's own unit normal facing the arriving ray, at which a new ray
    * in direction d starts off the surface: +ε on the side n faces when d goes there (n · d ≥ 0),
    * −ε beyond it, as Mitsuba's `spawn_ray` and POV-Ray's rays from the surface itself pass the
    * face whichever way they go. On a flat face a reflection or a lit point's shadow ray always
    * stays on n's side; on a smooth mesh one about the leaning normal may not.
    */
  inline def sideToward(
      nx: Double,
      ny: Double,
      nz: Double,
      dx: Double,
      dy: Double,
      dz: Double
  ): Double =
    if nx * dx + ny * dy + nz * dz < 0 then -Epsilon else Epsilon

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
    highlightAlong(
      surface,
      normal.x,
      normal.y,
      normal.z,
      direction.x,
      direction.y,
      direction.z,
      toLight.x,
      toLight.y,
      toLight.z
    )

  /** [[highlight]] with the normal n, the direction d and the way to the light l as doubles. */
  def highlightAlong(
      surface: Surface,
      nx: Double,
      ny: Double,
      nz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      lx: Double,
      ly: Double,
      lz: Double
  ): Double =
    val phong =
      if surface.phong <= 0 then 0.0
      else
        // Refraction.reflect(d, n) · l.
        val k   = 2 * (nx * dx + ny * dy + nz * dz)
        val cos = (dx - nx * k) * lx + (dy - ny * k) * ly + (dz - nz * k) * lz
        if cos > 0 && (surface.phongSize < 60 || cos > 0.0008) then
          surface.phong * Pow.pow(cos, surface.phongSize)
        else 0.0
    val specular =
      if surface.specular <= 0 then 0.0
      else
        // The half-way vector (l − d) / 2, its length and its cosine with n.
        val hx     = (lx - dx) * 0.5
        val hy     = (ly - dy) * 0.5
        val hz     = (lz - dz) * 0.5
        val length = Math.sqrt(hx * hx + hy * hy + hz * hz)
        val cos    = if length > 0 then (hx * nx + hy * ny + hz * nz) / length else 0.0
        if cos > 0 then surface.specular * Pow.pow(cos, 1 / surface.roughness) else 0.0
    phong + specular
