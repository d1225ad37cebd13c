package tracer.render.path

import tracer.render.SamplerKind

/** Path mode's random numbers: each a pure function of (seed, pixel x and y in the whole picture,
  * sample index j, dimension), so a picture is the same for every thread count, band and run
  * (docs/rendering.md, The sampler).
  *
  * Dimensions 0 and 1 place the sample in its pixel; each vertex of a path then takes its own
  * block of dimensions ([[Sampler.Dimensions]]).
  *
  * @param kind    the Sobol default or independent numbers
  * @param seed    which of many equally valid noise patterns, ≥ 0
  * @param samples N, the samples a pixel (the Sobol points are shuffled among the first N)
  */
final class Sampler(kind: SamplerKind, seed: Int, samples: Int):

  /** The hash of pixel (x, y) under this sampler's seed: the handle [[uniformAt]] and [[pairAt]]
    * take, computed once for all of a pixel's numbers.
    */
  def pixel(x: Int, y: Int): Long =
    Sampler.mix(
      Sampler.mix(
        (seed.toLong << 32) ^ 0x5851f42d4c957f2dL
      ) ^ ((x.toLong << 32) | (y & 0xffffffffL))
    )

  /** The number of dimension `dim` of sample j of pixel (x, y), uniform in [0, 1). */
  def uniform(x: Int, y: Int, j: Int, dim: Int): Double = uniformAt(pixel(x, y), j, dim)

  /** Dimensions `dim` and `dim + 1` of sample j of pixel (x, y) as one 2D point, packed in a
    * long (the first in the high 32 bits): read them with [[Sampler.first]] and
    * [[Sampler.second]]. The Sobol sampler keeps the pair's two-dimensional stratification.
    */
  def pair(x: Int, y: Int, j: Int, dim: Int): Long = pairAt(pixel(x, y), j, dim)

  /** [[uniform]] for the pixel whose [[pixel]] hash is `at`. */
  def uniformAt(at: Long, j: Int, dim: Int): Double = kind match
    case SamplerKind.Independent => Sampler.unit(Sampler.sampleKey(at, dim, j).toInt)
    case SamplerKind.Sobol       =>
      val key   = Sampler.dimensionKey(at, dim)
      val index = Sampler.permute(j, samples, key.toInt)
      Sampler.unit(Sampler.scramble(Integer.reverse(index), key))

  /** [[pair]] for the pixel whose [[pixel]] hash is `at`. */
  def pairAt(at: Long, j: Int, dim: Int): Long = kind match
    case SamplerKind.Independent => Sampler.sampleKey(at, dim, j)
    case SamplerKind.Sobol       =>
      val key   = Sampler.dimensionKey(at, dim)
      val index = Sampler.permute(j, samples, key.toInt)
      val a     = Sampler.scramble(Integer.reverse(index), key)
      val b     = Sampler.scramble(Sampler.sobolSecond(index), Sampler.mix(key + 1))
      (a.toLong << 32) | (b & 0xffffffffL)

/** The hash, the Sobol points and their scrambling behind [[Sampler]]. */
object Sampler:
  /** How many dimensions each vertex of a path takes: emitter choice (1), point on it (2), lobe
    * choice (1), direction (2), Russian roulette (1), reflect or refract at glass (1).
    */
  val Dimensions: Int = 8

  /** 2⁻³², one step of a 32-bit number read as a fraction. */
  val TwoToMinus32: Double = 1.0 / (1L << 32)

  /** The first number of a [[Sampler.pair]], in [0, 1). */
  inline def first(pair: Long): Double = unit((pair >>> 32).toInt)

  /** The second number of a [[Sampler.pair]], in [0, 1). */
  inline def second(pair: Long): Double = unit(pair.toInt)

  /** A 32-bit pattern as the number bits · 2⁻³² in [0, 1). */
  inline def unit(bits: Int): Double = (bits & 0xffffffffL) * Sampler.TwoToMinus32

  /** A 64-bit mixing function (pbrt-v4's `MixBits`): every output bit depends on every input bit. */
  def mix(value: Long): Long =
    val a = (value ^ (value >>> 31)) * 0x7fb5d329728ea185L
    val b = (a ^ (a >>> 27)) * 0x81dadef4bc2dd44dL
    b ^ (b >>> 33)

  /** The hash of a pixel's dimension `dim` (from [[Sampler.pixel]]'s hash `at`). */
  inline def dimensionKey(at: Long, dim: Int): Long = mix(at ^ (dim * 0x9e3779b97f4a7c15L))

  /** The hash of sample j's dimension `dim` of a pixel: a counter-based generator's output. */
  inline def sampleKey(at: Long, dim: Int, j: Int): Long =
    mix(dimensionKey(at, dim) ^ ((j & 0xffffffffL) * 0xd1b54a32d192ed03L))

  // The second Sobol dimension's generator matrix (primitive polynomial x + 1): column i is
  // m_i = m_{i−1} xor (m_{i−1} >> 1) from m_0 = 2³¹; and from it the xor of the columns of
  // every byte value at each of the index's four bytes.
  private val secondColumns: Array[Int] = Array.iterate(0x80000000, 32)(m => m ^ (m >>> 1))
  private val secondBytes: Array[Int]   = Array.tabulate(4 * 256) { k =>
    val (byte, value) = (k / 256, k % 256)
    (0 until 8)
      .filter(b => (value & (1 << b)) != 0)
      .map(b => secondColumns(8 * byte + b))
      .foldLeft(0)(_ ^ _)
  }

  /** The second Sobol dimension at `index`, as 32 bits (the first is the bit reversal). */
  def sobolSecond(index: Int): Int =
    secondBytes(index & 0xff) ^ secondBytes(256 + ((index >>> 8) & 0xff)) ^
      secondBytes(512 + ((index >>> 16) & 0xff)) ^ secondBytes(768 + (index >>> 24))

  /** A Sobol value Owen-scrambled by `key` (pbrt-v4's `FastOwenScrambler`), then digitally
    * shifted by more of the key's bits, which makes each point exactly uniform.
    */
  def scramble(value: Int, key: Long): Int =
    val seed = key.toInt
    val r0   = Integer.reverse(value)
    val r1   = r0 ^ (r0 * 0x3d20adea)
    val r2   = (r1 + seed) * ((seed >>> 16) | 1)
    val r3   = r2 ^ (r2 * 0x05526c56)
    val r4   = r3 ^ (r3 * 0x53a22864)
    Integer.reverse(r4) ^ (key >>> 32).toInt

  /** Element `i` of a pseudo-random permutation of 0 until `n` chosen by `p` (Kensler's hashed
    * permutation, as pbrt-v4's `PermutationElement`): a bijection of 0 until `n` for each `p`.
    */
  def permute(i: Int, n: Int, p: Int): Int =
    // Perf: w, the mask of all ones up to n − 1's top bit, by the usual shifts.
    var w = n - 1
    w |= w >>> 1
    w |= w >>> 2
    w |= w >>> 4
    w |= w >>> 8
    w |= w >>> 16
    // Perf: cycle-walking in ints, as Kensler's paper gives it: an index outside 0 until n is
    // hashed again until it falls inside.
    var v = i
    while
      v ^= p; v *= 0xe170893d; v ^= p >>> 16; v ^= (v & w) >>> 4
      v ^= p >>> 8; v *= 0x0929eb3f; v ^= p >>> 23; v ^= (v & w) >>> 1
      v *= 1 | p >>> 27; v *= 0x6935fa69; v ^= (v & w) >>> 11; v *= 0x74dcb303
      v ^= (v & w) >>> 2; v *= 0x9e501cc3; v ^= (v & w) >>> 2; v *= 0xc860a3df
      v &= w; v ^= v >>> 5
      v >= n // v ≤ w < 2³¹: never negative
    do ()
    ((v + (p & 0xffffffffL)) % n).toInt
