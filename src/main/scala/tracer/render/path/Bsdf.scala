package tracer.render.path

import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.Refraction
import tracer.scene.Surface

/** The direction a [[Bsdf]] sends a path on, and what it weighs.
  *
  * @param direction   the new unit direction ωo
  * @param weight      f·|cos θo| / density for a smooth lobe, the lobe's weight over the chance
  *   of choosing it for a mirror, glass or a clear pass: what the path's throughput is scaled by
  * @param density     the density of ωo per unit solid angle over all smooth lobes (the number
  *   multiple importance sampling compares with the emitters'), 0 for a delta lobe
  * @param transmitted true when ωo goes through the surface (refraction or a clear pass)
  * @param bounce      false only for a clear surface's straight pass, which is not a bounce
  * @param eta         the ratio of indices n_t / n_i crossed by a refraction (1 otherwise)
  */
final case class Scattered(
    direction: Vec3,
    weight: Colour,
    density: Double,
    transmitted: Boolean,
    bounce: Boolean,
    eta: Double
):
  /** True when nothing goes on: the path ends here. */
  def absorbed: Boolean = weight.max <= 0

/** The [[Scattered]] value that ends a path. */
object Scattered:
  /** No light goes on. */
  val Absorbed: Scattered = Scattered(Vec3.UnitZ, Colour.Black, 0, false, true, 1)

/** A surface point's scattering function in path mode (docs/rendering.md, Surfaces in path mode):
  *
  *   f = (1 − t)·kd·C/π + kr·mirror + P·ggx(α_P) + K·ggx(α_K) + t·pass(η)
  *
  * Each lobe can be evaluated (the smooth ones), sampled and given its density. A lobe is chosen
  * with probability its weight over their sum: (1 − t)·kd·mean(C), kr, P, K and t. The smooth
  * lobes (Lambert and the two GGX lobes) and the mirror reflect on the side the path came from,
  * whichever side of the surface that is; glass (η ≠ 1) knows inside from outside.
  *
  * Directions are unit vectors in world space: ωi points back along the arriving path, n is the
  * shading normal on ωi's side (n · ωi ≥ 0).
  *
  * @param diffuse    (1 − t)·kd·C, the Lambert lobe's albedo
  * @param mirror     kr
  * @param phong      P
  * @param alphaP     α_P = √(2 / (4s + 2))
  * @param specular   K
  * @param alphaK     α_K = √(2 / (1/ρ + 2))
  * @param transmit   t
  * @param ior        η; 1 for a clear surface
  */
final case class Bsdf(
    diffuse: Colour,
    mirror: Double,
    phong: Double,
    alphaP: Double,
    specular: Double,
    alphaK: Double,
    transmit: Double,
    ior: Double
):
  private val diffuseWeight = (diffuse.r + diffuse.g + diffuse.b) / 3

  /** The sum of the lobes' weights: a lobe is chosen with its weight over this. */
  val total: Double = diffuseWeight + mirror + phong + specular + transmit

  /** True when the surface transmits and refracts (t > 0, η ≠ 1): glass. */
  val glass: Boolean = transmit > 0 && Math.abs(ior - 1) >= Refraction.SameIndex

  /** True when the surface transmits without refracting (t > 0, η = 1): clear. */
  val clear: Boolean = transmit > 0 && !glass

  /** True when some lobe is smooth (not a delta), so the emitters can be sampled for it. */
  val smooth: Boolean = diffuseWeight > 0 || phong > 0 || specular > 0

  /** f(ωi, ωo)·|n · ωo| summed over the smooth lobes: zero for ωo on the far side of n. */
  def evaluate(n: Vec3, wi: Vec3, wo: Vec3): Colour =
    val out = Scratch()
    evaluateInto(out, n.x, n.y, n.z, wi.x, wi.y, wi.z, wo.x, wo.y, wo.z)
    Colour(out.fr, out.fg, out.fb)

  /** [[evaluate]] on coordinates, into `out.fr`, `out.fg`, `out.fb`: what path mode's loop calls,
    * allocating nothing (PathBench).
    */
  def evaluateInto(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      ox: Double,
      oy: Double,
      oz: Double
  ): Unit =
    val ci = nx * ix + ny * iy + nz * iz
    val co = nx * ox + ny * oy + nz * oz
    if co <= 0 || ci <= 0 then
      out.fr = 0; out.fg = 0; out.fb = 0
    else
      val lambert = co / Math.PI
      val rough   = glossy(nx, ny, nz, ix, iy, iz, ox, oy, oz, ci, co, reflectance = true)
      out.fr = diffuse.r * lambert + rough
      out.fg = diffuse.g * lambert + rough
      out.fb = diffuse.b * lambert + rough

  /** The density of ωo per unit solid angle when [[sample]] draws from the smooth lobes: each
    * lobe's density times the chance of choosing it. Zero on the far side of n.
    */
  def density(n: Vec3, wi: Vec3, wo: Vec3): Double =
    densityAt(n.x, n.y, n.z, wi.x, wi.y, wi.z, wo.x, wo.y, wo.z)

  /** [[density]] on coordinates. */
  def densityAt(
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      ox: Double,
      oy: Double,
      oz: Double
  ): Double =
    val ci = nx * ix + ny * iy + nz * iz
    val co = nx * ox + ny * oy + nz * oz
    if co <= 0 || ci <= 0 || total <= 0 then 0.0
    else
      (diffuseWeight * co / Math.PI +
        glossy(nx, ny, nz, ix, iy, iz, ox, oy, oz, ci, co, reflectance = false)) / total

  /** P·ggx(α_P) + K·ggx(α_K) times |cos θo| (`reflectance`), or their weighted densities. */
  private def glossy(
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      ci: Double,
      co: Double,
      reflectance: Boolean
  ): Double =
    if phong <= 0 && specular <= 0 then 0.0
    else
      // h = (ωi + ωo) normalised, n when that has no length.
      val sx  = ix + ox
      val sy  = iy + oy
      val sz  = iz + oz
      val len = Math.sqrt(sx * sx + sy * sy + sz * sz)
      val ok  = len > 0 && len < Double.PositiveInfinity
      val hx  = if ok then sx / len else nx
      val hy  = if ok then sy / len else ny
      val hz0 = if ok then sz / len else nz
      val hz  = nx * hx + ny * hy + nz * hz0
      val ih  = ix * hx + iy * hy + iz * hz0
      lobe(phong, alphaP, ci, co, hz, ih, reflectance) +
        lobe(specular, alphaK, ci, co, hz, ih, reflectance)

  /** One GGX lobe of weight `weight`: its f·|cos θo| or its density. */
  private def lobe(
      weight: Double,
      alpha: Double,
      ci: Double,
      co: Double,
      hz: Double,
      ih: Double,
      reflectance: Boolean
  ): Double =
    if weight <= 0 then 0.0
    else if reflectance then weight * Microfacet.reflected(alpha, ci, co, hz, ih)
    else weight * Microfacet.density(alpha, ci, co, hz, ih)

  /** A direction drawn from f: a lobe chosen by `choice`, then its direction by (u1, u2), and at
    * glass reflection or refraction by `fresnel` (each uniform in [0, 1)).
    *
    * @param entering true when ωi arrives on the outside of the surface (the `Hit.front` side)
    */
  def sample(
      n: Vec3,
      wi: Vec3,
      entering: Boolean,
      choice: Double,
      u1: Double,
      u2: Double,
      fresnel: Double
  ): Scattered =
    val out = Scratch()
    sampleInto(out, n.x, n.y, n.z, wi.x, wi.y, wi.z, entering, choice, u1, u2, fresnel)
    Scattered(
      Vec3(out.sx, out.sy, out.sz),
      Colour(out.wr, out.wg, out.wb),
      out.density,
      out.transmitted,
      out.bounce,
      out.eta
    )

  /** [[sample]] on coordinates, into `out`'s scattering fields: what path mode's loop calls,
    * allocating nothing (PathBench).
    */
  def sampleInto(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      entering: Boolean,
      choice: Double,
      u1: Double,
      u2: Double,
      fresnel: Double
  ): Unit =
    if total <= 0 then out.absorb()
    else
      val pick = choice * total
      if pick < diffuseWeight then
        Bsdf.cosineHemisphereInto(out, nx, ny, nz, u1, u2)
        if phong <= 0 && specular <= 0 then lambertSample(out, nx, ny, nz, ix, iy, iz)
        else smoothSample(out, nx, ny, nz, ix, iy, iz)
      else if pick < diffuseWeight + phong then
        glossySample(out, nx, ny, nz, ix, iy, iz, alphaP, u1, u2)
        smoothSample(out, nx, ny, nz, ix, iy, iz)
      else if pick < diffuseWeight + phong + specular then
        glossySample(out, nx, ny, nz, ix, iy, iz, alphaK, u1, u2)
        smoothSample(out, nx, ny, nz, ix, iy, iz)
      else if pick < diffuseWeight + phong + specular + mirror || transmit <= 0 then
        Bsdf.reflectInto(out, -ix, -iy, -iz, nx, ny, nz)
        out.scatter(total, total, total, 0, false, true, 1)
      else if clear then
        out.sx = -ix; out.sy = -iy; out.sz = -iz
        out.scatter(total, total, total, 0, true, false, 1)
      else dielectric(out, nx, ny, nz, ix, iy, iz, entering, fresnel)

  /** The smooth lobes' estimate for the direction in `out.sx`… drawn from one of them: f·|cos|
    * over the mixture's density (the density of having drawn ωo by any smooth lobe).
    */
  private def smoothSample(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double
  ): Unit =
    val ox  = out.sx
    val oy  = out.sy
    val oz  = out.sz
    val pdf = densityAt(nx, ny, nz, ix, iy, iz, ox, oy, oz)
    if pdf <= 0 then out.absorb()
    else
      evaluateInto(out, nx, ny, nz, ix, iy, iz, ox, oy, oz)
      out.scatter(out.fr / pdf, out.fg / pdf, out.fb / pdf, pdf, false, true, 1)

  /** [[smoothSample]] where Lambert is the only smooth lobe: the weight is (1 − t)·kd·C over
    * the chance of choosing it, the same for every direction above n.
    */
  private def lambertSample(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double
  ): Unit =
    val co = nx * out.sx + ny * out.sy + nz * out.sz
    if co <= 0 || nx * ix + ny * iy + nz * iz <= 0 then out.absorb()
    else
      out.scatter(
        lambertWeight.r,
        lambertWeight.g,
        lambertWeight.b,
        diffuseWeight / total * co / Math.PI,
        false,
        true,
        1
      )

  // (1 − t)·kd·C / (w_D / W): a Lambert sample's weight.
  private val lambertWeight =
    if diffuseWeight > 0 then diffuse * (total / diffuseWeight) else Colour.Black

  /** A direction drawn by GGX's visible normals: the mirror image of ωi in a sampled microfacet,
    * into `out.sx`….
    */
  private def glossySample(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      alpha: Double,
      u1: Double,
      u2: Double
  ): Unit =
    // The frame of [[Bsdf.tangents]], in doubles.
    val sign = if nz >= 0 then 1.0 else -1.0
    val a    = -1 / (sign + nz)
    val b    = nx * ny * a
    val sx   = 1 + sign * nx * nx * a
    val sy   = sign * b
    val sz   = -sign * nx
    val tx   = b
    val ty   = sign + ny * ny * a
    val tz   = -ny
    Microfacet.sampledNormal(
      alpha,
      ix * sx + iy * sy + iz * sz,
      ix * tx + iy * ty + iz * tz,
      ix * nx + iy * ny + iz * nz,
      u1,
      u2
    ) { (mx, my, mz) =>
      Bsdf.reflectInto(
        out,
        -ix,
        -iy,
        -iz,
        sx * mx + tx * my + nx * mz,
        sy * mx + ty * my + ny * mz,
        sz * mx + tz * my + nz * mz
      )
    }

  /** Mitsuba's smooth `dielectric`: reflection with the exact unpolarised Fresnel reflectance F
    * (1 past the critical angle), refraction otherwise, index η inside and 1 outside. A refracted
    * path's radiance is scaled by (n_i / n_t)², as light is squeezed into a narrower cone.
    */
  private def dielectric(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      entering: Boolean,
      u: Double
  ): Unit =
    val eta  = if entering then ior else 1 / ior // n_t / n_i
    val cosI = Math.min(1.0, nx * ix + ny * iy + nz * iz)
    val ct   = Bsdf.refractedCosine(cosI, eta)
    val f    = Bsdf.reflectance(cosI, eta, ct)
    val weight = total // the glass lobe's weight t over its chance t / total
    if u < f then
      Bsdf.reflectInto(out, -ix, -iy, -iz, nx, ny, nz)
      out.scatter(weight, weight, weight, 0, false, true, 1)
    else
      val ratio = 1 / eta
      val q     = ratio * cosI - ct
      val vx    = -ix * ratio + nx * q
      val vy    = -iy * ratio + ny * q
      val vz    = -iz * ratio + nz * q
      val len   = Math.sqrt(vx * vx + vy * vy + vz * vz)
      if len > 0 && len < Double.PositiveInfinity then
        out.sx = vx / len; out.sy = vy / len; out.sz = vz / len
      else
        out.sx = -ix; out.sy = -iy; out.sz = -iz
      val w = weight * ratio * ratio
      out.scatter(w, w, w, 0, true, true, eta)

/** Building a [[Bsdf]] from a surface, and the sampling helpers. */
object Bsdf:

  /** The scattering function of `surface` where its colour is `colour` (the texel or checker
    * cell at the point), with index `ior` inside (a combination's parts share the whole's).
    */
  def of(surface: Surface, colour: Colour, ior: Double): Bsdf =
    val t = surface.transmit
    Bsdf(
      colour * (surface.diffuse * (1 - t)),
      surface.reflection,
      surface.phong,
      Microfacet.phongAlpha(surface.phongSize),
      surface.specular,
      Microfacet.specularAlpha(surface.roughness),
      t,
      ior
    )

  /** The unpolarised Fresnel reflectance for a ray meeting a boundary at cos θi (> 0, on the
    * side it comes from) with index ratio η = n_t / n_i, and cos θt of the refracted ray (0 past
    * the critical angle, where the reflectance is 1) (Mitsuba's `fresnel`).
    */
  def fresnel(cosI: Double, eta: Double): (Double, Double) =
    val cosT = refractedCosine(cosI, eta)
    (reflectance(cosI, eta, cosT), cosT)

  /** The cos θt of [[fresnel]]: 0 past the critical angle (or for cos θi ≤ 0). */
  def refractedCosine(cosI: Double, eta: Double): Double =
    val inverse = 1 / eta
    val cosT2   = 1 - inverse * inverse * (1 - cosI * cosI)
    if cosT2 <= 0 || cosI <= 0 then 0.0 else Math.sqrt(cosT2)

  /** The reflectance of [[fresnel]] given its cos θt (from [[refractedCosine]]): 1 where that is 0. */
  def reflectance(cosI: Double, eta: Double, cosT: Double): Double =
    if cosT == 0 then 1.0
    else
      val s = (eta * cosT - cosI) / (eta * cosT + cosI)
      val p = (eta * cosI - cosT) / (eta * cosI + cosT)
      0.5 * (s * s + p * p)

  /** The mirror direction of (dx, dy, dz) about unit n, as [[Refraction.reflect]] computes it,
    * into `out.sx`….
    */
  def reflectInto(
      out: Scratch,
      dx: Double,
      dy: Double,
      dz: Double,
      nx: Double,
      ny: Double,
      nz: Double
  ): Unit =
    val k = 2 * (nx * dx + ny * dy + nz * dz)
    out.sx = dx - nx * k
    out.sy = dy - ny * k
    out.sz = dz - nz * k

  /** A direction about unit `n` with density cos θ / π, from (u1, u2) uniform in [0, 1). */
  def cosineHemisphere(n: Vec3, u1: Double, u2: Double): Vec3 =
    val out = Scratch()
    cosineHemisphereInto(out, n.x, n.y, n.z, u1, u2)
    Vec3(out.sx, out.sy, out.sz)

  /** [[cosineHemisphere]] on coordinates, into `out.sx`…. */
  def cosineHemisphereInto(
      out: Scratch,
      nx: Double,
      ny: Double,
      nz: Double,
      u1: Double,
      u2: Double
  ): Unit =
    // The frame of [[tangents]], in doubles: this runs at every diffuse bounce.
    val sign = if nz >= 0 then 1.0 else -1.0
    val a    = -1 / (sign + nz)
    val b    = nx * ny * a
    val r    = Math.sqrt(u1)
    val p    = r * Turn.cos(u2) // φ = 2π·u2
    val q    = r * Turn.sin(u2)
    val h    = Math.sqrt(Math.max(0.0, 1 - u1))
    out.sx = p * (1 + sign * nx * nx * a) + q * b + h * nx
    out.sy = p * (sign * b) + q * (sign + ny * ny * a) + h * ny
    out.sz = p * (-sign * nx) + q * (-ny) + h * nz

  /** Two unit vectors that make a right-handed orthonormal frame with unit `n` (Duff et al.,
    * "Building an Orthonormal Basis, Revisited", 2017).
    */
  def tangents(n: Vec3): (Vec3, Vec3) =
    val sign = if n.z >= 0 then 1.0 else -1.0
    val a    = -1 / (sign + n.z)
    val b    = n.x * n.y * a
    (Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y))
