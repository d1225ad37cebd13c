package tracer.render

/** The order in which a render task traces its pixels: a task holds a few whole rows, and traces
  * them a tile of [[Width]] columns at a time (the tile's rows in turn, each from left to right),
  * rather than a row at a time. The picture is the same, since each pixel is a function of its
  * place alone (`DeterminismSuite` compares with the plain row order of `renderSequential`).
  *
  * Perf: the rays of a tile's pixels, and the rays they spawn, meet the same few branches of the
  * trees and the same cells of the light and eye buffers, where the rays of a whole row sweep
  * across all of them; we take the gain to be the processor's caches keeping what the pixel above
  * used (this VM has no counters to show it, and smaller trees and faces did not move the times:
  * docs/performance.md, round 33). Steady frames on one thread (`scripts/ab.sh`): 1280×720 mesh-80000 1028 → 936
  * ms, mesh-5000 519 → 462, 3840×2160 mesh-20000 about 4100 → 3450 (docs/performance.md,
  * round 33).
  */
private[render] object Tiles:
  /** Columns a tile. */
  final val Width = 16

  /** The most rows a task holds. */
  final val Height = 16

  /** The rows a task holds in a picture (or band) of `rows` rows rendered on `threads` threads:
    * [[Height]], or fewer so that every thread gets at least eight tasks and none waits long for
    * the last (at least one).
    */
  def rowsPerTask(rows: Int, threads: Int): Int =
    Math.max(1, Math.min(Height, rows / (8 * Math.max(1, threads))))

  /** Calls `pixel(x, y, i)` for every pixel of rows `y` until `y + count` of a picture `columns`
    * wide (`i` the row's place in the task, from 0), a tile at a time.
    *
    * Perf: inline, so each frame's pixel method is called from its own small loops (one call a
    * pixel: the JIT compiles the pixel once, as the row's loop did; docs/performance.md, round 9).
    */
  inline def foreach(columns: Int, y: Int, count: Int)(
      inline pixel: (Int, Int, Int) => Unit
  ): Unit =
    runs(columns, y, count) { (from, until, row, i) =>
      // Why: a counted loop over the run's columns.
      var x = from
      while x < until do
        pixel(x, row, i)
        x += 1
    }

  /** Calls `run(from, until, row, i)` for every run of a tile's row, in [[foreach]]'s order: the
    * columns `from` until `until` of picture row `row` = `y + i`, the task's row `i`.
    */
  inline def runs(columns: Int, y: Int, count: Int)(
      inline run: (Int, Int, Int, Int) => Unit
  ): Unit =
    // Why: two counted loops, tiles and their rows.
    var from = 0
    while from < columns do
      val until = Math.min(columns, from + Width)
      var i     = 0
      while i < count do
        run(from, until, y + i, i)
        i += 1
      from = until
