package tracer.io

import java.lang.management.ManagementFactory
import java.nio.file.Files
import tracer.image.{Bitmap, Colour, Png}

/** Saving a picture: a PNG is encoded on the threads it is given (`-p`), and only those. */
class ImagesSuite extends munit.FunSuite:

  // 400 rows: 13 bands of the encoder, enough for a worker each.
  private val picture = Bitmap.tabulate(300, 400, 255)((x, y) => Colour(x / 300.0, y / 400.0, 0.5))

  /** The threads the JVM started while `body` ran, the fewest of three tries (a thread of the
    * JVM's own may start during one).
    */
  private def started(body: => Unit): Long =
    val threads = ManagementFactory.getThreadMXBean
    (1 to 3).map { _ =>
      val before = threads.getTotalStartedThreadCount
      body
      threads.getTotalStartedThreadCount - before
    }.min

  test("a PNG saved with one thread is encoded on the calling thread alone, the same bytes"):
    val dir = Files.createTempDirectory("images")
    try
      val one  = dir.resolve("one.png")
      val many = dir.resolve("many.png")
      assertEquals(started(assertEquals(Images.save(picture, one, threads = 1), Right(()))), 0L)
      assert(started(assertEquals(Images.save(picture, many, threads = 3), Right(()))) >= 1L)
      assert(Files.readAllBytes(one).sameElements(Files.readAllBytes(many)))
      assertEquals(Png.read(Files.readAllBytes(one)), Right(picture))
    finally
      Files.list(dir).forEach(Files.delete)
      Files.delete(dir)
