package tracer.render

import tracer.geometry.{Box, Csg, CsgOperation, Placed, Plane, Shape, Sphere, Triangle}
import tracer.image.{Bitmap, Colour, Encoding}
import tracer.math.{Placement, Vec3}
import tracer.scene.*
import tracer.testkit.Approx
import tracer.testkit.Scenes.{camera, matte}

/** The terms version 2 adds to shading (docs/rendering.md), checked on known values and on tiny
  * scenes whose pixels follow from the formulas: highlights, refraction, total internal
  * reflection, shadows through transmitting surfaces, area lights and output encoding.
  */
class Version2ShadingSuite extends munit.FunSuite with Approx with tracer.testkit.Images:

  private def render(scene: Scene, x: Int = 1, y: Int = 1, depth: Int = 5, samples: Int = 1) =
    Renderer.render(scene, CameraConfig(1, 1, 0.75, x, y, depth, samples = samples), threads = 2)

  private def samples(b: Bitmap, x: Int = 0, y: Int = 0) = (0 until 3).map(b.sample(x, y, _)).toList
  private def grey(level: Double)                        = List.fill(3)(Colour.quantise(level, 255))

  // A wall z = 0 facing the camera on −z; the single pixel's ray hits the origin head-on.
  private val wall                      = Plane.at(-Vec3.UnitZ, 0)
  private val facing                    = Vec3(0, 0, -1)
  private val view                      = Vec3(0, 0, 1)
  private def at(degrees: Double): Vec3 = // a unit direction on the camera's side, tilted in x
    Vec3(Math.sin(Math.toRadians(degrees)), 0, -Math.cos(Math.toRadians(degrees)))

  test("phong: phong · cos^phong-size of the angle between the view's mirror and the light"):
    val s = Surface(phong = 0.7, phongSize = 10)
    assertEqualsDouble(Shading.highlight(s, facing, view, facing), 0.7, 1e-12)
    assertEqualsDouble(
      Shading.highlight(s, facing, view, at(30)),
      0.7 * Math.pow(Math.cos(Math.toRadians(30)), 10),
      1e-12
    )
    assertEqualsDouble(Shading.highlight(s, facing, view, at(90)), 0.0, 1e-12)

  test("phong-size of 60 or more drops a highlight at cos 0.0008 or below, as POV-Ray does"):
    val angle = Math.toDegrees(Math.acos(0.0007))
    assertEquals(
      Shading.highlight(Surface(phong = 1, phongSize = 60), facing, view, at(angle)),
      0.0
    )
    assert(Shading.highlight(Surface(phong = 1, phongSize = 1), facing, view, at(angle)) > 0)

  test(
    "specular: specular · cos^(1/roughness) of the angle between the normal and the half-way vector"
  ):
    val s = Surface(specular = 0.5, roughness = 0.1)
    assertEqualsDouble(Shading.highlight(s, facing, view, facing), 0.5, 1e-12)
    // The half-way vector between the eye and a light 40° off lies 20° off the normal.
    assertEqualsDouble(
      Shading.highlight(s, facing, view, at(40)),
      0.5 * Math.pow(Math.cos(Math.toRadians(20)), 10),
      1e-12
    )

  // A camera inside a glass ball of ior 1.5, off its centre: the one pixel's ray leaves the
  // glass 30° off the normal and bends away from it (η = 1.5, to 48.6°), as POV-Ray's camera
  // inside an object does; a small glowing ball waits where that ray goes and nowhere near where
  // a ray taken as entering glass (η = 1/1.5, to 19.5°) would go.
  test("a camera inside glass looks out through it: its rays leave the glass, η = n/1"):
    val eye   = Vec3(0.5, 0, 0)
    val glass = SceneObject(
      Sphere(Vec3.Zero, 1),
      Surface(diffuse = 0, transmit = 1, ior = 1.5)
    )
    val exit   = Vec3(0.5, 0, Math.sqrt(0.75))
    val out    = Refraction.refract(Vec3.UnitZ, exit, 1.5).getOrElse(fail("no refraction"))
    val target = SceneObject(
      Sphere(exit + out * 4, 0.3),
      Surface(diffuse = 0, emission = Colour(0, 1, 0))
    )
    val scene = Scene(Camera(eye, eye + Vec3.UnitZ), Colour.Black, Nil, List(glass, target))
    assertEquals(World(scene).containing(eye), List(0))
    assertEquals(samples(render(scene)), List(0, 255, 0))

  // POV-Ray's InitRayContainerState lists every object around the camera, opaque ones too (each
  // has an interior), those of its bounding tree's unbounded part first.
  test("the objects around a point, clear or opaque: the later in the scene first, planes last"):
    val ball   = SceneObject(Sphere(Vec3.Zero, 2), Surface(transmit = 0.5, ior = 1.3))
    val inner  = SceneObject(Sphere(Vec3.Zero, 1), Surface(transmit = 0.9, ior = 1.5))
    val opaque = SceneObject(Sphere(Vec3.Zero, 3), Surface())
    val floor  = SceneObject(Plane.at(Vec3.UnitY, 4), Surface())
    val world  = World(Scene(camera, Colour.Black, Nil, List(ball, opaque, inner, floor)))
    assertEquals(world.containing(Vec3.Zero), List(2, 1, 0, 3))
    assertEquals(world.containing(Vec3(1.5, 0, 0)), List(1, 0, 3))
    assertEquals(world.containing(Vec3(5, 0, 0)), List(3))
    assertEquals(world.containing(Vec3(0, 5, 0)), Nil)

  test("a camera in a glass ball inside an opaque room later in the scene sees straight out"):
    // In POV-Ray the room is then the innermost object around the camera, so a ray leaving the
    // ball leaves an overlap (η = 1) and goes straight on, to the green emitter ahead; bent at
    // the ball's surface (η = 1.5, as from a ball alone) it would go to the red one.
    val eye   = Vec3(0.5, 0, -0.5)
    val glass = SceneObject(Sphere(Vec3.Zero, 1), Surface(transmit = 1, ior = 1.5))
    val room  = SceneObject(Box(Vec3(-5, -5, -5), Vec3(5, 5, 5)), Surface(diffuse = 0))
    def glow(x: Double, c: Colour) =
      SceneObject(Sphere(Vec3(x, 0, 3), 0.3), Surface(diffuse = 0, emission = c))
    val objects = List(glass, room, glow(0.5, Colour(0, 1, 0)), glow(-0.22, Colour(1, 0, 0)))
    val scene   = Scene(Camera(eye, eye + Vec3.UnitZ), Colour.Black, Nil, objects)
    assertEquals(World(scene).containing(eye), List(1, 0))
    assertEquals(samples(render(scene)), List(0, 255, 0))
    // The room first in the scene, the ball is the innermost and bends the ray.
    val first = scene.copy(objects = room :: glass :: objects.drop(2))
    assertEquals(samples(render(first)), List(255, 0, 0))

  // POV-Ray splits a union into its children, each with the union's interior, and lists that
  // interior once for each child around the camera.
  test("a glass union is around a point once for each of its parts that holds it"):
    def part(x: Double) = Sphere(Vec3(x, 0, 0), 0.8)
    val nested          = Csg(CsgOperation.Union, Vector(part(0.3), part(0.5)))
    val union           = Csg(CsgOperation.Union, Vector(part(-0.3), nested))
    val placed          = Placed(union, Placement(translate = Vec3(0, 0, 10)))
    val cut             = Csg(CsgOperation.Intersection, Vector(part(-0.3), part(0.3)))
    val glass           = Surface(transmit = 0.9, ior = 1.4)
    val world           = World(
      Scene(camera, Colour.Black, Nil, List(SceneObject(union, glass), SceneObject(cut, glass)))
    )
    assertEquals(world.containing(Vec3.Zero), List(1, 0, 0, 0))
    assertEquals(world.containing(Vec3(-0.9, 0, 0)), List(0))
    assertEquals(world.containing(Vec3(2, 0, 0)), Nil)
    assertEquals(World.partsHolding(placed, Vec3(0.4, 0, 10)), 3)
    assertEquals(World.partsHolding(placed, Vec3(0.4, 0, 0)), 0)

  test("leaving an object listed twice leaves the ray inside it, η = 1, as POV-Ray's list does"):
    val ior = Map(0 -> 1.4, 1 -> 1.2)
    assertEquals(Refraction.cross(List(0, 0), 0, ior), (1.0, List(0)))
    assertEquals(Refraction.cross(List(0, 1, 0), 0, ior), (1.0, List(0, 1)))
    assertEquals(Refraction.cross(List(1, 0, 0), 0, ior), (1.0, List(1, 0)))
    assertEquals(Refraction.cross(List(0, 0), 1, ior), (1.4 / 1.2, List(1, 0, 0)))

  // A camera inside both spheres of a glass union of ior 1.4: its one ray crosses the small
  // sphere's surface inside the large one (the union still around it: straight on), then leaves
  // the large one 30° off the normal, bending once as leaving glass, to a glowing ball. Listed
  // once, the ray would bend leaving glass at the inner surface and again entering at the outer.
  test("a camera inside two parts of a glass union bends once, where its ray leaves the union"):
    val eye    = Vec3(0.5, 0, 0)
    val union  = Csg(CsgOperation.Union, Vector(Sphere(Vec3.Zero, 1), Sphere(Vec3(0.2, 0, 0), 0.5)))
    val glass  = SceneObject(union, Surface(diffuse = 0, transmit = 1, ior = 1.4))
    val exit   = Vec3(0.5, 0, Math.sqrt(0.75))
    val out    = Refraction.refract(Vec3.UnitZ, exit, 1.4).getOrElse(fail("no refraction"))
    val target = SceneObject(
      Sphere(exit + out * 4, 0.3),
      Surface(diffuse = 0, emission = Colour(0, 1, 0))
    )
    val scene = Scene(Camera(eye, eye + Vec3.UnitZ), Colour.Black, Nil, List(glass, target))
    assertEquals(World(scene).containing(eye), List(0, 0))
    assertEquals(samples(render(scene)), List(0, 255, 0))

  // One face in the plane z = 0 over the whole picture, seen from −z, whose corners' normals all
  // lean 60° off its own towards +x.
  private val lean        = Vec3(Math.sin(Math.toRadians(60)), 0, -Math.cos(Math.toRadians(60)))
  private val leaningFace =
    Triangle(
      Vec3(-10, -10, 0),
      Vec3(10, -10, 0),
      Vec3(0, 10, 0),
      cornerNormals = Some((lean, lean, lean))
    )

  // A smooth face whose corners' normals lean 60° off its own: the camera's ray, mirrored about
  // that normal, leaves behind the face's plane. POV-Ray's reflected ray starts on the surface and
  // passes the face to the sky; one started on the camera's side would meet the face at once.
  test("a smooth face's reflection that leaves behind its plane passes the face to the sky"):
    val face  = leaningFace
    val sky   = Colour(0.2, 0.4, 0.6)
    val scene = Scene(
      Camera(Vec3(0, 0, -3), Vec3.Zero),
      sky,
      Nil,
      List(SceneObject(face, Surface(diffuse = 0, reflection = 1)))
    )
    assertEquals(samples(render(scene)), List(0.2, 0.4, 0.6).map(Colour.quantise(_, 255)))

  // The same leaning face lit by a point light behind its own plane that the leaning normal
  // faces: POV-Ray's shadow ray starts on the surface and passes the face, so the light counts;
  // one started on the camera's side would be blocked by the face itself.
  test("a smooth face is lit by a light behind its plane that its leaning normal faces"):
    val face  = leaningFace
    val lamp  = Vec3(10, 0, 2)
    val scene = Scene(
      Camera(Vec3(0, 0, -3), Vec3.Zero),
      Colour.Black,
      List(Light(lamp)),
      List(SceneObject(face, Surface(diffuse = 1)))
    )
    val s0 = Vec3(0, 0, -Shading.Epsilon)
    assertEquals(samples(render(scene)), grey(lean.dot((lamp - s0).normalisedOr(Vec3.UnitX))))

  // The leaning face as a leaf of a placed union (read whole: one with ior): it shades with its
  // own corners' normals, turned by the placement, not the face's, so its reflection passes it
  // as the face's alone does.
  test("a smooth face inside a placed union shades with its own leaning normal"):
    val far    = Sphere(Vec3(0, 0, -50), 1)
    val united = Placed(
      Csg(CsgOperation.Union, Vector(leaningFace, far)),
      Placement(translate = Vec3(0, 0, 0.5))
    )
    val sky                = Colour(0.2, 0.4, 0.6)
    def seen(shape: Shape) = samples(
      render(
        Scene(
          Camera(Vec3(0, 0, -3), Vec3.Zero),
          sky,
          Nil,
          List(SceneObject(shape, Surface(diffuse = 0, reflection = 1)))
        )
      )
    )
    assertEquals(seen(united), List(0.2, 0.4, 0.6).map(Colour.quantise(_, 255)))
    assertEquals(seen(united), seen(leaningFace))

  // As above with a small area light there: each of its sub-lights is sought through the face,
  // so every one reaches the point, as from a point light at its centre (POV-Ray's sub-lights'
  // shadow rays start on the surface too).
  test("a smooth face is lit by an area light behind its plane as by a point light there"):
    val lamp              = Vec3(10, 0, 2)
    def lit(light: Light) = samples(
      render(
        Scene(
          Camera(Vec3(0, 0, -3), Vec3.Zero),
          Colour.Black,
          List(light),
          List(SceneObject(leaningFace, Surface(diffuse = 1)))
        )
      )
    )
    val small = AreaLight(Vec3(0, 0.01, 0), Vec3(0, 0, 0.01), 2, 2)
    assertEquals(lit(Light(lamp, area = Some(small))), lit(Light(lamp)))
    assert(lit(Light(lamp)).head > 0)

  // A flat wall z = 0 under an area light whose centre is in front of it and whose far
  // sub-lights lie behind its plane. POV-Ray's sub-lights' shadow rays start on the surface and
  // pass it, so every sub-light reaches the point and the wall is lit as by a point light at the
  // centre; rays from S0 on the camera's side would lose the two behind to the wall itself.
  // Behind a ball the far sub-lights stay dark: their rays meet the ball's far side.
  test("a flat face is lit by every sub-light of an area light, those behind its plane too"):
    val lamp                                   = Vec3(0, 0, -0.2)
    val wide                                   = AreaLight(Vec3(1, 0, 0), Vec3(0, 0, 1), 2, 2)
    def lit(light: Light, shape: Shape = wall) = samples(
      render(
        Scene(
          Camera(Vec3(0, 0, -3), Vec3.Zero),
          Colour.Black,
          List(light),
          List(SceneObject(shape, Surface(diffuse = 1, pigment = Pigment.Solid(Colour.grey(0.5)))))
        )
      )
    )
    assertEquals(lit(Light(lamp, area = Some(wide))), lit(Light(lamp)))
    assertEquals(lit(Light(lamp)), grey(0.5))
    // A ball of radius 1 whose nearest point is the origin: the sub-lights at z = 0.3 lie behind
    // the tangent plane and inside the ball, so their rays end before its far side: still lit.
    // Those of a light behind the ball's far side (centre 2.5 beyond) are blocked by the ball.
    val ball = Sphere(Vec3(0, 0, 1), 1)
    assertEquals(lit(Light(lamp, area = Some(wide)), ball), lit(Light(lamp), ball))
    val deep = AreaLight(Vec3(0.5, 0, 0), Vec3(0, 0, 5), 2, 2)
    assertEquals(lit(Light(lamp, area = Some(deep)), ball), grey(0.25))

  test("phong-size and roughness alone change nothing"):
    val plain = Surface(phongSize = 5, roughness = 0.5)
    assertEquals(Shading.highlight(plain, facing, view, at(10)), 0.0)

  test("a highlight adds the light's colour, untinted, on top of the diffuse term"):
    val light = Light(Vec3(0, 0, -10), Colour(0.5, 0.5, 0.25))
    val red   = Surface(0.5, 0, Pigment.Solid(Colour(1, 0, 0)), phong = 0.4, specular = 0.2)
    val b     = render(Scene(camera, lights = List(light), objects = List(SceneObject(wall, red))))
    // Diffuse C ⊙ L · 0.5 = (0.25, 0, 0); highlights (0.4 + 0.2) · L = (0.3, 0.3, 0.15).
    assertEquals(samples(b), List(0.55, 0.3, 0.15).map(Colour.quantise(_, 255)))

  test("a highlight peaks where the normal halves the angle between the eye and the light"):
    val light = Light(Vec3(3, 0, -5))
    val shiny = Surface(diffuse = 0, phong = 1, phongSize = 200)
    val scene =
      Scene(camera, lights = List(light), objects = List(SceneObject(Sphere(Vec3.Zero, 1), shiny)))
    val config = CameraConfig(1, 1, 0.75, 81, 61)
    val image  = Renderer.render(scene, config)
    val (x, y) =
      (for x <- 0 until 81; y <- 0 until 61 yield (x, y)).maxBy((x, y) => image.sample(x, y, 0))
    // The peak point P on the sphere: its normal P bisects the directions to the eye and light.
    val peak = Iterator
      .iterate(Vec3(0, 0, -1)) { p =>
        ((camera.location - p) / (camera.location - p).length + (light.location - p) / (light.location - p).length)
          .normalisedOr(p)
      }
      .drop(200)
      .next()
    val toPeak  = (peak - camera.location) / (peak - camera.location).length
    val project = Projection(camera, config)
    val nearest = (for x <- 0 until 81; y <- 0 until 61
    yield (x, y)).maxBy((x, y) => project.ray(x + 0.5, y + 0.5).direction.dot(toPeak))
    assertEquals((x, y), nearest)

  test("Snell's law: sin θ₂ = η sin θ₁, and a ray along the normal goes straight on"):
    val eta = 1 / 1.5
    val in  = Vec3(Math.sin(0.6), 0, Math.cos(0.6))
    val out = Refraction.refract(in, facing, eta).getOrElse(fail("no refraction"))
    assertEqualsDouble(out.length, 1.0, 1e-12)
    assertEqualsDouble(out.x, eta * Math.sin(0.6), 1e-12)
    assert(out.z > 0)
    assertVecClose(Refraction.refract(view, facing, eta).get, view, 1e-15)

  test("total internal reflection: no refracted ray past the critical angle, one just before it"):
    val critical            = Math.asin(1 / 1.5) // leaving glass (η = 1.5)
    def from(angle: Double) = Vec3(Math.sin(angle), 0, Math.cos(angle))
    assertEquals(Refraction.refract(from(critical + 1e-6), facing, 1.5), None)
    assert(Refraction.refract(from(critical - 1e-6), facing, 1.5).isDefined)

  test("entering, nesting, leaving: the ratio of indices follows the objects the ray is inside"):
    val ior = Map(0 -> 1.5, 1 -> 1.2, 2 -> 1.0)
    assertEquals(Refraction.cross(Nil, 0, ior), (1 / 1.5, List(0)))
    assertEquals(Refraction.cross(List(0), 1, ior), (1.5 / 1.2, List(1, 0)))
    assertEquals(Refraction.cross(List(1, 0), 1, ior), (1.2 / 1.5, List(0)))
    assertEquals(Refraction.cross(List(0), 0, ior), (1.5, Nil))
    assertEquals(Refraction.cross(List(1, 0), 0, ior), (1.0, List(1))) // leaving an overlap

  // A clear glass ball in front of a white wall lit from behind the eye: the central ray passes
  // straight through the ball's centre (it meets both surfaces along the normal).
  private val behindEye                           = Light(Vec3(0, 0, -10))
  private val farWall                             = matte(Plane.at(-Vec3.UnitZ, -3))
  private def ball(transmit: Double, ior: Double) =
    SceneObject(Sphere(Vec3.Zero, 1), Surface(diffuse = 0, transmit = transmit, ior = ior))

  test("through a sphere's centre: transmit² of the wall, itself in a shadow dimmed by transmit²"):
    val scene = Scene(camera, lights = List(behindEye), objects = List(farWall, ball(0.8, 1.5)))
    // Two surfaces each way: 0.8 · 0.8 of the wall, lit through the ball at 0.8 · 0.8.
    assertEquals(samples(render(scene)), grey(0.8 * 0.8 * 0.8 * 0.8))

  test("refraction bends: a clear ball of index 1 is unseen; of index 1.5, it changes only itself"):
    val stripe =
      matte(Triangle(Vec3(-0.3, -5, -2.9), Vec3(0.3, -5, -2.9), Vec3(0, 5, -2.9)), Colour(1, 0, 0))
    def image(balls: List[SceneObject]) = render(
      Scene(camera, lights = List(behindEye), objects = List(farWall, stripe) ++ balls),
      x = 40,
      y = 30
    )
    val without  = image(Nil)
    val straight = image(List(ball(1, 1.0)))
    val bent     = image(List(ball(1, 1.5)))
    // The pixels whose primary ray meets the ball, and the others.
    val projection        = Projection(camera, CameraConfig(1, 1, 0.75, 40, 30))
    val pixels            = for y <- 0 until 30; x <- 0 until 40 yield (x, y)
    val (inside, outside) = pixels.partition((x, y) =>
      Shape.distance(Sphere(Vec3.Zero, 1), projection.ray(x + 0.5, y + 0.5)).isFinite
    )
    assert(inside.size > 100 && outside.size > 100, s"${inside.size} inside")
    def differ(a: Bitmap, b: Bitmap, x: Int, y: Int, by: Int) =
      samples(a, x, y).zip(samples(b, x, y)).exists((p, q) => Math.abs(p - q) > by)
    // Index 1 bends nothing: the clear ball shows what is behind it, as if it were not there.
    assertEquals(pixels.filter(differ(straight, without, _, _, 1)), Vector.empty)
    // Index 1.5 bends the rays through the ball alone: outside its outline nothing changes, and
    // inside it the world behind is moved (the stripe's shadow on the wall, the wall's shading).
    assertEquals(outside.filter(differ(bent, without, _, _, 0)), Vector.empty)
    // Inside it, each pixel shows what Snell's law, worked out here apart from the renderer,
    // says its ray meets: the red stripe in front of the ball, or after bending in and out of it
    // the lit wall or the stripe's shadow on the wall (cast by straight shadow rays). Pixels whose
    // answer lies within 0.02 of an edge are left out.
    val predicted =
      inside.flatMap((x, y) => behindGlass(projection.ray(x + 0.5, y + 0.5)).map((x, y) -> _))
    assert(predicted.size > inside.size * 3 / 4, s"${predicted.size} of ${inside.size} decided")
    // Both the stripe and the wall are seen through it, so a wrong bending shows.
    assert(Set(Seen.Stripe, Seen.Wall).subsetOf(predicted.map(_._2).toSet), predicted.map(_._2))
    val wrong = predicted.filter { case ((x, y), seen) =>
      val List(r, g, _) = samples(bent, x, y)
      seen match
        case Seen.Stripe => !(r > 200 && g == 0)
        case Seen.Wall   => !(r > 200 && g > 200)
        case Seen.Shadow => !(r == 0 && g == 0)
    }
    assertEquals(wrong.map((p, seen) => (p, seen, samples(bent, p._1, p._2))), Vector.empty)

  /** What a ray meets in the scene above: the stripe at z = −2.9 in front of the unit glass ball
    * of index 1.5, else, bent through the ball, the wall at z = 3, in the stripe's shadow or not
    * (the light at (0, 0, −10)); `None` within 0.02 of an edge. Snell's law in vector form,
    * written out apart from [[Refraction]].
    */
  private def behindGlass(ray: tracer.geometry.Ray): Option[Seen] =
    def bend(d: Vec3, n: Vec3, eta: Double) = // n faces the incoming ray
      val cos = -d.dot(n)
      d * eta + n * (eta * cos - Math.sqrt(1 - eta * eta * (1 - cos * cos)))
    val o             = ray.origin
    val d             = ray.direction.normalisedOr(ray.direction)
    val b             = o.dot(d)
    val t1            = -b - Math.sqrt(b * b - (o.dot(o) - 1))
    val p1            = o + d * t1
    val in            = bend(d, p1, 1 / 1.5)
    val p2            = p1 + in * (-2 * p1.dot(in))
    val out           = bend(in, -p2, 1.5)
    def at(z: Double) = p2 + out * ((z - p2.z) / out.z)
    val front         = o + d * ((-2.9 - o.z) / d.z)
    // Signed distances to the stripe's three edges, positive inside.
    def stripe(p: Vec3): Double =
      val corners = List((-0.3, -5.0), (0.3, -5.0), (0.0, 5.0))
      corners.indices.map { i =>
        val (ux, uy) = corners(i)
        val (vx, vy) = corners((i + 1) % 3)
        val (wx, wy) = corners((i + 2) % 3)
        val (nx, ny) = (uy - vy, vx - ux)
        val length   = Math.hypot(nx, ny)
        val side     = Math.signum((wx - ux) * nx + (wy - uy) * ny)
        side * ((p.x - ux) * nx + (p.y - uy) * ny) / length
      }.min
    val margin   = 0.02
    val onStripe = stripe(front)
    if Math.abs(onStripe) < margin then None
    else if onStripe > 0 then Some(Seen.Stripe)
    else
      val wall   = at(3)
      val shadow = stripe(wall + (Vec3(0, 0, -10) - wall) * (5.9 / 13))
      if Math.abs(shadow) < margin then None
      else if shadow > 0 then Some(Seen.Shadow)
      else Some(Seen.Wall)

  test("transmitted rays count against the depth where they bend, not where they go straight on"):
    val scene = (ior: Double) =>
      Scene(camera, lights = List(behindEye), objects = List(farWall, ball(0.8, ior)))
    // Index 1: two straight crossings are free, so depth 0 still forbids them (POV-Ray's rule).
    assertEquals(samples(render(scene(1.0), depth = 0)), grey(0))
    assertEquals(samples(render(scene(1.0), depth = 1)), grey(0.8 * 0.8 * 0.8 * 0.8))
    // Index 1.5: each of the two bends uses one level.
    assertEquals(samples(render(scene(1.5), depth = 1)), grey(0))
    assertEquals(samples(render(scene(1.5), depth = 2)), grey(0.8 * 0.8 * 0.8 * 0.8))

  test("a transmitting surface keeps (1 − transmit) of its diffuse light"):
    val light = Light(Vec3(0, 0, -10))
    val glass = SceneObject(wall, Surface(diffuse = 0.8, transmit = 0.25))
    assertEquals(
      samples(render(Scene(camera, lights = List(light), objects = List(glass)))),
      grey(0.6)
    )

  test("a light behind a transmitting surface does not light it"):
    val light = Light(Vec3(0, 0, 10))
    val glass = SceneObject(wall, Surface(diffuse = 1, transmit = 0.5))
    assertEquals(
      samples(render(Scene(camera, lights = List(light), objects = List(glass)))),
      grey(0)
    )

  // Shadows of a half-plane blocker at height 2 (covering x < 0) under an area light at height 4
  // with five sub-lights on x = −1 … 1: a floor point at x = p sees sub-light s unless p + s < 0,
  // so the penumbra runs from x = −1 (umbra) to x = 1 (full light).
  private val blocker          = matte(Triangle(Vec3(0, 2, -50), Vec3(0, 2, 50), Vec3(-50, 2, 0)))
  private val area             = AreaLight(Vec3(2, 0, 0), Vec3(0, 0, 1), 5, 1)
  private def share(x: Double) =
    val light = Light(Vec3(0, 4, 0), area = Some(area))
    val world = World(Scene(camera, lights = List(light), objects = List(blocker)))
    Shadows(world, world.newQuery()).area(Vec3(x, 0, 0), 0)

  test("a shadow ray through a CSG object is dimmed by the transmit of each leaf it crosses"):
    // A union kept whole (as one with an ior is) of two balls on the way to the light, their own
    // surfaces transmitting 0.5 and 0.25 and the whole's 0.9: the ray crosses each ball twice.
    val union = SceneObject(
      Csg(CsgOperation.Union, Vector(Sphere(Vec3(0, 0, 2), 0.5), Sphere(Vec3(0, 0, 5), 0.5))),
      Surface(transmit = 0.9),
      Vector(Surface(transmit = 0.5), Surface(transmit = 0.25))
    )
    val world   = World(Scene(camera, objects = List(union)))
    val shadows = Shadows(world, world.newQuery())
    assertEqualsDouble(shadows.point(Vec3.Zero, Vec3.UnitZ, 10), 0.5 * 0.5 * 0.25 * 0.25, 1e-15)
    assertEqualsDouble(shadows.point(Vec3(0, 0, 3.5), Vec3.UnitZ, 10), 0.25 * 0.25, 1e-15)
    assertEqualsDouble(shadows.point(Vec3(0, 0, 3.5), -Vec3.UnitZ, 10), 0.5 * 0.5, 1e-15)
    // From inside the near ball: its far side, then the far ball.
    assertEqualsDouble(shadows.point(Vec3(0, 0, 2), Vec3.UnitZ, 10), 0.5 * 0.25 * 0.25, 1e-15)

  test("an area light's penumbra spans exactly what the grid's end lights see past the blocker"):
    assertEquals(share(1.01), 1.0)
    assertEquals(share(-1.01), 0.0)
    val inside = List(-0.9, -0.4, 0.1, 0.6, 0.9).map(share)
    assert(inside.forall(s => s > 0 && s < 1), inside)
    assertEquals(inside, inside.sorted)

  test("an area light's samples are averaged as POV-Ray's four-corner subdivision weighs them"):
    // Five sub-lights split as (0..2)(2..4), then (0..1)(1..2)(2..3)(3..4): the weights are
    // 1/8, 1/4, 1/4, 1/4, 1/8. At x = 0.5 only the sub-light at x = −1 is hidden.
    assertEqualsDouble(share(0.5 + 1e-9), 1 - 1.0 / 8, 1e-12)
    // At x = 0.25 the sub-lights at −1 and −0.5 are hidden.
    assertEqualsDouble(share(0.25 + 1e-9), 1 - 1.0 / 8 - 1.0 / 4, 1e-12)

  test("sub-lights sit on a full regular grid centred on the light"):
    assertEquals(area.offset(0, 0), Vec3(-1, 0, 0))
    assertEquals(area.offset(2, 0), Vec3.Zero)
    assertEquals(area.offset(4, 0), Vec3(1, 0, 0))
    assertEquals(AreaLight(Vec3(2, 0, 0), Vec3(0, 0, 2), 1, 3).offset(0, 0), Vec3(0, 0, -1))

  test("an area light of one sample is the point light, but for the light-behind rule"):
    val point = Light(Vec3(-2, 3, -4))
    val one   = point.copy(area = Some(AreaLight(Vec3(1, 0, 0), Vec3(0, 1, 0), 1, 1)))
    val objs  = List(matte(Sphere(Vec3.Zero, 1)), matte(Plane.at(Vec3.UnitY, -1)))
    val size  = (x: Scene) => render(x, x = 40, y = 30)
    // Just past the sphere's terminator (rn · Sd < 0) S0, ε above the surface, still sees a point
    // light over the sphere's own curve for up to √(2ε/r) radians: |rn · Sd| lights it a little
    // (course rule), where the area light's light-behind rule (POV-Ray's) leaves it dark.
    assertImageClose(
      size(Scene(camera, lights = List(one), objects = objs)),
      size(Scene(camera, lights = List(point), objects = objs)),
      "one-sample area light",
      tolerance = Math.ceil(255 * Math.sqrt(2 * Shading.Epsilon)).toInt
    )

  test("sRGB and gamma encoding of known values"):
    assertEquals(Encoding.Srgb.encode(0.0), 0.0)
    assertEqualsDouble(Encoding.Srgb.encode(1.0), 1.0, 1e-12)
    assertEqualsDouble(Encoding.Srgb.encode(0.0031308), 0.0031308 * 12.92, 1e-12)
    assertEqualsDouble(Encoding.Srgb.encode(0.5), 1.055 * Math.pow(0.5, 1 / 2.4) - 0.055, 1e-12)
    assertEqualsDouble(Encoding.Power(2.2).encode(0.5), Math.pow(0.5, 1 / 2.2), 1e-12)
    assertEquals(Encoding.parse("1"), Right(Encoding.Linear))
    assertEquals(Encoding.parse("SRGB"), Right(Encoding.Srgb))
    assert(Encoding.parse("0").isLeft && Encoding.parse("-2").isLeft && Encoding.parse("x").isLeft)

  test("the encoding applies after the colour is brought into range, and after averaging samples"):
    val light = Light(Vec3(0, 0, -10), Colour(2, 1, 0.5))
    val scene = Scene(camera, lights = List(light), objects = List(matte(wall)))
    val srgb  = (n: Int) =>
      Renderer.render(scene, CameraConfig(1, 1, 0.75, 1, 1, samples = n, encoding = Encoding.Srgb))
    // (2, 1, 0.5) is brought to (1, 0.5, 0.25), then each channel encoded.
    assertEquals(
      samples(srgb(1)),
      List(1.0, 0.5, 0.25).map(c => Colour.quantise(Encoding.Srgb.encode(c), 255))
    )
    assertEquals(samples(srgb(3)), samples(srgb(1)))

  test("quick mode ignores every version 2 attribute"):
    val v2 = Surface(0.5, 0.3, Pigment.Solid(Colour(0.2, 0.6, 0.9)), 0.9, 20, 0.5, 0.2, 0.7, 1.5)
    val v1 = Surface(0.5, 0.3, Pigment.Solid(Colour(0.2, 0.6, 0.9)))
    def scene(s: Surface, area: Option[AreaLight]) = Scene(
      camera,
      lights = List(Light(Vec3(-2, 3, -4), area = area)),
      objects = List(SceneObject(Sphere(Vec3.Zero, 1), s), matte(Plane.at(Vec3.UnitY, -1)))
    )
    val quick =
      (s: Scene) => Renderer.render(s, CameraConfig(1, 1, 0.75, 40, 30, mode = ShadingMode.Quick))
    assertEquals(
      quick(scene(v2, Some(AreaLight(Vec3(1, 0, 0), Vec3(0, 1, 0), 3, 3)))),
      quick(scene(v1, None))
    )

/** What a ray through the glass ball of [[Version2ShadingSuite]] meets behind it. */
private enum Seen:
  /** The red stripe in front of the wall. */
  case Stripe

  /** The wall, lit. */
  case Wall

  /** The wall in the stripe's shadow. */
  case Shadow
