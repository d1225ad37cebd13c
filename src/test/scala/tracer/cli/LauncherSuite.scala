package tracer.cli

import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.{Files, Path}
import java.nio.file.attribute.PosixFilePermissions
import java.util.concurrent.TimeUnit
import scala.jdk.CollectionConverters.*
import tracer.testkit.{Images, Processes}

/** System tests: the real `tracer` launcher script run as a process, as a user would run it.
  *
  * They need the assembled jar; `./sbt test` builds it first (build.sbt), and without it the
  * launcher would start a nested build, so these tests then stop with a clear message.
  */
class LauncherSuite extends munit.FunSuite with Images:
  // A test may train one or two start-up caches (a training run each: 15 s on a fast machine, a
  // minute on a slow or busy one): munit's default of 30 s is a guard against hangs set too low.
  override val munitTimeout = scala.concurrent.duration.Duration(3, "min")

  private val home     = Path.of("").toAbsolutePath
  private val launcher = home.resolve("tracer")
  private val jar      = home.resolve("target/scala-3.8.3/tracer.jar")

  override def beforeAll(): Unit =
    assume(Files.exists(jar), s"$jar is missing: run ./sbt assembly (./sbt test does it first)")

  /** What one process did. */
  final case class Exit(status: Int, out: String, err: String)

  private def tracer(cwd: Path, stdin: Path, args: String*): Exit =
    runIn(cwd, stdin, launcher.toString +: args)

  private def runIn(cwd: Path, stdin: Path, command: Seq[String]): Exit =
    val out = Files.createTempFile("tracer-out", ".txt")
    val err = Files.createTempFile("tracer-err", ".txt")
    try
      val process = ProcessBuilder(command*)
        .directory(cwd.toFile)
        .redirectInput(stdin.toFile)
        .redirectOutput(out.toFile)
        .redirectError(err.toFile)
        .start()
      assert(process.waitFor(120, TimeUnit.SECONDS), s"$command did not finish")
      Exit(process.exitValue, Files.readString(out, UTF_8), Files.readString(err, UTF_8))
    finally List(out, err).foreach(Files.delete)

  private val work = FunFixture[Path](
    _ =>
      val d = Files.createTempDirectory("tracer launcher")
      for name <- List("basics.xml", "textures.xml", "orientation.ppm") do
        Files.write(d.resolve(name), getClass.getResourceAsStream(s"/samples/$name").readAllBytes())
      d
    ,
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
  )

  work.test("from another directory (whose path has a space) it renders the samples as expected"):
    d =>
      assertEquals(tracer(d, d.resolve("textures.xml"), "-x", "320", "t.png"), Exit(0, "", ""))
      assertImageClose(
        readImage(d.resolve("t.png")),
        resourceImage("/samples/expected/textures-320x240.png"),
        "launcher-textures"
      )
      assertEquals(tracer(d, d.resolve("basics.xml"), "-x", "320", "-t", "b.png").status, 0)
      assertImageClose(
        readImage(d.resolve("b.png")),
        resourceImage("/samples/expected/basics-320x240.png"),
        "launcher-basics"
      )

  /** The home of an installed JDK 17, found by its `release` file, if there is one. */
  private def jdk17: Option[Path] =
    val dir = Path.of("/usr/lib/jvm")
    if !Files.isDirectory(dir) then None
    else
      Files.list(dir).iterator.asScala.toList.sorted.find { home =>
        val release = home.resolve("release")
        Files.isRegularFile(release) && Files.isExecutable(home.resolve("bin/java")) &&
        Files.readAllLines(release).asScala.exists(_.startsWith("JAVA_VERSION=\"17."))
      }

  work.test("on JDK 17 (TRACER_JAVA) it renders the sample as expected and names that Java"): d =>
    assume(jdk17.isDefined, "no JDK 17 in /usr/lib/jvm")
    jdk17.foreach { home17 =>
      val env    = Map("TRACER_JAVA" -> Some(home17.toString))
      val render =
        Processes.run(Seq(launcher.toString, "-x", "320", "-i", "basics.xml", "b.png"), d, env)
      assertEquals(render, Processes.Exit(0, "", ""))
      assertImageClose(
        readImage(d.resolve("b.png")),
        resourceImage("/samples/expected/basics-320x240.png"),
        "launcher-jdk17"
      )
      val help = Processes.run(Seq(launcher.toString, "--help"), d, env)
      assertEquals(help.status, 0, help.err)
      assert(help.out.linesIterator.toList.last.startsWith("Java 17."), help.out)
      assert(help.out.contains(s" at ${home17.toRealPath()}"), help.out)
    }

  /** A stand-in JDK of version `v` in `dir`: a release file and a `java` that prints its name and
    * its arguments.
    */
  private def fakeJdk(dir: Path, v: String): Path =
    val home = Files.createDirectories(dir.resolve(s"jdk-$v/bin")).getParent
    Files.writeString(home.resolve("release"), s"IMPLEMENTOR=\"Fake\"\nJAVA_VERSION=\"$v\"\n")
    val java = home.resolve("bin/java")
    Files.writeString(java, s"#!/bin/sh\necho \"jdk-$v $$*\"\n")
    java.toFile.setExecutable(true)
    home

  /** The options that put the render's rows below the JIT, followed by a space, which the
    * launcher passes on Linux when it runs un-niced, as it does under this test when this process
    * is un-niced (launcher.sh, tracer_java_flags); otherwise nothing.
    */
  private val priority: String =
    val fields =
      try statFields(Files.readString(Path.of("/proc/self/stat"), UTF_8))
      catch case _: java.io.IOException => Array.empty[String]
    if fields.length > 16 && fields(16) == "0" then
      "-XX:ThreadPriorityPolicy=1 -XX:JavaPriority1_To_OSPriority=4 " +
        (6 to 10).map(p => s"-XX:JavaPriority${p}_To_OSPriority=0 ").mkString +
        "-XX:CompilerThreadPriority=0 -XX:VMThreadPriority=0 "
    else ""

  /** The fields of a `/proc` `stat` line after the command's name (which is in parentheses and
    * may hold spaces): the state at 0, the user-mode clock ticks at 11, the nice value at 16.
    */
  private def statFields(stat: String): Array[String] =
    stat.substring(stat.lastIndexOf(") ") + 2).split(' ')

  work.test(
    "it takes the newest Java >= 17 of JAVA_HOME, PATH and the JDK directories, or TRACER_JAVA"
  ): d =>
    val jdks   = Files.createDirectories(d.resolve("jvm"))
    val old    = fakeJdk(d, "11.0.2")
    val onPath = Files.createDirectories(d.resolve("bin"))
    Files.createSymbolicLink(onPath.resolve("java"), fakeJdk(d, "19.0.1").resolve("bin/java"))
    List("21.0.4", "25.0.1", "1.8.0_392").foreach(fakeJdk(jdks, _))
    val env = Map(
      "JAVA_HOME"       -> Some(old.toString),
      "PATH"            -> Some(s"$onPath:${sys.env.getOrElse("PATH", "/usr/bin:/bin")}"),
      "TRACER_JDK_DIRS" -> Some(jdks.toString),
      "TRACER_JAVA"     -> None,
      "TRACER_CACHE"    -> Some("off")
    )
    def chosen(extra: (String, Option[String])*) =
      val e = Processes.run(Seq(launcher.toString, "--version"), d, env ++ extra)
      assertEquals((e.status, e.err), (0, ""))
      e.out.trim
    // JDK 23 and newer are told to let Scala's LazyVals use sun.misc.Unsafe without a warning.
    assertEquals(
      chosen(),
      s"jdk-25.0.1 --sun-misc-unsafe-memory-access=allow $priority-Xss8m -XX:+UseSerialGC -XX:LoopUnrollLimit=1 -XX:Tier2BackedgeNotifyFreqLog=30 -Dtracer.exit=halt -jar $jar --version"
    )
    assertEquals(
      chosen("TRACER_JDK_DIRS" -> Some(d.resolve("none").toString)),
      s"jdk-19.0.1 $priority-Xss8m -XX:+UseSerialGC -XX:LoopUnrollLimit=1 -XX:Tier2BackedgeNotifyFreqLog=30 -Dtracer.exit=halt -jar $jar --version"
    )
    assertEquals(
      chosen("TRACER_JAVA" -> Some(old.toString), "TRACER_JAVA_OPTS" -> Some("-Xmx1g")),
      s"jdk-11.0.2 $priority-Xmx1g -jar $jar --version"
    )
    assertEquals(
      chosen("TRACER_JAVA" -> Some(old.resolve("bin/java").toString)),
      s"jdk-11.0.2 $priority-Xss8m -XX:+UseSerialGC -XX:LoopUnrollLimit=1 -XX:Tier2BackedgeNotifyFreqLog=30 -Dtracer.exit=halt -jar $jar --version"
    )

  work.test("a JDK whose path has a newline does not lend its neighbours the wrong home"): d =>
    // The launcher resolves every candidate in one readlink, a line each: a path with a newline
    // (here JAVA_HOME's) would shift the lines after it and pair a java with another's home.
    val odd  = fakeJdk(Files.createDirectories(d.resolve("a\nb")), "21.0.4")
    val jdks = Files.createDirectories(d.resolve("jvm"))
    // Newer than any real Java on PATH, so that the right pairing wins wherever the test runs.
    List("99.0.1", "17.0.15").foreach(fakeJdk(jdks, _))
    val env = Map(
      "JAVA_HOME"       -> Some(odd.toString),
      "TRACER_JDK_DIRS" -> Some(jdks.toString),
      "TRACER_JAVA"     -> None,
      "TRACER_CACHE"    -> Some("off")
    )
    val e = Processes.run(Seq(launcher.toString, "--version"), d, env)
    assertEquals((e.status, e.err), (0, ""))
    assertEquals(
      e.out.trim,
      s"jdk-99.0.1 --sun-misc-unsafe-memory-access=allow $priority-Xss8m -XX:+UseSerialGC -XX:LoopUnrollLimit=1 -XX:Tier2BackedgeNotifyFreqLog=30 -Dtracer.exit=halt -jar $jar --version"
    )

  work.test("no Java of 17 or newer, or a TRACER_JAVA that is none, is one line and exit 1"): d =>
    val old    = fakeJdk(d, "11.0.2")
    val onPath = Files.createDirectories(d.resolve("bin"))
    Files.createSymbolicLink(onPath.resolve("java"), old.resolve("bin/java"))
    val env = Map(
      "JAVA_HOME"       -> Some(old.toString),
      "PATH"            -> Some(s"$onPath:${sys.env.getOrElse("PATH", "/usr/bin:/bin")}"),
      "TRACER_JDK_DIRS" -> Some(d.resolve("none").toString),
      "TRACER_JAVA"     -> None
    )
    val none = Processes.run(Seq(launcher.toString, "--version"), d, env)
    assertEquals((none.status, none.out), (1, ""))
    assertEquals(
      none.err,
      "tracer: needs Java 17 or newer; found only older ones (set TRACER_JAVA to a newer one)\n"
    )
    val bad = Processes.run(
      Seq(launcher.toString, "--version"),
      d,
      env + ("TRACER_JAVA" -> Some(d.resolve("nowhere").toString))
    )
    assertEquals((bad.status, bad.out), (1, ""))
    assert(bad.err.startsWith("tracer: TRACER_JAVA="), bad.err)
    assertEquals(bad.err.linesIterator.length, 1, bad.err)

  work.test("through a symbolic link it still finds its jar"): d =>
    val link = Files.createSymbolicLink(d.resolve("tracer-link"), launcher)
    assertEquals(
      runIn(d, d.resolve("basics.xml"), List(link.toString, "-x", "16", "o.ppm")).status,
      0
    )

  work.test(
    "with TRACER_JAVA_OPTS the JVM exits rather than halts: a flight recording is written at exit"
  ): d =>
    // A name without the directory: the options are split at spaces, and the directory has one.
    val recording = d.resolve("r.jfr")
    val options   = "-Xss8m -XX:StartFlightRecording=filename=r.jfr"
    val env       = Map("TRACER_JAVA_OPTS" -> Some(options), "TRACER_CACHE" -> Some("off"))
    val e         =
      Processes.run(Seq(launcher.toString, "-x", "16", "-i", "basics.xml", "o.png"), d, env)
    assertEquals(e.status, 0, e.err)
    assert(Files.isRegularFile(d.resolve("o.png")))
    assert(Files.size(recording) > 0, s"no recording at $recording")

  work.test("-t prints exactly 'Tracetime: N ms' on stdout"): d =>
    val e = tracer(d, d.resolve("basics.xml"), "-t", "-x", "64", "-p", "2", "o.ppm")
    assertEquals(e.status, 0, e.err)
    assert(e.out.matches("Tracetime: \\d+ ms\n"), s"'${e.out}'")

  work.test("a bad scene exits 1 with one line on stderr, no stack trace"): d =>
    Files.writeString(d.resolve("bad.xml"), "<scene><camera/></scene>")
    val e = tracer(d, d.resolve("bad.xml"), "o.png")
    assertEquals((e.status, e.out), (1, ""))
    assertEquals(e.err.linesIterator.toList.length, 1, e.err)
    assert(e.err.startsWith("tracer: scene: line 1: <camera>: missing <location>"), e.err)
    assert(!Files.exists(d.resolve("o.png")))

  work.test("a usage error exits 2 with one line on stderr"): d =>
    val e = tracer(d, d.resolve("basics.xml"), "-p", "zero", "o.png")
    assertEquals((e.status, e.out), (2, ""))
    assertEquals(e.err.linesIterator.toList.length, 1, e.err)

  work.test("--help exits 0 with the usage on stdout"): d =>
    val e = tracer(d, d.resolve("basics.xml"), "--help")
    assertEquals((e.status, e.err), (0, ""))
    assert(e.out.contains("Usage: tracer"), e.out)

  work.test("on a terminal a long render shows a progress line on stderr, then erases it"): d =>
    assume(
      Files.isExecutable(Path.of("/usr/bin/script")),
      "needs script(1) to give the run a terminal"
    )
    Files.copy(home.resolve("scenes/showcase.xml"), d.resolve("showcase.xml"))
    Files.createSymbolicLink(d.resolve("textures"), home.resolve("scenes/textures"))
    // script(1) runs the command on a pseudo-terminal and copies what it shows to its stdout.
    val command = s"cd '$d' && '$launcher' -x 1200 -a 3 -p 1 o.png < showcase.xml"
    val e = runIn(d, Path.of("/dev/null"), List("/usr/bin/script", "-qec", command, "/dev/null"))
    assertEquals(e.status, 0, e.out + e.err)
    assert(e.out.contains("\rtracer: rendering ") && e.out.contains(" rows)"), e.out)
    assert(e.out.contains("\r\u001b[K"), "the line is erased at the end")

  work.test("TRACER_LANES=on: the same picture, and nothing on stderr (the JVM's warning dropped)"):
    d =>
      val on    = Map("TRACER_LANES" -> Some("on"))
      val plain = Processes.run(Seq(launcher.toString, "-x", "160", "-i", "basics.xml", "p.png"), d)
      assertEquals(plain, Processes.Exit(0, "", ""))
      val lanes =
        Processes.run(Seq(launcher.toString, "-x", "160", "-i", "basics.xml", "l.png"), d, on)
      assertEquals(lanes, Processes.Exit(0, "", ""))
      assert(
        java.util.Arrays
          .equals(Files.readAllBytes(d.resolve("p.png")), Files.readAllBytes(d.resolve("l.png"))),
        "the same bytes"
      )
      // A user's error still reaches stderr, as one line, with its exit status.
      Files.writeString(d.resolve("bad.xml"), "<scene><camera/></scene>")
      val bad = Processes.run(Seq(launcher.toString, "-i", "bad.xml", "o.png"), d, on)
      assertEquals((bad.status, bad.out), (1, ""))
      assertEquals(bad.err.linesIterator.toList.length, 1, bad.err)
      assert(bad.err.startsWith("tracer: bad.xml: line 1: <camera>: missing <location>"), bad.err)

  work.test("TRACER_CACHE other than off or cds is one line and exit 2"): d =>
    val e = Processes.run(
      Seq(launcher.toString, "-i", "basics.xml", "o.png"),
      d,
      Map("TRACER_CACHE" -> Some("of"))
    )
    assertEquals((e.status, e.out), (2, ""))
    assertEquals(e.err, "tracer: TRACER_CACHE='of' must be off or cds (or unset)\n")
    assert(!Files.exists(d.resolve("o.png")))

  work.test("TRACER_LANES other than on or off is one line and exit 2"): d =>
    val e = Processes.run(
      Seq(launcher.toString, "-i", "basics.xml", "o.png"),
      d,
      Map("TRACER_LANES" -> Some("fast"))
    )
    assertEquals((e.status, e.out), (2, ""))
    assertEquals(e.err, "tracer: TRACER_LANES='fast' must be on or off\n")
    assert(!Files.exists(d.resolve("o.png")))

  work.test("TRACER_LANES=on on a terminal still shows the progress line"): d =>
    assume(
      Files.isExecutable(Path.of("/usr/bin/script")),
      "needs script(1) to give the run a terminal"
    )
    Files.copy(home.resolve("scenes/showcase.xml"), d.resolve("showcase.xml"))
    Files.createSymbolicLink(d.resolve("textures"), home.resolve("scenes/textures"))
    val command = s"cd '$d' && TRACER_LANES=on '$launcher' -x 1200 -a 3 -p 1 o.png < showcase.xml"
    val e = runIn(d, Path.of("/dev/null"), List("/usr/bin/script", "-qec", command, "/dev/null"))
    assertEquals(e.status, 0, e.out + e.err)
    assert(e.out.contains("\rtracer: rendering ") && e.out.contains(" rows)"), e.out)
    assert(!e.out.contains("WARNING"), e.out)

  /** The nice value and user-mode clock ticks of each thread of process `pid` whose name
    * (`/proc`'s `comm`, 15 characters at most) starts with `name`; none once it has ended.
    */
  private def threads(pid: Long, name: String): List[(Int, Long)] =
    val tasks =
      try Files.list(Path.of(s"/proc/$pid/task")).iterator.asScala.toList
      catch case _: java.io.IOException => Nil
    tasks.flatMap { task =>
      try
        val comm   = Files.readString(task.resolve("comm"), UTF_8).trim
        val fields = statFields(Files.readString(task.resolve("stat"), UTF_8))
        if comm.startsWith(name) then Some((fields(16).toInt, fields(11).toLong)) else None
      catch case _: java.io.IOException | _: NumberFormatException => None
    }

  /** The nice values of the render's threads once they have rendered for a while, and of the
    * JIT's C2 thread then, for the launcher started with `prefix` before it (e.g. `nice -n 3`).
    */
  private def priorities(d: Path, prefix: String*): (List[Int], List[Int]) =
    val command = prefix ++ Seq(launcher.toString, "-x", "1200", "-a", "3", "-p", "2", "o.png")
    val process = ProcessBuilder(command.asJava)
      .directory(d.toFile)
      .redirectInput(d.resolve("showcase.xml").toFile)
      .redirectOutput(ProcessBuilder.Redirect.DISCARD)
      .redirectError(ProcessBuilder.Redirect.DISCARD)
      .start()
    try
      // nice and the launcher each replace themselves, so the JVM keeps this process's number.
      val pid      = process.pid
      val deadline = System.nanoTime + TimeUnit.SECONDS.toNanos(100)
      // Why: polled until the rows have run for 20 clock ticks (their first row sets their
      // priority), or the process ends.
      var rows = threads(pid, "tracer-render")
      while process.isAlive && System.nanoTime < deadline && rows.map(_._2).sum < 20 do
        Thread.sleep(10)
        rows = threads(pid, "tracer-render")
      (rows.map(_._1), threads(pid, "C2 Compiler").map(_._1))
    finally
      process.destroy()
      process.waitFor(30, TimeUnit.SECONDS): Unit

  work.test("the rows run at nice 4, the JIT at 0; a niced run keeps its niceness everywhere"): d =>
    assume(Files.isDirectory(Path.of("/proc/self/task")), "needs Linux's /proc")
    assume(Files.isExecutable(Path.of("/usr/bin/nice")), "needs nice(1)")
    Files.copy(home.resolve("scenes/showcase.xml"), d.resolve("showcase.xml"))
    Files.createSymbolicLink(d.resolve("textures"), home.resolve("scenes/textures"))
    // The suite's own niceness (a test run under `nice` starts the launcher niced already).
    val own         = statFields(Files.readString(Path.of("/proc/self/stat"), UTF_8))(16).toInt
    val (rows, jit) = priorities(d)
    if own == 0 then
      assertEquals(rows, List(4, 4), "the two render threads")
      assertEquals(jit, List(0))
    else
      assertEquals(rows, List(own, own), "the two render threads of a niced run")
      assertEquals(jit, List(own))
    val niced                 = Math.min(19, own + 3)
    val (nicedRows, nicedJit) = priorities(d, "/usr/bin/nice", "-n", "3")
    assertEquals(nicedRows, List(niced, niced))
    assertEquals(nicedJit, List(niced))

  work.test(
    "for a user other than root nothing reaches stderr (the JVM's priority warning dropped)"
  ): d =>
    assume(
      Files.isExecutable(Path.of("/usr/bin/setpriv")) &&
        new com.sun.security.auth.module.UnixSystem().getUid == 0,
      "needs root and setpriv(1) to run the launcher as nobody"
    )
    val nobody = Seq("/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups")
    // The warning the JVM gives such a user, which the launcher must know to drop.
    val javaBin = Path.of(System.getProperty("java.home"), "bin", "java").toString
    val jvm     = Processes.run(nobody ++ Seq(javaBin, "-XX:ThreadPriorityPolicy=1", "-version"), d)
    assert(jvm.err.contains("warning: -XX:ThreadPriorityPolicy=1 may require"), jvm.err)
    // A copy of the launcher and its jar that nobody may read (the checkout may be private), run
    // without a start-up cache (whose training is not what this test is about), writing into a
    // directory nobody may write.
    val open = PosixFilePermissions.fromString("rwxr-xr-x")
    val copy = Files.createTempDirectory("tracer-public")
    try
      for name <- List("tracer", "launcher/launcher.sh", "target/scala-3.8.3/tracer.jar") do
        val to = copy.resolve(name)
        Files.createDirectories(to.getParent)
        Files.copy(home.resolve(name), to)
      Files
        .walk(copy)
        .forEach(p => if Files.isDirectory(p) then Files.setPosixFilePermissions(p, open): Unit)
      Files.setPosixFilePermissions(d, PosixFilePermissions.fromString("rwxrwxrwx"))
      val run = Processes.run(
        nobody ++ Seq(copy.resolve("tracer").toString, "-x", "160", "-i", "basics.xml", "n.png"),
        d,
        Map("TRACER_CACHE" -> Some("off"))
      )
      assertEquals(run, Processes.Exit(0, "", ""))
      assertEquals(
        Files.readAllBytes(d.resolve("n.png")).take(4).toSeq,
        Seq(0x89, 'P', 'N', 'G').map(_.toByte)
      )
    finally Files.walk(copy).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
