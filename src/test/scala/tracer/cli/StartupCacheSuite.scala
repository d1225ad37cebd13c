package tracer.cli

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.testkit.Processes

/** The launcher's start-up cache holds what users' renders run (docs/install.md): on JDK 25 and
  * newer, a single render and the gallery's scenes load every class of the tracer, Scala and
  * scopt from the cache, none from the jar, and spin no function's class at run time (each such
  * class costs a cold JVM about a millisecond; docs/performance.md, rounds 6 and 23).
  *
  * The renders run the JVM as the launcher does (its options and the cache it made), with the
  * JVM's class-loading log, which the launcher itself keeps quiet.
  */
class StartupCacheSuite extends munit.FunSuite:
  override val munitTimeout = scala.concurrent.duration.Duration(5, "min")

  private val home = Path.of("").toAbsolutePath
  private val jar  = home.resolve("target/scala-3.8.3/tracer.jar")

  override def beforeAll(): Unit =
    assume(Files.exists(jar), s"$jar is missing: run ./sbt assembly (./sbt test does it first)")

  /** The launcher's Java (from `tracer --version`) and its AOT cache, made by a first render. */
  private lazy val javaAndCache: Option[(Path, Path)] =
    val scenes  = home.resolve("scenes")
    val picture = Files.createTempFile("tracer-first", ".png")
    val first   =
      try
        Processes.run(
          Seq(home.resolve("tracer").toString, "-x", "8", "-i", "showcase.xml", picture.toString),
          scenes
        )
      finally Files.deleteIfExists(picture): Unit
    val version = Processes.run(Seq(home.resolve("tracer").toString, "--version"), scenes)
    val java    = version.out.linesIterator
      .collectFirst { case line if line.contains(" at /") => Path.of(line.split(" at ", 2)(1)) }
    val cache = scala.util.Using.resource(Files.list(jar.getParent))(
      _.iterator.asScala.find { p =>
        val name = p.getFileName.toString
        name.startsWith("tracer-java") && name.endsWith(".aot")
      }
    )
    assertEquals(first.status, 0, first.err)
    for j <- java; c <- cache yield (j.resolve("bin/java"), c)

  /** The classes of the tracer, Scala and scopt that a render loaded from anywhere but the cache. */
  private def uncached(args: String*): List[String] =
    val (java, cache) =
      javaAndCache.getOrElse(fail("no AOT cache was made (needs a JDK 25 or newer)"))
    val log     = Files.createTempFile("tracer-classes", ".txt")
    val picture = Files.createTempFile("tracer-picture", ".png")
    try
      val command = Seq(
        java.toString,
        s"-XX:AOTCache=$cache",
        "-Xlog:cds=off",
        "--sun-misc-unsafe-memory-access=allow",
        "-Xss8m",
        "-XX:+UseSerialGC",
        "-XX:LoopUnrollLimit=1",
        "-XX:Tier2BackedgeNotifyFreqLog=20",
        "-Dtracer.exit=halt",
        s"-Xlog:class+load=info:file=$log",
        "-jar",
        jar.toString
      ) ++ args :+ picture.toString
      val run = Processes.run(command, home.resolve("scenes"))
      assertEquals(run.status, 0, run.err)
      val lines = Files.readAllLines(log).asScala.toList
      assert(
        lines.exists(_.contains("tracer.cli.Main$ source: shared objects file")),
        "the cache was not used: the launcher's JVM options and these differ"
      )
      lines.filter(l =>
        List(" tracer.", " scala.", " scopt.").exists(l.contains) &&
          !l.contains("source: shared objects file")
      )
    finally List(log, picture).foreach(Files.deleteIfExists)

  private def assumeAotJava(): Unit =
    assume(
      javaAndCache.nonEmpty,
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
