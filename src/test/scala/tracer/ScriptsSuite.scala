package tracer

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.testkit.MovieWorkspace

/** The shell scripts, run as a user runs them: `scripts/movie.sh` with the real tracer and ffmpeg,
  * and `scripts/extract-docs.sh` on a fixture and on the project itself.
  */
class ScriptsSuite extends MovieWorkspace:

  workspace.test(
    "a movie of tiny frames: total = the sum of the frames' times, every frame encoded, odd sizes padded"
  ): d =>
    writeFrames(d, colours.map(scene)): Unit
    val output = d.resolve("my movies/tiny.mp4")
    // Run from an unrelated directory, with a relative FRAMES path.
    val e = run(
      List(
        movie.toString,
        d.resolve("logging tracer").toString,
        "my frames/frames.txt",
        output.toString
      ),
      cwd = d,
      env = Map("TRACER_OPTS" -> "-x 33 -y 25 -p 1")
    )
    assertEquals(e.status, 0, e.err)
    val total = "Total tracetime: (\\d+) ms\n".r.findFirstMatchIn(e.out).map(_.group(1).toInt)
    assertEquals(e.out.linesIterator.toList.length, 1, e.out)
    assertEquals(total, Some(frameTimes(d, "tiny").sum))
    assertEquals(frameTimes(d, "tiny").length, 3)
    assertEquals(probe(output), (34, 26, 3))
    // One progress line a frame; each frame rendered from its scene's directory.
    assertEquals(e.err.linesIterator.count(_.startsWith("frame ")), 3, e.err)
    assertEquals(
      Files.readAllLines(d.resolve("calls.log")).asScala.toSet,
      Set(d.resolve("my frames").toString)
    )

  workspace.test(".mpg gives MPEG-1 video"): d =>
    val list   = writeFrames(d, colours.take(2).map(scene))
    val output = d.resolve("my movies/course.mpg")
    val e      = run(
      List(movie.toString, d.resolve("logging tracer").toString, list.toString, output.toString),
      env = Map("TRACER_OPTS" -> "-x 32")
    )
    assertEquals(e.status, 0, e.err)
    val codec = run(
      List(
        "ffprobe",
        "-v",
        "error",
        "-select_streams",
        "v:0",
        "-show_entries",
        "stream=codec_name",
        "-of",
        "csv=p=0",
        output.toString
      )
    )
    assertEquals(codec.out.trim, "mpeg1video")

  workspace.test("a failing frame stops the movie naming it; a rerun renders only what is missing"):
    d =>
      val list    = writeFrames(d, List(scene(colours(0)), "<scene>broken", scene(colours(2))))
      val output  = d.resolve("my movies/resume.mp4")
      val command =
        List(movie.toString, d.resolve("logging tracer").toString, list.toString, output.toString)
      val env    = Map("TRACER_OPTS" -> "-x 16")
      val failed = run(command, env = env)
      assertEquals(failed.status, 1)
      assert(failed.err.contains("frame 2 failed") && failed.err.contains("f1.xml"), failed.err)
      assert(!failed.out.contains("Total"), failed.out)
      assert(!Files.exists(output))
      // The frames go to one tracer process (a batch), which renders frame 3 despite frame 2.
      assertEquals(calls(d), 3)
      assertEquals(frameTimes(d, "resume").length, 2)
      // Mend the scene: the rerun renders frame 2 only, and still totals all three.
      Files.writeString(d.resolve("my frames/f1.xml"), scene(colours(1)))
      val resumed = run(command, env = env)
      assertEquals(resumed.status, 0, resumed.err)
      assertEquals(calls(d), 4)
      assert(resumed.err.contains("frame 1/3") && resumed.err.contains("done before"), resumed.err)
      assertEquals(resumed.out, s"Total tracetime: ${frameTimes(d, "resume").sum} ms\n")
      assertEquals(probe(output)._3, 3)
      // A third run renders nothing at all.
      assertEquals(run(command, env = env).status, 0)
      assertEquals(calls(d), 4)

  workspace.test("without ffmpeg the frames are rendered, then a message says how to install it"):
    d =>
      val list = writeFrames(d, colours.take(1).map(scene))
      // A PATH with the tools the script and the tracer need, but no ffmpeg.
      val bin = pathWith(
        d.resolve("bin"),
        "bash",
        "env",
        "dirname",
        "basename",
        "mkdir",
        "cat",
        "sed",
        "mv",
        "rm",
        "find",
        "java",
        "readlink",
        "mktemp",
        "grep"
      )
      val e = run(
        List(
          "bash",
          movie.toString,
          d.resolve("logging tracer").toString,
          list.toString,
          d.resolve("my movies/x.mp4").toString
        ),
        env = Map("PATH" -> bin.toString, "TRACER_OPTS" -> "-x 16")
      )
      assertEquals(e.status, 1, e.err)
      assert(e.out.startsWith("Total tracetime: "), e.out)
      assert(
        e.err.contains("ffmpeg is not installed") && e.err.contains("apt-get install ffmpeg"),
        e.err
      )
      assertEquals(frameTimes(d, "x").length, 1)

  /** The picture `tracer OPTIONS -i SCENE` makes, run alone from the scene's directory. */
  private def singleRun(d: Path, scene: Path, options: String, name: String): List[Byte] =
    val e = run(
      List(
        "bash",
        "-c",
        s"""'${home.resolve("tracer")}' $options -i '$scene' '${d.resolve(name)}'"""
      ),
      cwd = scene.getParent
    )
    assertEquals(e.status, 0, e.err)
    Files.readAllBytes(d.resolve(name)).toList

  workspace.test(
    "path mode: every frame is the bytes of a single run with the same options and seed"
  ): d =>
    writeFrames(d, colours.map(scene)): Unit
    val options = "-x 9 -y 7 -m path -s 4 --seed 3 -p 1"
    val e       = run(
      List(
        movie.toString,
        d.resolve("logging tracer").toString,
        d.resolve("my frames/frames.txt").toString,
        d.resolve("my movies/path.mp4").toString
      ),
      env = Map("TRACER_OPTS" -> options)
    )
    assertEquals(e.status, 0, e.err)
    val frames = (1 to 3).map(n =>
      Files.readAllBytes(d.resolve(f"my movies/path-frames/frame-$n%06d.png")).toList
    )
    val alone =
      colours.indices.map(i => singleRun(d, d.resolve(s"my frames/f$i.xml"), options, s"$i.png"))
    assertEquals(frames, alone)
    // The frames are path mode's, not Whitted's.
    assertNotEquals(frames(0), singleRun(d, d.resolve("my frames/f0.xml"), "-x 9 -y 7", "w.png"))
    assertEquals(probe(d.resolve("my movies/path.mp4"))._3, 3)

  workspace.test(
    "a usage error in TRACER_OPTS: the tracer's message, one line saying so, status 2"
  ): d =>
    val list = writeFrames(d, colours.take(2).map(scene))
    val e    = run(
      List(movie.toString, d.resolve("logging tracer").toString, list.toString, "bad.mp4"),
      cwd = d,
      env = Map("TRACER_OPTS" -> "-x 8 -m path -a 2")
    )
    assertEquals(e.status, 2, e.err)
    assert(e.err.contains("tracer: -a is Whitted's antialiasing"), e.err)
    assert(
      e.err.contains("movie.sh: the tracer refused TRACER_OPTS='-x 8 -m path -a 2'"),
      e.err
    )
    assert(!e.err.contains("failed"), e.err)
    assert(!e.out.contains("Total") && !Files.exists(d.resolve("bad.mp4")), e.out)
    // Nothing left behind: the frames directory the run made goes again, empty.
    assert(!Files.exists(d.resolve("bad-frames")))
    // Nor after a list that names no scene, while a directory made before the run stays.
    val empty = Files.writeString(d.resolve("empty.txt"), "# no frames\n")
    Files.createDirectory(d.resolve("kept-frames"))
    for output <- List("none.mp4", "kept.mp4") do
      val refused =
        run(
          List(movie.toString, d.resolve("logging tracer").toString, empty.toString, output),
          cwd = d
        )
      assertEquals(refused.status, 1, refused.err)
      assert(refused.err.contains("names no scene files"), refused.err)
    assert(!Files.exists(d.resolve("none-frames")))
    assert(Files.isDirectory(d.resolve("kept-frames")))

  workspace.test(
    "ab.sh times each jar on the scene, alternating, and keeps the pictures asked for"
  ): d =>
    val scene = Files.writeString(d.resolve("red.xml"), this.scene(colours(0)))
    // The project's jar, built by the tracer script if need be.
    assertEquals(run(List(home.resolve("tracer").toString, "--version")).status, 0)
    val jar  = home.resolve("target/scala-3.8.3/tracer.jar").toString
    val kept = d.resolve("kept")
    val e    = run(
      List("bash", "scripts/ab.sh", "--runs", "2", "--frames", "3", "--keep", kept.toString) ++
        List(scene.toString, jar, jar, "--", "-x", "9", "-y", "7")
    )
    assertEquals(e.status, 0, e.err)
    // A line a jar, a figure a run.
    assertEquals(e.out.linesIterator.count(_.matches(s"\\Q$jar\\E: \\d+ \\d+")), 2, e.out)
    val pictures = for i <- 0 to 1; f <- 1 to 3 yield Files.readAllBytes(kept.resolve(s"$i-$f.png"))
    assert(pictures.forall(_.sameElements(pictures(0))))
    assertEquals(run(List("bash", "scripts/ab.sh", scene.toString)).status, 2)
    assertEquals(run(List("bash", "scripts/ab.sh", "--runs", "x", scene.toString, jar)).status, 2)
    // A render the tracer refuses: its own message, then one line naming the jar.
    val refused = run(List("bash", "scripts/ab.sh", scene.toString, jar, "--", "-x", "0"))
    assertEquals(refused.status, 1)
    assert(refused.err.contains(s"ab.sh: $jar failed"), refused.err)

  workspace.test(
    "alternate.sh runs each checkout's tracer in turn and prints its times and median"
  ): d =>
    val scene = Files.writeString(d.resolve("red.xml"), this.scene(colours(0)))
    // The project's jar, built by the tracer script if need be (its messages are not ours).
    assertEquals(run(List(home.resolve("tracer").toString, "--version")).status, 0)
    val checkout = home.toString
    val e        = run(
      List("bash", "scripts/alternate.sh", "--runs", "2", scene.toString, checkout, checkout) ++
        List("--", "-p", "1", "-x", "9", "-y", "7")
    )
    assertEquals(e.status, 0, e.err)
    // A line a checkout: a wall time (Tracetime) a round, then the median wall time.
    val line = s"\\Q$checkout\\E: (\\d+)\\(\\d+\\) (\\d+)\\(\\d+\\) median (\\d+)".r
    val rows = e.out.linesIterator.toList
    assertEquals(rows.length, 2, e.out)
    rows.foreach {
      case line(first, second, median) =>
        assertEquals(median.toInt, Math.min(first.toInt, second.toInt))
      case other => fail(s"unexpected line: $other")
    }
    // The same checkout draws the same picture: nothing on standard error.
    assertEquals(e.err, "")
    assertEquals(run(List("bash", "scripts/alternate.sh", scene.toString)).status, 2)
    assertEquals(run(List("bash", "scripts/alternate.sh", scene.toString, d.toString)).status, 2)
    val refused =
      run(
        List(
          "bash",
          "scripts/alternate.sh",
          "--runs",
          "1",
          scene.toString,
          checkout,
          "--",
          "-x",
          "0"
        )
      )
    assertEquals(refused.status, 1)
    assert(refused.err.contains(s"alternate.sh: $checkout failed"), refused.err)

  test("movie.sh refuses bad arguments with status 2"):
    assertEquals(run(List(movie.toString)).status, 2)
    assertEquals(run(List(movie.toString, "/no/such/tracer", "frames.txt")).status, 2)
    val e = run(List(movie.toString, home.resolve("tracer").toString, "build.sbt", "movie.avi"))
    assertEquals(e.status, 2)
    assert(e.err.contains(".mpg") && e.err.contains(".mp4"), e.err)

  test(
    "extract-docs.sh lists the public, documented declarations of a fixture with their summaries"
  ):
    val e = run(List("bash", "scripts/extract-docs.sh", "src/test/resources/extract-docs"))
    assertEquals(e.status, 0, e.err)
    assertEquals(
      e.out,
      Files.readString(home.resolve("src/test/resources/extract-docs/expected.md"))
    )

  test("docs/api.md is what extract-docs.sh makes of the sources today"):
    val e = run(List("bash", "scripts/extract-docs.sh"))
    assertEquals(e.status, 0, e.err)
    assert(
      e.out.contains(
        "`final case class Vec3(x: Double, y: Double, z: Double)` — An immutable vector"
      ),
      e.out.take(500)
    )
    assertEquals(
      e.out,
      Files.readString(home.resolve("docs/api.md")),
      "run: scripts/extract-docs.sh > docs/api.md"
    )

  workspace.test("ci-totals.sh ends CI with the plain totals line, even after sbt's escape codes"):
    d =>
      val log = d.resolve("sbt.log")
      Files.writeString(
        log,
        "[info] \u001b[32mPassed: Total 12, Failed 0, Errors 0, Passed 12\u001b[0m\n" +
          "[error] Failed: Total 5, Failed 1, Errors 1, Passed 3\n\u001b[0J"
      )
      val e = run(List("bash", "scripts/ci-totals.sh", log.toString, "1"))
      assertEquals(e.status, 0, e.err)
      assertEquals(e.out.linesIterator.toList.last, "15 passed, 2 failed")
      assert(e.out.endsWith("\n15 passed, 2 failed\n"), e.out)
      Files.writeString(log, "[info] Passed: Total 3, Failed 0, Errors 0, Passed 3\n")
      assertEquals(
        run(List("bash", "scripts/ci-totals.sh", log.toString, "0")).out,
        "3 passed, 0 failed\n"
      )
      // A run that failed without a failing test (a compile error) counts one failure.
      assertEquals(
        run(List("bash", "scripts/ci-totals.sh", log.toString, "1")).out,
        "3 passed, 1 failed\n"
      )

  test(".ci/run runs the README's test command and closes with ci-totals.sh"):
    val ci     = Files.readString(home.resolve(".ci/run"))
    val readme = Files.readString(home.resolve("README.md"))
    assert(readme.contains("    bash .ci/run\n"), "README's test command")
    assert(ci.contains("./sbt check") && ci.contains("scripts/ci-totals.sh"), ci)
