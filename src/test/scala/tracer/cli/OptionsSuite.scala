package tracer.cli

/** Parsing the command line of cli.md. */
class OptionsSuite extends munit.FunSuite:

  private def options(args: String*): Options = Options.parse(args) match
    case Command.Render(o) => o
    case other             => fail(s"expected options, got $other")

  private def usageError(args: String*): String = Options.parse(args) match
    case Command.UsageError(message) => message
    case other                       => fail(s"expected a usage error, got $other")

  test("OUTPUT alone gives the defaults"):
    assertEquals(options("out.ppm"), Options(output = "out.ppm"))

  test("every option takes its value from the next argument"):
    val o = options(
      "-q",
      "-r",
      "3",
      "-t",
      "-p",
      "4",
      "-z",
      "2.5",
      "-x",
      "320",
      "-y",
      "200",
      "-w",
      "2",
      "-h",
      "1.5",
      "-a",
      "3",
      "out.png"
    )
    assertEquals(
      o,
      Options(
        "out.png",
        true,
        3,
        true,
        Some(4),
        Some(2.5),
        Some(320),
        Some(200),
        Some(2),
        Some(1.5),
        3,
        antialiased = true
      )
    )

  test("options may come before or after OUTPUT, in any order"):
    assertEquals(options("out.png", "-x", "10", "-q"), options("-q", "-x", "10", "out.png"))

  test("--help asks for the usage; -h is the height"):
    Options.parse(List("--help")) match
      case Command.Help(usage) => assert(usage.contains("-h, --height"), usage)
      case other               => fail(other.toString)
    assertEquals(options("-h", "2", "o.ppm").height, Some(2.0))

  test("a missing OUTPUT is a usage error"):
    assert(usageError().contains("OUTPUT"))
    assert(usageError("-q").contains("OUTPUT"))

  test("an unknown option is a usage error"):
    assert(usageError("-k", "o.ppm").contains("-k"))

  test("a missing value is a usage error"):
    assert(usageError("o.ppm", "-r").nonEmpty)

  test("malformed values are usage errors"):
    assert(usageError("-x", "3.5", "o.ppm").contains("3.5"))
    assert(usageError("-z", "abc", "o.ppm").contains("abc"))
    assert(usageError("-r", "two", "o.ppm").contains("two"))

  test("values out of range are usage errors"):
    assert(usageError("-r", "-1", "o.ppm").contains("-r"))
    assert(usageError("-p", "0", "o.ppm").contains("-p"))
    assert(usageError("-x", "0", "o.ppm").contains("-x"))
    assert(usageError("-y", "-5", "o.ppm").contains("-y"))
    assert(usageError("-z", "0", "o.ppm").contains("-z"))
    assert(usageError("-w", "-1", "o.ppm").contains("-w"))
    assert(usageError("-h", "NaN", "o.ppm").contains("-h"))
    assert(usageError("-z", "Infinity", "o.ppm").contains("-z"))
    assert(usageError("-a", "0", "o.ppm").contains("-a"))
    assert(usageError("-a", "17", "o.ppm").contains("-a"))

  test("-a accepts 1 to 16"):
    assertEquals(options("-a", "1", "o.ppm").samples, 1)
    assertEquals(options("-a", "16", "o.ppm").samples, 16)

  test("two OUTPUTs are a usage error"):
    assert(usageError("a.png", "b.png").contains("b.png"))
