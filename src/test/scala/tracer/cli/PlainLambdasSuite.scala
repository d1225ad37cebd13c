package tracer.cli

import java.net.URLClassLoader
import java.nio.file.{Files, Path}

/** The assembled jar's Scala lambdas are plain `LambdaMetafactory.metafactory` call sites
  * (project/PlainLambdas.scala, run by `assembly`), which the launcher's start-up cache can hold:
  * a function the jar makes is not serializable, where the same code compiled for the tests is.
  */
class PlainLambdasSuite extends munit.FunSuite:

  private val jar = Path.of("").toAbsolutePath.resolve("target/scala-3.8.3/tracer.jar")

  override def beforeAll(): Unit =
    assume(Files.exists(jar), s"$jar is missing: run ./sbt assembly (./sbt test does it first)")

  private val scratch = Path.of(System.getProperty("java.io.tmpdir"))

  /** `MeshFiles.loader` (a function literal, `String => Either`) as the jar makes it, in a class
    * loader of the jar's own, with `body` applied to it while the loader is open. (Not one of the
    * specialised functions, such as `Double => Boolean`: scala-library declares their interfaces
    * serializable.)
    */
  private def fromJar[A](body: (AnyRef, ClassLoader) => A): A =
    val loader = URLClassLoader(Array(jar.toUri.toURL), ClassLoader.getPlatformClassLoader)
    try
      val files = loader.loadClass("tracer.io.MeshFiles")
      // A static forwarder: the receiver is ignored.
      body(files.getMethod("loader", classOf[Path]).invoke(files, scratch), loader)
    finally loader.close()

  test("a function literal of the jar is not serializable: its call site is plain") {
    fromJar { (f, _) =>
      assert(!classOf[java.io.Serializable].isAssignableFrom(f.getClass), f.getClass.getName)
    }
  }

  test("it is the same function") {
    fromJar { (f, loader) =>
      val apply = loader.loadClass("scala.Function1").getMethod("apply", classOf[Object])
      val read  = apply.invoke(f, "no-such-mesh.obj")
      assert(read.toString.startsWith("Left("), read.toString)
    }
  }

  test("compiled by scalac alone, the same literal is serializable (what the rewrite undoes)") {
    val f = tracer.io.MeshFiles.loader(scratch)
    assert(classOf[java.io.Serializable].isAssignableFrom(f.getClass))
  }
