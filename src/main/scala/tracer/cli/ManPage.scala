package tracer.cli

import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import tracer.BuildInfo

/** `man tracer`: the manual page, in roff, made from the usage text of `--help`, so that the two
  * never disagree. `./sbt dist` runs [[main]] and ships the page in the Debian package.
  */
object ManPage:

  /** The manual page of version `version` whose synopsis, description, options and notes are
    * those of `usage` (scopt's usage text: a header line, a `Usage:` line, one line an option
    * with its text after two or more spaces, then the notes). The environment section tells the
    * launcher's variables (docs/install.md).
    */
  def roff(usage: String, version: String): String =
    val lines                  = usage.linesIterator.toList
    val (header, rest)         = lines.span(l => !l.startsWith("Usage:"))
    val (optionLines, notes)   = rest.drop(1).dropWhile(_.isBlank).span(_.startsWith("  "))
    val options: List[String]  = optionLines.map(option)
    val description            = header.map(text).mkString("\n")
    val noteText: List[String] = notes.dropWhile(_.isBlank).map(text)
    (List(
      s""".TH TRACER 1 "" "tracer ${text(version)}" "User Commands"""",
      ".SH NAME",
      "tracer \\- a ray tracer: renders an XML scene to a PNG, PPM, PFM or OpenEXR picture",
      ".SH SYNOPSIS",
      ".B tracer",
      "[\\fIoptions\\fR] \\fIOUTPUT\\fR < \\fIscene.xml\\fR",
      ".br",
      ".B tracer",
      "[\\fIoptions\\fR] \\fB\\-i\\fR \\fIscene.xml OUTPUT\\fR",
      ".SH DESCRIPTION",
      description,
      ".SH OPTIONS"
    ) ++ options ++ List(".SH NOTES") ++ noteText ++ environment ++ files ++ List(
      ".SH SEE ALSO",
      "The documentation in /usr/share/doc/tracer (or docs/ beside an unpacked archive):",
      "cli.md (the command line), scene-format.md (the scene files), guide.md (editing scenes),",
      "install.md."
    )).mkString("", "\n", "\n")

  /** Writes the manual page of this build to the file named by the first argument, or to standard
    * output without one.
    */
  def main(args: Array[String]): Unit =
    val page = roff(Options.usage, BuildInfo.version)
    args.headOption match
      case Some(file) => Files.writeString(Path.of(file), page, UTF_8): Unit
      case None       => print(page)

  /** One option line of the usage as a tagged paragraph: the option in bold, its text below. */
  private def option(line: String): String =
    val trimmed       = line.trim
    val (spec, about) = trimmed.indexOf("  ") match
      case -1 => (trimmed, "")
      case at => (trimmed.take(at), trimmed.drop(at).trim)
    s".TP\n.B ${text(spec)}\n${text(about)}"

  /** `s` as roff text: backslashes and hyphens escaped, a leading control character neutralised. */
  private def text(s: String): String =
    val escaped = s.replace("\\", "\\e").replace("-", "\\-")
    if escaped.startsWith(".") || escaped.startsWith("'") then "\\&" + escaped else escaped

  /** The files the package installs that a user points other programs at: the scene schema. */
  private val files = List(
    ".SH FILES",
    ".TP",
    ".B /usr/share/tracer/scene.xsd",
    "The scene format as an XML Schema (also docs/scene.xsd beside an unpacked archive), for",
    "completion and checking while a scene is edited. Name it on the root element:",
    "<scene xmlns:xsi=\"http://www.w3.org/2001/XMLSchema\\-instance\"",
    "xsi:noNamespaceSchemaLocation=\"/usr/share/tracer/scene.xsd\">.",
    "VS Code with Red Hat's XML extension (redhat.vscode\\-xml) and IntelliJ IDEA then complete",
    "element and attribute names and flag mistakes as you type; without the attributes, map",
    "the files in VS Code's setting xml.fileAssociations (pattern and systemId) or in IntelliJ's",
    "Settings, Languages & Frameworks, Schemas and DTDs. From the shell:",
    "xmllint \\-\\-noout \\-\\-schema /usr/share/tracer/scene.xsd scene.xml.",
    "Some rules (a pole at right angles to the equator, corners not collinear) only the tracer",
    "checks."
  )

  /** The launcher's environment variables, as docs/install.md tells them. */
  private val environment = List(
    ".SH ENVIRONMENT",
    ".TP",
    ".B TRACER_JAVA",
    "The Java to run: a \\fBjava\\fR program or a Java home. Unset, the launcher takes the newest",
    "Java of version 17 or newer among JAVA_HOME, the \\fBjava\\fR on PATH and /usr/lib/jvm.",
    ".TP",
    ".B TRACER_JAVA_OPTS",
    "The JVM's options, replacing the default \\-Xss8m \\-XX:+UseSerialGC \\-XX:LoopUnrollLimit=1",
    "\\-XX:Tier2BackedgeNotifyFreqLog=30 \\-Dtracer.exit=halt (the last ends the JVM without",
    "running shutdown hooks).",
    ".TP",
    ".B TRACER_CACHE",
    "\\fBoff\\fR: start without the start-up cache; \\fBcds\\fR: an AppCDS archive even on Java 25 or",
    "newer; any other value is refused (exit 2). The cache is made on first use for each Java",
    "and kept beside the jar, or in $XDG_CACHE_HOME/tracer (default ~/.cache/tracer) when the",
    "install directory is read-only.",
    ".TP",
    ".B TRACER_LANES",
    "\\fBon\\fR: the ray kernel tests four boxes at once with the JDK's Vector API: the same",
    "pictures, faster renders of many shapes, a start about 0.2 s slower. \\fBoff\\fR (the default):",
    "one box at a time."
  )
