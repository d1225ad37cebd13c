package tracer.demo

import tracer.Eithers
import java.nio.file.{Files, Path}
import tracer.geometry.{Plane, Sphere, Triangle}
import tracer.image.{Bitmap, Colour}
import tracer.io.SceneWriter
import tracer.math.Vec3
import tracer.scene.*

/** The project's own movie, described by what moves: a camera circling the scene, a planet turning
  * on its tilted axis, a red ball bouncing beside a mirror ball, two moons orbiting it, all over
  * a polished floor. Each frame is a [[tracer.scene.Scene]] built in code.
  */
object Animation:

  /** The movie's length in seconds. */
  val Seconds: Double = 6.0

  /** Frames a second. */
  val FramesPerSecond: Int = 25

  /** The number of frames. */
  val FrameCount: Int = (Seconds * FramesPerSecond).toInt

  /** The scene at time `t` seconds, 0 ≤ t < [[Seconds]]; textures are named relative to the
    * frame files' directory (`textures/…`).
    */
  def frame(t: Double, textures: Textures): Scene =
    val phase = t / Seconds // 0 → 1 over the movie
    Scene(
      camera = camera(phase),
      background = Colour(0.04, 0.06, 0.14),
      lights = List(
        // A warm key light with soft shadows (an area light of 4 × 4 sub-lights), a cool fill.
        Light(
          Vec3(-5, 8, -6),
          Colour(0.95, 0.88, 0.78),
          Some(AreaLight(Vec3(1.2, 0, 0), Vec3(0, 0, 1.2), 4, 4))
        ),
        Light(Vec3(6, 4, -4), Colour(0.25, 0.32, 0.5))
      ),
      objects = List(
        SceneObject(
          Plane.at(Vec3.UnitY, 0),
          Surface(0.8, 0.3, Pigment.Solid(Colour(0.55, 0.55, 0.6)))
        ),
        planet(phase, textures.planet),
        SceneObject(
          Sphere(Vec3(0.3, 0.8, 0.4), 0.8),
          Surface(0.15, 0.85, Pigment.Solid(Colour(0.9, 0.9, 0.95)))
        ),
        bouncingBall(t),
        moon(phase, 0.0, Colour(0.95, 0.75, 0.1)),
        moon(phase, 0.5, Colour(0.2, 0.6, 0.95))
      ) ++ mat(textures.checker)
    )

  /** The frames' textures, named as the frame files refer to them. */
  final case class Textures(planet: Texture, checker: Texture)

  /** Writes the movie's frame scenes (`frame-0001.xml`, …), their textures and `frames.txt`, the
    * list that `scripts/movie.sh` reads, into `dir`; or says which frame the scene format cannot
    * hold (see [[tracer.io.SceneWriter]]).
    */
  def writeFrames(dir: Path): Either[String, Unit] =
    Files.createDirectories(dir)
    ProceduralTextures.writeGallery(dir.resolve("textures"))
    // The frames only name their textures: the tracer loads them when it renders each frame.
    val placeholder = Bitmap.fill(1, 1, Colour.White)
    val textures    = Textures(
      Texture(placeholder, "textures/planet.ppm"),
      Texture(placeholder, "textures/checker.png")
    )
    val written = Eithers.traverse((0 until FrameCount).toList) { i =>
      val name = f"frame-${i + 1}%04d.xml"
      SceneWriter
        .write(frame(i.toDouble / FramesPerSecond, textures))
        .map(text => Files.writeString(dir.resolve(name), text))
        .map(_ => name)
    }
    written.map(names =>
      Files.writeString(
        dir.resolve("frames.txt"),
        names.mkString("# The frames of tracer's movie, in order.\n", "\n", "\n")
      ): Unit
    )

  /** Writes the frames into the directory named by the first argument (default `target/movie`). */
  def main(args: Array[String]): Unit =
    writeFrames(Path.of(args.headOption.getOrElse("target/movie"))).left.foreach { why =>
      System.err.println(s"Animation: $why")
      sys.exit(1)
    }

  /** Half a turn around the scene, the eye rising a little. */
  private def camera(phase: Double): Camera =
    val angle  = Math.PI * (-0.3 + 0.6 * smooth(phase))
    val radius = 6.5
    val eye    = Vec3(radius * Math.sin(angle), 1.5 + 0.6 * phase, -radius * Math.cos(angle))
    Camera(eye, Vec3(0, 0.8, 0.4), zoom = 1.2, width = 1.6, height = 0.9)

  /** The planet turns once on an axis tilted 15°: its equator vector rotates about the pole. */
  private def planet(phase: Double, texture: Texture): SceneObject =
    val tilt = Math.toRadians(15)
    val pole = Vec3(Math.sin(tilt), Math.cos(tilt), 0)
    val spin = 2 * Math.PI * phase
    // Two unit vectors at right angles to the pole, and the equator turning between them.
    val e1      = Vec3(0, 0, -1)
    val e2      = pole.cross(e1)
    val equator = e1 * Math.cos(spin) + e2 * Math.sin(spin)
    SceneObject(
      Sphere(Vec3(-1.9, 1, 1.2), 1, pole, equator),
      Surface(1, 0, Pigment.Textured(texture))
    )

  /** A glass ball bouncing three times, squashing nothing: |sin| gives the arcs. */
  private def bouncingBall(t: Double): SceneObject =
    val height = 0.35 + 1.4 * Math.abs(Math.sin(Math.PI * 3 * t / Seconds))
    SceneObject(
      Sphere(Vec3(1.6, height, -0.9), 0.35),
      Surface(
        0.1,
        0.1,
        Pigment.Solid(Colour(1, 0.85, 0.8)),
        phong = 0.9,
        phongSize = 120,
        transmit = 0.85,
        ior = 1.5
      )
    )

  /** A small moon circling the mirror ball, `offset` of a turn ahead. */
  private def moon(phase: Double, offset: Double, colour: Colour): SceneObject =
    val angle  = 2 * Math.PI * (phase * 1.5 + offset)
    val centre = Vec3(
      0.3 + 1.3 * Math.cos(angle),
      0.8 + 0.3 * Math.sin(angle * 2),
      0.4 + 1.3 * Math.sin(angle)
    )
    SceneObject(Sphere(centre, 0.18), Surface(0.9, 0.2, Pigment.Solid(colour), phong = 0.6))

  /** The checkered mat under the mirror ball: two textured triangles. */
  private def mat(checker: Texture): List[SceneObject] =
    val surface = Surface(0.9, 0.1, Pigment.Textured(checker))
    List(
      SceneObject(
        Triangle.fromLegs(Vec3(-0.7, 0.002, -0.6), Vec3(2, 0, 0), Vec3(0, 0, 2)),
        surface
      ),
      SceneObject(Triangle.fromLegs(Vec3(1.3, 0.002, 1.4), Vec3(-2, 0, 0), Vec3(0, 0, -2)), surface)
    )

  /** Eases in and out: 0 → 1 with zero slope at both ends. */
  private def smooth(x: Double): Double = x * x * (3 - 2 * x)
