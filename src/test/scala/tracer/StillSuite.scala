package tracer

import java.nio.file.{Files, Path}
import scala.jdk.CollectionConverters.*
import tracer.testkit.MovieWorkspace

/** `scripts/still.sh`: one picture rendered in bands — serially, on several cores (`FARM_JOBS`)
  * and through a real sshd (`FARM_HOSTS`) — and joined into exactly the picture of one run.
  */
class StillSuite extends MovieWorkspace:

  private val still = home.resolve("scripts/still.sh")

  /** The gallery's textured scene, copied into the workspace with its textures. */
  private def textured(d: Path): Path =
    val dir = Files.createDirectories(d.resolve("my scene"))
    Files.copy(home.resolve("scenes/textures.xml"), dir.resolve("textures.xml"))
    Files.createDirectories(dir.resolve("textures"))
    Files
      .list(home.resolve("scenes/textures"))
      .iterator
      .asScala
      .foreach(t => Files.copy(t, dir.resolve("textures").resolve(t.getFileName)))
    dir.resolve("textures.xml")

  private def stillRun(d: Path, scene: Path, output: String, env: Map[String, String] = Map.empty) =
    run(
      List(
        still.toString,
        d.resolve("logging tracer").toString,
        scene.toString,
        d.resolve(output).toString
      ),
      cwd = d,
      env = Map("TRACER_OPTS" -> "-x 48 -a 2 -p 1") ++ env
    )

  /** The picture of one plain run of the tracer, from the scene's directory. */
  private def single(
      d: Path,
      scene: Path,
      name: String,
      options: String = "-x 48 -a 2"
  ): List[Byte] =
    val e = run(
      List(
        "bash",
        "-c",
        s"""'${home.resolve("tracer")}' $options '${d.resolve(name)}' < '$scene'"""
      ),
      cwd = scene.getParent
    )
    assertEquals(e.status, 0, e.err)
    Files.readAllBytes(d.resolve(name)).toList

  private def total(e: Exit): Option[Int] =
    "Total tracetime: (\\d+) ms\n".r.findFirstMatchIn(e.out).map(_.group(1).toInt)

  private def bandTimes(d: Path, name: String): Seq[Int] = times(d.resolve(s"$name-bands"))

  workspace.test("serially: the bands joined are the single run's picture, PNG and PPM"): d =>
    val scene = textured(d)
    for name <- List("still.png", "still.ppm") do
      val e = stillRun(d, scene, name)
      assertEquals(e.status, 0, e.err)
      assertEquals(Files.readAllBytes(d.resolve(name)).toList, single(d, scene, s"one-$name"))
      assertEquals(total(e), Some(bandTimes(d, name.stripSuffix(name.takeRight(4))).sum))
      assertEquals(e.out.linesIterator.length, 1, e.out)
      assertEquals(e.err.linesIterator.count(_.startsWith("band ")), 4, e.err)

  workspace.test(
    "path mode: the bands joined are one run's picture, 8-bit and float (.pfm serially, .exr on 2 jobs)"
  ): d =>
    val scene = Files.copy(home.resolve("scenes/cornell.xml"), d.resolve("cornell.xml"))
    val opts  = "-x 12 -y 9 -m path -s 4 --seed 3"
    val runs  = List(
      "path.png" -> Map.empty[String, String],
      "path.pfm" -> Map.empty[String, String],
      "jobs.exr" -> Map("FARM_JOBS" -> "2")
    )
    for (name, env) <- runs do
      val e =
        stillRun(d, scene, name, Map("TRACER_OPTS" -> s"$opts -p 1", "FARM_BANDS" -> "5") ++ env)
      assertEquals(e.status, 0, e.err)
      assertEquals(e.err.linesIterator.count(_.startsWith("band ")), 5, e.err)
      assertEquals(Files.readAllBytes(d.resolve(name)).toList, single(d, scene, s"one-$name", opts))
    // The float bands are PFM (the unclamped mean), not 8-bit pictures.
    assert(Files.exists(d.resolve("path-bands/band-0005.pfm")))
    // Another seed is other noise: the comparison above can tell pictures apart.
    assertNotEquals(
      Files.readAllBytes(d.resolve("path.pfm")).toList,
      single(d, scene, "seed.pfm", "-x 12 -y 9 -m path -s 4 --seed 4")
    )

  workspace.test("a usage error in TRACER_OPTS is the tracer's message and one line, status 2"):
    d =>
      val scene = Files.copy(home.resolve("scenes/cornell.xml"), d.resolve("cornell.xml"))
      val e     = stillRun(d, scene, "bad.png", Map("TRACER_OPTS" -> "-x 8 -m path -a 2"))
      assertEquals(e.status, 2, e.err)
      assert(e.err.contains("tracer: -a is Whitted's antialiasing"), e.err)
      assert(e.err.contains("still.sh: the tracer refused TRACER_OPTS='-x 8 -m path -a 2'"), e.err)
      assert(!Files.exists(d.resolve("bad.png")) && total(e).isEmpty, e.out)
      assertEquals(calls(d), 1) // only the size query: no band was started

  workspace.test("FARM_JOBS=2 with 7 bands: the same picture, more bands than slots"): d =>
    val scene = textured(d)
    val e     = stillRun(d, scene, "farm.png", Map("FARM_JOBS" -> "2", "FARM_BANDS" -> "7"))
    assertEquals(e.status, 0, e.err)
    assertEquals(Files.readAllBytes(d.resolve("farm.png")).toList, single(d, scene, "one.png"))
    assertEquals(bandTimes(d, "farm").length, 7)
    assertEquals(total(e), Some(bandTimes(d, "farm").sum))

  workspace.test("a mesh scene and a tall thin picture (more bands asked than rows)"): d =>
    val dir = Files.createDirectories(d.resolve("meshes"))
    Files.copy(home.resolve("scenes/meshes.xml"), dir.resolve("meshes.xml"))
    Files.createDirectories(dir.resolve("models"))
    Files.createDirectories(dir.resolve("textures"))
    for
      sub <- List("models", "textures");
      f   <- Files.list(home.resolve(s"scenes/$sub")).iterator.asScala
    do Files.copy(f, dir.resolve(sub).resolve(f.getFileName))
    val e = stillRun(
      d,
      dir.resolve("meshes.xml"),
      "thin.ppm",
      Map("TRACER_OPTS" -> "-x 3 -y 5 -w 0.3 -h 0.5", "FARM_BANDS" -> "9")
    )
    assertEquals(e.status, 0, e.err)
    assertEquals(bandTimes(d, "thin").length, 5) // one row a band at most
    assertEquals(
      Files.readAllBytes(d.resolve("thin.ppm")).toList,
      single(d, dir.resolve("meshes.xml"), "one.ppm", "-x 3 -y 5 -w 0.3 -h 0.5")
    )

  workspace.test("a failing band is named; a rerun renders only the bands that are missing"): d =>
    val scene = textured(d)
    // A tracer whose first batch dies after its second band, as a crashed host would.
    val once  = d.resolve("failed once")
    val flaky = executable(
      d.resolve("flaky tracer"),
      s"""#!/usr/bin/env bash
         |list=; previous=
         |for a in "$$@"; do [ "$$previous" = --batch ] && list=$$a; previous=$$a; done
         |if [ -n "$$list" ] && [ ! -f "$once" ]; then
         |  touch "$once"
         |  head -2 "$$list" > "$$list.short"
         |  args=(); for a in "$$@"; do [ "$$a" = "$$list" ] && a="$$list.short"; args+=("$$a"); done
         |  "${d.resolve("logging tracer")}" "$${args[@]}"; rm -f "$$list.short"
         |  echo "tracer: simulated crash" >&2; exit 1
         |fi
         |exec "${d.resolve("logging tracer")}" "$$@"
         |""".stripMargin
    )
    val env   = Map("TRACER_OPTS" -> "-x 48 -a 2 -p 1")
    val runIt = () =>
      run(
        List(still.toString, flaky.toString, scene.toString, d.resolve("s.png").toString),
        cwd = d,
        env = env
      )
    val failed = runIt()
    assertEquals(failed.status, 1)
    assert(failed.err.contains("band 3 failed") && failed.err.contains("(-R "), failed.err)
    assert(failed.err.contains("band 4 failed"), failed.err)
    assertEquals(bandTimes(d, "s").length, 2) // bands 1 and 2 were finished and kept
    assert(!Files.exists(d.resolve("s.png")) && total(failed).isEmpty)
    val before  = calls(d)
    val resumed = runIt()
    assertEquals(resumed.status, 0, resumed.err)
    // Now only bands 3 and 4 are rendered (one batch), then joined.
    assertEquals(calls(d) - before, 2 + 2) // two bands, the size query and the join
    assertEquals(Files.readAllBytes(d.resolve("s.png")).toList, single(d, scene, "one.png"))

  workspace.test("changed options throw the old bands away"): d =>
    val scene = textured(d)
    assertEquals(stillRun(d, scene, "s.png").status, 0)
    val e = stillRun(d, scene, "s.png", Map("TRACER_OPTS" -> "-x 40 -p 1"))
    assertEquals(e.status, 0, e.err)
    assertEquals(
      Files.readAllBytes(d.resolve("s.png")).toList,
      single(d, scene, "one.png", "-x 40")
    )

  workspace.test("bad arguments: status 2 and a clear message; a bad scene names the problem"): d =>
    assertEquals(run(List(still.toString)).status, 2)
    val scene    = textured(d)
    val noTracer = run(List(still.toString, "/no/tracer", scene.toString, "x.png"))
    assertEquals(noTracer.status, 2)
    assert(noTracer.err.contains("TRACER"), noTracer.err)
    val tracer = d.resolve("logging tracer").toString
    assertEquals(run(List(still.toString, tracer, "/no/scene.xml", "x.png")).status, 2)
    val badJobs =
      run(List(still.toString, tracer, scene.toString, "x.png"), env = Map("FARM_JOBS" -> "0"))
    assert(badJobs.status == 2 && badJobs.err.contains("FARM_JOBS"), badJobs.err)
    Files.writeString(d.resolve("bad.xml"), "<scene>")
    val bad =
      run(List(still.toString, tracer, d.resolve("bad.xml").toString, d.resolve("x.png").toString))
    assertEquals(bad.status, 1)
    assert(bad.err.contains("line 1: malformed XML") && bad.err.contains("still.sh:"), bad.err)

  workspace.test("FARM_JOBS without GNU parallel is a clear message before anything is rendered"):
    d =>
      val scene = textured(d)
      val bin   = pathWith(d.resolve("bin"), "bash", "env", "dirname", "basename", "mkdir", "cat")
      val e     = run(
        List("bash", still.toString, d.resolve("logging tracer").toString, scene.toString, "x.png"),
        env = Map("PATH" -> bin.toString, "FARM_JOBS" -> "2")
      )
      assertEquals(e.status, 1)
      assert(e.err.contains("GNU parallel") && e.err.contains("apt-get install parallel"), e.err)
      assertEquals(calls(d), 0)

  workspace.test(
    "FARM_HOSTS: bands rendered through a real sshd on a loopback port join up exactly"
  ): d =>
    val sshd = Sshd.start(Files.createTempDirectory("sshd"))
    try
      val scene = textured(d)
      val e     = stillRun(
        d,
        scene,
        "farm.png",
        Map("FARM_HOSTS" -> sshd.loginFile(d.resolve("hosts")).toString)
      )
      assertEquals(e.status, 0, e.err)
      assertEquals(Files.readAllBytes(d.resolve("farm.png")).toList, single(d, scene, "one.png"))
      // Two slots (the sshd and this machine): eight bands, some of them over ssh.
      assertEquals(bandTimes(d, "farm").length, 8)
      assertEquals(total(e), Some(bandTimes(d, "farm").sum))
      val log = Files.readAllLines(d.resolve("calls.log")).asScala
      assert(log.exists(_.startsWith("ssh:")), s"no band went through ssh: $log")
    finally sshd.stop()

  workspace.test("movie.sh takes FARM_JOBS too"): d =>
    writeFrames(d, colours.map(this.scene)): Unit
    val e = run(
      List(
        movie.toString,
        d.resolve("logging tracer").toString,
        d.resolve("my frames/frames.txt").toString,
        d.resolve("my movies/m.mp4").toString
      ),
      env = Map("TRACER_OPTS" -> "-x 16 -p 1", "FARM_JOBS" -> "2")
    )
    assertEquals(e.status, 0, e.err)
    assertEquals(frameTimes(d, "m").length, 3)
