package tracer.bench

import java.nio.file.{Files, Path}
import tracer.io.SceneXml
import tracer.scene.Scene

/** The gallery's scenes for the benchmarks, found from the repository's root or from `bench/`
  * (where sbt may start JMH's fork).
  */
object GalleryScene:
  /** The scene `scenes/name`, its textures and meshes beside it; a scene that is missing or fails
    * to load stops the run loudly (a benchmark has no caller to hand the error to, and must not
    * time nothing).
    */
  def load(name: String): Scene =
    // Why: a benchmark has no caller to hand an error to; it must stop rather than time nothing.
    val file = List(Path.of("scenes", name), Path.of("..", "scenes", name))
      .map(_.toAbsolutePath)
      .find(Files.isRegularFile(_))
      .getOrElse(throw IllegalStateException(s"scenes/$name not found"))
    SceneXml.load(file, file.getParent).fold(why => throw IllegalStateException(why), identity)
