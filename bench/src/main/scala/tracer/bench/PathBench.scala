package tracer.bench

import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.image.Raster
import tracer.io.SceneXml
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
    // The room from the repository root or from bench/ (where sbt may start the fork).
    val file = List(Path.of("scenes/cornell.xml"), Path.of("../scenes/cornell.xml"))
      .find(Files.isRegularFile(_))
      .getOrElse(Path.of("scenes/cornell.xml"))
    // Why: a benchmark has no caller to hand an error to; a scene that fails to load must stop
    // the run loudly rather than time nothing.
    scene = SceneXml.load(file).fold(why => throw IllegalStateException(why), identity)
    config = CameraConfig
      .forCamera(scene.camera, 64)
      .withIntegrator(Integrator.Path(16, 0, SamplerKind.Default))
      .copy(depth = 7)

  /** One frame on the calling thread, as linear values (what `.pfm` output renders). */
  @Benchmark def frame: Raster = Renderer.renderRaster(scene, config, threads = 1)
