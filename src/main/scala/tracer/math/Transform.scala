package tracer.math

/** An affine map p ↦ M·p + t of 3-space, kept with its inverse (pbrt's `Transform`): the
  * placement of a version 3 element (docs/scene-format.md, Placement), and the way back from the
  * world into that element's own space.
  *
  * Matrices are row-major, nine doubles each. Build one with [[Transform$ the companion]]'s
  * `scale`, `rotate` and `translate`, and chain them with [[andThen]].
  *
  * @param matrix      M, row-major
  * @param translation t
  * @param inverseMatrix M⁻¹, row-major
  */
final class Transform private (
    matrix: IArray[Double],
    translation: Vec3,
    inverseMatrix: IArray[Double]
):

  /** The placed point M·p + t. */
  def point(p: Vec3): Vec3 = Transform.times(matrix, p) + translation

  /** The placed direction M·d (no translation). */
  def direction(d: Vec3): Vec3 = Transform.times(matrix, d)

  /** The point `p` of the world taken back into this transform's own space: M⁻¹·(p − t). */
  def pointBack(p: Vec3): Vec3 = Transform.times(inverseMatrix, p - translation)

  /** The direction `d` of the world taken back into this transform's own space: M⁻¹·d. */
  def directionBack(d: Vec3): Vec3 = Transform.times(inverseMatrix, d)

  /** A normal `n` of the own space carried into the world: (M⁻¹)ᵀ·n, not normalised. */
  def normal(n: Vec3): Vec3 =
    val m = inverseMatrix
    Vec3(
      m(0) * n.x + m(3) * n.y + m(6) * n.z,
      m(1) * n.x + m(4) * n.y + m(7) * n.z,
      m(2) * n.x + m(5) * n.y + m(8) * n.z
    )

  /** This transform followed by `next`: p ↦ next(this(p)). */
  def andThen(next: Transform): Transform =
    new Transform(
      Transform.product(next.matrixValues, matrix),
      next.point(translation),
      Transform.product(inverseMatrix, next.inverseValues)
    )

  /** M⁻¹'s entries, row-major, then t's three: what the kernels need to take a ray of the world
    * into this transform's own space on plain doubles (`tracer.geometry.Kernel`).
    */
  def backEntries: IArray[Double] =
    inverseMatrix ++ IArray(translation.x, translation.y, translation.z)

  private def matrixValues: IArray[Double]  = matrix
  private def inverseValues: IArray[Double] = inverseMatrix

  /** M's entries, then t, for messages and tests. */
  override def toString: String = s"Transform(${matrix.mkString(", ")}; $translation)"

/** Constructors of [[Transform]]s. */
object Transform:
  private val One = IArray[Double](1, 0, 0, 0, 1, 0, 0, 0, 1)

  /** The identity. */
  val Identity: Transform = new Transform(One, Vec3.Zero, One)

  /** Scaling by `s` (> 0) about the origin. */
  def scale(s: Double): Transform =
    new Transform(
      IArray(s, 0, 0, 0, s, 0, 0, 0, s),
      Vec3.Zero,
      IArray(1 / s, 0, 0, 0, 1 / s, 0, 0, 0, 1 / s)
    )

  /** Moving by `v`. */
  def translate(v: Vec3): Transform = new Transform(One, v, One)

  /** POV-Ray's `rotate <x, y, z>`: `x` degrees about the x axis, then `y` about y, then `z` about
    * z, each turning y towards z, z towards x and x towards y respectively.
    */
  def rotate(degrees: Vec3): Transform =
    axis(1, 2, degrees.x).andThen(axis(2, 0, degrees.y)).andThen(axis(0, 1, degrees.z))

  /** A turn by `degrees` in the plane of axes `a` and `b`, taking a towards b. */
  private def axis(a: Int, b: Int, degrees: Double): Transform =
    val radians            = Math.toRadians(degrees)
    val (s, c)             = (StrictMath.sin(radians), StrictMath.cos(radians))
    def turn(sine: Double) =
      IArray.tabulate(9) { k =>
        val (row, column) = (k / 3, k % 3)
        if row == column then if row == a || row == b then c else 1.0
        else if row == b && column == a then sine
        else if row == a && column == b then -sine
        else 0.0
      }
    new Transform(turn(s), Vec3.Zero, turn(-s))

  private def times(m: IArray[Double], v: Vec3): Vec3 =
    Vec3(
      m(0) * v.x + m(1) * v.y + m(2) * v.z,
      m(3) * v.x + m(4) * v.y + m(5) * v.z,
      m(6) * v.x + m(7) * v.y + m(8) * v.z
    )

  private def product(a: IArray[Double], b: IArray[Double]): IArray[Double] =
    IArray.tabulate(9) { k =>
      val (row, column) = (k / 3, k % 3)
      a(3 * row) * b(column) + a(3 * row + 1) * b(3 + column) + a(3 * row + 2) * b(6 + column)
    }

/** The placement of a version 3 element (docs/scene-format.md, Placement): a uniform scale, then a
  * rotation (degrees about x, then y, then z, as POV-Ray's `rotate`), then a move.
  *
  * @param scale     the factor, > 0
  * @param rotate    the angles in degrees
  * @param translate the move
  */
final case class Placement(
    scale: Double = 1,
    rotate: Vec3 = Vec3.Zero,
    translate: Vec3 = Vec3.Zero
):
  require(scale > 0 && scale.isFinite, s"a placement's scale must be positive, got $scale")

  /** The map from the element's own space to the space around it. */
  val transform: Transform =
    Transform.scale(scale).andThen(Transform.rotate(rotate)).andThen(Transform.translate(translate))

  /** True when the placement moves nothing. */
  def isIdentity: Boolean = scale == 1 && rotate == Vec3.Zero && translate == Vec3.Zero

/** The placement that leaves everything where it is. */
object Placement:
  /** No scale, rotation or move. */
  val Identity: Placement = Placement()
