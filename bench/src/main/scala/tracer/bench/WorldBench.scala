package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.demo.BenchScenes
import tracer.geometry.{Ray, Shape}
import tracer.math.Vec3
import tracer.render.{Bvh, CameraConfig, Projection, Query, Refraction, Shading, World}
import tracer.scene.Scene

/** Nearest-hit and shadow queries against the benchmark scenes, with and without the hierarchy.
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 -prof gc WorldBench"`
  */
@State(Scope.Thread)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.NANOSECONDS)
class WorldBench:
  // Why: JMH sets a @Param through a var field before the set-up runs.
  @Param(Array("few", "spheres", "mesh-20000"))
  var sceneName: String = ""

  // Why: JMH state, built by setup() before any measurement: fields JMH can reach, so vars;
  // `index` is the cursor that walks the rays, one step a call.
  var world: World     = null // nosemgrep: no-null — set by setup() before any benchmark
  var query: Query     = null // nosemgrep: no-null — set by setup() before any benchmark
  var rays: Array[Ray] = null // nosemgrep: no-null — set by setup() before any benchmark
  var bvh: Bvh         = null // nosemgrep: no-null — set by setup() before any benchmark
  var index            = 0
  // Why: as `rays`: 1024 mirrored rays, leaving surfaces the camera sees.
  var mirrored: Array[Ray] = null // nosemgrep: no-null — set by setup() before any benchmark

  @Setup def setup(): Unit =
    val scene: Scene = BenchScenes.scene(sceneName)
    world = World(scene)
    query = world.newQuery()
    bvh = Bvh(scene.objects.map(_.shape).toIndexedSeq)
    // 1024 primary rays spread over the picture.
    val projection = Projection(scene.camera, CameraConfig.forCamera(scene.camera, 32))
    rays = Array.tabulate(1024)(i => projection.ray(i % 32 + 0.5, (i / 32) % 18 + 0.5))
    // The rays that leave the surfaces the camera sees over a finer grid, as shading reflects
    // them (from ε off the surface): most of a 4K mesh render's walks are such rays, and two in
    // three of them meet nothing (docs/performance.md, round 44).
    val grid    = CameraConfig.forCamera(scene.camera, 128)
    val fine    = Projection(scene.camera, grid)
    val leaving = for
      j      <- 0 until grid.rows
      i      <- 0 until grid.columns
      mirror <- mirrorOf(scene, fine.ray(i + 0.5, j + 0.5))
    yield mirror
    mirrored = Array.tabulate(1024)(i => leaving(i * leaving.size / 1024))

  /** `ray` mirrored at its nearest hit in `scene`, from ε off the surface, as shading reflects it
    * about a flat surface's normal; none when it meets nothing.
    */
  private def mirrorOf(scene: Scene, ray: Ray): Option[Ray] =
    val hit = world.nearest(ray, query)
    Option.when(hit >= 0) {
      val at = Shape.hitAt(scene.objects(hit).shape, ray, query.distance)
      Ray(at.point + at.normal * Shading.Epsilon, Refraction.reflect(ray.direction, at.normal))
    }

  private def next(): Ray = nextOf(rays)

  /** The next of the 1024 rays `from`, one step of the cursor a call. */
  private def nextOf(from: Array[Ray]): Ray =
    index = (index + 1) & 1023
    from(index)

  /** The nearest hit through the hierarchy. */
  @Benchmark def nearest: Int = world.nearest(next(), query)

  /** The nearest hit of a ray leaving a surface the camera sees (a mirrored ray). */
  @Benchmark def reflected: Int = world.nearest(nextOf(mirrored), query)

  /** The hierarchy alone, its 4-wide tree (what `nearest` walks). */
  @Benchmark def bvhWide: Int =
    val r = next()
    val o = r.origin
    val d = r.direction
    bvh.nearest(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, Int.MaxValue, query)

  /** The hierarchy alone, the binary tree it was collapsed from: what the wide tree gains. */
  @Benchmark def bvhBinary: Int =
    val r = next()
    val o = r.origin
    val d = r.direction
    bvh.nearestBinary(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, Int.MaxValue, query)

  /** A shadow ray through the 4-wide tree alone. */
  @Benchmark def occludedWide: Boolean =
    val r = next()
    bvh.occluded(0, 0.05, 2, -0.4 + r.direction.x, 0.6, -0.6, 12.0, query)

  /** The same shadow ray through the binary tree. */
  @Benchmark def occludedBinary: Boolean =
    val r = next()
    bvh.occludedBinary(0, 0.05, 2, -0.4 + r.direction.x, 0.6, -0.6, 12.0, query)

  /** The nearest hit by testing every shape: what the hierarchy saves. */
  @Benchmark def nearestBruteForce: Int = world.nearestByBruteForce(next())

  /** A shadow ray from the middle of the scene towards a light, stopping at the first blocker. */
  @Benchmark def occluded: Boolean =
    val r = next()
    world.occluded(
      Ray(
        Vec3(0, 0.05, 2),
        (Vec3(-5, 8, -6) - Vec3(0, 0.05, 2) + r.direction).normalisedOr(Vec3.UnitY)
      ),
      12.0,
      query
    )
