package tracer.render.path

import tracer.geometry.{Box, Cone, Mesh, Placed, Shape, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.World
import tracer.scene.{Light, Scene}

/** A light found by next-event estimation: where it is seen from a point, and what it gives.
  *
  * @param direction the unit direction from the point towards the light
  * @param distance  how far the light is along it (+∞ for the sky)
  * @param value     the radiance arriving, over the density of having drawn it (emitter choice
  *   included); for a point light, π·C·A(d) over the chance of choosing it, so that f·|cos θ|
  *   times this is the light's share of the estimate
  * @param density   the density per unit solid angle of having drawn this direction, emitter
  *   choice included, for multiple importance sampling; 0 for a point light (a delta)
  */
final case class LightSample(direction: Vec3, distance: Double, value: Colour, density: Double):
  /** True when the sample carries no light (a light behind its own face, a point inside a ball). */
  def dark: Boolean = value.max <= 0

/** The [[LightSample]] of no light at all. */
object LightSample:
  /** Nothing to light the point with. */
  val Dark: LightSample = LightSample(Vec3.UnitZ, 0, Colour.Black, 0)

/** One light that next-event estimation samples. */
enum Emitter:
  /** A point light, or an area light as its grid of sub-lights (version 4: each a point light of
    * colour C / (NA·NB) with the light's fade).
    */
  case Points(light: Light, positions: IArray[Vec3])

  /** A glowing sphere (shape `index` of the world), drawn by the solid angle it fills. */
  case Ball(index: Int, sphere: Sphere, emission: Colour)

  /** A glowing triangle or mesh (shape `index`), one emitter drawn uniformly by area over all
    * its faces, as Mitsuba draws a mesh emitter: a face by its share of the area (`shares`, the
    * faces' areas summed in order over their `area`), then a point on it. A triangle is the one
    * face of its own.
    */
  case Faces(
      index: Int,
      faces: IArray[Triangle],
      shares: IArray[Double],
      emission: Colour,
      area: Double
  )

  /** A glowing box (shape `index`), one emitter drawn uniformly by area over its six faces, each
    * as two triangles (`faces`, wound outwards; `shares` as a mesh's), as Mitsuba draws its
    * `cube`. Every point of its surface has the same density by area, 1 / `area`, so a hit's
    * density per unit solid angle needs only the hit's normal, not which triangle it is on.
    */
  case Cuboid(
      index: Int,
      faces: IArray[Triangle],
      shares: IArray[Double],
      emission: Colour,
      area: Double
  )

  /** A glowing cylinder or cone (shape `index`; `cone` in the world's space), one emitter drawn
    * uniformly by area over its side and, when closed, its two discs (their areas `parts`,
    * [[Emitters.frustumAreas]]; `area` all of it), as
    * [[Cuboid]]: a hit's density from its normal.
    */
  case Frustum(index: Int, cone: Cone, emission: Colour, parts: IArray[Double], area: Double)

  /** The background, radiance B from every direction no surface blocks, drawn uniformly over
    * the sphere of directions.
    */
  case Sky(radiance: Colour)

/** The part of a glowing shape that next-event estimation draws on, in the world's space. */
enum Glow:
  /** A sphere, drawn by the solid angle it fills. */
  case Round(sphere: Sphere)

  /** A triangle, or a mesh's faces: drawn by area, a hit's face named by its leaf. */
  case Flat(faces: IArray[Triangle])

  /** A box's faces as twelve outward triangles: drawn by area, a hit's density from its normal. */
  case Cuboid(faces: IArray[Triangle])

  /** A cylinder's or cone's side and discs: drawn by area, a hit's density from its normal. */
  case Conical(cone: Cone)

  /** This glow where `placement` takes its shape. */
  def placed(placement: tracer.math.Placement): Glow =
    val t = placement.transform
    this match
      case Round(s)   => Round(Sphere(t.point(s.centre), s.radius * placement.scale))
      case Flat(fs)   => Flat(fs.map(_.placed(placement)))
      case Cuboid(fs) => Cuboid(fs.map(_.placed(placement)))
      case Conical(c) =>
        val k = placement.scale
        Conical(Cone(t.point(c.base), c.baseRadius * k, t.point(c.cap), c.capRadius * k, c.open))

/** The emitters of a scene that next-event estimation samples: its point and area lights, its
  * glowing spheres, triangles, meshes, boxes, cylinders and cones (top-level shapes, placed or
  * not, not inside a combination; a mesh one emitter over all its faces, as Mitsuba's, a box over
  * its six, a cylinder or cone over its side and discs), and the sky when the background is not
  * black. Each is chosen with the same chance 1/count. Glowing planes, tori and combinations are
  * found by the paths alone.
  *
  * @param world `scene` compiled: its lights' sub-lights are the world's
  */
final class Emitters(scene: Scene, world: World):

  /** Every sampled emitter, lights first, then glowing shapes in document order, then the sky. */
  val all: IArray[Emitter] =
    // Each light's sub-lights as the world computed them once (a point light: its location).
    val lights = world.lights.indices.map(k =>
      Emitter.Points(world.lights(k), IArray.from(world.subLightPositions(k)))
    )
    val shapes = scene.objects.zipWithIndex.collect {
      case (o, i) if o.leafSurfaces.isEmpty && o.surface.emits =>
        Emitters.glow(o.shape) match
          case Some(Glow.Round(s)) => Vector(Emitter.Ball(i, s, o.surface.emission))
          case Some(Glow.Flat(fs)) =>
            val (shares, area) = Emitters.shares(fs)
            Vector(Emitter.Faces(i, fs, shares, o.surface.emission, area))
          case Some(Glow.Cuboid(fs)) =>
            val (shares, area) = Emitters.shares(fs)
            Vector(Emitter.Cuboid(i, fs, shares, o.surface.emission, area))
          case Some(Glow.Conical(c)) =>
            val parts = Emitters.frustumAreas(c)
            Vector(Emitter.Frustum(i, c, o.surface.emission, parts, parts.sum))
          case None => Vector.empty
    }.flatten
    val sky = Option.when(scene.background.max > 0)(Emitter.Sky(scene.background))
    IArray.from(lights ++ shapes ++ sky)

  private val count = all.length

  // Perf: the emitters and the points' positions in plain arrays: a generic IArray's element is
  // read through ScalaRunTime.array_apply, not inlined (6% of the benchmark room's samples).
  private val table: Array[Emitter]           = Array.from(all)
  private val positionsOf: Array[Array[Vec3]] = table.map {
    case Emitter.Points(_, positions) => Array.from(positions)
    case _                            => Array.empty[Vec3]
  }

  // The emitter of each world shape that has one (a mesh: of its first face), −1 for the others.
  private val ofShape: Array[Int] =
    val slots = Array.fill(scene.objects.size)(-1)
    all.indices.reverse.foreach(k =>
      all(k) match
        case Emitter.Ball(i, _, _)          => slots(i) = k
        case Emitter.Faces(i, _, _, _, _)   => slots(i) = k
        case Emitter.Cuboid(i, _, _, _, _)  => slots(i) = k
        case Emitter.Frustum(i, _, _, _, _) => slots(i) = k
        case _                              => ()
    )
    slots

  /** True when there is nothing to sample. */
  def isEmpty: Boolean = count == 0

  /** The chance-weighted density per unit solid angle with which [[sample]] from `from` draws
    * the sky's direction: 1 / (4π·count), or 0 when the sky is not sampled.
    */
  val skyDensity: Double =
    if all.exists { case _: Emitter.Sky => true; case _ => false } then 1 / (4 * Math.PI * count)
    else 0.0

  /** True when shape `i` of the world is a sampled emitter. */
  def samples(i: Int): Boolean = ofShape(i) >= 0

  /** The density per unit solid angle with which [[sample]] from `from` draws `point` on the
    * emitting front of shape `i` (choice included), 0 when it cannot; `leaf` is the hit's, which
    * on a mesh names the face, and `normal` the surface's there (only a box's, a cylinder's or a
    * cone's density asks it).
    */
  def density(i: Int, from: Vec3, point: Vec3, leaf: Int = 0, normal: Vec3 = Vec3.Zero): Double =
    densityAt(
      i,
      from.x,
      from.y,
      from.z,
      point.x,
      point.y,
      point.z,
      leaf,
      normal.x,
      normal.y,
      normal.z
    )

  /** [[density]] on coordinates: from (fx, fy, fz) to (px, py, pz), the normal (nx, ny, nz) at
    * the point, on either side.
    */
  def densityAt(
      i: Int,
      fx: Double,
      fy: Double,
      fz: Double,
      px: Double,
      py: Double,
      pz: Double,
      leaf: Int,
      nx: Double,
      ny: Double,
      nz: Double
  ): Double =
    if ofShape(i) < 0 then 0.0
    else
      // A sphere's and a triangle's hits are on leaf 0; a mesh's leaf names its face.
      table(ofShape(i)) match
        case Emitter.Ball(_, sphere, _)          => Emitters.coneDensity(sphere, fx, fy, fz) / count
        case Emitter.Faces(_, faces, _, _, area) =>
          val n = faces(leaf).normal
          areaDensity(n.x, n.y, n.z, area, fx, fy, fz, px, py, pz)
        case Emitter.Cuboid(_, _, _, _, area)  => byNormal(area, fx, fy, fz, px, py, pz, nx, ny, nz)
        case Emitter.Frustum(_, _, _, _, area) => byNormal(area, fx, fy, fz, px, py, pz, nx, ny, nz)
        case _                                 => 0.0

  /** [[areaDensity]] with the hit's normal (nx, ny, nz) turned towards (fx, fy, fz): |cos θ| (a
    * solid glows outwards, and a path reaches its outside only from outside).
    */
  private def byNormal(
      area: Double,
      fx: Double,
      fy: Double,
      fz: Double,
      px: Double,
      py: Double,
      pz: Double,
      nx: Double,
      ny: Double,
      nz: Double
  ): Double =
    val s = if (px - fx) * nx + (py - fy) * ny + (pz - fz) * nz > 0 then -1.0 else 1.0
    areaDensity(nx * s, ny * s, nz * s, area, fx, fy, fz, px, py, pz)

  /** The density per unit solid angle, choice included, of drawing the point (px, py, pz) of a
    * surface of normal (nx, ny, nz) from (fx, fy, fz), on its front, points drawn uniformly over
    * an emitter of `area`.
    */
  private def areaDensity(
      nx: Double,
      ny: Double,
      nz: Double,
      area: Double,
      fx: Double,
      fy: Double,
      fz: Double,
      px: Double,
      py: Double,
      pz: Double
  ): Double =
    val wx = px - fx
    val wy = py - fy
    val wz = pz - fz
    val d2 = wx * wx + wy * wy + wz * wz
    val c  = -(wx * nx + wy * ny + wz * nz) / Math.sqrt(d2)
    if c <= 0 then 0.0 else d2 / (area * c) / count

  /** A light for the point `p`, chosen by `choice` among the emitters, with a point on it (or a
    * direction) from (u1, u2), each uniform in [0, 1).
    */
  def sample(p: Vec3, choice: Double, u1: Double, u2: Double): LightSample =
    val out = Scratch()
    sampleInto(out, p.x, p.y, p.z, choice, u1, u2, p.x, p.y, p.z)
    LightSample(
      Vec3(out.lx, out.ly, out.lz),
      out.distance,
      Colour(out.lr, out.lg, out.lb),
      out.lightDensity
    )

  /** [[sample]] for the point (px, py, pz), into `out`'s light fields: what path mode's loop
    * calls, allocating nothing for points, faces and the sky (PathBench). The point lit is
    * (qx, qy, qz): a fading light's A(d) takes d from it (scene-format.md, Fading lights), while
    * the direction and distance are (px, py, pz)'s, the shadow ray's start S0 just off it.
    */
  def sampleInto(
      out: Scratch,
      px: Double,
      py: Double,
      pz: Double,
      choice: Double,
      u1: Double,
      u2: Double,
      qx: Double,
      qy: Double,
      qz: Double
  ): Unit =
    val scaled = choice * count
    val k      = Math.min(count - 1, scaled.toInt)
    val rest   = scaled - k
    table(k) match
      case Emitter.Points(light, _) =>
        val positions = positionsOf(k)
        val m         = positions.length
        val at        = positions(Math.min(m - 1, (rest * m).toInt))
        val tx        = at.x - px
        val ty        = at.y - py
        val tz        = at.z - pz
        val d         = Math.sqrt(tx * tx + ty * ty + tz * tz)
        if d <= 0 then out.dark()
        else
          // Sub-light C/m, chosen with chance 1/m among the grid (MitsubaSuite, lambert).
          val scale = Math.PI * Emitters.faded(light, at, qx, qy, qz) * count
          val c     = light.colour
          out.light(tx / d, ty / d, tz / d, d, c.r * scale, c.g * scale, c.b * scale, 0)
      case Emitter.Ball(_, sphere, emission) =>
        val l = Emitters.ball(sphere, emission, Vec3(px, py, pz), u1, u2, count)
        val d = l.direction
        out.light(d.x, d.y, d.z, l.distance, l.value.r, l.value.g, l.value.b, l.density)
      case Emitter.Faces(_, faces, shares, emission, area) =>
        // The face by its share of the area, from what is left of the choice (uniform in [0, 1)).
        val f = Emitters.pick(shares, rest)
        pointOn(out, faces(f), emission, area, px, py, pz, u1, u2)
      case Emitter.Cuboid(_, faces, shares, emission, area) =>
        // As a mesh: the box's six faces are twelve triangles of one emitter.
        val f = Emitters.pick(shares, rest)
        pointOn(out, faces(f), emission, area, px, py, pz, u1, u2)
      case Emitter.Frustum(_, cone, emission, parts, area) =>
        Emitters.onFrustum(cone, parts, rest, u1, u2) { (x, y, z, nx, ny, nz) =>
          seen(out, x, y, z, nx, ny, nz, emission, area, px, py, pz)
        }
      case Emitter.Sky(radiance) =>
        val z   = 1 - 2 * u1
        val r   = Math.sqrt(Math.max(0.0, 1 - z * z))
        val pdf = 1 / (4 * Math.PI * count)
        out.light(
          r * Turn.cos(u2), // φ = 2π·u2
          r * Turn.sin(u2),
          z,
          Double.PositiveInfinity,
          radiance.r / pdf,
          radiance.g / pdf,
          radiance.b / pdf,
          pdf
        )

  /** A point drawn uniformly on triangle `t` (√u₁ and u₂ barycentrically) of an emitter of
    * `area` glowing `emission`, seen from (px, py, pz), into `out` (dark where its front does
    * not face the point).
    */
  private def pointOn(
      out: Scratch,
      t: Triangle,
      emission: Colour,
      area: Double,
      px: Double,
      py: Double,
      pz: Double,
      u1: Double,
      u2: Double
  ): Unit =
    val su = Math.sqrt(u1)
    val a  = 1 - su
    val b  = su * (1 - u2)
    val c  = su * u2
    val n  = t.normal
    seen(
      out,
      t.t0.x * a + t.t1.x * b + t.t2.x * c,
      t.t0.y * a + t.t1.y * b + t.t2.y * c,
      t.t0.z * a + t.t1.z * b + t.t2.z * c,
      n.x,
      n.y,
      n.z,
      emission,
      area,
      px,
      py,
      pz
    )

  /** The light from the point (qx, qy, qz) of outward normal (nx, ny, nz), drawn uniformly by
    * area over an emitter of `area` glowing `emission`, seen from (px, py, pz), into `out` (dark
    * where its front does not face the point).
    */
  private def seen(
      out: Scratch,
      qx: Double,
      qy: Double,
      qz: Double,
      nx: Double,
      ny: Double,
      nz: Double,
      emission: Colour,
      area: Double,
      px: Double,
      py: Double,
      pz: Double
  ): Unit =
    val wx = qx - px
    val wy = qy - py
    val wz = qz - pz
    val d2 = wx * wx + wy * wy + wz * wz
    val d  = Math.sqrt(d2)
    if d <= 0 then out.dark()
    else
      val dx     = wx / d
      val dy     = wy / d
      val dz     = wz / d
      val facing = -(dx * nx + dy * ny + dz * nz)
      if facing <= 0 then out.dark()
      else
        val pdf = d2 / (area * facing) / count
        out.light(dx, dy, dz, d, emission.r / pdf, emission.g / pdf, emission.b / pdf, pdf)

/** Sampling spheres by solid angle, and a light's fade. */
object Emitters:
  /** The area of triangle `t`. */
  def areaOf(t: Triangle): Double = t.a.cross(t.b).length / 2

  /** The running shares of `faces`' areas, in order, over their total (the last is 1: what
    * [[pick]] searches), and that total.
    */
  def shares(faces: IArray[Triangle]): (IArray[Double], Double) =
    val areas = faces.map(areaOf)
    val total = areas.sum
    (IArray.from(areas.scanLeft(0.0)(_ + _).tail.map(_ / total)), total)

  /** What next-event estimation can draw on `shape`, in the world's space: a sphere, a triangle
    * or a mesh's faces, a box's faces, or a cylinder or cone, each taken through the placements
    * around it (a placement is a similarity: a sphere stays a sphere, a cone a cone, a face keeps
    * its winding); None for a shape of another kind (a plane, a torus, a combination).
    */
  def glow(shape: Shape): Option[Glow] =
    shape match
      case s: Sphere                => Some(Glow.Round(s))
      case t: Triangle              => Some(Glow.Flat(IArray(t)))
      case m: Mesh                  => Some(Glow.Flat(IArray.from(m.faces)))
      case b: Box                   => Some(Glow.Cuboid(boxFaces(b)))
      case c: Cone                  => Some(Glow.Conical(c))
      case Placed(inner, placement) => glow(inner).map(_.placed(placement))
      case _                        => None

  /** The areas of `cone`'s side, base disc and cap disc (the discs 0 when it is open). */
  def frustumAreas(cone: Cone): IArray[Double] =
    val (r0, r1) = (cone.baseRadius, cone.capRadius)
    val side     = Math.PI * (r0 + r1) * Math.hypot(cone.height, r1 - r0)
    if cone.open then IArray(side, 0.0, 0.0) else IArray(side, Math.PI * r0 * r0, Math.PI * r1 * r1)

  /** Runs `body` on a point drawn uniformly by area on `cone` (its side, and its discs when it is
    * closed; their areas `areas`, [[frustumAreas]]), with its outward unit normal: the part by its
    * share of the area from `u`, then on
    * the side the height s ∈ [0, 1] from `u1` with density ∝ the radius there and the angle from
    * `u2`, on a disc the radius √u₁ and the angle u₂ (each uniform in [0, 1)).
    */
  inline def onFrustum(cone: Cone, areas: IArray[Double], u: Double, u1: Double, u2: Double)(
      inline body: (Double, Double, Double, Double, Double, Double) => Unit
  ): Unit =
    val total    = areas(0) + areas(1) + areas(2)
    val (r0, r1) = (cone.baseRadius, cone.capRadius)
    val axis     = cone.axis
    val (e1, e2) = Bsdf.tangents(axis)
    val c        = Turn.cos(u2)
    val sn       = Turn.sin(u2)
    val radial   = e1 * c + e2 * sn
    if u * total < areas(0) || areas(1) + areas(2) <= 0 then
      // F(s) = (r0·s + (r1 − r0)·s²/2) / ((r0 + r1)/2) = u1, solved without cancellation.
      val s = u1 * (r0 + r1) / (r0 + Math.sqrt(r0 * r0 + u1 * (r1 * r1 - r0 * r0)))
      val r = r0 + (r1 - r0) * s
      val p = cone.base + axis * (s * cone.height) + radial * r
      val n = (radial - axis * cone.slope).normalisedOr(radial)
      body(p.x, p.y, p.z, n.x, n.y, n.z)
    else
      val onBase = u * total < areas(0) + areas(1)
      val centre = if onBase then cone.base else cone.cap
      val n      = if onBase then -axis else axis
      val p      = centre + radial * ((if onBase then r0 else r1) * Math.sqrt(u1))
      body(p.x, p.y, p.z, n.x, n.y, n.z)

  /** The six faces of box `b` as twelve triangles, each wound so that its normal points out. */
  def boxFaces(b: Box): IArray[Triangle] =
    val lo             = b.extent.lo
    val hi             = b.extent.hi
    val centre         = (lo + hi) / 2
    def corner(i: Int) =
      Vec3(
        if (i & 1) == 0 then lo.x else hi.x,
        if (i & 2) == 0 then lo.y else hi.y,
        if (i & 4) == 0 then lo.z else hi.z
      )
    // Each face as its four corners in order around it (the bits of the corner's number: x, y, z).
    val quads =
      List((0, 2, 6, 4), (1, 3, 7, 5), (0, 1, 5, 4), (2, 3, 7, 6), (0, 1, 3, 2), (4, 5, 7, 6))
    IArray.from(quads.flatMap { (a, b, c, d) =>
      List(
        outward(corner(a), corner(b), corner(c), centre),
        outward(corner(a), corner(c), corner(d), centre)
      )
    })

  /** The triangle (p, q, r), or (p, r, q), whichever has its normal pointing away from `inside`. */
  private def outward(p: Vec3, q: Vec3, r: Vec3, inside: Vec3): Triangle =
    val t = Triangle(p, q, r)
    if t.normal.dot((p + q + r) / 3 - inside) > 0 then t else Triangle(p, r, q)

  /** The first k whose running share `shares(k)` exceeds `u` (the last when rounding leaves none):
    * index k drawn with chance shares(k) − shares(k − 1) for u uniform in [0, 1).
    */
  def pick(shares: IArray[Double], u: Double): Int =
    // Why: a binary search over the running shares.
    var lo = 0
    var hi = shares.length - 1
    while lo < hi do
      val mid = (lo + hi) >>> 1
      if shares(mid) > u then hi = mid else lo = mid + 1
    lo

  /** A(d) of `light` for the point (qx, qy, qz) it lights from `at` (a point light's location or
    * one of an area light's sub-lights): d = |at − q|, measured from the point itself, not from
    * the shadow ray's start just off it; 1 without fade.
    */
  def faded(light: Light, at: Vec3, qx: Double, qy: Double, qz: Double): Double =
    if light.fade.isEmpty then 1.0
    else
      val x = at.x - qx
      val y = at.y - qy
      val z = at.z - qz
      light.attenuation(Math.sqrt(x * x + y * y + z * z))

  /** The density per unit solid angle of a direction drawn uniformly from the cone of directions
    * in which `sphere` is seen from `from`: 1 / (2π(1 − cos θmax)); 0 from inside.
    */
  def coneDensity(sphere: Sphere, from: Vec3): Double = coneDensity(sphere, from.x, from.y, from.z)

  /** [[coneDensity]] from (fx, fy, fz). */
  def coneDensity(sphere: Sphere, fx: Double, fy: Double, fz: Double): Double =
    val cx = sphere.centre.x - fx
    val cy = sphere.centre.y - fy
    val cz = sphere.centre.z - fz
    val d2 = cx * cx + cy * cy + cz * cz
    if d2 <= sphere.radiusSquared then 0.0
    else 1 / (2 * Math.PI * capFraction(sphere.radiusSquared / d2))

  /** 1 − cos θmax for sin²θmax = `sin2`, without cancellation for small spheres. */
  private def capFraction(sin2: Double): Double = sin2 / (1 + Math.sqrt(Math.max(0.0, 1 - sin2)))

  /** A direction towards `sphere` drawn uniformly from its cone seen from `p`, and the light
    * from the point it meets (a sphere seen from outside shows only its emitting front).
    */
  private[path] def ball(
      sphere: Sphere,
      emission: Colour,
      p: Vec3,
      u1: Double,
      u2: Double,
      count: Int
  ): LightSample =
    val wc = sphere.centre - p
    val d2 = wc.lengthSquared
    if d2 <= sphere.radiusSquared then LightSample.Dark
    else
      val dc        = Math.sqrt(d2)
      val cap       = capFraction(sphere.radiusSquared / d2)
      val cos       = 1 - u1 * cap
      val sin       = Math.sqrt(Math.max(0.0, 1 - cos * cos))
      val axis      = wc / dc
      val (s, t)    = Bsdf.tangents(axis)
      val direction =
        (s * (sin * Turn.cos(u2)) + t * (sin * Turn.sin(u2)) + axis * cos)
          .normalisedOr(axis)
      val tca  = direction.dot(wc)
      val half = Math.sqrt(Math.max(0.0, sphere.radiusSquared - (d2 - tca * tca)))
      val pdf  = 1 / (2 * Math.PI * cap) / count
      LightSample(direction, tca - half, emission / pdf, pdf)
