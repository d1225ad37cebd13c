package tracer.cli

/** `man tracer` is made from `--help`'s usage: every option and note of the one is in the other. */
class ManPageSuite extends munit.FunSuite:

  private val page = ManPage.roff(Options.usage, "2.0.0")

  test("the page is roff for section 1 of this version, with its sections in order"):
    assert(page.startsWith(".TH TRACER 1 \"\" \"tracer 2.0.0\" \"User Commands\"\n"), page)
    val sections = page.linesIterator.filter(_.startsWith(".SH ")).toList
    assertEquals(
      sections,
      List(
        "NAME",
        "SYNOPSIS",
        "DESCRIPTION",
        "OPTIONS",
        "NOTES",
        "ENVIRONMENT",
        "FILES",
        "SEE ALSO"
      )
        .map(".SH " + _)
    )

  test("the page says where the scene schema is and how editors complete scenes with it"):
    val text = page.replace("\\-", "-")
    for words <- List(
        "/usr/share/tracer/scene.xsd",
        "xsi:noNamespaceSchemaLocation",
        "redhat.vscode-xml",
        "xml.fileAssociations",
        "IntelliJ",
        "xmllint"
      )
    do assert(text.contains(words), words)

  test("every option of the usage is a tagged paragraph with its text, hyphens escaped"):
    val options = Options.usage.linesIterator.filter(_.startsWith("  ")).map(_.trim).toList
    assert(options.length >= 15, options)
    val lines = page.linesIterator.toList
    for line <- options do
      val spec  = line.take(line.indexOf("  ")).replace("-", "\\-")
      val about = line.drop(line.indexOf("  ")).trim.replace("-", "\\-")
      val at    = lines.indexOf(s".B $spec")
      assert(at > 0 && lines(at - 1) == ".TP", s"$spec missing")
      assertEquals(lines(at + 1), about)

  test(
    "the header and the notes of the usage are there, and no line starts a roff request by chance"
  ):
    assert(page.contains("tracer: renders an XML scene"), page)
    assert(page.contains("2 usage error."), page)
    val requests = page.linesIterator.filter(l => l.startsWith(".") || l.startsWith("'"))
    for line <- requests do assert(line.matches("\\.(TH|SH|TP|B|br) ?.*"), line)

  test("text that would be a request or an escape is made plain"):
    val odd = ManPage.roff("head\nUsage: x\n\n  --a  .starts with a dot \\ and a backslash\n", "1")
    assert(odd.contains("\\&.starts with a dot \\e and a backslash"), odd)
