package tracer.render.path

/** The GGX (Trowbridge–Reitz) microfacet distribution of a rough mirror, as Mitsuba 3's
  * `roughconductor` uses it with `distribution="ggx"` (Mitsuba's `microfacet.h`): isotropic
  * roughness α, the separable Smith masking-shadowing G₁(ωi)·G₁(ωo), sampled by its visible
  * normals (Heitz 2018). Directions are in the local frame whose z axis is the normal, given as
  * their three coordinates.
  */
object Microfacet:

  /** D(m), the density of microfacet normals m (unit, local) per unit solid angle projected on
    * the surface: α² / (π (cos²θm (α² − 1) + 1)²), 0 below the surface.
    */
  def distribution(alpha: Double, mz: Double): Double =
    if mz <= 0 then 0.0
    else
      val a2 = alpha * alpha
      val d  = mz * mz * (a2 - 1) + 1
      a2 / (Math.PI * d * d)

  /** G₁(v, m), the share of microfacets of normal m seen from unit direction v (local): Smith's
    * 2 / (1 + √(1 + α² tan²θv)), 1 at normal incidence, 0 where v sees m's back (Mitsuba's
    * `smith_g1`).
    *
    * @param vz v's z coordinate, cos θv
    * @param vm v · m
    */
  def smithG1(alpha: Double, vz: Double, vm: Double): Double =
    if vm * vz <= 0 then 0.0
    else
      val xy2 = Math.max(0.0, 1 - vz * vz) * alpha * alpha
      if xy2 == 0 then 1.0 else 2 / (1 + Math.sqrt(1 + xy2 / (vz * vz)))

  /** f·cos θo of a GGX rough mirror of Fresnel 1 for unit directions ωi (towards the eye) and ωo
    * (towards the light): D(h)·G₁(ωi)·G₁(ωo) / (4 cos θi), h the unit half vector; 0 unless both
    * are above the surface (Mitsuba's `roughconductor::eval`). The directions enter through their
    * cosines with the normal n and with h.
    *
    * @param iz n · ωi
    * @param oz n · ωo
    * @param hz n · h
    * @param ih ωi · h (which equals ωo · h)
    */
  def reflected(alpha: Double, iz: Double, oz: Double, hz: Double, ih: Double): Double =
    if iz <= 0 || oz <= 0 then 0.0
    else distribution(alpha, hz) * smithG1(alpha, iz, ih) * smithG1(alpha, oz, ih) / (4 * iz)

  /** The density per unit solid angle with which [[sampledNormal]] followed by a mirror
    * reflection of ωi produces ωo: D(h)·G₁(ωi, h) / (4 cos θi) (visible normals); arguments as
    * [[reflected]]'s.
    */
  def density(alpha: Double, iz: Double, oz: Double, hz: Double, ih: Double): Double =
    if iz <= 0 || oz <= 0 then 0.0
    else distribution(alpha, hz) * smithG1(alpha, iz, ih) / (4 * iz)

  /** A microfacet normal drawn from the normals visible from unit local ωi (iz > 0), with the
    * density G₁(ωi, m)·max(0, ωi · m)·D(m) / cos θi, from the uniform numbers u1, u2 (Heitz,
    * "Sampling the GGX Distribution of Visible Normals", 2018), in the local frame, handed to `k`
    * as three doubles.
    *
    * Perf: `inline` with an inline body, so a glossy path sample makes no `Vec3` and no tuple
    * (a pair of doubles is two boxed doubles and a `Tuple2`), before C2's escape analysis as
    * after it (`Bsdf.glossySample`; docs/performance.md, round 38).
    */
  inline def sampledNormal[A](
      alpha: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      u1: Double,
      u2: Double
  )(inline k: (Double, Double, Double) => A): A =
    // The view direction in the hemisphere configuration (α stretched to 1).
    val vx0 = alpha * ix
    val vy0 = alpha * iy
    val vl  = Math.sqrt(vx0 * vx0 + vy0 * vy0 + iz * iz)
    val vx  = vx0 / vl
    val vy  = vy0 / vl
    val vz  = iz / vl
    // An orthonormal basis (T1, T2, V).
    val lensq = vx * vx + vy * vy
    val t1x   = if lensq > 0 then -vy / Math.sqrt(lensq) else 1.0
    val t1y   = if lensq > 0 then vx / Math.sqrt(lensq) else 0.0
    val t2x   = -vz * t1y
    val t2y   = vz * t1x
    val t2z   = vx * t1y - vy * t1x
    // A point on the projected disc, its lower half squeezed towards the view.
    val r  = Math.sqrt(u1)
    val p1 = r * Turn.cos(u2) // φ = 2π·u2
    val s  = 0.5 * (1 + vz)
    val p2 = (1 - s) * Math.sqrt(Math.max(0.0, 1 - p1 * p1)) + s * r * Turn.sin(u2)
    val pz = Math.sqrt(Math.max(0.0, 1 - p1 * p1 - p2 * p2))
    // Back onto the hemisphere, then unstretched.
    val nx = p1 * t1x + p2 * t2x + pz * vx
    val ny = p1 * t1y + p2 * t2y + pz * vy
    val nz = p2 * t2z + pz * vz
    val mx = alpha * nx
    val my = alpha * ny
    val mz = Math.max(0.0, nz)
    val ml = Math.sqrt(mx * mx + my * my + mz * mz)
    if ml > 0 then k(mx / ml, my / ml, mz / ml) else k(0.0, 0.0, 1.0)

  /** α for POV-Ray's Phong highlight of size s: √(2 / (4s + 2)) (a Phong exponent s on R·V is
    * about a Blinn exponent 4s, and a Blinn exponent e is about GGX's α = √(2 / (e + 2))).
    */
  def phongAlpha(size: Double): Double = Math.sqrt(2 / (4 * size + 2))

  /** α for POV-Ray's specular highlight of roughness ρ (Blinn with exponent 1/ρ): √(2 / (1/ρ + 2)). */
  def specularAlpha(roughness: Double): Double = Math.sqrt(2 / (1 / roughness + 2))
