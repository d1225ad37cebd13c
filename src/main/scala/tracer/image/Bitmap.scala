package tracer.image

/** An immutable width × height grid of RGB pixels, row 0 at the top, each channel a sample from 0
  * to `maxval` (as in PPM: 255 for 8-bit images, up to 65535 for 16-bit ones).
  *
  * The samples live in one flat array of 16-bit values, three per pixel, so a 3840×2160 image is
  * 50 MB and has no object per pixel. "Changing" a pixel returns a new bitmap; to build an image
  * pixel by pixel use [[Bitmap.tabulate]], and to build it in bands use [[Bitmap.stack]].
  */
final class Bitmap private (
    val width: Int,
    val height: Int,
    val maxval: Int,
    // Perf: Char is Scala's unsigned 16-bit integer; three per pixel, never mutated once built.
    private val samples: Array[Char]
):

  /** The colour of pixel (x, y), each channel its sample divided by `maxval`. */
  def apply(x: Int, y: Int): Colour =
    val i = offset(x, y)
    Colour.fromSamples(samples(i), samples(i + 1), samples(i + 2), maxval)

  /** The raw sample of `channel` (0 red, 1 green, 2 blue) at pixel (x, y), from 0 to `maxval`. */
  def sample(x: Int, y: Int, channel: Int): Int =
    require(channel >= 0 && channel < 3, s"channel must be 0, 1 or 2, got $channel")
    samples(offset(x, y) + channel).toInt

  /** A copy of this bitmap with pixel (x, y) set to `colour` (brought into range, hue kept). */
  def updated(x: Int, y: Int, colour: Colour): Bitmap =
    val copy = samples.clone()
    Bitmap.store(copy, offset(x, y), colour, maxval)
    new Bitmap(width, height, maxval, copy)

  /** This bitmap with every pixel's colour passed through `f`. */
  def map(f: Colour => Colour): Bitmap =
    Bitmap.tabulate(width, height, maxval)((x, y) => f(this(x, y)))

  /** True when (x, y) is a pixel of this bitmap. */
  def contains(x: Int, y: Int): Boolean = x >= 0 && x < width && y >= 0 && y < height

  /** The largest difference between a sample of this bitmap and the same sample of `that`, which
    * must have the same size and maxval; 0 means the images are identical.
    */
  def maxSampleDifference(that: Bitmap): Int =
    require(width == that.width && height == that.height && maxval == that.maxval, "sizes differ")
    samples.indices.foldLeft(0)((m, i) => Math.max(m, Math.abs(samples(i) - that.samples(i))))

  /** Bitmaps are equal when their sizes, maxvals and every sample are. */
  override def equals(other: Any): Boolean = other match
    case that: Bitmap =>
      width == that.width && height == that.height && maxval == that.maxval &&
      java.util.Arrays.equals(samples, that.samples)
    case _ => false

  /** A hash consistent with [[equals]]. */
  override def hashCode: Int = (width, height, maxval, java.util.Arrays.hashCode(samples)).##

  /** The size and depth, for messages: `Bitmap(640×480, maxval 255)`. */
  override def toString: String = s"Bitmap($width×$height, maxval $maxval)"

  private def offset(x: Int, y: Int): Int =
    if !contains(x, y) then
      // Why: a pixel outside the bitmap is a caller's bug, as for an array index.
      throw IndexOutOfBoundsException(s"pixel ($x, $y) is outside a $width×$height bitmap")
    3 * (y * width + x)

/** Constructors for [[Bitmap]], with the size rules every constructor checks. */
object Bitmap:

  /** The largest pixel count a bitmap can hold (three samples each in one JVM array). */
  val MaxPixels: Long = (Int.MaxValue - 8) / 3

  /** `Right(())` when a width × height image can exist, else a message saying why not. */
  def checkSize(width: Int, height: Int): Either[String, Unit] =
    if width < 1 || height < 1 then
      Left(s"image size ${width}x$height: width and height must be at least 1")
    else if width.toLong * height > MaxPixels then
      Left(s"image size ${width}x$height: more than $MaxPixels pixels")
    else Right(())

  /** A bitmap whose pixel (x, y) is `pixel(x, y)`, each colour brought into range keeping its hue. */
  def tabulate(width: Int, height: Int, maxval: Int = 255)(pixel: (Int, Int) => Colour): Bitmap =
    val samples = allocate(width, height, maxval)
    // Perf: one pass over a flat array; the only mutation is of the array being built.
    var y = 0
    while y < height do
      var x = 0
      while x < width do
        store(samples, 3 * (y * width + x), pixel(x, y), maxval)
        x += 1
      y += 1
    new Bitmap(width, height, maxval, samples)

  /** A bitmap built row by row, the rows possibly on other threads, without copying them.
    *
    * `fill` is given a [[PixelWriter]] that stores pixel (x, y) (brought into range) straight into
    * the bitmap; when `fill` returns it must have stored every pixel, and each row's writes must
    * have completed (its Future awaited). Each row is written by one thread.
    */
  def byRows(width: Int, height: Int, maxval: Int = 255)(fill: PixelWriter => Unit): Bitmap =
    val builder = Builder(width, height, maxval)
    fill(builder)
    builder.result

  /** A bitmap being filled pixel by pixel, as [[byRows]] fills one: rows may be stored from
    * several threads at once, each row by one, and [[result]] is the bitmap once every pixel is
    * stored. Its rows can be read as they are finished (the PNG encoder's [[PngStream]]).
    */
  final class Builder(val width: Int, val height: Int, val maxval: Int = 255) extends PixelWriter:
    // Perf: each row is written once into the final array, by whichever thread computes it; the
    // rows are disjoint, and the bitmap is made only after every row is done (Renderer awaits
    // them). The pixel comes as three doubles: no Colour a pixel (RenderBench).
    private[image] val samples: Array[Char] = allocate(width, height, maxval)

    /** Stores pixel (x, y) as the colour (r, g, b), brought into range as [[Colour.inRange]] does. */
    def put(x: Int, y: Int, r: Double, g: Double, b: Double): Unit =
      storeRgb(samples, 3 * (y * width + x), r, g, b, maxval)

    /** The bitmap of the stored pixels. It shares the builder's samples: store nothing after. */
    def result: Bitmap = new Bitmap(width, height, maxval, samples)

  /** A bitmap of one colour. */
  def fill(width: Int, height: Int, colour: Colour, maxval: Int = 255): Bitmap =
    tabulate(width, height, maxval)((_, _) => colour)

  /** A bitmap from raw samples in row order, three per pixel, each from 0 to `maxval`. */
  def fromSamples(width: Int, height: Int, maxval: Int, samples: IndexedSeq[Int]): Bitmap =
    val data = allocate(width, height, maxval)
    require(
      samples.length == data.length,
      s"expected ${data.length} samples, got ${samples.length}"
    )
    samples.indices.foreach { i =>
      val s = samples(i)
      require(s >= 0 && s <= maxval, s"sample $i is $s, outside 0..$maxval")
      data(i) = s.toChar
    }
    new Bitmap(width, height, maxval, data)

  /** One bitmap made of `bands` placed top to bottom; all must share width and maxval. */
  def stack(bands: Seq[Bitmap]): Bitmap =
    require(bands.nonEmpty, "no bands to stack")
    val first = bands.head
    require(bands.forall(b => b.width == first.width && b.maxval == first.maxval), "bands differ")
    val height = bands.iterator.map(_.height.toLong).sum
    require(height <= Int.MaxValue, "stacked image too tall")
    val samples = allocate(first.width, height.toInt, first.maxval)
    val starts  = bands.scanLeft(0)(_ + _.samples.length)
    bands
      .lazyZip(starts)
      .foreach((band, at) => System.arraycopy(band.samples, 0, samples, at, band.samples.length))
    new Bitmap(first.width, height.toInt, first.maxval, samples)

  /** A bitmap on `samples`, which the caller hands over (and must not change afterwards): the
    * codecs' way to make one without copying. Every sample must be at most `maxval`.
    */
  private[image] def owning(width: Int, height: Int, maxval: Int, samples: Array[Char]): Bitmap =
    require(samples.length == allocate(width, height, maxval).length, "wrong number of samples")
    new Bitmap(width, height, maxval, samples)

  /** The raw samples, for the codecs in this package; callers must not change them. */
  private[image] def samplesOf(bitmap: Bitmap): Array[Char] = bitmap.samples

  private def allocate(width: Int, height: Int, maxval: Int): Array[Char] =
    // Why: every caller has checked the size (`checkSize`); a bad one is a bug, as with require.
    checkSize(width, height).fold(msg => throw IllegalArgumentException(msg), identity)
    require(maxval >= 1 && maxval <= 65535, s"maxval must be 1..65535, got $maxval")
    new Array[Char](3 * width * height)

  private def store(samples: Array[Char], i: Int, colour: Colour, maxval: Int): Unit =
    storeRgb(samples, i, colour.r, colour.g, colour.b, maxval)

  /** Stores the colour (r, g, b), brought into range as [[Colour.inRange]] does, at sample `i`. */
  private def storeRgb(
      samples: Array[Char],
      i: Int,
      r: Double,
      g: Double,
      b: Double,
      maxval: Int
  ): Unit =
    Colour.inRangeOf(r, g, b) { (r, g, b) =>
      samples(i) = Colour.quantise(r, maxval).toChar
      samples(i + 1) = Colour.quantise(g, maxval).toChar
      samples(i + 2) = Colour.quantise(b, maxval).toChar
    }
