package tracer.io

import java.nio.charset.CharacterCodingException
import java.nio.file.{
  AccessDeniedException,
  FileSystemException,
  NoSuchFileException,
  NotDirectoryException
}

/** Why a file could not be read or written, in a few plain words for a one-line message: the
  * JDK's exceptions often carry only the path as their message (`/proc/1/mem`), which says
  * nothing about what went wrong.
  */
object IoFailure:
  /** The reason `e` gives, plainly: "no such file", "permission denied", "not a directory", "not
    * UTF-8 text", the file system's own reason ("Is a directory"), else the message, else the
    * exception's name.
    */
  def reason(e: Throwable): String = e match
    case _: NoSuchFileException                                           => "no such file"
    case _: AccessDeniedException                                         => "permission denied"
    case _: NotDirectoryException                                         => "not a directory"
    case _: CharacterCodingException                                      => "not UTF-8 text"
    case f: FileSystemException if Option(f.getReason).exists(_.nonEmpty) => f.getReason
    case f: FileSystemException => f.getClass.getSimpleName
    case other                  =>
      Option(other.getMessage).filter(_.nonEmpty).getOrElse(other.getClass.getSimpleName)
