package tracer.demo

import java.nio.file.{Files, Path}
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.Colour
import tracer.io.SceneWriter
import tracer.math.Vec3
import tracer.render.CameraConfig
import tracer.scene.*

/** The benchmark scenes of `docs/performance.md`, generated: a few objects, a field of 500
  * spheres, and triangle meshes of 5k, 20k and 80k triangles over a mirror, each also written for
  * POV-Ray ([[PovRay]]) so that both renderers draw the same picture.
  */
object BenchScenes:

  /** The scenes' names: the file names without extension. */
  val names: List[String] = List("few", "spheres", "mesh-5000", "mesh-20000", "mesh-80000")

  /** The scene called `name` (one of [[names]]), built on demand. */
  def scene(name: String): Scene = name match
    case "few"     => few
    case "spheres" => spheres
    case _         => mesh(Math.round(Math.sqrt(name.stripPrefix("mesh-").toInt / 2.0)).toInt)

  /** Writes `NAME.xml` and `NAME.pov` for every scene into `dir`; the meshes' XML names their
    * triangles in `NAME.obj` through a `<mesh>` element, as a user would.
    */
  def writeAll(dir: Path, depth: Int = CameraConfig.DefaultDepth): Unit =
    Files.createDirectories(dir)
    names.foreach { name =>
      val s = scene(name)
      Files.writeString(dir.resolve(s"$name.pov"), PovRay.write(s, depth))
      if name.startsWith("mesh-") then
        val n = Math.round(Math.sqrt(name.stripPrefix("mesh-").toInt / 2.0)).toInt
        Files.writeString(
          dir.resolve(s"$name.obj"),
          Models.obj(grid(n), s"$name: a terrain of ${2 * n * n} triangles")
        )
        val withoutMesh = SceneWriter.write(s.copy(objects = s.objects.take(1)))
        val mesh        =
          s"""  <mesh file="$name.obj"><surface diffuse="0.9" reflection="0.1"><colour r="0.75" g="0.6" b="0.35"/></surface></mesh>\n"""
        Files.writeString(
          dir.resolve(s"$name.xml"),
          withoutMesh.replace("</scene>", mesh + "</scene>")
        )
      else Files.writeString(dir.resolve(s"$name.xml"), SceneWriter.write(s))
    }

  /** Writes the scenes into the directory named by the first argument (default `scenes/bench`). */
  def main(args: Array[String]): Unit = writeAll(Path.of(args.headOption.getOrElse("scenes/bench")))

  private val camera =
    Camera(Vec3(0, 2.2, -7), Vec3(0, 0.6, 0), zoom = 1.2, width = 1.6, height = 0.9)
  private val lights = List(
    Light(Vec3(-5, 8, -6), Colour(0.8, 0.75, 0.7)),
    Light(Vec3(6, 4, -4), Colour(0.3, 0.35, 0.5))
  )
  private def matte(c: Colour, reflection: Double = 0) = Surface(0.9, reflection, Pigment.Solid(c))
  private val mirrorFloor                              =
    SceneObject(Plane.at(Vec3.UnitY, 0), Surface(0.7, 0.4, Pigment.Solid(Colour.grey(0.6))))

  /** (a) A few objects: two planes, three spheres, a triangle, two lights, reflections. */
  lazy val few: Scene = Scene(
    camera,
    Colour(0.1, 0.1, 0.2),
    lights,
    List(
      mirrorFloor,
      SceneObject(Plane.at(Vec3(0, 0, -1), -6), matte(Colour(0.5, 0.45, 0.4))),
      SceneObject(Sphere(Vec3(-1.2, 1, 0.5), 1), matte(Colour(0.9, 0.3, 0.2), 0.2)),
      SceneObject(
        Sphere(Vec3(1.2, 0.6, -0.3), 0.6),
        Surface(0.2, 0.7, Pigment.Solid(Colour.grey(0.95)))
      ),
      SceneObject(Sphere(Vec3(0.2, 0.3, -1.5), 0.3), matte(Colour(0.2, 0.4, 0.9), 0.3)),
      SceneObject(
        Triangle(Vec3(1, 0, 1.5), Vec3(2.4, 0, 1.8), Vec3(1.6, 2.2, 2)),
        matte(Colour(0.3, 0.8, 0.3))
      )
    )
  )

  /** (b) A field of 500 spheres on a mirror floor, a third of them reflective. */
  lazy val spheres: Scene =
    val balls = (0 until 500).map { i =>
      // A deterministic scatter: the golden angle spreads the spheres evenly over a disc.
      val r      = 0.35 * Math.sqrt(i.toDouble)
      val a      = i * 2.399963229728653
      val radius = 0.12 + 0.1 * ((i * 7919) % 13) / 13.0
      val colour = Colour(
        0.3 + 0.7 * ((i * 31) % 17) / 17.0,
        0.3 + 0.7 * ((i * 17) % 11) / 11.0,
        0.3 + 0.7 * ((i * 13) % 7) / 7.0
      )
      SceneObject(
        Sphere(Vec3(r * Math.cos(a), radius, 3 + r * Math.sin(a)), radius),
        matte(colour, if i % 3 == 0 then 0.6 else 0)
      )
    }
    Scene(camera, Colour(0.1, 0.1, 0.2), lights, mirrorFloor +: balls)

  /** (c) A rolling terrain of 2·n² triangles floating over a mirror floor. */
  def mesh(n: Int): Scene =
    val model     = grid(n)
    val surface   = matte(Colour(0.75, 0.6, 0.35), 0.1)
    val triangles = model.faces.map(f =>
      SceneObject(
        Triangle(model.vertices(f(0) - 1), model.vertices(f(1) - 1), model.vertices(f(2) - 1)),
        surface
      )
    )
    Scene(camera, Colour(0.1, 0.1, 0.2), lights, mirrorFloor +: triangles)

  /** The terrain of [[mesh]] as a model: an (n + 1)² grid of vertices, two triangles a cell. */
  def grid(n: Int): Models.Model =
    def height(x: Double, z: Double) =
      0.8 + 0.35 * Math.sin(1.7 * x) * Math.cos(1.3 * z) + 0.15 * Math.sin(4.1 * x + 2.3 * z)
    val vertices = (for i <- 0 to n; j <- 0 to n yield
      val (x, z) = (-3 + 6.0 * i / n, 6.0 * j / n - 1)
      Vec3(x, height(x, z), z)
    ).toVector
    def at(i: Int, j: Int) = i * (n + 1) + j + 1
    val faces              = (for
      i <- 0 until n; j <- 0 until n;
      f <- Seq(
        Seq(at(i, j), at(i + 1, j), at(i, j + 1)),
        Seq(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))
      )
    yield f).toVector
    Models.Model(vertices, Vector.empty, faces)
