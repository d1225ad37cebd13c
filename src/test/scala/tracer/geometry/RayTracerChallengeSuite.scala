package tracer.geometry

import tracer.math.Vec3

/** The Ray Tracer Challenge's feature files for cylinders, cones and CSG (`cylinders.feature`,
  * `cones.feature`, `csg.feature`), ported to our shapes. Their cylinder is infinite along y with
  * radius 1, cut to minimum < y < maximum; ours is finite from `base` to `cap`, so theirs is a long
  * open one and theirs with limits 1 and 2 runs from (0, 1, 0) to (0, 2, 0). Their cone is
  * double (x² + z² = y²), which here is a union of two cones meeting at the origin. Where the book
  * counts a t < 0, the ray starts further back; where the two rules differ (the rim, which POV-Ray
  * and we count as part of the side, the book does not), the comment says so.
  */
class RayTracerChallengeSuite extends munit.FunSuite:

  private val far                   = 1e4
  private val infinite              = Cylinder(Vec3(0, -far, 0), Vec3(0, far, 0), 1, open = true)
  private val limited               = Cylinder(Vec3(0, 1, 0), Vec3(0, 2, 0), 1, open = true)
  private val capped                = Cylinder(Vec3(0, 1, 0), Vec3(0, 2, 0), 1)
  private def ray(o: Vec3, d: Vec3) = Ray(o, d.normalised.get)
  private def ts(s: Shape, r: Ray)  = Shape.crossings(s, r).map(_.t)
  private def near(a: Double, b: Double) = Math.abs(a - b) < 1e-4

  /** The distinct distances (a ray through a rim crosses the side and the disc at one point). */
  private def distinct(s: Shape, r: Ray) =
    ts(s, r).foldLeft(List.empty[Double])((seen, t) =>
      if seen.exists(near(_, t)) then seen else t :: seen
    )

  test("cylinders.feature: a ray misses a cylinder"):
    for (o, d) <- List(
        (Vec3(1, 0, 0), Vec3(0, 1, 0)),
        (Vec3(0, 0, 0), Vec3(0, 1, 0)),
        (Vec3(0, 0, -5), Vec3(1, 1, 1))
      )
    do assertEquals(ts(infinite, ray(o, d)), Nil, s"$o $d")

  test("cylinders.feature: a ray strikes a cylinder"):
    for (o, d, t0, t1) <- List(
        (Vec3(1, 0, -5), Vec3(0, 0, 1), 5.0, 5.0),
        (Vec3(0, 0, -5), Vec3(0, 0, 1), 4.0, 6.0),
        (Vec3(0.5, 0, -5), Vec3(0.1, 1, 1), 6.80798, 7.08872)
      )
    do
      val found = ts(infinite, ray(o, d))
      assert(found.length == 2 && near(found(0), t0) && near(found(1), t1), s"$o $d: $found")

  test("cylinders.feature: the normal vector on a cylinder"):
    for (p, n) <- List(
        (Vec3(1, 0, 0), Vec3(1, 0, 0)),
        (Vec3(0, 5, -1), Vec3(0, 0, -1)),
        (Vec3(0, -2, 1), Vec3(0, 0, 1)),
        (Vec3(-1, 1, 0), Vec3(-1, 0, 0))
      )
    do
      // A ray coming in along the normal meets the side first at p.
      val c = Shape.crossings(infinite, Ray(p + n * 3, -n)).head
      assert(near(c.t, 3) && (c.normal - n).length < 1e-12, s"$p: $c")

  test("cylinders.feature: intersecting a constrained cylinder"):
    for (o, d, count) <- List(
        (Vec3(0, 1.5, 0), Vec3(0.1, 1, 0), 0),
        (Vec3(0, 3, -5), Vec3(0, 0, 1), 0),
        (Vec3(0, 0, -5), Vec3(0, 0, 1), 0),
        // The book excludes the rims y = 1 and y = 2; POV-Ray (z ≥ 0 and z ≤ 1 in its unit
        // cylinder) and we include them, so a ray along a rim crosses there.
        (Vec3(0, 2, -5), Vec3(0, 0, 1), 2),
        (Vec3(0, 1, -5), Vec3(0, 0, 1), 2),
        (Vec3(0, 1.5, -2), Vec3(0, 0, 1), 2)
      )
    do assertEquals(ts(limited, ray(o, d)).length, count, s"$o $d")

  test("cylinders.feature: intersecting the caps of a closed cylinder"):
    for (o, d) <- List(
        (Vec3(0, 3, 0), Vec3(0, -1, 0)),
        (Vec3(0, 3, -2), Vec3(0, -1, 2)),
        (Vec3(0, 4, -2), Vec3(0, -1, 1)), // through the rim: side and disc at one point
        (Vec3(0, 0, -2), Vec3(0, 1, 2)),
        (Vec3(0, -1, -2), Vec3(0, 1, 1)) // through the rim
      )
    do assertEquals(distinct(capped, ray(o, d)).length, 2, s"$o $d")

  test("cylinders.feature: the normal vector on a cylinder's end caps"):
    for (p, n) <- List(
        (Vec3(0, 1, 0), Vec3(0, -1, 0)),
        (Vec3(0.5, 1, 0), Vec3(0, -1, 0)),
        (Vec3(0, 1, 0.5), Vec3(0, -1, 0)),
        (Vec3(0, 2, 0), Vec3(0, 1, 0)),
        (Vec3(0.5, 2, 0), Vec3(0, 1, 0)),
        (Vec3(0, 2, 0.5), Vec3(0, 1, 0))
      )
    do
      val c = Shape.crossings(capped, Ray(p + n * 3, -n)).head
      assert(near(c.t, 3) && c.normal == n, s"$p: $c")

  /** The book's double cone x² + z² = y², cut at |y| ≤ `reach`, closed or not. */
  private def double(reach: Double, open: Boolean) = Csg(
    CsgOperation.Union,
    Vector(
      Cone(Vec3.Zero, 0, Vec3(0, reach, 0), reach, open),
      Cone(Vec3.Zero, 0, Vec3(0, -reach, 0), reach, open)
    )
  )

  test("cones.feature: intersecting a cone with a ray"):
    val cone = double(far, open = true)
    for (o, d, t0, t1) <- List(
        (Vec3(0, 0, -5), Vec3(0, 0, 1), 5.0, 5.0),
        (Vec3(0, 0, -5), Vec3(1, 1, 1), 8.66025, 8.66025),
        (Vec3(1, 1, -5), Vec3(-0.5, -1, 1), 4.55006, 49.44994)
      )
    do
      // Through the apex, both halves meet the ray: every crossing is at the book's t.
      val found = ts(cone, ray(o, d))
      assert(found.nonEmpty && near(found.head, t0) && near(found.last, t1), s"$o $d: $found")
      assert(found.forall(t => near(t, t0) || near(t, t1)), s"$o $d: $found")

  test("cones.feature: a ray parallel to one of its halves crosses it once"):
    // The book gives t = 0.35355, which is −c/(2b) where its linear case needs −c/b: the point
    // there, (0, 0.25, −0.75), is off the cone. The crossing is at t = √2/2, at (0, 0.5, −0.5).
    val found = ts(double(far, open = true), ray(Vec3(0, 0, -1), Vec3(0, 1, 1)))
    assertEquals(found.length, 1)
    assert(near(found.head, Math.sqrt(2) / 2), found.toString)

  test("cones.feature: intersecting a cone's end caps"):
    val cone = double(0.5, open = false)
    // The book's third ray starts at y = 0 and counts crossings behind it; ours starts below.
    for (o, d, count) <- List(
        (Vec3(0, 0, -5), Vec3(0, 1, 0), 0),
        (Vec3(0, 0, -0.25), Vec3(0, 1, 1), 2),
        (Vec3(0, -5, -0.25), Vec3(0, 1, 0), 4)
      )
    do assertEquals(ts(cone, ray(o, d)).length, count, s"$o $d")

  test("cones.feature: the normal vector on a cone"):
    val cone = double(far, open = true)
    // The book's (1, 1, 1) is not on the cone; (1, √2, 1) is, in the same direction round it.
    for (p, n) <- List(
        (Vec3(1, Math.sqrt(2), 1), Vec3(1, -Math.sqrt(2), 1)),
        (Vec3(-1, -1, 0), Vec3(-1, 1, 0))
      )
    do
      val unit = n.normalised.get
      val c    = Shape.crossings(cone, Ray(p + unit * 1e-3, -unit)).head
      assert((c.normal - unit).length < 1e-9, s"$p: $c")

  private val unitSphere = Sphere(Vec3.Zero, 1)
  private val cube       = Box(Vec3(-1, -1, -1), Vec3(1, 1, 1))

  test("csg.feature: a ray misses a CSG object"):
    assertEquals(
      ts(Csg(CsgOperation.Union, Vector(unitSphere, cube)), ray(Vec3(0, 2, -5), Vec3(0, 0, 1))),
      Nil
    )

  test("csg.feature: a ray hits a CSG object, each crossing naming its child"):
    val csg =
      Csg(
        CsgOperation.Union,
        Vector(unitSphere, Placed(unitSphere, tracer.math.Placement(translate = Vec3(0, 0, 0.5))))
      )
    val found = Shape.crossings(csg, ray(Vec3(0, 0, -5), Vec3(0, 0, 1)))
    // The book's union is POV-Ray's merge, which drops inner surfaces; the scene format's union is
    // POV-Ray's union, which keeps them: the outer two are the book's, 4 on s1 and 6.5 on s2.
    assertEquals(found.map(c => (c.t, c.leaf)), List((4.0, 0), (4.5, 1), (6.0, 0), (6.5, 1)))

  test("csg.feature: the rule of each operation, through two overlapping spheres"):
    // s1 at the origin, s2 moved 0.5 along z: along z the ray crosses s1 at 4 and 6, s2 at 4.5
    // and 6.5. The book's table: intersection keeps a hit inside the other child; difference a
    // left hit outside the right and a right hit inside the left.
    val s2                     = Sphere(Vec3(0, 0, 0.5), 1)
    val r                      = ray(Vec3(0, 0, -5), Vec3(0, 0, 1))
    def kept(op: CsgOperation) =
      Shape.crossings(Csg(op, Vector(unitSphere, s2)), r).map(c => (c.t, c.leaf))
    assertEquals(kept(CsgOperation.Intersection), List((4.5, 1), (6.0, 0)))
    assertEquals(kept(CsgOperation.Difference), List((4.0, 0), (4.5, 1)))
