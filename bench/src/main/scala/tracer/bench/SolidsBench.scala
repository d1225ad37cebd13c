package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.geometry.{CrossingBuffer, Kernel, Ray, Shape}
import tracer.render.{CameraConfig, Projection, Query, World}

/** The general route on the gallery's `scenes/solids.xml` (version 3: CSG, placed solids, a
  * torus, cones): the reference `Shape` functions against the kernel on plain doubles, and the
  * whole nearest-hit query.
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 -prof gc SolidsBench"` — ns and bytes per test; each
  * call tests one primary ray against one of the scene's shapes, cycling through both.
  */
@State(Scope.Thread)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.NANOSECONDS)
class SolidsBench:
  // Why: JMH state, built by setup() before any measurement: fields JMH can reach, so vars;
  // `index` is the cursor that walks the rays and shapes, one step a call.
  var world: World           = null // nosemgrep: no-null — set by setup() before any benchmark
  var query: Query           = null // nosemgrep: no-null — set by setup() before any benchmark
  var buffer: CrossingBuffer = null // nosemgrep: no-null — set by setup() before any benchmark
  var rays: Array[Ray]       = null // nosemgrep: no-null — set by setup() before any benchmark
  var shapes: Array[Shape]   = null // nosemgrep: no-null — set by setup() before any benchmark
  var index                  = 0

  @Setup def setup(): Unit =
    val scene = GalleryScene.load("solids.xml")
    world = World(scene)
    query = world.newQuery()
    buffer = CrossingBuffer()
    shapes = scene.objects.map(_.shape).toArray
    // 1024 primary rays over the middle of the picture, where the solids stand.
    val projection = Projection(scene.camera, CameraConfig.forCamera(scene.camera, 64))
    rays = Array.tabulate(1024)(i => projection.ray(i % 64 + 0.5, 10 + (i / 64) % 16 + 0.5))

  private def step(): Int =
    index = (index + 1) & 0xfffff
    index

  /** `Shape.distance`, the reference (lists, tuples and options on the general route). */
  @Benchmark def distanceReference: Double =
    val i = step()
    Shape.distance(shapes(i % shapes.length), rays(i & 1023))

  /** `Kernel.distance`: the same bits on plain doubles. */
  @Benchmark def distanceKernel: Double =
    val i = step()
    val r = rays(i & 1023)
    val o = r.origin
    val d = r.direction
    Kernel.distance(shapes(i % shapes.length), o.x, o.y, o.z, d.x, d.y, d.z, buffer)

  /** `Shape.crossings`, the reference for combinations. */
  @Benchmark def crossingsReference: Int =
    val i = step()
    Shape.crossings(shapes(i % shapes.length), rays(i & 1023)).size

  /** `Kernel.collect`: the same crossings into the buffer. */
  @Benchmark def crossingsKernel: Int =
    val i = step()
    val r = rays(i & 1023)
    val o = r.origin
    val d = r.direction
    Kernel.collect(shapes(i % shapes.length), o.x, o.y, o.z, d.x, d.y, d.z, buffer, 0)

  /** The nearest hit of a primary ray through the world (hierarchy and kernel). */
  @Benchmark def nearest: Int = world.nearest(rays(step() & 1023), query)
