package tracer.demo

import tracer.geometry.*
import tracer.image.Colour
import tracer.math.{Placement, Vec3}
import tracer.scene.*

/** A Python value of a Mitsuba twin, written as a literal by [[Mitsuba]]. */
private enum Py:
  case Num(value: Double)
  case Whole(value: Int)
  case Str(value: String)
  case Code(text: String)
  case List(values: Vector[Py])
  case Dict(entries: Vector[(String, Py)])
  case Call(function: String, arguments: Vector[Py])

import Py.*

/** Writes a scene's Mitsuba 3 twin (docs/mitsuba.md): a Python program that renders with
  * Mitsuba 3 the picture path mode must converge to, and writes it as a `.pfm` file. The camera
  * is Mitsuba's `perspective` mirrored (our world is left-handed), point and area lights are a
  * small Python emitter that lights as ours do (π·C·A(d)·cos θ), glowing surfaces are `area`
  * emitters, the background a `constant` one, and each surface the mixture of version 4's lobes —
  * Lambert, mirror, two GGX lobes, glass — in a Python BSDF that chooses lobes by weight, under a
  * `mask` where the surface is clear. Run it with `scripts/mitsuba.sh TWIN.py OUT.pfm`.
  *
  * Cones, tori, CSG, textures and checkers have no twin: [[write]] says so instead.
  */
object Mitsuba:

  /** What the twin renders: a picture of `width` × `height` pixels, `samples` a pixel, at most
    * `depth` bounces after the camera ray (our `-r`).
    */
  final case class Settings(width: Int, height: Int, samples: Int, depth: Int)

  /** The Python program of `scene`'s twin, or why the scene has none. */
  def write(scene: Scene, settings: Settings): Either[String, String] =
    for
      _       <- aspect(scene.camera, settings)
      objects <- traverse(scene.objects.zipWithIndex) { case (o, i) => twins(o, i) }
    yield
      val parts  = objects.flatten
      val meshes = parts
        .collect { case f: Facet => f }
        .groupBy(f => (f.surface, f.normals.isDefined))
        .toVector
        .sortBy { case (_, facets) => facets.map(_.order).min }
        .zipWithIndex
        .map { case (((surface, _), facets), i) =>
          s"mesh_$i" -> mesh(s"mesh_$i", facets.sortBy(_.order), surface)
        }
      val solids = parts.collect { case s: Solid => s }.zipWithIndex.map { case (s, i) =>
        s"shape_$i" -> solid(s)
      }
      val entries =
        Vector(
          "type"       -> Str("scene"),
          "integrator" -> integrator(scene, settings.depth),
          "sensor"     -> sensor(scene.camera, settings)
        ) ++ sky(scene.background) ++ lights(scene.lights) ++ solids ++ meshes
      preamble + "\nrender(" + render(Dict(entries), 0) + ")\n"

  /** The twin's Python code before the scene: the emitter, the BSDF and the helpers. */
  private lazy val preamble: String =
    val stream = getClass.getResourceAsStream("/tracer/demo/mitsuba-twin.py")
    try String(stream.readAllBytes, "UTF-8")
    finally stream.close()

  private def render(p: Py, indent: Int): String =
    val inner = "  " * (indent + 1)
    p match
      // The shortest decimal that reads back as d, which Python reads as the same double.
      case Num(d)   => d.toString
      case Code(t)  => t
      case Whole(i) => i.toString
      case Str(s)   => "\"" + s + "\""
      case List(vs) => vs.map(render(_, indent + 1)).mkString("[", ", ", "]")
      case Dict(es) =>
        es.map { case (k, v) => s"$inner\"$k\": ${render(v, indent + 1)}" }
          .mkString("{\n", ",\n", "\n" + "  " * indent + "}")
      case Call(f, as) => as.map(render(_, indent + 1)).mkString(s"$f(", ", ", ")")

  private def vec(v: Vec3): Py   = List(Vector(Num(v.x), Num(v.y), Num(v.z)))
  private def rgb(c: Colour): Py = Call("rgb", Vector(Num(c.r), Num(c.g), Num(c.b)))

  /** A lobe's weight as the twin's `reflectance`, which may exceed 1 (Mitsuba refuses a plain
    * `rgb` above 1 where a reflectance goes).
    */
  private def reflectance(c: Colour): Py =
    Call("reflectance", Vector(Num(c.r), Num(c.g), Num(c.b)))
  private def typed(name: String, entries: (String, Py)*): Py =
    Dict(("type" -> Str(name)) +: entries.toVector)

  /** The film's pixels must have our image plane's shape: Mitsuba's pixels are square. */
  private def aspect(c: Camera, s: Settings): Either[String, Unit] =
    val ours   = c.width / c.height
    val theirs = s.width.toDouble / s.height
    Either.cond(
      Math.abs(ours / theirs - 1) < 1e-9,
      (),
      f"no Mitsuba twin: the image plane's W/H = $ours%.6g differs from the picture's X/Y = $theirs%.6g (Mitsuba's pixels are square)"
    )

  /** Version 4's depth: Mitsuba's `max_depth` counts the camera ray; `volpath` where a clear
    * surface (transmit without ior) is crossed, as `path` does not pass them for free.
    */
  private def integrator(scene: Scene, depth: Int): Py =
    val clear = scene.objects.exists(_.surfaces.exists(s => s.transmit > 0 && s.ior == 1))
    typed(
      if clear then "volpath" else "path",
      "max_depth" -> Whole(depth + 1),
      "rr_depth"  -> Whole(if clear then 4 else 5)
    )

  private def sensor(c: Camera, s: Settings): Py =
    val fov = Math.toDegrees(2 * Math.atan(c.width / (2 * c.zoom)))
    typed(
      "perspective",
      "fov_axis"  -> Str("x"),
      "fov"       -> Num(fov),
      "near_clip" -> Num(1e-6),
      "far_clip"  -> Num(1e9),
      "to_world"  -> Call("look_at", Vector(vec(c.location), vec(c.lookAt), vec(c.up))),
      "film"      -> typed(
        "hdrfilm",
        "width"            -> Whole(s.width),
        "height"           -> Whole(s.height),
        "rfilter"          -> typed("box"),
        "component_format" -> Str("float32"),
        "pixel_format"     -> Str("rgb")
      ),
      "sampler" -> typed("independent", "sample_count" -> Whole(s.samples))
    )

  private def sky(b: Colour): Vector[(String, Py)] =
    if b.max > 0 then Vector("sky" -> typed("constant", "radiance" -> rgb(b))) else Vector.empty

  /** Every point light, and every sub-light of an area light with C/(NA·NB), as the Python
    * emitter that lights as ours do.
    */
  private def lights(ls: Seq[Light]): Vector[(String, Py)] =
    val points = ls.toVector.flatMap { l =>
      l.area match
        case None    => Vector((l.location, l.colour, l.fade))
        case Some(a) =>
          val share = l.colour / (a.samplesA * a.samplesB).toDouble
          for i <- (0 until a.samplesA).toVector; j <- 0 until a.samplesB
          yield (l.location + a.offset(i, j), share, l.fade)
    }
    points.zipWithIndex.map { case ((p, c, fade), i) =>
      val faded = fade.toVector.flatMap(f =>
        Vector("fade_distance" -> Num(f.distance), "fade_power" -> Num(f.power))
      )
      s"light_$i" -> Dict(
        Vector(
          "type"     -> Str("tracer_light"),
          "position" -> vec(p),
          "colour"   -> Call("mi.ScalarColor3f", Vector(Num(c.r), Num(c.g), Num(c.b)))
        ) ++ faded
      )
    }

  // The shapes of the twin: triangles (which go into meshes by surface) and Mitsuba's own shapes.
  private sealed trait Part
  private final case class Facet(
      corners: (Vec3, Vec3, Vec3),
      normals: Option[(Vec3, Vec3, Vec3)],
      surface: Surface,
      order: Int
  ) extends Part
  private final case class Solid(kind: String, fields: Vector[(String, Py)], surface: Surface)
      extends Part

  /** An affine map of points, as the chain of placements above a shape makes it. */
  private final case class Affine(map: Vec3 => Vec3, scale: Double):
    def apply(p: Vec3): Vec3 = map(p)

    /** A direction carried by the map, normalised (the maps are similarities: normals too). */
    def direction(d: Vec3): Vec3 = (map(d) - map(Vec3.Zero)).normalisedOr(d)

    def after(p: Placement): Affine =
      Affine(q => map(p.transform.point(q)), scale * p.scale)

  private val Identity = Affine(identity, 1)

  /** The half-size of a plane's twin on each side of the plane's point nearest the origin: far
    * beyond any scene's lights and camera, so that no ray of a scene meets its edge.
    */
  private val PlaneReach = 1e5

  private def twins(o: SceneObject, index: Int): Either[String, Vector[Part]] =
    for
      _     <- look(o.surface)
      parts <- twin(o.shape, Identity, o.surface, index)
    yield parts

  private def twin(
      s: Shape,
      f: Affine,
      surface: Surface,
      order: Int
  ): Either[String, Vector[Part]] = s match
    case sp: Sphere =>
      Right(
        Vector(
          Solid(
            "sphere",
            Vector("center" -> vec(f(sp.centre)), "radius" -> Num(sp.radius * f.scale)),
            surface
          )
        )
      )
    case tr: Triangle =>
      val normals =
        tr.cornerNormals.map((a, b, c) => (f.direction(a), f.direction(b), f.direction(c)))
      Right(Vector(Facet((f(tr.t0), f(tr.t1), f(tr.t2)), normals, surface, order)))
    case m: Mesh =>
      traverse(m.faces.toVector)(twin(_, f, surface, order)).map(_.flatten.toVector)
    case p: Plane =>
      Right(planeFacets(f(p.normal * p.distance), f.direction(p.normal), surface, order))
    case b: Box =>
      val centre = (b.corner1 + b.corner2) * 0.5
      val half   = Vec3(
        Math.abs(b.corner2.x - b.corner1.x) / 2,
        Math.abs(b.corner2.y - b.corner1.y) / 2,
        Math.abs(b.corner2.z - b.corner1.z) / 2
      )
      val origin  = f(centre)
      val columns = Vector(Vec3(half.x, 0, 0), Vec3(0, half.y, 0), Vec3(0, 0, half.z))
        .map(axis => f(centre + axis) - origin)
      Right(Vector(Solid("cube", Vector("to_world" -> matrix(columns, origin)), surface)))
    case c: Cone if c.baseRadius == c.capRadius =>
      val (base, cap, r) = (f(c.base), f(c.cap), c.baseRadius * f.scale)
      val side           = Solid(
        "cylinder",
        Vector("p0" -> vec(base), "p1" -> vec(cap), "radius" -> Num(r)),
        surface
      )
      val axis = (cap - base).normalisedOr(Vec3.UnitY)
      val caps =
        if c.open then Vector.empty
        else Vector(disk(base, -axis, r, surface), disk(cap, axis, r, surface))
      Right(side +: caps)
    case _: Cone   => Left("no Mitsuba twin for a cone (only for a cylinder, equal radii)")
    case _: Torus  => Left("no Mitsuba twin for a torus")
    case _: Csg    => Left("no Mitsuba twin for CSG")
    case p: Placed => twin(p.shape, f.after(p.placement), surface, order)

  /** A disk of radius `r` at `centre` facing `normal` (Mitsuba's disk: the unit disk in z = 0). */
  private def disk(centre: Vec3, normal: Vec3, r: Double, surface: Surface): Solid =
    val (u, v) = basis(normal)
    Solid("disk", Vector("to_world" -> matrix(Vector(u * r, v * r, normal), centre)), surface)

  /** Two unit vectors at right angles to unit `n` and to each other, with u × v = n. */
  private def basis(n: Vec3): (Vec3, Vec3) =
    val helper = if Math.abs(n.x) < 0.9 then Vec3.UnitX else Vec3.UnitY
    val u      = helper.cross(n).normalisedOr(Vec3.UnitZ)
    (u, n.cross(u))

  /** A plane as triangles reaching [[PlaneReach]] on each side of `point`, their corners ordered
    * so that Mitsuba's face normal is the plane's: a square of half-size [[PlaneCore]] about
    * `point`, then square rings each [[PlaneGrowth]] times wider, each ring four trapezoids of
    * two triangles sharing its inner square's corners (no cracks). Mitsuba's hit points lie off a
    * triangle by about 10⁻⁷ of its size (single precision): near the scene the triangles are
    * small, so the hit points are as close as on a finite floor; two triangles of 10⁵ units put
    * them 5·10⁻³ off, and shadowed a tilted plane in stripes (docs/mitsuba.md).
    */
  private def planeFacets(point: Vec3, normal: Vec3, surface: Surface, order: Int) =
    val (u, v)                   = basis(normal)
    def at(a: Double, b: Double) = point + u * a + v * b
    def square(h: Double)        = Vector(at(-h, -h), at(h, -h), at(h, h), at(-h, h))
    val core                     = square(PlaneCore)
    val sizes                    =
      Iterator.iterate(PlaneCore)(_ * PlaneGrowth).takeWhile(_ < PlaneReach).toVector :+ PlaneReach
    val rings = sizes.zip(sizes.tail).flatMap { (inner, outer) =>
      val (a, b) = (square(inner), square(outer))
      (0 until 4).flatMap { k =>
        val next = (k + 1) % 4
        Vector((a(k), b(k), b(next)), (a(k), b(next), a(next)))
      }
    }
    ((core(0), core(1), core(2)) +: (core(0), core(2), core(3)) +: rings)
      .map(corners => Facet(corners, None, surface, order))

  /** The half-size of the innermost square of a plane's twin, in scene units. */
  private val PlaneCore = 2.0

  /** How much wider each ring of a plane's twin is than the one inside it. */
  private val PlaneGrowth = 4.0

  /** A 4×4 matrix with the three given columns and translation. */
  private def matrix(columns: Vector[Vec3], translation: Vec3): Py =
    def row(k: Vec3 => Double, t: Double) =
      List(columns.map(c => Num(k(c))) :+ Num(t))
    Call(
      "matrix",
      Vector(
        List(
          Vector(
            row(_.x, translation.x),
            row(_.y, translation.y),
            row(_.z, translation.z),
            List(Vector(Num(0), Num(0), Num(0), Num(1)))
          )
        )
      )
    )

  private def solid(s: Solid): Py =
    Dict((("type" -> Str(s.kind)) +: s.fields) ++ material(s.surface))

  /** The mesh of `facets` (all with `surface`), each triangle's corners in our order. */
  private def mesh(name: String, facets: Vector[Facet], surface: Surface): Py =
    val corners = facets.flatMap(f => Vector(f.corners._1, f.corners._2, f.corners._3))
    val normals = facets.flatMap(_.normals.toVector.flatMap((a, b, c) => Vector(a, b, c)))
    def flat(vs: Vector[Vec3]) = List(vs.flatMap(v => Vector(Num(v.x), Num(v.y), Num(v.z))))
    val emitter = if surface.emits then Vector(area(surface.emission)) else Vector(Code("None"))
    Call(
      "mesh",
      Vector(
        Str(name),
        flat(corners),
        if normals.isEmpty then Code("None") else flat(normals),
        bsdf(surface)
      ) ++ emitter
    )

  private def area(e: Colour): Py = typed("area", "radiance" -> rgb(e))

  private def material(s: Surface): Vector[(String, Py)] =
    ("bsdf" -> bsdf(s)) +: (if s.emits then Vector("emitter" -> area(s.emission)) else Vector())

  /** Whether a surface has a twin: plain colours only. */
  private def look(s: Surface): Either[String, Unit] = s.pigment match
    case Pigment.Solid(_)    => clearTwin(s)
    case Pigment.Textured(_) => Left("no Mitsuba twin for a texture")
    case _: Pigment.Checker  => Left("no Mitsuba twin for a checker")

  private def clearTwin(s: Surface): Either[String, Unit] =
    Either.cond(
      !(s.transmit == 1 && s.ior == 1 && (s.reflection > 0 || s.highlighted)),
      (),
      "no Mitsuba twin for a fully clear surface (transmit 1 without ior) with a mirror or highlight"
    )

  /** One lobe of the mixture: its weight in choosing lobes and its BSDF. */
  private final case class Lobe(weight: Double, bsdf: Py)

  /** The surface's scattering function f = (1 − t)·kd·C/π + kr·mirror + P·ggx(α_P) + K·ggx(α_K)
    * + t·pass(η) (docs/mitsuba.md): each lobe carrying its own weight, one-sided lobes made
    * two-sided, several lobes mixed by the Python BSDF; a clear surface (t > 0, η = 1) is a
    * `mask` of opacity 1 − t over the rest with their weights divided by 1 − t.
    */
  private def bsdf(s: Surface): Py =
    val colour = s.pigment match
      case Pigment.Solid(c) => c
      case _                => Colour.grey(0.5) // refused before: write checks `look` first
    val clear                              = s.transmit > 0 && s.ior == 1
    val scale                              = if clear then 1 / (1 - s.transmit) else 1.0
    def sided(b: Py)                       = typed("twosided", "bsdf" -> b)
    def ggx(weight: Double, alpha: Double) = Lobe(
      weight * scale,
      sided(
        typed(
          "roughconductor",
          "distribution"         -> Str("ggx"),
          "alpha"                -> Num(alpha),
          "material"             -> Str("none"),
          "specular_reflectance" -> reflectance(Colour.grey(weight * scale))
        )
      )
    )
    val diffuse = colour * ((1 - s.transmit) * s.diffuse * scale)
    val lobes   = Vector(
      Option.when(diffuse.max > 0)(
        Lobe(
          (diffuse.r + diffuse.g + diffuse.b) / 3,
          sided(typed("diffuse", "reflectance" -> reflectance(diffuse)))
        )
      ),
      Option.when(s.reflection > 0)(
        Lobe(
          s.reflection * scale,
          sided(
            typed(
              "conductor",
              "material"             -> Str("none"),
              "specular_reflectance" -> reflectance(Colour.grey(s.reflection * scale))
            )
          )
        )
      ),
      Option.when(s.phong > 0)(ggx(s.phong, Math.sqrt(2 / (4 * s.phongSize + 2)))),
      Option.when(s.specular > 0)(ggx(s.specular, Math.sqrt(2 / (1 / s.roughness + 2)))),
      Option.when(s.transmit > 0 && s.ior != 1)(
        Lobe(
          s.transmit,
          typed(
            "dielectric",
            "int_ior"                -> Num(s.ior),
            "ext_ior"                -> Num(1),
            "specular_reflectance"   -> reflectance(Colour.grey(s.transmit)),
            "specular_transmittance" -> reflectance(Colour.grey(s.transmit))
          )
        )
      )
    ).flatten
    val mixed = lobes match
      case Vector()     => sided(typed("diffuse", "reflectance" -> reflectance(Colour.Black)))
      case Vector(only) => only.bsdf
      case many         => Call("mixture", many.map(l => List(Vector(Num(l.weight), l.bsdf))))
    if !clear then mixed
    else if s.transmit == 1 then typed("null")
    else typed("mask", "opacity" -> Num(1 - s.transmit), "bsdf" -> mixed)

  private def traverse[A, B](as: Seq[A])(f: A => Either[String, B]): Either[String, Vector[B]] =
    as.foldLeft[Either[String, Vector[B]]](Right(Vector.empty))((acc, a) =>
      for bs <- acc; b <- f(a) yield bs :+ b
    )

  /** Prints the twin of the scene file named by the first argument (its meshes relative to its
    * directory) for a picture of WIDTH × HEIGHT pixels, SAMPLES a pixel and DEPTH bounces (`-r`).
    */
  def main(args: Array[String]): Unit =
    args.toList match
      case scala.List(name, width, height, samples, depth)
          if scala.List(width, height, samples, depth).forall(_.matches("\\d{1,7}")) =>
        val file     = java.nio.file.Path.of(name).toAbsolutePath
        val settings = Settings(width.toInt, height.toInt, samples.toInt, depth.toInt)
        tracer.io.SceneXml
          .load(file, file.getParent)
          .left
          .map(_.toString)
          .flatMap(write(_, settings)) match
          case Right(program) => print(program)
          case Left(error)    => System.err.println(s"Mitsuba: $name: $error"); sys.exit(1)
      case _ =>
        System.err.println("usage: Mitsuba SCENE WIDTH HEIGHT SAMPLES DEPTH")
        sys.exit(2)
