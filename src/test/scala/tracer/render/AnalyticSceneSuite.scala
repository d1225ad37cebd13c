package tracer.render

import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.Scenes.{camera, matte}

/** Tiny scenes whose pixels are known from the shading formulas of rendering.md. */
class AnalyticSceneSuite extends munit.FunSuite:

  private def render(
      scene: Scene,
      x: Int = 8,
      y: Int = 6,
      depth: Int = 5,
      mode: ShadingMode = ShadingMode.Full
  ) =
    Renderer.render(scene, CameraConfig(1, 1, 0.75, x, y, depth, mode), threads = 2)

  private def samples(b: Bitmap, x: Int, y: Int) = (0 until 3).map(b.sample(x, y, _)).toList
  private def bytes(c: Colour)                   = List(c.r, c.g, c.b).map(Colour.quantise(_, 255))

  // A wall z = 0 facing the camera, lit head-on by a light straight behind the eye: cos φ = 1 at
  // the centre. The tests that look at one pixel render a 1 × 1 picture, whose one ray goes
  // through the centre of the image plane and meets the wall at the origin.
  private val wall = Plane.at(-Vec3.UnitZ, 0)

  test("the renderer's ray offset is the one the geometry tests check for shadow acne"):
    assertEquals(Shading.Epsilon, tracer.testkit.Offsets.Ray)

  test("an empty scene is the background everywhere"):
    val b = render(Scene(camera, background = Colour(0.2, 0.4, 0.6)))
    for x <- 0 until 8; y <- 0 until 6 do assertEquals(samples(b, x, y), List(51, 102, 153))

  test("a lit matte point is C ⊙ L · diffuse · |rn · Sd|"):
    val light = Light(Vec3(0, 0, -10), Colour(0.5, 1, 1))
    val scene = Scene(
      camera,
      lights = List(light),
      objects = List(matte(wall, Colour(1, 0.5, 0.25), diffuse = 0.8))
    )
    val b = render(scene, x = 1, y = 1)
    // The single pixel's ray hits (0, 0, 0); Sd = (0, 0, −1) from S0 = (0, 0, −ε).
    assertEquals(samples(b, 0, 0), bytes(Colour(0.5 * 0.8, 0.5 * 0.8, 0.25 * 0.8)))

  test("the cosine factor follows the angle to the light"):
    val light = Light(Vec3(0, 10, 0) + Vec3(0, 0, -10), Colour.White)
    val b   = render(Scene(camera, lights = List(light), objects = List(matte(wall))), x = 1, y = 1)
    val cos = 10 / Math.sqrt(200 - 20 * 1e-4 + 1e-8) // |rn · Sd| with S0 ε in front of the wall
    assertEquals(samples(b, 0, 0), bytes(Colour.grey(cos)))

  test("light from several sources adds up, and an over-bright sum keeps its hue"):
    val lights = List(
      Light(Vec3(0, 0, -10), Colour(1.5, 0.75, 0)),
      Light(Vec3(0, 0, -20), Colour(0.5, 0.25, 0.5))
    )
    val b = render(Scene(camera, lights = lights, objects = List(matte(wall))), x = 1, y = 1)
    // Sum (2, 1, 0.5) is divided by 2.
    assertEquals(samples(b, 0, 0), List(255, 128, 64))

  test("a blocker between the point and the light casts a hard shadow"):
    val light   = Light(Vec3(0, 0, -10))
    val blocker = matte(Sphere(Vec3(0, 0, -7), 0.5), Colour.Black)
    val lit = render(Scene(camera, lights = List(light), objects = List(matte(wall))), x = 1, y = 1)
    val shaded = render(
      Scene(
        camera.copy(location = Vec3(0, 0, -2)),
        lights = List(light),
        objects = List(matte(wall), blocker)
      ),
      x = 1,
      y = 1
    )
    assertEquals(samples(lit, 0, 0), List(255, 255, 255))
    assertEquals(samples(shaded, 0, 0), List(0, 0, 0))

  test("a shape beyond the light casts no shadow"):
    val light       = Light(Vec3(0, 0, -1))
    val behindLight = matte(Sphere(Vec3(0, 0, -3), 0.5), Colour.Black)
    val scene       = Scene(
      camera.copy(location = Vec3(0, 0, -0.5)),
      lights = List(light),
      objects = List(matte(wall), behindLight)
    )
    assertEquals(samples(render(scene, x = 1, y = 1), 0, 0), List(255, 255, 255))

  test("there is no ambient term: a surface no light reaches is black"):
    val b =
      render(Scene(camera, background = Colour.White, objects = List(matte(wall))), x = 1, y = 1)
    assertEquals(samples(b, 0, 0), List(0, 0, 0))

  test("quick mode is C · |rn · Rd|: no lights, no shadows, no diffuse factor"):
    val scene = Scene(camera, objects = List(matte(wall, Colour(1, 0.5, 0), diffuse = 0.1)))
    assertEquals(
      samples(render(scene, x = 1, y = 1, mode = ShadingMode.Quick), 0, 0),
      List(255, 128, 0)
    )

  // A mirror wall facing a red wall behind the camera; a white light near the eye.
  private val mirrorScene =
    val mirror  = matte(wall, Colour.Black, reflection = 0.5)
    val redWall = matte(Plane.at(Vec3.UnitZ, -20), Colour(1, 0, 0))
    Scene(
      camera,
      background = Colour(0, 0, 1),
      lights = List(Light(Vec3(0, 0, -10))),
      objects = List(mirror, redWall)
    )

  test("a mirror adds reflection · the colour seen along the reflected ray"):
    // The reflected ray goes back along −z to the red wall, lit head-on: red 1, so 0.5 in the mirror.
    assertEquals(samples(render(mirrorScene, x = 1, y = 1), 0, 0), List(128, 0, 0))

  test("depth 0 means no reflection at all"):
    assertEquals(samples(render(mirrorScene, x = 1, y = 1, depth = 0), 0, 0), List(0, 0, 0))

  test("reflections stop after depth bounces"):
    // Two parallel half-mirrors facing each other with the camera between: each bounce halves.
    val light = Light(Vec3(0, 0, -1), Colour.White)
    val front = matte(wall, Colour.Black, reflection = 0.5)
    val back  = matte(Plane.at(Vec3.UnitZ, -10), Colour(0.4, 0.4, 0.4), reflection = 0.5)
    val scene = Scene(camera, lights = List(light), objects = List(front, back))
    def level(depth: Int) = samples(render(scene, x = 1, y = 1, depth = depth), 0, 0).head
    assertEquals(level(0), 0)
    assertEquals(level(1), Colour.quantise(0.5 * 0.4, 255))
    assertEquals(level(2), level(1)) // the second bounce meets the black front mirror: adds 0·…
    // Each bounce adds half of what it sees: the back wall's 0.4 at odd bounces, the black front
    // mirror's 0 at even ones. Depth 3: 0.5·(0.4 + 0.5·(0 + 0.5·0.4)) = 0.25; depth 4 the same;
    // depth 5: 0.5·(0.4 + 0.25·(0.4 + 0.25·0.4)) = 0.2625.
    assertEquals(level(3), Colour.quantise(0.25, 255))
    assertEquals(level(4), level(3))
    assertEquals(level(5), Colour.quantise(0.2625, 255))

  test("a texture gives the surface colour at the hit"):
    val texture = Texture(
      Bitmap.tabulate(2, 2)((x, y) => if x == 0 && y == 1 then Colour(0, 1, 0) else Colour(1, 0, 1))
    )
    val tri   = Triangle(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(-1, 1, 0))
    val scene =
      Scene(camera, objects = List(SceneObject(tri, Surface(pigment = Pigment.Textured(texture)))))
    // Zoom 5 puts the 2 × 2 image plane on the triangle's plane: the image spans x, y in −1..1.
    val b = Renderer.render(scene, CameraConfig(5, 2, 2, 4, 4, mode = ShadingMode.Quick))
    // Bottom-left pixel of the image shows the bottom-left texel (T0 is the texture's bottom-left).
    assert(b.sample(0, 3, 1) > 200 && b.sample(0, 3, 0) == 0, samples(b, 0, 3).toString)
    assert(b.sample(0, 0, 0) > 200 && b.sample(0, 0, 1) == 0, samples(b, 0, 0).toString)
