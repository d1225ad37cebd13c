package tracer.render

import tracer.geometry.Plane
import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.Scenes.matte

/** n × n samples a pixel (rendering.md, Antialiasing). */
class AntialiasSuite extends munit.FunSuite:

  test("sample offsets are (i + 0.5)/n: the centre for n = 1, a regular grid otherwise"):
    assertEquals(Renderer.sampleOffsets(1), Vector(0.5))
    assertEquals(Renderer.sampleOffsets(2), Vector(0.25, 0.75))
    assertEquals(Renderer.sampleOffsets(4), Vector(0.125, 0.375, 0.625, 0.875))
    for n <- 1 to 16 do
      val offsets = Renderer.sampleOffsets(n)
      assertEquals(offsets.length, n)
      assert(offsets.forall(o => o > 0 && o < 1), offsets.toString)
      offsets.zip(offsets.reverse).foreach((a, b) => assertEqualsDouble(a + b, 1.0, 1e-15))

  // The camera one unit above a white floor y = 0, looking level: the horizon splits the image
  // in two halves, sky (black background) above and floor below.
  private val level = Camera(Vec3(0, 1, -5), Vec3(0, 1, 0))
  private val floor = matte(Plane.at(Vec3.UnitY, 0), Colour.White)

  test("one sample a pixel is the ray through the pixel's centre"):
    val scene      = Scene(level, objects = List(floor))
    val config     = CameraConfig(1, 1, 0.75, 16, 12, mode = ShadingMode.Quick, samples = 1)
    val projection = Projection(level, config)
    val image      = Renderer.render(scene, config)
    // In quick mode a floor sample is |rn · Rd| = |Rd.y|; a sky sample is black.
    def seen(x: Double, y: Double) =
      Colour.quantise(Math.max(0, -projection.ray(x, y).direction.y), 255)
    for y <- 0 until 12; x <- 0 until 16 do
      assertEquals(image.sample(x, y, 0), seen(x + 0.5, y + 0.5), s"pixel ($x, $y)")
    // A sample at the pixel's corner would give another picture: the check above can fail.
    val corner = for y <- 0 until 12; x <- 0 until 16 yield image.sample(x, y, 0) - seen(x, y)
    assert(corner.exists(_ != 0), "the corners see what the centres see")

  test("a pixel straddling the horizon is the mean of what its samples see"):
    val scene  = Scene(level, objects = List(floor))
    val config = CameraConfig(1, 1, 1, 1, 1, mode = ShadingMode.Quick, samples = 4)
    // In quick mode a floor sample is |rn · Rd| = |Rd.y|; a sky sample is black.
    val projection = Projection(level, config)
    val offsets    = Renderer.sampleOffsets(4)
    val expected   =
      (for j <- offsets; i <- offsets yield Math.max(0, -projection.ray(i, j).direction.y)).sum / 16
    assert(expected > 0.05, expected.toString)
    assertEquals(Renderer.render(scene, config).sample(0, 0, 0), Colour.quantise(expected, 255))

  test("each sample is brought into range before the samples are averaged"):
    // The two floor samples are over-bright red (about 9.6, 0, 0); each becomes (1, 0, 0) before the
    // mean with two black sky samples: 0.5, so 128. Averaging first would give 255.
    val light = Light(Vec3(0, 5, 0), Colour.grey(10))
    val scene = Scene(
      level,
      lights = List(light),
      objects = List(matte(Plane.at(Vec3.UnitY, 0), Colour(1, 0, 0)))
    )
    val b = Renderer.render(scene, CameraConfig(1, 1, 1, 1, 1, samples = 2))
    assertEquals((0 until 3).map(b.sample(0, 0, _)), Vector(128, 0, 0))

  test("antialiasing is deterministic across thread counts"):
    val scene  = Scene(level, lights = List(Light(Vec3(1, 2, -4))), objects = List(floor))
    val config = CameraConfig(1, 1, 0.75, 31, 17, samples = 3)
    assertEquals(
      Renderer.render(scene, config, threads = 1),
      Renderer.render(scene, config, threads = 2)
    )

  test("floating-point output holds the mean of the unclamped samples, not encoded"):
    // As above: two floor samples of about (9.6, 0, 0) and two black: their mean, unclamped,
    // is about 4.8, where the 8-bit picture holds 0.5.
    val light = Light(Vec3(0, 5, 0), Colour.grey(10))
    val scene = Scene(
      level,
      lights = List(light),
      objects = List(matte(Plane.at(Vec3.UnitY, 0), Colour(1, 0, 0)))
    )
    val config     = CameraConfig(1, 1, 1, 1, 1, samples = 2)
    val projection = Projection(level, config)
    // Lambert at each floor sample: 10 · |rn · Sd| with Sd towards the light.
    val floorSamples = for
      j <- Renderer.sampleOffsets(2)
      i <- Renderer.sampleOffsets(2)
      r = projection.ray(i, j)
      if r.direction.y < 0
    yield
      val p = r.at(-r.origin.y / r.direction.y)
      10 * (light.location - p).normalised.get.y
    assertEquals(floorSamples.length, 2)
    val raster = Renderer.renderRaster(scene, config.copy(encoding = tracer.image.Encoding.Srgb))
    assertEqualsDouble(raster(0, 0).r, floorSamples.sum / 4, 1e-5)
    assertEquals(raster(0, 0).g, 0.0)
    assert(raster(0, 0).r > 4, raster(0, 0).toString)

  test("floating-point output is deterministic across thread counts and bands"):
    val scene  = Scene(level, lights = List(Light(Vec3(1, 2, -4))), objects = List(floor))
    val config = CameraConfig(1, 1, 0.75, 31, 17, samples = 3)
    val whole  = Renderer.renderRaster(scene, config, threads = 1)
    assertEquals(Renderer.renderRaster(scene, config, threads = 2), whole)
    val bands = List(0 until 5, 5 until 17).map(b => Renderer.renderRaster(scene, config, band = b))
    assertEquals(tracer.image.Raster.stack(bands), whole)
