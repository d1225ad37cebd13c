package tracer.render

import jdk.incubator.vector.{DoubleVector, FloatVector, VectorOperators}

/** A wide node's four slab tests at once, on JDK 25's Vector API (`jdk.incubator.vector`, four
  * doubles in one 256-bit register), lane for lane the operations of [[WideWalk.entry]].
  *
  * Only loaded when [[WideWalk.lanes]]: on a JDK without the module (17 as the launcher starts
  * it) this class is never touched (its vector types could not be verified), and the walks
  * take the scalar path.
  */
private[render] object WideLanes:

  /** The entry distances of the ray into the four child boxes of the wide node whose floats
    * start at `b` in `wb`, written to `out(0)` to `out(3)`, and a mask of the lanes whose box
    * the ray meets before `limit` (bit c for child c). A lane of the mask has the distance
    * [[WideWalk.entry]] gives, bit for bit; a lane outside it is one that `entry` answers +∞ for.
    *
    * Perf: a method of its own, small, so that C2 compiles it early and the interpreter's or
    * C1's walks call the compiled code (the Vector API outside C2 boxes every vector).
    */
  def entries(
      wb: Array[Float],
      b: Int,
      ox: Double,
      oy: Double,
      oz: Double,
      ix: Double,
      iy: Double,
      iz: Double,
      sx: Int,
      sy: Int,
      sz: Int,
      limit: Double,
      out: Array[Double]
  ): Int =
    // Perf: the scalar test's compare-and-assign steps as compares and blends (not max/min,
    // which differ on NaN from 0 × ∞ and on −0.0), in the same order, so each lane is exact.
    val nx   = plane(wb, b + 4 * sx, ox, ix)
    val fx   = plane(wb, b + 12 - 4 * sx, ox, ix)
    val zero = DoubleVector.zero(DoubleVector.SPECIES_256)
    val lim  = DoubleVector.broadcast(DoubleVector.SPECIES_256, limit)
    val t1   = zero.blend(nx, nx.compare(VectorOperators.GT, zero))
    val u1   = lim.blend(fx, fx.compare(VectorOperators.LT, lim))
    val ny   = plane(wb, b + 4 + 4 * sy, oy, iy)
    val fy   = plane(wb, b + 16 - 4 * sy, oy, iy)
    val t2   = t1.blend(ny, ny.compare(VectorOperators.GT, t1))
    val u2   = u1.blend(fy, fy.compare(VectorOperators.LT, u1))
    val nz   = plane(wb, b + 8 + 4 * sz, oz, iz)
    val fz   = plane(wb, b + 20 - 4 * sz, oz, iz)
    val t3   = t2.blend(nz, nz.compare(VectorOperators.GT, t2))
    val u3   = u2.blend(fz, fz.compare(VectorOperators.LT, u2))
    t3.intoArray(out, 0)
    t3.compare(VectorOperators.LE, u3).toLong.toInt

  /** The distances along the axis (origin o, inverse direction i) to the four planes at floats
    * `at` to `at + 3`: each float widened to double (exactly), then `(p - o) * i`.
    */
  private inline def plane(wb: Array[Float], at: Int, o: Double, i: Double): DoubleVector =
    FloatVector
      .fromArray(FloatVector.SPECIES_128, wb, at)
      .convertShape(VectorOperators.F2D, DoubleVector.SPECIES_256, 0)
      .asInstanceOf[DoubleVector]
      .sub(o)
      .mul(i)
