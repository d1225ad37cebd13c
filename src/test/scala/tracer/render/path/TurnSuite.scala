package tracer.render.path

/** [[Turn]]'s cosine and sine of 2πu against StrictMath's, within the rounding of StrictMath's argument. */
class TurnSuite extends munit.FunSuite:

  private val edges = List(0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, Math.nextDown(1.0))
  private val us    = edges ++ (0 until 100000).map(k => (k + 0.5) / 100000) ++
    edges.flatMap(u => List(Math.nextUp(u), Math.nextDown(Math.max(u, Double.MinPositiveValue))))

  test(
    "cos 2πu and sin 2πu within 2e-15 of StrictMath's (whose 2πu is rounded, up to 8.9e-16 off) over [0, 1), the octant edges included"
  ):
    for u <- us.filter(u => u >= 0 && u < 1) do
      val phi = 2 * Math.PI * u
      assert(Math.abs(Turn.cos(u) - StrictMath.cos(phi)) <= 2e-15, s"cos at $u")
      assert(Math.abs(Turn.sin(u) - StrictMath.sin(phi)) <= 2e-15, s"sin at $u")

  test("a unit vector at every angle, exactly 1 and 0 at the quarter turns"):
    for u <- us.filter(u => u >= 0 && u < 1) do
      val (c, s) = (Turn.cos(u), Turn.sin(u))
      assert(Math.abs(c * c + s * s - 1) <= 1e-15, s"at $u")
    assertEquals((Turn.cos(0), Turn.sin(0)), (1.0, 0.0))
    assertEquals((Turn.cos(0.25), Turn.sin(0.25)), (-0.0, 1.0))
    assertEquals((Turn.cos(0.5), Turn.sin(0.5)), (-1.0, -0.0))
    assertEquals((Turn.cos(0.75), Turn.sin(0.75)), (0.0, -1.0))
