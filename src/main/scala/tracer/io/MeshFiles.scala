package tracer.io

import java.nio.file.Path

/** Loads OBJ mesh files, relative paths resolved against a base directory. */
object MeshFiles:

  /** A loader for [[SceneXml.parse]] reading OBJ files relative to `base` (by default the current
    * working directory, like textures).
    */
  def loader(base: Path = Path.of("").toAbsolutePath): SceneXml.MeshLoader =
    name => ObjReader.read(base.resolve(name), name)
