package tracer.bench

import java.io.OutputStream
import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.demo.BenchScenes
import tracer.image.{Bitmap, Png}
import tracer.render.{CameraConfig, Renderer}

/** A 3840×2160 picture encoded as PNG: the benchmark scene `mesh-20000` rendered once (quick
  * mode's colours would be flatter than a real picture's, so the full shading), then its
  * filtering and deflating on one thread, and on two, into a stream that counts the bytes.
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 PngBench"` — ms per picture.
  */
@State(Scope.Benchmark)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.MILLISECONDS)
class PngBench:
  // Why: JMH state, built by setup() before any measurement: a field JMH can reach, so a var.
  var picture: Bitmap = null // nosemgrep: no-null — set by setup() before any benchmark

  @Setup def setup(): Unit =
    val scene = BenchScenes.scene("mesh-20000")
    picture = Renderer.render(scene, CameraConfig.forCamera(scene.camera, 3840), threads = 2)

  /** The encoded picture's size in bytes, on one thread. */
  @Benchmark def encodeOneThread: Long = encode(1)

  /** The encoded picture's size in bytes, on two threads. */
  @Benchmark def encodeTwoThreads: Long = encode(2)

  private def encode(threads: Int): Long =
    val out = Counting()
    Png.write(picture, out, threads)
    out.count

/** An output stream that keeps only the number of bytes written to it. */
private final class Counting extends OutputStream:
  // Why: the count of a stream written to by one thread, the encoder's.
  var count = 0L

  /** Counts one byte. */
  override def write(b: Int): Unit = count += 1

  /** Counts `len` bytes. */
  override def write(b: Array[Byte], off: Int, len: Int): Unit = count += len
