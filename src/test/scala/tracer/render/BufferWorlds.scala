package tracer.render

import org.scalacheck.Gen
import tracer.geometry.{
  Box,
  Cone,
  Csg,
  CsgOperation,
  Cylinder,
  Mesh,
  Placed,
  Plane,
  Shape,
  Sphere,
  Torus,
  Triangle
}
import tracer.math.{Placement, Vec3}
import tracer.testkit.Generators.unitVec

/** Random shapes for the buffers' properties ([[LightBufferProperties]], [[EyeBufferProperties]]):
  * spheres, triangles, bumpy grids of faces, solids and combinations and planes, placed anywhere
  * or on a coarse grid, so that directions along a buffer's edges and faces are common.
  */
object BufferWorlds:
  /** A coordinate in [−6, 6]. */
  val small = Gen.choose(-6.0, 6.0)

  /** A point anywhere in the cube of [[small]] coordinates. */
  val point = for x <- small; y <- small; z <- small yield Vec3(x, y, z)

  /** A point of the integer grid in [−4, 4]³. */
  val gridPoint = for x <- Gen.choose(-4, 4); y <- Gen.choose(-4, 4); z <- Gen.choose(-4, 4)
  yield Vec3(x, y, z)

  /** A size for a solid. */
  val size = Gen.choose(0.2, 2.5)

  /** A bumpy grid of squares (two faces each) at height about y, n × n squares. */
  def terrain(n: Int, y: Double, bump: Double): Mesh =
    val vertices =
      IArray.from(for
        i <- 0 to n; j <- 0 to n
        c <- List(-4 + 8.0 * i / n, y + bump * Math.sin(i * 1.7 + j * 0.9), -4 + 8.0 * j / n)
      yield c)
    def at(i: Int, j: Int) = i * (n + 1) + j
    val corners            = IArray.from(for
      i <- 0 until n; j <- 0 until n
      c <- List(at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))
    yield c)
    Mesh(vertices, corners)

  /** A proper triangle, its corners anywhere or on the grid. */
  val triangle = Gen
    .oneOf(point, gridPoint)
    .flatMap { p =>
      Gen.zip(Gen.const(p), Gen.oneOf(point, gridPoint), Gen.oneOf(point, gridPoint))
    }
    .retryUntil(Triangle.isProper.tupled)
    .map(Triangle(_, _, _))

  /** A placement: scaled, rotated, moved. */
  val placement: Gen[Placement] =
    for s <- Gen.choose(0.3, 2.0); r <- point; t <- point yield Placement(s, r * 18, t)

  /** A shape of the general route: a box, a cylinder, a cone, a placed torus, a difference. */
  val general: Gen[Shape] = Gen.oneOf(
    for c <- Gen.oneOf(point, gridPoint); d <- size yield Box(c, c + Vec3(d, d * 0.5, d)),
    for b <- point; axis <- unitVec; h <- size; r <- size; open <- Gen.oneOf(true, false)
    yield Cylinder(b, b + axis * h, r * 0.5, open),
    for b <- point; axis <- unitVec; h <- size; r <- size yield Cone(b, 0.0, b + axis * h, r),
    for r <- size; p <- placement yield Placed(Torus(r, r * 0.3), p),
    for c <- point; d <- size
    yield Csg(CsgOperation.Difference, Vector(Box(c, c + Vec3(d, d, d)), Sphere(c, d * 0.7)))
  )

  /** Any bounded or unbounded shape, meshes and planes included. */
  val shape: Gen[Shape] = Gen.frequency(
    4 -> (for c <- Gen.oneOf(point, gridPoint); r <- Gen.choose(0.05, 1.5) yield Sphere(c, r)),
    4 -> triangle,
    2 -> (for n <- Gen.choose(2, 12); y <- small; b <- Gen.choose(0.0, 1.0)
    yield terrain(n, y, b)),
    2 -> general,
    1 -> Gen.choose(-6, 6).map(d => Plane.at(Vec3.UnitY, d))
  )
