package tracer.geometry

import munit.ScalaCheckSuite
import org.scalacheck.{Gen, Prop}
import org.scalacheck.Prop.{forAll, propBoolean}
import tracer.math.Vec3

/** Constructive solid geometry against point membership: along any ray, the crossings of a
  * combination are exactly where membership in it changes, membership being the operation applied
  * to the children's inside tests (union: any; intersection: all; difference: the first and none
  * of the others).
  */
class CsgLaws extends ScalaCheckSuite:

  private val coordinate = Gen.choose(-2.0, 2.0)
  private val point      = for x <- coordinate; y <- coordinate; z <- coordinate yield Vec3(x, y, z)

  private val sphere = for c <- point; r <- Gen.choose(0.3, 1.5) yield Sphere(c, r)
  private val box    =
    for
      c <- point; dx <- Gen.choose(0.3, 2.0); dy <- Gen.choose(0.3, 2.0); dz <- Gen.choose(0.3, 2.0)
    yield Box(c, c + Vec3(dx, dy, dz))
  private val cylinder =
    for a <- point; b <- point.retryUntil(_.distance(a) > 0.3); r <- Gen.choose(0.2, 1.0)
    yield Cylinder(a, b, r)

  private val solid: Gen[Shape] = Gen.oneOf(sphere, box, cylinder)
  private val operation         = Gen.oneOf(CsgOperation.values.toIndexedSeq)

  private val csg: Gen[Csg] =
    for
      op       <- operation
      n        <- Gen.choose(2, 3)
      children <- Gen.listOfN(n, solid)
      nested   <- Gen.oneOf(true, false)
      inner    <- operation
    yield
      val kids = children.toVector
      if nested then Csg(op, Csg(inner, kids.take(2)) +: kids.drop(2)) else Csg(op, kids)

  private val ray =
    for o <- point.map(_ * 3); target <- point.retryUntil(_.distance(Vec3.Zero) < 3)
    yield Ray(o, (target - o).normalisedOr(Vec3.UnitX))

  private def member(shape: Shape, p: Vec3): Boolean = shape match
    case c: Csg =>
      c.operation match
        case CsgOperation.Union        => c.children.exists(member(_, p))
        case CsgOperation.Intersection => c.children.forall(member(_, p))
        case CsgOperation.Difference   =>
          member(c.children.head, p) && !c.children.tail.exists(member(_, p))
    case other => Shape.inside(other, p)

  property("inside a combination is the operation on its children's inside tests"):
    forAll(csg, point)((c, p) => Shape.inside(c, p) == member(c, p))

  private def hasUnion(shape: Shape): Boolean = shape match
    case c: Csg => c.operation == CsgOperation.Union || c.children.exists(hasUnion)
    case _      => false

  // A union keeps its children's inner surfaces (POV-Ray's union, not merge): a crossing there
  // changes no membership, so this law is for trees of intersections and differences.
  property("without unions, every crossing is a place where membership changes"):
    forAll(csg.retryUntil(!hasUnion(_)), ray) { (c, r) =>
      val δ = 1e-6
      Prop.all(Shape.crossings(c, r).filter(_.t > δ).map { x =>
        (member(c, r.at(x.t - δ)) != member(c, r.at(x.t + δ))) :| s"no change at $x"
      }*)
    }

  property("every change of membership along the ray has a crossing there"):
    forAll(csg, ray) { (c, r) =>
      val steps   = (1 to 4000).map(_ * 0.005)
      val ts      = Shape.crossings(c, r).map(_.t)
      val changes = steps.zip(steps.tail).filter((a, b) => member(c, r.at(a)) != member(c, r.at(b)))
      Prop.all(
        changes.map((a, b) =>
          ts.exists(t => t >= a - 1e-9 && t <= b + 1e-9) :| s"none in [$a, $b]"
        )*
      )
    }

  property("the distance is the first crossing, and a hit names a leaf of the tree"):
    forAll(csg, ray) { (c, r) =>
      val xs = Shape.crossings(c, r)
      Shape.distance(c, r) == xs.headOption.fold(Double.PositiveInfinity)(_.t) &&
      xs.forall(x => x.leaf >= 0 && x.leaf < Shape.leafCount(c))
    }
