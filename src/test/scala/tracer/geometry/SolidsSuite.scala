package tracer.geometry

import tracer.math.{Placement, Vec3}

/** The version 3 solids on rays whose answers are known: faces, edges, discs, grazing rays, rays
  * from inside, the torus's four roots, and placement.
  */
class SolidsSuite extends munit.FunSuite:

  private def ray(o: Vec3, d: Vec3)       = Ray(o, d.normalised.get)
  private def near(a: Double, b: Double)  = Math.abs(a - b) < 1e-9
  private def crossings(s: Shape, r: Ray) = Shape.crossings(s, r).map(c => (c.t, c.normal))

  private val box = Box(Vec3(1, 1, 1), Vec3(-1, -1, -1))

  test("a box is met on the face the ray enters and left on the one it leaves"):
    assertEquals(
      crossings(box, ray(Vec3(0, 0, -5), Vec3(0, 0, 1))),
      List((4.0, Vec3(0, 0, -1)), (6.0, Vec3(0, 0, 1)))
    )
    assertEquals(
      crossings(box, ray(Vec3(5, 0.5, 0), Vec3(-1, 0, 0))),
      List((4.0, Vec3(1, 0, 0)), (6.0, Vec3(-1, 0, 0)))
    )
    assertEquals(Shape.hitAt(box, ray(Vec3(0, -5, 0), Vec3(0, 1, 0)), 4).normal, Vec3(0, -1, 0))

  test("a ray from inside a box crosses only the face it leaves by, its normal facing the ray"):
    val r = ray(Vec3(0, 0, 0), Vec3(0, 1, 0))
    assertEquals(crossings(box, r), List((1.0, Vec3(0, 1, 0))))
    assertEquals(Shape.intersect(box, r).map(_.normal), Some(Vec3(0, -1, 0)))

  test("a ray along a box's edge or past it: edges count, a miss by a hair misses"):
    assertEquals(Shape.distance(box, ray(Vec3(1, 1, -5), Vec3(0, 0, 1))), 4.0)
    assertEquals(
      Shape.distance(box, ray(Vec3(1 + 1e-9, 0, -5), Vec3(0, 0, 1))),
      Double.PositiveInfinity
    )
    assertEquals(Shape.distance(box, ray(Vec3(0, 0, 5), Vec3(0, 0, 1))), Double.PositiveInfinity)

  test("a box's corners may be given in any order, but must differ in every coordinate"):
    assertEquals(Box(Vec3(1, -1, 1), Vec3(-1, 1, -1)).extent, box.extent)
    intercept[IllegalArgumentException](Box(Vec3(0, 0, 0), Vec3(1, 0, 1)))

  private val cylinder = Cylinder(Vec3(0, 0, 0), Vec3(0, 2, 0), 0.5)

  test("a cylinder: side, discs, and a ray along its axis from inside"):
    assertEquals(
      crossings(cylinder, ray(Vec3(0, 1, -5), Vec3(0, 0, 1))),
      List((4.5, Vec3(0, 0, -1)), (5.5, Vec3(0, 0, 1)))
    )
    assertEquals(
      crossings(cylinder, ray(Vec3(0.2, 5, 0), Vec3(0, -1, 0))),
      List((3.0, Vec3(0, 1, 0)), (5.0, Vec3(0, -1, 0)))
    )
    assertEquals(crossings(cylinder, ray(Vec3(0, 1, 0), Vec3(0, 1, 0))), List((1.0, Vec3(0, 1, 0))))

  test("an open cylinder has no discs: a ray down its axis passes through"):
    val open = cylinder.copy(open = true)
    assertEquals(crossings(open, ray(Vec3(0.2, 5, 0), Vec3(0, -1, 0))), Nil)
    // ...but it still bounds a solid (POV-Ray's inside test ignores `open`).
    assert(Shape.inside(open, Vec3(0, 1, 0)) && !Shape.inside(open, Vec3(0, 3, 0)))

  test("a grazing ray along a cylinder's side touches it at one point twice"):
    val found = crossings(cylinder, ray(Vec3(0.5, 1, -5), Vec3(0, 0, 1)))
    assert(found.length == 2 && found.forall((t, _) => near(t, 5)), found.toString)

  test("a cone: the side's normal leans by the slope, the wide disc and the point"):
    val cone  = Cone(Vec3(0, 0, 0), 1, Vec3(0, 1, 0), 0)
    val found = crossings(cone, ray(Vec3(-5, 0.5, 0), Vec3(1, 0, 0)))
    assertEquals(found.length, 2)
    assert(near(found.head._1, 4.5), found.toString)
    assert((found.head._2 - Vec3(-1, 1, 0).normalised.get).length < 1e-12, found.toString)
    // Up the axis: the disc at 3, then the point, touched at 4 (a double root of the side).
    assertEquals(
      crossings(cone, ray(Vec3(0, -3, 0), Vec3(0, 1, 0))).map(_._1).distinct,
      List(3.0, 4.0)
    )
    assertEquals(crossings(cone, ray(Vec3(0, -3, 0), Vec3(0, 1, 0))).head._2, Vec3(0, -1, 0))

  test("a cone's radii may grow either way along the axis"):
    val widening = Cone(Vec3(0, 0, 0), 0.5, Vec3(0, 2, 0), 1)
    val ts       = Shape.crossings(widening, ray(Vec3(-5, 1, 0), Vec3(1, 0, 0))).map(_.t)
    assertEquals(ts.map(t => Math.round(t * 1e9) / 1e9), List(4.25, 5.75))

  test("the torus's quartic: a ray through its centre line crosses the tube four times"):
    val torus = Torus(2, 0.5)
    val found = Shape.crossings(torus, ray(Vec3(-5, 0, 0), Vec3(1, 0, 0))).map(_.t)
    assertEquals(found.length, 4)
    List(2.5, 3.5, 6.5, 7.5)
      .zip(found)
      .foreach((want, got) => assert(near(want, got), found.toString))
    // The normal at the first crossing points out of the tube, back along the ray.
    assert(
      (Shape.crossings(torus, ray(Vec3(-5, 0, 0), Vec3(1, 0, 0))).head.normal - Vec3(
        -1,
        0,
        0
      )).length < 1e-9
    )

  test("the torus: through the hole misses, from above crosses twice, from far away stays exact"):
    val torus = Torus(2, 0.5)
    assertEquals(Shape.crossings(torus, ray(Vec3(0, 5, 0), Vec3(0, -1, 0))), Nil)
    assertEquals(
      Shape
        .crossings(torus, ray(Vec3(2, 5, 0), Vec3(0, -1, 0)))
        .map(_.t)
        .map(t => Math.round(t * 1e9) / 1e9),
      List(4.5, 5.5)
    )
    val far = Shape.crossings(torus, ray(Vec3(-1e4, 0, 0), Vec3(1, 0, 0))).map(_.t)
    assert(near(far.head, 1e4 - 2.5) && far.length == 4, far.toString)

  test("a ray a hair below the top of the tube crosses it twice on each side, close together"):
    val torus = Torus(2, 0.5)
    val found = Shape.crossings(torus, ray(Vec3(-5, 0.5 - 1e-6, 0), Vec3(1, 0, 0))).map(_.t)
    assertEquals(found.length, 4)
    assert(found.forall(t => Math.abs(t - 3) < 1e-2 || Math.abs(t - 7) < 1e-2), found.toString)

  test("inside tests: box and torus include their surface, spheres do not, a plane its far side"):
    assert(Shape.inside(box, Vec3(1, 0, 0)) && !Shape.inside(box, Vec3(1.000001, 0, 0)))
    assert(
      Shape.inside(Torus(2, 0.5), Vec3(2.5, 0, 0)) && !Shape.inside(Torus(2, 0.5), Vec3(0, 0, 0))
    )
    assert(!Shape.inside(Sphere(Vec3.Zero, 1), Vec3(1, 0, 0)))
    assert(Shape.inside(Plane.at(Vec3.UnitY, 0), Vec3(0, -1, 0)))
    assert(!Shape.inside(Plane.at(Vec3.UnitY, 0), Vec3(0, 1, 0)))
    assert(!Shape.inside(Triangle(Vec3.Zero, Vec3.UnitX, Vec3.UnitY), Vec3(0.1, 0.1, 0)))

  test("a placed shape: rays met in its own space, distances and normals brought back"):
    // A unit box scaled by 2, turned 90° about y and moved 10 along x.
    val placed = Placed(box, Placement(2, Vec3(0, 90, 0), Vec3(10, 0, 0)))
    val found  = Shape.crossings(placed, ray(Vec3(10, 0, -10), Vec3(0, 0, 1)))
    assertEquals(found.length, 2)
    assert(near(found(0).t, 8) && near(found(1).t, 12), found.toString)
    assert((found(0).normal - Vec3(0, 0, -1)).length < 1e-12, found.toString)
    assert(Shape.inside(placed, Vec3(11.5, 1.5, 1.5)) && !Shape.inside(placed, Vec3(12.5, 0, 0)))
    val b = Shape.bounds(placed).get
    assert(
      (b.lo - Vec3(8, -2, -2)).length < 1e-9 && (b.hi - Vec3(12, 2, 2)).length < 1e-9,
      b.toString
    )

  test("POV-Ray's rotation: x, then y, then z, each by the left-hand rule"):
    def turn(degrees: Vec3, p: Vec3) = Placement(rotate = degrees).transform.point(p)
    assert((turn(Vec3(0, 90, 0), Vec3.UnitX) - Vec3(0, 0, -1)).length < 1e-15)
    assert((turn(Vec3(90, 0, 0), Vec3.UnitY) - Vec3(0, 0, 1)).length < 1e-15)
    assert((turn(Vec3(0, 0, 90), Vec3.UnitX) - Vec3(0, 1, 0)).length < 1e-15)
    // Order: about x first, then y.
    assert((turn(Vec3(90, 90, 0), Vec3.UnitY) - Vec3(1, 0, 0)).length < 1e-15)

  test("bounds: CSG boxes come from the children"):
    val a = Sphere(Vec3(0, 0, 0), 1)
    val b = Sphere(Vec3(1, 0, 0), 1)
    assertEquals(
      Shape.bounds(Csg(CsgOperation.Union, Vector(a, b))),
      Some(Bounds(Vec3(-1, -1, -1), Vec3(2, 1, 1)))
    )
    assertEquals(
      Shape.bounds(Csg(CsgOperation.Intersection, Vector(a, b))),
      Some(Bounds(Vec3(0, -1, -1), Vec3(1, 1, 1)))
    )
    assertEquals(Shape.bounds(Csg(CsgOperation.Difference, Vector(a, b))), Shape.bounds(a))
    assertEquals(Shape.bounds(Csg(CsgOperation.Union, Vector(a, Plane.at(Vec3.UnitY, 0)))), None)
    assertEquals(
      Shape.bounds(Csg(CsgOperation.Intersection, Vector(a, Plane.at(Vec3.UnitY, 0)))),
      Shape.bounds(a)
    )

  test("an intersection holding a triangle is the part of the triangle inside the other children"):
    // A triangle has no inside (the reader allows it in a <union> only), so built in code an
    // intersection keeps none of the ball's surface and the part of the triangle within the ball,
    // as POV-Ray's intersection does: a disc of radius 1 in the plane z = 0.
    val ball     = Sphere(Vec3.Zero, 1)
    val sheet    = Triangle(Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0))
    val both     = Csg(CsgOperation.Intersection, Vector(ball, sheet))
    val straight = Ray(Vec3(0, 0, -5), Vec3.UnitZ)
    assertEquals(Shape.distance(both, straight), 5.0) // the sheet at z = 0, not the ball at 4
    val hit = Shape.hitAt(both, straight, 5.0)
    assertEquals((hit.leaf, hit.normal), (1, -Vec3.UnitZ))
    assertEquals(Shape.distance(both, Ray(Vec3(0.5, 0.5, -5), Vec3.UnitZ)), 5.0)
    // Outside the ball the sheet is cut away; along the sheet's plane nothing is hit.
    assertEquals(Shape.distance(both, Ray(Vec3(2, 0, -5), Vec3.UnitZ)), Double.PositiveInfinity)
    assertEquals(Shape.distance(both, Ray(Vec3(-5, 0, 0.5), Vec3.UnitX)), Double.PositiveInfinity)
    assert(!Shape.inside(both, Vec3.Zero))

  test("a union used to cut cuts with its outer surface only, as POV-Ray inverts it"):
    // A box less the union of a ball and the half-space y < 0. POV-Ray's difference is the
    // intersection of the box with the union's complement, the intersection of the ball's and
    // the half-space's complements: of the union's surfaces only those outside its other child
    // are cut faces. Straight down at x = 0.5: the box's top (y = 2), then the ball's surface
    // (y = 0.866, above the half-space). The half-space's plane inside the ball (y = 0) and the
    // ball's lower half inside the half-space (y = −0.866) are the union's inner surfaces, in
    // empty space once cut: not crossings. The box's bottom lies inside the cutter.
    val ball  = Sphere(Vec3.Zero, 1)
    val below = Plane.at(Vec3.UnitY, 0)
    val cut   = Csg(
      CsgOperation.Difference,
      Vector(Box(Vec3(-2, -2, -2), Vec3(2, 2, 2)), Csg(CsgOperation.Union, Vector(ball, below)))
    )
    val down    = ray(Vec3(0.5, 5, 0), Vec3(0, -1, 0))
    val heights = Shape.crossings(cut, down).map(c => 5 - c.t)
    assertEquals(heights.length, 2, heights)
    assert(near(heights(0), 2) && near(heights(1), Math.sqrt(0.75)), heights)
    // The same through the kernel. A cutter that is an intersection keeps what it keeps uncut:
    // POV-Ray inverts it into the merge of its children's complements, which keeps a child's
    // crossing where the point is inside no other complement, that is inside every other child.
    // Under the lens of the ball and the half-space y > 0: the ball's upper half and the plane
    // within the ball, not the ball's lower half.
    val b = CrossingBuffer()
    assertEquals(Kernel.collect(cut, 0.5, 5, 0, 0, -1, 0, b, 0), 2)
    val above = Plane.at(-Vec3.UnitY, 0)
    val lens  = Csg(
      CsgOperation.Difference,
      Vector(
        Box(Vec3(-2, -2, -2), Vec3(2, 2, 2)),
        Csg(CsgOperation.Intersection, Vector(ball, above))
      )
    )
    val seen = Shape.crossings(lens, down).map(c => 5 - c.t)
    assertEquals(seen.length, 4, seen) // top, ball (y > 0), plane, bottom
    assert(near(seen(1), Math.sqrt(0.75)) && near(seen(2), 0), seen)
    assertEquals(Kernel.collect(lens, 0.5, 5, 0, 0, -1, 0, b, 0), 4)
    // Inverted twice (a difference inside a difference's cutter), a union is a merge: its
    // children's crossings inside one another go. A box less (a slab less the union of two
    // overlapping balls): of the balls only the outer surface of the pair is a face.
    val pair =
      Csg(CsgOperation.Union, Vector(Sphere(Vec3(-0.3, 0, 0), 1), Sphere(Vec3(0.3, 0, 0), 1)))
    val slab  = Csg(CsgOperation.Difference, Vector(Box(Vec3(-3, -0.5, -3), Vec3(3, 0.5, 3)), pair))
    val nest  = Csg(CsgOperation.Difference, Vector(Box(Vec3(-2, -2, -2), Vec3(2, 2, 2)), slab))
    val along = ray(Vec3(-5, 0, 0), Vec3.UnitX)
    val xs    = Shape.crossings(nest, along).map(c => c.t - 5)
    // Along the slab's middle only what the pair carved out of it is left of the box: the pair's
    // outer surface at −1.3 and 1.3, not the balls' inner surfaces at −0.7 and 0.7.
    assertEquals(xs.length, 2, xs)
    assert(near(xs(0), -1.3) && near(xs(1), 1.3), xs)
    assertEquals(Kernel.collect(nest, -5, 0, 0, 1, 0, 0, b, 0), 2)
    // The solids themselves are unchanged: inside the box and outside the union.
    assert(Shape.inside(cut, Vec3(1.5, 0.5, 1.5)) && !Shape.inside(cut, Vec3(0.5, 0.5, 0)))

  test("a union holding a triangle or a mesh cuts as POV-Ray's patch objects do"):
    // POV-Ray's triangle has no inside, inverted or not, so the complement of a union holding one
    // (the intersection of its children's complements) is empty: the box's faces all vanish, and
    // of the cutter only the part of the triangle inside the box and outside the ball is left.
    val box   = Box(Vec3(-2, -2, -2), Vec3(2, 2, 2))
    val ball  = Sphere(Vec3.Zero, 1)
    val sheet = Triangle(Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0))
    val cut   =
      Csg(CsgOperation.Difference, Vector(box, Csg(CsgOperation.Union, Vector(ball, sheet))))
    val beside  = ray(Vec3(1.5, 0.5, -5), Vec3.UnitZ)
    val through = ray(Vec3(0, 0, -5), Vec3.UnitZ)
    assertEquals(Shape.crossings(cut, beside).map(_.t), List(5.0)) // the sheet, not the box at 3
    assertEquals(Shape.crossings(cut, through), Nil) // the sheet inside the ball is cut too
    assert(!Shape.inside(cut, Vec3(1.5, 1.5, 1.5)), "inside an empty complement")
    // A mesh of two faces is, in the twin, a union of two triangles: inverted, each face's
    // crossing would lie inside the other's empty complement, so nothing is left.
    val square = Mesh(
      IArray(-10.0, -10, 0, 10, -10, 0, 10, 10, 0, -10, 10, 0),
      IArray(0, 1, 2, 0, 2, 3)
    )
    val meshCut =
      Csg(CsgOperation.Difference, Vector(box, Csg(CsgOperation.Union, Vector(ball, square))))
    assertEquals(Shape.crossings(meshCut, beside), Nil)
    // The kernel agrees, and with a solid cutter alone the complement is still the outside.
    val b = CrossingBuffer()
    assertEquals(Kernel.collect(cut, 1.5, 0.5, -5, 0, 0, 1, b, 0), 1)
    assertEquals(b.t(0), 5.0)
    assertEquals(Kernel.collect(cut, 0, 0, -5, 0, 0, 1, b, 0), 0)
    assertEquals(Kernel.collect(meshCut, 1.5, 0.5, -5, 0, 0, 1, b, 0), 0)
    assert(!Kernel.inside(cut, 1.5, 1.5, 1.5))
    val solid = Csg(CsgOperation.Difference, Vector(box, Csg(CsgOperation.Union, Vector(ball))))
    assertEquals(Shape.crossings(solid, through).map(_.t), List(3.0, 4.0, 6.0, 7.0))
    assert(Shape.inside(solid, Vec3(1.5, 1.5, 1.5)) && Kernel.inside(solid, 1.5, 1.5, 1.5))

  test("a cutting intersection holding a far triangle still cuts with its other children"):
    // A ball less (a cone ∩ a union holding only a triangle far away). Inverted, the intersection
    // is the merge of its children's complements, and the union's is empty: the cone's whole
    // surface is kept, beyond the box the two children share (empty here). So the ball is less
    // the cone, and a ray down into the hole meets the cone's base disc at z = 0, not the ball's
    // far side (POV-Ray draws the same; the common box culled the cone: the hole looked empty).
    val cone = Cone(Vec3.Zero, 0.6, Vec3(0, 0, 2), 0)
    val far  = Csg(
      CsgOperation.Union,
      Vector(Triangle(Vec3(9, 0, 0), Vec3(10, 0, 0), Vec3(9, 1, 0)))
    )
    val cut = Csg(
      CsgOperation.Difference,
      Vector(Sphere(Vec3.Zero, 1), Csg(CsgOperation.Intersection, Vector(cone, far)))
    )
    val down = ray(Vec3(0.2, 0, 5), Vec3(0, 0, -1))
    assertEquals(Shape.crossings(cut, down).headOption.map(_.t), Some(5.0))
    val b = CrossingBuffer()
    assert(Kernel.collect(cut, 0.2, 0, 5, 0, 0, -1, b, 0) > 0)
    assertEquals(b.t(0), 5.0)
    // A difference whose first child holds the patch: inverted, the merge of that child's (empty)
    // complement and the cone, so its box must hold the cone too.
    val patchFirst = Csg(CsgOperation.Difference, Vector(far, cone))
    assert(Shape.bounds(patchFirst).exists(_.contains(Vec3(0.2, 0, 0.5))))

  test("Polynomial.roots finds every real root of a quartic in an interval, in order"):
    // (x − 1)(x − 2)(x − 3)(x − 4) = x⁴ − 10x³ + 35x² − 50x + 24
    val c     = IArray(24.0, -50.0, 35.0, -10.0, 1.0)
    val roots = Polynomial.roots(c, 0, 10)
    // All four, not only the first: zip alone would pass on a prefix.
    assertEquals(roots.length, 4, roots)
    List(1.0, 2.0, 3.0, 4.0).zip(roots).foreach((a, b) => assert(near(a, b), s"$a vs $b in $roots"))
    assertEquals(Polynomial.roots(c, 1.5, 2.5).length, 1)
    assertEquals(Polynomial.roots(IArray(1.0, 0.0, 1.0), -10, 10), Nil) // x² + 1
