package tracer.testkit

/** Distances the geometry tests borrow from the renderer, kept here so that a test of the
  * `geometry` package need not import `render` (the packages depend the other way).
  */
object Offsets:
  /** How far off a surface the renderer starts shadow and reflected rays (`Shading.Epsilon`,
    * docs/rendering.md); `render.AnalyticSceneSuite` checks that the two are the same.
    */
  val Ray: Double = 1e-4
