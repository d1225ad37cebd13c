package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.demo.BenchScenes
import tracer.render.{CameraConfig, Integrator, Projection, Shading, ShadingMode, World}
import tracer.scene.Scene

/** Primary rays alone: a 640×360 quick-mode frame of a built world (`-q`: one ray a pixel, no lights, shadows or
  * reflections) on one thread, the JVM side of the Embree comparison (`scripts/bench.sh --embree`).
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 5 -i 5 -prof gc PrimaryRayBench"` — ms per frame; divide
  * 230,400 rays by it for rays per second, and the B/op by it for bytes per ray.
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MILLISECONDS)
class PrimaryRayBench:
  // Why: JMH sets a @Param through a var field before the set-up runs.
  @Param(Array("mesh-20000", "spheres"))
  var sceneName: String = ""

  // Why: JMH state, built by setup() before any measurement: fields JMH can reach, so vars.
  var config: CameraConfig   = null // nosemgrep: no-null — set by setup() before any benchmark
  var projection: Projection = null // nosemgrep: no-null — set by setup() before any benchmark
  var shading: Shading       = null // nosemgrep: no-null — set by setup() before any benchmark

  @Setup def setup(): Unit =
    val scene: Scene = BenchScenes.scene(sceneName)
    config = CameraConfig
      .forCamera(scene.camera, 640)
      .withIntegrator(Integrator.Whitted(ShadingMode.Quick))
    projection = Projection(scene.camera, config)
    shading = Shading(World(scene), ShadingMode.Quick)

  /** Every pixel's primary ray, traced and shaded in quick mode (the world built once, outside).
    * Returns the sum of the red channel so that nothing is optimised away.
    */
  @Benchmark def quickFrame: Double =
    // Perf: a plain counted loop over the pixels, as the renderer's own, so that what is
    // measured is the shading and not a Range's closure calls.
    var sum = 0.0
    var y   = 0
    while y < config.rows do
      var x = 0
      while x < config.columns do
        // As the renderer traces a pixel: the ray as six doubles, the colour left in the shading.
        val o = projection.origin
        projection.direction(x + 0.5, y + 0.5)((dx, dy, dz) =>
          shading.trace(o.x, o.y, o.z, dx, dy, dz, config.depth)
        )
        sum += shading.r
        x += 1
      y += 1
    sum
