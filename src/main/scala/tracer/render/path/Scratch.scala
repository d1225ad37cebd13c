package tracer.render.path

/** One path-mode task's scratch space: where [[Bsdf]] and [[Emitters]] leave the results of the
  * calls path mode's loop makes at every vertex (a direction and its weight, f·|cos θ|, a light
  * sample), so that the loop allocates no [[Scattered]], [[LightSample]], vector or colour.
  *
  * Not thread-safe: each [[PathTracer.Task]] has its own. The immutable values of the public
  * calls ([[Bsdf.sample]], [[Emitters.sample]]) are read from one made for the call.
  *
  * Perf: mutable fields, written by the `…Into` calls and read right after (PathBench).
  */
final class Scratch:
  // Why: the fields below are the results of the last `…Into` call (see the class's Perf note).

  /** A scattered or sampled direction ωo (unit). */
  var sx: Double = 0.0

  /** ωo's y. */
  var sy: Double = 0.0

  /** ωo's z. */
  var sz: Double = 1.0

  /** The scattering's weight, red (see [[Scattered.weight]]). */
  var wr: Double = 0.0

  /** The weight, green. */
  var wg: Double = 0.0

  /** The weight, blue. */
  var wb: Double = 0.0

  /** The scattering's density (see [[Scattered.density]]). */
  var density: Double = 0.0

  /** True when ωo goes through the surface. */
  var transmitted: Boolean = false

  /** False only for a clear surface's straight pass. */
  var bounce: Boolean = true

  /** The ratio of indices crossed (see [[Scattered.eta]]). */
  var eta: Double = 1.0

  /** f·|cos θo| of [[Bsdf.evaluateInto]], red. */
  var fr: Double = 0.0

  /** f·|cos θo|, green. */
  var fg: Double = 0.0

  /** f·|cos θo|, blue. */
  var fb: Double = 0.0

  /** A light sample's direction (see [[LightSample]]), x. */
  var lx: Double = 0.0

  /** The light's direction, y. */
  var ly: Double = 0.0

  /** The light's direction, z. */
  var lz: Double = 1.0

  /** How far the light is. */
  var distance: Double = 0.0

  /** The light's value over its density, red. */
  var lr: Double = 0.0

  /** The light's value, green. */
  var lg: Double = 0.0

  /** The light's value, blue. */
  var lb: Double = 0.0

  /** The light sample's density (0 for a point light). */
  var lightDensity: Double = 0.0

  /** Sets the scattering's weight and the rest beside the direction. */
  def scatter(
      r: Double,
      g: Double,
      b: Double,
      pdf: Double,
      through: Boolean,
      bounces: Boolean,
      ratio: Double
  ): Unit =
    wr = r; wg = g; wb = b; density = pdf; transmitted = through; bounce = bounces; eta = ratio

  /** Sets the scattering that ends a path ([[Scattered.Absorbed]]). */
  def absorb(): Unit =
    sx = 0; sy = 0; sz = 1
    scatter(0, 0, 0, 0, false, true, 1)

  /** True when the last scattering carries nothing on: the path ends. */
  def absorbed: Boolean = Math.max(wr, Math.max(wg, wb)) <= 0

  /** Sets a light sample. */
  def light(
      x: Double,
      y: Double,
      z: Double,
      far: Double,
      r: Double,
      g: Double,
      b: Double,
      pdf: Double
  ): Unit =
    lx = x; ly = y; lz = z; distance = far; lr = r; lg = g; lb = b; lightDensity = pdf

  /** Sets the sample of no light ([[LightSample.Dark]]). */
  def dark(): Unit = light(0, 0, 1, 0, 0, 0, 0, 0)

  /** True when the light sample carries no light. */
  def isDark: Boolean = Math.max(lr, Math.max(lg, lb)) <= 0
