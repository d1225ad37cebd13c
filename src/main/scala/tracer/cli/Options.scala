package tracer.cli

import scopt.{OEffect, OParser}
import tracer.BuildInfo
import tracer.image.Encoding
import tracer.render.{CameraConfig, Integrator, SamplerKind}

/** The command line as given: each optional value is `None` when its option was absent.
  *
  * @param output  the image file to write (OUTPUT)
  * @param quick   `-q`, quick mode
  * @param depth   `-r d`, the reflection depth
  * @param timing  `-t`, print `Tracetime: N ms`
  * @param threads `-p n`, the number of render threads
  * @param zoom    `-z`, the camera zoom Z
  * @param columns `-x`, the image width in pixels X
  * @param rows    `-y`, the image height in pixels Y
  * @param width   `-w`, the image width in world units W
  * @param height  `-h`, the image height in world units H
  * @param samples `-a n`, n × n antialiasing samples a pixel
  * @param encoding `-g`, how the output is encoded
  * @param encodingGiven true when `-g` was given at all (even `-g 1`), which a `.pfm` or `.exr`
  *   output refuses
  * @param band    `-R a:b`, the rows a until b to render, when only a band is wanted
  * @param input   `-i FILE`, the scene file; standard input when absent
  * @param version `--version`, print the version instead of rendering
  * @param size    `--size`, print the picture's size `X Y` instead of rendering
  * @param stack   `--stack FILE`, repeated: write OUTPUT as these images one below the other
  *   instead of rendering (how `scripts/still.sh` joins its bands)
  * @param batch   `--batch LIST`: render every frame the list names, in this one process
  * @param pathMode    `-m path`: path tracing instead of Whitted's tracer
  * @param pathSamples `-s N`, path mode's samples a pixel
  * @param seed        `--seed S`, path mode's noise pattern
  * @param sampler     `--sampler KIND`, path mode's sampler
  * @param antialiased true when `-a` was given (a usage error in path mode, even `-a 1`)
  */
final case class Options(
    output: String = "",
    quick: Boolean = false,
    depth: Int = CameraConfig.DefaultDepth,
    timing: Boolean = false,
    threads: Option[Int] = None,
    zoom: Option[Double] = None,
    columns: Option[Int] = None,
    rows: Option[Int] = None,
    width: Option[Double] = None,
    height: Option[Double] = None,
    samples: Int = 1,
    encoding: Encoding = Encoding.Linear,
    encodingGiven: Boolean = false,
    band: Option[Range] = None,
    input: Option[String] = None,
    version: Boolean = false,
    size: Boolean = false,
    stack: List[String] = Nil,
    batch: Option[String] = None,
    pathMode: Boolean = false,
    pathSamples: Option[Int] = None,
    seed: Option[Int] = None,
    sampler: Option[SamplerKind] = None,
    antialiased: Boolean = false
)

/** What the command line asks for: a render, the usage text, or a usage error. */
enum Command:
  /** Render with these options. */
  case Render(options: Options)

  /** Print this usage text and exit successfully (`--help`). */
  case Help(usage: String)

  /** Print `tracer VERSION` and exit successfully (`--version`). */
  case Version(line: String)

  /** Render every frame of the batch list `list` with these options (`--batch`). */
  case Batch(options: Options, list: String)

  /** Print the picture's size `X Y` that these options and the scene give (`--size`). */
  case Size(options: Options)

  /** Write `output` as the images `bands` one below the other (`--stack`). */
  case Stack(bands: List[String], output: String)

  /** Report this usage error and exit with status 2. */
  case UsageError(message: String)

/** The `tracer` command line (cli.md), parsed with scopt. */
object Options:

  /** Parses `args` into the command they ask for. Never prints and never exits. */
  def parse(args: Seq[String]): Command =
    val (result, effects) = OParser.runParser(parser, args, Options())
    val errors   = effects.collect { case OEffect.ReportError(message) => clearer(message, args) }
    val conflict = result.flatMap(pathConflict)
    if effects.exists { case OEffect.DisplayToOut(_) => true; case _ => false } then
      Command.Help(usage)
    else
      (result, errors) match
        case (Some(options), Nil) if modes(options).length > 1 =>
          val named = modes(options)
          Command.UsageError(
            s"${named.init.mkString(", ")} and ${named.last} cannot be used together: " +
              "each is a mode of its own"
          )
        case (Some(_), Nil) if conflict.isDefined    => Command.UsageError(conflict.mkString)
        case (Some(options), Nil) if options.version =>
          Command.Version(s"tracer ${BuildInfo.version}")
        case (Some(options @ Options(batch = Some(list))), Nil) =>
          if options.output.nonEmpty then
            Command.UsageError(
              s"--batch takes no OUTPUT: the list names them (got ${options.output})"
            )
          else if options.input.isDefined then
            Command.UsageError("--batch takes no -i: the list names the scenes")
          else Command.Batch(options, list)
        case (Some(options), Nil) if options.output.isEmpty && !options.size =>
          Command.UsageError("Missing argument OUTPUT")
        case (Some(options), Nil) if options.size           => Command.Size(options)
        case (Some(options), Nil) if options.stack.nonEmpty =>
          Command.Stack(options.stack, options.output)
        case (Some(options), Nil) => Command.Render(options)
        case (_, first :: _)      => Command.UsageError(first)
        case (None, Nil)          => Command.UsageError("invalid arguments")

  /** The options of one frame of a batch: `args`, render options alone, applied on top of
    * `base` (the command line's, with the frame's scene and output), or why they cannot be.
    */
  def forFrame(base: Options, args: Seq[String]): Either[String, Options] =
    val (result, effects) = OParser.runParser(parser, args, base)
    val errors = effects.collect { case OEffect.ReportError(message) => clearer(message, args) }
    val help   = effects.exists { case OEffect.DisplayToOut(_) => true; case _ => false }
    result match
      case _ if help || errors.nonEmpty =>
        Left(errors.headOption.getOrElse("--help is no render option"))
      case Some(options)
          if options.output != base.output || options.input != base.input ||
            modes(options) != modes(base) || options.version != base.version =>
        Left("a frame's options are render options: no OUTPUT, -i or mode of its own")
      case Some(options) => pathConflict(options).toLeft(options)
      case None          => Left("invalid options")

  /** Why path mode's options and these options cannot go together, if they cannot: `-s`,
    * `--seed` and `--sampler` need `-m path`, and `-a` and `-q` are Whitted's alone.
    */
  private def pathConflict(options: Options): Option[String] =
    if options.pathMode then
      if options.antialiased then
        Some("-a is Whitted's antialiasing: with -m path give -s N samples instead")
      else if options.quick then Some("-q is a Whitted preview and cannot go with -m path")
      else None
    else if options.pathSamples.isDefined then Some("-s needs -m path")
    else if options.seed.isDefined then Some("--seed needs -m path")
    else if options.sampler.isDefined then Some("--sampler needs -m path")
    else None

  /** The modes that `options` asks for, of `--version`, `--batch`, `--size` and `--stack`, which
    * exclude each other (each does something else than render OUTPUT).
    */
  private def modes(options: Options): List[String] =
    List(
      "--version" -> options.version,
      "--batch"   -> options.batch.isDefined,
      "--size"    -> options.size,
      "--stack"   -> options.stack.nonEmpty
    ).collect { case (name, true) => name }

  /** The Java this process runs on, as the last line of `--help` names it (`--version` prints
    * `tracer VERSION` alone, as the command's specification says).
    */
  private[cli] def javaLine: String =
    def property(name: String) = sys.props.getOrElse(name, "unknown")
    s"Java ${property("java.version")} (${property("java.vendor")}) at ${property("java.home")}"

  /** The usage text of `--help`. */
  def usage: String = OParser.usage(parser)

  /** scopt's `message` said more plainly: an option given twice (which scopt calls unknown) is
    * named as given twice, and a value an option's reader refused says what the option takes.
    */
  private def clearer(message: String, args: Seq[String]): String =
    val unknown = "Unknown option "
    val failed  = "Option (\\S+) failed when given '(.*)'\\. (.*)".r
    message match
      case failed(option, value, reason)     => s"$option $reason, got '$value'"
      case _ if !message.startsWith(unknown) => message
      case _                                 => twice(message.drop(unknown.length), args)

  /** The message for option `named`, which scopt calls unknown: given twice, if it is one of
    * ours, with the spellings used in `args`.
    */
  private def twice(named: String, args: Seq[String]): String =
    spellings
      .find(_.contains(named))
      .map(names => names.filter(args.contains))
      .fold(s"Unknown option $named") {
        case List(one) => s"$one is given more than once"
        case used      => s"$named is given more than once (as ${used.mkString(" and ")})"
      }

  /** Each option's spellings: its short `-x` and long `--xpix` names. */
  private lazy val spellings: List[List[String]] =
    parser.toList
      .filter(o => o.name.nonEmpty)
      .map(o => o.shortOpt.map("-" + _).toList :+ s"--${o.name}")

  // The command line's numbers are written as the scene's are ([+-]?(d+.?d*|.d+)([eE][+-]?d+)?,
  // an integer without point or exponent), not as the JDK's parsers also take them (0x10, 2f,
  // 2d, 0x1p3): a malformed value is a usage error (cli.md). These givens stand before scopt's.
  // Why: scopt's readers report a value they cannot read by throwing; it turns a
  // NumberFormatException into "expects a number" and any other into the option's usage error.
  private given scopt.Read[Int] = scopt.Read.reads { text =>
    if !text.matches("[-+]?[0-9]+") then throw NumberFormatException(text)
    else
      text.toIntOption.getOrElse(
        throw IllegalArgumentException(s"takes integers from ${Int.MinValue} to ${Int.MaxValue}")
      )
  }

  // Why: as the integers' reader above (the scene's reader gives NaN for a malformed number).
  private given scopt.Read[Double] = scopt.Read.reads { text =>
    val value = tracer.io.Decimal.parse(text)
    if java.lang.Double.isNaN(value) then throw NumberFormatException(text) else value
  }

  private val builder = OParser.builder[Options]

  private def positiveDouble(name: String)(v: Double): Either[String, Unit] =
    if v > 0 && v.isFinite then Right(())
    else Left(s"$name must be a number greater than 0, got $v")

  private def atLeast(name: String, min: Int)(v: Int): Either[String, Unit] =
    if v >= min then Right(()) else Left(s"$name must be an integer of at least $min, got $v")

  /** `a:b` with integers 0 ≤ a < b, as the rows a until b; whether b ≤ Y is checked once Y is known. */
  private[cli] def band(text: String): Either[String, Range] =
    text.split(":", -1).map(_.toIntOption) match
      case Array(Some(first), Some(end)) if first >= 0 && first < end => Right(first until end)
      case _ => Left(s"-R must be a:b with integers 0 <= a < b, got '$text'")

  private val parser =
    import builder.*
    OParser.sequence(
      programName("tracer"),
      head(
        "tracer: renders an XML scene (tracer [options] OUTPUT < scene.xml, or -i scene.xml)"
      ),
      opt[Unit]('q', "quick")
        .action((_, o) => o.copy(quick = true))
        .text("quick mode: no shadows, no reflection"),
      opt[Int]('r', "depth")
        .valueName("d")
        .validate(atLeast("-r", 0))
        .action((v, o) => o.copy(depth = v))
        .text(
          "depth: the most reflections and refractions (-m path: bounces) a ray makes (default 5)"
        ),
      opt[String]('m', "mode")
        .valueName("whitted|path")
        .validate(v =>
          if v == "whitted" || v == "path" then Right(())
          else Left(s"-m must be whitted or path, got '$v'")
        )
        .action((v, o) => o.copy(pathMode = v == "path"))
        .text("whitted (the default: versions 1-3 exactly) or path (Monte Carlo path tracing)"),
      opt[Int]('s', "samples")
        .valueName("N")
        .validate(v =>
          if v >= 1 && v <= Integrator.MaxPathSamples then Right(())
          else Left(s"-s must be an integer from 1 to ${Integrator.MaxPathSamples}, got $v")
        )
        .action((v, o) => o.copy(pathSamples = Some(v)))
        .text(s"path mode: N samples a pixel, 1 to ${Integrator.MaxPathSamples} (default 64)"),
      opt[Int]("seed")
        .valueName("S")
        .validate(atLeast("--seed", 0))
        .action((v, o) => o.copy(seed = Some(v)))
        .text("path mode: which noise pattern, 0 <= S < 2^31 (default 0)"),
      opt[String]("sampler")
        .valueName("KIND")
        .validate(v =>
          SamplerKind
            .named(v)
            .map(_ => ())
            .toRight(
              s"--sampler must be ${SamplerKind.values.map(_.name).mkString(" or ")}, got '$v'"
            )
        )
        .action((v, o) => o.copy(sampler = SamplerKind.named(v)))
        .text(
          s"path mode: the random numbers, ${SamplerKind.Default.name} (the default) or independent"
        ),
      opt[Unit]('t', "time")
        .action((_, o) => o.copy(timing = true))
        .text("print 'Tracetime: N ms', the rendering time, on standard output"),
      opt[Int]('p', "threads")
        .valueName("n")
        .validate(atLeast("-p", 1))
        .action((v, o) => o.copy(threads = Some(v)))
        .text("render (and encode a PNG) with n threads (default: the number of processors)"),
      opt[Double]('z', "zoom")
        .valueName("zoom")
        .validate(positiveDouble("-z"))
        .action((v, o) => o.copy(zoom = Some(v)))
        .text("camera zoom Z, overrides the scene"),
      opt[Int]('x', "xpix")
        .valueName("xpix")
        .validate(atLeast("-x", 1))
        .action((v, o) => o.copy(columns = Some(v)))
        .text("image width in pixels X"),
      opt[Int]('y', "ypix")
        .valueName("ypix")
        .validate(atLeast("-y", 1))
        .action((v, o) => o.copy(rows = Some(v)))
        .text("image height in pixels Y"),
      opt[Double]('w', "width")
        .valueName("width")
        .validate(positiveDouble("-w"))
        .action((v, o) => o.copy(width = Some(v)))
        .text("image width W in world units, overrides the scene"),
      opt[Double]('h', "height")
        .valueName("height")
        .validate(positiveDouble("-h"))
        .action((v, o) => o.copy(height = Some(v)))
        .text("image height H in world units, overrides the scene"),
      opt[Int]('a', "antialias")
        .valueName("n")
        .validate(v =>
          if v >= 1 && v <= CameraConfig.MaxSamples then Right(())
          else Left(s"-a must be an integer from 1 to ${CameraConfig.MaxSamples}, got $v")
        )
        .action((v, o) => o.copy(samples = v, antialiased = true))
        .text(
          s"antialiasing: average n×n samples a pixel, 1 to ${CameraConfig.MaxSamples} (default 1)"
        ),
      opt[String]('g', "gamma")
        .valueName("srgb|G")
        .validate(v => Encoding.parse(v).map(_ => ()))
        .action((v, o) =>
          o.copy(encoding = Encoding.parse(v).getOrElse(Encoding.Linear), encodingGiven = true)
        )
        .text("encode the output for display: srgb, or a gamma G > 0 (default 1, linear)"),
      opt[String]('R', "rows")
        .valueName("a:b")
        .validate(v => band(v).map(_ => ()))
        .action((v, o) => o.copy(band = band(v).toOption))
        .text("render only rows a to b-1 of the picture (row 0 at the top), 0 <= a < b <= ypix"),
      opt[String]('i', "input")
        .valueName("FILE")
        .action((v, o) => o.copy(input = Some(v)))
        .text("read the scene from FILE, its textures and meshes relative to FILE's directory"),
      opt[Unit]("size")
        .action((_, o) => o.copy(size = true))
        .text("print the picture's size 'X Y' (after the size rule) and exit; OUTPUT not needed"),
      opt[String]("stack")
        .valueName("FILE")
        .unbounded()
        .action((v, o) => o.copy(stack = o.stack :+ v))
        .text(
          "repeated: write OUTPUT as these images (all PPM/PNG or all PFM/EXR) one below the other"
        ),
      opt[String]("batch")
        .valueName("LIST")
        .action((v, o) => o.copy(batch = Some(v)))
        .text(
          "render every frame of LIST (lines SCENE<TAB>OUTPUT[<TAB>a:b][<TAB>OPTIONS]) in one process"
        ),
      opt[Unit]("version")
        .action((_, o) => o.copy(version = true))
        .text("print the version and exit"),
      help("help").text("print this usage and exit"),
      arg[String]("OUTPUT")
        .optional()
        .action((v, o) => o.copy(output = v))
        .text("the image file to write: .png PNG, .pfm/.exr linear floats, else binary PPM"),
      note(
        "\nGiven three of -w -h -x -y, the fourth keeps the picture undistorted; given fewer," +
          "\nthe scene's width and height and 640 pixels fill in. Exit status: 0 success," +
          "\n1 failure (bad scene, unreadable texture, unwritable output), 2 usage error."
      )
    )
