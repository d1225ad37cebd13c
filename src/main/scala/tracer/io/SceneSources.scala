package tracer.io

import java.nio.file.Path
import tracer.image.Texels

/** Where a scene's textures and meshes come from, and where warnings about them go.
  *
  * @param texture loads a `<texture file="…">`
  * @param mesh    loads a `<mesh file="…">`
  * @param warn    receives warnings (skipped OBJ statements and faces), one line each
  */
final case class SceneSources(
    texture: SceneXml.TextureLoader,
    mesh: SceneXml.MeshLoader,
    warn: String => Unit = _ => ()
)

/** Constructors for [[SceneSources]]. */
object SceneSources:
  /** Files relative to `base`, warnings to `warn`. */
  def files(base: Path, warn: String => Unit = _ => ()): SceneSources =
    SceneSources(
      located(base, TextureFiles.loader(base)),
      located(base, MeshFiles.loader(base)),
      warn
    )

  /** [[files]], each texture and mesh taken from `reuse` while its file is unchanged (a batch's
    * frames share them).
    */
  def reusing(base: Path, reuse: Reuse, warn: String => Unit): SceneSources =
    SceneSources(
      located(base, name => reuse.textures(base.resolve(name))(TextureFiles.readTexels)),
      located(base, name => reuse.meshes(base.resolve(name))(ObjReader.read(_, name))),
      warn
    )

  /** `load`, whose failure for a relative name of a file that is not there also says where it
    * was looked for: relative names resolve against the scene file's directory, which a user may
    * not expect.
    */
  private def located[A](
      base: Path,
      load: String => Either[String, A]
  ): String => Either[String, A] =
    name =>
      load(name).left.map { why =>
        val where =
          try Some(Path.of(name)).filter(!_.isAbsolute).map(base.resolve(_).normalize)
          catch case _: java.nio.file.InvalidPathException => None
        where.filter(java.nio.file.Files.notExists(_)).fold(why)(w => s"$why (looked for $w)")
      }

  /** What the frames of one batch share: their decoded textures and read meshes. */
  final class Reuse:
    /** The textures kept. */
    val textures: FileReuse[Texels] = FileReuse()

    /** The meshes kept. */
    val meshes: FileReuse[ObjMesh] = FileReuse()

    /** Starts the next frame (see [[FileReuse.nextFrame]]). */
    def nextFrame(): Unit =
      textures.nextFrame()
      meshes.nextFrame()
