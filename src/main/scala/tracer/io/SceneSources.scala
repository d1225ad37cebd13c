package tracer.io

import java.nio.file.Path

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
    SceneSources(TextureFiles.loader(base), MeshFiles.loader(base), warn)
