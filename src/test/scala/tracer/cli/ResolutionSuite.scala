package tracer.cli

/** The W/H/X/Y rule of cli.md, with its table of examples. */
class ResolutionSuite extends munit.FunSuite:

  private def resolve(
      w: Option[Double] = None,
      h: Option[Double] = None,
      x: Option[Int] = None,
      y: Option[Int] = None,
      sceneW: Double = 1,
      sceneH: Double = 0.75
  ) = Resolution.resolve(w, h, x, y, sceneW, sceneH)

  test("nothing given: W 1, H 0.75, X 640, Y 480"):
    assertEquals(resolve(), Resolution(1, 0.75, 640, 480))

  test("-x 800: W 1, H 0.75, X 800, Y 600"):
    assertEquals(resolve(x = Some(800)), Resolution(1, 0.75, 800, 600))

  test("-x 800 -y 800: W 1, H 1, X 800, Y 800"):
    assertEquals(resolve(x = Some(800), y = Some(800)), Resolution(1, 1, 800, 800))

  test("-w 2 -x 100 -y 50: W 2, H 1, X 100, Y 50"):
    assertEquals(resolve(w = Some(2), x = Some(100), y = Some(50)), Resolution(2, 1, 100, 50))

  test("-w 2 -h 2 -x 100 -y 50: as given, distorted"):
    assertEquals(resolve(Some(2), Some(2), Some(100), Some(50)), Resolution(2, 2, 100, 50))

  test("three given: the missing pixel count from W/X = H/Y"):
    assertEquals(resolve(w = Some(4), h = Some(3), y = Some(300)), Resolution(4, 3, 400, 300))
    assertEquals(resolve(w = Some(4), h = Some(3), x = Some(100)), Resolution(4, 3, 100, 75))

  test("three given: the missing world size from W/X = H/Y"):
    assertEquals(resolve(h = Some(3), x = Some(400), y = Some(300)), Resolution(4, 3, 400, 300))

  test("fewer than three: the scene's W, then H, then X = 640 fill in"):
    assertEquals(resolve(y = Some(100), sceneW = 2, sceneH = 1), Resolution(2, 1, 200, 100))
    assertEquals(resolve(h = Some(2), y = Some(100)), Resolution(1, 2, 50, 100))
    assertEquals(resolve(w = Some(3), h = Some(1)), Resolution(3, 1, 640, 213))
    assertEquals(resolve(w = Some(2)), Resolution(2, 0.75, 640, 240))
    assertEquals(resolve(h = Some(1), sceneW = 2), Resolution(2, 1, 640, 320))

  test("a computed pixel count rounds halves up and is at least 1"):
    assertEquals(resolve(w = Some(4), h = Some(1), x = Some(2)).rows, 1)     // 0.5 rounds up to 1
    assertEquals(resolve(w = Some(4), h = Some(3), x = Some(2)).rows, 2)     // 1.5 rounds up to 2
    assertEquals(resolve(w = Some(1000), h = Some(1), x = Some(10)).rows, 1) // 0.01 becomes 1
