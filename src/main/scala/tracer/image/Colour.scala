package tracer.image

/** An RGB colour with channels as doubles: 0..1 is the displayable range, but values are not
  * limited while light is being added up (rendering.md, From colour to bytes).
  */
final case class Colour(r: Double, g: Double, b: Double):

  /** The channel-wise sum: light from two sources together. */
  inline def +(that: Colour): Colour = Colour(r + that.r, g + that.g, b + that.b)

  /** Every channel scaled by `s`. */
  inline def *(s: Double): Colour = Colour(r * s, g * s, b * s)

  /** Every channel divided by `s`. */
  inline def /(s: Double): Colour = Colour(r / s, g / s, b / s)

  /** The channel-wise product: a surface colour lit by a light colour. */
  inline def *(that: Colour): Colour = Colour(r * that.r, g * that.g, b * that.b)

  /** The largest of the three channels. */
  def max: Double = Math.max(r, Math.max(g, b))

  /** This colour brought into 0..1 keeping its hue: when a channel exceeds 1, all three are
    * divided by the largest. Negative channels (which no scene produces) become 0.
    */
  def inRange: Colour =
    val m    = max
    val kept = if m > 1 then Colour(r / m, g / m, b / m) else this
    if kept.r >= 0 && kept.g >= 0 && kept.b >= 0 then kept
    else Colour(Math.max(kept.r, 0), Math.max(kept.g, 0), Math.max(kept.b, 0))

  /** A compact `rgb(r, g, b)` rendering for messages. */
  override def toString: String = s"rgb($r, $g, $b)"

/** Named colours and the byte conversion of [[Colour]]. */
object Colour:
  /** No light at all. */
  val Black: Colour = Colour(0, 0, 0)

  /** Full light in every channel. */
  val White: Colour = Colour(1, 1, 1)

  /** A grey of the given brightness in every channel. */
  def grey(level: Double): Colour = Colour(level, level, level)

  /** The sample round(maxval·c) for a channel value c in 0..1, halves rounding up: ⌊maxval·c +
    * ½⌋ clamped to 0..maxval (NaN gives 0).
    *
    * Perf: the conversion to Int truncates toward zero, which is the floor for every value the
    * clamp keeps, and gives 0 or less (so 0) for every other, NaN included: the same sample
    * without `Math.floor`, which only C2 compiles to an instruction (the interpreter and C1 call
    * `StrictMath.floorOrCeil`, 6 ms of a 3840×2160 run's first half second; docs/performance.md,
    * round 38). `ColourLaws` compares it with the floor's over all doubles.
    */
  def quantise(c: Double, maxval: Int): Int =
    Math.min(maxval, Math.max(0, (c * maxval + 0.5).toInt))

  /** [[Colour.inRange]] of the colour (r, g, b), handed to `k` as three doubles: the same
    * operations, for hot loops that keep colours in doubles.
    *
    * Perf: inline with an inline function, so no Colour is made (RenderBench).
    */
  inline def inRangeOf[A](r: Double, g: Double, b: Double)(
      inline k: (Double, Double, Double) => A
  ): A =
    val m        = Math.max(r, Math.max(g, b))
    val kr       = if m > 1 then r / m else r
    val kg       = if m > 1 then g / m else g
    val kb       = if m > 1 then b / m else b
    val positive = kr >= 0 && kg >= 0 && kb >= 0
    k(
      if positive then kr else Math.max(kr, 0),
      if positive then kg else Math.max(kg, 0),
      if positive then kb else Math.max(kb, 0)
    )

  /** A colour from samples scaled by 1/`maxval` (PPM's rule). */
  def fromSamples(r: Int, g: Int, b: Int, maxval: Int): Colour =
    Colour(r.toDouble / maxval, g.toDouble / maxval, b.toDouble / maxval)
