package tracer.render

import scala.concurrent.ExecutionContext
import tracer.geometry.{Hit, Mesh, Ray, Shape}
import tracer.scene.{Light, Scene, SceneObject, Surface}

/** A scene compiled for tracing: its shapes and surfaces in flat arrays, the bounded shapes in a
  * [[Bvh]] (the ray kernel), the unbounded ones (planes) in a list of their own; each shape tested
  * as its [[Route]] says. Built once per picture from the immutable [[tracer.scene.Scene]] and
  * never changed after. `pool` (the render's threads) builds the hierarchy of a large mesh in
  * parallel; without it everything is built on the calling thread, to the same result.
  */
final class World(scene: Scene, pool: Option[ExecutionContext] = None):
  private val objects: Array[SceneObject] = scene.objects.toArray
  private val shapes: Array[Shape]        = objects.map(_.shape)
  private val surfaces: Array[Surface]    = objects.map(_.surface)
  private val unbounded                   =
    Primitives(
      shapes.toIndexedSeq,
      shapes.indices.filter(i => Shape.bounds(shapes(i)).isEmpty).toArray
    )
  private val bvh = Bvh(shapes.toIndexedSeq, pool)

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
  def newQuery(): Query = Query()

  /** The index of the shape `ray` hits first (smallest t > 0; the first in document order on a
    * tie), or −1 when it hits nothing; its distance t is left in `query.distance` (+∞ for none).
    * `query` comes from [[newQuery]] and is not shared between threads.
    */
  def nearest(ray: Ray, query: Query): Int =
    val o = ray.origin
    val d = ray.direction
    nearestAlong(o.x, o.y, o.z, d.x, d.y, d.z, Double.PositiveInfinity, query)

  /** As [[nearest]] for the ray from (ox, oy, oz) in unit direction (dx, dy, dz), counting only
    * hits at t ≤ `limit`.
    */
  def nearestAlong(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Int =
    // Perf: the unbounded shapes in a plain loop (in index order, so the first wins a tie), then
    // the hierarchy, pruned by the nearest of them.
    var best  = Int.MaxValue
    var bestT = limit
    var k     = 0
    while k < unbounded.size do
      val t = Primitives.distance(unbounded, k, bestT, ox, oy, oz, dx, dy, dz, query)
      if t < bestT || (t == bestT && t < Double.PositiveInfinity && best == Int.MaxValue) then
        bestT = t
        best = unbounded.index(k)
      k += 1
    val winner = bvh.nearest(ox, oy, oz, dx, dy, dz, bestT, best, query)
    if winner == Int.MaxValue then
      query.distance = Double.PositiveInfinity
      -1
    else winner

  /** The hit on shape `i` (the last [[nearest]] or [[nearestAlong]] with `query` found it) along
    * `ray`, at `query.distance`: [[tracer.geometry.Shape.hitAt]], except that on a mesh the face
    * is the one the query found (the first at that distance), not looked for again.
    */
  def hitAt(i: Int, ray: Ray, query: Query): Hit = shapes(i) match
    case m: Mesh => Shape.hitOnFace(m, query.face, ray, query.distance)
    case other   => Shape.hitAt(other, ray, query.distance)

  /** True when some shape is hit by `ray` at a t with 0 < t < `limit` (a shadow test). */
  def occluded(ray: Ray, limit: Double, query: Query): Boolean =
    val o = ray.origin
    val d = ray.direction
    occludedAlong(o.x, o.y, o.z, d.x, d.y, d.z, limit, query)

  /** As [[occluded]] for the ray from (ox, oy, oz) in unit direction (dx, dy, dz). */
  def occludedAlong(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    // Perf: the unbounded shapes in a plain loop that stops at the first blocker (any hit will
    // do), then the hierarchy; no closure per shadow ray.
    var k = 0
    while k < unbounded.size && !(Primitives.distance(
        unbounded,
        k,
        limit,
        ox,
        oy,
        oz,
        dx,
        dy,
        dz,
        query
      ) < limit)
    do k += 1
    k < unbounded.size || bvh.occluded(ox, oy, oz, dx, dy, dz, limit, query)

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
