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
    val iz = n.dot(wi)
    val oz = n.dot(wo)
    if oz <= 0 || iz <= 0 then Colour.Black
    else
      val lambert = oz / Math.PI
      val rough   = glossy(n, wi, wo, iz, oz, reflectance = true)
      Colour(diffuse.r * lambert + rough, diffuse.g * lambert + rough, diffuse.b * lambert + rough)

  /** The density of ωo per unit solid angle when [[sample]] draws from the smooth lobes: each
    * lobe's density times the chance of choosing it. Zero on the far side of n.
    */
  def density(n: Vec3, wi: Vec3, wo: Vec3): Double =
    val iz = n.dot(wi)
    val oz = n.dot(wo)
    if oz <= 0 || iz <= 0 || total <= 0 then 0.0
    else (diffuseWeight * oz / Math.PI + glossy(n, wi, wo, iz, oz, reflectance = false)) / total

  /** P·ggx(α_P) + K·ggx(α_K) times |cos θo| (`reflectance`), or their weighted densities. */
  private def glossy(
      n: Vec3,
      wi: Vec3,
      wo: Vec3,
      iz: Double,
      oz: Double,
      reflectance: Boolean
  ): Double =
    if phong <= 0 && specular <= 0 then 0.0
    else
      val h                                   = (wi + wo).normalisedOr(n)
      val hz                                  = n.dot(h)
      val ih                                  = wi.dot(h)
      def lobe(weight: Double, alpha: Double) =
        if weight <= 0 then 0.0
        else if reflectance then weight * Microfacet.reflected(alpha, iz, oz, hz, ih)
        else weight * Microfacet.density(alpha, iz, oz, hz, ih)
      lobe(phong, alphaP) + lobe(specular, alphaK)

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
    if total <= 0 then Scattered.Absorbed
    else
      val pick = choice * total
      if pick < diffuseWeight then
        val wo = Bsdf.cosineHemisphere(n, u1, u2)
        if phong <= 0 && specular <= 0 then lambertSample(n, wi, wo)
        else smoothSample(n, wi, wo)
      else if pick < diffuseWeight + phong then
        smoothSample(n, wi, glossySample(n, wi, alphaP, u1, u2))
      else if pick < diffuseWeight + phong + specular then
        smoothSample(n, wi, glossySample(n, wi, alphaK, u1, u2))
      else if pick < diffuseWeight + phong + specular + mirror || transmit <= 0 then
        Scattered(Refraction.reflect(-wi, n), Colour.grey(total), 0, false, true, 1)
      else if clear then Scattered(-wi, Colour.grey(total), 0, true, false, 1)
      else dielectric(n, wi, entering, fresnel)

  /** The smooth lobes' estimate for a direction drawn from one of them: f·|cos| over the
    * mixture's density (the density of having drawn ωo by any smooth lobe).
    */
  private def smoothSample(n: Vec3, wi: Vec3, wo: Vec3): Scattered =
    val pdf = density(n, wi, wo)
    if pdf <= 0 then Scattered.Absorbed
    else Scattered(wo, evaluate(n, wi, wo) / pdf, pdf, false, true, 1)

  /** [[smoothSample]] where Lambert is the only smooth lobe: the weight is (1 − t)·kd·C over
    * the chance of choosing it, the same for every direction above n.
    */
  private def lambertSample(n: Vec3, wi: Vec3, wo: Vec3): Scattered =
    val oz = n.dot(wo)
    if oz <= 0 || n.dot(wi) <= 0 then Scattered.Absorbed
    else Scattered(wo, lambertWeight, diffuseWeight / total * oz / Math.PI, false, true, 1)

  // (1 − t)·kd·C / (w_D / W): a Lambert sample's weight.
  private val lambertWeight =
    if diffuseWeight > 0 then diffuse * (total / diffuseWeight) else Colour.Black

  /** A direction drawn by GGX's visible normals: the mirror image of ωi in a sampled microfacet. */
  private def glossySample(n: Vec3, wi: Vec3, alpha: Double, u1: Double, u2: Double): Vec3 =
    val (s, t) = Bsdf.tangents(n)
    val m      = Microfacet.sampleNormal(alpha, wi.dot(s), wi.dot(t), wi.dot(n), u1, u2)
    val world  = s * m.x + t * m.y + n * m.z
    Refraction.reflect(-wi, world)

  /** Mitsuba's smooth `dielectric`: reflection with the exact unpolarised Fresnel reflectance F
    * (1 past the critical angle), refraction otherwise, index η inside and 1 outside. A refracted
    * path's radiance is scaled by (n_i / n_t)², as light is squeezed into a narrower cone.
    */
  private def dielectric(n: Vec3, wi: Vec3, entering: Boolean, u: Double): Scattered =
    val eta     = if entering then ior else 1 / ior // n_t / n_i
    val cosI    = Math.min(1.0, n.dot(wi))
    val (f, ct) = Bsdf.fresnel(cosI, eta)
    val weight = total // the glass lobe's weight t over its chance t / total
    if u < f then Scattered(Refraction.reflect(-wi, n), Colour.grey(weight), 0, false, true, 1)
    else
      val ratio     = 1 / eta
      val direction = (-wi * ratio + n * (ratio * cosI - ct)).normalisedOr(-wi)
      Scattered(direction, Colour.grey(weight * ratio * ratio), 0, true, true, eta)

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
    val inverse = 1 / eta
    val cosT2   = 1 - inverse * inverse * (1 - cosI * cosI)
    if cosT2 <= 0 then (1.0, 0.0)
    else if cosI <= 0 then (1.0, 0.0)
    else
      val cosT = Math.sqrt(cosT2)
      val s    = (eta * cosT - cosI) / (eta * cosT + cosI)
      val p    = (eta * cosI - cosT) / (eta * cosI + cosT)
      (0.5 * (s * s + p * p), cosT)

  /** A direction about unit `n` with density cos θ / π, from (u1, u2) uniform in [0, 1). */
  def cosineHemisphere(n: Vec3, u1: Double, u2: Double): Vec3 =
    // The frame of [[tangents]], in doubles: this runs at every diffuse bounce.
    val sign = if n.z >= 0 then 1.0 else -1.0
    val a    = -1 / (sign + n.z)
    val b    = n.x * n.y * a
    val r    = Math.sqrt(u1)
    val phi  = 2 * Math.PI * u2
    val p    = r * StrictMath.cos(phi)
    val q    = r * StrictMath.sin(phi)
    val h    = Math.sqrt(Math.max(0.0, 1 - u1))
    Vec3(
      p * (1 + sign * n.x * n.x * a) + q * b + h * n.x,
      p * (sign * b) + q * (sign + n.y * n.y * a) + h * n.y,
      p * (-sign * n.x) + q * (-n.y) + h * n.z
    )

  /** Two unit vectors that make a right-handed orthonormal frame with unit `n` (Duff et al.,
    * "Building an Orthonormal Basis, Revisited", 2017).
    */
  def tangents(n: Vec3): (Vec3, Vec3) =
    val sign = if n.z >= 0 then 1.0 else -1.0
    val a    = -1 / (sign + n.z)
    val b    = n.x * n.y * a
    (Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y))
