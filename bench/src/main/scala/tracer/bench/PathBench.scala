package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.image.Raster
import tracer.render.{CameraConfig, Integrator, Renderer, SamplerKind}
import tracer.scene.Scene

/** Path mode on the benchmark room (`scenes/cornell.xml`, the scene of `bench.sh --mitsuba`): one
  * 64×64 frame at 16 samples a pixel, `-r 7`, on the calling thread.
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -w 1s -i 5 -r 1s -prof gc PathBench"` — ms per frame and B
  * per frame (divide by 65,536 for bytes per path).
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MILLISECONDS)
class PathBench:
  // Why: JMH state, built by setup() before any measurement: fields JMH can reach, so vars.
  var scene: Scene         = null // nosemgrep: no-null — set by setup() before any benchmark
  var config: CameraConfig = null // nosemgrep: no-null — set by setup() before any benchmark

  @Setup def setup(): Unit =
    scene = GalleryScene.load("cornell.xml")
    config = CameraConfig
      .forCamera(scene.camera, 64)
      .withIntegrator(Integrator.Path(16, 0, SamplerKind.Default))
      .copy(depth = 7)

  /** One frame on the calling thread, as linear values (what `.pfm` output renders). */
  @Benchmark def frame: Raster = Renderer.renderRaster(scene, config, threads = 1)
