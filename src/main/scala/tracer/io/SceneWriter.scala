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
      lines += s"  <light>${vector("location", l.location)}${colour("colour", l.colour)}</light>"
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
        s"<triangle>${vector("corner", t.t0)}${vector("corner", t.t1)}${vector("corner", t.t2)}$surface</triangle>"

  private def surface(s: Surface): String =
    val pigment = s.pigment match
      case Pigment.Solid(c)          => colour("colour", c)
      case Pigment.Textured(texture) => s"""<texture file="${escape(texture.name)}"/>"""
    s"""<surface diffuse="${number(s.diffuse)}" reflection="${number(
        s.reflection
      )}">$pigment</surface>"""

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
