package tracer.render.path

import tracer.geometry.{Shape, Sphere, Triangle}
import tracer.image.{Colour, Raster}
import tracer.math.Vec3
import tracer.render.{CameraConfig, Film, Integrator, Projection, Renderer, SamplerKind, World}
import tracer.scene.{Camera, Scene, SceneObject, Surface}

/** Scenes built in code for path mode's tests, and the statistics their tolerances come from. */
object PathScenes:

  /** A camera at the origin looking along +z, image plane 1 × 1 at distance 1. */
  val camera: Camera = Camera(Vec3(0, 0, -3), Vec3.Zero, zoom = 1, width = 1, height = 1)

  /** Renders `scene` in path mode at `size` × `size` pixels into linear floats. */
  def render(
      scene: Scene,
      size: Int,
      samples: Int,
      depth: Int,
      seed: Int = 0,
      sampler: SamplerKind = SamplerKind.Sobol,
      threads: Int = 2
  ): Raster =
    val config = CameraConfig(
      Film(scene.camera.zoom, scene.camera.width, scene.camera.height, size, size),
      Integrator.Path(samples, seed, sampler),
      depth,
      tracer.image.Encoding.Linear
    )
    Renderer.renderRaster(scene, config, threads)

  /** Renders `scene` with one [[PathTracer.Strategy]], on this thread. */
  def renderWith(
      scene: Scene,
      size: Int,
      samples: Int,
      depth: Int,
      strategy: PathTracer.Strategy
  ): Raster =
    val film   = Film(scene.camera.zoom, scene.camera.width, scene.camera.height, size, size)
    val tracer = PathTracer(
      scene,
      World(scene),
      Projection(scene.camera, film),
      Integrator.Path(samples),
      depth,
      strategy
    )
    val task = tracer.task()
    Raster.tabulate(size, size)((x, y) => task.pixel(x, y))

  /** The green channel of every pixel of `raster` for which `keep` holds. */
  def values(raster: Raster, keep: (Int, Int) => Boolean = (_, _) => true): IndexedSeq[Double] =
    for
      y <- 0 until raster.height
      x <- 0 until raster.width
      if keep(x, y)
    yield raster(x, y).g

  /** The mean of `xs` and its standard error, from their spread (each value one estimate). */
  def meanAndError(xs: Seq[Double]): (Double, Double) =
    val n    = xs.size
    val mean = xs.sum / n
    val sd   = Math.sqrt(xs.map(x => (x - mean) * (x - mean)).sum / (n - 1))
    (mean, sd / Math.sqrt(n))

  /** The two triangles of the square with corner `o` and legs `a`, `b`, their normals a × b. */
  def square(o: Vec3, a: Vec3, b: Vec3): List[Triangle] =
    List(Triangle(o, o + a, o + b), Triangle(o + a + b, o + b, o + a))

  /** The twelve triangles of the cube [−1, 1]³, every normal pointing inwards. */
  val inwardCube: List[Triangle] =
    val faces = for
      axis <- 0 until 3
      side <- List(-1.0, 1.0)
    yield
      def v(i: Int, value: Double) = Vec3.Zero.copy(
        x = if i == 0 then value else 0,
        y = if i == 1 then value else 0,
        z = if i == 2 then value else 0
      )
      val u = v((axis + 1) % 3, 2)
      val w = v((axis + 2) % 3, 2)
      val o = v(axis, side) - u * 0.5 - w * 0.5
      // Inwards is −side along the axis: choose the order of the legs that points there.
      val (a, b) = if u.cross(w).dot(v(axis, side)) < 0 then (u, w) else (w, u)
      square(o, a, b)
    faces.flatten.toList

  /** A glowing, diffuse object. */
  def glowing(shape: Shape, emission: Double, diffuse: Double): SceneObject =
    SceneObject(shape, Surface(diffuse = diffuse, emission = Colour.grey(emission)))

  /** A unit sphere at the origin. */
  val ball: Sphere = Sphere(Vec3.Zero, 1)
