package tracer.cli

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.io.SceneXml

/** The scenes of the launcher's training run (launcher/training/) read without error: a training
  * batch with a frame that fails makes no start-up cache, and the launcher says nothing of it.
  */
class TrainingScenesSuite extends munit.FunSuite:

  private val dir = Path.of("").toAbsolutePath.resolve("launcher/training")

  test("every training scene is a scene the tracer reads") {
    val scenes =
      Files.list(dir).iterator.asScala.filter(_.getFileName.toString.endsWith(".xml")).toList
    assert(scenes.nonEmpty, s"no training scenes in $dir")
    scenes.foreach(scene => assert(SceneXml.load(scene, dir).isRight, SceneXml.load(scene, dir)))
  }
