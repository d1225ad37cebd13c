package tracer

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.testkit.MovieWorkspace

/** `scripts/movie.sh` on a render farm: frames through GNU parallel on several cores
  * (`MOVIE_JOBS`) and on a real ssh host (`MOVIE_HOSTS`), with every guarantee of a serial run.
  */
class FarmSuite extends MovieWorkspace:

  private val movie  = home.resolve("scripts/movie.sh")
  private val shades = (1 to 6).toList.map(i => s"""r="${i / 6.0}" g="0.5" b="${1 - i / 6.0}"""")

  private def movieRun(
      d: Path,
      output: String,
      env: Map[String, String],
      options: String = "-x 24 -p 1"
  ): Exit =
    run(
      List(
        movie.toString,
        d.resolve("logging tracer").toString,
        d.resolve("my frames/frames.txt").toString,
        d.resolve(s"my movies/$output").toString
      ),
      env = env + ("TRACER_OPTS" -> options)
    )

  private def frames(d: Path, name: String): Seq[List[Byte]] =
    Files
      .list(d.resolve(s"my movies/$name-frames"))
      .iterator
      .asScala
      .toSeq
      .sortBy(_.toString)
      .filter(_.toString.endsWith(".png"))
      .map(p => Files.readAllBytes(p).toList)

  private def total(e: Exit): Option[Int] =
    "Total tracetime: (\\d+) ms".r.findFirstMatchIn(e.out).map(_.group(1).toInt)

  workspace.test(
    "MOVIE_JOBS=2 renders the same frames as a serial run, and totals them the same way"
  ): d =>
    writeFrames(d, shades.map(scene)): Unit
    val serial   = movieRun(d, "serial.mp4", Map.empty)
    val parallel = movieRun(d, "parallel.mp4", Map("MOVIE_JOBS" -> "2"))
    assertEquals((serial.status, parallel.status), (0, 0), parallel.err)
    assertEquals(frames(d, "parallel"), frames(d, "serial"))
    assertEquals(frames(d, "parallel").length, 6)
    assertEquals(total(parallel), Some(frameTimes(d, "parallel").sum))
    assertEquals(parallel.err.linesIterator.count(_.startsWith("frame ")), 6, parallel.err)

  workspace.test("MOVIE_JOBS=2 in path mode: the same frames as a serial run, one seed for all"):
    d =>
      writeFrames(d, shades.take(4).map(scene)): Unit
      val options  = "-x 10 -y 8 -m path -s 4 --seed 3 -p 1"
      val serial   = movieRun(d, "serial.mp4", Map.empty, options)
      val parallel =
        movieRun(d, "parallel.mp4", Map("MOVIE_JOBS" -> "2", "MOVIE_CHUNK" -> "1"), options)
      assertEquals((serial.status, parallel.status), (0, 0), parallel.err)
      assertEquals(frames(d, "parallel"), frames(d, "serial"))
      assertEquals(frames(d, "parallel").length, 4)
      // Each frame its own process: a per-process seed or noise would differ from the serial batch.
      assertEquals(calls(d), 8)

  workspace.test("MOVIE_JOBS=2: a usage error in TRACER_OPTS is said once a chunk, status 2"): d =>
    writeFrames(d, shades.take(2).map(scene)): Unit
    val e = movieRun(d, "bad.mp4", Map("MOVIE_JOBS" -> "2"), "-x 8 -m path -a 2")
    assertEquals(e.status, 2, e.err)
    assert(e.err.contains("tracer: -a is Whitted's antialiasing"), e.err)
    assert(e.err.contains("movie.sh: the tracer refused TRACER_OPTS="), e.err)
    assert(!e.err.contains("movie.sh: frame"), e.err)
    assert(total(e).isEmpty && !Files.exists(d.resolve("my movies/bad.mp4")), e.out)

  workspace.test(
    "MOVIE_JOBS=2: a failing frame is named and stops the movie; a rerun renders only what is missing"
  ): d =>
    writeFrames(d, shades.take(2).map(scene) ++ List("<scene>", scene(shades(3)))): Unit
    val failed = movieRun(d, "farm.mp4", Map("MOVIE_JOBS" -> "2"))
    assertEquals(failed.status, 1)
    assert(failed.err.contains("frame 3 failed") && failed.err.contains("f2.xml"), failed.err)
    assert(total(failed).isEmpty, failed.out)
    val before = calls(d)
    Files.writeString(d.resolve("my frames/f2.xml"), scene(shades(2)))
    val resumed = movieRun(d, "farm.mp4", Map("MOVIE_JOBS" -> "2"))
    assertEquals(resumed.status, 0, resumed.err)
    val rendered = frameTimes(d, "farm").length
    assertEquals(rendered, 4)
    // Only the frames without a time were rendered again: at most the failed one and the one after it.
    assert(calls(d) - before <= 2 && calls(d) - before >= 1, s"${calls(d) - before} renders")
    assertEquals(total(resumed), Some(frameTimes(d, "farm").sum))

  workspace.test("MOVIE_JOBS without GNU parallel is a clear message before anything is rendered"):
    d =>
      writeFrames(d, shades.take(1).map(scene)): Unit
      val bin =
        pathWith(d.resolve("bin"), "bash", "env", "dirname", "basename", "mkdir", "cat", "sed")
      val e = run(
        List(
          "bash",
          movie.toString,
          d.resolve("logging tracer").toString,
          d.resolve("my frames/frames.txt").toString,
          d.resolve("my movies/x.mp4").toString
        ),
        env = Map("PATH" -> bin.toString, "MOVIE_JOBS" -> "2")
      )
      assertEquals(e.status, 1)
      assert(e.err.contains("GNU parallel") && e.err.contains("apt-get install parallel"), e.err)
      assertEquals(calls(d), 0)

  workspace.test(
    "MOVIE_HOSTS: frames rendered through a real sshd on a loopback port are identical"
  ): d =>
    // sshd_config cannot quote paths, so its files live where the path has no spaces.
    val sshd = Sshd.start(Files.createTempDirectory("sshd"))
    try
      writeFrames(d, shades.map(scene)): Unit
      val serial = movieRun(d, "serial.mp4", Map.empty)
      assertEquals(serial.status, 0, serial.err)
      val before = calls(d)
      val farm   =
        movieRun(d, "farm.mp4", Map("MOVIE_HOSTS" -> sshd.loginFile(d.resolve("hosts")).toString))
      assertEquals(farm.status, 0, farm.err)
      assertEquals(frames(d, "farm"), frames(d, "serial"))
      assertEquals(total(farm), Some(frameTimes(d, "farm").sum))
      val log = Files.readAllLines(d.resolve("calls.log")).asScala.drop(before)
      assertEquals(log.length, 6)
      assert(log.exists(_.startsWith("ssh:")), s"no frame went through ssh: $log")
    finally sshd.stop()
