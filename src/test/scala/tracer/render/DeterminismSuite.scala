package tracer.render

import tracer.image.Colour
import tracer.geometry.*
import tracer.math.{Placement, Vec3}
import tracer.scene.*
import tracer.testkit.Scenes.{camera, matte}

/** The picture depends on the scene and the configuration only, never on the thread count. */
class DeterminismSuite extends munit.FunSuite:

  private val scene = Scene(
    camera,
    background = Colour(0.1, 0.1, 0.3),
    lights = List(Light(Vec3(-3, 4, -4)), Light(Vec3(3, 2, -5), Colour(0.3, 0.3, 0.5))),
    objects = List(
      matte(Plane.at(Vec3.UnitY, -1), Colour.grey(0.7), reflection = 0.4),
      matte(Sphere(Vec3(-0.6, 0, 0.5), 1), Colour(0.9, 0.3, 0.2), reflection = 0.3),
      matte(Sphere(Vec3(1, -0.4, -0.4), 0.6), Colour.grey(0.9), diffuse = 0.3, reflection = 0.7)
    )
  )
  private val config = CameraConfig(1, 1, 0.75, 97, 61, samples = 2)

  // Version 2: glass, highlights and an area light.
  private val glassy = scene.copy(
    lights = Light(
      Vec3(-3, 4, -4),
      area = Some(AreaLight(Vec3(1, 0, 0), Vec3(0, 0, 1), 4, 3))
    ) :: scene.lights.tail.toList,
    objects = scene.objects :+ SceneObject(
      Sphere(Vec3(0.2, -0.2, -1.5), 0.5),
      Surface(0.1, 0.1, transmit = 0.9, ior = 1.5, phong = 0.8, specular = 0.3)
    )
  )

  // Version 3, built in code as in the REPL: a glass difference with a cut face of its own, a
  // placed torus with a checker, and a cylinder.
  private val solid = scene.copy(
    objects = scene.objects ++ List(
      SceneObject(
        Placed(
          Csg(
            CsgOperation.Difference,
            Vector(Box(Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5)), Sphere(Vec3.Zero, 0.65))
          ),
          Placement(rotate = Vec3(20, 35, 0), translate = Vec3(0.9, 0.2, -1.2))
        ),
        Surface(0.2, 0.1, transmit = 0.8, ior = 1.4),
        Vector(
          Surface(0.2, 0.1, transmit = 0.8, ior = 1.4),
          Surface(0.9, pigment = Pigment.Solid(Colour(0.2, 0.4, 0.9)))
        )
      ),
      SceneObject(
        Placed(
          Torus(0.5, 0.15),
          Placement(rotate = Vec3(70, 0, 0), translate = Vec3(-1.2, 0.3, -1))
        ),
        Surface(0.8, pigment = Pigment.Checker(Colour.White, Colour(0.8, 0.1, 0.1), 0.2))
      ),
      SceneObject(
        Cylinder(Vec3(0, -1, 1.5), Vec3(0.3, 0.8, 1.5), 0.25),
        Surface(0.8, 0.2, phong = 0.5)
      )
    )
  )

  test("a version 3 scene (solids, placement, a glass CSG, a checker) too"):
    val expected = Renderer.renderSequential(solid, config)
    for threads <- List(1, 2, 3, 8) do
      assertEquals(Renderer.render(solid, config, threads), expected, s"$threads threads")

  test("1, 2, 3 and 8 threads give the same bitmap as the sequential renderer"):
    val expected = Renderer.renderSequential(scene, config)
    for threads <- List(1, 2, 3, 8) do
      assertEquals(Renderer.render(scene, config, threads), expected, s"$threads threads")

  test("a version 2 scene (glass, highlights, an area light) too"):
    val expected = Renderer.renderSequential(glassy, config)
    for threads <- List(1, 2, 3, 8) do
      assertEquals(Renderer.render(glassy, config, threads), expected, s"$threads threads")

  test("every row is reported once"):
    val rows = java.util.concurrent.atomic.AtomicInteger()
    Renderer.render(
      scene,
      config,
      threads = 3,
      onRow = () =>
        rows.incrementAndGet(); ()
    ): Unit
    assertEquals(rows.get, config.rows)

  test("renderInto stores render's picture, each row reported once, a band's rows from 0"):
    val expected = Renderer.render(scene, config, 2, band = 10 until 40)
    for threads <- List(1, 3) do
      val picture = tracer.image.Bitmap.Builder(config.columns, 30)
      val times   = java.util.concurrent.atomic.AtomicIntegerArray(30)
      Renderer.renderInto(
        scene,
        config,
        picture,
        threads,
        (at, count) => (at until at + count).foreach(times.incrementAndGet(_): Unit),
        10 until 40
      )
      assertEquals(picture.result, expected, s"$threads threads")
      assertEquals((0 until 30).map(times.get), Vector.fill(30)(1), s"$threads threads")
