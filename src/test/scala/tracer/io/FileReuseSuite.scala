package tracer.io

import java.nio.file.{Files, Path}
import java.nio.file.attribute.FileTime

/** [[FileReuse]]: a batch's frames read a file once while it is unchanged, and no more than the
  * last two frames' files are kept.
  */
class FileReuseSuite extends munit.FunSuite:

  private val dir = FunFixture[Path](
    _ => Files.createTempDirectory("reuse"),
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete(_))
  )

  /** A reuse memo and a reader of a file's text that counts its reads. */
  private final class Counted:
    val reuse = FileReuse[String]()
    // Why: the number of reads is what these tests observe.
    var reads                                     = 0
    def apply(path: Path): Either[String, String] =
      reuse(path) { p =>
        reads += 1
        if Files.exists(p) then Right(Files.readString(p)) else Left("no such file")
      }

  dir.test("an unchanged file is read once, whichever frame asks, and shared"): d =>
    val file = Files.writeString(d.resolve("t.txt"), "one")
    val c    = Counted()
    assertEquals(c(file), Right("one"))
    c.reuse.nextFrame()
    assertEquals(c(file), Right("one"))
    c.reuse.nextFrame()
    assertEquals(c(d.resolve("./t.txt")), Right("one"), "the same file by another path")
    assertEquals(c.reads, 1)

  dir.test("a file with another size or time is read again"): d =>
    val file = Files.writeString(d.resolve("t.txt"), "one")
    val c    = Counted()
    assertEquals(c(file), Right("one"))
    Files.writeString(file, "three") // another size
    c.reuse.nextFrame()
    assertEquals(c(file), Right("three"))
    Files.writeString(file, "seven") // the same size: only the time says
    Files.setLastModifiedTime(file, FileTime.fromMillis(86_400_000L))
    c.reuse.nextFrame()
    assertEquals(c(file), Right("seven"))
    assertEquals(c.reads, 3)

  dir.test("a failed read is not kept: the next frame tries again"): d =>
    val file = d.resolve("later.txt")
    val c    = Counted()
    assertEquals(c(file), Left("no such file"))
    Files.writeString(file, "here")
    c.reuse.nextFrame()
    assertEquals(c(file), Right("here"))
    assertEquals(c.reads, 2)
    assertEquals(c.reuse.size, 1)

  dir.test("a file that neither this frame nor the one before used is let go"): d =>
    val a = Files.writeString(d.resolve("a.txt"), "a")
    val b = Files.writeString(d.resolve("b.txt"), "b")
    val c = Counted()
    assertEquals(List(c(a), c(b)), List(Right("a"), Right("b")))
    c.reuse.nextFrame()
    assertEquals(c(b), Right("b"))
    assertEquals(c.reuse.size, 2, "a is still the previous frame's")
    c.reuse.nextFrame()
    assertEquals(c.reuse.size, 1, "only b, which the previous frame used")
    assertEquals(c(a), Right("a"))
    assertEquals(c.reads, 3, "a was read again")
