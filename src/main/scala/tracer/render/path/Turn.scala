package tracer.render.path

/** cos 2πu and sin 2πu for a fraction u of a full turn in [0, 1): the angles path mode's sampling
  * draws (a direction about a normal, on a disc, towards the sky or a ball).
  *
  * The same bits on every machine, as StrictMath's (plain double arithmetic, which Java does the
  * same everywhere), at a fraction of StrictMath's cost: u is reduced to its quarter turn exactly
  * (4u and its fraction are exact), folded into [0, π/4], and the angle's cosine and sine taken
  * there by fdlibm's kernel polynomials (`__kernel_cos`, `__kernel_sin`), within about one ulp.
  */
object Turn:
  private val QuarterTurn = Math.PI / 2

  /** cos 2πu, u in [0, 1). */
  def cos(u: Double): Double =
    val v    = 4 * u
    val q    = v.toInt
    val f    = v - q
    val near = f <= 0.5
    val x    = if near then f * QuarterTurn else (1 - f) * QuarterTurn
    (q & 3) match
      case 0 => if near then kernelCos(x) else kernelSin(x)
      case 1 => -(if near then kernelSin(x) else kernelCos(x))
      case 2 => -(if near then kernelCos(x) else kernelSin(x))
      case _ => if near then kernelSin(x) else kernelCos(x)

  /** sin 2πu, u in [0, 1). */
  def sin(u: Double): Double =
    val v    = 4 * u
    val q    = v.toInt
    val f    = v - q
    val near = f <= 0.5
    val x    = if near then f * QuarterTurn else (1 - f) * QuarterTurn
    (q & 3) match
      case 0 => if near then kernelSin(x) else kernelCos(x)
      case 1 => if near then kernelCos(x) else kernelSin(x)
      case 2 => -(if near then kernelSin(x) else kernelCos(x))
      case _ => -(if near then kernelCos(x) else kernelSin(x))

  /** sin x for |x| ≤ π/4 (fdlibm's `__kernel_sin` with no tail). */
  private def kernelSin(x: Double): Double =
    val z = x * x
    val v = z * x
    val r =
      8.33333333332248946124e-03 + z * (-1.98412698298579493134e-04 + z *
        (2.75573137070700676789e-06 + z * (-2.50507602534068634195e-08 + z *
          1.58969099521155010221e-10)))
    x + v * (-1.66666666666666324348e-01 + z * r)

  /** cos x for |x| ≤ π/4 (fdlibm's `__kernel_cos` polynomial with no tail). */
  private def kernelCos(x: Double): Double =
    val z = x * x
    val r = z * (4.16666666666666019037e-02 + z * (-1.38888888888741095749e-03 + z *
      (2.48015872894767294178e-05 + z * (-2.75573143513906633035e-07 + z *
        (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))))
    1 - (0.5 * z - z * r)
