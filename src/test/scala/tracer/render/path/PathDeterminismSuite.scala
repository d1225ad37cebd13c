package tracer.render.path

import tracer.geometry.{Plane, Sphere}
import tracer.image.{Colour, Encoding}
import tracer.math.Vec3
import tracer.render.{CameraConfig, Film, Integrator, Renderer, SamplerKind}
import tracer.scene.{Camera, Light, Scene, SceneObject, Surface}

/** Path mode's pictures depend on the scene and the options alone: the same bytes for every
  * thread count, every split into bands and every run (docs/rendering.md, The sampler).
  */
class PathDeterminismSuite extends munit.FunSuite:

  private val scene = Scene(
    Camera(Vec3(0, 1, -4), Vec3(0, 0, 0)),
    Colour(0.3, 0.4, 0.6),
    List(Light(Vec3(-2, 3, -2), Colour.grey(0.8))),
    List(
      SceneObject(
        Sphere(Vec3(0, 0.5, 0), 0.8),
        Surface(diffuse = 0.5, phong = 0.6, reflection = 0.2)
      ),
      SceneObject(Sphere(Vec3(1.2, 0.3, -0.8), 0.4), Surface(diffuse = 0, transmit = 1, ior = 1.5)),
      SceneObject(Sphere(Vec3(-1.3, 0.3, -0.5), 0.3), Surface(emission = Colour(2, 1, 0.5))),
      SceneObject(Plane.at(Vec3.UnitY, -0.3), Surface(diffuse = 0.8, specular = 0.3))
    )
  )

  private def config(sampler: SamplerKind, seed: Int = 0) =
    CameraConfig(Film(1, 1, 0.75, 23, 17), Integrator.Path(9, seed, sampler), 4, Encoding.Srgb)

  for sampler <- SamplerKind.values do
    test(s"$sampler: the same bytes on 1, 2 and 5 threads, and run after run"):
      val one = Renderer.render(scene, config(sampler), threads = 1)
      assertEquals(Renderer.render(scene, config(sampler), threads = 2), one)
      assertEquals(Renderer.render(scene, config(sampler), threads = 5), one)
      assertEquals(Renderer.render(scene, config(sampler), threads = 2), one)
      val raster = Renderer.renderRaster(scene, config(sampler), threads = 1)
      assertEquals(Renderer.renderRaster(scene, config(sampler), threads = 3), raster)

    test(s"$sampler: bands hold exactly the whole picture's rows (x, y counted in the whole)"):
      val whole = Renderer.renderRaster(scene, config(sampler), threads = 2)
      for (a, b) <- List((0, 5), (5, 6), (6, 17)) do
        val band = Renderer.renderRaster(scene, config(sampler), threads = 2, band = a until b)
        for y <- a until b; x <- 0 until 23 do assertEquals(band(x, y - a), whole(x, y))
      val bytes = Renderer.render(scene, config(sampler), threads = 2)
      val top   = Renderer.render(scene, config(sampler), threads = 2, band = 0 until 8)
      for y <- 0 until 8; x <- 0 until 23 do assertEquals(top(x, y), bytes(x, y))

  test("the 8-bit picture is the raster's mean brought into range, then encoded"):
    val raster = Renderer.renderRaster(scene, config(SamplerKind.Sobol), threads = 2)
    val bytes  = Renderer.render(scene, config(SamplerKind.Sobol), threads = 2)
    assertEquals(raster.toBitmap(Encoding.Srgb), bytes)

  test("another seed gives another picture"):
    assertNotEquals(
      Renderer.renderRaster(scene, config(SamplerKind.Sobol, 1)),
      Renderer.renderRaster(scene, config(SamplerKind.Sobol, 0))
    )
