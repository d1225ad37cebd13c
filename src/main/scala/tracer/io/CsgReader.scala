package tracer.io

import tracer.geometry.{Csg, CsgOperation, Mesh, Placed, Shape, Triangle}
import tracer.math.Placement
import tracer.scene.{SceneObject, Surface}

/** Reads the shape elements of a scene into scene objects, the CSG elements (`union`,
  * `intersection`, `difference`) among them: children combined, placed, with surfaces inherited
  * from the nearest enclosing element that has one (docs/scene-format.md, Constructive solid
  * geometry).
  */
private[io] final class CsgReader(shapes: ShapeReader, surfaces: SurfaceReader):
  import ElementRules.*

  /** The scene objects of the shape element `e`, a child of `<scene>`. A union without `ior`
    * becomes its children, each an object of its own, as POV-Ray splits such unions: the same
    * picture, and each child in the hierarchy apart.
    */
  def sceneObjects(e: Element): Result[Vector[SceneObject]] = e.name match
    case "mesh" =>
      shapes
        .mesh(e, Enclosure.Top)
        .map((mesh, surface) => mesh.map(SceneObject(_, surface)).toVector)
    case _ =>
      piece(e, Enclosure.Top).map { p =>
        if e.name == "union" && p.whole.ior == 1 then split(p.shape, p.surfaces, Nil)
        else Vector(whole(p.shape, p.surfaces, p.whole))
      }

  /** The piece for shape element `e` standing at `at`. */
  def piece(e: Element, at: Enclosure): Result[Piece] = e.name match
    case "sphere"   => shapes.sphere(e, at)
    case "plane"    => shapes.plane(e, at)
    case "triangle" => shapes.triangle(e, at)
    case "mesh"     =>
      shapes.mesh(e, at).flatMap {
        case (Some(m), s) => Right(Piece(m, Vector.fill(m.faceCount)(s), s))
        case (None, _)    => e.fail("the mesh has no faces whose corners are not collinear")
      }
    case "box"          => shapes.box(e, at)
    case "cylinder"     => shapes.cylinder(e, at)
    case "cone"         => shapes.cone(e, at)
    case "torus"        => shapes.torus(e, at)
    case "union"        => combination(e, at, CsgOperation.Union)
    case "intersection" => combination(e, at, CsgOperation.Intersection)
    case "difference"   => combination(e, at, CsgOperation.Difference)
    case other          => e.fail(s"<$other> is not a shape")

  private def combination(e: Element, at: Enclosure, operation: CsgOperation): Result[Piece] =
    val union   = operation == CsgOperation.Union
    val allowed =
      Vocabulary.SolidChildren ++ (if union then Vocabulary.UnionOnlyChildren else Set.empty)
    for
      _ <- check(
        at.placements.length < CsgReader.MaxNesting,
        e,
        s"CSG elements nested more than ${CsgReader.MaxNesting} deep"
      )
      _ <- e.children.find(c => Vocabulary.UnionOnlyChildren(c.name) && !union) match
        case Some(c) => c.fail(s"<${c.name}> has no inside: it is allowed in a <union> only")
        case None    => Right(())
      children <- contents(e, Set("scale"), allowed ++ Vocabulary.PlacementChildren + "surface")
      own      <- shapes.placement(e, children)
      surface  <- surfaces.optional(
        e,
        children,
        SurfacePlace(texturable = false, shapes.iorRefusal(e, at, solid = true), at.space(own))
      )
      parts = children.filter(c => Vocabulary.Shapes(c.name))
      _ <- check(parts.nonEmpty, e, s"<${e.name}> needs at least one shape inside")
      inside = Enclosure(own :: at.placements, surface.orElse(at.surface), Some(e))
      pieces <- traverse(parts)(piece(_, inside))
    yield Piece(
      shapes.placed(Csg(operation, pieces.map(_.shape).toVector), own),
      pieces.toVector.flatMap(_.surfaces),
      surface.getOrElse(Surface())
    )

  /** One scene object: per-leaf surfaces kept only where some leaf shows another than `surface`. */
  private def whole(shape: Shape, leaves: Vector[Surface], surface: Surface): SceneObject =
    if leaves.forall(_ == surface) then SceneObject(shape, surface)
    else SceneObject(shape, surface, leaves)

  /** A union's children as objects of their own, each placed by the unions around it (listed
    * innermost first); nested unions split too.
    */
  private def split(
      shape: Shape,
      leaves: Vector[Surface],
      around: List[Placement]
  ): Vector[SceneObject] =
    shape match
      case c: Csg if c.operation == CsgOperation.Union =>
        c.children.indices.toVector.flatMap { i =>
          val first = c.firstLeaves(i)
          split(c.children(i), leaves.slice(first, first + c.leafCounts(i)), around)
        }
      case Placed(c: Csg, p) if c.operation == CsgOperation.Union => split(c, leaves, p :: around)
      case other                                                  =>
        val placed = around.foldLeft(other)(place)
        Vector(
          whole(placed, leaves, if leaves.forall(_ == leaves.head) then leaves.head else Surface())
        )

  /** `shape` placed by `p`: a triangle's or mesh's corners and normals moved, anything else
    * wrapped.
    */
  private def place(shape: Shape, p: Placement): Shape = shape match
    case t: Triangle => t.placed(p)
    case m: Mesh     => m.transformed(p.transform)
    case other       => shapes.placed(other, p)

/** The limits of [[CsgReader]]. */
private[io] object CsgReader:
  /** The most CSG elements one may stand inside: reading and tracing recurse once a level, at
    * some 2.7 KB of stack a level in the reader, so 3,000 nested unions overflowed the command's
    * 8 MB stack and 1,000 a JVM's default 1 MB (a program's own thread, a test's); 200 leave room
    * on either, and far more than any scene nests.
    */
  val MaxNesting: Int = 200
