package tracer.io

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.Generators.*

/** Scenes written by [[SceneWriter]] read back as the same scenes. */
class SceneWriterProperties extends ScalaCheckSuite:

  private val image                            = Bitmap.fill(2, 2, Colour(0.2, 0.4, 0.6))
  private val textures: SceneXml.TextureLoader = _ => Right(image)

  private val unitChannel = Gen.choose(0.0, 1.0)
  private val unitColour  = for r <- unitChannel; g <- unitChannel; b <- unitChannel
  yield Colour(r, g, b)
  private val positive = Gen.choose(1e-3, 1e3)

  /** A version 2 attribute: half the time its default, else a value from `values`. */
  private def sometimes(default: Double, values: Gen[Double]) =
    Gen.frequency(1 -> Gen.const(default), 1 -> values)

  private val surface: Gen[Surface] =
    for
      diffuse    <- Gen.choose(0.0, 5.0)
      reflection <- unitChannel
      pigment    <- Gen.oneOf(
        unitColour.map(Pigment.Solid(_)),
        Gen.oneOf("a.ppm", "dir/b & c.png").map(n => Pigment.Textured(Texture(image, n)))
      )
      phong     <- sometimes(0, Gen.choose(0.0, 3.0))
      phongSize <- sometimes(Surface.DefaultPhongSize, positive)
      specular  <- sometimes(0, Gen.choose(0.0, 3.0))
      roughness <- sometimes(Surface.DefaultRoughness, Gen.choose(1e-4, 1.0))
      transmit  <- sometimes(0, unitChannel)
    yield Surface(diffuse, reflection, pigment, phong, phongSize, specular, roughness, transmit)

  private val sphere =
    for c <- vec; r <- positive; p <- unitVec; s <- surface; ior <- sometimes(1, positive) yield
      // An equator at right angles to the pole.
      val e = p.cross(if Math.abs(p.x) < 0.9 then Vec3.UnitX else Vec3.UnitY).normalised.get
      SceneObject(Sphere(c, r, p, e), s.copy(ior = ior))
  private val plane = for n <- unitVec; d <- scalar; s <- surface
  yield SceneObject(Plane.at(n, d), s.copy(pigment = Pigment.Solid(Colour.White)))
  private val triangle = for
    t <- Gen.zip(vec, vec, vec).retryUntil((a, b, c) => Triangle.isProper(a, b, c)); s <- surface
  yield SceneObject(Triangle(t._1, t._2, t._3), s)

  private val area = for
    (a, b) <- Gen.zip(vec, vec).retryUntil((a, b) => a.cross(b).normalised.isDefined)
    na     <- Gen.choose(1, AreaLight.MaxSamples); nb <- Gen.choose(1, AreaLight.MaxSamples)
  yield AreaLight(a, b, na, nb)

  private val scene: Gen[Scene] =
    for
      eye        <- vec
      target     <- vec.retryUntil(_ != eye)
      up         <- unitVec.retryUntil(u => u.cross(target - eye).normalised.isDefined)
      zoom       <- positive; width <- positive; height <- positive
      background <- unitColour
      lights  <- Gen.listOf(for l <- vec; c <- colour; a <- Gen.option(area) yield Light(l, c, a))
      objects <- Gen.listOf(Gen.oneOf(sphere, plane, triangle))
    yield Scene(Camera(eye, target, up, zoom, width, height), background, lights, objects)

  /** Planes are stored with a unit normal, which the reader normalises again: that may move its
    * last bit, so plane normals compare within 1e-15; everything else compares exactly.
    */
  private def sameScene(a: Scene, b: Scene): Boolean =
    a.copy(objects = Nil) == b.copy(objects = Nil) && a.objects.length == b.objects.length &&
      a.objects.zip(b.objects).forall {
        case (SceneObject(p: Plane, s, _), SceneObject(q: Plane, t, _)) =>
          s == t && p.distance == q.distance && (p.normal - q.normal).length < 1e-15
        case (x, y) => x == y
      }

  property("parse(write(scene)) = scene"):
    forAll(scene) { s =>
      val text = SceneWriter.write(s)
      SceneXml.parse(text, textures) match
        case Right(back) => assert(sameScene(back, s), s"$back\n!=\n$s\n$text")
        case Left(e)     => fail(s"${e.describe}\n$text")
    }
