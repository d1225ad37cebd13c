package tracer.geometry

/** The rules of [[Csg]]: which crossings of its children are crossings of the whole. */
private[geometry] object Combination:

  /** The crossings of `csg` along `ray` at t > 0, in increasing t, their leaves numbered in the
    * whole tree. A child's crossing counts where the point is, for every other child, inside it
    * (intersection), or inside the first and outside the others (difference); a union keeps
    * them all. `inverted`: the crossings of the complement, as POV-Ray inverts a later child of a
    * difference ([[inverts]]).
    */
  def crossings(csg: Csg, ray: Ray, inverted: Boolean = false): List[Crossing] =
    val all = csg.children.indices.toList.flatMap { i =>
      Shape
        .crossings(csg.children(i), ray, inverted != inverts(csg, i))
        .filter(c => keeps(csg, i, ray.at(c.t), inverted))
        .map(c =>
          // A subtracted child's outside is the inside of the whole: its normals turn round.
          val outward =
            if inverts(csg, i) then -c.normal else c.normal
          Crossing(c.t, outward, c.leaf + csg.firstLeaves(i))
        )
    }
    all.sortBy(_.t)

  /** True when `p` is inside `csg`. */
  def inside(csg: Csg, p: tracer.math.Vec3): Boolean = csg.operation match
    case CsgOperation.Union        => csg.children.exists(Shape.inside(_, p))
    case CsgOperation.Intersection => csg.children.forall(Shape.inside(_, p))
    case CsgOperation.Difference   =>
      Shape.inside(csg.children.head, p) && csg.children.tail.forall(Shape.insideComplement(_, p))

  /** True when `p` is inside the complement of `csg` as POV-Ray builds it (`CSGUnion::Invert` and
    * the others, by De Morgan's rules): a union's is the intersection of its children's
    * complements, an intersection's the union of theirs, a difference's the union of its first
    * child's complement and its later children. For solids alone that is "not inside"; a
    * triangle or mesh has an empty complement ([[Shape.insideComplement]]).
    */
  def insideComplement(csg: Csg, p: tracer.math.Vec3): Boolean = csg.operation match
    case CsgOperation.Union        => csg.children.forall(Shape.insideComplement(_, p))
    case CsgOperation.Intersection => csg.children.exists(Shape.insideComplement(_, p))
    case CsgOperation.Difference   =>
      Shape.insideComplement(csg.children.head, p) || csg.children.tail.exists(Shape.inside(_, p))

  /** True when child `i` of `csg` enters it as its complement: a later child of a difference
    * (POV-Ray's difference is the intersection of the first child with the others inverted).
    */
  def inverts(csg: Csg, i: Int): Boolean = csg.operation == CsgOperation.Difference && i > 0

  /** True when a crossing of child `i` at `p` is on the surface of the whole, or with `inverted`
    * of its complement as POV-Ray inverts it (`CSGUnion::Invert` and the others, by De Morgan):
    * an inverted union is the intersection of its inverted children, keeping a child's crossing
    * only where the point is inside every other child's complement (so the inner surfaces of a
    * union used to cut are not cut faces); an inverted intersection or difference is a union,
    * keeping all. A difference keeps a crossing inside its first child and inside the complement
    * of each later one ([[insideComplement]]).
    */
  private def keeps(csg: Csg, i: Int, p: tracer.math.Vec3, inverted: Boolean): Boolean =
    csg.operation match
      case CsgOperation.Union =>
        !inverted ||
        csg.children.indices.forall(j => j == i || Shape.insideComplement(csg.children(j), p))
      case CsgOperation.Intersection =>
        inverted || csg.children.indices.forall(j => j == i || Shape.inside(csg.children(j), p))
      case CsgOperation.Difference =>
        inverted || csg.children.indices.forall { j =>
          j == i || (if j == 0 then Shape.inside(csg.children(j), p)
                     else Shape.insideComplement(csg.children(j), p))
        }
