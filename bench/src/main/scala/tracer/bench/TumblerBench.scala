package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.geometry.{CrossingBuffer, Csg, Kernel, Placed, Ray, Shape}
import tracer.math.Vec3

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
  var tumbler: Placed        = null // nosemgrep: no-null — set by setup() before any benchmark
  var buffer: CrossingBuffer = null // nosemgrep: no-null — set by setup() before any benchmark
  var rays: Array[Double]    = null // nosemgrep: no-null — set by setup() before any benchmark
  var local: Array[Double]   = null // nosemgrep: no-null — set by setup() before any benchmark
  var inner: Csg             = null // nosemgrep: no-null — set by setup() before any benchmark
  var outer: Shape           = null // nosemgrep: no-null — set by setup() before any benchmark
  var index                  = 0

  @Setup def setup(): Unit =
    val scene = GalleryScene.load("solids.xml")
    // The tumbler: the only shape that stands left of x = −1.5 and above y = 1.
    // Why: a benchmark has no caller to hand an error to; it must stop rather than time nothing.
    val placed = scene.objects
      .map(_.shape)
      .collectFirst {
        case p @ Placed(difference: Csg, _)
            if Shape.bounds(p).exists(b => b.lo.x < -1.5 && b.hi.y > 1) =>
          (p, difference)
      }
      .getOrElse(throw IllegalStateException("no placed combination for a tumbler in solids.xml"))
    tumbler = placed(0)
    inner = placed(1)
    outer = inner.children(0)
    buffer = CrossingBuffer()
    // Why: as above, a scene that no longer holds the tumbler stops the run.
    val box = Shape.bounds(tumbler).getOrElse(throw IllegalStateException("an unbounded tumbler"))
    // As a render shoots them: from points along rows over and around the tumbler (on the floor
    // behind it, on and in its wall), 16 rays each toward the 4 × 4 sub-lights of the light's
    // square (−4.6..−3.4, 7, −4.6..−3.4), kept when their line meets the tumbler at all.
    val heights = Array.tabulate(11)(h => 0.6 * h / 11.0)
    val origins =
      for
        row <- Iterator.from(0)
        col <- Iterator.range(0, 64)
      yield Vec3(
        box.lo.x - 0.5 + (box.hi.x - box.lo.x + 1) * col / 64,
        heights(row * 7 % 11),
        box.lo.z - 0.2 + (box.hi.z - box.lo.z + 1) * (row % 16) / 16
      )
    val kept =
      for
        from <- origins
        k    <- Iterator.range(0, 16)
        d = (Vec3(-4.6 + 0.4 * (k / 4), 7.0, -4.6 + 0.4 * (k % 4)) - from).normalisedOr(Vec3.UnitY)
        if Kernel.collect(tumbler, from.x, from.y, from.z, d.x, d.y, d.z, buffer, 0, false) > 0
      yield Ray(from, d)
    val shadows = kept.take(1024).toVector
    rays = flat(shadows)
    // The same rays in the tumbler's own space (its placement undone; a translation, so their
    // directions stay unit).
    local = flat(shadows.map(r => Ray(tumbler.transform.pointBack(r.origin), r.direction)))

  /** Rays as six doubles each: origin, then direction. */
  private def flat(rays: Vector[Ray]): Array[Double] =
    rays
      .flatMap(r =>
        Seq(r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z)
      )
      .toArray

  /** The place in the ray arrays of the next ray, cycling through the 1024. */
  private def step(): Int =
    index = (index + 1) & 1023
    6 * index

  /** `Kernel.collect` of `shape` without normals along the ray at `r` of `from`. */
  private def collect(shape: Shape, from: Array[Double], r: Int): Int =
    Kernel.collect(
      shape,
      from(r),
      from(r + 1),
      from(r + 2),
      from(r + 3),
      from(r + 4),
      from(r + 5),
      buffer,
      0,
      false
    )

  /** `Kernel.collect` of the tumbler without normals, as a shadow ray collects it. */
  @Benchmark def crossings: Int = collect(tumbler, rays, step())

  /** The difference in its own space (no placement). */
  @Benchmark def difference: Int = collect(inner, local, step())

  /** The outer cylinder alone, in the tumbler's space. */
  @Benchmark def cylinder: Int = collect(outer, local, step())

  /** An inside test of the outer cylinder, at a ray's origin in the tumbler's space. */
  @Benchmark def inside: Boolean =
    val r = step()
    Kernel.inside(outer, local(r), local(r + 1), local(r + 2))
