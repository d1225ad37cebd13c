package tracer.testkit

import java.nio.charset.StandardCharsets.UTF_8
import java.nio.file.attribute.PosixFilePermissions
import java.nio.file.{Files, Path}
import java.net.ServerSocket
import java.util.concurrent.TimeUnit
import scala.jdk.CollectionConverters.*

/** Running scripts as processes, and a movie workspace: a directory whose path has spaces, with a
  * "logging tracer" that records, one line a picture it is asked for (every frame of a `--batch`
  * list), where and whether over ssh it ran, then runs the real `tracer`.
  */
trait MovieWorkspace extends munit.FunSuite:

  // Each test starts the real tracer (a JVM) several times: allow for a slow, busy machine.
  override val munitTimeout = scala.concurrent.duration.Duration(3, "min")

  protected val home  = Path.of("").toAbsolutePath
  protected val movie = home.resolve("scripts/movie.sh")

  /** What one run of a script did. */
  final case class Exit(status: Int, out: String, err: String)

  protected def run(
      command: Seq[String],
      cwd: Path = home,
      env: Map[String, String] = Map.empty
  ): Exit =
    val (out, err) = (Files.createTempFile("out", ".txt"), Files.createTempFile("err", ".txt"))
    try
      val builder = ProcessBuilder(command*)
        .directory(cwd.toFile)
        .redirectOutput(out.toFile)
        .redirectError(err.toFile)
        .redirectInput(ProcessBuilder.Redirect.from(java.io.File("/dev/null")))
      builder.environment.putAll(env.asJava)
      val process = builder.start()
      assert(process.waitFor(300, TimeUnit.SECONDS), s"$command did not finish")
      Exit(process.exitValue, Files.readString(out, UTF_8), Files.readString(err, UTF_8))
    finally List(out, err).foreach(Files.delete)

  protected def executable(path: Path, text: String): Path =
    Files.writeString(path, text)
    Files.setPosixFilePermissions(path, PosixFilePermissions.fromString("rwxr-xr-x"))
    path

  /** A workspace whose path has spaces, with a tracer wrapper that logs every scene it renders. */
  protected val workspace = FunFixture[Path](
    _ =>
      val d = Files.createTempDirectory("movie test")
      Files.createDirectories(d.resolve("my frames"))
      Files.createDirectories(d.resolve("my movies"))
      executable(
        d.resolve("logging tracer"),
        s"""#!/usr/bin/env bash
           |# One line a frame: a --batch run renders every frame its list names.
           |list=; previous=
           |for a in "$$@"; do [ "$$previous" = --batch ] && list=$$a; previous=$$a; done
           |frames=1
           |[ -z "$$list" ] || frames=$$(grep -c '^[^#]' "$$list")
           |for ((k = 0; k < frames; k++)); do
           |  echo "$${SSH_CONNECTION:+ssh:}$$PWD" >> "${d.resolve("calls.log")}"
           |done
           |exec "${home.resolve("tracer")}" "$$@"
           |""".stripMargin
      ): Unit
      d
    ,
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
  )

  protected def scene(colour: String) =
    s"""<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
       |<light><location x="-3" y="3" z="-5"/></light>
       |<sphere radius="1"><centre x="0" y="0" z="0"/><surface><colour $colour/></surface></sphere></scene>""".stripMargin

  protected def writeFrames(d: Path, scenes: Seq[String]): Path =
    scenes.zipWithIndex.foreach((s, i) => Files.writeString(d.resolve(s"my frames/f$i.xml"), s))
    val list = "# a comment, then a blank line\n\n" + scenes.indices
      .map(i => s"f$i.xml")
      .mkString("\n") + "\n"
    Files.writeString(d.resolve("my frames/frames.txt"), list)

  protected def calls(d: Path): Int =
    if Files.exists(d.resolve("calls.log")) then Files.readAllLines(d.resolve("calls.log")).size
    else 0

  protected def probe(file: Path): (Int, Int, Int) =
    val e = run(
      List(
        "ffprobe",
        "-v",
        "error",
        "-count_frames",
        "-select_streams",
        "v:0",
        "-show_entries",
        "stream=width,height,nb_read_frames",
        "-of",
        "csv=p=0",
        file.toString
      )
    )
    assertEquals(e.status, 0, e.err)
    val Array(w, h, n) = e.out.trim.split(",").map(_.toInt)
    (w, h, n)

  protected def frameTimes(d: Path, name: String): Seq[Int] =
    times(d.resolve(s"my movies/$name-frames"))

  /** The figures of the `.time` files in `dir`, one a finished frame or band. */
  protected def times(dir: Path): Seq[Int] =
    Files
      .list(dir)
      .iterator
      .asScala
      .filter(_.toString.endsWith(".time"))
      .map(p => Files.readString(p).trim.toInt)
      .toSeq

  protected val colours =
    List("r=\"1\" g=\"0\" b=\"0\"", "r=\"0\" g=\"1\" b=\"0\"", "r=\"0\" g=\"0\" b=\"1\"")

  /** A directory of links to `tools` (found on this PATH), to use as a PATH without the others. */
  protected def pathWith(dir: Path, tools: String*): Path =
    val bin = Files.createDirectories(dir)
    for tool <- tools do
      val real = run(List("bash", "-c", s"command -v $tool")).out.trim
      if real.nonEmpty then Files.createSymbolicLink(bin.resolve(tool), Path.of(real)): Unit
    bin

  /** A throwaway OpenSSH server on a free loopback port, for the current user, with fresh keys. */
  protected final class Sshd(dir: Path, port: Int, process: Process):
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

  protected object Sshd:
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
        Files.createDirectories(Path.of("/run/sshd")): Unit
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
