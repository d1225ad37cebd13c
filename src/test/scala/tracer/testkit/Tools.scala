package tracer.testkit

import java.nio.file.{Files, Path}

/** Outside programs some tests drive (ImageMagick, OpenEXR's tools): where they are, and the
  * rule for a missing one: under CI (`CI` set) the test fails, elsewhere it is skipped saying why.
  */
object Tools:

  /** The first executable called `name` on the PATH. */
  def find(name: String): Option[Path] =
    sys.env
      .getOrElse("PATH", "")
      .split(java.io.File.pathSeparator)
      .iterator
      .filter(_.nonEmpty)
      .map(Path.of(_, name))
      .find(Files.isExecutable(_))

  /** The program `name`, or the test stops: failed under CI, skipped elsewhere. */
  def require(name: String, install: String)(using munit.Location): Path =
    find(name) match
      case Some(path) => path
      case None       =>
        val why = s"needs $name ($install; .ci/run installs it)"
        if sys.env.contains("CI") then munit.Assertions.fail(why)
        else
          munit.Assertions.assume(false, why)
          Path.of(name)
