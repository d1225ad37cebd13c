package tracer.io

/** Numbers as the scene format writes them: finite decimals like `-1`, `0.25`, `2.5e-3`. */
private[io] object Decimal:

  /** True when `text` is a number as a scene file may write it: `[+-]?(d+.?d*|.d+)([eE][+-]?d+)?`.
    *
    * Perf: a scan, not a regular expression: a big scene has hundreds of thousands of numbers, and
    * a regex matcher per number was a sixth of the loading's allocation (docs/performance.md).
    */
  def matches(text: String): Boolean =
    val n             = text.length
    var i             = 0
    def digits(): Int =
      val start = i
      while i < n && text.charAt(i) >= '0' && text.charAt(i) <= '9' do i += 1
      i - start
    if i < n && (text.charAt(i) == '+' || text.charAt(i) == '-') then i += 1
    val whole    = digits()
    val fraction = if i < n && text.charAt(i) == '.' then
      i += 1; digits()
    else 0
    val mantissa = whole > 0 || fraction > 0
    val exponent =
      if i < n && (text.charAt(i) == 'e' || text.charAt(i) == 'E') then
        i += 1
        if i < n && (text.charAt(i) == '+' || text.charAt(i) == '-') then i += 1
        digits() > 0
      else true
    mantissa && exponent && i == n

  /** `d` as a person would write it and as it reads back exactly: `-1`, not `-1.0`; otherwise the
    * shortest decimal that is exactly `d` (Java's `Double.toString`).
    */
  def show(d: Double): String =
    if d == Math.rint(d) && Math.abs(d) < 1e15 then d.toLong.toString else d.toString
