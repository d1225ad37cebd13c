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

  private def movieRun(d: Path, output: String, env: Map[String, String]): Exit =
    run(
      List(
        movie.toString,
        d.resolve("logging tracer").toString,
        d.resolve("my frames/frames.txt").toString,
        d.resolve(s"my movies/$output").toString
      ),
      env = env + ("TRACER_OPTS" -> "-x 24 -p 1")
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
