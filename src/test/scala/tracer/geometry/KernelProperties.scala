package tracer.geometry

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll
import tracer.math.{Placement, Vec3}
import tracer.testkit.Generators.unitVec

/** The solids' kernel on plain doubles gives what the reference functions of [[Shape]] give, bit
  * for bit: distances, every crossing with its normal and leaf, inside tests, the quartic's roots.
  */
class KernelProperties extends ScalaCheckSuite:

  private val coordinate = Gen.choose(-3.0, 3.0)
  private val point      = for x <- coordinate; y <- coordinate; z <- coordinate yield Vec3(x, y, z)
  // Coordinates on a grid: rays along faces and edges, through corners, parallel to slabs.
  private val gridPoint =
    for x <- Gen.choose(-2, 2); y <- Gen.choose(-2, 2); z <- Gen.choose(-2, 2)
    yield Vec3(x, y, z)
  private val size = Gen.choose(0.2, 2.5)

  private val sphere = for c <- point; r <- size yield Sphere(c, r)
  private val box    = Gen.oneOf(
    for c <- point; dx <- size; dy <- size; dz <- size yield Box(c, c + Vec3(dx, dy, dz)),
    for c <- gridPoint; d <- Gen.choose(1, 2) yield Box(c, c + Vec3(d, d, d))
  )
  private val cone =
    for
      b    <- Gen.oneOf(point, gridPoint)
      axis <- Gen.oneOf(
        unitVec,
        Gen.oneOf(Vec3.UnitX, Vec3.UnitY, Vec3.UnitZ, -Vec3.UnitX, -Vec3.UnitY, -Vec3.UnitZ)
      )
      h     <- size
      r0    <- Gen.oneOf(Gen.const(0.0), size)
      r1    <- size
      open  <- Gen.oneOf(true, false)
      equal <- Gen.oneOf(true, false)
    yield if equal then Cylinder(b, b + axis * h, r1, open) else Cone(b, r0, b + axis * h, r1, open)
  private val torus    = for r <- size; f <- Gen.choose(0.1, 0.9) yield Torus(r, r * f)
  private val triangle =
    Gen.zip(point, point, point).retryUntil(Triangle.isProper.tupled).map(Triangle(_, _, _))
  private val plane     = for n <- unitVec; d <- coordinate yield Plane.at(n, d)
  private val placement =
    for s <- Gen.choose(0.3, 3.0); r <- point; t <- point yield Placement(s, r * 60, t)
  private val primitive: Gen[Shape] = Gen.oneOf(sphere, box, cone, torus)
  private val placed: Gen[Shape]    = for s <- primitive; p <- placement yield Placed(s, p)
  private val operation             = Gen.oneOf(CsgOperation.values.toIndexedSeq)
  private val meshUnion: Gen[Shape] =
    Gen.listOfN(4, Gen.oneOf(triangle, sphere)).map(ts => Csg(CsgOperation.Union, ts.toVector))
  // A union holding triangles may cut too: its complement is not its outside (Shape.holdsPatch).
  // Combinations nested up to `depth` deep, a nested one anywhere among its siblings: as a
  // later child of a difference it is inverted, and inside another such child inverted twice.
  private def csgOf(depth: Int): Gen[Shape] =
    val leaf  = Gen.frequency(3 -> primitive, 3 -> placed, 1 -> meshUnion)
    val child = if depth == 0 then leaf else Gen.frequency(3 -> leaf, 1 -> csgOf(depth - 1))
    for
      op       <- operation
      n        <- Gen.choose(1, 3)
      children <- Gen.listOfN(n, child)
      moved    <- Gen.option(placement)
    yield
      val tree = Csg(op, children.toVector)
      moved.fold(tree: Shape)(Placed(tree, _))
  private val csg: Gen[Shape]   = csgOf(2)
  private val shape: Gen[Shape] =
    Gen.frequency(
      2 -> primitive,
      2 -> placed,
      4 -> csg,
      1 -> meshUnion,
      1 -> triangle,
      1 -> plane
    )

  private val ray: Gen[Ray] = Gen.oneOf(
    for o <- point.map(_ * 2); target <- point
    yield Ray(o, (target - o).normalisedOr(Vec3.UnitX)),
    for o <- gridPoint.map(_ * 2); d <- Gen.oneOf(Vec3.UnitX, -Vec3.UnitY, Vec3.UnitZ)
    yield Ray(o, d)
  )

  private def bits(x: Double) = java.lang.Double.doubleToRawLongBits(x)

  private def collected(s: Shape, r: Ray): List[(Long, Long, Long, Long, Int)] =
    val b = CrossingBuffer()
    val o = r.origin
    val d = r.direction
    // Start past 0, as a nested call does.
    val end = Kernel.collect(s, o.x, o.y, o.z, d.x, d.y, d.z, b, 3)
    (3 until end).toList.map(k =>
      (bits(b.t(k)), bits(b.nx(k)), bits(b.ny(k)), bits(b.nz(k)), b.leaf(k))
    )

  private def reference(s: Shape, r: Ray): List[(Long, Long, Long, Long, Int)] =
    Shape
      .crossings(s, r)
      .map(c => (bits(c.t), bits(c.normal.x), bits(c.normal.y), bits(c.normal.z), c.leaf))

  property("collect gives Shape.crossings: every t, normal and leaf, bit for bit, in order"):
    forAll(shape, Gen.listOfN(20, ray)) { (s, rays) =>
      rays.foreach(r => assertEquals(collected(s, r), reference(s, r), s"$s $r"))
    }

  property("collect without normals gives the same ts and leaves"):
    forAll(shape, Gen.listOfN(20, ray)) { (s, rays) =>
      rays.foreach { r =>
        val b   = CrossingBuffer()
        val o   = r.origin
        val d   = r.direction
        val end = Kernel.collect(s, o.x, o.y, o.z, d.x, d.y, d.z, b, 0, normals = false)
        val got = (0 until end).toList.map(k => (bits(b.t(k)), b.leaf(k)))
        assertEquals(got, reference(s, r).map(c => (c._1, c._5)), s"$s $r")
      }
    }

  property("distance is Shape.distance, bit for bit"):
    forAll(shape, Gen.listOfN(20, ray)) { (s, rays) =>
      val b = CrossingBuffer()
      rays.foreach { r =>
        val o = r.origin
        val d = r.direction
        assertEquals(
          bits(Kernel.distance(s, o.x, o.y, o.z, d.x, d.y, d.z, b)),
          bits(Shape.distance(s, r)),
          s"$s $r"
        )
      }
    }

  property("distance within a cutoff is Shape.distance there, and beyond it when farther"):
    forAll(shape, Gen.listOfN(20, ray), Gen.choose(0.0, 12.0)) { (s, rays, cutoff) =>
      val b = CrossingBuffer()
      rays.foreach { r =>
        val o    = r.origin
        val d    = r.direction
        val want = Shape.distance(s, r)
        // The reference's own distance as the cutoff too: a tie must still be found.
        List(cutoff, want).foreach { c =>
          val got = Kernel.distance(s, o.x, o.y, o.z, d.x, d.y, d.z, b, c)
          if want <= c then assertEquals(bits(got), bits(want), s"$s $r cutoff $c")
          else assert(got > c, s"$s $r cutoff $c: $got, the reference $want")
        }
      }
    }

  property("blocks is Shape.distance below the limit, the reference's own distance included"):
    forAll(shape, Gen.listOfN(20, ray), Gen.choose(0.0, 12.0)) { (s, rays, limit) =>
      val b = CrossingBuffer()
      rays.foreach { r =>
        val o    = r.origin
        val d    = r.direction
        val want = Shape.distance(s, r)
        // At the reference's distance itself a shape does not block; just beyond it, it does.
        List(limit, want, Math.nextUp(want)).filter(_ < Double.PositiveInfinity).foreach { l =>
          val got = Kernel.blocks(s, o.x, o.y, o.z, d.x, d.y, d.z, b, l)
          assertEquals(got, want < l, s"$s $r limit $l: the reference's distance $want")
        }
      }
    }

  property("firstCrossing is the first of Shape.crossings: t, normal and leaf, bit for bit"):
    forAll(shape, Gen.listOfN(20, ray)) { (s, rays) =>
      rays.foreach { r =>
        val b   = CrossingBuffer()
        val o   = r.origin
        val d   = r.direction
        val end = Kernel.firstCrossing(s, o.x, o.y, o.z, d.x, d.y, d.z, b, 2)
        val got = (2 until end).toList.map(k =>
          (bits(b.t(k)), bits(b.nx(k)), bits(b.ny(k)), bits(b.nz(k)), b.leaf(k))
        )
        assertEquals(got, reference(s, r).take(1), s"$s $r")
      }
    }

  property("a torus's crossings on rays passing near its tube, bit for bit"):
    // Rays through points 0.9 to 1.3 tube radii from the tube's circle: the pre-test that skips
    // the root finder on rays more than 1.1 radii away must never skip a crossing.
    val near =
      for
        tr    <- torus
        angle <- Gen.choose(0.0, 2 * Math.PI)
        turn  <- Gen.choose(0.0, 2 * Math.PI)
        rho   <- Gen.choose(0.9, 1.3)
        d     <- unitVec
        back  <- Gen.choose(0.5, 6.0)
      yield
        val c   = Vec3(Math.cos(angle) * tr.major, 0, Math.sin(angle) * tr.major)
        val out =
          Vec3(Math.cos(angle) * Math.cos(turn), Math.sin(turn), Math.sin(angle) * Math.cos(turn))
        val p = c + out * (rho * tr.minor)
        (tr, Ray(p - d * back, d))
    forAll(Gen.listOfN(20, near)) { cases =>
      cases.foreach((tr, r) => assertEquals(collected(tr, r), reference(tr, r), s"$tr $r"))
    }

  property("inside is Shape.inside"):
    forAll(shape, Gen.listOfN(20, Gen.oneOf(point, gridPoint))) { (s, ps) =>
      ps.foreach(p => assertEquals(Kernel.inside(s, p.x, p.y, p.z), Shape.inside(s, p), s"$s $p"))
    }

  property("cones along an axis: their shortcut's crossings and inside tests, bit for bit"):
    // The shortcut of Cone.axial leaves out products with zeros; only zeros' signs could tell.
    // So: rays from the axis, from the discs' planes and from the grid, along the axis, across
    // it and anywhere, and points on the axis, on the discs and on the side.
    val axial = for
      b    <- gridPoint
      k    <- Gen.choose(0, 2)
      s    <- Gen.oneOf(1.0, -1.0)
      h    <- Gen.oneOf(Gen.choose(1, 3).map(_.toDouble), size)
      r0   <- Gen.oneOf(Gen.const(0.0), Gen.const(1.0), size)
      r1   <- Gen.oneOf(Gen.const(1.0), size)
      open <- Gen.oneOf(true, false)
    yield
      val axis = Vec3(if k == 0 then s else 0, if k == 1 then s else 0, if k == 2 then s else 0)
      Cone(b, r0, b + axis * h, r1, open)
    def on(c: Cone): Gen[Vec3] =
      val a = c.axis
      // Across the axis: the unit vector along the next axis round.
      val across = Vec3(a.z.abs, a.x.abs, a.y.abs)
      for
        along <- Gen.oneOf(Gen.const(0.0), Gen.const(c.height), Gen.choose(-1.0, 3.0))
        out   <- Gen.oneOf(Gen.const(0.0), Gen.const(c.baseRadius), Gen.choose(-2.0, 2.0))
      yield c.base + a * along + across * out
    val axes  = Gen.oneOf(Vec3.UnitX, Vec3.UnitY, Vec3.UnitZ, -Vec3.UnitX, -Vec3.UnitY, -Vec3.UnitZ)
    val cases = for
      c  <- axial
      os <- Gen.listOfN(20, Gen.oneOf(on(c), gridPoint, point))
      ds <- Gen.listOfN(20, Gen.oneOf(axes, unitVec))
    yield (c, os.zip(ds).map(Ray(_, _)))
    forAll(cases) { (c, rays) =>
      rays.foreach { r =>
        assertEquals(collected(c, r), reference(c, r), s"$c $r")
        assertEquals(
          Kernel.inside(c, r.origin.x, r.origin.y, r.origin.z),
          Shape.inside(c, r.origin)
        )
        val o = r.origin
        val d = r.direction
        val b = CrossingBuffer()
        assertEquals(
          bits(Kernel.distance(c, o.x, o.y, o.z, d.x, d.y, d.z, b)),
          bits(Shape.distance(c, r)),
          s"$c $r"
        )
      }
      assert(c.axial >= 0, c)
    }

  test(
    "a cone along an axis, from an origin whose offset from its base overflows, as the reference"
  ):
    // A reviewer's counterexamples to the shortcut without its finiteness check: the general
    // arithmetic's 0 · ∞ makes NaN and no crossing, where the shortcut found two, and an inside
    // test that said true.
    val far = Cone(Vec3(-1e308, 0, 0), 1e200, Vec3(-1e308, 0, 1), 1e200)
    val ray = Ray(Vec3(1e308, 0, -1), Vec3.UnitZ)
    assertEquals(far.axial, 2)
    assertEquals(collected(far, ray), reference(far, ray))
    assertEquals(
      bits(Kernel.distance(far, 1e308, 0, -1, 0, 0, 1, CrossingBuffer())),
      bits(Shape.distance(far, ray))
    )
    val thin =
      Cone(
        Vec3(-1e308, 0, 0),
        0,
        Vec3(-1e308, 0, 1),
        java.lang.Double.longBitsToDouble(0x1e56a09e667d4a38L),
        open = true
      )
    val p = Vec3(1e308, 0, 1 + 5e-11)
    assertEquals(Kernel.inside(thin, p.x, p.y, p.z), Shape.inside(thin, p))

  property("hitAt is the first crossing: its t, point, normal facing the ray, leaf and side"):
    forAll(shape, Gen.listOfN(20, ray)) { (s, rays) =>
      rays.foreach { r =>
        val t       = Shape.distance(s, r)
        val general = s match
          case _: (Sphere | Plane | Triangle | Mesh)  => false
          case _: (Box | Cone | Torus | Placed | Csg) => true
        Shape.crossings(s, r).headOption.filter(_ => general && t < Double.PositiveInfinity) match
          case Some(c) =>
            val front = c.normal.dot(r.direction) < 0
            val n     = if front then c.normal else -c.normal
            assertEquals(Shape.hitAt(s, r, t), Hit(c.t, r.at(c.t), n, c.leaf, front), s"$s $r")
          case None => ()
      }
    }

  property("Polynomial.ulp is Math.ulp, bit for bit, for doubles of every kind"):
    val edges = List(
      0.0,
      -0.0,
      Double.MinPositiveValue,
      java.lang.Double.MIN_NORMAL,
      Double.MaxValue,
      Double.PositiveInfinity,
      Double.NegativeInfinity,
      Double.NaN,
      java.lang.Double.longBitsToDouble(53L << 52),
      java.lang.Double.longBitsToDouble((53L << 52) - 1),
      java.lang.Double.longBitsToDouble(52L << 52),
      java.lang.Double.longBitsToDouble(0x7fefffffffffffffL)
    )
    val anyDouble = Gen.oneOf(
      Gen.long.map(java.lang.Double.longBitsToDouble),
      Gen.choose(-10.0, 10.0),
      Gen.oneOf(edges ++ edges.map(-_))
    )
    forAll(anyDouble) { x =>
      assertEquals(bits(Polynomial.ulp(x)), bits(Math.ulp(x)), s"$x")
    }

  property("rootsInto finds Polynomial.roots' roots, bit for bit"):
    val coefficient = Gen.frequency(4 -> Gen.choose(-10.0, 10.0), 1 -> Gen.const(0.0))
    forAll(Gen.listOfN(5, coefficient), Gen.choose(-5.0, 0.0), Gen.choose(0.0, 5.0)) {
      (c, lo, hi) =>
        val s = new Array[Double](Polynomial.ScratchSize)
        c.zipWithIndex.foreach((x, k) => s(k) = x)
        val n     = Polynomial.rootsInto(s, 0, 5, lo, hi, Polynomial.ScratchLevel)
        val found = (0 until n).map(k => bits(s(Polynomial.ScratchLevel + Polynomial.RootsAt + k)))
        assertEquals(found.toList, Polynomial.roots(IArray.from(c), lo, hi).map(bits))
    }

  property("rootsInto with `wanted` roots finds the first of them, bit for bit"):
    val coefficient = Gen.frequency(4 -> Gen.choose(-10.0, 10.0), 1 -> Gen.const(0.0))
    forAll(Gen.listOfN(5, coefficient), Gen.choose(0.0, 5.0), Gen.choose(1, 3)) { (c, hi, wanted) =>
      val s = new Array[Double](Polynomial.ScratchSize)
      c.zipWithIndex.foreach((x, k) => s(k) = x)
      val n     = Polynomial.rootsInto(s, 0, 5, 0, hi, Polynomial.ScratchLevel, wanted)
      val found = (0 until n).map(k => bits(s(Polynomial.ScratchLevel + Polynomial.RootsAt + k)))
      assertEquals(found.toList, Polynomial.roots(IArray.from(c), 0, hi).map(bits).take(wanted))
    }

  test("a double root at 0 on [0, 0] is one root, as `distinct` has it (0.0 and -0.0 alike)"):
    // A case a random seed found: p = x², whose derivative's root is -0.0.
    val s = new Array[Double](Polynomial.ScratchSize)
    s(2) = 1.615990584939829e-5
    val n     = Polynomial.rootsInto(s, 0, 5, 0, 0.0, Polynomial.ScratchLevel, 3)
    val found = (0 until n).map(k => bits(s(Polynomial.ScratchLevel + Polynomial.RootsAt + k)))
    assertEquals(found.toList, Polynomial.roots(IArray(0.0, 0.0, s(2), 0.0, 0.0), 0, 0.0).map(bits))
    assertEquals(n, 1)

  property("polynomials with known roots: each found within 1e-9"):
    // (x − r1)(x − r2)(x − r3)(x − r4) on [0, 10], its roots apart by more than 0.1.
    val root = Gen.choose(0.05, 9.95)
    forAll(Gen.listOfN(4, root).suchThat(r => r.sorted.sliding(2).forall(p => p(1) - p(0) > 0.1))) {
      rs =>
        val c = rs.foldLeft(IArray(1.0)) { (p, r) =>
          IArray.tabulate(p.length + 1)(k =>
            (if k > 0 then p(k - 1) else 0.0) - r * (if k < p.length then p(k) else 0.0)
          )
        }
        val found = Polynomial.roots(c, 0, 10)
        assertEquals(found.length, 4, s"$rs: $found")
        found.zip(rs.sorted).foreach((x, r) => assert(Math.abs(x - r) < 1e-9, s"$x for $r"))
    }

  property("the plane test refuses by the signs exactly what the division's sign refuses"):
    // Values where the sign test and the division could part: zeros of both signs, infinities,
    // NaN, the smallest subnormals (a quotient that underflows to 0) and ordinary ones.
    val special = Gen.oneOf(
      0.0,
      -0.0,
      Double.MinPositiveValue,
      -Double.MinPositiveValue,
      1e-300,
      -1e-300,
      Double.MaxValue,
      Double.PositiveInfinity,
      Double.NegativeInfinity,
      Double.NaN
    )
    val value = Gen.frequency(1 -> special, 3 -> Gen.choose(-5.0, 5.0))
    forAll(value, value, value, value, value, value) { (n, d, o, dir, other, scale) =>
      // A plane of normal (n, 0, 0) at distance d, a ray from (o, other, scale) along (dir, 1, 0):
      // the old formula, (D − Pn·O) / (Pn·d) when Pn·d ≠ 0 and the quotient is positive.
      val vd       = n * dir + 0.0 * 1.0 + 0.0 * 0.0
      val expected =
        if vd == 0 then Double.PositiveInfinity
        else
          val t = (d - (n * o + 0.0 * other + 0.0 * scale)) / vd
          if t > 0 then t else Double.PositiveInfinity
      val got = Kernel.planeT(n, 0.0, 0.0, d, o, other, scale, dir, 1.0, 0.0)
      assertEquals(
        java.lang.Double.doubleToLongBits(got),
        java.lang.Double.doubleToLongBits(expected)
      )
    }
