package tracer.testkit

import java.nio.file.{Files, Path}

/** The outside programs a suite drives, such as an independent renderer used as an oracle. */
object Tools:

  /** True when the tests run in CI (the environment variable `CI` is set, as CI services and
    * `.ci/run` set it): there a missing tool is a failure, never a silent skip.
    */
  def inCi: Boolean = sys.env.contains("CI")

  /** Goes on when `program` is executable; otherwise skips the suite on a developer's machine,
    * and fails it in CI, with `why` (which names how to install it).
    */
  def needs(program: Path, why: String)(using munit.Location): Unit =
    if !Files.isExecutable(program) then
      if inCi then munit.Assertions.fail(s"$program is missing and CI is set: $why")
      else munit.Assertions.assume(false, s"$program is missing: $why")
