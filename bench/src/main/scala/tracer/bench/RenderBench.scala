package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.demo.BenchScenes
import tracer.image.Bitmap
import tracer.render.{CameraConfig, Renderer}
import tracer.scene.Scene

/** Whole pictures: a 160×90 frame of each benchmark scene on one thread, and on two.
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 -prof gc RenderBench"` — ms per frame and B per frame
  * (divide by 14,400 pixels for bytes per primary ray).
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MILLISECONDS)
class RenderBench:
  // Why: JMH sets a @Param through a var field before the set-up runs.
  @Param(Array("few", "spheres", "mesh-20000"))
  var sceneName: String = ""

  // Why: JMH state, built by setup() before any measurement: fields JMH can reach, so vars.
  var scene: Scene         = null // nosemgrep: no-null — set by setup() before any benchmark
  var config: CameraConfig = null // nosemgrep: no-null — set by setup() before any benchmark

  @Setup def setup(): Unit =
    scene = BenchScenes.scene(sceneName)
    config = CameraConfig.forCamera(scene.camera, 160)

  /** One frame on the calling thread. */
  @Benchmark def frameOneThread: Bitmap = Renderer.renderSequential(scene, config)

  /** One frame on a pool of two threads. */
  @Benchmark def frameTwoThreads: Bitmap = Renderer.render(scene, config, threads = 2)
