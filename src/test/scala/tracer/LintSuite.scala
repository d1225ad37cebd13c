package tracer

import java.nio.file.{Files, Path}
import java.util.Comparator
import java.util.concurrent.TimeUnit

/** The code analysis itself (`./sbt lint`, docs/analysis.md), run on scratch trees: a finding
  * fails it and is named by file and line; the `// Why:`/`// Perf:` and `nosemgrep` rules let
  * exactly what they promise stand; and the report's list must match the tree.
  */
class LintSuite extends munit.FunSuite:

  private val home = Path.of("").toAbsolutePath

  /** A scratch tree holding the analysis (script, rules, driver) and `files`. */
  private val scratch = FunFixture[Path](
    _ =>
      val d = Files.createTempDirectory("tracer-lint")
      for name <- List("scripts/lint.sh", "lint/lint.py", "lint/semgrep.yml", ".semgrepignore") do
        Files.createDirectories(d.resolve(name).getParent)
        Files.copy(home.resolve(name), d.resolve(name))
      d
    ,
    d => Files.walk(d).sorted(Comparator.reverseOrder()).forEach(p => Files.delete(p))
  )

  private def write(d: Path, name: String, text: String): Unit =
    Files.createDirectories(d.resolve(name).getParent)
    Files.writeString(d.resolve(name), text): Unit

  /** Runs scripts/lint.sh in `d` with `args`: (exit status, what it printed). */
  private def lint(d: Path, args: String*): (Int, String) =
    val out     = d.resolve("lint.out")
    val process = ProcessBuilder(("bash" :: "scripts/lint.sh" :: args.toList)*)
      .directory(d.toFile)
      .redirectErrorStream(true)
      .redirectOutput(out.toFile)
      .start()
    assert(process.waitFor(10, TimeUnit.MINUTES), "lint.sh did not finish")
    (process.exitValue, Files.readString(out))

  scratch.test("a file with a null and an asInstanceOf fails the analysis, named with its lines"):
    d =>
      write(
        d,
        "src/main/scala/x/Bad.scala",
        """package x
          |
          |object Bad:
          |  val name: String = null
          |  def size(a: Any): Int = a.asInstanceOf[Int]
          |""".stripMargin
      )
      write(d, "src/main/scala/x/Good.scala", "package x\n\nobject Good:\n  val n = 1\n")
      val (status, out) = lint(d, "src")
      assertEquals(status, 1, out)
      assert(out.contains("src/main/scala/x/Bad.scala:4:22: no-null:"), out)
      assert(out.contains("src/main/scala/x/Bad.scala:5:28: no-as-instance-of:"), out)
      assert(!out.contains("Good.scala"), out)

  scratch.test("x.isNaN and x.isInfinite fail in main code; java.lang.Double's tests do not"): d =>
    write(
      d,
      "src/main/scala/x/Nan.scala",
      """package x
          |
          |object Nan:
          |  def bad(x: Double): Boolean = x.isNaN || x.isInfinite
          |  def good(x: Double): Boolean = java.lang.Double.isNaN(x) // not x.isNaN
          |  val text = "x.isNaN in a string"
          |""".stripMargin
    )
    write(
      d,
      "src/test/scala/x/NanSuite.scala",
      "package x\n\nobject NanSuite:\n  def t(x: Double): Boolean = x.isNaN\n"
    )
    val (status, out) = lint(d, "src")
    assertEquals(status, 1, out)
    assert(out.contains("src/main/scala/x/Nan.scala:4:34: boxed-nan-test:"), out)
    assert(out.contains("src/main/scala/x/Nan.scala:4:45: boxed-nan-test:"), out)
    assert(!out.contains("Nan.scala:5:"), out)
    assert(!out.contains("Nan.scala:6:"), out)
    assert(!out.contains("NanSuite.scala"), out)

  scratch.test("StrictMath.pow fails in main code, not in comments, strings or tests"): d =>
    write(
      d,
      "src/main/scala/x/Power.scala",
      """package x
          |
          |object Power:
          |  def bad(x: Double): Double = StrictMath.pow(x, 3)
          |  def good(x: Double): Double = tracer.math.Pow.pow(x, 3) // not StrictMath.pow(x, 3)
          |  val text = "StrictMath.pow(x, 3) in a string"
          |""".stripMargin
    )
    write(
      d,
      "src/test/scala/x/PowerSuite.scala",
      "package x\n\nobject PowerSuite:\n  def t(x: Double): Double = StrictMath.pow(x, 2)\n"
    )
    val (status, out) = lint(d, "src")
    assertEquals(status, 1, out)
    assert(out.contains("src/main/scala/x/Power.scala:4:32: strict-pow:"), out)
    assert(!out.contains("Power.scala:5:"), out)
    assert(!out.contains("Power.scala:6:"), out)
    assert(!out.contains("PowerSuite.scala"), out)

  scratch.test("var, while and throw stand exactly where a Why: or Perf: comment covers them"): d =>
    write(
      d,
      "src/main/scala/x/Loops.scala",
      """package x
          |
          |object Loops:
          |  // Perf: a counted loop over an array, no boxing.
          |  def sum(a: Array[Int]): Int =
          |    var s = 0
          |    var i = 0
          |
          |    while i < a.length do
          |      s += a(i)
          |      i += 1
          |    s
          |
          |  def count(n: Int): Int =
          |    // Perf: the counter and its loop, one paragraph.
          |    var i = 0
          |    while i < n do i += 1
          |
          |    var uncovered = i
          |    uncovered
          |
          |  def fail(): Nothing = throw IllegalStateException("x") // Why: a bug, as require.
          |  def bare(): Nothing = throw IllegalStateException("y")
          |  val text = "a var, a while and a null in a string"
          |  // a var, a while, a throw and a null in a comment
          |""".stripMargin
    )
    val (status, out) = lint(d, "src")
    assertEquals(status, 1, out)
    val named = out.linesIterator.filter(_.startsWith("src/")).map(_.split(": ").head).toList
    assertEquals(
      named,
      List("src/main/scala/x/Loops.scala:19:5", "src/main/scala/x/Loops.scala:23:25"),
      out
    )

  scratch.test("nosemgrep needs the rule and a reason, and must suppress something"): d =>
    write(
      d,
      "src/main/scala/x/Kept.scala",
      """package x
          |
          |object Kept:
          |  def a(o: Option[Int]): Int = o.get // nosemgrep: option-get — checked by the caller
          |  def b(o: Option[Int]): Int = o.get // nosemgrep: option-get
          |  // nosemgrep: no-null — nothing here any more
          |  def c(o: Option[Int]): Int = o.getOrElse(0)
          |  // nosemgrep: no-null — a Java API's "no value"
          |  val d: String = null
          |""".stripMargin
    )
    val (status, out) = lint(d, "src")
    assertEquals(status, 1, out)
    val problems = out.linesIterator.filter(_.startsWith("lint: src/")).toList
    assertEquals(
      problems.map(_.split(" ")(1)),
      List("src/main/scala/x/Kept.scala:5:", "src/main/scala/x/Kept.scala:6:"),
      out
    )
    assert(problems.head.contains("without a reason"), out)
    assert(problems(1).contains("suppresses nothing"), out)
    assert(!out.linesIterator.exists(_.startsWith("src/")), out)

  scratch.test("docs/analysis.md must list what stands: out of date fails, --write-doc mends it"):
    d =>
      write(
        d,
        "src/main/scala/x/Hot.scala",
        "package x\n\nobject Hot:\n  var calls = 0 // Why: a counter the tests read.\n"
      )
      val stale = "# Code analysis\n\n<!-- lint:begin (generated by scripts/lint.sh --write-doc;" +
        " do not edit by hand) -->\nnothing\n<!-- lint:end -->\n"
      write(d, "docs/analysis.md", stale)
      val (status, out) = lint(d)
      assertEquals(status, 1, out)
      assert(out.contains("docs/analysis.md: its list of findings and suppressions is out of date"))
      assertEquals(lint(d, "--write-doc")._1, 0)
      val doc = Files.readString(d.resolve("docs/analysis.md"))
      assert(
        doc.contains(
          "| `src/main/scala/x/Hot.scala` | `Why:` | 1 × `var-without-why` | a counter the tests read. |"
        ),
        doc
      )
      assertEquals(lint(d)._1, 0)
