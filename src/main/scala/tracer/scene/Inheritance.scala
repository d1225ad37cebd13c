package tracer.scene

import tracer.geometry.{Box, Cone, Csg, Mesh, Placed, Plane, Shape, Sphere, Torus, Triangle}
import tracer.math.Placement

/** Where the surfaces of a scene object sit in an element tree, for the writers that rebuild one
  * (the scene format's and POV-Ray's): a child without a surface inherits its parent's, and a
  * pattern lies in the space of the element that carries its surface (docs/scene-format.md,
  * Constructive solid geometry).
  */
object Inheritance:

  /** The pattern space of an element placed by `placements` (innermost first): the ones that move. */
  def space(placements: List[Placement]): List[Placement] = placements.filterNot(_.isIdentity)

  /** The surface that combination `c`, whose first leaf is number `leaf` of `o`'s shape, should
    * carry inside elements placed by `placements` (its own first, innermost first): a checker
    * lying in its space on a leaf placed apart (it can sit nowhere else), else the surface its
    * leaves show most that may sit there (the first of equals); nothing when a leaf inherits a
    * checker lying in the space of an element further out.
    */
  def carried(o: SceneObject, c: Csg, leaf: Int, placements: List[Placement]): Option[Surface] =
    val here    = space(placements)
    val shown   = (leaf until leaf + Shape.leafCount(c)).map(o.surfaceOf)
    val pattern = shown.zip(leafSpaces(c, placements)).collectFirst {
      case (surface, own) if lies(surface, here) && own != here && checker(surface) => surface
    }
    val fitting = shown.filter(lies(_, here))
    // A leaf showing a checker that lies neither here nor in its own space inherits it from an
    // element outside: this combination must carry nothing, or it would come between them.
    val fromOutside = shown.zip(leafSpaces(c, placements)).exists { (surface, own) =>
      checker(surface) && !lies(surface, here) && !lies(surface, own)
    }
    if fromOutside then None
    else pattern.orElse(fitting.distinct.maxByOption(s => fitting.count(_ == s)))

  /** How many of `chain` (placements innermost first, inside elements placed by `enclosing`) come
    * before `surface` is given, so that its pattern moves with the rest: 0 unless it is a checker
    * lying in the space of the outer ones.
    */
  def depth(surface: Surface, chain: List[Placement], enclosing: List[Placement]): Int =
    (0 to chain.length)
      .find(k => lies(surface, space(chain.drop(k) ++ enclosing)))
      .filter(_ => checker(surface))
      .getOrElse(0)

  /** True when `surface` carries a checker whose space is none of the places [[depth]] tries for
    * it among `chain` inside `enclosing`: a shape whose placement was built into it (a triangle
    * or mesh of a union split into its children) while its pattern stays in the union's space.
    */
  def unplaced(surface: Surface, chain: List[Placement], enclosing: List[Placement]): Boolean =
    checker(surface) && !(0 to chain.length).exists(k =>
      lies(surface, space(chain.drop(k) ++ enclosing))
    )

  /** The pattern space of each leaf of `s` (as a surface of its own would have it) inside
    * elements placed by `placements`, innermost first.
    */
  private def leafSpaces(s: Shape, placements: List[Placement]): Vector[List[Placement]] = s match
    case p: Placed => leafSpaces(p.shape, p.placement :: placements)
    case c: Csg    => c.children.flatMap(leafSpaces(_, Placement.Identity :: placements))
    case m: Mesh   => Vector.fill(m.faceCount)(space(placements))
    case _: (Sphere | Plane | Triangle | Box | Cone | Torus) => Vector(space(placements))

  /** True when `surface`'s pattern, if it has one, lies in `here`. */
  private def lies(surface: Surface, here: List[Placement]): Boolean = surface.pigment match
    case c: Pigment.Checker                     => c.space == here
    case Pigment.Solid(_) | Pigment.Textured(_) => true

  private def checker(surface: Surface): Boolean = surface.pigment match
    case _: Pigment.Checker                     => true
    case Pigment.Solid(_) | Pigment.Textured(_) => false
