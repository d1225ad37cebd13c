package tracer.io

import java.nio.file.{Files, Path}
import java.nio.file.attribute.{BasicFileAttributes, FileTime}
import scala.util.Try

/** What reading a file gave, kept while the file is unchanged, for the frames of one batch:
  * a movie's frames name the same textures and meshes, which are then read and decoded once
  * instead of once a frame (docs/performance.md, round 7: the movie).
  *
  * A file counts as unchanged while its real path, size and modification time are the same. Only
  * successful reads are kept, and only those the current or the previous frame used (see
  * [[nextFrame]]), so a long batch keeps at most two frames' files in memory. What is kept must be
  * immutable (the decoded texels, an OBJ mesh's arrays): every frame that reads the file shares it.
  */
final class FileReuse[A]:

  /** A file's identity as far as reuse goes: its real path, size and modification time. */
  private final case class Stamp(real: Path, size: Long, modified: FileTime)

  // Why: a memo across a batch's frames, touched by one thread (the batch reads its frames' scenes
  // one after another); the two maps are replaced, never shared.
  private var current  = Map.empty[Path, (Stamp, A)]
  private var previous = Map.empty[Path, (Stamp, A)]

  /** The contents of the file at `path`: what an earlier read of the same unchanged file gave, or
    * what `read` (which reads and decodes it, or says why it cannot) gives now.
    */
  def apply(path: Path)(read: Path => Either[String, A]): Either[String, A] =
    stamp(path) match
      case None        => read(path) // it cannot be looked at: the reader says why
      case Some(stamp) =>
        current.get(stamp.real).orElse(previous.get(stamp.real)) match
          case Some((kept, value)) if kept == stamp =>
            current = current.updated(stamp.real, (stamp, value))
            Right(value)
          case _ =>
            read(path).map { value =>
              current = current.updated(stamp.real, (stamp, value))
              value
            }

  /** Starts the next frame: what neither this frame nor the one before used is let go. */
  def nextFrame(): Unit =
    previous = current
    current = Map.empty

  /** The number of files kept. */
  def size: Int = (previous ++ current).size

  private def stamp(path: Path): Option[Stamp] =
    Try {
      val real       = path.toRealPath()
      val attributes = Files.readAttributes(real, classOf[BasicFileAttributes])
      Stamp(real, attributes.size, attributes.lastModifiedTime)
    }.toOption
