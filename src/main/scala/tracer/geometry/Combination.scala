package tracer.geometry

/** The rules of [[Csg]]: which crossings of its children are crossings of the whole, as POV-Ray
  * builds the combination. POV-Ray's difference is the intersection of its first child with the
  * later ones inverted, and inverting a combination rebuilds it (`CSGUnion::Invert`,
  * `CSGIntersection::Invert`): an inverted union is the intersection of its inverted children,
  * an inverted intersection the merge of its inverted children, and a merge inverted is an
  * intersection again. So what a subtree is depends on how often it was inverted, which these
  * rules count as [[Plain]], [[Inverted]] or [[Restored]].
  */
private[geometry] object Combination:

  /** A subtree never inverted. */
  final val Plain = 0

  /** A subtree inverted an odd number of times: its points are its complement's. */
  final val Inverted = 1

  /** A subtree inverted an even number of times, at least twice: its points are its own, but a
    * union there is a merge (its children's crossings inside one another dropped).
    */
  final val Restored = 2

  /** The count of a subtree of count `k` inverted once more. */
  inline def invert(k: Int): Int = if k == Inverted then Restored else Inverted

  /** The inversion count of child `i` of `csg`, whose own count is `k`: one more for a later
    * child of a difference ([[inverts]]).
    */
  inline def childInversions(csg: Csg, i: Int, k: Int): Int =
    if inverts(csg, i) then invert(k) else k

  /** What POV-Ray keeps of the children's crossings: all of them. */
  final val KeepAll = 0

  /** What POV-Ray keeps: a child's crossing where the point is inside every other child. */
  final val KeepInsideOthers = 1

  /** What POV-Ray keeps: a child's crossing where the point is inside no other child (a merge). */
  final val KeepOutsideOthers = 2

  /** Which crossings `csg` keeps at inversion count `k`: a union keeps all ([[Plain]]), is an
    * intersection ([[Inverted]]) or a merge ([[Restored]]); an intersection or a difference is
    * an intersection, or a merge when [[Inverted]]. "Inside" a child means as its own count says:
    * its complement when that is odd.
    */
  inline def rule(csg: Csg, k: Int): Int = csg.operation match
    case CsgOperation.Union =>
      if k == Plain then KeepAll else if k == Inverted then KeepInsideOthers else KeepOutsideOthers
    case CsgOperation.Intersection | CsgOperation.Difference =>
      if k == Inverted then KeepOutsideOthers else KeepInsideOthers

  /** The crossings of `csg` along `ray` at t > 0, in increasing t, their leaves numbered in the
    * whole tree: each child's crossings (counted with its own inversions) that [[rule]] keeps.
    * `inversions`: how often POV-Ray has inverted `csg` ([[Plain]] by default; a later child of a
    * difference is inverted once more).
    */
  def crossings(csg: Csg, ray: Ray, inversions: Int = Plain): List[Crossing] =
    val all = csg.children.indices.toList.flatMap { i =>
      Shape
        .crossings(csg.children(i), ray, childInversions(csg, i, inversions))
        .filter(c => keeps(csg, i, ray.at(c.t), inversions))
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

  /** True when `p` is inside the complement of `csg` as POV-Ray builds it (by De Morgan's rules):
    * a union's is the intersection of its children's complements, an intersection's the union
    * of theirs, a difference's the union of its first child's complement and its later children.
    * For solids alone that is "not inside"; a triangle or mesh has an empty complement
    * ([[Shape.insideComplement]]).
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

  /** True when `p` is inside `shape` counted `k` times inverted: its complement's inside when `k`
    * is odd ([[Shape.insideComplement]]), its own otherwise.
    */
  def insideAs(shape: Shape, p: tracer.math.Vec3, k: Int): Boolean =
    if k == Inverted then Shape.insideComplement(shape, p) else Shape.inside(shape, p)

  /** True when a crossing of child `i` at `p` is kept by `csg` at inversion count `k` ([[rule]]):
    * so the inner surfaces of a union used to cut are not cut faces (an intersection of
    * complements), and an intersection or a difference used to cut keeps what it keeps uncut
    * (a merge of complements).
    */
  private def keeps(csg: Csg, i: Int, p: tracer.math.Vec3, k: Int): Boolean =
    def others(inside: Boolean) = csg.children.indices.forall(j =>
      j == i || insideAs(csg.children(j), p, childInversions(csg, j, k)) == inside
    )
    rule(csg, k) match
      case KeepAll          => true
      case KeepInsideOthers => others(inside = true)
      case _                => others(inside = false)
