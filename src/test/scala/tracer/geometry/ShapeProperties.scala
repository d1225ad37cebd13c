package tracer.geometry

import munit.ScalaCheckSuite
import org.scalacheck.Prop.forAll
import org.scalacheck.{Gen, Prop}
import tracer.math.Vec3
import tracer.render.Shading
import tracer.testkit.Generators.*

/** Geometric properties of intersections with random shapes and rays (after pbrt's shapes_test). */
class ShapeProperties extends ScalaCheckSuite:

  private val sphere: Gen[Sphere] =
    for c <- vec; r <- Gen.choose(0.1, 100.0) yield Sphere(c, r)

  private val plane: Gen[Plane] = for n <- unitVec; d <- scalar yield Plane.at(n, d)

  private val triangle: Gen[Triangle] =
    Gen
      .zip(vec, vec, vec)
      .suchThat((a, b, c) => (b - a).cross(c - a).length > 1e-2)
      .map(Triangle(_, _, _))

  private val shape: Gen[Shape] = Gen.oneOf(sphere, plane, triangle)

  /** A point on `shape`: on the surface of a sphere, a plane near the origin, inside a triangle. */
  private def pointOn(shape: Shape): Gen[Vec3] = shape match
    case s: Sphere   => unitVec.map(d => s.centre + d * s.radius)
    case p: Plane    => vec.map(q => q - p.normal * (q.dot(p.normal) - p.distance))
    case t: Triangle =>
      // v as a fraction of what is left after u, so no generator's bounds depend on another's
      // value (a dependent Gen.choose once failed with crossed bounds under some seed).
      for u <- Gen.choose(0.05, 0.85); f <- Gen.choose(0.0, 1.0)
      yield t.t0 + t.a * u + t.b * (0.05 + f * Math.max(0.0, 0.9 - u))

  /** A shape, a point on it, and a ray from a random origin aimed at that point. */
  private val aimed: Gen[(Shape, Vec3, Ray)] =
    for
      s <- shape
      p <- pointOn(s)
      o <- vec.suchThat(o => (p - o).length > 1)
    yield (s, p, Ray(o, (p - o).normalised.get))

  private def isOn(shape: Shape, p: Vec3): Boolean = shape match
    case s: Sphere =>
      Math.abs(p.distance(s.centre) - s.radius) <= 1e-9 * (s.radius + s.centre.length + 1e3)
    case pl: Plane   => Math.abs(p.dot(pl.normal) - pl.distance) <= 1e-8 * (p.length + 1)
    case t: Triangle => Math.abs(p.dot(t.normal) - t.distance) <= 1e-8 * (p.length + 1)

  property("a ray aimed at a point of a shape hits it, at t > 0, on its surface"):
    forAll(aimed) { (s, _, r) =>
      Shape.intersect(s, r) match
        case None    => Prop.falsified :| s"$r missed $s"
        case Some(h) => Prop(h.t > 0 && isOn(s, h.point)) :| s"$h is not on $s"
    }

  property("the normal at a hit has unit length and faces the ray"):
    forAll(aimed) { (s, _, r) =>
      // Equation 20 (t2hc = Sr² − L2oc + tca²) cancels two large terms: its rounding error is about
      // 1e-16·L2oc, so a grazing hit's t, and the normal (ri − Sc)/Sr, are off by up to
      // sqrt(1e-16·L2oc)/Sr — 7e-5 for a 0.2-unit sphere 1400 units away. The course's formula
      // is what the spec asks for, so the tolerance follows it.
      val tolerance = s match
        case sphere: Sphere => 1e-9 + 1e-7 * (1 + sphere.centre.distance(r.origin)) / sphere.radius
        case _              => 1e-9
      Shape
        .intersect(s, r)
        .forall(h =>
          Math.abs(h.normal.length - 1) < tolerance && h.normal.dot(r.direction) <= tolerance
        )
    }

  property("a sphere's outward normal points along p − c"):
    forAll(sphere, unitVec) { (s, d) =>
      val r = Ray(s.centre + d * (s.radius * 3), -d)
      Shape.intersect(s, r).exists(h => h.normal.dot(d) > 1 - 1e-9)
    }

  property("a ray aimed away from a sphere it starts outside misses"):
    forAll(sphere, unitVec) { (s, d) =>
      Shape.distance(s, Ray(s.centre + d * (s.radius * 2), d)) == Double.PositiveInfinity
    }

  property(
    "a ray leaving a hit point along the normal, the renderer's ε off, does not hit it again"
  ):
    forAll(aimed) { (s, _, r) =>
      // From inside a sphere the normal points inwards, and the far side is rightly hit again.
      val fromInside = s match
        case sphere: Sphere => r.origin.distance(sphere.centre) < sphere.radius
        case _              => false
      fromInside || Shape.intersect(s, r).forall { h =>
        // The offset the renderer gives shadow and reflected rays: a hit here is shadow acne.
        val away = Ray(h.point + h.normal * Shading.Epsilon, h.normal)
        Shape.distance(s, away) == Double.PositiveInfinity
      }
    }

  property("distance is never NaN for finite inputs"):
    forAll(shape, vec, unitVec)((s, o, d) => !Shape.distance(s, Ray(o, d)).isNaN)
