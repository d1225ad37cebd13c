package tracer.image

/** An immutable width × height grid of linear RGB radiance, row 0 at the top, each channel a
  * 32-bit float that is not limited to 0..1: what `.pfm` and `.exr` files hold, and what a
  * path-traced picture is before it is brought into range for an 8-bit file.
  *
  * The channels live in one flat array, three per pixel. To build a raster pixel by pixel use
  * [[Raster.tabulate]]; row by row on many threads, [[Raster.byRows]]; in bands, [[Raster.stack]].
  */
final class Raster private (
    val width: Int,
    val height: Int,
    // Perf: three floats per pixel in one array, never mutated once built.
    private val channels: Array[Float]
):

  /** The colour of pixel (x, y), its channels widened to doubles. */
  def apply(x: Int, y: Int): Colour =
    val i = offset(x, y)
    Colour(channels(i).toDouble, channels(i + 1).toDouble, channels(i + 2).toDouble)

  /** Channel `channel` (0 red, 1 green, 2 blue) of pixel (x, y), as stored. */
  def channel(x: Int, y: Int, channel: Int): Float =
    require(channel >= 0 && channel < 3, s"channel must be 0, 1 or 2, got $channel")
    channels(offset(x, y) + channel)

  /** True when (x, y) is a pixel of this raster. */
  def contains(x: Int, y: Int): Boolean = x >= 0 && x < width && y >= 0 && y < height

  /** This raster as an 8-bit (or up to 16-bit) bitmap: each pixel `encode`d after it is brought
    * into range (the version 1 range rule, then `-g`).
    */
  def toBitmap(encoding: Encoding, maxval: Int = 255): Bitmap =
    Bitmap.tabulate(width, height, maxval)((x, y) => encoding.encode(this(x, y).inRange))

  /** Rasters are equal when their sizes and every channel's bits are. */
  override def equals(other: Any): Boolean = other match
    case that: Raster =>
      width == that.width && height == that.height &&
      java.util.Arrays.equals(channels, that.channels)
    case _ => false

  /** A hash consistent with [[equals]]. */
  override def hashCode: Int = (width, height, java.util.Arrays.hashCode(channels)).##

  /** The size, for messages: `Raster(640×480)`. */
  override def toString: String = s"Raster($width×$height)"

  private def offset(x: Int, y: Int): Int =
    if !contains(x, y) then
      // Why: a pixel outside the raster is a caller's bug, as for an array index.
      throw IndexOutOfBoundsException(s"pixel ($x, $y) is outside a $width×$height raster")
    3 * (y * width + x)

/** Constructors for [[Raster]]; the size rules are [[Bitmap.checkSize]]'s. */
object Raster:

  /** A raster whose pixel (x, y) is `pixel(x, y)`, stored as floats (not brought into range). */
  def tabulate(width: Int, height: Int)(pixel: (Int, Int) => Colour): Raster =
    byRows(width, height)(out =>
      for y <- 0 until height; x <- 0 until width do out.put(x, y, pixel(x, y))
    )

  /** A raster built row by row, the rows possibly on other threads, without copying them: as
    * [[Bitmap.byRows]], with `fill`'s writer storing each pixel as floats.
    */
  def byRows(width: Int, height: Int)(fill: PixelWriter => Unit): Raster =
    val channels = allocate(width, height)
    // Perf: each row is written once into the final array, by whichever thread computes it; the
    // rows are disjoint, and `fill` returns only after every row is done.
    fill { (x, y, r, g, b) =>
      val i = 3 * (y * width + x)
      channels(i) = r.toFloat
      channels(i + 1) = g.toFloat
      channels(i + 2) = b.toFloat
    }
    new Raster(width, height, channels)

  /** A raster from raw channels in row order, three per pixel (red, green, blue), copied. */
  def fromChannels(width: Int, height: Int, values: Array[Float]): Raster =
    val channels = allocate(width, height)
    require(
      values.length == channels.length,
      s"expected ${channels.length} values, got ${values.length}"
    )
    System.arraycopy(values, 0, channels, 0, channels.length)
    new Raster(width, height, channels)

  /** One raster made of `bands` placed top to bottom; all must share their width. */
  def stack(bands: Seq[Raster]): Raster =
    require(bands.nonEmpty, "no bands to stack")
    val first = bands.head
    require(bands.forall(_.width == first.width), "bands differ in width")
    val height = bands.iterator.map(_.height.toLong).sum
    require(height <= Int.MaxValue, "stacked image too tall")
    val channels = allocate(first.width, height.toInt)
    val starts   = bands.scanLeft(0)(_ + _.channels.length)
    bands
      .lazyZip(starts)
      .foreach((band, at) => System.arraycopy(band.channels, 0, channels, at, band.channels.length))
    new Raster(first.width, height.toInt, channels)

  /** The raw channels, for the codecs in this package; callers must not change them. */
  private[image] def channelsOf(raster: Raster): Array[Float] = raster.channels

  private def allocate(width: Int, height: Int): Array[Float] =
    // Why: every caller has checked the size (`Bitmap.checkSize`); a bad one is a bug.
    Bitmap.checkSize(width, height).fold(msg => throw IllegalArgumentException(msg), identity)
    new Array[Float](3 * width * height)
