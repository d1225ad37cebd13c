package tracer.render.path

import tracer.geometry.{Box, Cone, Cylinder, Placed, Plane, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.{Placement, Vec3}
import tracer.render.{SamplerKind, World}
import tracer.scene.{Camera, Fade, Light, Scene, SceneObject, Surface}

/** Path mode against exact answers (docs/rendering.md, Path tracing). Tolerances are stated per
  * test: k standard errors of the mean, the error estimated from the pixels' own spread (each
  * pixel an independent estimate of the same value), so a test fails on a biased estimator and
  * not on noise (k = 5: a false alarm about once in 3.5 million runs).
  */
class PathAnalyticSuite extends munit.FunSuite:
  import PathScenes.*

  private val K = 5.0

  private def assertMean(xs: Seq[Double], expected: Double, floor: Double = 1e-9)(using
      munit.Location
  ): Unit =
    val (mean, error) = meanAndError(xs)
    val tolerance     = K * error + floor
    assert(
      Math.abs(mean - expected) <= tolerance,
      s"mean $mean is not within $tolerance ($K standard errors $error) of $expected"
    )

  // The sphere's disc covers the middle pixels of the 1 × 1 picture seen from z = −3.
  private def onBall(size: Int)(x: Int, y: Int): Boolean =
    val dx = (x + 0.5) / size - 0.5
    val dy = (y + 0.5) / size - 0.5
    dx * dx + dy * dy < 0.25 * 0.25

  for depth <- List(1, 2, 6) do
    test(s"white furnace: a diffuse ball under a uniform sky B shows kd·B at -r $depth"):
      val kd    = 0.6
      val sky   = 1.7 // above 1: a bright sky is allowed
      val scene = Scene(
        camera,
        Colour.grey(sky),
        Nil,
        List(SceneObject(ball, Surface(diffuse = kd)))
      )
      val raster = render(scene, 24, 64, depth)
      assertMean(values(raster, onBall(24)), kd * sky)
      // Far from the ball every pixel is the sky itself, exactly.
      assertEqualsDouble(raster(0, 0).g, sky, 1e-6)

  // One open face over the whole picture, its corners' normals leaning 40° off its own: a third
  // of the cosine lobe about the shading normal lies behind the face's plane, and the paths and
  // shadow rays sent there pass the face (as Mitsuba's), so it shows kd·B like a furnace; with
  // them stopped by the face itself it showed 0.88·kd·B.
  for depth <- List(1, 3) do
    test(s"a smooth face leaning off its plane shows kd·B under a uniform sky at -r $depth"):
      val kd   = 0.6
      val sky  = 1.3
      val lean = Vec3(Math.sin(Math.toRadians(40)), 0, -Math.cos(Math.toRadians(40)))
      val face = Triangle(
        Vec3(-10, -10, 0),
        Vec3(10, -10, 0),
        Vec3(0, 10, 0),
        cornerNormals = Some((lean, lean, lean))
      )
      val scene =
        Scene(camera, Colour.grey(sky), Nil, List(SceneObject(face, Surface(diffuse = kd))))
      val raster = render(scene, 16, 64, depth)
      assertMean(values(raster), kd * sky)

  test("-r 0 shows only emission and the background: a lit diffuse ball is black"):
    val scene = Scene(
      camera,
      Colour.grey(0.5),
      List(Light(Vec3(0, 3, -3))),
      List(SceneObject(ball, Surface(diffuse = 1)))
    )
    val raster = render(scene, 16, 4, 0)
    assertEquals(values(raster, onBall(16)).distinct, IndexedSeq(0.0))
    assertEqualsDouble(raster(0, 0).g, 0.5, 1e-6)

  // A closed box of inward glowing triangles: every hit adds kd^k·E (k bounces before it).
  for depth <- List(0, 1, 3, 8) do
    test(s"a closed glowing box seen from inside shows Σ_{k≤d} kd^k·E at -r $depth"):
      val (kd, e) = (0.5, 0.8)
      val scene   = Scene(
        Camera(Vec3(0.1, -0.2, -0.5), Vec3(0.3, 0, 1), zoom = 1, width = 1.5, height = 1.5),
        Colour.Black,
        Nil,
        inwardCube.map(glowing(_, e, kd))
      )
      val raster   = render(scene, 16, 32, depth)
      val expected = (0 to depth).map(k => Math.pow(kd, k) * e).sum
      if depth == 0 then
        assertEquals(values(raster).distinct.map(v => Math.abs(v - e) < 1e-6), IndexedSeq(true))
      else assertMean(values(raster), expected)

  test("the glowing box's faces glow inwards only: seen from outside it is black"):
    val scene = Scene(camera, Colour.Black, Nil, inwardCube.map(glowing(_, 1, 0.5)))
    assertEquals(values(render(scene, 8, 4, 3)).distinct, IndexedSeq(0.0))

  // A point light over the plane y = 0 seen from above: E = π·C·A(d)·cos θ, f = kd/π, so the
  // pixel is the mean over its samples of kd·C·A(d)·cos θ at the points they see, d = |L − p|
  // from the point itself (cos θ from S0, where the shadow ray starts). The samples' positions
  // come from the sampler itself, so the comparison is exact up to rounding (a fade measured
  // from S0 is off by 6·10⁻⁵ to 1.4·10⁻⁴ of it here, six to fourteen times the tolerance).
  for fade <- List(None, Some(Fade(1.5, 2)), Some(Fade(0.7, 3))) do
    test(s"a point light over a plane gives kd·C·A(d)·cos θ at every pixel (fade $fade)"):
      val kd     = 0.8
      val colour = 1.3
      val light  = Light(Vec3(0.2, 2, 0.1), Colour.grey(colour), fade = fade)
      val eye    =
        Camera(Vec3(0, 3, 0), Vec3(0, 0, 0), up = Vec3.UnitZ, zoom = 1, width = 1, height = 1)
      val scene = Scene(
        eye,
        Colour.Black,
        List(light),
        List(SceneObject(Plane.at(Vec3.UnitY, 0), Surface(diffuse = kd)))
      )
      val (size, n) = (8, 16)
      for depth <- List(1, 4) do
        val raster     = render(scene, size, n, depth)
        val film       = tracer.render.Film(1, 1, 1, size, size)
        val projection = tracer.render.Projection(eye, film)
        val sampler    = Sampler(SamplerKind.Sobol, 0, n)
        for y <- 0 until size; x <- 0 until size do
          val expected = (0 until n).map { j =>
            val uv  = sampler.pair(x, y, j, 0)
            val ray = projection.ray(x + Sampler.first(uv), y + Sampler.second(uv))
            val p   = ray.at(-ray.origin.y / ray.direction.y)
            val s0  = p + Vec3.UnitY * 1e-4
            val d   = (light.location - s0).length
            val a   = light.attenuation((light.location - p).length)
            kd * colour * a * (light.location - s0).y / d
          }.sum / n
          assertEqualsDouble(
            raster(x, y).g,
            expected,
            1e-5 * expected,
            s"pixel ($x, $y) at -r $depth"
          )

  // An area light of NA × NB sub-lights is NA·NB point lights of C/(NA·NB) each (with the
  // light's fade, d from each sub-light): at the point a sample sees, the expected value is
  // Σ kd·(C/(NA·NB))·A(d)·cos θ over the grid. Which sub-light a sample takes is random, so each
  // pixel differs from its exact value by noise alone, and their mean difference is 0 within K
  // standard errors (a sub-light weighed C·NA·NB, or C, or not faded, is far outside).
  for fade <- List(None, Some(Fade(1.2, 2))) do
    test(s"an area light over a plane is the sum of its sub-lights, C/(NA·NB) each (fade $fade)"):
      val kd    = 0.7
      val area  = tracer.scene.AreaLight(Vec3(1.6, 0, 0), Vec3(0, 0, 1.2), 3, 3)
      val light = Light(Vec3(0.1, 1.5, 0), Colour.grey(2), Some(area), fade)
      val eye   =
        Camera(Vec3(0, 3, 0), Vec3(0, 0, 0), up = Vec3.UnitZ, zoom = 1, width = 1, height = 1)
      val scene = Scene(
        eye,
        Colour.Black,
        List(light),
        List(SceneObject(Plane.at(Vec3.UnitY, 0), Surface(diffuse = kd)))
      )
      val (size, n)  = (16, 16)
      val raster     = render(scene, size, n, 1)
      val film       = tracer.render.Film(1, 1, 1, size, size)
      val projection = tracer.render.Projection(eye, film)
      val sampler    = Sampler(SamplerKind.Sobol, 0, n)
      val subLights  =
        for u <- 0 until 3; v <- 0 until 3 yield light.location + area.offset(u, v)
      val differences = for y <- 0 until size; x <- 0 until size yield
        val exact = (0 until n).map { j =>
          val uv  = sampler.pair(x, y, j, 0)
          val ray = projection.ray(x + Sampler.first(uv), y + Sampler.second(uv))
          val p   = ray.at(-ray.origin.y / ray.direction.y)
          val s0  = p + Vec3.UnitY * 1e-4
          subLights.map { at =>
            val d = (at - s0).length
            kd * (2.0 / 9) * light.attenuation((at - p).length) * (at - s0).y / d
          }.sum
        }.sum / n
        raster(x, y).g - exact
      val level = raster(size / 2, size / 2).g
      assert(level > 0.1, s"the plane under the light is lit: $level")
      assertMean(differences, 0)

  test(
    "glass neither gains nor loses light in a furnace: a glass ball under a uniform sky shows B"
  ):
    val scene = Scene(
      camera,
      Colour.grey(1),
      Nil,
      List(SceneObject(ball, Surface(diffuse = 0, transmit = 1, ior = 1.5)))
    )
    // Deep enough that the light still trapped inside after 64 bounces is far below the noise.
    val raster = render(scene, 16, 64, 64)
    assertMean(values(raster, onBall(16)), 1.0)

  test("a clear pane is not a bounce: at -r 0 a glowing panel behind it shows E·t"):
    val (t, e) = (0.6, 2.0)
    val panel  = PathScenes.square(Vec3(-2, -2, 1), Vec3(4, 0, 0), Vec3(0, 4, 0))
    // Normals a × b point along +z, away from the camera: flip the legs to glow towards it.
    val facing = panel.map(tr => Triangle(tr.t0, tr.t2, tr.t1))
    val pane   = PathScenes.square(Vec3(-2, -2, 0), Vec3(4, 0, 0), Vec3(0, 4, 0))
    val scene  = Scene(
      camera,
      Colour.Black,
      Nil,
      facing.map(glowing(_, e, 0)) ++ pane.map(SceneObject(_, Surface(diffuse = 0.5, transmit = t)))
    )
    assertEquals(
      values(render(scene, 8, 4, 0)).map(v => Math.abs(v - e * t) < 1e-6).distinct,
      IndexedSeq(true)
    )

  /** Renders `scene` by next-event estimation alone, by the paths alone and by both (12 × 12
    * pixels, 256 samples, `-r 3`), and asserts that it is lit and that the first and the last
    * estimate the paths' picture: the difference of two independent estimates of the same
    * picture has mean 0 over all pixels.
    */
  private def assertStrategiesAgree(scene: Scene)(using munit.Location): Unit =
    val lights        = renderWith(scene, 12, 256, 3, PathTracer.Strategy.LightsOnly)
    val paths         = renderWith(scene, 12, 256, 3, PathTracer.Strategy.PathsOnly)
    val both          = renderWith(scene, 12, 256, 3, PathTracer.Strategy.Both)
    val diff          = values(lights).zip(values(paths)).map(_ - _)
    val (mean, error) = meanAndError(diff)
    assert(Math.abs(mean) <= K * error, s"next-event-only minus path-only: $mean ± $error")
    val (total, _) = meanAndError(values(both))
    assert(total > 0.05, s"the scene is lit ($total)")
    val diffBoth      = values(both).zip(values(paths)).map(_ - _)
    val (mean2, err2) = meanAndError(diffBoth)
    assert(Math.abs(mean2) <= K * err2, s"combined minus path-only: $mean2 ± $err2")

  test("next-event-only and path-only estimates of glowing spheres, triangles and the sky agree"):
    val floor = PathScenes.square(Vec3(-3, -1, -3), Vec3(0, 0, 6), Vec3(6, 0, 0))
    val lamp  = Triangle(Vec3(-1, 1.5, 0.5), Vec3(1, 1.5, 0.5), Vec3(0, 1.5, -1))
    val scene = Scene(
      camera,
      Colour(0.2, 0.3, 0.5),
      Nil,
      floor.map(SceneObject(_, Surface(diffuse = 0.8, phong = 0.4, phongSize = 10))) ++ List(
        SceneObject(
          Sphere(Vec3(0.4, -0.5, 0), 0.5),
          Surface(diffuse = 0.7, specular = 0.5, roughness = 0.1)
        ),
        glowing(Sphere(Vec3(-0.8, 0.3, 0.6), 0.25), 4, 0.5),
        glowing(lamp, 3, 0)
      )
    )
    assertStrategiesAgree(scene)

  // Glowing boxes, cylinders, cones and placed shapes are drawn by next-event estimation too
  // (Emitters.glow): drawn by it alone or found by the paths alone, their light is the same.
  test("next-event-only and path-only estimates of glowing solids and placed shapes agree"):
    val floor  = PathScenes.square(Vec3(-3, -1, -3), Vec3(0, 0, 6), Vec3(6, 0, 0))
    val turned = Placement(0.8, Vec3(25, 40, 10), Vec3(0.9, 0.9, 0.4))
    val scene  = Scene(
      camera,
      Colour.Black,
      Nil,
      floor.map(SceneObject(_, Surface(diffuse = 0.8, phong = 0.4, phongSize = 10))) ++ List(
        glowing(Box(Vec3(-1.2, 0.8, 0.2), Vec3(-0.4, 1.1, 0.9)), 3, 0.5),
        glowing(Placed(Box(Vec3(-0.3, -0.1, -0.2), Vec3(0.3, 0.1, 0.2)), turned), 4, 0),
        glowing(
          Placed(Sphere(Vec3(0, 0, 0), 0.3), Placement(0.5, translate = Vec3(0.2, -0.4, -0.6))),
          4,
          0.5
        ),
        glowing(
          Placed(
            Triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)),
            turned.copy(translate = Vec3(-0.5, 1.2, -1))
          ),
          3,
          0
        ),
        glowing(Cylinder(Vec3(1, -1, 0.8), Vec3(1.2, 0.2, 1), 0.15), 3, 0.5),
        glowing(
          Placed(Cone(Vec3(0, 0, 0), 0.3, Vec3(0, 0.5, 0), 0.1, open = true), turned),
          3,
          0
        )
      )
    )
    val emitters = Emitters(scene, World(scene))
    assertEquals((2 to 7).map(emitters.samples), (2 to 7).map(_ => true))
    assertStrategiesAgree(scene)

  // What drawing a small lamp by next-event estimation is for: a wall lit by a small glowing box
  // out of view, at 4 samples a pixel, is nearly smooth; found by the paths alone it is speckled.
  test("a wall lit by a small glowing box is far less noisy with next-event estimation"):
    val wall  = PathScenes.square(Vec3(-2.5, -2.5, 1), Vec3(0, 5, 0), Vec3(5, 0, 0))
    val scene = Scene(
      camera,
      Colour.Black,
      Nil,
      wall.map(SceneObject(_, Surface(diffuse = 0.8))) :+
        glowing(Box(Vec3(-0.3, 2.3, -0.3), Vec3(0.3, 2.5, 0.3)), 5, 0)
    )
    // The root mean square of the steps between neighbouring pixels of a row: the wall's own
    // shading changes little from one pixel to the next, the noise a lot. Both renders draw the
    // same numbers, so were the box not drawn by next-event estimation they would be the same
    // picture (ratio 1); drawn, it reads about 0.2.
    def roughness(raster: tracer.image.Raster) =
      val steps = for
        y <- 0 until raster.height
        x <- 0 until raster.width - 1
      yield raster(x + 1, y).g - raster(x, y).g
      Math.sqrt(steps.map(d => d * d).sum / steps.size)
    val both     = renderWith(scene, 16, 4, 1, PathTracer.Strategy.Both)
    val paths    = renderWith(scene, 16, 4, 1, PathTracer.Strategy.PathsOnly)
    val (lit, _) = meanAndError(values(both))
    assert(lit > 0.01, s"the wall is lit ($lit)")
    assert(
      roughness(both) < 0.5 * roughness(paths),
      s"roughness ${roughness(both)} with next-event estimation, ${roughness(paths)} without"
    )

  // A smooth open square whose corner normals lean out towards its corners, lit by a glowing
  // ball behind its plane that the leaning normals face: the shadow rays start beyond the face
  // and must aim at the point sampled on the ball from there (Mitsuba's spawn_ray_to). Aimed
  // along the direction from S0, 2ε away, the rays grazing the ball met the ball itself before
  // their reach: next-event estimation lost a third of the light that paths find there.
  test("a smooth face lit by a glowing ball behind its plane: next-event and paths agree"):
    def n(x: Double, y: Double) = Vec3(x, y, -1).normalised.get
    val (a, b, c, d)            = (Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0))
    val square                  = List(
      Triangle(a, b, c, cornerNormals = Some((n(-0.5, -0.5), n(0.5, -0.5), n(0.5, 0.5)))),
      Triangle(a, c, d, cornerNormals = Some((n(-0.5, -0.5), n(0.5, 0.5), n(-0.5, 0.5))))
    )
    // The camera looks at the square's lit corner only.
    val corner =
      Camera(Vec3(-0.8, 0.8, -3), Vec3(-0.8, 0.8, 0), zoom = 1, width = 0.3, height = 0.3)
    val scene = Scene(
      corner,
      Colour.Black,
      Nil,
      glowing(Sphere(Vec3(-3.5, 3.5, 2), 2.5), 5, 0) +: square.map(
        SceneObject(_, Surface(diffuse = 0.5))
      )
    )
    val lights        = renderWith(scene, 8, 2048, 1, PathTracer.Strategy.LightsOnly)
    val paths         = renderWith(scene, 8, 2048, 1, PathTracer.Strategy.PathsOnly)
    val diff          = values(lights).zip(values(paths)).map(_ - _)
    val (mean, error) = meanAndError(diff)
    val (lit, _)      = meanAndError(values(paths))
    assert(lit > 0.01, s"the square is lit ($lit)")
    assert(Math.abs(mean) <= K * error, s"next-event-only minus path-only: $mean ± $error of $lit")

  test("--seed changes the noise, not the mean"):
    val scene = Scene(
      camera,
      Colour.grey(0.8),
      List(Light(Vec3(1, 2, -2))),
      List(SceneObject(ball, Surface(diffuse = 0.7, phong = 0.5)))
    )
    val a = render(scene, 16, 16, 3, seed = 0)
    val b = render(scene, 16, 16, 3, seed = 12345)
    assertNotEquals(a, b)
    val diff          = values(a).zip(values(b)).map(_ - _)
    val (mean, error) = meanAndError(diff)
    assert(Math.abs(mean) <= K * error, s"seed 0 minus seed 12345: $mean ± $error")

  for sampler <- SamplerKind.values do
    test(s"the $sampler sampler converges to the same picture as the other"):
      val scene = Scene(
        camera,
        Colour.grey(0.5),
        List(Light(Vec3(1, 2, -2))),
        List(SceneObject(ball, Surface(diffuse = 0.7, reflection = 0.2)))
      )
      val other         = SamplerKind.values.filter(_ != sampler).head
      val a             = render(scene, 16, 16, 3, sampler = sampler)
      val b             = render(scene, 16, 16, 3, sampler = other, seed = 7)
      val diff          = values(a).zip(values(b)).map(_ - _)
      val (mean, error) = meanAndError(diff)
      assert(Math.abs(mean) <= K * error, s"$sampler minus $other: $mean ± $error")
