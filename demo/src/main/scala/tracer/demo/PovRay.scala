package tracer.demo

import java.util.Locale
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.Colour
import tracer.math.Vec3
import tracer.render.{CameraConfig, Projection}
import tracer.scene.*

/** Writes a scene in POV-Ray 3.7's scene language, set up to draw the same picture as the tracer
  * (the "twin" of docs/scene-format.md): no ambient light, no gamma, lights without fall-off,
  * reflection untinted, the camera of equations 10–16 as POV-Ray's direction, right and up
  * vectors, and version 2's highlights, transmission, refraction, area lights and smooth mesh
  * faces as the finish, pigment, interior, `area_light` and `smooth_triangle` they stand for.
  * Used to compare the two renderers' pictures and speed; textures are not exported (a textured
  * surface becomes mid-grey). Render it with `+FP File_Gamma=1.0 -A` (or `File_Gamma=sRGB` for
  * `-g srgb`).
  */
object PovRay:

  /** The POV-Ray scene for `scene`, tracing up to `depth` reflections. */
  def write(scene: Scene, depth: Int = CameraConfig.DefaultDepth): String =
    val c                      = scene.camera
    val (right, down, forward) = Projection(c, CameraConfig.forCamera(c)).basis
    val lines                  = Vector(
      "#version 3.7;",
      s"global_settings { assumed_gamma 1 max_trace_level ${depth + 1} adc_bailout 0 ambient_light 0 }",
      s"background { color rgb ${colour(scene.background)} }",
      s"camera { location ${vec(c.location)} direction ${vec(forward * c.zoom)} right ${vec(right * c.width)} up ${vec(down * -c.height)} }"
    ) ++ scene.lights.map(light) ++
      scene.objects.map(sceneObject)
    lines.mkString("", "\n", "\n")

  private def light(l: Light): String =
    val area =
      l.area.fold("")(a => s" area_light ${vec(a.a)}, ${vec(a.b)}, ${a.samplesA}, ${a.samplesB}")
    s"light_source { ${vec(l.location)} color rgb ${colour(l.colour)}$area }"

  private def sceneObject(o: SceneObject): String =
    val shape = o.shape match
      case s: Sphere => s"sphere { ${vec(s.centre)}, ${num(s.radius)}"
      case p: Plane  => s"plane { ${vec(p.normal)}, ${num(p.distance)}"
      case t: Triangle if t.cornerNormals.isDefined =>
        val (n0, n1, n2) = t.cornerNormals.get
        s"smooth_triangle { ${vec(t.t0)}, ${vec(n0)}, ${vec(t.t1)}, ${vec(n1)}, ${vec(t.t2)}, ${vec(n2)}"
      case t: Triangle => s"triangle { ${vec(t.t0)}, ${vec(t.t1)}, ${vec(t.t2)}"
    val f       = o.surface
    val pigment = f.pigment match
      case Pigment.Solid(c)    => c
      case Pigment.Textured(_) => Colour.grey(0.5)
    val finish = s"finish { ambient 0 diffuse ${num(f.diffuse)} reflection ${num(f.reflection)}" +
      s" phong ${num(f.phong)} phong_size ${num(f.phongSize)}" +
      s" specular ${num(f.specular)} roughness ${num(f.roughness)} }"
    val interior = if f.ior != 1 then s" interior { ior ${num(f.ior)} }" else ""
    s"$shape pigment { color rgbt <${num(pigment.r)}, ${num(pigment.g)}, ${num(pigment.b)}, ${num(f.transmit)}> } $finish$interior }"

  private def vec(v: Vec3): String      = s"<${num(v.x)}, ${num(v.y)}, ${num(v.z)}>"
  private def colour(c: Colour): String = s"<${num(c.r)}, ${num(c.g)}, ${num(c.b)}>"
  private def num(d: Double): String    = String.format(Locale.ROOT, "%.17g", d)

  /** Prints the POV-Ray twin of the scene file named by the first argument (its textures and
    * meshes relative to its directory), tracing as many reflections as the second (default 5).
    * With `--beside FILE…`, writes each FILE's twin beside it instead (`frame.xml` → `frame.pov`).
    */
  def main(args: Array[String]): Unit =
    def twin(name: String, depth: Int): String =
      val file = java.nio.file.Path.of(name).toAbsolutePath
      tracer.io.SceneXml.load(file, file.getParent) match
        case Right(scene) => write(scene, depth)
        case Left(error)  => System.err.println(error); sys.exit(1)
    args.toList match
      case "--beside" :: files =>
        files.foreach { name =>
          java.nio.file.Files.writeString(
            java.nio.file.Path.of(name.replaceAll("\\.xml$", "") + ".pov"),
            twin(name, CameraConfig.DefaultDepth)
          )
        }
      case name :: depth =>
        print(twin(name, depth.headOption.fold(CameraConfig.DefaultDepth)(_.toInt)))
      case Nil => System.err.println("usage: PovRay SCENE [DEPTH] | --beside SCENE..."); sys.exit(2)
