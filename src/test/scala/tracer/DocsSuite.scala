package tracer

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*

/** The documentation a user clones is whole: every page that a source file, script or page cites
  * exists in the repository, every relative link resolves, and nothing points outside it.
  */
class DocsSuite extends munit.FunSuite:

  private val home = Path.of("").toAbsolutePath

  /** Every text file of the project that may cite a page. */
  private val citing: List[Path] =
    val roots = List("src", "bench/src", "scripts", "docs", "project").map(home.resolve)
    val files = roots.filter(Files.isDirectory(_)).flatMap(r => Files.walk(r).iterator.asScala)
    (files ++ List("README.md", "build.sbt", ".ci/run", "tracer", "sbt").map(home.resolve))
      .filter(p => Files.isRegularFile(p))
      .filter(p =>
        List(".scala", ".md", ".sh", ".sbt", "run", "tracer", "sbt").exists(p.toString.endsWith)
      )
      .filterNot(_.startsWith(home.resolve("src/test/resources/extract-docs")))
      .filterNot(_.endsWith("DocsSuite.scala")) // this file names the rules, not pages

  private val pageName = """[A-Za-z0-9_./-]*[A-Za-z0-9_-]\.md\b""".r

  /** A cited page exists beside the citing file, from the project's root, or in docs/. */
  private def exists(from: Path, name: String): Boolean =
    List(from.getParent.resolve(name), home.resolve(name), home.resolve("docs").resolve(name))
      .exists(Files.isRegularFile(_))

  test("every *.md that a source, script or page cites exists in the repository"):
    val missing = for
      file <- citing
      name <- pageName.findAllIn(Files.readString(file)).toList.distinct
      if !exists(file, name)
    yield s"${home.relativize(file)} cites $name"
    assertEquals(missing, Nil)

  test("the reference pages exist: scene format, rendering, command line, scripts"):
    for page <- List("scene-format", "rendering", "cli", "movie", "guide", "farm") do
      assert(Files.isRegularFile(home.resolve(s"docs/$page.md")), page)

  test("every relative link in README.md and docs/ resolves"):
    val link = """\]\(([^)#:]+)(#[^)]*)?\)""".r
    // Code spans are not links (an API page's `def walk[A](…)`).
    val code   = "`[^`\n]*`".r
    val pages  = home.resolve("README.md") :: citing.filter(_.startsWith(home.resolve("docs")))
    val broken = for
      page <- pages.filter(_.toString.endsWith(".md"))
      text = code.replaceAllIn(Files.readString(page), "")
      target <- link.findAllMatchIn(text).map(_.group(1)).toList
      if !Files.exists(page.getParent.resolve(target))
    yield s"${home.relativize(page)} links to $target"
    assertEquals(broken, Nil)

  test("no page points outside the repository"):
    val outside = for
      file <- citing
      if Files.readString(file).contains("../shared")
    yield home.relativize(file).toString
    assertEquals(outside, Nil)
