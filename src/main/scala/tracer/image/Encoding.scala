package tracer.image

import tracer.math.Pow

/** How a pixel's linear colour becomes the values written to the file (the `-g` option;
  * docs/scene-format.md, Output encoding). Applied after the colour is brought into range.
  */
enum Encoding:
  /** Values written as they are: the course's output, and `-g 1`. */
  case Linear

  /** Each channel c written as c^(1/gamma) (`-g gamma`, POV-Ray's `File_Gamma=gamma`). */
  case Power(gamma: Double)

  /** The sRGB transfer function (`-g srgb`, POV-Ray's `File_Gamma=sRGB`). */
  case Srgb

  /** One channel value in 0..1, encoded; with `StrictMath.pow`'s bits ([[tracer.math.Pow]]), the
    * same on every machine.
    */
  def encode(c: Double): Double = this match
    case Linear       => c
    case Power(gamma) => Pow.pow(c, 1 / gamma)
    case Srgb         =>
      if c <= 0.0031308 then 12.92 * c else 1.055 * Pow.pow(c, 1 / 2.4) - 0.055

  /** A colour brought into range (hue kept), then encoded channel by channel. */
  def encode(colour: Colour): Colour = this match
    case Linear => colour
    case _      =>
      val c = colour.inRange
      Colour(encode(c.r), encode(c.g), encode(c.b))

/** Parsing of the `-g` option's value. */
object Encoding:
  /** `srgb` (any case), or a gamma G > 0, where 1 is [[Encoding.Linear]]; else why not. */
  def parse(text: String): Either[String, Encoding] =
    if text.equalsIgnoreCase("srgb") then Right(Srgb)
    else
      Some(tracer.io.Decimal.parse(text)).filter(g => g > 0 && g.isFinite) match
        case Some(1.0)   => Right(Linear)
        case Some(gamma) => Right(Power(gamma))
        case None        => Left(s"-g must be srgb or a number greater than 0, got '$text'")
