package tracer.render

import scala.concurrent.{Await, ExecutionContext, Future}
import scala.concurrent.duration.Duration
import tracer.geometry.{Csg, CsgOperation, Hit, Mesh, Placed, Ray, Shape}
import tracer.math.Vec3
import tracer.scene.{Light, Scene, SceneObject, Surface}

/** A scene compiled for tracing: its shapes and surfaces in flat arrays, the bounded shapes in a
  * [[Bvh]] (the ray kernel), the unbounded ones (planes) in a list of their own; each shape tested
  * as its [[Route]] says. Built once per picture from the immutable [[tracer.scene.Scene]] and
  * never changed after. `pool` (the render's threads) builds the hierarchy of a large mesh in
  * parallel; without it everything is built on the calling thread, to the same result.
  *
  * @param shadowRays about how many shadow rays toward each point light the render will trace
  *   (its samples: 0 for none); when that is at least [[LightBuffer.RaysPerItem]] an item its
  *   shadow rays may meet, each point light gets a [[LightBuffer]] (in a world that lets light
  *   through, over its opaque shapes, unless a clear shape is a mesh)
  * @param eyeRays about how many rays the render will trace from the camera's location (its
  *   primary rays: pixels times samples); when that is at least [[EyeBuffer.MinRays]] and
  *   [[EyeBuffer.RaysPerItem]] an item, or [[EyeBuffer.ShortRenderRaysPerItem]] an item, of a
  *   tree of at least [[EyeBuffer.MinItems]] items, the camera gets an [[EyeBuffer]] that answers
  *   them; and trees of many more primitives than that get coarser leaves, quicker to build
  *   ([[BvhBuilder.wholeLeaf]]); 0 (unknown, the default) for no buffer and the finest trees
  * @param mirrorRays about how many of the camera's rays the render will reflect off its mirroring
  *   planes (Whitted's full mode: its primary rays); when that is as many as `eyeRays` needs,
  *   each plane that mirrors gets an [[EyeBuffer]] around the camera's mirror image, which answers
  *   the rays it reflects from the camera's
  * @param eyeOnly    whether every ray the render traces starts at the camera (Whitted's quick
  *   mode): then, when the camera's buffer will answer them all, nothing walks the trees but the
  *   buffer's build, and they are built coarse ([[BvhBuilder.wholeLeaf]] of one ray)
  */
final class World(
    scene: Scene,
    pool: Option[ExecutionContext] = None,
    shadowRays: Long = 0,
    eyeRays: Long = 0,
    mirrorRays: Long = 0,
    eyeOnly: Boolean = false
):
  private val objects: Array[SceneObject] = scene.objects.toArray
  private val shapes: Array[Shape]        = objects.map(_.shape)
  // The rays the trees are built for: the primary rays when known, else as many as need the
  // finest; one when the camera's buffer will answer every ray (World.walkless).
  private val rays =
    if eyeOnly && World.walkless(shapes, eyeRays) then 1L
    else if eyeRays > 0 then eyeRays
    else Long.MaxValue
  private val surfaces: Array[Surface] = objects.map(_.surface)
  // Perf: whether each shape shows more than one surface, asked once: a `Vector`'s isEmpty on
  // every hit went through `lengthCompare` and `length` calls the JIT left out of line (1% of a
  // 3840×2160 mesh-20000 run's processor samples; docs/performance.md, round 48).
  private val leafy: Array[Boolean] = objects.map(_.leafSurfaces.nonEmpty)
  private val bvh                   = Bvh(shapes.toIndexedSeq, pool, rays = rays)
  // The shapes the hierarchy left out for having no bounds: the builder asked each shape once.
  private val unbounded = Primitives(shapes.toIndexedSeq, bvh.unbounded)
  // Each shape's mesh tree (None for a shape that is not a mesh), found once.
  private val trees = bvh.meshTrees(shapes.length)

  /** The lights, in document order. */
  val lights: IArray[Light] = IArray.from(scene.lights)

  /** Where the lights stand, three doubles a light (x, y, z), in the order of [[lights]].
    *
    * Perf: read by the shading for every shaded point (Shading.lit), without a `Light` and a
    * `Vec3` to reach per light.
    */
  private[render] val lightPoints: Array[Double] =
    lights.iterator.flatMap(l => Iterator(l.location.x, l.location.y, l.location.z)).toArray

  // Perf: every area light's sub-light positions centre + offset(u, v), computed once a world
  // and shared by every row task and both integrators (x, y, z at 3(u·samplesB + v); empty for a
  // point light), so a shadow sample makes no Vec3 (RenderBench; docs/performance.md, round 4).
  private val subLightGrid: IArray[IArray[Double]] =
    lights.map(l => l.area.fold(IArray.emptyDoubleIArray)(World.positions(l.location, _)))

  /** The sub-light positions of light `k` (an area light): sub-light (u, v)'s x, y and z at
    * 3(u·samplesB + v), 3(u·samplesB + v) + 1 and + 2. Empty for a point light.
    */
  def subLights(k: Int): IArray[Double] = subLightGrid(k)

  /** Where light `k` shines from: an area light's sub-lights in the order of [[subLights]], or a
    * point light's location alone.
    */
  def subLightPositions(k: Int): IndexedSeq[Vec3] =
    val grid = subLightGrid(k)
    if grid.isEmpty then Vector(lights(k).location)
    else Vector.tabulate(grid.length / 3)(s => Vec3(grid(3 * s), grid(3 * s + 1), grid(3 * s + 2)))

  /** The background colour. */
  val background = scene.background

  /** The most sub-lights of any one area light (0 without area lights). */
  val largestAreaLight: Int =
    lights.iterator.flatMap(_.area).map(a => a.samplesA * a.samplesB).maxOption.getOrElse(0)

  // Which shapes show a surface that lets light through.
  private val letThrough: Array[Boolean] = objects.map(_.transmits)

  /** The shapes that let light through, in index order. */
  private[render] val clearShapes: Array[Int] = Array.range(0, shapes.length).filter(letThrough(_))

  /** True when some surface lets light through, so shadow rays must weigh what they cross. */
  val transmits: Boolean = clearShapes.nonEmpty

  /** True when shape `i` shows a surface that lets light through (its `transmit` above 0). */
  def letsThrough(i: Int): Boolean = letThrough(i)

  /** True when the shadow rays of an area light test the few shapes its beam may meet
    * ([[Shadows]]): a world of at most [[World.BeamShapes]] shapes with an area light.
    */
  val beams: Boolean = largestAreaLight > 0 && shapes.length <= World.BeamShapes

  /** Every shape as a primitive of its own, in index order, for the beams (empty without). */
  private[render] val each: Primitives =
    if beams then Primitives(shapes.toIndexedSeq, shapes.indices.toArray, known = bvh.meshTree)
    else Primitives(IndexedSeq.empty, Array.emptyIntArray)

  // Perf: each shape's box for the beams, lo then hi at 6i, widened by 10⁻⁷ of its coordinates'
  // size (as the tree rounds its boxes outwards to floats); a shape without bounds has NaN (a
  // plane is then tested by its side, anything else always kept).
  private[render] val boxes: Array[Double] =
    if !beams then Array.emptyDoubleArray else shapes.flatMap(World.widenedBox)

  /** True when shadow rays weigh the clear shapes from the crossings each gives along the whole
    * ray, tested once ([[Shadows]]), after an any-hit test of the opaque shapes alone: a world
    * that transmits, none of whose clear shapes is a mesh (whose crossings would be all its
    * faces'; such a world walks from hit to hit in the world's tree).
    */
  val clearWalks: Boolean = transmits && clearShapes.forall(i =>
    shapes(i) match
      case _: Mesh => false
      case _       => true
  )

  // Each clear shape's transmit, at j for clearShapes(j): NaN for one that shows a surface per leaf.
  private[render] val clearTransmits: Array[Double] =
    clearShapes.map(i => if hasLeafSurfaces(i) then Double.NaN else surfaces(i).transmit)

  // Each clear shape's box, widened as `boxes` (NaN for an unbounded one), at 6j for clearShapes(j).
  private[render] val clearBoxes: Array[Double] =
    if !clearWalks then Array.emptyDoubleArray
    else clearShapes.flatMap(i => World.widenedBox(shapes(i)))

  // The opaque shapes on their own, for the any-hit test of clearWalks: a hierarchy of the bounded
  // ones (sharing the meshes' trees with the whole world's) and the unbounded ones.
  private val opaqueIndex =
    if clearWalks then shapes.indices.filterNot(letThrough) else IndexedSeq.empty[Int]
  private val opaqueTree =
    Option.when(clearWalks)(Bvh(opaqueIndex.map(shapes), pool, known = bvh.meshTree, rays = rays))
  private val opaqueUnbounded = opaqueTree.fold(Primitives(IndexedSeq.empty, Array.emptyIntArray)) {
    t => Primitives(opaqueIndex.map(shapes), t.unbounded)
  }

  // Perf: a point light's shadow rays look up their cell of its buffer and test a few items,
  // instead of walking the tree (docs/performance.md, round 19); only where the render is long
  // enough to pay for the buffers, however shallow the tree (a one-leaf tree's rays still tested
  // its box and its every shape: the few-object scene −13% a 720p frame; round 21). The items are
  // the shapes a shadow ray asks "blocked?": all of them in a world that lets no light through,
  // the opaque ones (in their own tree) in one that clearWalks.
  private val shadowTree: Bvh             = if transmits then opaqueTree.getOrElse(bvh) else bvh
  private val shadowUnbounded: Primitives = if transmits then opaqueUnbounded else unbounded
  private val buffered                    = (!transmits || clearWalks) &&
    lights.exists(_.area.isEmpty) && shadowRays >= LightBuffer.RaysPerItem * shadowTree.itemCount
  // Perf: triangles binned by their outlines when enough rays will ask each item (round 32).
  private val outlinedLights =
    shadowRays >= LightBuffer.OutlineRaysPerItem * shadowTree.itemCount
  private val items: BufferItems =
    if buffered then shadowTree.bufferItems(outlinedLights) else BufferItems.empty

  // Perf: rays from the camera, and those a mirroring plane reflects from it, look up their cell
  // of a buffer around the camera (or its mirror image) and test a few items, nearest first,
  // instead of walking the tree (docs/performance.md, round 20); only where the walk is more than
  // a node, the items many, and the render long enough to pay for the buffer (its build and its
  // code's compilation in the JIT's window). Their items are all the tree's (the point lights'
  // when those are the same).
  private def worth(rays: Long) =
    bvh.deep && bvh.itemCount >= EyeBuffer.MinItems && EyeBuffer.pays(rays, bvh.itemCount)
  private val centres: IArray[Vec3] =
    val eye    = scene.camera.location
    val images = if worth(mirrorRays) then World.mirrorImages(eye, objects) else IArray.empty[Vec3]
    if worth(eyeRays) then eye +: images else images

  // The point lights' buffers and the centres', built on the pool when there is one (a buffer a
  // task).
  private val (buffers, eyes): (IArray[Option[LightBuffer]], IArray[EyeBuffer]) =
    def build(l: Light) =
      if !buffered || l.area.isDefined then None
      else LightBuffer.build(l.location.x, l.location.y, l.location.z, items)
    val outlinedEyes =
      Math.max(eyeRays, mirrorRays) >= LightBuffer.OutlineRaysPerItem * bvh.itemCount
    lazy val every =
      if buffered && (shadowTree eq bvh) && outlinedEyes == outlinedLights then items
      else bvh.bufferItems(outlinedEyes)
    def around(c: Vec3) = EyeBuffer.build(c.x, c.y, c.z, every)
    pool match
      case Some(context) if centres.nonEmpty || buffered && lights.count(_.area.isEmpty) > 1 =>
        given ExecutionContext = context
        val eyesBuilt          = Future.traverse(centres.toSeq)(c => Future(around(c)))
        val built              = Future.traverse(lights.toSeq)(l => Future(build(l)))
        (
          IArray.from(Await.result(built, Duration.Inf)),
          IArray.from(Await.result(eyesBuilt, Duration.Inf).flatten)
        )
      case _ => (lights.map(build), centres.flatMap(around))

  /** The camera's buffer when the world has one. */
  private[render] def eyeBuffer: Option[EyeBuffer] =
    val eye = scene.camera.location
    eyes.find(b => b.x == eye.x && b.y == eye.y && b.z == eye.z)

  /** The buffers around the camera and its mirror images (tests observe which rays they answer). */
  private[render] def eyeBuffers: IArray[EyeBuffer] = eyes

  /** The buffer of light `k` when it has one (a point light, in a world that builds them). */
  private[render] def lightBuffer(k: Int): Option[LightBuffer] = buffers(k)

  /** [[occludedAlong]] (in a world that lets light through, [[opaqueAlong]]) for a shadow ray
    * toward the point light whose buffer is `buffer`, from (ox, oy, oz) in unit direction
    * (dx, dy, dz), `limit` the distance to the light: the same answer, from the unbounded shapes,
    * the buffer's items tested on every ray and those of the ray's cell (the tree when the
    * buffer does not answer the ray). The direction must point at the light and `limit` be the
    * distance from the origin to it, as a shading point's shadow ray has them: the items whose
    * boxes lie farther from the light than `limit` are skipped ([[Bvh.anyBlocks]]), which a
    * shorter ray would need tested.
    */
  private[render] def occludedToward(
      buffer: LightBuffer,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    val cell = buffer.cell(dx, dy, dz, limit)
    if cell == LightBuffer.Walk then
      if transmits then opaqueAlong(ox, oy, oz, dx, dy, dz, limit, query)
      else occludedAlong(ox, oy, oz, dx, dy, dz, limit, query)
    else
      // Perf: as occludedAlong, the unbounded shapes in a plain loop that stops at the first.
      var k = 0
      while k < shadowUnbounded.size && !(shadowUnboundedDistance(
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
      k < shadowUnbounded.size ||
      shadowTree.anyBlocks(
        buffer,
        buffer.always,
        0,
        buffer.always.length,
        ox,
        oy,
        oz,
        dx,
        dy,
        dz,
        limit,
        query
      ) ||
      cell >= 0 && shadowTree.anyBlocks(
        buffer,
        buffer.items,
        buffer.start(cell),
        buffer.start(cell + 1),
        ox,
        oy,
        oz,
        dx,
        dy,
        dz,
        limit,
        query
      )

  /** True when item `item` of light buffer `buffer` blocks the shadow ray from (ox, oy, oz) in
    * unit direction (dx, dy, dz) before `limit`: a guess tested before [[occludedToward]], whose
    * answer it gives when true.
    */
  private[render] def itemBlocks(
      buffer: LightBuffer,
      item: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean = shadowTree.itemBlocks(buffer, item, ox, oy, oz, dx, dy, dz, limit, query)

  /** True when shape `i` (its face `face`, a mesh's face a nearest query named) blocks the
    * shadow ray from (ox, oy, oz) in unit direction (dx, dy, dz) at a t below `limit`, tested as
    * the walks test it ([[Bvh.ownBlocks]]); false for an unbounded shape and in a world that lets
    * light through (where a shape may block only part of the light).
    *
    * Perf: a point light behind a flat opaque surface is shadowed by that surface itself: one
    * test of it answers the shadow ray before the light's guess and buffer (docs/performance.md,
    * round 28).
    */
  def ownBlocks(
      i: Int,
      face: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    !transmits && bvh.ownBlocks(i, face, ox, oy, oz, dx, dy, dz, limit, query)

  /** Primitives.distance of unbounded shape `k` of those shadow rays toward a buffered light
    * ask (all of them, or in a world that lets light through, the opaque ones).
    */
  private def shadowUnboundedDistance(
      k: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      query: Query
  ): Double = Primitives.distance(shadowUnbounded, k, cutoff, ox, oy, oz, dx, dy, dz, query)

  /** The number of shapes. */
  def size: Int = shapes.length

  /** The hierarchy over the bounded shapes ([[Shadows]] tests a blocker guess on it). */
  private[render] def tree: Bvh = bvh

  /** The tree the hierarchy built for `mesh`, one of the world's shapes (tests observe that it is
    * built once).
    */
  private[render] def meshTree(mesh: tracer.geometry.Mesh): Option[MeshTree] = bvh.meshTree(mesh)

  /** The shape with index `i`. */
  def shape(i: Int): Shape = shapes(i)

  /** The tree of shape `i` when it is a mesh (the scene's meshes each have one), for its faces'
    * planes ([[Hits.record]]).
    */
  private[render] def treeOf(i: Int): Option[MeshTree] = trees(i)

  /** The surface of shape `i` as a whole (for a CSG combination, the one that holds its `ior`). */
  def surface(i: Int): Surface = surfaces(i)

  /** The surface that primitive `leaf` of shape `i` shows (see [[tracer.geometry.Hit.leaf]]). */
  def surface(i: Int, leaf: Int): Surface =
    if leafy(i) then objects(i).surfaceOf(leaf) else surfaces(i)

  /** True when shape `i` shows more than one surface, so a hit must say which leaf it is on. */
  def hasLeafSurfaces(i: Int): Boolean = leafy(i)

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
    // Perf: the unbounded shapes first (their nearest distance left in query.distance), then the
    // hierarchy, pruned by the nearest of them, or for a ray from the camera, its buffer. Each
    // step is a method of its own, so this one is small and has no loop: the JIT compiles it
    // once, quickly (docs/performance.md, round 9). `length == 0`, not `isEmpty`: an IArray's
    // isEmpty asks java.lang.reflect.Array.getLength, a native call a ray until C2 has compiled
    // this (round 37).
    val best   = nearestUnbounded(ox, oy, oz, dx, dy, dz, limit, query)
    val winner =
      if eyes.length == 0 then bvh.nearest(ox, oy, oz, dx, dy, dz, query.distance, best, query)
      else nearestBounded(ox, oy, oz, dx, dy, dz, best, query)
    if winner == Int.MaxValue then
      query.distance = Double.PositiveInfinity
      -1
    else winner

  /** [[Bvh.nearest]]'s answer for the ray, competing with shape `best` at `query.distance`: from
    * the first buffer of [[eyeBuffers]] that answers it, else from the walk.
    */
  private def nearestBounded(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      best: Int,
      query: Query
  ): Int =
    // Perf: a plain loop over the (few) buffers, the camera's first.
    var behind = -1.0
    var k      = 0
    while k < eyes.length && behind < 0 do
      behind = eyes(k).behind(ox, oy, oz, dx, dy, dz)
      k += 1
    if behind < 0 then bvh.nearest(ox, oy, oz, dx, dy, dz, query.distance, best, query)
    else nearestFromEye(eyes(k - 1), behind, ox, oy, oz, dx, dy, dz, best, query)

  /** [[Bvh.nearest]]'s answer for a ray that `buffer` answers, starting `behind` beyond its
    * centre, competing with shape `best` at `query.distance`: the items tested on every ray, then
    * those of the ray's cell (the tree when the buffer does not answer the ray's direction).
    */
  private def nearestFromEye(
      buffer: EyeBuffer,
      behind: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      best: Int,
      query: Query
  ): Int =
    val cell = buffer.cell(dx, dy, dz)
    if cell == LightBuffer.Walk then
      bvh.nearest(ox, oy, oz, dx, dy, dz, query.distance, best, query)
    else
      val cells  = buffer.cells
      val owner  = cells.owner
      val face   = cells.face
      val gaps   = cells.gaps
      val always = cells.always
      query.face = -1
      val first =
        bvh.nearestAmong(
          owner,
          face,
          gaps,
          always,
          0,
          always.length,
          ox,
          oy,
          oz,
          dx,
          dy,
          dz,
          behind,
          best,
          query
        )
      if cell < 0 then first
      else
        val from = cells.start(cell)
        val to   = cells.start(cell + 1)
        bvh.nearestAmong(
          owner,
          face,
          gaps,
          cells.items,
          from,
          to,
          ox,
          oy,
          oz,
          dx,
          dy,
          dz,
          behind,
          first,
          query
        )

  /** The index of the unbounded shape that the ray from (ox, oy, oz) in unit direction
    * (dx, dy, dz) hits first at a t ≤ `limit` (the first in index order on a tie), or
    * `Int.MaxValue` for none; its distance (else `limit`) is left in `query.distance`.
    */
  private def nearestUnbounded(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Int =
    // Perf: a plain loop in index order, so the first wins a tie; each shape's test a method of
    // its own (unboundedDistance), so this loop compiles small.
    var best  = Int.MaxValue
    var bestT = limit
    var k     = 0
    while k < unbounded.size do
      val t = unboundedDistance(k, bestT, ox, oy, oz, dx, dy, dz, query)
      if t < bestT || (t == bestT && t < Double.PositiveInfinity && best == Int.MaxValue) then
        bestT = t
        best = unbounded.index(k)
      k += 1
    query.distance = bestT
    best

  /** Primitives.distance of unbounded shape `k` (the kernel's whole test, in one method). */
  private def unboundedDistance(
      k: Int,
      cutoff: Double,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      query: Query
  ): Double = Primitives.distance(unbounded, k, cutoff, ox, oy, oz, dx, dy, dz, query)

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
    // do), each test a method of its own (unboundedDistance) so this one compiles small, then
    // the hierarchy; no closure per shadow ray.
    var k = 0
    while k < unbounded.size && !(unboundedDistance(
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

  /** As [[occludedAlong]] among the shapes that let no light through (only in a world that
    * [[clearWalks]]; elsewhere false).
    */
  def opaqueAlong(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double,
      query: Query
  ): Boolean =
    // Perf: as occludedAlong.
    var k = 0
    while k < opaqueUnbounded.size &&
      !(Primitives.distance(opaqueUnbounded, k, limit, ox, oy, oz, dx, dy, dz, query) < limit)
    do k += 1
    // Why: a match, not `exists`, whose closure the code before C2 made for every ray (JFR).
    k < opaqueUnbounded.size || (opaqueTree match
      case Some(tree) => tree.occluded(ox, oy, oz, dx, dy, dz, limit, query)
      case None       => false)

  /** The shapes that hold `point` inside them, innermost first: the list a ray starting at
    * `point` carries across surfaces ([[Refraction]]). As POV-Ray's `InitRayContainerState` finds
    * the objects around the camera, so that a camera inside a glass sphere looks out through it:
    * every object, clear or opaque (each has an interior there, its index of refraction among
    * them); of several around the point, the unbounded ones (planes) count as the outer, as
    * POV-Ray's bounding tree lists them first, and otherwise the later in the scene counts as the
    * inner. A union is listed once for each of its parts that holds the point
    * ([[World.partsHolding]]), as POV-Ray, which splits a union into its children, lists the
    * union's interior once for each child around its camera.
    */
  def containing(point: Vec3): List[Int] =
    val around =
      shapes.indices.toList.flatMap(i => List.fill(World.partsHolding(shapes(i), point))(i))
    val outer                = bvh.unbounded.toSet
    val (unbounded, bounded) = around.partition(outer)
    (unbounded ++ bounded).reverse

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

/** Precomputation for [[World]]. */
object World:
  /** How many of the parts POV-Ray splits `shape` into hold `point`: a union is split into its
    * children (nested unions likewise, placed or not), any other shape is one part; 0 when the
    * point lies outside it.
    */
  private[render] def partsHolding(shape: Shape, point: Vec3): Int = shape match
    case Csg(CsgOperation.Union, children) => children.map(partsHolding(_, point)).sum
    case p: Placed                         => partsHolding(p.shape, p.transform.pointBack(point))
    case _                                 => if Shape.inside(shape, point) then 1 else 0

  /** The most shapes a world may have for its area lights' shadow rays to be tested shape by
    * shape in the beam ([[World.beams]]): beyond it the tree's walk is the better cull.
    */
  val BeamShapes: Int = 64

  /** The shape's bounds as six doubles, lo then hi, widened by 10⁻⁷ of their coordinates' size
    * (as the tree rounds its boxes outwards to floats); NaN for a shape without bounds.
    */
  private def widenedBox(shape: Shape): Array[Double] =
    Shape.bounds(shape).fold(Array.fill(6)(Double.NaN)) { b =>
      val box = Array(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z)
      widen(box, 0)
      box
    }

  /** True when a render of `rays` rays, all from the camera, over `shapes` will build the
    * camera's buffer over a tree coarse enough to be deep: more than sixteen of the coarsest
    * leaves' worth of items ([[BvhBuilder.CoarseLeaf]]), each bounded shape one and each face of
    * a mesh one (planes none), and rays enough to pay for it ([[EyeBuffer.pays]]).
    *
    * Perf: in quick mode at 3840×2160 of 20,000 `<triangle>`s, the fine tree's build was 29 ms
    * of a 600 ms first frame, and no ray walks it (docs/performance.md, round 32).
    */
  private[render] def walkless(shapes: Array[Shape], rays: Long): Boolean =
    // Perf: a plain count, once a world (a million faces count as one mesh).
    var items = 0L
    var k     = 0
    while k < shapes.length do
      items += (shapes(k) match
        case m: Mesh                  => m.faceCount.toLong
        case _: tracer.geometry.Plane => 0L
        case _                        => 1L)
      k += 1
    items > 16L * BvhBuilder.CoarseLeaf && EyeBuffer.pays(rays, items)

  /** Widens the box at `at` of `boxes` (six doubles, lo then hi) by 10⁻⁷ of its coordinates'
    * size, 1 + the largest |coordinate|: what the beams' and the light buffers' boxes take for
    * the tree's rounding of its boxes outwards to floats.
    */
  private[render] def widen(boxes: Array[Double], at: Int): Unit =
    // Perf: run for every item of a light buffer (up to millions, cold): no range or collection.
    var largest = 0.0
    var c       = 0
    while c < 6 do
      largest = Math.max(largest, Math.abs(boxes(at + c)))
      c += 1
    val m = 1e-7 * (1 + largest)
    c = 0
    while c < 3 do
      boxes(at + c) -= m
      boxes(at + 3 + c) += m
      c += 1

  /** Where the camera at `eye` appears in each plane among `objects` that mirrors (its surface's
    * reflection above 0), as seen from the rays it reflects: the eye mirrored in the plane and
    * moved off it as shading moves a reflected ray's start ([[Shading.Epsilon]] along the normal
    * facing the eye), so each such ray lies on a line through that point (none for an eye in the
    * plane).
    */
  private[render] def mirrorImages(eye: Vec3, objects: Array[SceneObject]): IArray[Vec3] =
    IArray.from(objects.iterator.flatMap { o =>
      o.shape match
        case p: tracer.geometry.Plane if o.surface.reflection > 0 =>
          val side = p.normal.dot(eye) - p.distance
          val n    = if side > 0 then p.normal else -p.normal
          Option.when(side != 0)(eye - p.normal * (2 * side) + n * Shading.Epsilon)
        case _ => None
    })

  /** The positions centre + offset(u, v) of an area light's sub-lights, x, y, z at 3(u·samplesB + v). */
  private def positions(centre: Vec3, light: tracer.scene.AreaLight): IArray[Double] =
    val out = new Array[Double](3 * light.samplesA * light.samplesB)
    for u <- 0 until light.samplesA; v <- 0 until light.samplesB do
      val p = centre + light.offset(u, v)
      val k = u * light.samplesB + v
      out(3 * k) = p.x; out(3 * k + 1) = p.y; out(3 * k + 2) = p.z
    IArray.unsafeFromArray(out)
