package tracer.demo

import java.util.Locale
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.{CameraConfig, Projection}
import tracer.scene.*

/** Writes a scene in POV-Ray 3.7's scene language, set up to draw the same picture as the tracer:
  * no ambient light, no gamma, point lights without fall-off, reflection untinted, and the camera
  * of equations 10–16 as POV-Ray's direction, right and up vectors. Used to compare the two
  * renderers' speed (`docs/performance.md`); textures are not exported.
  */
object PovRay:

  /** The POV-Ray scene for `scene`, tracing up to `depth` reflections. */
  def write(scene: Scene, depth: Int = CameraConfig.DefaultDepth): String =
    val c                      = scene.camera
    val (right, down, forward) = Projection(c, CameraConfig.forCamera(c)).basis
    val lines                  = Vector(
      s"global_settings { assumed_gamma 1 max_trace_level ${depth + 1} adc_bailout 0 ambient_light 0 }",
      s"background { color rgb ${colour(scene.background)} }",
      s"camera { location ${vec(c.location)} direction ${vec(forward * c.zoom)} right ${vec(right * c.width)} up ${vec(down * -c.height)} }"
    ) ++ scene.lights.map(l =>
      s"light_source { ${vec(l.location)} color rgb ${colour(l.colour)} }"
    ) ++
      scene.objects.map(sceneObject)
    lines.mkString("", "\n", "\n")

  private def sceneObject(o: SceneObject): String =
    val shape = o.shape match
      case s: Sphere   => s"sphere { ${vec(s.centre)}, ${num(s.radius)}"
      case p: Plane    => s"plane { ${vec(p.normal)}, ${num(p.distance)}"
      case t: Triangle => s"triangle { ${vec(t.t0)}, ${vec(t.t1)}, ${vec(t.t2)}"
    val pigment = o.surface.pigment match
      case Pigment.Solid(c)    => colour(c)
      case Pigment.Textured(_) => colour(Colour.grey(0.5))
    s"$shape pigment { color rgb $pigment } finish { ambient 0 diffuse ${num(o.surface.diffuse)} reflection ${num(o.surface.reflection)} } }"

  private def vec(v: Vec3): String      = s"<${num(v.x)}, ${num(v.y)}, ${num(v.z)}>"
  private def colour(c: Colour): String = s"<${num(c.r)}, ${num(c.g)}, ${num(c.b)}>"
  private def num(d: Double): String    = String.format(Locale.ROOT, "%.17g", d)
