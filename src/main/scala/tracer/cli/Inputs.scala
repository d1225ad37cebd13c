package tracer.cli

import java.io.{IOException, InputStream, PrintStream}
import java.nio.file.{Files, Path}
import tracer.io.{IoFailure, SceneSources, SceneXml}
import tracer.scene.Scene

/** Where the command's inputs come from: the scene from `-i FILE` or standard input, and files
  * read whole, each failure one message naming the file.
  */
private[cli] object Inputs:

  /** The scene, from `-i FILE` or standard input, with its textures and meshes (those of `reuse`
    * while their files are unchanged, in a batch); warnings to `err`, and, when standard input is
    * a terminal (`typed`) and the scene comes from it, a line saying so. A scene error names FILE
    * (`scene` for standard input) before its line.
    */
  def scene(
      options: Options,
      in: InputStream,
      err: PrintStream,
      cwd: Path,
      reuse: Option[SceneSources.Reuse] = None,
      typed: Boolean = false
  ): Either[String, Scene] =
    if typed && options.input.isEmpty then
      err.println(
        "tracer: reading the scene from standard input (end it with Ctrl-D, or give -i FILE)"
      )
    sceneBytes(options.input, in, cwd).flatMap { (bytes, where) =>
      val warn: String => Unit = w => err.println(s"tracer: warning: $w")
      val sources              = reuse.fold(SceneSources.files(where, warn))(
        SceneSources.reusing(where, _, warn)
      )
      SceneXml
        .parse(bytes, sources)
        .left
        .map(e => s"${options.input.getOrElse("scene")}: ${e.describe}")
    }

  /** The bytes of `file`, or why it cannot be read, naming it as `what`. */
  def read(file: Path, what: String): Either[String, Array[Byte]] =
    try
      if Files.isDirectory(file) then Left(s"cannot read $what: it is a directory")
      else Right(Files.readAllBytes(file))
    catch case e: IOException => Left(s"cannot read $what: ${IoFailure.reason(e)}")

  /** The scene's bytes and the directory its relative paths resolve against: FILE's own
    * directory with `-i FILE`, else standard input and the working directory.
    */
  private def sceneBytes(
      input: Option[String],
      in: InputStream,
      cwd: Path
  ): Either[String, (Array[Byte], Path)] =
    input match
      case None =>
        try
          val bytes = in.readAllBytes()
          if bytes.isEmpty then Left("no scene on standard input (pipe one in, or give -i FILE)")
          else Right((bytes, cwd))
        catch
          case e: IOException =>
            Left(s"cannot read the scene from standard input: ${IoFailure.reason(e)}")
      case Some("")   => Left("cannot read scene file '': -i needs a file name")
      case Some(name) =>
        val file = cwd.resolve(name)
        read(file, s"scene file $name").map((_, file.toAbsolutePath.getParent))
