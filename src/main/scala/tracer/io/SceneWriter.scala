package tracer.io

import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.*

/** Writes scenes in the XML format that [[SceneXml]] reads, so that scenes built in code (the
  * movie's frames, the REPL's experiments) can be rendered by the `tracer` command.
  *
  * Numbers are written exactly (shortest round-trip decimal), so reading the text back gives the
  * same scene; a texture is written as its `name`, which must be the file it can be loaded from.
  * Version 2 attributes are written only where they differ from their defaults, so a version 1
  * scene is written as version 1. A smooth mesh triangle has no element of its own (only
  * `<mesh smooth="true">` makes them) and is refused.
  */
object SceneWriter:

  /** The XML document for `scene`. */
  def write(scene: Scene): String =
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
      lines += s"  <light>${vector("location", l.location)}${colour("colour", l.colour)}$area</light>"
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
    val surface = this.surface(o.surface)
    o.shape match
      case s: Sphere =>
        s"""<sphere radius="${number(s.radius)}">${vector("centre", s.centre)}""" +
          s"${vector("pole", s.pole)}${vector("equator", s.equator)}$surface</sphere>"
      case p: Plane =>
        s"""<plane distance="${number(p.distance)}">${vector("normal", p.normal)}$surface</plane>"""
      case t: Triangle =>
        require(
          t.cornerNormals.isEmpty,
          "a smooth triangle cannot be written as <triangle>: use <mesh smooth=\"true\">"
        )
        s"<triangle>${vector("corner", t.t0)}${vector("corner", t.t1)}${vector("corner", t.t2)}$surface</triangle>"

  private def surface(s: Surface): String =
    val pigment = s.pigment match
      case Pigment.Solid(c)          => colour("colour", c)
      case Pigment.Textured(texture) => s"""<texture file="${escape(texture.name)}"/>"""
    val defaults = Surface()
    val extras   = List(
      ("phong", s.phong, defaults.phong),
      ("phong-size", s.phongSize, defaults.phongSize),
      ("specular", s.specular, defaults.specular),
      ("roughness", s.roughness, defaults.roughness),
      ("transmit", s.transmit, defaults.transmit),
      ("ior", s.ior, defaults.ior)
    ).collect { case (key, value, default) if value != default => s""" $key="${number(value)}"""" }
    s"""<surface diffuse="${number(s.diffuse)}" reflection="${number(s.reflection)}"""" +
      s"""${extras.mkString}>$pigment</surface>"""

  private def vector(name: String, v: Vec3): String =
    s"""<$name x="${number(v.x)}" y="${number(v.y)}" z="${number(v.z)}"/>"""

  private def colour(name: String, c: Colour): String =
    s"""<$name r="${number(c.r)}" g="${number(c.g)}" b="${number(c.b)}"/>"""

  /** `d` in the scene format, reading back as exactly `d`. */
  private def number(d: Double): String =
    require(d.isFinite, s"a scene holds only finite numbers, got $d")
    Decimal.show(d)

  private def escape(text: String): String =
    text.flatMap {
      case '&' => "&amp;"
      case '<' => "&lt;"
      case '"' => "&quot;"
      case c   => c.toString
    }
