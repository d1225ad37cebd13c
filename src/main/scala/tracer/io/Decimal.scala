package tracer.io

/** Numbers as the scene format writes them: finite decimals like `-1`, `0.25`, `2.5e-3`. */
private[tracer] object Decimal:

  /** True when `text` is a number as a scene file may write it: `[+-]?(d+.?d*|.d+)([eE][+-]?d+)?`.
    *
    * Perf: a scan ([[parse]]), not a regular expression: a big scene has hundreds of thousands of
    * numbers, and a regex matcher per number was a sixth of the loading's allocation
    * (docs/performance.md).
    */
  def matches(text: String): Boolean = !java.lang.Double.isNaN(parse(text))

  /** The value of `text` read as [[matches]] accepts it, or NaN when it is not such a number.
    * Exactly `java.lang.Double.parseDouble(text)` for every accepted text (so it may be ±∞ for a
    * huge exponent).
    */
  def parse(text: CharSequence): Double = parse(text, 0, text.length)

  /** [[parse]] of the characters `text(from until to)`, without making a String of them. */
  def parse(text: CharSequence, from: Int, to: Int): Double =
    scan(text.charAt(_), from, to)(text.subSequence(from, to).toString)

  /** [[parse]] of the characters `chars(from until to)`: the same scan on an array (the OBJ
    * reader's block of text), so the same value bit for bit (`DecimalProperties`).
    */
  def parse(chars: Array[Char], from: Int, to: Int): Double =
    scan(chars(_), from, to)(String(chars, from, to - from))

  /** The scan of [[parse]] over the characters `at(from until to)`; `slow` is them as a String,
    * made only for `parseDouble` when the fast path does not apply. Inlined with `at`, so each
    * caller gets its own loop over its own kind of text, from this one source.
    */
  private inline def scan(inline at: Int => Char, from: Int, to: Int)(
      inline slow: => String
  ): Double =
    // Perf: one scan that checks the grammar and gathers the digits; a value of at most 15
    // significant digits with a power of ten up to 22 is computed exactly as one correctly rounded
    // product or quotient of two exact doubles (Clinger's fast path), which is what parseDouble
    // gives (docs/performance.md, round 4); up to 18 digits by EiselLemire (round 26); anything
    // longer, or what EiselLemire cannot decide, goes to parseDouble itself.
    // Mutable scan state, local to this loop.
    var i        = from
    val negative = i < to && at(i) == '-'
    if i < to && (at(i) == '-' || at(i) == '+') then i += 1
    var mantissa = 0L
    var digits   = 0     // significant digits gathered into mantissa
    var dropped  = false // a nonzero digit beyond what mantissa can hold exactly
    var scale    = 0     // the power of ten mantissa is to be multiplied by
    var seen     = 0     // digits of the mantissa, whole and fraction
    var fraction = false
    var more     = true
    while more && i < to do
      val c = at(i)
      if c >= '0' && c <= '9' then
        seen += 1
        if mantissa == 0 && c == '0' then
          (if fraction then scale -= 1
        )
        else if digits < 18 then
          mantissa = 10 * mantissa + (c - '0')
          digits += 1
          if fraction then scale -= 1
        else
          if c != '0' then dropped = true
          if !fraction then scale += 1
        i += 1
      else if c == '.' && !fraction then
        fraction = true
        i += 1
      else more = false
    var exponent = 0
    var valid    = seen > 0
    if valid && i < to && (at(i) == 'e' || at(i) == 'E') then
      i += 1
      val minus = i < to && at(i) == '-'
      if i < to && (at(i) == '-' || at(i) == '+') then i += 1
      val start = i
      while i < to && at(i) >= '0' && at(i) <= '9' do
        if exponent < 100000 then exponent = 10 * exponent + (at(i) - '0')
        i += 1
      valid = i > start
      if minus then exponent = -exponent
    if !valid || i != to then Double.NaN
    else
      val power = scale + exponent
      val exact =
        if dropped then Double.NaN
        else if mantissa == 0 then 0.0
        else if mantissa <= (1L << 53) && power >= 0 && power <= 22 then
          mantissa.toDouble * Powers(power)
        else if mantissa <= (1L << 53) && power < 0 && power >= -22 then
          mantissa.toDouble / Powers(-power)
        else EiselLemire.toDouble(mantissa, power)
      if java.lang.Double.isNaN(exact) then java.lang.Double.parseDouble(slow)
      else if negative then -exact
      else exact

  /** 10⁰ … 10²², each exact as a double. */
  private val Powers: Array[Double] = Array.tabulate(23)(k => Math.pow(10, k))

  /** `d` as a person would write it and as it reads back exactly: `-1`, not `-1.0`; otherwise the
    * shortest decimal that is exactly `d` (Java's `Double.toString`).
    */
  def show(d: Double): String =
    if d == Math.rint(d) && Math.abs(d) < 1e15 then d.toLong.toString else d.toString
