package tracer.render.path

import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.forAll
import tracer.image.Colour
import tracer.math.Vec3

/** The scattering functions' own laws: sampling agrees with evaluation and density,
  * reciprocity, no lobe reflects more than it receives, GGX's sampled directions follow its
  * density. Monte Carlo tolerances are 5 standard errors of the estimate, stated per law.
  */
class BsdfLaws extends ScalaCheckSuite:

  private val unit: Gen[Vec3] =
    for
      z   <- Gen.choose(-1.0, 1.0)
      phi <- Gen.choose(0.0, 2 * Math.PI)
    yield
      val r = Math.sqrt(1 - z * z)
      Vec3(r * Math.cos(phi), r * Math.sin(phi), z)

  /** A direction above `n` (n · ω > 0.05), from any unit vector. */
  private def above(n: Vec3, w: Vec3): Vec3 =
    val c = n.dot(w)
    val v = if c < 0 then w - n * (2 * c) else w
    if n.dot(v) < 0.05 then (v + n * 0.2).normalisedOr(n) else v

  private val glossy: Gen[Bsdf] =
    for
      kd       <- Gen.choose(0.0, 1.0)
      phong    <- Gen.choose(0.0, 1.0)
      size     <- Gen.choose(1.0, 200.0)
      specular <- Gen.choose(0.0, 1.0)
      rough    <- Gen.choose(0.005, 1.0)
    yield Bsdf(
      Colour.grey(kd),
      0,
      phong,
      Microfacet.phongAlpha(size),
      specular,
      Microfacet.specularAlpha(rough),
      0,
      1
    )

  property("reciprocity: f(ωi, ωo) = f(ωo, ωi) for every smooth lobe"):
    forAll(glossy, unit, unit, unit) { (bsdf, n, a, b) =>
      val wi = above(n, a)
      val wo = above(n, b)
      val f1 = bsdf.evaluate(n, wi, wo).g / n.dot(wo)
      val f2 = bsdf.evaluate(n, wo, wi).g / n.dot(wi)
      assertEqualsDouble(f1, f2, 1e-9 * Math.max(1.0, Math.abs(f1)))
    }

  property("a sample's weight is f·|cos θo| over the density it reports, which density() gives"):
    forAll(glossy, unit, unit, Gen.choose(0.0, 1.0), Gen.choose(0.0, 1.0), Gen.choose(0.0, 1.0)) {
      (bsdf, n, a, choice, u1, u2) =>
        val wi = above(n, a)
        val s  = bsdf.sample(n, wi, entering = true, choice, u1, u2, 0.5)
        Prop(s.absorbed || {
          val pdf = bsdf.density(n, wi, s.direction)
          val f   = bsdf.evaluate(n, wi, s.direction)
          Math.abs(s.density - pdf) <= 1e-9 * pdf &&
          Math.abs(s.weight.g - f.g / pdf) <= 1e-9 * Math.max(1.0, s.weight.g)
        })
    }

  private def albedo(bsdf: Bsdf, n: Vec3, wi: Vec3, count: Int): (Double, Double) =
    val sampler = Sampler(tracer.render.SamplerKind.Independent, 3, count)
    val xs      = (0 until count).map { j =>
      val a = sampler.pair(0, 0, j, 0)
      val s = bsdf.sample(
        n,
        wi,
        true,
        sampler.uniform(0, 0, j, 2),
        Sampler.first(a),
        Sampler.second(a),
        0.5
      )
      if s.absorbed then 0.0 else s.weight.g
    }
    PathScenes.meanAndError(xs)

  // ∫ f cos dω over the hemisphere, by uniform directions: an estimate that does not use the
  // lobe's own sampling, to compare with the mean of its sample weights.
  private def uniformAlbedo(bsdf: Bsdf, n: Vec3, wi: Vec3, count: Int): (Double, Double) =
    val sampler = Sampler(tracer.render.SamplerKind.Independent, 5, count)
    val (s, t)  = Bsdf.tangents(n)
    val xs      = (0 until count).map { j =>
      val a   = sampler.pair(0, 0, j, 0)
      val z   = Sampler.first(a)
      val phi = 2 * Math.PI * Sampler.second(a)
      val r   = Math.sqrt(1 - z * z)
      val wo  = s * (r * Math.cos(phi)) + t * (r * Math.sin(phi)) + n * z
      bsdf.evaluate(n, wi, wo).g * 2 * Math.PI
    }
    PathScenes.meanAndError(xs)

  for (name, alpha) <- List("sharp" -> 0.08, "medium" -> 0.3, "broad" -> 0.8) do
    for cos <- List(0.95, 0.5, 0.15) do
      test(s"GGX ($name, cos θi $cos): sampling and evaluation agree, and no energy is gained"):
        val bsdf    = Bsdf(Colour.Black, 0, 1, alpha, 0, 0.1, 0, 1)
        val n       = Vec3(0.2, 0.9, -0.3).normalisedOr(Vec3.UnitY)
        val (s, _)  = Bsdf.tangents(n)
        val wi      = (n * cos + s * Math.sqrt(1 - cos * cos)).normalisedOr(n)
        val (a, ea) = albedo(bsdf, n, wi, 40000)
        val (b, eb) = uniformAlbedo(bsdf, n, wi, 200000)
        val tol     = 5 * Math.sqrt(ea * ea + eb * eb)
        assert(Math.abs(a - b) <= tol, s"by its sampling $a ± $ea, by uniform directions $b ± $eb")
        assert(a <= 1 + 5 * ea, s"albedo $a > 1")
        // Visible-normal sampling: every weight is G1(ωo) ≤ 1.
        assert(a > 0)

  test("Lambert: albedo kd, by sampling and by uniform directions"):
    val bsdf    = Bsdf(Colour.grey(0.7), 0, 0, 0.1, 0, 0.1, 0, 1)
    val n       = Vec3.UnitY
    val wi      = Vec3(0.3, 0.8, 0.1).normalisedOr(n)
    val (a, ea) = albedo(bsdf, n, wi, 1000)
    assertEqualsDouble(a, 0.7, 1e-9) // cosine sampling makes every weight exactly kd
    assert(ea < 1e-12, s"spread $ea")
    val (b, eb) = uniformAlbedo(bsdf, n, wi, 100000)
    assert(Math.abs(b - 0.7) <= 5 * eb, s"$b ± $eb")

  test("GGX's sampled directions follow its density: a histogram over cos θo and φ"):
    val alpha    = 0.35
    val bsdf     = Bsdf(Colour.Black, 0, 1, alpha, 0, 0.1, 0, 1)
    val n        = Vec3.UnitZ
    val wi       = Vec3(0.6, 0, 0.8)
    val (bz, bp) = (8, 8)
    val count    = 200000
    val sampler  = Sampler(tracer.render.SamplerKind.Independent, 11, count)
    val counts   = Array.ofDim[Int](bz, bp)
    for j <- 0 until count do
      val a = sampler.pair(0, 0, j, 0)
      val s = bsdf.sample(n, wi, true, 0.5, Sampler.first(a), Sampler.second(a), 0.5)
      if !s.absorbed then
        val d  = s.direction
        val iz = Math.min(bz - 1, (d.z * bz).toInt)
        val ph = (Math.atan2(d.y, d.x) + Math.PI) / (2 * Math.PI)
        val ip = Math.min(bp - 1, (ph * bp).toInt)
        counts(iz)(ip) += 1
    // The expected share of each bin: the density integrated over it (a 24 × 24 midpoint rule).
    val q = 24
    for iz <- 0 until bz; ip <- 0 until bp do
      // Why: a sum over the quadrature grid, written as the rule reads.
      var mass = 0.0
      for a <- 0 until q; b <- 0 until q do
        val z   = (iz + (a + 0.5) / q) / bz
        val phi = (ip + (b + 0.5) / q) / bp * 2 * Math.PI - Math.PI
        val r   = Math.sqrt(1 - z * z)
        val wo  = Vec3(r * Math.cos(phi), r * Math.sin(phi), z)
        mass += bsdf.density(n, wi, wo) * (1.0 / bz / q) * (2 * Math.PI / bp / q)
      val expected = mass * count
      val sd       = Math.sqrt(expected * (1 - mass)) + 1
      // 5 binomial standard deviations, plus 1% of the bin for the quadrature's own error.
      assert(
        Math.abs(counts(iz)(ip) - expected) <= 5 * sd + 0.01 * expected,
        s"bin ($iz, $ip): ${counts(iz)(ip)} samples, density gives $expected"
      )

  test(
    "glass: Fresnel's reflectance and transmittance sum to one; past the critical angle all reflects"
  ):
    for cos <- List(1.0, 0.7, 0.3, 0.05); eta <- List(1.5, 1 / 1.5, 1.33) do
      val (f, ct) = Bsdf.fresnel(cos, eta)
      assert(f >= 0 && f <= 1, s"F = $f")
      val sinT2 = (1 - cos * cos) / (eta * eta)
      if sinT2 >= 1 then assertEquals(f, 1.0)
      else assertEqualsDouble(ct, Math.sqrt(1 - sinT2), 1e-12)
    // Normal incidence: ((η − 1) / (η + 1))².
    assertEqualsDouble(Bsdf.fresnel(1, 1.5)._1, 0.04, 1e-12)

  test("glass: Fresnel's reflectance at oblique angles is Fresnel's formula in sines and tangents"):
    // An independent form of the same law: with θt from Snell's law (sin θi = η sin θt),
    // R = ½(sin²(θi − θt)/sin²(θi + θt) + tan²(θi − θt)/tan²(θi + θt)). A wrong s or p term
    // (their forms swapped, or η on the wrong side) gives other values at every oblique angle.
    def expected(thetaI: Double, eta: Double) =
      val thetaT        = Math.asin(Math.sin(thetaI) / eta)
      def sq(x: Double) = x * x
      0.5 * (sq(Math.sin(thetaI - thetaT) / Math.sin(thetaI + thetaT)) +
        sq(Math.tan(thetaI - thetaT) / Math.tan(thetaI + thetaT)))
    for
      degrees <- List(10.0, 30.0, 45.0, 60.0, 80.0, 89.0)
      eta     <- List(1.5, 1.33, 2.4)
    do
      val thetaI = Math.toRadians(degrees)
      assertEqualsDouble(Bsdf.fresnel(Math.cos(thetaI), eta)._1, expected(thetaI, eta), 1e-12)
    // From inside glass (η = 1/1.5) below the critical angle of 41.8°.
    for degrees <- List(10.0, 30.0, 41.0) do
      val thetaI = Math.toRadians(degrees)
      assertEqualsDouble(
        Bsdf.fresnel(Math.cos(thetaI), 1 / 1.5)._1,
        expected(thetaI, 1 / 1.5),
        1e-12
      )
    // Known values: 45° into η = 1.5 reflects 5.024%; at Brewster's angle (tan θB = η) the p
    // wave is not reflected at all, leaving ½·rs² = 0.0740 (rs = (1 − η²)/(1 + η²)).
    assertEqualsDouble(Bsdf.fresnel(Math.cos(Math.PI / 4), 1.5)._1, 0.0502399, 1e-7)
    val rs = (1 - 1.5 * 1.5) / (1 + 1.5 * 1.5)
    assertEqualsDouble(Bsdf.fresnel(Math.cos(Math.atan(1.5)), 1.5)._1, 0.5 * rs * rs, 1e-12)

  test("glass: a refracted direction obeys Snell's law, and radiance is scaled by (n_i/n_t)²"):
    val bsdf = Bsdf(Colour.Black, 0, 0, 0.1, 0, 0.1, 1, 1.5)
    val n    = Vec3.UnitY
    val wi   = Vec3(0.6, 0.8, 0).normalisedOr(n)
    val s    = bsdf.sample(n, wi, entering = true, 0.5, 0.5, 0.5, fresnel = 0.99)
    assert(s.transmitted)
    val sinI = 0.6
    val sinT = Math.sqrt(s.direction.x * s.direction.x + s.direction.z * s.direction.z)
    assertEqualsDouble(sinI, 1.5 * sinT, 1e-12)
    assert(s.direction.y < 0)
    assertEqualsDouble(s.weight.g, 1 / (1.5 * 1.5), 1e-12)
    assertEqualsDouble(s.eta, 1.5, 0)
