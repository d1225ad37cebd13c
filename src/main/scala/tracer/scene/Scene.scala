package tracer.scene

import tracer.geometry.Shape
import tracer.image.{Bitmap, Colour, Raster, Texels}
import tracer.math.{Placement, Pow, Vec3}

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

/** A light: a point, or the centre of an area light; invisible, no fall-off with distance.
  *
  * @param location where it is (L0); for an area light, the centre of its grid
  * @param colour   its intensity per channel, ≥ 0 and possibly above 1
  * @param area     the grid of sub-lights that soften its shadows, if it is an area light
  * @param fade     its fall-off with distance (version 4), if any: none is POV-Ray's default
  */
final case class Light(
    location: Vec3,
    colour: Colour = Colour.White,
    area: Option[AreaLight] = None,
    fade: Option[Fade] = None
):
  /** A(d), the share of the light's colour that reaches a point at distance `d`: 1 without fade. */
  def attenuation(d: Double): Double = fade.fold(1.0)(_.attenuation(d))

/** POV-Ray's `fade_distance` D and `fade_power` n (version 4): a light's colour scaled by
  * A(d) = 2 / (1 + (d / D)ⁿ) at distance d, so A(D) = 1 and, for n = 2, inverse-square beyond D.
  *
  * @param distance D, > 0 and finite
  * @param power    n, > 0 and finite
  */
final case class Fade(distance: Double, power: Double):
  require(distance > 0 && distance.isFinite, s"fade-distance must be positive, got $distance")
  require(power > 0 && power.isFinite, s"fade-power must be positive, got $power")

  /** A(d) = 2 / (1 + (d / D)ⁿ), with `StrictMath.pow`'s bits ([[tracer.math.Pow]]), so that every
    * machine computes the same.
    */
  def attenuation(d: Double): Double = 2 / (1 + Pow.pow(d / distance, power))

/** The regular grid of sub-lights of an area light (docs/scene-format.md, Version 2, Area lights), as POV-Ray's
  * `area_light a, b, samplesA, samplesB` without jitter: sub-light (i, j) sits at
  * location + a·(i/(samplesA − 1) − ½) + b·(j/(samplesB − 1) − ½), an axis with one sample adding
  * nothing. Lighting directions still point at the centre; only shadows come from the grid.
  *
  * @param a        the first axis, the grid's full extent along it
  * @param b        the second axis, not parallel to `a`
  * @param samplesA sub-lights along `a`, 1..64
  * @param samplesB sub-lights along `b`, 1..64
  */
final case class AreaLight(a: Vec3, b: Vec3, samplesA: Int, samplesB: Int):
  require(
    samplesA >= 1 && samplesA <= AreaLight.MaxSamples &&
      samplesB >= 1 && samplesB <= AreaLight.MaxSamples,
    s"an area light has 1 to ${AreaLight.MaxSamples} samples along each axis, got $samplesA × $samplesB"
  )
  require(a.cross(b).normalised.isDefined, s"the area light's axes $a and $b are zero or parallel")

  /** Sub-light (i, j)'s offset from the light's centre. */
  def offset(i: Int, j: Int): Vec3 =
    AreaLight.along(a, i, samplesA) + AreaLight.along(b, j, samplesB)

/** Limits and helpers of [[AreaLight]]. */
object AreaLight:
  /** The most sub-lights along one axis. */
  val MaxSamples: Int = 64

  private def along(axis: Vec3, i: Int, samples: Int): Vec3 =
    if samples > 1 then axis * (i.toDouble / (samples - 1) - 0.5) else Vec3.Zero

/** A shape with the surface that colours it.
  *
  * @param shape        the geometry
  * @param surface      the surface of the whole; for a CSG combination its `ior` is the interior
  *   of the whole object (docs/scene-format.md, Glass solids)
  * @param leafSurfaces for a CSG combination, the surface of each of its primitives, numbered
  *   depth-first as [[tracer.geometry.Csg]] numbers them; empty when every part shows `surface`
  */
final case class SceneObject(
    shape: Shape,
    surface: Surface = Surface(),
    leafSurfaces: Vector[Surface] = Vector.empty
):
  /** The surface shown by primitive `leaf` of the shape (0 for a shape that is not a combination). */
  def surfaceOf(leaf: Int): Surface =
    if leafSurfaces.isEmpty then surface else leafSurfaces(leaf)

  /** Every surface the object shows. */
  def surfaces: Vector[Surface] = if leafSurfaces.isEmpty then Vector(surface) else leafSurfaces

  /** True when some surface the object shows lets light through (its `transmit` above 0).
    *
    * Perf: [[surfaces]]' answer without its `Vector`, which `World` made for each of a scene's
    * objects, cold (the 5 MB scene's 20,000; docs/performance.md, round 21).
    */
  def transmits: Boolean =
    if leafSurfaces.isEmpty then surface.transmit > 0 else leafSurfaces.exists(_.transmit > 0)

/** How a surface reflects and lets through light (scene-format.md; the last six parameters are
  * version 2, each off by default, each rendering as POV-Ray's finish of the same name).
  *
  * @param diffuse    the diffuse coefficient, ≥ 0
  * @param reflection the mirror coefficient, 0..1
  * @param pigment    the colour of the surface, plain or from a texture
  * @param phong      the Phong highlight's strength, ≥ 0
  * @param phongSize  the Phong exponent, > 0: larger is a smaller, sharper highlight
  * @param specular   the Blinn highlight's strength, ≥ 0
  * @param roughness  the Blinn highlight's roughness, in (0, 1]: smaller is sharper
  * @param transmit   the share of light let through, 0..1
  * @param ior        the index of refraction inside, > 0: on a sphere, a closed solid or a CSG
  *   object at the top of a scene (the reader refuses it elsewhere); 1 on every other shape
  * @param emission   the radiance the surface sends out from its outward side (version 4's
  *   `<emission>`), each channel ≥ 0; black for a surface that does not glow
  */
final case class Surface(
    diffuse: Double = 1.0,
    reflection: Double = 0.0,
    pigment: Pigment = Pigment.Solid(Colour.White),
    phong: Double = 0.0,
    phongSize: Double = Surface.DefaultPhongSize,
    specular: Double = 0.0,
    roughness: Double = Surface.DefaultRoughness,
    transmit: Double = 0.0,
    ior: Double = 1.0,
    emission: Colour = Colour.Black
):
  /** True when the surface has a highlight (phong or specular). */
  val highlighted: Boolean = phong > 0 || specular > 0

  /** True when the surface glows (some channel of its emission is above 0).
    *
    * Perf: worked out once, not on every hit the shading colours (the emission's `max` was 0.3%
    * of a 4K mesh run's samples; docs/performance.md, round 50).
    */
  val emits: Boolean = emission.max > 0

/** The defaults of [[Surface]]'s version 2 parameters. */
object Surface:
  /** POV-Ray's default `phong_size`. */
  val DefaultPhongSize: Double = 40.0

  /** POV-Ray's default `roughness`. */
  val DefaultRoughness: Double = 0.05

/** Where a surface's own colour comes from. */
enum Pigment:
  /** One colour everywhere. */
  case Solid(colour: Colour)

  /** An image mapped onto the shape (rendering.md, Textures). */
  case Textured(texture: Texture)

  /** POV-Ray's `checker`: cubes of side `size` alternating between two colours in the space of
    * the element that carries the surface (docs/rendering.md, The checker pattern).
    *
    * @param first  the colour of the cube at the origin's corner (even cells)
    * @param second the colour of its neighbours (odd cells)
    * @param size   the side of a cube, > 0
    * @param space  the placements that take the pattern's space to the world: the placement of
    *   the element that carries the surface, then of each element enclosing it, innermost first
    */
  case Checker(first: Colour, second: Colour, size: Double = 1, space: List[Placement] = Nil)

/** The pattern rules of [[Pigment]]. */
object Pigment:
  /** How far a point may sit below a cell's boundary and still count as in the next cell: POV-Ray
    * adds its EPSILON to each coordinate before rounding down.
    */
  val CheckerTolerance: Double = 1e-10

  /** The colour of checker `c` at world point `p`: cell ⌊x + δ⌋ + ⌊y + δ⌋ + ⌊z + δ⌋ of the
    * point in the pattern's space scaled by 1/size, `first` when even, `second` when odd.
    */
  def checkerColour(c: Checker, p: Vec3): Colour =
    val q = c.space.foldRight(p)((placement, q) => placement.transform.pointBack(q)) * (1 / c.size)
    val cell =
      Math.floor(q.x + CheckerTolerance) + Math.floor(q.y + CheckerTolerance) +
        Math.floor(q.z + CheckerTolerance)
    if Math.floorMod(cell.toLong, 2L) == 0 then c.first else c.second

/** An image used as a texture, with the name it was loaded from (for messages).
  *
  * A point (u, v) in [0, 1]² takes the texel at column min(w − 1, ⌊u·w⌋) and row
  * min(h − 1, ⌊(1 − v)·h⌋): nearest neighbour, v = 1 at the top of the image. An 8- or 16-bit
  * image's texel is sample / maxval; a floating-point one's (version 4) is its value, above 1
  * included.
  */
final case class Texture(image: Texels, name: String = "texture"):
  /** The image's width in texels. */
  val width: Int = image match
    case b: Bitmap => b.width
    case r: Raster => r.width

  /** The image's height in texels. */
  val height: Int = image match
    case b: Bitmap => b.height
    case r: Raster => r.height

  /** The texel colour at texture coordinates (u, v). */
  def colourAt(u: Double, v: Double): Colour =
    val column = Math.min(width - 1, Math.max(0, Math.floor(u * width).toInt))
    val row    = Math.min(height - 1, Math.max(0, Math.floor((1 - v) * height).toInt))
    image match
      case b: Bitmap => b(column, row)
      case r: Raster => r(column, row)
