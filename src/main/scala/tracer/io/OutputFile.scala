package tracer.io

import java.io.OutputStream
import java.nio.file.{
  AtomicMoveNotSupportedException,
  Files,
  Path,
  StandardCopyOption,
  StandardOpenOption
}
import scala.util.control.NonFatal

/** Writes files whole or not at all: a failed or killed write never leaves a partial file and
  * never destroys an existing file of the same name.
  */
object OutputFile:

  /** Checks up front that `path` can be written: its directory exists and is writable, and it is
    * not a directory itself. Rendering can then fail fast instead of after the work is done.
    */
  def checkWritable(path: Path): Either[String, Unit] =
    val dir = Option(path.toAbsolutePath.getParent).getOrElse(Path.of("/"))
    if Files.isDirectory(path) then Left(s"cannot write '$path': it is a directory")
    else if !Files.isDirectory(dir) then
      if Files.exists(dir) then Left(s"cannot write '$path': '$dir' is not a directory")
      else Left(s"cannot write '$path': no such directory '$dir'")
    else if !Files.isWritable(dir) then
      Left(s"cannot write '$path': directory '$dir' is not writable")
    else if Files.exists(path) && !Files.isWritable(path) then
      Left(s"cannot write '$path': permission denied")
    else Right(())

  /** Writes `path` through `write`, first into a temporary file beside it, then renaming that into
    * place in one step. On any failure the temporary file is removed and `path` is untouched.
    */
  def write(path: Path)(write: OutputStream => Unit): Either[String, Unit] =
    checkWritable(path).flatMap { _ =>
      val target = path.toAbsolutePath
      // Why: the temporary file while it exists, shared with the shutdown hook that removes it.
      var temporary: Option[Path] = None
      // A kill (SIGTERM, Ctrl-C) between creation and the rename still removes the temporary file.
      val cleanup = Thread(() => temporary.foreach(Files.deleteIfExists))
      try
        // Created like any new file (so the umask applies), under a name no other run uses.
        val tmp =
          target.resolveSibling(s".${target.getFileName}.${ProcessHandle.current.pid}.partial")
        val out =
          Files.newOutputStream(tmp, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)
        temporary = Some(tmp)
        Runtime.getRuntime.addShutdownHook(cleanup)
        try write(out)
        finally out.close()
        moveIntoPlace(tmp, target)
        temporary = None
        Right(())
      catch
        case NonFatal(e) =>
          temporary.foreach(Files.deleteIfExists)
          Left(s"cannot write '$path': ${IoFailure.reason(e)}")
      finally
        try Runtime.getRuntime.removeShutdownHook(cleanup): Unit
        catch case _: IllegalStateException => () // already shutting down: the hook runs
    }

  private def moveIntoPlace(from: Path, to: Path): Unit =
    try
      Files.move(
        from,
        to,
        StandardCopyOption.ATOMIC_MOVE,
        StandardCopyOption.REPLACE_EXISTING
      ): Unit
    catch
      case _: AtomicMoveNotSupportedException =>
        Files.move(from, to, StandardCopyOption.REPLACE_EXISTING): Unit
