package tracer.image

/** Where a picture being built takes its pixels, each as three doubles: the renderer's row tasks
  * write through it straight into a [[Bitmap]] or a [[Raster]] (`byRows`), without a `Colour` a
  * pixel. Rows may be written from several threads at once, each row by one.
  */
trait PixelWriter:
  /** Stores pixel (x, y) as the colour (r, g, b) (a bitmap brings it into range first). */
  def put(x: Int, y: Int, r: Double, g: Double, b: Double): Unit

  /** Stores pixel (x, y) as `colour`. */
  final def put(x: Int, y: Int, colour: Colour): Unit = put(x, y, colour.r, colour.g, colour.b)
