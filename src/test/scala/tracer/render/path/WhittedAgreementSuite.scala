package tracer.render.path

import java.nio.file.Path
import tracer.geometry.{Ray, Shape}
import tracer.image.Colour
import tracer.io.SceneXml
import tracer.render.{Film, Integrator, Projection, SamplerKind, Shading, ShadingMode, World}
import tracer.scene.{Scene, SceneObject, Surface}

/** Path mode's direct light is Whitted's: with one point light, a black background and matte
  * surfaces (no mirror, highlight, transmission or emission), a path at `-r 1` gathers exactly
  * the Whitted colour at `-r 0` of its camera ray (the light found by next-event estimation,
  * nothing beyond). So each path-traced pixel is the mean of Whitted's colours at the pixel's
  * sample positions: an exact test of every shape, texture, checker and smooth mesh in path mode.
  */
class WhittedAgreementSuite extends munit.FunSuite:

  private def matte(s: Surface) =
    s.copy(reflection = 0, phong = 0, specular = 0, transmit = 0, emission = Colour.Black)

  private def matteScene(scene: Scene): Scene =
    scene.copy(
      background = Colour.Black,
      lights = scene.lights.take(1).map(_.copy(area = None)),
      objects =
        scene.objects.map(o => SceneObject(o.shape, matte(o.surface), o.leafSurfaces.map(matte)))
    )

  for name <- List("textures.xml", "solids.xml", "meshes.xml", "showcase.xml") do
    test(s"scenes/$name made matte: path mode at -r 1 is Whitted's -r 0 at the same sample points"):
      val loaded = SceneXml.load(Path.of("scenes", name), Path.of("scenes")).fold(fail(_), identity)
      val scene  = matteScene(loaded)
      val (w, h, n)  = (24, 18, 4)
      val film       = Film(scene.camera.zoom, scene.camera.width, scene.camera.height, w, h)
      val world      = World(scene)
      val projection = Projection(scene.camera, film)
      val tracer     = PathTracer(scene, world, projection, Integrator.Path(n), 1)
      val task       = tracer.task()
      val whitted    = Shading(world, ShadingMode.Full)
      val sampler    = Sampler(SamplerKind.Sobol, 0, n)
      val query      = world.newQuery()
      val light      = scene.lights.head.location
      // Whitted lights a point whose shading normal turns just away from the light when the
      // shadow ray from S0 slips past the surface (|cos| at the terminator); the scattering
      // function of path mode is zero there. Pixels with a sample that grazes the light within
      // cos 0.05 are left out of the exact comparison.
      def grazing(ray: Ray): Boolean =
        val i = world.nearest(ray, query)
        i >= 0 && {
          val hit    = Shape.hitAt(world.shape(i), ray, query.distance)
          val normal = Shape.shadingNormal(world.shape(i), hit, ray)
          val s0     = hit.point + hit.normal * Shading.Epsilon
          Math.abs(normal.dot((light - s0).normalisedOr(normal))) < 0.05
        }
      val compared = for
        y <- 0 until h
        x <- 0 until w
        rays = (0 until n).map { j =>
          val uv = sampler.pair(x, y, j, 0)
          projection.ray(x + Sampler.first(uv), y + Sampler.second(uv))
        }
        if !rays.exists(grazing)
      yield
        val expected = rays.map(whitted.colour(_, 0)).reduce(_ + _) / n
        val got      = task.pixel(x, y)
        for (a, b) <- List((got.r, expected.r), (got.g, expected.g), (got.b, expected.b)) do
          assertEqualsDouble(
            a,
            b,
            1e-9 + 1e-6 * Math.abs(b),
            s"$name pixel ($x, $y): $got, Whitted $expected"
          )
        expected.max
      assert(compared.size >= w * h * 3 / 4, s"only ${compared.size} pixels compared")
      assert(compared.exists(_ > 0), "the comparison saw no light")
