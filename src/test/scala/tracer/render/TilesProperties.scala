package tracer.render

import munit.ScalaCheckSuite
import org.scalacheck.Gen
import org.scalacheck.Prop.forAll

/** A task's pixel order ([[Tiles]]): every pixel of its rows once, a tile of [[Tiles.Width]]
  * columns at a time; and the rows a task holds.
  */
class TilesProperties extends ScalaCheckSuite:

  /** The pixels `Tiles.foreach` visits, in order, as (x, y, i). */
  private def visits(columns: Int, y: Int, count: Int): Vector[(Int, Int, Int)] =
    val seen = Vector.newBuilder[(Int, Int, Int)]
    Tiles.foreach(columns, y, count)((x, row, i) => seen += ((x, row, i)))
    seen.result()

  property("every pixel of the task's rows once, each with its row's place in the task"):
    forAll(Gen.choose(1, 200), Gen.choose(0, 500), Gen.choose(1, 20)) { (columns, y, count) =>
      val seen = visits(columns, y, count)
      assertEquals(seen.size, columns * count)
      assertEquals(
        seen.map((x, row, _) => (x, row)).toSet,
        (for row <- y until y + count; x <- 0 until columns yield (x, row)).toSet
      )
      assert(seen.forall((_, row, i) => row == y + i))
    }

  property("a tile at a time: its rows in turn, each left to right, the tiles left to right"):
    forAll(Gen.choose(1, 200), Gen.choose(1, 20)) { (columns, count) =>
      val expected =
        for
          from <- 0 until columns by Tiles.Width
          i    <- 0 until count
          x    <- from until Math.min(columns, from + Tiles.Width)
        yield (x, i, i)
      assertEquals(visits(columns, 0, count), expected.toVector)
    }

  test("one row a task is the plain row order"):
    assertEquals(visits(37, 5, 1), (0 until 37).map(x => (x, 5, 0)).toVector)

  property("a task holds 1 to Height rows, and every thread gets eight tasks when it can"):
    forAll(Gen.choose(1, 5000), Gen.choose(1, 64)) { (rows, threads) =>
      val height = Tiles.rowsPerTask(rows, threads)
      assert(height >= 1 && height <= Tiles.Height, s"$height rows a task")
      if height > 1 then assert((rows + height - 1) / height >= 8 * threads)
    }
