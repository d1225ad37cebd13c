package tracer.image

/** Adler-32 checksums (RFC 1950) joined: the checksum of two byte sequences one after the other,
  * from each one's checksum and the second's length, as zlib's `adler32_combine` computes it. The
  * PNG encoder checksums each band of a picture where it is filtered, on whichever thread, and
  * joins the bands' checksums as it writes them in order.
  */
private[image] object Adler:
  /** The modulus of both of Adler-32's sums. */
  private val Base = 65521L

  /** The Adler-32 of sequence A followed by sequence B, from A's checksum `first`, B's `second`
    * and B's length `length` (at least 0).
    */
  def combine(first: Long, second: Long, length: Long): Long =
    // The low sum of A+B is a + b − 1; the high sum is A's high plus B's plus `length` times A's
    // low sum minus `length` (B's high sum counts from a low sum of 1, not of A's), all mod Base.
    val rem  = length                   % Base
    val low  = (first & 0xffff) + (second & 0xffff) + Base - 1
    val high = (rem * (first & 0xffff)) % Base + ((first >>> 16) & 0xffff) +
      ((second >>> 16) & 0xffff) + Base - rem
    ((high % Base) << 16) | (low % Base)
