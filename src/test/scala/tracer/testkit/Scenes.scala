package tracer.testkit

import scala.reflect.ClassTag
import tracer.geometry.Shape
import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.*

/** Small scenes for tests, built in code. */
object Scenes:

  /** A camera on −z looking at the origin with the default image plane. */
  val camera: Camera = Camera(Vec3(0, 0, -5), Vec3.Zero)

  /** A shape with a plain matte surface of `colour`. */
  def matte(
      shape: Shape,
      colour: Colour = Colour.White,
      diffuse: Double = 1,
      reflection: Double = 0
  ): SceneObject =
    SceneObject(shape, Surface(diffuse, reflection, Pigment.Solid(colour)))

  extension (scene: Scene)
    /** The shape of the scene's first object as an `S`, or the test fails saying what it was. */
    def firstShape[S <: Shape](using kind: ClassTag[S], at: munit.Location): S =
      scene.objects.headOption.map(_.shape) match
        case Some(kind(shape)) => shape
        case other             =>
          munit.Assertions.fail(s"expected a ${kind.runtimeClass.getSimpleName}, found $other")
