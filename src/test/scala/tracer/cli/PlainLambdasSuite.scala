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

  /** `AtLeastZero.accepts` (a function literal of ElementRules) as the jar makes it, in a class
    * loader of the jar's own, with `body` applied to it while the loader is open.
    */
  private def fromJar[A](body: AnyRef => A): A =
    val loader = URLClassLoader(Array(jar.toUri.toURL), ClassLoader.getPlatformClassLoader)
    try
      val rules = loader.loadClass("tracer.io.ElementRules")
      // A static forwarder: the receiver is ignored.
      val range = rules.getMethod("AtLeastZero").invoke(rules)
      body(range.getClass.getMethod("accepts").invoke(range))
    finally loader.close()

  test("a function literal of the jar is not serializable: its call site is plain") {
    fromJar { f =>
      assert(!classOf[java.io.Serializable].isAssignableFrom(f.getClass), f.getClass.getName)
    }
  }

  test("it is the same function") {
    fromJar { f =>
      val apply = f.getClass.getMethod("apply", classOf[Object])
      assertEquals(apply.invoke(f, java.lang.Double.valueOf(0.5)), java.lang.Boolean.TRUE)
      assertEquals(apply.invoke(f, java.lang.Double.valueOf(-0.5)), java.lang.Boolean.FALSE)
    }
  }

  test("compiled by scalac alone, the same literal is serializable (what the rewrite undoes)") {
    val f: Double => Boolean = _ >= 0
    assert(classOf[java.io.Serializable].isAssignableFrom(f.getClass))
  }
