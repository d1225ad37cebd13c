package tracer

import java.net.ServerSocket
import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
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
    writeFrames(d, shades.map(scene))
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
    writeFrames(d, shades.take(2).map(scene) ++ List("<scene>", scene(shades(3))))
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
      writeFrames(d, shades.take(1).map(scene))
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
      writeFrames(d, shades.map(scene))
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

  /** A throwaway OpenSSH server on a free loopback port, for the current user, with fresh keys. */
  private final class Sshd(dir: Path, port: Int, process: Process):
    /** An sshlogin file for GNU parallel: this server, one job, and the local machine `:`. */
    def loginFile(path: Path): Path =
      val ssh =
        s"ssh -p $port -i ${dir.resolve("user_key")} -o StrictHostKeyChecking=no -o UserKnownHostsFile=/dev/null " +
          s"-o LogLevel=ERROR -o BatchMode=yes ${System.getProperty("user.name")}@127.0.0.1"
      Files.writeString(path, s"1/$ssh\n1/:\n")

    def stop(): Unit =
      process.destroy()
      process.waitFor(10, TimeUnit.SECONDS)
      Files.walk(dir).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)

  private object Sshd:
    def start(dir: Path): Sshd =
      for key <- List("host_key", "user_key") do
        assertEquals(
          run(
            List("ssh-keygen", "-q", "-t", "ed25519", "-N", "", "-f", dir.resolve(key).toString)
          ).status,
          0
        )
      Files.copy(dir.resolve("user_key.pub"), dir.resolve("authorized_keys"))
      val port =
        val s = ServerSocket(0);
        try s.getLocalPort
        finally s.close()
      Files.writeString(
        dir.resolve("sshd_config"),
        s"""Port $port
           |ListenAddress 127.0.0.1
           |HostKey ${dir.resolve("host_key")}
           |AuthorizedKeysFile ${dir.resolve("authorized_keys")}
           |PidFile ${dir.resolve("sshd.pid")}
           |StrictModes no
           |UsePAM no
           |PasswordAuthentication no
           |KbdInteractiveAuthentication no
           |PermitRootLogin prohibit-password
           |""".stripMargin
      )
      // Privilege separation needs this directory when sshd runs as root.
      if System.getProperty("user.name") == "root" then
        Files.createDirectories(Path.of("/run/sshd"))
      val sshd = Path.of("/usr/sbin/sshd")
      assert(
        Files.isExecutable(sshd),
        "needs OpenSSH's sshd (apt-get install openssh-server; .ci/run installs it)"
      )
      val process =
        ProcessBuilder(sshd.toString, "-D", "-e", "-f", dir.resolve("sshd_config").toString)
          .redirectErrorStream(true)
          .redirectOutput(dir.resolve("sshd.log").toFile)
          .start()
      // Wait until it accepts connections.
      val ready = (1 to 50).exists { _ =>
        Thread.sleep(100)
        try
          java.net.Socket("127.0.0.1", port).close(); true
        catch case _: java.io.IOException => false
      }
      assert(ready, s"sshd did not start: ${Files.readString(dir.resolve("sshd.log"))}")
      Sshd(dir, port, process)
