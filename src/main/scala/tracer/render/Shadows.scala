package tracer.render

import tracer.geometry.{Kernel, Plane, Ray, Shape}
import tracer.math.Vec3
import tracer.scene.AreaLight

/** How much of a light reaches a point: 1 in full light, 0 in full shadow, and in between behind
  * transmitting surfaces and in an area light's penumbra (docs/rendering.md, Shadows).
  *
  * Not thread-safe: it keeps scratch space, so each [[Shading]] makes its own.
  *
  * An area light's shadow rays from one point all lie in its **beam**, the convex hull of the
  * point and the sub-lights. In a small world ([[World.beams]]) the shapes whose boxes lie
  * outside the beam (separated from it along an axis, with a margin far above rounding), and the
  * planes with the whole beam on one side, are left out for all of that point's sub-lights: no
  * ray in the beam can meet them, so testing the rest one by one in index order gives the same
  * nearest hit, distance and tie as the world's tree (`ShadowProperties`).
  *
  * @param world the scene
  * @param query the queries' scratch space, from `world.newQuery()`
  * @param beams false to test every shadow ray with the world's tree (the reference)
  */
final class Shadows(world: World, query: Query, beams: Boolean = true):
  // Perf: the area lights' grid of samples, reused for every shading point (a sample is computed
  // once and shared by the cells that have it as a corner; −1 marks one not yet computed). Sized
  // for the scene's largest area light: a Shading is made per row, so a full 64 × 64 grid for a
  // scene without area lights was 32 KB a row (JFR allocation samples, docs/performance.md).
  private val grid = new Array[Double](world.largestAreaLight)
  // Perf: the beam of the area light being sampled: the shapes its shadow rays may meet, in
  // index order, their count in `inBeam` (−1 when no beam is aimed: the world's tree), and the
  // hull's seven axes (x, y, z and its four sides) with its extent along each (JFR of the
  // gallery's materials and solids: three quarters of the render in the shadow walk; round 7).
  private val beam   = new Array[Int](if beams && world.beams then world.size else 0)
  private var inBeam = -1
  // Perf: no shape in the beam lets light through, so its shadow rays need only know whether
  // anything blocks them: the first blocker found ends a ray, as in a world without glass (a
  // walk would stop at the nearest opaque hit with the same share, 0; docs/performance.md, round 12).
  private var opaqueBeam = true
  // Perf: in a world that clearWalks, the beam's shapes parted: the opaque ones (`solid`, by
  // index, `solidCount` of them) tested for any hit, the clear ones (`clear`, by their place in
  // world.clearShapes) weighed from their crossings, collected once a ray (docs/performance.md,
  // round 16).
  private val parted     = world.clearWalks && beam.length > 0
  private val solid      = new Array[Int](if parted then world.size else 0)
  private var solidCount = 0
  private val clear      = new Array[Int](if parted then world.clearShapes.length else 0)
  private var clearCount = 0
  // Perf: the crossings of a shadow ray's clear shapes, those of the j-th tested at
  // starts(j) until ends(j); `everyClear` lists all of world.clearShapes, for the tree's rays.
  private val crossed    = tracer.geometry.CrossingBuffer()
  private val starts     = new Array[Int](world.clearShapes.length)
  private val ends       = new Array[Int](world.clearShapes.length)
  private val everyClear = Array.range(0, world.clearShapes.length)
  private val axes       = new Array[Double](21)
  private val corners    = new Array[Int](4)
  private val low        = new Array[Double](7)
  private val high       = new Array[Double](7)
  // Perf: the last blocker first. A point light's shadow rays from neighbouring points of a row
  // are mostly blocked by the same shape, so the primitive that blocked the last one from the
  // same light and depth (mod Shadows.Depths: a mirror's points shoot theirs between two of a
  // row's primary points) is tested before the walk; for a mesh, the faces below the node of its
  // tree that held the blocking face. A ray the walk finds unblocked clears the guess: most rays
  // of an open scene are, and a kept guess costs each of them a test (docs/performance.md,
  // round 9). The answer is the walk's either way (ShadowGuessProperties). A world whose walks
  // take one node each (4K few: 4 bounded shapes) guesses nothing: there a guess saves no walk.
  private val tree      = world.tree
  private val guessing  = tree.deep && !world.transmits
  private val guess     = Array.fill(Shadows.Depths * world.lights.length)(-1)
  private val guessNode = new Array[Int](Shadows.Depths * world.lights.length)
  // Perf: the same for a light with a buffer: the item that blocked its last shadow ray from the
  // same depth is tested before the ray's cell (docs/performance.md, round 27).
  private val itemGuess = Array.fill(Shadows.Depths * world.lights.length)(-1)

  /** The share of a point light at distance `reach` in unit direction `toward` from `from`: the
    * product of the `transmit` of every surface crossed at 0 < t < reach (0 at an opaque one).
    */
  def point(from: Vec3, toward: Vec3, reach: Double): Double =
    pointAlong(from.x, from.y, from.z, toward.x, toward.y, toward.z, reach)

  /** The share of the world's light `k`, an area light, that reaches `from`, as POV-Ray 3.7
    * computes it without `adaptive` (`Trace::TraceAreaLightSubsetShadowRay`): the grid's four
    * corners are sampled, and a cell wider than one step is split at its middle sample into four
    * cells (the middle row and column shared when the count is odd); the result is the mean of
    * the four parts. For a point light, [[point]] toward it.
    */
  def area(from: Vec3, k: Int): Double = areaFrom(from.x, from.y, from.z, k)

  /** [[area]] from the point (fx, fy, fz). */
  def areaFrom(fx: Double, fy: Double, fz: Double, k: Int): Double =
    areaBeside(fx, fy, fz, fx, fy, fz, 0, 0, 0, k)

  /** [[areaFrom]] S0 = (fx, fy, fz) just off a face at p, whose own unit normal n faces the ray:
    * a sub-light behind the face's plane (n · (sub-light − S0) < 0), which off-centre sub-lights
    * of a light whose centre is in front, or a smooth mesh's leaning normal, may be, is sought
    * from p − ε·n on the far side, so that its shadow ray passes the face, as POV-Ray's from the
    * surface itself does (`Trace::TracePointLightShadowRay` ignores its own surface there). With
    * n = 0, or every sub-light in front, every sub-light is sought from S0 ([[areaFrom]]).
    */
  def areaBeside(
      fx: Double,
      fy: Double,
      fz: Double,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      k: Int
  ): Double =
    val light = world.lights(k)
    light.area match
      case Some(area) =>
        java.util.Arrays.fill(grid, 0, area.samplesA * area.samplesB, -1.0)
        val positions = world.subLights(k)
        val beside    = Shadows.anyBehind(positions, fx, fy, fz, nx, ny, nz)
        // A beam holds the rays from S0 alone: when a sub-light is sought from beyond the face,
        // the rays walk the tree. (With none behind, `sample` seeks each from S0.)
        if beam.length > 0 && !beside then aim(fx, fy, fz, positions, area)
        val share =
          cell(
            fx,
            fy,
            fz,
            px,
            py,
            pz,
            nx,
            ny,
            nz,
            positions,
            area,
            0,
            0,
            area.samplesA - 1,
            area.samplesB - 1
          )
        inBeam = -1
        share
      case None =>
        val tx    = light.location.x - fx
        val ty    = light.location.y - fy
        val tz    = light.location.z - fz
        val reach = Math.sqrt(tx * tx + ty * ty + tz * tz)
        if reach > 0 then pointAlong(fx, fy, fz, tx / reach, ty / reach, tz / reach, reach) else 1.0

  private def cell(
      fx: Double,
      fy: Double,
      fz: Double,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      positions: IArray[Double],
      light: AreaLight,
      u1: Int,
      v1: Int,
      u2: Int,
      v2: Int
  ): Double =
    if u2 - u1 > 1 || v2 - v1 > 1 then
      val lowU  = (u1 + u2) / 2
      val highU = (u1 + u2 + 1) / 2
      val lowV  = (v1 + v2) / 2
      val highV = (v1 + v2 + 1) / 2
      (cell(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, u1, v1, lowU, lowV) +
        cell(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, highU, v1, u2, lowV) +
        cell(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, u1, highV, lowU, v2) +
        cell(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, highU, highV, u2, v2)) * 0.25
    else
      (sample(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, u1, v1) +
        sample(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, u2, v1) +
        sample(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, u1, v2) +
        sample(fx, fy, fz, px, py, pz, nx, ny, nz, positions, light, u2, v2)) * 0.25

  /** The share of sub-light (u, v) that reaches S0 = (fx, fy, fz), computed once per shading
    * point; sought from p − ε·n when it lies behind the plane of normal n ([[areaBeside]]).
    */
  private def sample(
      fx: Double,
      fy: Double,
      fz: Double,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      positions: IArray[Double],
      light: AreaLight,
      u: Int,
      v: Int
  ): Double =
    val k = u * light.samplesB + v
    if grid(k) < 0 then
      // toLight = (centre + offset) − from, its length and its direction, in plain doubles.
      val tx    = positions(3 * k) - fx
      val ty    = positions(3 * k + 1) - fy
      val tz    = positions(3 * k + 2) - fz
      val reach = Math.sqrt(tx * tx + ty * ty + tz * tz)
      grid(k) =
        if !(reach > 0) then 1.0
        else
          val side = Shading.sideToward(nx, ny, nz, tx, ty, tz)
          if side < 0 then
            pointAlong(
              px + nx * side,
              py + ny * side,
              pz + nz * side,
              tx / reach,
              ty / reach,
              tz / reach,
              reach
            )
          else pointAlong(fx, fy, fz, tx / reach, ty / reach, tz / reach, reach)
    grid(k)

  /** [[pointAlong]] toward the world's light `k`, a point light, from a point shaded `depth`
    * reflections or refractions from the last allowed: the same share, trying first what blocked
    * that light's last shadow ray from the same depth (the buffer's item when the light has a
    * [[LightBuffer]], else the shape), then the light's buffer or the walk.
    */
  def pointToward(
      k: Int,
      depth: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if inBeam >= 0 then pointAlong(fx, fy, fz, dx, dy, dz, reach)
    else
      world.lightBuffer(k) match
        case Some(buffer) => buffered(buffer, k, depth, fx, fy, fz, dx, dy, dz, reach)
        case None         =>
          if guessing then guessed(k, depth, fx, fy, fz, dx, dy, dz, reach)
          else pointAlong(fx, fy, fz, dx, dy, dz, reach)

  /** [[pointToward]] for light `k` through its buffer `buffer`, trying first the item that blocked
    * the light's last shadow ray from the same depth.
    */
  private def buffered(
      buffer: LightBuffer,
      k: Int,
      depth: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    val g = Shadows.Depths * k + (depth & (Shadows.Depths - 1))
    val b = itemGuess(g)
    if b >= 0 && world.itemBlocks(buffer, b, fx, fy, fz, dx, dy, dz, reach, query) then 0.0
    else
      query.blockingItem = -1
      val blocked = world.occludedToward(buffer, fx, fy, fz, dx, dy, dz, reach, query)
      // An unbounded shape's block (a plane's) leaves the item at −1: no guess.
      itemGuess(g) = if blocked then query.blockingItem else -1
      if blocked then 0.0
      else if !world.transmits then 1.0
      else clearShare(everyClear, everyClear.length, fx, fy, fz, dx, dy, dz, reach)

  /** [[pointToward]] with the last blocker's guess, for a light without a buffer. */
  private def guessed(
      k: Int,
      depth: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    val g = Shadows.Depths * k + (depth & (Shadows.Depths - 1))
    val b = guess(g)
    if b >= 0 && tree.blocks(b, guessNode(g), fx, fy, fz, dx, dy, dz, reach, query) then 0.0
    else
      query.blocker = -1
      val blocked = world.occludedAlong(fx, fy, fz, dx, dy, dz, reach, query)
      // An unbounded shape's block (a plane's) leaves blocker at −1: no guess.
      guess(g) = if blocked then query.blocker else -1
      guessNode(g) = query.blockerNode
      if blocked then 0.0 else 1.0

  /** [[point]] from (fx, fy, fz) in unit direction (dx, dy, dz). */
  def pointAlong(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    // Perf: the opaque cases here, the clear ones in methods of their own, so this one stays
    // small enough for the JIT to inline into its callers (showcase: 2.5% slower otherwise).
    if inBeam >= 0 then
      if opaqueBeam then
        if blockedAmong(beam, inBeam, fx, fy, fz, dx, dy, dz, reach) then 0.0 else 1.0
      else throughBeam(fx, fy, fz, dx, dy, dz, reach)
    else if !world.transmits then
      if world.occludedAlong(fx, fy, fz, dx, dy, dz, reach, query) then 0.0 else 1.0
    else throughWorld(fx, fy, fz, dx, dy, dz, reach)

  /** [[pointAlong]] in a beam that holds clear shapes. */
  private def throughBeam(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if !parted then walk(fx, fy, fz, dx, dy, dz, reach, inBeamOnly = true)
    else if blockedAmong(solid, solidCount, fx, fy, fz, dx, dy, dz, reach) then 0.0
    else clearShare(clear, clearCount, fx, fy, fz, dx, dy, dz, reach)

  /** [[pointAlong]] without a beam in a world that transmits. */
  private def throughWorld(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if !world.clearWalks then transmittanceByWalk(fx, fy, fz, dx, dy, dz, reach)
    else if world.opaqueAlong(fx, fy, fz, dx, dy, dz, reach, query) then 0.0
    else clearShare(everyClear, everyClear.length, fx, fy, fz, dx, dy, dz, reach)

  /** The share let through by the clear shapes `list(0 until count)` (places in
    * `world.clearShapes`) along the ray from f in unit direction d before `reach`, when no opaque
    * shape blocks it: the product of the `transmit` of the surfaces it crosses, walking from
    * crossing to crossing, each next one looked for beyond ε past the last (of equal distances,
    * the lower index's), as [[walk]] does.
    *
    * Perf: each shape's crossings along the whole ray are collected once and read in order, where
    * the walk tested every shape again after each surface: a glass tumbler four times more
    * (docs/performance.md, round 16).
    */
  private def clearShare(
      list: Array[Int],
      count: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if count == 1 then alone(list(0), fx, fy, fz, dx, dy, dz, reach)
    else among(list, count, fx, fy, fz, dx, dy, dz, reach)

  /** [[clearShare]] of one clear shape (its place in `world.clearShapes`): its crossings in
    * order, no search among shapes (Perf: the common case, a glass object in the beam).
    */
  private def alone(
      place: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    if !met(world.clearBoxes, 6 * place, fx, fy, fz, dx, dy, dz, reach) then 1.0
    else
      val shape = world.shape(world.clearShapes(place))
      val end   = Kernel.collect(shape, fx, fy, fz, dx, dy, dz, crossed, 0, false)
      // Why: the share so far, the distance up to which crossings are behind, the next one.
      var share  = 1.0
      var walked = 0.0
      var k      = 0
      while k < end && share > 0 && crossed.distanceAt(k) < reach do
        val t = crossed.distanceAt(k)
        if t > walked then
          share *= transmitAt(place, k)
          walked = t + Shading.Epsilon
        k += 1
      share

  /** The `transmit` of the surface that crossing `k` of the clear shape at `place` shows. */
  private inline def transmitAt(place: Int, k: Int): Double =
    val whole = world.clearTransmits(place)
    if !java.lang.Double.isNaN(whole) then whole
    else world.surface(world.clearShapes(place), crossed.leafAt(k)).transmit

  /** [[clearShare]] of several clear shapes: at each step the nearest next crossing of any. */
  private def among(
      list: Array[Int],
      count: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double =
    val shapes = world.clearShapes
    // Why: the crossings written so far, shape after shape.
    var end = 0
    var j   = 0
    while j < count do
      starts(j) = end
      if met(world.clearBoxes, 6 * list(j), fx, fy, fz, dx, dy, dz, reach) then
        end =
          Kernel.collect(world.shape(shapes(list(j))), fx, fy, fz, dx, dy, dz, crossed, end, false)
      ends(j) = end
      j += 1
    // Why: the share so far, and the distance up to which crossings are behind the walk.
    var share  = 1.0
    var walked = 0.0
    var more   = end > 0
    while more && share > 0 do
      var best  = -1
      var bestT = reach
      j = 0
      while j < count do
        // Each shape's crossings come in increasing t: skip those behind.
        var k = starts(j)
        while k < ends(j) && crossed.distanceAt(k) <= walked do k += 1
        starts(j) = k
        if k < ends(j) && crossed.distanceAt(k) < bestT then
          best = j
          bestT = crossed.distanceAt(k)
        j += 1
      if best < 0 then more = false
      else
        share *= transmitAt(list(best), starts(best))
        walked = bestT + Shading.Epsilon
    share

  /** The product of the `transmit` of every surface the ray from `from` in direction d crosses
    * before `reach`, walking from hit to hit; 0 as soon as an opaque one is found.
    */
  private[render] def transmittanceByWalk(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double
  ): Double = walk(fx, fy, fz, dx, dy, dz, reach, inBeamOnly = false)

  /** [[transmittanceByWalk]], each step's nearest hit from the world's tree or, `inBeamOnly`,
    * among the beam's shapes.
    */
  private inline def walk(
      fx: Double,
      fy: Double,
      fz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      reach: Double,
      inline inBeamOnly: Boolean
  ): Double =
    // Perf: the walk's state in local doubles, no Vec3 or Ray per step: the origin moves past
    // each surface crossed.
    var ox    = fx
    var oy    = fy
    var oz    = fz
    var left  = reach
    var share = 1.0
    while share > 0 && left > 0 do
      // Only hits before what is left of the way count (t ≤ left, then t < left below).
      val i =
        if inBeamOnly then nearestInBeam(ox, oy, oz, dx, dy, dz, left)
        else world.nearestAlong(ox, oy, oz, dx, dy, dz, left, query)
      val t = query.distance
      if i >= 0 && t < left then
        share *= world.surface(i, leafAt(i, ox, oy, oz, dx, dy, dz, t)).transmit
        // Step just past the surface, so the next query does not find it again.
        val step = t + Shading.Epsilon
        ox = ox + dx * step
        oy = oy + dy * step
        oz = oz + dz * step
        left -= step
      else left = 0
    share

  /** As `world.nearestAlong` among the beam's shapes: the lowest index hit at the smallest
    * t ≤ `limit` (−1 for none), its distance in `query.distance`.
    */
  private def nearestInBeam(
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double
  ): Int =
    // Perf: a plain loop over the few shapes, in index order so the first wins a tie.
    var best  = -1
    var bestT = limit
    var j     = 0
    while j < inBeam do
      val i = beam(j)
      if enters(i, ox, oy, oz, dx, dy, dz, bestT) then
        val t = Primitives.distance(world.each, i, bestT, ox, oy, oz, dx, dy, dz, query)
        if t < bestT || (t == bestT && t < Double.PositiveInfinity && best < 0) then
          bestT = t
          best = i
      j += 1
    query.distance = if best < 0 then Double.PositiveInfinity else bestT
    best

  /** As `world.occludedAlong` among the shapes `list(0 until count)`: some shape hit at
    * 0 < t < `limit`.
    */
  private def blockedAmong(
      list: Array[Int],
      count: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double
  ): Boolean =
    // Perf: as nearestInBeam, stopping at the first blocker.
    var j = 0
    while j < count && !(enters(list(j), ox, oy, oz, dx, dy, dz, limit) &&
        Primitives.blocks(world.each, list(j), limit, ox, oy, oz, dx, dy, dz, query))
    do j += 1
    j < count

  /** False when the ray cannot meet shape `i` at t ≤ `limit`: for a shape of the general route
    * or a mesh, its widened box missed (the slab test; NaN from an origin on a slab's plane
    * counts as inside); the fast shapes' own tests are as quick, so they are always tried.
    */
  private inline def enters(
      i: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double
  ): Boolean =
    val kind = world.each.kind(i)
    kind == Primitives.SphereKind || kind == Primitives.TriangleKind ||
    kind == Primitives.PlaneKind || met(world.boxes, 6 * i, ox, oy, oz, dx, dy, dz, limit)

  /** False when the ray misses the box of six doubles at `at` of `b` (lo then hi; NaN for no
    * bounds: always met) at 0 ≤ t ≤ `limit`: the slab test, NaN from an origin on a slab's plane
    * counting as inside.
    */
  private inline def met(
      b: Array[Double],
      at: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      limit: Double
  ): Boolean =
    if java.lang.Double.isNaN(b(at)) then true
    else
      val ix = 1 / dx
      val iy = 1 / dy
      val iz = 1 / dz
      val ax = (b(at) - ox) * ix
      val bx = (b(at + 3) - ox) * ix
      val ay = (b(at + 1) - oy) * iy
      val by = (b(at + 4) - oy) * iy
      val az = (b(at + 2) - oz) * iz
      val bz = (b(at + 5) - oz) * iz
      // Why: the ray's interval inside the box, narrowed axis by axis (NaN leaves it alone).
      var near = 0.0
      var far  = limit
      val nx   = Math.min(ax, bx)
      val fx   = Math.max(ax, bx)
      if nx > near then near = nx
      if fx < far then far = fx
      val ny = Math.min(ay, by)
      val fy = Math.max(ay, by)
      if ny > near then near = ny
      if fy < far then far = fy
      val nz = Math.min(az, bz)
      val fz = Math.max(az, bz)
      if nz > near then near = nz
      if fz < far then far = fz
      near <= far

  /** Aims the beam from (fx, fy, fz) at the sub-lights `positions` of `light`: keeps in
    * [[beam]] the shapes that a segment from the point to a sub-light may meet.
    */
  private def aim(
      fx: Double,
      fy: Double,
      fz: Double,
      positions: IArray[Double],
      light: AreaLight
  ): Unit =
    val nb = light.samplesB
    val c1 = (light.samplesA - 1) * nb
    axis(0, 1, 0, 0)
    axis(1, 0, 1, 0)
    axis(2, 0, 0, 1)
    // The sides through the point and two neighbouring corners of the grid (a zero axis when
    // the grid is a line or a point separates nothing).
    side(3, fx, fy, fz, positions, 0, c1)
    side(4, fx, fy, fz, positions, c1, c1 + nb - 1)
    side(5, fx, fy, fz, positions, c1 + nb - 1, nb - 1)
    side(6, fx, fy, fz, positions, nb - 1, 0)
    // Perf: the hull's extents and the shapes' tests in plain loops, once a shading point. The
    // sub-lights lie on a parallelogram's regular grid, so its four corners reach every extreme
    // (a linear function's over the grid, |x|'s too): 4 points, not all 16 of a 4 × 4 light (their
    // rounding, ~10⁻¹⁶ of the size, is far below the margin; docs/performance.md, round 16).
    corners(0) = 0; corners(1) = 3 * (nb - 1); corners(2) = 3 * c1; corners(3) = 3 * (c1 + nb - 1)
    var scale = Math.max(Math.abs(fx), Math.max(Math.abs(fy), Math.abs(fz)))
    var p     = 0
    while p < 4 do
      val q = corners(p)
      scale = Math.max(
        scale,
        Math.max(
          Math.abs(positions(q)),
          Math.max(Math.abs(positions(q + 1)), Math.abs(positions(q + 2)))
        )
      )
      p += 1
    var a = 0
    while a < 7 do
      val ax = axes(3 * a)
      val ay = axes(3 * a + 1)
      val az = axes(3 * a + 2)
      var lo = ax * fx + ay * fy + az * fz
      var hi = lo
      var c  = 0
      while c < 4 do
        val q = corners(c)
        val v = ax * positions(q) + ay * positions(q + 1) + az * positions(q + 2)
        if v < lo then lo = v
        if v > hi then hi = v
        c += 1
      low(a) = lo
      high(a) = hi
      a += 1
    var count  = 0
    var opaque = true
    // Why: the beam's opaque and clear shapes, and the place in world.clearShapes of the next.
    var solids = 0
    var clears = 0
    var place  = 0
    var i      = 0
    while i < world.size do
      val through = world.letsThrough(i)
      if mayMeet(i, fx, fy, fz, positions, scale) then
        beam(count) = i
        count += 1
        opaque = opaque && !through
        if parted then
          if through then
            clear(clears) = place
            clears += 1
          else
            solid(solids) = i
            solids += 1
      if through then place += 1
      i += 1
    inBeam = count
    opaqueBeam = opaque
    solidCount = solids
    clearCount = clears

  /** Axis `a` of the beam: (x, y, z). */
  private inline def axis(a: Int, x: Double, y: Double, z: Double): Unit =
    axes(3 * a) = x; axes(3 * a + 1) = y; axes(3 * a + 2) = z

  /** Axis `a`: the normal (p − f) × (q − f) of the side through f and sub-lights p and q. */
  private def side(
      a: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      positions: IArray[Double],
      p: Int,
      q: Int
  ): Unit =
    val ux = positions(3 * p) - fx
    val uy = positions(3 * p + 1) - fy
    val uz = positions(3 * p + 2) - fz
    val vx = positions(3 * q) - fx
    val vy = positions(3 * q + 1) - fy
    val vz = positions(3 * q + 2) - fz
    axis(a, uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)

  /** False when shape `i` lies wholly outside the beam: its box separated from the hull along
    * one of the axes by more than a margin (10⁻⁷ of the coordinates' size, far above their
    * rounding), or, a plane, with the point and every sub-light on one side of it by as much.
    */
  private def mayMeet(
      i: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      positions: IArray[Double],
      scale: Double
  ): Boolean =
    val b   = world.boxes
    val at  = 6 * i
    val lox = b(at)
    if java.lang.Double.isNaN(lox) then
      world.shape(i) match
        case plane: Plane =>
          val n = plane.normal
          val m = Shadows.Margin * (1 + scale + Math.abs(plane.distance))
          val s = n.x * fx + n.y * fy + n.z * fz - plane.distance
          // Perf: the grid's corners' sides (as every sub-light's, see aim), in a plain loop.
          var above = s > m
          var below = s < -m
          var c     = 0
          while c < 4 && (above || below) do
            val q = corners(c)
            val v = n.x * positions(q) + n.y * positions(q + 1) + n.z * positions(q + 2) -
              plane.distance
            above = above && v > m
            below = below && v < -m
            c += 1
          !(above || below)
        case _ => true
    else
      val cx   = (lox + b(at + 3)) * 0.5
      val cy   = (b(at + 1) + b(at + 4)) * 0.5
      val cz   = (b(at + 2) + b(at + 5)) * 0.5
      val hx   = (b(at + 3) - lox) * 0.5
      val hy   = (b(at + 4) - b(at + 1)) * 0.5
      val hz   = (b(at + 5) - b(at + 2)) * 0.5
      val size = 1 + scale + Math.abs(cx) + Math.abs(cy) + Math.abs(cz) + hx + hy + hz
      // Perf: the seven axes in a plain loop, stopping at the first that separates.
      var meets = true
      var a     = 0
      while meets && a < 7 do
        val ax = axes(3 * a)
        val ay = axes(3 * a + 1)
        val az = axes(3 * a + 2)
        val c  = ax * cx + ay * cy + az * cz
        val r  = Math.abs(ax) * hx + Math.abs(ay) * hy + Math.abs(az) * hz
        val m  = Shadows.Margin * (Math.abs(ax) + Math.abs(ay) + Math.abs(az)) * size
        meets = !(c + r < low(a) - m || c - r > high(a) + m)
        a += 1
      meets

  /** Which leaf of shape `i` the ray from (ox, oy, oz) along d meets at `t`: 0 unless the shape
    * shows a surface per leaf (a CSG combination), which takes the general path's full hit.
    */
  private def leafAt(
      i: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      dx: Double,
      dy: Double,
      dz: Double,
      t: Double
  ): Int =
    if !world.hasLeafSurfaces(i) then 0
    else Shape.hitAt(world.shape(i), Ray(Vec3(ox, oy, oz), Vec3(dx, dy, dz)), t).leaf

/** The margin of [[Shadows]]' beams, and which sub-lights lie behind a face. */
object Shadows:
  /** True when some sub-light at `positions` (x, y, z at 3k) lies behind the plane through
    * (fx, fy, fz) of normal n (n · (sub-light − f) < 0, as [[Shading.sideToward]] weighs it);
    * false for n = 0.
    */
  private[render] def anyBehind(
      positions: IArray[Double],
      fx: Double,
      fy: Double,
      fz: Double,
      nx: Double,
      ny: Double,
      nz: Double
  ): Boolean =
    // Perf: a plain loop over the few sub-lights, once a shading point and area light.
    var behind = false
    var k      = 0
    while !behind && k < positions.length do
      val tx = positions(k) - fx
      val ty = positions(k + 1) - fy
      val tz = positions(k + 2) - fz
      behind = Shading.sideToward(nx, ny, nz, tx, ty, tz) < 0
      k += 3
    behind

  /** A beam's margin, as a share of the size of the coordinates compared. */
  val Margin: Double = 1e-7

  /** The depths (mod this power of two) a point light's blocker guesses are kept apart for. */
  val Depths: Int = 4
