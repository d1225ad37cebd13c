package tracer.cli

import java.io.{ByteArrayInputStream, ByteArrayOutputStream, PrintStream}
import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import tracer.demo.{BenchScenes, PovRay}
import tracer.image.{Bitmap, Ppm}
import tracer.io.SceneWriter

/** An independent renderer agrees: POV-Ray 3.7, given the same scenes through
  * [[tracer.demo.PovRay]], draws the same pictures to within rounding and a few edge pixels.
  */
class PovRaySuite extends munit.FunSuite:

  private val povray = Path.of("/usr/bin/povray")

  override def beforeAll(): Unit =
    assume(
      Files.isExecutable(povray),
      "needs POV-Ray (apt-get install povray; .ci/run installs it)"
    )

  private def ours(xml: String, dir: Path): Bitmap =
    val out    = dir.resolve("ours.ppm")
    val err    = ByteArrayOutputStream()
    val status = Main.run(
      List("-x", "160", "-y", "90", out.toString),
      ByteArrayInputStream(xml.getBytes("UTF-8")),
      PrintStream(ByteArrayOutputStream()),
      PrintStream(err),
      dir
    )
    assertEquals(status, 0, err.toString)
    Ppm.read(Files.readAllBytes(out)).fold(fail(_), identity)

  private def theirs(pov: String, dir: Path): Bitmap =
    Files.writeString(dir.resolve("scene.pov"), pov)
    val process = ProcessBuilder(
      povray.toString,
      "+WT2",
      "-A",
      "+W160",
      "+H90",
      "+Iscene.pov",
      "+Otheirs.ppm",
      "+FP",
      "File_Gamma=1.0",
      "-D",
      "-V",
      "-GA"
    ).directory(dir.toFile)
      .redirectErrorStream(true)
      .redirectOutput(dir.resolve("povray.log").toFile)
      .start()
    assert(
      process.waitFor(120, TimeUnit.SECONDS) && process.exitValue == 0,
      Files.readString(dir.resolve("povray.log"))
    )
    Ppm.read(Files.readAllBytes(dir.resolve("theirs.ppm"))).fold(fail(_), identity)

  for name <- List("few", "spheres", "mesh-5000") do
    test(s"the $name benchmark scene matches POV-Ray's picture in 99.5% of its samples"):
      val dir = Files.createTempDirectory("povray")
      try
        val scene  = BenchScenes.scene(name)
        val (a, b) = (ours(SceneWriter.write(scene), dir), theirs(PovRay.write(scene), dir))
        assertEquals((a.width, a.height), (b.width, b.height))
        val samples = for x <- 0 until a.width; y <- 0 until a.height; c <- 0 until 3
        yield Math.abs(a.sample(x, y, c) - b.sample(x, y, c))
        val close = samples.count(_ <= 2).toDouble / samples.length
        // Shadow and silhouette edges may fall a pixel apart: the two renderers round differently.
        assert(
          close >= 0.995,
          f"only ${100 * close}%.2f%% of samples within 2 levels; largest difference ${samples.max}"
        )
      finally Files.walk(dir).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
