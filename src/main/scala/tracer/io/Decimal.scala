package tracer.io

/** Numbers as the scene format writes them: finite decimals like `-1`, `0.25`, `2.5e-3`. */
private[io] object Decimal:

  /** The text a number may have in a scene file. */
  val Pattern = raw"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?".r

  /** `d` as a person would write it and as it reads back exactly: `-1`, not `-1.0`; otherwise the
    * shortest decimal that is exactly `d` (Java's `Double.toString`).
    */
  def show(d: Double): String =
    if d == Math.rint(d) && Math.abs(d) < 1e15 then d.toLong.toString else d.toString
