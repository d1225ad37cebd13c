package tracer.scene

import tracer.geometry.Shape
import tracer.image.{Bitmap, Colour}
import tracer.math.Vec3

/** A scene as the XML describes it: a camera, a background, lights and objects, all immutable.
  *
  * @param camera     where the picture is taken from
  * @param background the colour of every ray, primary or reflected, that hits nothing
  * @param lights     the point lights, in document order
  * @param objects    the shapes with their surfaces, in document order
  */
final case class Scene(
    camera: Camera,
    background: Colour = Colour.Black,
    lights: Seq[Light] = Nil,
    objects: Seq[SceneObject] = Nil
)

/** The camera of the course text, section 4 (equations 8–16).
  *
  * @param location the eye Ce
  * @param lookAt   the point Cl the camera faces; differs from `location`
  * @param up       which way is up in the picture (Cu); not parallel to Cl − Ce, need not be unit
  * @param zoom     Z, the distance from the eye to the image plane, > 0
  * @param width    W, the image plane's width in world units, > 0
  * @param height   H, the image plane's height in world units, > 0
  */
final case class Camera(
    location: Vec3,
    lookAt: Vec3,
    up: Vec3 = Vec3.UnitY,
    zoom: Double = Camera.DefaultZoom,
    width: Double = Camera.DefaultWidth,
    height: Double = Camera.DefaultHeight
):
  require(location != lookAt, s"the camera's location and lookat are the same point $location")
  require(
    up.cross(lookAt - location).normalised.isDefined,
    s"the camera's up $up is parallel to its viewing direction ${lookAt - location}"
  )
  require(
    zoom > 0 && width > 0 && height > 0,
    "the camera's zoom, width and height must be positive"
  )

/** The scene format's camera defaults. */
object Camera:
  /** Z when the scene gives none. */
  val DefaultZoom: Double = 1.0

  /** W when the scene gives none. */
  val DefaultWidth: Double = 1.0

  /** H when the scene gives none. */
  val DefaultHeight: Double = 0.75

/** A point light: no size, invisible, no fall-off with distance.
  *
  * @param location where it is (L0)
  * @param colour   its intensity per channel, ≥ 0 and possibly above 1
  */
final case class Light(location: Vec3, colour: Colour = Colour.White)

/** A shape with the surface that colours it. */
final case class SceneObject(shape: Shape, surface: Surface = Surface())

/** How a surface reflects light.
  *
  * @param diffuse    the diffuse coefficient, ≥ 0
  * @param reflection the mirror coefficient, 0..1
  * @param pigment    the colour of the surface, plain or from a texture
  */
final case class Surface(
    diffuse: Double = 1.0,
    reflection: Double = 0.0,
    pigment: Pigment = Pigment.Solid(Colour.White)
)

/** Where a surface's own colour comes from. */
enum Pigment:
  /** One colour everywhere. */
  case Solid(colour: Colour)

  /** An image mapped onto the shape (rendering.md, Textures). */
  case Textured(texture: Texture)

/** An image used as a texture, with the name it was loaded from (for messages).
  *
  * A point (u, v) in [0, 1]² takes the texel at column min(w − 1, ⌊u·w⌋) and row
  * min(h − 1, ⌊(1 − v)·h⌋): nearest neighbour, v = 1 at the top of the image.
  */
final case class Texture(image: Bitmap, name: String = "texture"):

  /** The texel colour at texture coordinates (u, v). */
  def colourAt(u: Double, v: Double): Colour =
    val column = Math.min(image.width - 1, Math.max(0, Math.floor(u * image.width).toInt))
    val row    = Math.min(image.height - 1, Math.max(0, Math.floor((1 - v) * image.height).toInt))
    image(column, row)
