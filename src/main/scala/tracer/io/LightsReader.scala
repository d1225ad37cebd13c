package tracer.io

import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.{AreaLight, Camera, Fade, Light}

/** Reads `<camera>` and `<light>` (with version 2's `<area>`). */
private[io] object LightsReader:
  import Decimal.show
  import ElementRules.*

  /** A `<camera>`. */
  def camera(e: Element): Result[Camera] =
    for
      children <- contents(e, Vocabulary.CameraAttributes, Vocabulary.CameraChildren)
      zoom     <- positive(e, "zoom", Camera.DefaultZoom)
      width    <- positive(e, "width", Camera.DefaultWidth)
      height   <- positive(e, "height", Camera.DefaultHeight)
      location <- requiredVector(e, children, "location")
      lookAt   <- requiredVector(e, children, "lookat")
      up       <- optionalVector(e, children, Vec3.UnitY, "up")
      _ <- check(location != lookAt, e, s"<lookat> must differ from <location>, both are $location")
      _ <- check(
        up.cross(lookAt - location).normalised.isDefined,
        e,
        s"<up> $up is parallel to the viewing direction ${lookAt - location}"
      )
    yield Camera(location, lookAt, up, zoom, width, height)

  /** A `<light>`, with version 4's `fade-distance` and `fade-power`. */
  def light(e: Element): Result[Light] =
    for
      children <- contents(e, Vocabulary.LightAttributes, Vocabulary.LightChildren)
      fade     <- this.fade(e)
      location <- requiredVector(e, children, "location")
      colour   <- atMostOne(e, children, "colour", "color").flatMap(
        _.fold(Right(Colour.White))(colour(_, Double.PositiveInfinity))
      )
      area <- atMostOne(e, children, "area").flatMap(traverseOption(_)(areaLight))
    yield Light(location, colour, area, fade)

  /** The light's fall-off (version 4): `fade-distance` and `fade-power` both, each greater than
    * 0, or neither.
    */
  private def fade(e: Element): Result[Option[Fade]] =
    def above0(key: String) = number(e, key).flatMap(traverseOption(_) { v =>
      if v > 0 then Right(v) else e.fail(s"attribute $key must be greater than 0, got ${show(v)}")
    })
    for
      distance <- above0("fade-distance")
      power    <- above0("fade-power")
      fade     <- (distance, power) match
        case (Some(d), Some(n)) => Right(Some(Fade(d, n)))
        case (None, None)       => Right(None)
        case (Some(_), None)    => e.fail("attribute fade-distance needs fade-power beside it")
        case (None, Some(_))    => e.fail("attribute fade-power needs fade-distance beside it")
    yield fade

  /** An `<area samples-a samples-b>` with its axes `<a>` and `<b>` (docs/scene-format.md,
    * Version 2, Area lights).
    */
  private def areaLight(e: Element): Result[AreaLight] =
    for
      children <- contents(e, Vocabulary.AreaAttributes, Vocabulary.AreaChildren)
      samplesA <- samples(e, "samples-a")
      samplesB <- samples(e, "samples-b")
      a        <- requiredVector(e, children, "a")
      b        <- requiredVector(e, children, "b")
      _        <- check(
        a.cross(b).normalised.isDefined,
        e,
        s"the axes <a> $a and <b> $b must be non-zero and not parallel"
      )
    yield AreaLight(a, b, samplesA, samplesB)

  /** A required whole number of sub-lights, 1 to [[AreaLight.MaxSamples]]. */
  private def samples(e: Element, key: String): Result[Int] =
    requiredNumber(e, key).flatMap { v =>
      if v.isWhole && v >= 1 && v <= AreaLight.MaxSamples then Right(v.toInt)
      else
        e.fail(
          s"attribute $key must be a whole number from 1 to ${AreaLight.MaxSamples}, got ${show(v)}"
        )
    }
