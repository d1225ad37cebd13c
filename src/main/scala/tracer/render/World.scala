package tracer.render

import tracer.geometry.{Ray, Shape}
import tracer.scene.{Light, Scene, Surface}

/** A scene compiled for tracing: its shapes, surfaces and lights in flat arrays.
  *
  * Built once per picture from the immutable [[tracer.scene.Scene]] and never changed after.
  */
final class World(scene: Scene):
  private val shapes: Array[Shape]     = scene.objects.map(_.shape).toArray
  private val surfaces: Array[Surface] = scene.objects.map(_.surface).toArray

  /** The lights, in document order. */
  val lights: IndexedSeq[Light] = scene.lights.toIndexedSeq

  /** The background colour. */
  val background = scene.background

  /** The shape with index `i`. */
  def shape(i: Int): Shape = shapes(i)

  /** The surface of shape `i`. */
  def surface(i: Int): Surface = surfaces(i)

  /** The index of the shape `ray` hits first (smallest t > 0; the first in document order on a
    * tie), or −1 when it hits nothing.
    */
  def nearest(ray: Ray): Int =
    // Perf: a while loop keeping the best index and distance; nothing is allocated per shape.
    var best  = -1
    var bestT = Double.PositiveInfinity
    var i     = 0
    while i < shapes.length do
      val t = Shape.distance(shapes(i), ray)
      if t < bestT then
        bestT = t
        best = i
      i += 1
    best

  /** True when some shape is hit by `ray` at a t with 0 < t < `limit` (a shadow test). */
  def occluded(ray: Ray, limit: Double): Boolean =
    // Perf: stops at the first blocker; order does not matter for a yes/no answer.
    var i = 0
    while i < shapes.length && !(Shape.distance(shapes(i), ray) < limit) do i += 1
    i < shapes.length
