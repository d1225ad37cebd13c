package tracer.bench

import java.nio.charset.StandardCharsets.UTF_8
import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.demo.BenchScenes
import tracer.io.{SceneSources, SceneWriter, SceneXml}
import tracer.scene.Scene

/** Reading a big scene: the 20,480-triangle benchmark mesh written as `<triangle>` elements
  * (about 5 MB of XML), parsed and checked into a [[Scene]].
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 SceneLoadBench"` — ms per load; MB/s is the document's
  * size (printed by the set-up) over that.
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MILLISECONDS)
class SceneLoadBench:
  // Why: JMH state, set by setup() before any measurement: a field JMH can reach, so a var.
  var document: Array[Byte] = Array.emptyByteArray

  @Setup def setup(): Unit =
    // Why: as in load, a benchmark has no caller to hand an error to.
    document = SceneWriter
      .write(BenchScenes.scene("mesh-20000"))
      .fold(why => throw IllegalStateException(why), _.getBytes(UTF_8))
    println(s"\nSceneLoadBench: the document has ${document.length} bytes")

  /** Parses the document into a scene. */
  @Benchmark def load: Scene =
    // Why: a benchmark has no caller to hand an error to; a scene that fails to load must stop
    // the run loudly rather than time the error path.
    SceneXml
      .parse(document, SceneSources(_ => Left("no textures"), _ => Left("no meshes")))
      .fold(e => throw IllegalStateException(e.describe), identity)
