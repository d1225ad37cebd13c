package tracer.io

import tracer.image.Colour
import tracer.math.Vec3
import tracer.scene.{AreaLight, Camera, Light}

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

  /** A `<light>`. */
  def light(e: Element): Result[Light] =
    for
      children <- contents(e, Vocabulary.NoNames, Vocabulary.LightChildren)
      location <- requiredVector(e, children, "location")
      colour   <- atMostOne(e, children, "colour", "color").flatMap(
        _.fold(Right(Colour.White))(colour(_, Double.PositiveInfinity))
      )
      area <- atMostOne(e, children, "area").flatMap(traverseOption(_)(areaLight))
    yield Light(location, colour, area)

  /** An `<area samples-a samples-b>` with its axes `<a>` and `<b>` (scene-format-v2). */
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
