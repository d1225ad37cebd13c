package tracer.image

import java.io.{BufferedOutputStream, OutputStream}
import java.nio.charset.StandardCharsets.US_ASCII
import java.nio.{BufferUnderflowException, ByteBuffer, ByteOrder}
import java.util.zip.{DataFormatException, Inflater}

/** Reads and writes OpenEXR images (`.exr`) in the scanline form: the tracer writes channels B,
  * G and R as 32-bit floats without compression; it reads scanline files of 16-bit half or
  * 32-bit float channels, uncompressed, ZIPS or ZIP (docs/cli.md, Floating-point output).
  */
object Exr:

  /** The four bytes every OpenEXR file starts with (20000630 as a little-endian integer). */
  val Magic: IArray[Byte] = IArray(0x76, 0x2f, 0x31, 0x01).map(_.toByte)

  private val Half  = 1
  private val Whole = 2 // OpenEXR's FLOAT: a 32-bit float

  private val NoCompression = 0
  private val Zips          = 2
  private val Zip           = 3

  /** Writes `raster` as a single-part scanline OpenEXR file: the required header attributes
    * (channels B, G, R as FLOAT, compression NONE, the data and display windows, increasing-y
    * line order, pixel aspect ratio 1, screen window centre 0 and width 1), the offset table,
    * then one chunk a line, each channel's values of the line in the order B, G, R.
    */
  def write(raster: Raster, out: OutputStream): Unit =
    val width    = raster.width
    val height   = raster.height
    val header   = headerBytes(width, height)
    val lineSize = 12 * width
    val buffered = BufferedOutputStream(out, 1 << 16)
    buffered.write(header)
    val table = ByteBuffer.allocate(8 * height).order(ByteOrder.LITTLE_ENDIAN)
    val first = header.length.toLong + 8L * height
    for y <- 0 until height do table.putLong(first + y.toLong * (8 + lineSize))
    buffered.write(table.array)
    val channels = Raster.channelsOf(raster)
    val line     = ByteBuffer.allocate(8 + lineSize).order(ByteOrder.LITTLE_ENDIAN)
    for y <- 0 until height do
      line.clear(): Unit
      line.putInt(y).putInt(lineSize): Unit
      // Channels in the file's (alphabetical) order: blue, green, red.
      for c <- List(2, 1, 0); x <- 0 until width do line.putFloat(channels(3 * (y * width + x) + c))
      buffered.write(line.array)
    buffered.flush()

  private def headerBytes(width: Int, height: Int): Array[Byte] =
    val b                            = ByteBuffer.allocate(512).order(ByteOrder.LITTLE_ENDIAN)
    def bytes(values: Int*): Unit    = values.foreach(v => b.put(v.toByte): Unit)
    def ints(values: Int*): Unit     = values.foreach(v => b.putInt(v): Unit)
    def floats(values: Float*): Unit = values.foreach(v => b.putFloat(v): Unit)
    def text(t: String): Unit        =
      b.put(t.getBytes(US_ASCII)): Unit; bytes(0)
    def attribute(name: String, kind: String, size: Int): Unit =
      text(name); text(kind); ints(size)
    Magic.foreach(v => bytes(v))
    ints(2) // version 2, single-part scanline: no flags
    attribute("channels", "chlist", 3 * 18 + 1)
    // Each channel: its name, FLOAT, pLinear 0 and three reserved bytes, sampling 1 × 1.
    for name <- List("B", "G", "R") do
      text(name); ints(Whole, 0, 1, 1)
    bytes(0)
    attribute("compression", "compression", 1); bytes(NoCompression)
    attribute("dataWindow", "box2i", 16); ints(0, 0, width - 1, height - 1)
    attribute("displayWindow", "box2i", 16); ints(0, 0, width - 1, height - 1)
    attribute("lineOrder", "lineOrder", 1); bytes(0) // increasing y
    attribute("pixelAspectRatio", "float", 4); floats(1f)
    attribute("screenWindowCenter", "v2f", 8); floats(0f, 0f)
    attribute("screenWindowWidth", "float", 4); floats(1f)
    bytes(0)
    java.util.Arrays.copyOf(b.array, b.position)

  /** One channel of the file: its name, its type (1 half, 2 float) and its bytes a value. */
  private final case class Channel(name: String, kind: Int):
    def size: Int = if kind == Half then 2 else 4

  /** What the reader needs of a header. */
  private final case class Header(
      channels: List[Channel],
      compression: Int,
      xMin: Int,
      yMin: Int,
      width: Int,
      height: Int
  ):
    def linesPerChunk: Int = if compression == Zip then 16 else 1
    def lineSize: Int      = width * channels.map(_.size).sum

  /** Decodes a single-part scanline OpenEXR file whose channels are R, G and B (or Y alone, for
    * grey), 16-bit half or 32-bit float, uncompressed, ZIPS or ZIP; other channels (such as A)
    * are skipped. Values are kept as they are; values that are not finite are refused.
    */
  def read(bytes: Array[Byte]): Either[String, Raster] =
    val buffer = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN)
    try
      for
        _      <- Either.cond(bytes.take(4).sameElements(Magic), (), "not an OpenEXR file")
        _      <- version(buffer.getInt(4))
        header <- attributes(buffer.position(8), Map.empty).flatMap(headerOf)
        raster <- pixels(buffer, header)
      yield raster
    catch
      // Why: a file cut short or with sizes that do not add up runs a read off its end; that is
      // one error, said plainly, not a stack trace.
      case _: BufferUnderflowException | _: IndexOutOfBoundsException |
          _: IllegalArgumentException =>
        Left("the OpenEXR file is truncated or its sizes are inconsistent")

  /** The version field: 2, not tiled (flag 0x200), neither deep (0x800) nor multi-part
    * (0x1000); long names (0x400) are fine.
    */
  private def version(field: Int): Either[String, Unit] =
    if (field & 0xff) != 2 then Left(s"OpenEXR version ${field & 0xff} is not supported (only 2)")
    else if (field & 0x200) != 0 then Left("tiled OpenEXR files are not supported, only scanline")
    else if (field & 0x1800) != 0 then
      Left("multi-part and deep OpenEXR files are not supported, only single-part scanline")
    else Right(())

  /** Reads attributes (name, type, size, value) up to the empty name that ends the header. */
  @annotation.tailrec
  private def attributes(
      b: ByteBuffer,
      found: Map[String, (String, Array[Byte])]
  ): Either[String, Map[String, (String, Array[Byte])]] =
    val name = text(b)
    if name.isEmpty then Right(found)
    else
      val kind = text(b)
      val size = b.getInt()
      if size < 0 || size > b.remaining then
        Left(s"the header attribute $name has a bad size $size")
      else
        val value = new Array[Byte](size)
        b.get(value): Unit
        attributes(b, found.updated(name, (kind, value)))

  /** A zero-terminated string of at most 255 bytes. */
  private def text(b: ByteBuffer): String =
    val start = b.position
    val end   = (start until Math.min(b.limit, start + 256)).find(b.get(_) == 0)
    val stop  = end.getOrElse(
      // Why: a name without its terminating zero is a malformed header (caught in read).
      throw IllegalArgumentException("unterminated name")
    )
    b.position(stop + 1): Unit
    String(b.array, start, stop - start, US_ASCII)

  private def headerOf(found: Map[String, (String, Array[Byte])]): Either[String, Header] =
    def value(name: String, kind: String) =
      found.get(name) match
        case Some((`kind`, v)) => Right(ByteBuffer.wrap(v).order(ByteOrder.LITTLE_ENDIAN))
        case Some((other, _))  => Left(s"the header attribute $name has type $other, not $kind")
        case None              => Left(s"the header has no $name attribute")
    for
      list        <- value("channels", "chlist").flatMap(channels(_, Nil))
      compression <- value("compression", "compression").map(_.get() & 0xff).flatMap {
        case c @ (NoCompression | Zips | Zip) => Right(c)
        case c                                =>
          Left(s"OpenEXR compression ${compressionName(c)} is not supported (only none, ZIPS, ZIP)")
      }
      window <- value("dataWindow", "box2i")
      (xMin, yMin, xMax, yMax) = (
        window.getInt(),
        window.getInt(),
        window.getInt(),
        window.getInt()
      )
      width  = xMax.toLong - xMin + 1
      height = yMax.toLong - yMin + 1
      _ <-
        if width > Int.MaxValue || height > Int.MaxValue then
          Left(s"image size ${width}x$height: too large")
        else Bitmap.checkSize(width.toInt, height.toInt)
      _ <- Either.cond(
        Set("R", "G", "B").subsetOf(list.map(_.name).toSet) || list.exists(_.name == "Y"),
        (),
        s"expected channels R, G and B (or Y), found ${list.map(_.name).mkString(", ")}"
      )
    yield Header(list, compression, xMin, yMin, width.toInt, height.toInt)

  private def compressionName(c: Int): String =
    Vector("none", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB")
      .lift(c)
      .getOrElse(c.toString)

  @annotation.tailrec
  private def channels(b: ByteBuffer, found: List[Channel]): Either[String, List[Channel]] =
    val name = text(b)
    if name.isEmpty then
      if found.isEmpty then Left("the OpenEXR file has no channels") else Right(found.reverse)
    else
      val kind     = b.getInt()
      val _        = b.getInt() // pLinear and three reserved bytes
      val (xs, ys) = (b.getInt(), b.getInt())
      if kind != Half && kind != Whole then
        Left(s"channel $name: only half and float channels are supported, not unsigned integers")
      else if xs != 1 || ys != 1 then Left(s"channel $name: subsampled channels are not supported")
      else channels(b, Channel(name, kind) :: found)

  // Perf: the chunks' values go straight into the raster's array, line by line and channel by
  // channel, in plain loops (a texture may be large).
  private def pixels(buffer: ByteBuffer, h: Header): Either[String, Raster] =
    val chunks = (h.height + h.linesPerChunk - 1) / h.linesPerChunk
    val table  = buffer.position
    val out    = new Array[Float](3 * h.width * h.height)
    val wanted = List("R", "G", "B").map(n =>
      h.channels.indexWhere(_.name == n) match
        case -1 => h.channels.indexWhere(_.name == "Y")
        case i  => i
    )
    // Each channel's offset within a line, in bytes, and its kind.
    val starts = h.channels.scanLeft(0)((at, c) => at + h.width * c.size).toArray
    val kinds  = h.channels.map(_.kind).toArray
    val done   = (0 until chunks).foldLeft[Either[String, Int]](Right(0)) { (seen, k) =>
      seen.flatMap { count =>
        val offset = buffer.getLong(table + 8 * k)
        if offset < 0 || offset > Int.MaxValue - 8 then Left(s"chunk $k has a bad offset $offset")
        else
          val at    = offset.toInt
          val y     = buffer.getInt(at) - h.yMin
          val size  = buffer.getInt(at + 4)
          val lines = Math.min(h.linesPerChunk, h.height - y)
          if y < 0 || y >= h.height || y % h.linesPerChunk != 0 then
            Left(s"chunk $k starts at line ${y + h.yMin}, outside the picture or off its blocks")
          else
            val raw = h.lineSize * lines
            chunkData(buffer, at + 8, size, raw, h.compression).flatMap { data =>
              val values = ByteBuffer.wrap(data).order(ByteOrder.LITTLE_ENDIAN)
              var line   = 0
              while line < lines do
                var c = 0
                while c < 3 do
                  val ch   = wanted(c)
                  val base = line * h.lineSize + starts(ch)
                  var x    = 0
                  while x < h.width do
                    out(3 * ((y + line) * h.width + x) + c) =
                      if kinds(ch) == Half then halfToFloat(values.getShort(base + 2 * x))
                      else values.getFloat(base + 4 * x)
                    x += 1
                  c += 1
                line += 1
              Right(count + lines)
            }
      }
    }
    done.flatMap { lines =>
      val bad = out.indexWhere(v => !v.isFinite)
      if lines != h.height then Left(s"the chunks hold $lines lines of ${h.height}")
      else if bad >= 0 then
        val pixel = bad / 3
        Left(s"the value of pixel (${pixel % h.width}, ${pixel / h.width}) is not a finite number")
      else Right(Raster.fromChannels(h.width, h.height, out))
    }

  /** A chunk's `raw` bytes of values: as stored, or inflated and un-predicted for ZIP(S) (a
    * compressed chunk that would not be smaller is stored as it is).
    */
  private def chunkData(
      buffer: ByteBuffer,
      at: Int,
      size: Int,
      raw: Int,
      compression: Int
  ): Either[String, Array[Byte]] =
    if size < 0 || size > buffer.limit - at then Left(s"a chunk of $size bytes runs past the file")
    else if compression == NoCompression || size == raw then
      if size != raw then Left(s"an uncompressed chunk holds $size bytes, not $raw")
      else Right(java.util.Arrays.copyOfRange(buffer.array, at, at + size))
    else inflate(buffer.array, at, size, raw).map(unpredict)

  private def inflate(
      bytes: Array[Byte],
      at: Int,
      size: Int,
      raw: Int
  ): Either[String, Array[Byte]] =
    val inflater = Inflater()
    try
      inflater.setInput(bytes, at, size)
      val out = new Array[Byte](raw)
      val n   = inflater.inflate(out)
      if n != raw || !inflater.finished then Left(s"a ZIP chunk inflates to $n bytes, not $raw")
      else Right(out)
    catch case e: DataFormatException => Left(s"a ZIP chunk is corrupt: ${e.getMessage}")
    finally inflater.end()

  /** Undoes OpenEXR's ZIP predictor (each byte stored as the difference from the one before,
    * plus 128) and its split of the bytes into the even-indexed half and the odd-indexed half.
    */
  // Perf: two passes over the chunk's bytes in plain loops, no per-byte collection.
  private def unpredict(t: Array[Byte]): Array[Byte] =
    var i = 1
    while i < t.length do
      t(i) = (t(i - 1) + t(i) - 128).toByte
      i += 1
    val out  = new Array[Byte](t.length)
    val half = (t.length + 1) / 2
    var k    = 0
    while k < t.length do
      out(k) = if k % 2 == 0 then t(k / 2) else t(half + k / 2)
      k += 1
    out

  /** The 32-bit float of a 16-bit IEEE half (sign, 5 exponent bits, 10 mantissa bits). */
  def halfToFloat(bits: Short): Float =
    val h        = bits & 0xffff
    val sign     = if (h & 0x8000) != 0 then -1f else 1f
    val exponent = (h >>> 10) & 0x1f
    val mantissa = h & 0x3ff
    if exponent == 0 then sign * Math.scalb(mantissa.toFloat, -24)
    else if exponent == 31 then if mantissa == 0 then sign * Float.PositiveInfinity else Float.NaN
    else sign * Math.scalb((1024 + mantissa).toFloat, exponent - 25)
