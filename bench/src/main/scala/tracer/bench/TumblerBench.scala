package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.geometry.{CrossingBuffer, Kernel, Shape}
import tracer.scene.Scene

/** The glass tumbler of the gallery's `scenes/solids.xml` (a placed difference of two cylinders)
  * against shadow rays toward its area light: the crossings an area light's shadow ray through
  * glass collects, a third of that scene's render (docs/performance.md, round 22).
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 TumblerBench"` — ns per ray; 1024 rays from points on
  * and around the tumbler toward the light, each meeting the tumbler, cycled; the parts (the
  * difference in its own space, its outer cylinder, an inside test) show where the time goes.
  */
@State(Scope.Thread)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.NANOSECONDS)
class TumblerBench:
  // Why: JMH state, built by setup() before any measurement: fields JMH can reach, so vars;
  // `index` is the cursor that walks the rays, one step a call.
  var tumbler: Shape         = null // nosemgrep: no-null — set by setup() before any benchmark
  var buffer: CrossingBuffer = null // nosemgrep: no-null — set by setup() before any benchmark
  var rays: Array[Double]    = null // nosemgrep: no-null — set by setup() before any benchmark
  var local: Array[Double]   = null // nosemgrep: no-null — set by setup() before any benchmark
  var inner: Shape           = null // nosemgrep: no-null — set by setup() before any benchmark
  var outer: Shape           = null // nosemgrep: no-null — set by setup() before any benchmark
  var index                  = 0

  @Setup def setup(): Unit =
    val file = List("scenes/solids.xml", "../scenes/solids.xml")
      .map(java.nio.file.Path.of(_).toAbsolutePath)
      .find(java.nio.file.Files.exists(_))
      .getOrElse(sys.error("scenes/solids.xml not found"))
    val scene =
      tracer.io.SceneXml.load(file, file.getParent).fold(e => sys.error(e), identity): Scene
    // The tumbler: the only shape that stands left of x = −1.5 and above y = 1.
    tumbler = scene.objects
      .map(_.shape)
      .find(s => Shape.bounds(s).exists(b => b.lo.x < -1.5 && b.hi.y > 1))
      .getOrElse(sys.error("no tumbler in scenes/solids.xml"))
    buffer = CrossingBuffer()
    val box = Shape.bounds(tumbler).getOrElse(sys.error("the tumbler has no bounds"))
    // As a render shoots them: from points along rows over and around the tumbler (on the floor
    // behind it, on and in its wall), 16 rays each toward the 4 × 4 sub-lights of the light's
    // square (−4.6..−3.4, 7, −4.6..−3.4), kept when their line meets the tumbler at all.
    val lines =
      for
        row <- Iterator.from(0)
        col <- Iterator.range(0, 64)
        k   <- Iterator.range(0, 16)
        fx = box.lo.x - 0.5 + (box.hi.x - box.lo.x + 1) * col / 64
        fy = 0.6 * ((row * 7)                                  % 11) / 11.0
        fz = box.lo.z - 0.2 + (box.hi.z - box.lo.z + 1) * (row % 16) / 16
        lx = -4.6 + 0.4 * (k / 4) - fx
        ly = 7.0 - fy
        lz = -4.6 + 0.4 * (k                                   % 4) - fz
        l  = Math.sqrt(lx * lx + ly * ly + lz * lz)
        if Kernel.collect(tumbler, fx, fy, fz, lx / l, ly / l, lz / l, buffer, 0, false) > 0
      yield Array(fx, fy, fz, lx / l, ly / l, lz / l)
    val kept = lines.take(1024).flatten.toArray
    rays = kept
    // The same rays in the tumbler's own space: its placement is a translation by
    // (−2.05, 0.002, −0.2) (scenes/solids.xml).
    local = Array.tabulate(rays.length)(i =>
      rays(i) + (if i % 6 == 0 then 2.05
                 else if i % 6 == 1 then -0.002
                 else if i % 6 == 2 then 0.2
                 else 0)
    )
    tumbler match
      case tracer.geometry.Placed(difference: tracer.geometry.Csg, _) =>
        inner = difference
        outer = difference.children(0)
      case other => sys.error(s"the tumbler is no longer a placed combination: $other")

  /** `Kernel.collect` of the tumbler without normals, as a shadow ray collects it. */
  @Benchmark def crossings: Int =
    index = (index + 1) & 1023
    val r = 6 * index
    Kernel.collect(
      tumbler,
      rays(r),
      rays(r + 1),
      rays(r + 2),
      rays(r + 3),
      rays(r + 4),
      rays(r + 5),
      buffer,
      0,
      false
    )

  /** The difference in its own space (no placement). */
  @Benchmark def difference: Int =
    index = (index + 1) & 1023
    val r = 6 * index
    Kernel.collect(
      inner,
      local(r),
      local(r + 1),
      local(r + 2),
      local(r + 3),
      local(r + 4),
      local(r + 5),
      buffer,
      0,
      false
    )

  /** The outer cylinder alone, in the tumbler's space. */
  @Benchmark def cylinder: Int =
    index = (index + 1) & 1023
    val r = 6 * index
    Kernel.collect(
      outer,
      local(r),
      local(r + 1),
      local(r + 2),
      local(r + 3),
      local(r + 4),
      local(r + 5),
      buffer,
      0,
      false
    )

  /** An inside test of the outer cylinder, at a ray's origin. */
  @Benchmark def inside: Boolean =
    index = (index + 1) & 1023
    val r = 6 * index
    Kernel.inside(outer, local(r), local(r + 1), local(r + 2))
