package tracer.io

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.Vec3
import tracer.testkit.Generators

/** [[MeshTransform.placeInto]], the arrays' placement of a mesh's vertices, gives the same doubles
  * as [[MeshTransform.apply]], the model it stands in for.
  */
class MeshTransformProperties extends ScalaCheckSuite:

  private val placements: Gen[MeshTransform] =
    for
      scale       <- Gen.oneOf(Gen.const(1.0), Gen.choose(1e-3, 1e3))
      degrees     <- Gen.oneOf(Gen.const(Vec3(0, 0, 0)), Generators.vec.map(_ * 40))
      translation <- Generators.vec
    yield MeshTransform(scale, degrees, translation)

  private def bits(d: Double) = java.lang.Double.doubleToRawLongBits(d)

  property("a vertex placed into an array is the point apply places, bit for bit"):
    forAll(placements, Generators.vec, Gen.choose(0, 5)) { (place, p, at) =>
      val out = new Array[Double](at + 3)
      place.placeInto(p.x, p.y, p.z, out, at)
      val q = place(p)
      assertEquals(out.drop(at).toList.map(bits), List(q.x, q.y, q.z).map(bits), s"$place $p")
    }
