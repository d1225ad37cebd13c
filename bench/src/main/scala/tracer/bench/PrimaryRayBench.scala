package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.demo.BenchScenes
import tracer.render.{CameraConfig, Projection, Shading, ShadingMode, World}
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
  @Param(Array("mesh-20000", "spheres"))
  var sceneName: String = ""

  var config: CameraConfig   = null
  var projection: Projection = null
  var shading: Shading       = null

  @Setup def setup(): Unit =
    val scene: Scene = BenchScenes.scene(sceneName)
    config = CameraConfig.forCamera(scene.camera, 640).copy(mode = ShadingMode.Quick)
    projection = Projection(scene.camera, config)
    shading = Shading(World(scene), ShadingMode.Quick)

  /** Every pixel's primary ray, traced and shaded in quick mode (the world built once, outside).
    * Returns the sum of the red channel so that nothing is optimised away.
    */
  @Benchmark def quickFrame: Double =
    var sum = 0.0
    var y   = 0
    while y < config.rows do
      var x = 0
      while x < config.columns do
        sum += shading.colour(projection.ray(x + 0.5, y + 0.5), config.depth).r
        x += 1
      y += 1
    sum
