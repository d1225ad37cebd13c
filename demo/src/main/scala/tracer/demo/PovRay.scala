package tracer.demo

import java.util.Locale
import tracer.geometry.*
import tracer.image.Colour
import tracer.math.{Placement, Vec3}
import tracer.cli.Resolution
import tracer.render.{CameraConfig, Projection}
import tracer.scene.*

/** Writes a scene in POV-Ray 3.7's scene language, set up to draw the same picture as the tracer
  * (the "twin" of docs/scene-format.md): no ambient light, no gamma, lights without fall-off
  * unless they carry version 4's fade (`fade_distance`, `fade_power`), reflection untinted, the camera of equations 10–16 as POV-Ray's direction, right and up
  * vectors, and version 2's highlights, transmission, refraction, area lights and smooth mesh
  * faces as the finish, pigment, interior, `area_light` and `smooth_triangle` they stand for.
  * Used to compare the two renderers' pictures and speed; textures are not exported (a textured
  * surface becomes mid-grey), nor is version 4's emission (POV-Ray's `emission` is tinted by the
  * pigment and glows on both sides, so it is no twin of ours). Render it with `+FP File_Gamma=1.0 -A` (or `File_Gamma=sRGB` for
  * `-g srgb`).
  */
object PovRay:

  /** The POV-Ray scene for `scene`, tracing up to `depth` reflections. With `quick`, the twin of
    * quick mode (`-q`): one shadowless light at the eye and every surface its plain pigment
    * with diffuse 1, which POV-Ray shades as colour · |rn · Rd|. With `pixels` (X, Y), the
    * camera's image plane is the one the tracer uses for `-x X -y Y` (cli.md: W kept, H = W·Y/X),
    * so that a picture of another shape than the camera's `width` and `height` is not distorted
    * in the twin alone.
    */
  def write(
      scene: Scene,
      depth: Int = CameraConfig.DefaultDepth,
      quick: Boolean = false,
      pixels: Option[(Int, Int)] = None
  ): String =
    val sized = pixels.fold(scene) { (x, y) =>
      val c    = scene.camera
      val size = Resolution.resolve(None, None, Some(x), Some(y), c.width, c.height)
      scene.copy(camera = c.copy(width = size.width, height = size.height))
    }
    if !quick then twin(sized, depth, sized.lights.map(light))
    else
      val eye  = s"light_source { ${vec(sized.camera.location)} color rgb <1, 1, 1> shadowless }"
      val flat = sized.objects.map(o =>
        o.copy(surface = plain(o.surface), leafSurfaces = o.leafSurfaces.map(plain))
      )
      twin(sized.copy(objects = flat), depth, Seq(eye))

  /** A surface as quick mode sees it: its pigment alone, diffuse 1. */
  private def plain(s: Surface): Surface = Surface(diffuse = 1, pigment = s.pigment)

  private def twin(scene: Scene, depth: Int, lights: Seq[String]): String =
    val c                      = scene.camera
    val (right, down, forward) = Projection(c, CameraConfig.forCamera(c)).basis
    val lines                  = Vector(
      "#version 3.7;",
      s"global_settings { assumed_gamma 1 max_trace_level ${depth + 1} adc_bailout 0 ambient_light 0 }",
      s"background { color rgb ${colour(scene.background)} }",
      s"camera { location ${vec(c.location)} direction ${vec(forward * c.zoom)} right ${vec(right * c.width)} up ${vec(down * -c.height)} }"
    ) ++ lights ++ scene.objects.map(sceneObject)
    lines.mkString("", "\n", "\n")

  private def light(l: Light): String =
    val area =
      l.area.fold("")(a => s" area_light ${vec(a.a)}, ${vec(a.b)}, ${a.samplesA}, ${a.samplesB}")
    val fade =
      l.fade.fold("")(f => s" fade_distance ${num(f.distance)} fade_power ${num(f.power)}")
    s"light_source { ${vec(l.location)} color rgb ${colour(l.colour)}$area$fade }"

  private def sceneObject(o: SceneObject): String =
    shape(o.shape, o, 0, Nil, Nil, Right(o.surface))

  /** The twin of `s`, whose first leaf is number `leaf` of `o`'s shape, placed by `chain` (the
    * placements met on the way down, innermost first) inside elements placed by `enclosing`.
    * `look` is the surface it must carry (`Right`, at the top) or the one it would inherit
    * (`Left`): a primitive carries its own where it differs, a combination the one
    * [[tracer.scene.Inheritance.carried]] chooses; the texture goes among the transforms where
    * its pattern moves with the right ones, as POV-Ray's textures move with the transforms after
    * them.
    */
  private def shape(
      s: Shape,
      o: SceneObject,
      leaf: Int,
      chain: List[Placement],
      enclosing: List[Placement],
      look: Either[Surface, Surface]
  ): String =
    def carried(own: Option[Surface]) = look match
      case Right(top)      => (Some(top), top)
      case Left(inherited) => (own.filter(_ != inherited), own.getOrElse(inherited))
    // The transforms, with the texture before the ones its pattern moves with; at the top, the
    // interior of the whole object.
    def rest(own: Option[Surface]) =
      val (written, _) = carried(own)
      val at           = written.fold(0)(Inheritance.depth(_, chain, enclosing))
      val moves        = chain.map(placement)
      val interior     =
        look.fold(_ => "", top => if top.ior != 1 then s"interior { ior ${num(top.ior)} } " else "")
      // A checker whose space none of the transforms reach (the shape's placement built into
      // its corners) carries that space's transforms itself, after all the shape's.
      written.filter(Inheritance.unplaced(_, chain, enclosing)) match
        case Some(surface) =>
          val (own, undo) = ownSpace(surface, enclosing)
          " " + moves.mkString + texture(surface, own, undo) + " " + interior + "}"
        case None =>
          " " + moves.take(at).mkString + written.fold("")(texture(_) + " ") +
            moves.drop(at).mkString + interior + "}"
    def leafRest = rest(Some(o.surfaceOf(leaf)))
    s match
      case s: Sphere    => s"sphere { ${vec(s.centre)}, ${num(s.radius)}$leafRest"
      case p: Plane     => s"plane { ${vec(p.normal)}, ${num(p.distance)}$leafRest"
      case tr: Triangle =>
        tr.cornerNormals match
          case Some((n0, n1, n2)) =>
            val face =
              s"smooth_triangle { ${vec(tr.t0)}, ${vec(n0)}, ${vec(tr.t1)}, ${vec(n1)}, ${vec(tr.t2)}, ${vec(n2)}"
            // POV-Ray drops a lone smooth_triangle whose corner normals are not all on one side
            // of its face (SmoothTriangle::Compute_Smooth_Triangle); a mesh keeps it.
            if oneSided(tr, n0, n1, n2) then face + leafRest else s"mesh { $face }$leafRest"
          case None => s"triangle { ${vec(tr.t0)}, ${vec(tr.t1)}, ${vec(tr.t2)}$leafRest"
      case b: Box  => s"box { ${vec(b.corner1)}, ${vec(b.corner2)}$leafRest"
      case c: Cone =>
        val open = if c.open then " open" else ""
        if c.baseRadius == c.capRadius then
          s"cylinder { ${vec(c.base)}, ${vec(c.cap)}, ${num(c.baseRadius)}$open$leafRest"
        else
          s"cone { ${vec(c.base)}, ${num(c.baseRadius)}, ${vec(c.cap)}, ${num(c.capRadius)}$open$leafRest"
      case tr: Torus => s"torus { ${num(tr.major)}, ${num(tr.minor)}$leafRest"
      case m: Mesh   =>
        // Its faces, each the triangle it stands for, as when each was a shape of its own; at the
        // top in a union, whose one interior they share, as the mesh is one object to the rays
        // that cross it (in a combination they share its interior already).
        val faces = Iterator
          .range(0, m.faceCount)
          .map(f => shape(m.face(f), o, leaf + f, chain, enclosing, look))
          .mkString("\n")
        if look.isRight then s"union {\n$faces\n}" else faces
      case p: Placed => shape(p.shape, o, leaf, p.placement :: chain, enclosing, look)
      case c: Csg    =>
        val name = c.operation match
          case CsgOperation.Union        => "union"
          case CsgOperation.Intersection => "intersection"
          case CsgOperation.Difference   => "difference"
        val own         = Inheritance.carried(o, c, leaf, chain ++ enclosing)
        val (_, passed) = carried(own)
        val children    = c.children.indices.map { i =>
          shape(c.children(i), o, leaf + c.firstLeaves(i), Nil, chain ++ enclosing, Left(passed))
        }
        s"$name { ${children.mkString(" ")}${rest(own)}"

  /** True when the corner normals all lie on one side of the face (each dot with its normal of
    * the same strict sign), as a lone POV-Ray `smooth_triangle` needs to be drawn at all.
    */
  private def oneSided(tr: Triangle, n0: Vec3, n1: Vec3, n2: Vec3): Boolean =
    val dots = List(n0, n1, n2).map(_.dot(tr.normal))
    dots.forall(_ > 0) || dots.forall(_ < 0)

  private def placement(p: Placement): String =
    s"scale ${num(p.scale)} rotate ${vec(p.rotate)} translate ${vec(p.translate)} "

  /** The placements of `surface`'s checker space that lie inside elements placed by `enclosing`
    * (whose transforms move the texture after the shape's own), innermost first; and the
    * enclosing placements to undo first when the space does not end with them (a checker of a
    * split union's surface on a leaf of a placed combination: the combination's placement lies
    * between the pattern and the union's).
    */
  private def ownSpace(
      surface: Surface,
      enclosing: List[Placement]
  ): (List[Placement], List[Placement]) =
    surface.pigment match
      case c: Pigment.Checker =>
        val outer = Inheritance.space(enclosing)
        if c.space.endsWith(outer) then (c.space.dropRight(outer.length), Nil) else (c.space, outer)
      case Pigment.Solid(_) | Pigment.Textured(_) => (Nil, Nil)

  /** POV-Ray's texture for `f`, its pattern moved by `moves` (innermost first) of its own, then
    * by the inverse of `undo`'s (innermost first), which the transforms after it will redo.
    */
  private def texture(
      f: Surface,
      moves: List[Placement] = Nil,
      undo: List[Placement] = Nil
  ): String =
    def rgbt(c: Colour) = s"rgbt <${num(c.r)}, ${num(c.g)}, ${num(c.b)}, ${num(f.transmit)}>"
    val pigment         = f.pigment match
      case Pigment.Solid(c)    => s"color ${rgbt(c)}"
      case Pigment.Textured(_) => s"color ${rgbt(Colour.grey(0.5))}"
      case c: Pigment.Checker  =>
        val undone =
          if undo.isEmpty then "" else s"transform { ${undo.map(placement).mkString}inverse } "
        s"checker color ${rgbt(c.first)}, color ${rgbt(c.second)} scale ${num(c.size)} " +
          moves.map(placement).mkString + undone
    val finish = s"finish { ambient 0 diffuse ${num(f.diffuse)} reflection ${num(f.reflection)}" +
      s" phong ${num(f.phong)} phong_size ${num(f.phongSize)}" +
      s" specular ${num(f.specular)} roughness ${num(f.roughness)} }"
    s"texture { pigment { $pigment } $finish }"

  private def vec(v: Vec3): String      = s"<${num(v.x)}, ${num(v.y)}, ${num(v.z)}>"
  private def colour(c: Colour): String = s"<${num(c.r)}, ${num(c.g)}, ${num(c.b)}>"
  private def num(d: Double): String    = String.format(Locale.ROOT, "%.17g", d)

  /** Prints the POV-Ray twin of the scene file named by the first argument (its textures and
    * meshes relative to its directory), tracing as many reflections as the second (default 5),
    * for a picture of the third and fourth's pixels when given (as the tracer's `-x X -y Y`).
    * With `--beside FILE…`, writes each FILE's twin beside it instead (`frame.xml` → `frame.pov`).
    */
  def main(args: Array[String]): Unit =
    def twin(name: String, depth: Int, pixels: Option[(Int, Int)] = None): String =
      val file = java.nio.file.Path.of(name).toAbsolutePath
      tracer.io.SceneXml.load(file, file.getParent) match
        case Right(scene) => write(scene, depth, pixels = pixels)
        case Left(error)  => System.err.println(error); sys.exit(1)
    args.toList match
      case "--beside" :: files =>
        files.foreach { name =>
          java.nio.file.Files.writeString(
            java.nio.file.Path.of(name.replaceAll("\\.xml$", "") + ".pov"),
            twin(name, CameraConfig.DefaultDepth)
          )
        }
      case List(name, depth, x, y) => print(twin(name, depth.toInt, Some((x.toInt, y.toInt))))
      case name :: depth if depth.length <= 1 =>
        print(twin(name, depth.headOption.fold(CameraConfig.DefaultDepth)(_.toInt)))
      case _ =>
        System.err.println("usage: PovRay SCENE [DEPTH [X Y]] | --beside SCENE...")
        sys.exit(2)
