package tracer.cli

/** The image plane's size in world units and in pixels, after the W/H/X/Y rule of cli.md.
  *
  * @param width   W, world units
  * @param height  H, world units
  * @param columns X, pixels
  * @param rows    Y, pixels
  */
final case class Resolution(width: Double, height: Double, columns: Int, rows: Int)

/** The rule that keeps a picture undistorted (W/X = H/Y) unless all four values are given. */
object Resolution:

  /** The pixel width used when neither the command line nor the rule gives one. */
  val DefaultColumns: Int = 640

  /** Resolves W, H, X and Y from the values given on the command line and the scene's camera.
    *
    * All four given: as they are. Three: the fourth from W/X = H/Y. Fewer: the scene's W, then its
    * H, then X = 640 fill in, in that order, until three are known; then the fourth as before.
    * A computed pixel count is rounded to the nearest integer, halves up, and is at least 1.
    */
  def resolve(
      width: Option[Double],
      height: Option[Double],
      columns: Option[Int],
      rows: Option[Int],
      sceneWidth: Double,
      sceneHeight: Double
  ): Resolution =
    val known       = List(width, height, columns, rows).count(_.isDefined)
    val (w, knownW) = fill(width, sceneWidth, known)
    val (h, knownH) = fill(height, sceneHeight, knownW)
    val (x, _)      = fill(columns, DefaultColumns, knownH)
    (w, h, x, rows) match
      case (Some(w), Some(h), Some(x), Some(y)) => Resolution(w, h, x, y)
      case (Some(w), Some(h), Some(x), None)    => Resolution(w, h, x, pixels(h * x / w))
      case (Some(w), Some(h), None, Some(y))    => Resolution(w, h, pixels(w * y / h), y)
      case (Some(w), None, Some(x), Some(y))    => Resolution(w, w * y / x, x, y)
      case (None, Some(h), Some(x), Some(y))    => Resolution(h * x / y, h, x, y)
      // Why: unreachable — `fill` makes three of the four known, and a match cannot say so.
      case _ => throw IllegalStateException("three of W, H, X, Y are always known here")

  /** `value`, or `fallback` when it is absent and fewer than three values are `known`. */
  private def fill[A](value: Option[A], fallback: A, known: Int): (Option[A], Int) =
    if value.isEmpty && known < 3 then (Some(fallback), known + 1) else (value, known)

  /** A computed pixel count: the nearest integer, halves up, at least 1. */
  private def pixels(exact: Double): Int =
    Math.max(1.0, Math.min(Int.MaxValue.toDouble, Math.floor(exact + 0.5))).toInt
