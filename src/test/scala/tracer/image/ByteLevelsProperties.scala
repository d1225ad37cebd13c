package tracer.image

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll

/** [[ByteLevels]] gives the sample that encoding and quantising give, for every channel value. */
class ByteLevelsProperties extends ScalaCheckSuite:

  private val encodings =
    List(
      Encoding.Srgb,
      Encoding.Power(2.2),
      Encoding.Power(1.8),
      Encoding.Power(0.45),
      Encoding.Power(3)
    )

  private def direct(e: Encoding, c: Double) = Colour.quantise(e.encode(c), 255)

  /** The smallest double c in [0, 1] whose sample is at least k, by bisection on the bits. */
  private def step(e: Encoding, k: Int): Double =
    @scala.annotation.tailrec
    def search(lo: Long, hi: Long): Long =
      if lo >= hi then lo
      else
        val mid = (lo + hi) >>> 1
        if direct(e, java.lang.Double.longBitsToDouble(mid)) >= k then search(lo, mid)
        else search(mid + 1, hi)
    java.lang.Double.longBitsToDouble(search(0L, java.lang.Double.doubleToRawLongBits(1.0)))

  /** The doubles within `n` ulps of c. */
  private def around(c: Double, n: Int): Iterator[Double] =
    val bits = java.lang.Double.doubleToRawLongBits(c)
    (-n to n).iterator
      .map(i => java.lang.Double.longBitsToDouble(bits + i))
      .filter(x => x >= 0 && x <= 1)

  test("the gallery's encodings are tabled"):
    encodings.foreach(e => assert(ByteLevels(e).tabled, e.toString))
    assert(!ByteLevels(Encoding.Linear).tabled)

  test("every step of every encoding, and 2,000 doubles around it"):
    encodings.foreach { e =>
      val levels = ByteLevels(e)
      (1 to 255).foreach { k =>
        around(step(e, k), 1000).foreach(c =>
          assertEquals(levels.sample(c), direct(e, c), s"$e $k $c")
        )
      }
    }

  test("around sRGB's switch from its line to its curve, where it steps down by 3e-8"):
    val levels = ByteLevels(Encoding.Srgb)
    around(0.0031308, 20000).foreach(c =>
      assertEquals(levels.sample(c), direct(Encoding.Srgb, c), c.toString)
    )

  test("the ends, the smallest values and what is not in range"):
    encodings.foreach { e =>
      val levels = ByteLevels(e)
      List(
        0.0,
        -0.0,
        Double.MinPositiveValue,
        1e-300,
        1e-12,
        0.5,
        1.0,
        Math.nextDown(1.0),
        Double.NaN
      )
        .foreach(c => assertEquals(levels.sample(c), direct(e, c), s"$e $c"))
      (0 to 255).foreach(k => assertEquals(levels.sample(k / 255.0), direct(e, k / 255.0)))
    }

  property("any channel value in range"):
    forAll(Gen.oneOf(encodings), Gen.choose(0.0, 1.0), Gen.choose(-30.0, 0.0)) { (e, c, p) =>
      val levels = ByteLevels(e)
      val small  = Math.pow(10, p) // near 0, where the steps crowd
      assertEquals(levels.sample(c), direct(e, c), s"$e $c")
      assertEquals(levels.sample(small), direct(e, small), s"$e $small")
    }

  test("a bitmap stores the encoded value as the sample"):
    encodings.foreach { e =>
      val levels = ByteLevels(e)
      (0 to 100000).foreach { i =>
        val c = i / 100000.0
        assertEquals(Colour.quantise(levels.encoded(c), 255), direct(e, c), s"$e $c")
      }
    }
