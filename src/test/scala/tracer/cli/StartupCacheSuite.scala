package tracer.cli

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.testkit.Processes

/** The launcher's start-up cache holds what users' renders run (docs/install.md): on JDK 25 and
  * newer, a single render and the gallery's scenes load every class of the tracer, Scala and
  * scopt from the cache, none from the jar, and spin no function's class at run time (each such
  * class costs a cold JVM about a millisecond; docs/performance.md, rounds 6 and 23).
  *
  * The renders run through the launcher itself (its Java, its options, the cache it chose), with
  * the JVM's class-loading log asked for by `JDK_JAVA_OPTIONS`, which the `java` command reads
  * and the cache's name does not depend on; so no other cache beside the jar (one made for other
  * options) can be taken for the launcher's.
  */
class StartupCacheSuite extends munit.FunSuite:
  override val munitTimeout = scala.concurrent.duration.Duration(5, "min")

  private val home   = Path.of("").toAbsolutePath
  private val jar    = home.resolve("target/scala-3.8.3/tracer.jar")
  private val tracer = home.resolve("tracer").toString
  private val scenes = home.resolve("scenes")

  override def beforeAll(): Unit =
    assume(Files.exists(jar), s"$jar is missing: run ./sbt assembly (./sbt test does it first)")

  /** The feature version of the launcher's Java (from `tracer --version`), after a first render
    * that made its cache.
    */
  private lazy val javaFeature: Option[Int] =
    val picture = Files.createTempFile("tracer-first", ".png")
    val first   =
      try Processes.run(Seq(tracer, "-x", "8", "-i", "showcase.xml", picture.toString), scenes)
      finally Files.deleteIfExists(picture): Unit
    assertEquals(first.status, 0, first.err)
    val help = Processes.run(Seq(tracer, "--help"), scenes)
    help.out.linesIterator.collectFirst {
      case line if line.startsWith("Java ") => line.drop(5).takeWhile(_.isDigit).toIntOption
    }.flatten

  /** The classes of the tracer, Scala and scopt that a render loaded from anywhere but the cache. */
  private def uncached(args: String*): List[String] =
    val log     = Files.createTempFile("tracer-classes", ".txt")
    val picture = Files.createTempFile("tracer-picture", ".png")
    try
      val run = Processes.run(
        Seq(tracer) ++ args :+ picture.toString,
        scenes,
        Map("JDK_JAVA_OPTIONS" -> Some(s"-Xlog:class+load=info:file=$log"))
      )
      assertEquals(run.status, 0, run.err)
      val lines = Files.readAllLines(log).asScala.toList
      assert(
        lines.exists(_.contains("tracer.cli.Main$ source: shared objects file")),
        "the launcher's cache was not used"
      )
      lines.filter(l =>
        List(" tracer.", " scala.", " scopt.").exists(l.contains) &&
          !l.contains("source: shared objects file")
      )
    finally List(log, picture).foreach(Files.deleteIfExists)

  private def assumeAotJava(): Unit =
    assume(
      javaFeature.exists(_ >= 25),
      "the launcher chose a Java older than 25: its cache keeps classes only"
    )

  test("a single small render with -g srgb loads every class from the cache") {
    assumeAotJava()
    assertEquals(uncached("-x", "48", "-p", "2", "-g", "srgb", "-i", "showcase.xml"), Nil)
  }

  test("the solids, the meshes and a path-traced room load every class from the cache") {
    assumeAotJava()
    assertEquals(uncached("-x", "64", "-p", "2", "-i", "solids.xml"), Nil)
    assertEquals(uncached("-x", "64", "-p", "2", "-i", "meshes.xml"), Nil)
    assertEquals(uncached("-x", "32", "-p", "2", "-m", "path", "-s", "2", "-i", "cornell.xml"), Nil)
  }

  test(
    "a short render of many triangles (a coarse tree in Morton order) loads every class from the cache"
  ) {
    assumeAotJava()
    val scene = "../launcher/training/triangles-1000.xml"
    assertEquals(uncached("-x", "4", "-p", "2", "-i", scene), Nil)
  }
