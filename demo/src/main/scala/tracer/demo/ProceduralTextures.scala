package tracer.demo

import java.nio.file.{Files, Path}
import tracer.image.{Bitmap, Colour, Png, Ppm, PpmFormat}

/** Textures drawn by code: the images the gallery and the movie map onto their shapes.
  *
  * Each is a pure function of texture coordinates (u across, v up, both in 0..1) turned into a
  * bitmap by [[ProceduralTextures.draw]]; nothing is random, so the files are the same every time.
  */
object ProceduralTextures:

  /** A `columns` × `rows` checkerboard of two colours. */
  def checker(columns: Int, rows: Int, a: Colour, b: Colour)(u: Double, v: Double): Colour =
    if (Math.floor(u * columns) + Math.floor(v * rows)).toInt % 2 == 0 then a else b

  /** A planet: oceans and continents from smooth noise, ice caps at the poles (v near 0 and 1). */
  def planet(u: Double, v: Double): Colour =
    val latitude = Math.abs(v - 0.5) * 2
    // u wraps around the sphere, so sample the noise on a circle to hide the seam.
    val angle  = 2 * Math.PI * u
    val height = fractalNoise(3 + 2 * Math.cos(angle), 3 + 2 * Math.sin(angle), v * 5)
    if latitude > 0.86 - 0.1 * height then Colour(0.95, 0.97, 1.0)
    else if height > 0.55 then
      mix(Colour(0.25, 0.55, 0.2), Colour(0.6, 0.5, 0.3), (height - 0.55) * 3)
    else mix(Colour(0.02, 0.1, 0.35), Colour(0.1, 0.35, 0.65), height / 0.55)

  /** Red bricks in a running bond with light mortar, `courses` rows of them. */
  def bricks(courses: Int)(u: Double, v: Double): Colour =
    val row    = v * courses
    val shift  = if Math.floor(row).toInt % 2 == 0 then 0.0 else 0.5
    val column = u * courses / 2 + shift
    val mortar = row - Math.floor(row) < 0.1 || column - Math.floor(column) < 0.05
    if mortar then Colour(0.85, 0.83, 0.78)
    else
      val shade = 0.8 + 0.2 * fractalNoise(Math.floor(column) * 7.1, Math.floor(row) * 3.3, 0)
      Colour(0.65 * shade, 0.22 * shade, 0.15 * shade)

  /** Veined marble from turbulent noise. */
  def marble(u: Double, v: Double): Colour =
    val vein = Math.abs(Math.sin((u * 4 + v * 2 + 2.5 * fractalNoise(u * 6, v * 6, 1)) * Math.PI))
    mix(Colour(0.35, 0.35, 0.42), Colour(0.95, 0.94, 0.9), Math.pow(vein, 0.4))

  /** The `width` × `height` bitmap of a texture function: pixel (x, y) samples (u, v) at its centre,
    * with v = 1 at the top row, the inverse of how the tracer reads textures.
    */
  def draw(width: Int, height: Int)(texture: (Double, Double) => Colour): Bitmap =
    Bitmap.tabulate(width, height)((x, y) => texture((x + 0.5) / width, 1 - (y + 0.5) / height))

  /** Writes the gallery's textures into `dir`, in all three formats the tracer reads. */
  def writeGallery(dir: Path): Unit =
    Files.createDirectories(dir)
    def write(name: String, bitmap: Bitmap, bytes: Bitmap => Array[Byte]) =
      Files.write(dir.resolve(name), bytes(bitmap))
    write("planet.ppm", draw(512, 256)(planet), Ppm.encode(_, PpmFormat.Binary)): Unit
    write(
      "checker.png",
      draw(256, 256)(checker(8, 8, Colour.grey(0.95), Colour(0.1, 0.1, 0.12))),
      Png.encode
    ): Unit
    write("bricks.ppm", draw(128, 64)(bricks(8)), Ppm.encode(_, PpmFormat.Ascii)): Unit
    write("marble.png", draw(256, 256)(marble), Png.encode): Unit

  /** Writes the gallery's textures into the directory named by the first argument (default `scenes/textures`). */
  def main(args: Array[String]): Unit = writeGallery(
    Path.of(args.headOption.getOrElse("scenes/textures"))
  )

  private def mix(a: Colour, b: Colour, t: Double): Colour =
    val k = Math.max(0, Math.min(1, t))
    a * (1 - k) + b * k

  /** Smooth value noise in 0..1 summed over four octaves. */
  private def fractalNoise(x: Double, y: Double, z: Double): Double =
    (0 until 4)
      .map(o => valueNoise(x * (1 << o), y * (1 << o), z * (1 << o)) / (1 << o))
      .sum / 1.875

  private def valueNoise(x: Double, y: Double, z: Double): Double =
    val (x0, y0, z0)                          = (Math.floor(x), Math.floor(y), Math.floor(z))
    def smooth(t: Double)                     = t * t * (3 - 2 * t)
    val (fx, fy, fz)                          = (smooth(x - x0), smooth(y - y0), smooth(z - z0))
    def corner(dx: Int, dy: Int, dz: Int)     = lattice(x0.toInt + dx, y0.toInt + dy, z0.toInt + dz)
    def lerp(a: Double, b: Double, t: Double) = a + (b - a) * t
    def plane(dz: Int)                        =
      lerp(
        lerp(corner(0, 0, dz), corner(1, 0, dz), fx),
        lerp(corner(0, 1, dz), corner(1, 1, dz), fx),
        fy
      )
    lerp(plane(0), plane(1), fz)

  /** A fixed pseudo-random value in 0..1 for each integer lattice point (an integer hash). */
  private def lattice(x: Int, y: Int, z: Int): Double =
    val h0 = x * 374761393 + y * 668265263 + z * 1274126177
    val h  = (h0 ^ (h0 >>> 13)) * 1274126177
    ((h ^ (h >>> 16)) & 0xffffff).toDouble / 0xffffff
