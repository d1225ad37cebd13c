package tracer.render

import tracer.geometry.{Csg, CsgOperation, Plane, Sphere, Triangle}
import tracer.image.{Colour, Raster}
import tracer.math.Vec3
import tracer.scene.*
import tracer.testkit.Scenes.matte

/** Version 4 in Whitted mode (docs/rendering.md, Emission and fade): a glowing surface adds its
  * emission where it is seen from its outward side and lights nothing; a light's fade scales
  * what it gives by A(d) = 2 / (1 + (d/D)ⁿ), d from the hit to the light (an area light's
  * centre). Pixels are read from [[Renderer.renderRaster]], unclamped.
  */
class Version4WhittedSuite extends munit.FunSuite:

  // The floor y = 0, seen from above by a camera looking straight down (up = +z).
  private val floor = Plane.at(Vec3.UnitY, 0)
  private val above = Camera(Vec3(0, 4, 0), Vec3.Zero, up = Vec3.UnitZ)

  private def raster(
      scene: Scene,
      x: Int,
      y: Int,
      mode: ShadingMode = ShadingMode.Full,
      depth: Int = 5
  ): Raster =
    val c = scene.camera
    Renderer.renderRaster(scene, CameraConfig(c.zoom, c.width, c.height, x, y, depth, mode), 2)

  private def assertColour(obtained: Colour, expected: Colour, tolerance: Double)(using
      munit.Location
  ): Unit =
    val off = List(obtained.r - expected.r, obtained.g - expected.g, obtained.b - expected.b)
    assert(
      off.forall(d => Math.abs(d) <= tolerance * Math.max(1, expected.max)),
      s"$obtained is not within $tolerance of $expected"
    )

  test("a point light with fade over a plane gives C·kd·A(d)·cos θ at every pixel"):
    val light  = Light(Vec3(0.3, 1.5, -0.2), Colour(2, 1, 0.5), fade = Some(Fade(1.2, 2)))
    val kd     = 0.8
    val scene  = Scene(above, lights = List(light), objects = List(matte(floor, diffuse = kd)))
    val (x, y) = (16, 12)
    val config = CameraConfig(above.zoom, above.width, above.height, x, y)
    val image  = raster(scene, x, y)
    val rays   = Projection(above, config)
    for i <- 0 until x; j <- 0 until y do
      val ray = rays.ray(i + 0.5, j + 0.5)
      val p   = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y)
      val d   = (light.location - p).length
      val cos = (light.location.y - p.y) / d
      val a   = 2 / (1 + Math.pow(d / 1.2, 2))
      // Float pixels; S0 lies 1e-4 above p, which moves cos θ by less than 1e-5.
      assertColour(image(i, j), light.colour * (kd * a * cos), 2e-5)

  test("fade at known distances: A(D) = 1, A(2D) = 2/5 for n = 2, A(3D) = 1/2 for n = 1"):
    // One pixel, its ray straight down onto the point under the light: cos θ = 1, d = h exactly.
    val cases = List((2.0, 2.0, 2.0, 1.0), (1.0, 2.0, 2.0, 0.4), (1.0, 3.0, 1.0, 0.5))
    for (distance, h, power, expected) <- cases do
      val light = Light(Vec3(0, h, 0), Colour(0.5, 1, 0.25), fade = Some(Fade(distance, power)))
      val scene = Scene(above, lights = List(light), objects = List(matte(floor)))
      // d is measured from the hit point, as POV-Ray does, not from S0 1e-4 above it (that
      // would move A(2D) by 4e-5).
      assertColour(raster(scene, 1, 1)(0, 0), light.colour * expected, 1e-6)

  test("without fade a light does not fall off; A(d) decides only where fade is given"):
    val near  = Light(Vec3(0, 1, 0), Colour.grey(0.5))
    val far   = Light(Vec3(0, 30, 0), Colour.grey(0.5))
    val image =
      (l: Light) => raster(Scene(above, lights = List(l), objects = List(matte(floor))), 1, 1)(0, 0)
    assertEquals(image(near), Colour.grey(0.5))
    assertEquals(image(far), Colour.grey(0.5))

  test("an area light's fade takes d from its centre, once, as POV-Ray's does"):
    // A 3 × 3 grid 2 wide, nothing in the way: every sub-light reaches the point, so the share
    // is 1 and the light is C · A(|centre − p|) · cos θ (the direction is the centre's).
    val area  = AreaLight(Vec3(2, 0, 0), Vec3(0, 0, 2), 3, 3)
    val light = Light(Vec3(0, 1, 0), Colour.White, Some(area), Some(Fade(0.5, 2)))
    val scene = Scene(above, lights = List(light), objects = List(matte(floor)))
    // A(1) with D = 0.5: 2 / (1 + 4) = 0.4. The mean of the sub-lights' own A would be 0.3.
    assertColour(raster(scene, 1, 1)(0, 0), Colour.grey(0.4), 1e-6)

  test("fade scales the highlight with the diffuse light"):
    val shiny               = SceneObject(floor, Surface(diffuse = 0, phong = 1, phongSize = 1))
    val light               = (f: Option[Fade]) => Light(Vec3(0, 2, 0), Colour.White, fade = f)
    def at(f: Option[Fade]) =
      raster(Scene(above, lights = List(light(f)), objects = List(shiny)), 1, 1)(0, 0)
    val plain = at(None)
    assert(plain.r > 0.5, s"$plain")
    assertColour(at(Some(Fade(1, 2))), plain * 0.4, 1e-6)

  private val glow = Colour(2.5, 0.5, 0)

  private def glowing(shape: tracer.geometry.Shape, diffuse: Double = 1) =
    SceneObject(shape, Surface(diffuse = diffuse, emission = glow))

  test("an emitting sphere seen from outside shows its emission, unclamped, on a black ground"):
    val scene =
      Scene(Camera(Vec3(0, 0, -5), Vec3.Zero), objects = List(glowing(Sphere(Vec3.Zero, 1))))
    val image = raster(scene, 8, 6)
    // The four centre pixels look at the sphere, the corners miss it.
    for (i, j) <- List((3, 2), (4, 3), (3, 3), (4, 2)) do assertEquals(image(i, j), glow)
    assertEquals(image(0, 0), Colour.Black)

  test("the emission is added after shading: a lit emitter is its shading plus E"):
    val light                  = Light(Vec3(0, 0, -10), Colour.grey(0.5))
    val ball                   = Sphere(Vec3.Zero, 1)
    def centre(o: SceneObject) =
      raster(
        Scene(Camera(Vec3(0, 0, -5), Vec3.Zero), lights = List(light), objects = List(o)),
        1,
        1
      )(0, 0)
    val shaded = centre(matte(ball, diffuse = 0.5))
    assertEquals(shaded, Colour.grey(0.25))
    assertColour(centre(glowing(ball, diffuse = 0.5)), shaded + glow, 1e-7)

  test("an emitting sphere's inside is not lit by it, nor is anything else"):
    // The eye inside a glowing sphere sees its inner side: no glow. A matte floor beside a
    // glowing ball outside stays black: emission lights nothing in Whitted mode.
    val inside =
      Scene(Camera(Vec3(0, 0, -0.5), Vec3.Zero), objects = List(glowing(Sphere(Vec3.Zero, 2))))
    val seen = raster(inside, 4, 3)
    for i <- 0 until 4; j <- 0 until 3 do assertEquals(seen(i, j), Colour.Black)
    val beside = Scene(
      above,
      objects = List(glowing(Sphere(Vec3(0, 0.5, 5), 0.5)), matte(floor))
    )
    val floorSeen = raster(beside, 4, 3)
    for i <- 0 until 4; j <- 0 until 3 do assertEquals(floorSeen(i, j), Colour.Black)

  test("a triangle glows on the side its normal Pn points to only; a cut face glows into the hole"):
    // Pn = (t1 − t0) × (t2 − t0) = (0, 2, 0) × (2, 0, 0) points to −z, towards the camera; the
    // second triangle has two corners swapped.
    val towards                = Triangle(Vec3(-1, -1, 0), Vec3(-1, 1, 0), Vec3(1, -1, 0))
    val away                   = Triangle(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(-1, 1, 0))
    val camera                 = Camera(Vec3(0, 0, -5), Vec3.Zero)
    def centre(o: SceneObject) = raster(Scene(camera, objects = List(o)), 4, 4)(1, 2)
    assertEquals(centre(glowing(towards)), glow)
    assertEquals(centre(glowing(away)), Colour.Black)
    // A ball with a ball taken out of its front, along the eye's axis: the ray meets the cut face
    // (the removed ball's far side, leaf 1), whose outward normal points out of the whole, into
    // the hole and at the eye, so it glows.
    val bowl =
      Csg(CsgOperation.Difference, Vector(Sphere(Vec3(0, 0, 0), 1), Sphere(Vec3(0, 0, -1), 1)))
    val cut = SceneObject(bowl, Surface(), Vector(Surface(), Surface(emission = glow)))
    assertEquals(raster(Scene(camera, objects = List(cut)), 1, 1)(0, 0), glow)

  test("quick mode ignores the emission; a mirror shows it"):
    val camera = Camera(Vec3(0, 0, -5), Vec3.Zero)
    val ball   = Sphere(Vec3.Zero, 1)
    val quick  =
      (o: SceneObject) => raster(Scene(camera, objects = List(o)), 1, 1, ShadingMode.Quick)(0, 0)
    assertEquals(quick(glowing(ball)), quick(matte(ball)))
    // The eye looks at a mirror at z = 2 that shows a glowing ball behind the eye at z = −8;
    // with -r 0 the mirror passes nothing on.
    val mirror = SceneObject(Plane.at(-Vec3.UnitZ, 2), Surface(diffuse = 0, reflection = 1))
    val behind = glowing(Sphere(Vec3(0, 0, -8), 1))
    assertEquals(raster(Scene(camera, objects = List(mirror, behind)), 1, 1)(0, 0), glow)
    assertEquals(
      raster(Scene(camera, objects = List(mirror, behind)), 1, 1, depth = 0)(0, 0),
      Colour.Black
    )
