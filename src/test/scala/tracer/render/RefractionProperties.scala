package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.Vec3
import tracer.testkit.Generators.*

/** Refraction on doubles (the shading's path) is Refraction.refract, bit for bit. */
class RefractionProperties extends ScalaCheckSuite:

  private def bits(v: Vec3) = List(v.x, v.y, v.z).map(java.lang.Double.doubleToRawLongBits)

  private def onDoubles(d: Vec3, n: Vec3, eta: Double): Option[Vec3] =
    Refraction.refracted(d.x, d.y, d.z, n.x, n.y, n.z, eta)((x, y, z) => Some(Vec3(x, y, z)))(None)

  property("refracted gives refract's direction, or its total internal reflection"):
    val eta = Gen.oneOf(Gen.choose(0.3, 3.0), Gen.oneOf(1.0, 1 / 1.5, 1.5))
    forAll(unitVec, unitVec, eta) { (d, n, e) =>
      assertEquals(onDoubles(d, n, e).map(bits), Refraction.refract(d, n, e).map(bits))
    }

  test("past the critical angle both say total internal reflection"):
    // Leaving glass (η = 1.5) at 60° from the normal: sin θ₂ = 1.5 · 0.87 > 1.
    val d = Vec3(Math.sin(Math.PI / 3), Math.cos(Math.PI / 3), 0)
    assertEquals(onDoubles(d, Vec3.UnitY, 1.5), None)
    assertEquals(Refraction.refract(d, Vec3.UnitY, 1.5), None)
