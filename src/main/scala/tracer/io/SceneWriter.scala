package tracer.io

import tracer.geometry.*
import tracer.image.Colour
import tracer.math.{Placement, Vec3}
import tracer.scene.*

/** Writes scenes in the XML format that [[SceneXml]] reads, so that scenes built in code (the
  * movie's frames, the REPL's experiments) can be rendered by the `tracer` command.
  *
  * Numbers are written exactly (shortest round-trip decimal), so reading the text back gives the
  * same scene; a texture is written as its `name`, which must be the file it can be loaded from.
  * Version 2 attributes (and version 4's emission and fade) are written only where they differ
  * from their defaults, so a version 1 scene is written as version 1. Version 3 solids and
  * combinations are written with their placement, and a child of a combination with its surface
  * where it differs from the one it would inherit. What the format cannot say is not written but
  * told: a number that is not finite, and a mesh triangle with smooth normals or texture
  * coordinates at its corners (only `<mesh>` makes those, from its OBJ file, and a `<triangle>`
  * would lose them).
  */
object SceneWriter:

  /** The XML document for `scene`, or why the format cannot say it. */
  def write(scene: Scene): Either[String, String] =
    unwritable(scene).toLeft(document(scene))

  /** The first part of `scene` that the format cannot say, described. */
  private def unwritable(scene: Scene): Option[String] =
    scene.objects.iterator
      .flatMap(o => leaves(o.shape))
      .collectFirst {
        case t: Triangle if t.cornerNormals.isDefined =>
          s"a triangle with smooth normals at its corners ${corners(t)} has no element of its " +
            "own: only <mesh smooth=\"true\"> makes one, from its OBJ file"
        case t: Triangle if t.textureCorners.isDefined =>
          s"a triangle with texture coordinates at its corners ${corners(t)} has no element of " +
            "its own: only <mesh> makes one, from its OBJ file"
      }
      .orElse(nonFinite(scene, "scene"))

  private def corners(t: Triangle): String = s"${t.t0}, ${t.t1}, ${t.t2}"

  /** The primitive shapes inside `s`. */
  private def leaves(s: Shape): Iterator[Shape] = s match
    case c: Csg    => c.children.iterator.flatMap(leaves)
    case m: Mesh   => m.faces
    case p: Placed => leaves(p.shape)
    case other     => Iterator(other)

  /** The first number in `value`, at any depth of its fields, that is not finite, named by its
    * path from `path` (`scene.objects(2).shape.centre.y`). A texture's pixels are not written
    * (only its name), so they are not looked at.
    */
  private def nonFinite(value: Any, path: String): Option[String] = value match
    case d: Double if !d.isFinite =>
      Some(s"$path is $d: the scene format holds finite numbers only")
    case _: Texture      => None
    case xs: Iterable[?] =>
      xs.iterator.zipWithIndex.map((x, i) => nonFinite(x, s"$path($i)")).collectFirst {
        case Some(m) => m
      }
    case p: Product =>
      p.productIterator.zipWithIndex
        .map((v, i) => nonFinite(v, s"$path.${p.productElementName(i)}"))
        .collectFirst { case Some(m) => m }
    case _ => None

  /** The document for a scene that [[unwritable]] passed. */
  private def document(scene: Scene): String =
    val lines = Vector.newBuilder[String]
    lines += """<?xml version="1.0" encoding="UTF-8"?>"""
    lines += "<scene>"
    lines ++= camera(scene.camera)
    lines += s"  ${colour("background", scene.background)}"
    scene.lights.foreach { l =>
      val area = l.area.fold("")(a =>
        s"""<area samples-a="${a.samplesA}" samples-b="${a.samplesB}">""" +
          s"""${vector("a", a.a)}${vector("b", a.b)}</area>"""
      )
      val fade = l.fade.fold("")(f =>
        s""" fade-distance="${number(f.distance)}" fade-power="${number(f.power)}""""
      )
      lines += s"  <light$fade>${vector("location", l.location)}${colour("colour", l.colour)}$area</light>"
    }
    scene.objects.foreach(o => lines += s"  ${sceneObject(o)}")
    lines += "</scene>"
    lines.result().mkString("", "\n", "\n")

  private def camera(c: Camera): Seq[String] = Seq(
    s"""  <camera zoom="${number(c.zoom)}" width="${number(c.width)}" height="${number(
        c.height
      )}">""",
    s"    ${vector("location", c.location)}${vector("lookat", c.lookAt)}${vector("up", c.up)}",
    "  </camera>"
  )

  private def sceneObject(o: SceneObject): String =
    shape(o.shape, o, 0, Placement.Identity, Nil, Right(o.surface))

  /** The element for `s`, whose first leaf is number `leaf` of `o`'s shape, placed by `placement`
    * inside elements placed by `enclosing` (innermost first). `look` is the surface it must carry
    * (`Right`, at the top of the scene), or (`Left`) the one it would inherit: a primitive then
    * carries its own where it differs, and a combination the surface of its leaves that can sit on
    * it — one whose pattern lies in its space — so that its children inherit it (the version 3
    * rule). A child's `ior` means nothing and is not written.
    */
  private def shape(
      s: Shape,
      o: SceneObject,
      leaf: Int,
      placement: Placement,
      enclosing: List[Placement],
      look: Either[Surface, Surface]
  ): String =
    def carried(own: Option[Surface], look: Either[Surface, Surface] = look) = look match
      case Right(top)      => (Some(top), top)
      case Left(inherited) =>
        val mine = own.filter(_ != inherited)
        (mine.map(_.copy(ior = Surface().ior)), own.getOrElse(inherited))
    def element(own: Option[Surface], look: Either[Surface, Surface] = look) =
      val (written, _) = carried(own, look)
      written.fold("")(surface) + place(placement)
    val scale = if placement.scale != 1 then s""" scale="${number(placement.scale)}"""" else ""
    s match
      case s: Sphere =>
        s"""<sphere radius="${number(s.radius)}"$scale>${vector("centre", s.centre)}""" +
          s"${vector("pole", s.pole)}${vector("equator", s.equator)}${element(Some(o.surfaceOf(leaf)))}</sphere>"
      case p: Plane =>
        s"""<plane distance="${number(p.distance)}"$scale>${vector("normal", p.normal)}""" +
          s"${element(Some(o.surfaceOf(leaf)))}</plane>"
      case t: Triangle =>
        s"<triangle>${vector("corner", t.t0)}${vector("corner", t.t1)}${vector("corner", t.t2)}" +
          s"${element(Some(o.surfaceOf(leaf)))}</triangle>"
      case m: Mesh =>
        // A flat mesh without texture coordinates (unwritable saw to it): its faces as triangles,
        // the same picture (a tie between faces goes to the first, as between the triangles).
        Iterator
          .range(0, m.faceCount)
          .map(f => shape(m.face(f), o, leaf + f, placement, enclosing, look))
          .mkString("\n  ")
      case b: Box =>
        s"<box$scale>${vector("corner1", b.corner1)}${vector("corner2", b.corner2)}" +
          s"${element(Some(o.surfaceOf(leaf)))}</box>"
      case c: Cone =>
        val open  = if c.open then """ open="true"""" else ""
        val parts =
          s"${vector("base", c.base)}${vector("cap", c.cap)}${element(Some(o.surfaceOf(leaf)))}"
        if c.baseRadius == c.capRadius then
          s"""<cylinder radius="${number(c.baseRadius)}"$open$scale>$parts</cylinder>"""
        else
          val radii =
            s"""base-radius="${number(c.baseRadius)}" cap-radius="${number(c.capRadius)}""""
          s"""<cone $radii$open$scale>$parts</cone>"""
      case t: Torus =>
        s"""<torus major="${number(t.major)}" minor="${number(t.minor)}"$scale>""" +
          s"${element(Some(o.surfaceOf(leaf)))}</torus>"
      case Placed(t: Triangle, p) =>
        // The format never places a triangle: its corners carry the placement, as when read.
        shape(t.placed(p), o, leaf, placement, enclosing, look)
      case p: Placed if placement.isIdentity && !(enclosing.isEmpty && unplacedAtTop(p.shape)) =>
        shape(p.shape, o, leaf, p.placement, enclosing, look)
      case p: Placed =>
        // Placed twice (a child of a union that was split), or a placed sphere or plane at the top
        // of the scene, where the format places neither: the union it came from, written again,
        // which reading splits the same way.
        // The union carries the surface where its pattern lies in the union's space.
        val (outer, inner) = look match
          case Right(top)
              if Inheritance.depth(top, List(p.placement), placement :: enclosing) == 1 =>
            (look, Left(top))
          case Right(top)      => (Left(Surface()), Right(top))
          case Left(inherited) => (look, Left(inherited))
        val child = shape(p, o, leaf, Placement.Identity, placement :: enclosing, inner)
        s"<union$scale>$child${element(None, outer)}</union>"
      case c: Csg =>
        val name = c.operation match
          case CsgOperation.Union        => "union"
          case CsgOperation.Intersection => "intersection"
          case CsgOperation.Difference   => "difference"
        val own         = Inheritance.carried(o, c, leaf, placement :: enclosing)
        val (_, passed) = carried(own)
        val children    = c.children.indices.map { i =>
          shape(
            c.children(i),
            o,
            leaf + c.firstLeaves(i),
            Placement.Identity,
            placement :: enclosing,
            Left(passed)
          )
        }
        s"<$name$scale>${children.mkString}${element(own)}</$name>"

  /** True for a shape the format places only inside a combination: a sphere or a plane. */
  private def unplacedAtTop(s: Shape): Boolean = s match
    case _: (Sphere | Plane) => true
    case _                   => false

  private def place(p: Placement): String =
    (if p.rotate != Vec3.Zero then vector("rotate", p.rotate) else "") +
      (if p.translate != Vec3.Zero then vector("translate", p.translate) else "")

  private def surface(s: Surface): String =
    val pigment = s.pigment match
      case Pigment.Solid(c)          => colour("colour", c)
      case Pigment.Textured(texture) => s"""<texture file="${escape(texture.name)}"/>"""
      case c: Pigment.Checker        =>
        s"""<checker size="${number(c.size)}">${colour("colour", c.first)}${colour(
            "colour",
            c.second
          )}</checker>"""
    val defaults = Surface()
    val extras   = List(
      ("phong", s.phong, defaults.phong),
      ("phong-size", s.phongSize, defaults.phongSize),
      ("specular", s.specular, defaults.specular),
      ("roughness", s.roughness, defaults.roughness),
      ("transmit", s.transmit, defaults.transmit),
      ("ior", s.ior, defaults.ior)
    ).collect { case (key, value, default) if value != default => s""" $key="${number(value)}"""" }
    val emission = if s.emission != defaults.emission then colour("emission", s.emission) else ""
    s"""<surface diffuse="${number(s.diffuse)}" reflection="${number(s.reflection)}"""" +
      s"""${extras.mkString}>$pigment$emission</surface>"""

  private def vector(name: String, v: Vec3): String =
    s"""<$name x="${number(v.x)}" y="${number(v.y)}" z="${number(v.z)}"/>"""

  private def colour(name: String, c: Colour): String =
    s"""<$name r="${number(c.r)}" g="${number(c.g)}" b="${number(c.b)}"/>"""

  /** `d` in the scene format, reading back as exactly `d` (finite: [[unwritable]] saw to it). */
  private def number(d: Double): String = Decimal.show(d)

  private def escape(text: String): String =
    text.flatMap {
      case '&' => "&amp;"
      case '<' => "&lt;"
      case '"' => "&quot;"
      case c   => c.toString
    }
