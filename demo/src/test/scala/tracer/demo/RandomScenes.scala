package tracer.demo

import java.util.Locale
import org.scalacheck.Gen
import org.scalacheck.rng.Seed
import tracer.demo.Models.Model
import tracer.math.Vec3

/** Random scenes of versions 1 to 3 (and version 4's fade) for cross-checks against another
  * renderer: a camera looking into a few units around the origin, one to three point or area
  * lights, sometimes a floor, and one to five objects — spheres, boxes, cylinders, cones (open or
  * closed), tori, triangles, the OBJ models of [[models]] (smooth, faceted or `auto`), and unions,
  * intersections and differences of them nested up to two deep, placed, with surfaces drawn from
  * every finish: diffuse, reflection, Phong, Blinn, transmit with or without an index of
  * refraction, checkers. Each scene comes with the recursion depth it is to be rendered at.
  *
  * Image textures are left out (the POV-Ray twin carries none); triangles and meshes join unions
  * only (they have no inside), at any depth, so some cut. A combination at the top that holds a
  * clear surface has a surface of its own that lets a thousandth through, which keeps POV-Ray's
  * shadow cache, whose picture depends on the order of its pixels, out of the comparison.
  */
object RandomScenes:

  /** A scene's XML text and the depth (`-r`) to render it at. */
  final case class RandomScene(xml: String, depth: Int)

  /** The scene of `seed`: the same text for the same seed, on every run. */
  def scene(seed: Long): RandomScene =
    generator.pureApply(Gen.Parameters.default, Seed(seed))

  /** The models scenes name (`models/NAME`), as OBJ text: an icosphere of 80 faces with its exact
    * normals, without normals, and with normals on two faces in three; a cube of quads and a
    * wavy height field of quads, both without normals; a pyramid of eight sides whose normals
    * lean as a cone's.
    */
  val models: Map[String, String] =
    val ico = Models.icosphere(1)
    Map(
      "ico.obj"       -> Models.obj(ico, "ico"),
      "ico_bare.obj"  -> Models.obj(ico.copy(uvs = Vector.empty, normals = Vector.empty), "bare"),
      "ico_mixed.obj" -> mixed(ico),
      "cube.obj"      -> Models.obj(cube, "cube"),
      "wave.obj"      -> Models.obj(wave(6), "wave"),
      "spire.obj"     -> Models.obj(spire(8), "spire")
    )

  /** The icosphere's OBJ text with normals on the faces whose number is not a multiple of 3. */
  private def mixed(model: Model): String =
    val lines   = Models.obj(model.copy(uvs = Vector.empty), "mixed").linesIterator.toVector
    val numbers = lines.scanLeft(-1)((k, line) => if line.startsWith("f ") then k + 1 else k).tail
    lines
      .zip(numbers)
      .map((line, k) =>
        if line.startsWith("f ") && k % 3 == 0 then line.replaceAll("//\\d+", "") else line
      )
      .mkString("", "\n", "\n")

  private def cube: Model =
    val corners = for x <- Vector(-0.5, 0.5); y <- Vector(-0.5, 0.5); z <- Vector(-0.5, 0.5)
    yield Vec3(x, y, z)
    def at(x: Int, y: Int, z: Int) = x * 4 + y * 2 + z + 1
    Model(
      corners,
      Vector.empty,
      Vector(
        Seq(at(0, 0, 0), at(0, 1, 0), at(1, 1, 0), at(1, 0, 0)),
        Seq(at(0, 0, 1), at(1, 0, 1), at(1, 1, 1), at(0, 1, 1)),
        Seq(at(0, 0, 0), at(0, 0, 1), at(0, 1, 1), at(0, 1, 0)),
        Seq(at(1, 0, 0), at(1, 1, 0), at(1, 1, 1), at(1, 0, 1)),
        Seq(at(0, 0, 0), at(1, 0, 0), at(1, 0, 1), at(0, 0, 1)),
        Seq(at(0, 1, 0), at(0, 1, 1), at(1, 1, 1), at(1, 1, 0))
      )
    )

  private def wave(n: Int): Model =
    val points = for i <- 0 to n; j <- 0 to n
    yield Vec3(-1 + 2.0 * i / n, 0.25 * Math.sin(2.1 * i) * Math.cos(1.7 * j), -1 + 2.0 * j / n)
    def at(i: Int, j: Int) = i * (n + 1) + j + 1
    val faces              = for i <- 0 until n; j <- 0 until n
    yield Seq(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j))
    Model(points.toVector, Vector.empty, faces.toVector)

  private def spire(sides: Int): Model =
    val angles  = Vector.tabulate(sides)(k => 2 * Math.PI * k / sides)
    val rim     = angles.map(a => Vec3(0.6 * Math.cos(a), 0, 0.6 * Math.sin(a)))
    val leaning = angles.map(a => Vec3(Math.cos(a), 0.6, Math.sin(a)) / Math.sqrt(1.36))
    Model(
      Vec3(0, 1, 0) +: rim,
      Vector.empty,
      Vector.tabulate(sides)(k => Seq(1, 2 + (k + 1) % sides, 2 + k)),
      Vec3(0, 1, 0) +: leaning
    )

  // The generators, from numbers up.

  /** A number as the scenes write it: three decimals at most, trailing zeros dropped. */
  private def n(x: Double): String =
    if Math.abs(x) < 5e-4 then "0"
    else String.format(Locale.ROOT, "%.3f", x).replaceAll("0+$", "").stripSuffix(".")

  private def vec(name: String, v: Vec3) = s"""<$name x="${n(v.x)}" y="${n(v.y)}" z="${n(v.z)}"/>"""

  private def colour(c: Vec3, name: String = "colour") =
    s"""<$name r="${n(c.x)}" g="${n(c.y)}" b="${n(c.z)}"/>"""

  private def within(lo: Double, hi: Double): Gen[Vec3] =
    Gen.zip(Gen.choose(lo, hi), Gen.choose(lo, hi), Gen.choose(lo, hi)).map(Vec3(_, _, _))

  private def chance(p: Double): Gen[Boolean] = Gen.choose(0.0, 1.0).map(_ < p)

  private def maybe(p: Double, text: Gen[String]): Gen[String] =
    chance(p).flatMap(if _ then text else Gen.const(""))

  private val direction: Gen[Vec3] =
    within(-1, 1).retryUntil(v => v.length > 0.1 && v.length <= 1).map(v => v / v.length)

  private def attribute(name: String, value: Gen[Double]) = value.map(v => s""" $name="${n(v)}"""")

  /** A surface: each finish with its own chance; `ior` whether an index of refraction may come
    * with transmit (not on open shapes, which have no inside).
    */
  private def surface(ior: Boolean): Gen[String] =
    for
      diffuse    <- maybe(0.85, attribute("diffuse", Gen.choose(0.5, 1.0)))
      reflection <- maybe(0.3, attribute("reflection", Gen.choose(0.1, 0.5)))
      phong      <- maybe(
        0.3,
        for
          p    <- attribute("phong", Gen.choose(0.1, 0.6))
          size <- maybe(
            0.7,
            attribute("phong-size", Gen.oneOf(Gen.choose(2.0, 60.0), Gen.choose(60.0, 300.0)))
          )
        yield p + size
      )
      specular <- maybe(
        0.2,
        for
          s <- attribute("specular", Gen.choose(0.1, 0.5))
          r <- maybe(0.7, attribute("roughness", Gen.choose(0.005, 0.3)))
        yield s + r
      )
      transmit <- maybe(
        0.22,
        for
          t <- attribute("transmit", Gen.choose(0.3, 0.95))
          i <- if ior then maybe(0.6, attribute("ior", Gen.choose(1.1, 2.0))) else Gen.const("")
        yield t + i
      )
      checker <- chance(0.3)
      body    <-
        if checker then
          for
            size <- Gen.choose(0.15, 1.0)
            a    <- within(0.2, 1.0)
            b    <- within(0.2, 1.0)
          yield s"""<checker size="${n(size)}">${colour(a)}${colour(b)}</checker>"""
        else within(0.25, 1.0).map(colour(_))
    yield s"<surface$diffuse$reflection$phong$specular$transmit>$body</surface>"

  /** A placement: a scale attribute and rotate and translate elements in either order. */
  private def placement(p: Double): Gen[(String, String)] =
    chance(p).flatMap(placed =>
      if !placed then Gen.const(("", ""))
      else
        for
          scale     <- maybe(0.5, attribute("scale", Gen.choose(0.5, 1.6)))
          rotate    <- maybe(0.7, within(-90, 90).map(vec("rotate", _)))
          translate <- maybe(0.7, within(-1, 1).map(vec("translate", _)))
          swap      <- chance(0.5)
        yield (scale, if swap then translate + rotate else rotate + translate)
    )

  /** A surface of its own, certainly at the top of the scene and sometimes inside a combination
    * (which otherwise passes its own down).
    */
  private def ownSurface(top: Boolean, ior: Boolean): Gen[String] =
    if top then surface(ior) else maybe(0.4, surface(ior))

  private val solids = Vector("sphere", "box", "cylinder", "cone", "torus")

  /** A solid of `kind` about `centre`; `top`: at the scene's top, `inCsg`: inside a combination. */
  private def solid(kind: String, top: Boolean, inCsg: Boolean): Gen[String] =
    val spread = if top then 1.5 else 0.6
    within(-spread, spread).flatMap(centre =>
      kind match
        case "sphere" =>
          for
            radius  <- Gen.choose(0.3, 1.1)
            surf    <- ownSurface(top, ior = top)
            (s, pl) <- if inCsg then placement(0.4) else Gen.const(("", ""))
          yield s"""<sphere radius="${n(radius)}"$s>${vec("centre", centre)}$surf$pl</sphere>"""
        case "plane" => plane(top, inCsg, centre)
        case "box"   =>
          for
            half    <- within(0.2, 0.9)
            surf    <- ownSurface(top, ior = top)
            (s, pl) <- placement(0.6)
          yield s"<box$s>${vec("corner1", centre - half)}${vec("corner2", centre + half)}$surf$pl</box>"
        case "cylinder" | "cone" =>
          for
            axis    <- direction
            length  <- Gen.choose(0.4, 1.8)
            open    <- chance(0.2)
            surf    <- ownSurface(top, ior = top && !open)
            (s, pl) <- placement(0.6)
            radius  <- Gen.choose(0.15, 0.7)
            r0      <- Gen.choose(0.0, 0.8)
            r1      <- Gen.choose(0.0, 0.8)
            point   <- chance(0.3)
          yield
            val ends =
              vec("base", centre - axis * (length / 2)) + vec("cap", centre + axis * (length / 2))
            val o = if open then """ open="true"""" else ""
            if kind == "cylinder" then
              s"""<cylinder radius="${n(radius)}"$o$s>$ends$surf$pl</cylinder>"""
            else
              val top1  = if point then 0.0 else r1
              val base0 = if r0 < 0.05 && top1 < 0.05 then 0.4 else r0
              s"""<cone base-radius="${n(base0)}" cap-radius="${n(
                  top1
                )}"$o$s>$ends$surf$pl</cone>"""
        case _ =>
          for
            major   <- Gen.choose(0.4, 1.0)
            minor   <- Gen.choose(0.1, Math.min(0.45, major * 0.9))
            surf    <- ownSurface(top, ior = top)
            (s, pl) <- placement(0.6)
          yield
            val moved = if pl.contains("translate") then pl else pl + vec("translate", centre)
            s"""<torus major="${n(major)}" minor="${n(minor)}"$s>$surf$moved</torus>"""
    )

  /** A plane: a floor below the scene at the top, any plane through the middle in a combination. */
  private def plane(top: Boolean, inCsg: Boolean, centre: Vec3): Gen[String] =
    for
      tilted  <- chance(0.6)
      normal  <- if tilted || inCsg then direction else Gen.const(Vec3(0, 1, 0))
      byPoint <- chance(0.5)
      floor   <- Gen.choose(-1.5, -0.8)
      offset  <- Gen.choose(-0.5, 0.5)
      (s, pl) <- if inCsg then placement(0.3) else Gen.const(("", ""))
      surf    <- ownSurface(top, ior = false)
    yield
      val point = if inCsg then centre else Vec3(0, floor, 0)
      if byPoint then s"<plane$s>${vec("normal", normal)}${vec("point", point)}$surf$pl</plane>"
      else
        val distance = if inCsg then offset else floor
        s"""<plane distance="${n(distance)}"$s>${vec("normal", normal)}$surf$pl</plane>"""

  private val modelNames =
    Vector("ico.obj", "ico_bare.obj", "ico_mixed.obj", "cube.obj", "wave.obj", "spire.obj")

  private def mesh(inCsg: Boolean): Gen[String] =
    for
      model     <- Gen.oneOf(modelNames)
      smooth    <- Gen.oneOf("", "false", "true", "auto", "auto", "true")
      scale     <- Gen.choose(0.5, 1.3)
      rotate    <- maybe(0.6, within(-90, 90).map(vec("rotate", _)))
      translate <- within(if inCsg then -0.6 else -1.5, if inCsg then 0.6 else 1.5)
      surf      <- if inCsg then maybe(0.4, surface(false)) else surface(false)
    yield
      val s = if smooth.isEmpty then "" else s""" smooth="$smooth""""
      s"""<mesh file="models/$model" scale="${n(scale)}"$s>$rotate${vec(
          "translate",
          translate
        )}$surf</mesh>"""

  private def triangle(inCsg: Boolean): Gen[String] =
    for
      centre  <- within(if inCsg then -0.6 else -1.5, if inCsg then 0.6 else 1.5)
      corners <- Gen.listOfN(3, within(-1, 1).map(centre + _))
      byEdges <- chance(0.5)
      surf    <- if inCsg then maybe(0.4, surface(false)) else surface(false)
    yield
      val List(a, b, c) = corners: @unchecked
      val body          =
        if byEdges then vec("origin", a) + vec("a", b - a) + vec("b", c - a)
        else corners.map(vec("corner", _)).mkString
      s"<triangle>$body$surf</triangle>"

  /** A combination `depth` deep (0 at the scene's top): two or three children, each a solid, a
    * plane, a nested combination (up to two deep) or, in a union, a triangle or mesh.
    */
  private def combination(depth: Int): Gen[String] =
    for
      operation <- Gen.oneOf("union", "intersection", "difference")
      count     <- Gen.oneOf(2, 2, 2, 3)
      children  <- Gen.listOfN(count, child(depth, operation))
      surf      <- if depth == 0 then surface(true) else maybe(0.5, surface(false))
      (s, pl)   <- placement(0.7)
      centre    <- within(-1.2, 1.2)
    yield
      val moved =
        if depth > 0 || pl.contains("translate") then pl else pl + vec("translate", centre)
      // POV-Ray's shadow cache counts a clear face of a combination twice, depending on the
      // pixels traced before, when the combination's own surface is opaque (docs/rendering.md,
      // Shadows): at the top, a combination holding a clear surface lets a little light through.
      val own =
        if depth == 0 && children.mkString.contains("transmit=") && !surf.contains("transmit=")
        then surf.replaceFirst("<surface", """<surface transmit="0.001"""")
        else surf
      s"<$operation$s>${children.mkString}$own$moved</$operation>"

  private def child(depth: Int, operation: String): Gen[String] =
    Gen
      .choose(0.0, 1.0)
      .flatMap(r =>
        if depth < 2 && r < 0.2 then combination(depth + 1)
        else if r < 0.28 then solid("plane", top = false, inCsg = true)
        else if operation == "union" && r < 0.38 then
          Gen.oneOf(triangle(inCsg = true), mesh(inCsg = true))
        else Gen.oneOf(solids).flatMap(solid(_, top = false, inCsg = true))
      )

  private val camera: Gen[String] =
    for
      look     <- within(-0.5, 0.5)
      closeUp  <- chance(0.15)
      distance <- if closeUp then Gen.choose(1.2, 2.5) else Gen.choose(3.5, 8.0)
      d        <- direction
      above    <- chance(0.8)
      width    <- Gen.choose(0.8, 1.4)
      zoom     <- Gen.choose(0.7, 1.6)
      up       <- maybe(0.25, direction.map(vec("up", _)))
    yield
      val toward = if above then Vec3(d.x, Math.abs(d.y) * 0.8, d.z) else d
      val eye    = look + toward * distance
      s"""<camera zoom="${n(zoom)}" width="${n(width)}" height="${n(width * 0.75)}">""" +
        vec("location", eye) + vec("lookat", look) + up + "</camera>"

  private def light(share: Double): Gen[String] =
    for
      tint     <- within(0.8, 1.0)
      at       <- within(-6, 6)
      fade     <- chance(0.1)
      distance <- Gen.choose(2.0, 6.0)
      power    <- Gen.oneOf(1, 2)
      area     <- maybe(
        0.3,
        for
          na <- Gen.choose(1, 5)
          nb <- Gen.choose(2, 5)
          a  <- within(-1.5, 1.5)
          b  <- within(-1.5, 1.5)
        yield s"""<area samples-a="$na" samples-b="$nb">${vec("a", a)}${vec("b", b)}</area>"""
      )
    yield
      val place  = Vec3(at.x, Math.abs(at.y) + 1, at.z)
      val scaled = tint * (if fade then share / 2 else share)
      val faded  = if fade then s""" fade-distance="${n(distance)}" fade-power="$power"""" else ""
      s"<light$faded>${vec("location", place)}${colour(scaled)}$area</light>"

  private val objectGen: Gen[String] = Gen
    .choose(0.0, 1.0)
    .flatMap(r =>
      if r < 0.3 then combination(0)
      else if r < 0.42 then mesh(inCsg = false)
      else if r < 0.5 then triangle(inCsg = false)
      else Gen.oneOf(solids :+ "sphere").flatMap(solid(_, top = true, inCsg = false))
    )

  private val generator: Gen[RandomScene] =
    for
      cam        <- camera
      background <- maybe(0.7, within(0, 0.4).map(colour(_, "background")))
      count      <- Gen.oneOf(1, 1, 2, 2, 3)
      budget     <- Gen.choose(0.85, 1.0)
      lights     <- Gen.listOfN(count, light(budget / count))
      floor      <- maybe(0.6, solid("plane", top = true, inCsg = false))
      many       <- Gen.choose(1, 5)
      objects    <- Gen.listOfN(many, objectGen)
      depth      <- Gen.oneOf(5, 5, 5, 5, 3, 2, 1)
    yield
      val parts = (cam :: background :: lights) ++ (floor :: objects)
      RandomScene(
        parts
          .filter(_.nonEmpty)
          .mkString(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<scene>\n  ",
            "\n  ",
            "\n</scene>\n"
          ),
        depth
      )
