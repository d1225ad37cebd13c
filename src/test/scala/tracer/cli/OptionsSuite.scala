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

  test("numbers are written as the scene's: hexadecimal, Java suffixes and commas are malformed"):
    for (option, value) <- List(
        "-x" -> "0x10",
        "-y" -> "1,5",
        "-p" -> "2L",
        "-z" -> "2f",
        "-w" -> "2d",
        "-h" -> "0x1p3",
        "-g" -> "2f",
        "-g" -> "0x1p1",
        "-g" -> " 2.2",
        "-z" -> "1e",
        "-z" -> "."
      )
    do assert(usageError(option, value, "o.ppm").contains(s"'$value'"), s"$option $value")
    // The scene's own grammar: a sign, a leading or trailing point and an exponent are numbers.
    assertEquals(options("-x", "+5", "o.ppm").columns, Some(5))
    assertEquals(options("-z", ".5", "-w", "2.", "-h", "1e-1", "o.ppm").zoom, Some(0.5))

  test("an integer beyond Int's range names the option and what it takes"):
    assertEquals(
      usageError("-x", "3000000000", "o.ppm"),
      "--xpix takes integers from -2147483648 to 2147483647, got '3000000000'"
    )

  test("an option given twice is named as given twice, not as unknown"):
    assertEquals(usageError("-x", "16", "-x", "8", "o.ppm"), "-x is given more than once")
    assertEquals(usageError("-q", "-q", "o.ppm"), "-q is given more than once")
    assertEquals(
      usageError("--xpix", "8", "-x", "8", "o.ppm"),
      "-x is given more than once (as -x and --xpix)"
    )
    assert(usageError("--bogus", "o.ppm").startsWith("Unknown option --bogus"))

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

  test("-a accepts 1 to CameraConfig.MaxSamples (16), and the usage and the error say so"):
    val max = tracer.render.CameraConfig.MaxSamples
    assertEquals(max, 16)
    assertEquals(options("-a", "1", "o.ppm").samples, 1)
    assertEquals(options("-a", s"$max", "o.ppm").samples, max)
    assert(usageError("-a", s"${max + 1}", "o.ppm").contains(s"from 1 to $max"))
    assert(Options.usage.contains(s"1 to $max (default 1)"), Options.usage)

  // Each mode does something other than render OUTPUT; before they were exclusive, the order of
  // the cases decided (--size --stack x dropped --stack without a word).
  private val modes = List(
    "--version" -> List("--version"),
    "--batch"   -> List("--batch", "list.txt"),
    "--size"    -> List("--size"),
    "--stack"   -> List("--stack", "a.ppm")
  )

  test("every two of --version, --batch, --size and --stack are a usage error naming both"):
    for
      (a, aArgs) <- modes
      (b, bArgs) <- modes
      if a != b
    do
      val message = usageError((aArgs ++ bArgs :+ "out.png")*)
      val first   = List(a, b).minBy(m => modes.indexWhere(_._1 == m))
      val second  = List(a, b).maxBy(m => modes.indexWhere(_._1 == m))
      assertEquals(
        message,
        s"$first and $second cannot be used together: each is a mode of its own"
      )

  test("--size --stack x is refused, not read as --size alone"):
    assertEquals(
      Options.parse(List("--size", "--stack", "x.ppm", "out.png")),
      Command.UsageError("--size and --stack cannot be used together: each is a mode of its own")
    )

  test("three modes at once are named all three"):
    assert(
      usageError("--size", "--version", "--stack", "a.ppm", "o.png")
        .startsWith("--version, --size and --stack cannot be used together"),
      usageError("--size", "--version", "--stack", "a.ppm", "o.png")
    )

  test("one mode alone is still that mode"):
    Options.parse(List("--size")) match
      case Command.Size(_) => ()
      case other           => fail(s"expected --size, got $other")

  test("two OUTPUTs are a usage error"):
    assert(usageError("a.png", "b.png").contains("b.png"))
