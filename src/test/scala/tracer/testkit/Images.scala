package tracer.testkit

import java.nio.file.{Files, Path}
import munit.{Assertions, Location}
import tracer.image.{Bitmap, ImageFile, Png}

/** Comparing rendered images with reference images, leaving evidence behind on a mismatch. */
trait Images:
  self: Assertions =>

  /** The image in `path`, or a test failure saying why it cannot be read. */
  def readImage(path: Path)(using Location): Bitmap =
    ImageFile.decode(Files.readAllBytes(path)).fold(why => fail(s"$path: $why"), identity)

  /** The image in test resource `name`. */
  def resourceImage(name: String)(using Location): Bitmap =
    val stream = Option(getClass.getResourceAsStream(name)).getOrElse(fail(s"no resource $name"))
    try ImageFile.decode(stream.readAllBytes()).fold(why => fail(s"$name: $why"), identity)
    finally stream.close()

  /** Asserts that `actual` matches the committed reference picture `src/test/resources/golden/NAME.png`.
    * With the environment variable `GOLDEN_UPDATE=true`, writes `actual` as the new reference first.
    */
  def assertGolden(actual: Bitmap, name: String)(using Location): Unit =
    val reference = Path.of("src/test/resources/golden", s"$name.png")
    if sys.env.get("GOLDEN_UPDATE").contains("true") then
      Files.write(reference, Png.encode(actual)): Unit
    assertImageClose(actual, readImage(reference), name)

  /** Asserts that `actual` matches `expected` to within `tolerance` levels in every sample; on a
    * mismatch, writes the actual image to `target/golden/NAME-actual.png` for a person to look at.
    */
  def assertImageClose(actual: Bitmap, expected: Bitmap, name: String, tolerance: Int = 2)(using
      Location
  ): Unit =
    assertEquals((actual.width, actual.height), (expected.width, expected.height), s"$name: size")
    val difference = actual.maxSampleDifference(expected)
    if difference > tolerance then
      val evidence = Path.of("target", "golden", s"$name-actual.png")
      Files.createDirectories(evidence.getParent)
      Files.write(evidence, Png.encode(actual))
      fail(
        s"$name differs from its reference by up to $difference levels (allowed $tolerance); see $evidence"
      )
