package tracer.image

import java.util.zip.{DataFormatException, Inflater}

/** A PNG decoder for the common kinds of file, giving the same samples as the JDK's image I/O
  * ([[Png.read]]), written directly (PNG specification, ISO/IEC 15948).
  *
  * Perf: image I/O's first use loads and initialises about 150 classes of `java.desktop` (colour
  * models, the plug-in registry, a cache file for the stream), which cost the gallery's showcase
  * 70–110 ms of its whole run reading two 256×256 textures (docs/performance.md, round 8); this
  * decoder needs only `java.util.zip`.
  *
  * It decodes non-interlaced files without a `tRNS` chunk of colour type 2 and 6 (RGB, RGBA; 8 or
  * 16 bits), 0 (grey) of 1, 2, 4 or 16 bits, 4 (grey and alpha) of 16 bits, and 3 (palette) whose
  * only chunks are `IHDR`, one `PLTE`, the `IDAT`s and `IEND` and whose every index is in the
  * palette. Everything else — interlaced files, 8-bit grey (image I/O maps it from linear grey to
  * sRGB through the colour management's table), transparency chunks, and any file that is
  * damaged in any way — it leaves to image I/O (`None`), so that each message and each odd case
  * stays image I/O's own. Alpha is ignored, as image I/O's reading ignores it; so are `gAMA`,
  * `sRGB`, `iCCP` and `cHRM`, which image I/O reads as metadata only. `PngReaderProperties` holds
  * both decoders to the same bitmaps on files of every kind that image I/O writes.
  */
private[image] object PngReader:

  private val Signature = Array[Byte](0x89.toByte, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n')

  private val IHDR = chunkType("IHDR")
  private val PLTE = chunkType("PLTE")
  private val IDAT = chunkType("IDAT")
  private val IEND = chunkType("IEND")
  private val tRNS = chunkType("tRNS")

  /** The bitmap image I/O would decode from `bytes` (16-bit files at maxval 65535, the others at
    * 255), or `None` when the file is not one this decoder takes, or is damaged.
    */
  def read(bytes: Array[Byte]): Option[Bitmap] =
    try decode(bytes)
    catch
      // Why: a damaged stream is image I/O's to report, with its own message.
      case _: DataFormatException | _: IndexOutOfBoundsException | _: IllegalArgumentException =>
        None

  /** The header's fields: size, bit depth and colour type. */
  private final case class Header(width: Int, height: Int, depth: Int, colour: Int):
    /** Samples a pixel: grey 1, grey and alpha 2, RGB 3, palette 1, RGBA 4. */
    def channels: Int = colour match
      case 0 | 3 => 1
      case 4     => 2
      case 2     => 3
      case _     => 4

    /** Bytes of one row's samples, without its filter byte. */
    def rowBytes: Long = (width.toLong * channels * depth + 7) / 8

    /** Bytes a pixel takes for filtering: at least one. */
    def filterStep: Int = Math.max(1, channels * depth / 8)

  private def decode(bytes: Array[Byte]): Option[Bitmap] =
    for
      header <- readHeader(bytes)
      data   <- chunks(bytes, header)
      (palette, idats) = data
      raw <- inflate(bytes, idats, header)
      if unfilter(raw, header)
      bitmap <- toBitmap(raw, header, palette)
    yield bitmap

  /** The IHDR chunk's fields, when the file is of a kind this decoder takes. */
  private def readHeader(bytes: Array[Byte]): Option[Header] =
    val ok = bytes.length >= 33 && bytes.take(8).sameElements(Signature) &&
      int(bytes, 8) == 13 && int(bytes, 12) == IHDR
    if !ok then None
    else
      val header    = Header(int(bytes, 16), int(bytes, 20), bytes(24) & 0xff, bytes(25) & 0xff)
      val methods   = bytes(26) == 0 && bytes(27) == 0 && bytes(28) == 0 // no interlace
      val supported = (header.colour, header.depth) match
        case (2 | 6, 8 | 16)     => true
        case (0, 1 | 2 | 4 | 16) => true
        case (4, 16)             => true
        case (3, 1 | 2 | 4 | 8)  => true
        case _                   => false
      val sized = Bitmap.checkSize(header.width, header.height).isRight &&
        header.height * (header.rowBytes + 1) <= Int.MaxValue - 8
      Option.when(methods && supported && sized)(header)

  /** The palette (for colour type 3) and the positions and lengths of the IDAT chunks' data, read
    * as image I/O reads them: a palette file chunk by chunk to IEND, the others up to the first
    * IDAT and then its run of IDATs.
    */
  private def chunks(bytes: Array[Byte], header: Header): Option[(Array[Int], Vector[(Int, Int)])] =
    val paletted = header.colour == 3
    // Why: a walk over the chunks, each step checked; the first thing this decoder does not take
    // ends it with None.
    var at                                               = 33
    var palette: Array[Int]                              = Array.empty
    var idats                                            = Vector.empty[(Int, Int)]
    var result: Option[(Array[Int], Vector[(Int, Int)])] = None
    var done                                             = false
    // Why: chunk after chunk until the data's end is known, or the file is refused.
    while !done do
      val whole = at.toLong + 8 <= bytes.length && {
        val length = int(bytes, at)
        length >= 0 && at.toLong + 12 + length <= bytes.length
      }
      val kind = if whole then int(bytes, at + 4) else 0
      if !whole then
        // The file ends (or its last chunk is cut short): a run of IDATs ends with it, as image
        // I/O's reading of them does; anything else is image I/O's to judge.
        if !paletted && idats.nonEmpty && at.toLong + 8 > bytes.length then
          result = Some((palette, idats))
        done = true
      else
        val length = int(bytes, at)
        if kind == IDAT then idats = idats :+ (at + 8, length)
        else if idats.nonEmpty && !paletted then
          result = Some((palette, idats)); done = true
        else if paletted && kind == IEND then
          if idats.nonEmpty && palette.nonEmpty then result = Some((palette, idats))
          done = true
        else if paletted && kind == PLTE && palette.isEmpty && idats.isEmpty &&
          length % 3 == 0 && length > 0 && length / 3 <= (1 << header.depth)
        then palette = Array.tabulate(length / 3)(i => rgb(bytes, at + 8 + 3 * i))
        else if paletted || kind == tRNS then done = true
        at += 12 + length
    result

  /** The inflated data of the IDAT chunks: exactly the rows' bytes, filter bytes included. */
  private def inflate(
      bytes: Array[Byte],
      idats: Vector[(Int, Int)],
      header: Header
  ): Option[Array[Byte]] =
    val size       = header.height * (header.rowBytes + 1)
    val compressed = idats.iterator.map(_._2.toLong).sum
    // Deflate expands at most about 1032 times: a header promising more than the data can hold
    // is image I/O's to refuse, before this decoder allocates the rows.
    if compressed * 1032 + 1024 < size then None
    else inflateInto(new Array[Byte](size.toInt), bytes, idats)

  private def inflateInto(
      out: Array[Byte],
      bytes: Array[Byte],
      idats: Vector[(Int, Int)]
  ): Option[Array[Byte]] =
    val inflater = Inflater()
    try
      // Why: the output filled chunk by chunk; `filled` and `next` are the loop's own state.
      var filled = 0
      var next   = 0
      var stuck  = false
      // Gives the inflater the next IDAT chunk; false when there is none left.
      def feed(): Boolean =
        if next < idats.length then
          val (from, length) = idats(next)
          inflater.setInput(bytes, from, length)
          next += 1
          true
        else false
      // Why: inflate until the rows are whole, feeding the next IDAT when the inflater needs it.
      while filled < out.length && !stuck do
        if inflater.needsInput then stuck = !feed()
        else
          val n = inflater.inflate(out, filled, out.length - filled)
          filled += n
          // The stream's end, a preset dictionary, or no progress with input left.
          if n == 0 && !inflater.needsInput then stuck = true
      // The rows are whole: the stream must end right after them, its checksum verified (a
      // damaged tail, or data beyond the rows, is image I/O's to judge).
      val probe = new Array[Byte](1)
      // Why: feeding the rest of the IDAT chunks until the inflater reaches the stream's end.
      while filled == out.length && !stuck && !inflater.finished do
        if inflater.needsInput then stuck = !feed()
        else if inflater.inflate(probe) > 0 || (!inflater.finished && !inflater.needsInput) then
          stuck = true
      Option.when(filled == out.length && !stuck && inflater.finished)(out)
    finally inflater.end()

  /** Undoes each row's filter in place; false at a filter type that does not exist. */
  private def unfilter(raw: Array[Byte], header: Header): Boolean =
    val stride = header.rowBytes.toInt
    val step   = header.filterStep
    // Why: a pass over the rows, each in place on the row above it, already unfiltered.
    var y  = 0
    var ok = true
    while ok && y < header.height do
      val at    = y * (stride + 1) + 1
      val above = at - (stride + 1)
      val kind  = raw(at - 1)
      ok = kind >= 0 && kind <= 4
      // Perf: one loop a row, over the row's bytes in place.
      var i = 0
      while ok && i < stride do
        val a         = if i >= step then raw(at + i - step) & 0xff else 0
        val b         = if y > 0 then raw(above + i) & 0xff else 0
        val c         = if i >= step && y > 0 then raw(above + i - step) & 0xff else 0
        val predicted = kind match
          case 0 => 0
          case 1 => a
          case 2 => b
          case 3 => (a + b) >> 1
          case _ => paeth(a, b, c)
        raw(at + i) = (raw(at + i) + predicted).toByte
        i += 1
      y += 1
    ok

  private def paeth(a: Int, b: Int, c: Int): Int =
    val pa = Math.abs(b - c)
    val pb = Math.abs(a - c)
    val pc = Math.abs(a + b - c - c)
    if pa <= pb && pa <= pc then a else if pb <= pc then b else c

  /** The unfiltered rows as a bitmap, as image I/O's reading gives them (see [[read]]). */
  private def toBitmap(raw: Array[Byte], header: Header, palette: Array[Int]): Option[Bitmap] =
    val (w, h)   = (header.width, header.height)
    val stride   = header.rowBytes.toInt + 1
    val channels = header.channels
    val deep     = header.depth == 16
    val samples  = new Array[Char](3 * w * h)
    // Why: stays true while every palette index is in the palette.
    var inPalette = true
    // Perf: one pass over the pixels into the bitmap's own array.
    var y = 0
    while y < h do
      val row = y * stride + 1
      var x   = 0
      while x < w do
        val to = 3 * (y * w + x)
        if deep then
          val from = row + 2 * channels * x
          val grey = channels < 3
          samples(to) = short(raw, from)
          samples(to + 1) = short(raw, if grey then from else from + 2)
          samples(to + 2) = short(raw, if grey then from else from + 4)
        else if channels >= 3 then
          val from = row + channels * x
          samples(to) = (raw(from) & 0xff).toChar
          samples(to + 1) = (raw(from + 1) & 0xff).toChar
          samples(to + 2) = (raw(from + 2) & 0xff).toChar
        else
          // One sample of 1, 2, 4 or 8 bits, packed from the byte's high bits.
          val bit   = x * header.depth
          val shift = 8 - header.depth - (bit & 7)
          val value = ((raw(row + (bit >> 3)) & 0xff) >> shift) & ((1 << header.depth) - 1)
          if header.colour == 3 then
            if value < palette.length then
              val c = palette(value)
              samples(to) = ((c >> 16) & 0xff).toChar
              samples(to + 1) = ((c >> 8) & 0xff).toChar
              samples(to + 2) = (c & 0xff).toChar
            else inPalette = false
          else
            val level = (value * 255 / ((1 << header.depth) - 1)).toChar
            samples(to) = level
            samples(to + 1) = level
            samples(to + 2) = level
        x += 1
      y += 1
    Option.when(inPalette)(Bitmap.owning(w, h, if deep then 65535 else 255, samples))

  private def int(bytes: Array[Byte], at: Int): Int =
    ((bytes(at) & 0xff) << 24) | ((bytes(at + 1) & 0xff) << 16) | ((bytes(at + 2) & 0xff) << 8) |
      (bytes(at + 3) & 0xff)

  private def short(bytes: Array[Byte], at: Int): Char =
    (((bytes(at) & 0xff) << 8) | (bytes(at + 1) & 0xff)).toChar

  private def rgb(bytes: Array[Byte], at: Int): Int =
    ((bytes(at) & 0xff) << 16) | ((bytes(at + 1) & 0xff) << 8) | (bytes(at + 2) & 0xff)

  private def chunkType(name: String): Int =
    name.foldLeft(0)((t, c) => (t << 8) | c.toInt)
