package tracer.render

import tracer.geometry.{Ray, Shape}
import tracer.scene.{Light, Scene, SceneObject, Surface}

/** A scene compiled for tracing: its shapes and surfaces in flat arrays, the bounded shapes in a
  * [[Bvh]], the planes (unbounded) in a list of their own. Built once per picture from the
  * immutable [[tracer.scene.Scene]] and never changed after.
  */
final class World(scene: Scene):
  private val objects: Array[SceneObject] = scene.objects.toArray
  private val shapes: Array[Shape]        = objects.map(_.shape)
  private val surfaces: Array[Surface]    = objects.map(_.surface)
  private val planes: Array[Int] = shapes.indices.filterNot(i => Bvh.isBounded(shapes(i))).toArray
  private val bvh                = Bvh(shapes.toIndexedSeq)

  /** The lights, in document order. */
  val lights: IArray[Light] = IArray.from(scene.lights)

  /** The background colour. */
  val background = scene.background

  /** The most sub-lights of any one area light (0 without area lights). */
  val largestAreaLight: Int =
    lights.iterator.flatMap(_.area).map(a => a.samplesA * a.samplesB).maxOption.getOrElse(0)

  /** True when some surface lets light through, so shadow rays must weigh what they cross. */
  val transmits: Boolean = objects.exists(_.surfaces.exists(_.transmit > 0))

  /** The shape with index `i`. */
  def shape(i: Int): Shape = shapes(i)

  /** The surface of shape `i` as a whole (for a CSG combination, the one that holds its `ior`). */
  def surface(i: Int): Surface = surfaces(i)

  /** The surface that primitive `leaf` of shape `i` shows (see [[tracer.geometry.Hit.leaf]]). */
  def surface(i: Int, leaf: Int): Surface = objects(i).surfaceOf(leaf)

  /** True when shape `i` shows more than one surface, so a hit must say which leaf it is on. */
  def hasLeafSurfaces(i: Int): Boolean = objects(i).leafSurfaces.nonEmpty

  /** Scratch space for one thread's queries ([[nearest]], [[occluded]]). */
  def newStack(): Array[Int] = new Array[Int](Bvh.StackSize)

  /** The index of the shape `ray` hits first (smallest t > 0; the first in document order on a
    * tie), or −1 when it hits nothing. `stack` comes from [[newStack]] and is not shared.
    */
  def nearest(ray: Ray, stack: Array[Int]): Int =
    // Perf: planes in a plain loop, then the hierarchy, pruned by the nearest plane.
    var best  = Int.MaxValue
    var bestT = Double.PositiveInfinity
    var k     = 0
    while k < planes.length do
      val t = Shape.distance(shapes(planes(k)), ray)
      if t < bestT then
        bestT = t
        best = planes(k)
      k += 1
    val winner = bvh.nearest(ray, bestT, best, stack)
    if winner == Int.MaxValue then -1 else winner

  /** True when some shape is hit by `ray` at a t with 0 < t < `limit` (a shadow test). */
  def occluded(ray: Ray, limit: Double, stack: Array[Int]): Boolean =
    var k = 0
    while k < planes.length && !(Shape.distance(shapes(planes(k)), ray) < limit) do k += 1
    k < planes.length || bvh.occluded(ray, limit, stack)

  /** The index of the shape `ray` hits first, by testing every shape: the reference that
    * [[nearest]] must agree with (tests and benchmarks).
    */
  def nearestByBruteForce(ray: Ray): Int =
    shapes.indices
      .foldLeft((-1, Double.PositiveInfinity)) { case ((best, bestT), i) =>
        val t = Shape.distance(shapes(i), ray)
        if t < bestT then (i, t) else (best, bestT)
      }
      ._1
