package tracer.bench

import java.util.concurrent.TimeUnit
import org.openjdk.jmh.annotations.*
import tracer.geometry.{Plane, Ray, Shape, Sphere, Triangle}
import tracer.math.Vec3

/** Ray–shape tests, the innermost kernel: `Shape.distance` for each shape, hit and miss.
  *
  * `./sbt "bench/Jmh/run -f 1 -wi 3 -i 5 -prof gc IntersectBench"` — expect 0 B/op.
  */
@State(Scope.Thread)
@BenchmarkMode(Array(Mode.AverageTime))
@OutputTimeUnit(TimeUnit.NANOSECONDS)
class IntersectBench:
  // Why: inputs in (JMH state) var fields, so the JIT cannot fold them into constants.
  var sphere: Shape   = Sphere(Vec3(0, 0, 5), 1)
  var plane: Shape    = Plane.at(Vec3(0, 1, 0), -1)
  var triangle: Shape = Triangle(Vec3(-1, -1, 5), Vec3(1, -1, 5), Vec3(0, 1, 5))
  var hit: Ray        = Ray(Vec3.Zero, Vec3(0.05, -0.05, 1).normalisedOr(Vec3.UnitZ))
  var miss: Ray       = Ray(Vec3.Zero, Vec3(0.5, 0.3, 1).normalisedOr(Vec3.UnitZ))

  /** A ray that hits a sphere. */
  @Benchmark def sphereHit: Double = Shape.distance(sphere, hit)

  /** A ray that misses a sphere. */
  @Benchmark def sphereMiss: Double = Shape.distance(sphere, miss)

  /** A ray that hits a plane. */
  @Benchmark def planeHit: Double = Shape.distance(plane, hit)

  /** A ray that hits a triangle. */
  @Benchmark def triangleHit: Double = Shape.distance(triangle, hit)

  /** A ray that misses a triangle. */
  @Benchmark def triangleMiss: Double = Shape.distance(triangle, miss)
