package tracer.demo

import java.io.{ByteArrayInputStream, ByteArrayOutputStream, PrintStream}
import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import tracer.cli.Main
import tracer.image.{Bitmap, Ppm}
import tracer.io.{SceneWriter, SceneXml}

/** An independent renderer agrees: POV-Ray 3.7, given the same scenes through
  * [[tracer.demo.PovRay]], draws the same pictures to within rounding and a few edge pixels —
  * the version 1 benchmark scenes, a scene for each addition of scene format version 2, the
  * version 3 scenes, and version 4's fade.
  */
class PovRaySuite extends munit.FunSuite:

  private val povray = Path.of("/usr/bin/povray")

  override def beforeAll(): Unit =
    assume(
      Files.isExecutable(povray),
      "needs POV-Ray (apt-get install povray; .ci/run installs it)"
    )

  private val size = List("-x", "160", "-y", "90")

  private def ours(dir: Path, options: List[String]): Bitmap =
    val out    = dir.resolve("ours.ppm")
    val err    = ByteArrayOutputStream()
    val status = Main.run(
      size ++ options ++ List("-i", "scene.xml", out.toString),
      ByteArrayInputStream(Array.emptyByteArray),
      PrintStream(ByteArrayOutputStream()),
      PrintStream(err),
      dir
    )
    assertEquals(status, 0, err.toString)
    Ppm.read(Files.readAllBytes(out)).fold(fail(_), identity)

  private def theirs(pov: String, dir: Path, gamma: String): Bitmap =
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
      s"File_Gamma=$gamma",
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

  /** Renders the scene written in `dir/scene.xml` with both renderers and checks that at least
    * `share` of the samples are within 2 levels of each other.
    */
  private def agree(dir: Path, share: Double, options: List[String] = Nil, gamma: String = "1.0") =
    val (a, b) = pictures(dir, options, gamma)
    assertEquals((a.width, a.height), (b.width, b.height))
    val samples = for x <- 0 until a.width; y <- 0 until a.height; c <- 0 until 3
    yield Math.abs(a.sample(x, y, c) - b.sample(x, y, c))
    val close = samples.count(_ <= 2).toDouble / samples.length
    val mse   = samples.map(d => d.toDouble * d).sum / samples.length
    val psnr  = if mse == 0 then Double.PositiveInfinity else 10 * Math.log10(255.0 * 255 / mse)
    // Shadow and silhouette edges may fall a pixel apart: the two renderers round differently.
    assert(
      close >= share,
      f"only ${100 * close}%.2f%% of samples within 2 levels (PSNR $psnr%.1f dB); largest difference ${samples.max}"
    )

  /** Our picture of `dir/scene.xml` with `options`, and POV-Ray's of its twin (at the same
    * depth, and in quick mode for `-q`).
    */
  private def pictures(dir: Path, options: List[String], gamma: String): (Bitmap, Bitmap) =
    val scene = SceneXml.load(dir.resolve("scene.xml"), dir).fold(fail(_), identity)
    val depth = options.sliding(2).collectFirst { case List("-r", d) => d.toInt }
    val twin  = PovRay.write(scene, depth.getOrElse(5), quick = options.contains("-q"))
    (ours(dir, options), theirs(twin, dir, gamma))

  /** The version 3 criterion: PSNR ≥ 40 dB, and at most 0.5% of the pixels with a channel more
    * than 8 levels apart.
    */
  private def closeTo(dir: Path, options: List[String], gamma: String) =
    val (a, b) = pictures(dir, options, gamma)
    assertEquals((a.width, a.height), (b.width, b.height))
    val pixels = for x <- 0 until a.width; y <- 0 until a.height
    yield (0 until 3).map(c => Math.abs(a.sample(x, y, c) - b.sample(x, y, c)))
    val off  = pixels.count(_.max > 8).toDouble / pixels.length
    val mse  = pixels.flatten.map(d => d.toDouble * d).sum / (3 * pixels.length)
    val psnr = if mse == 0 then Double.PositiveInfinity else 10 * Math.log10(255.0 * 255 / mse)
    if psnr < 40 || off > 0.005 then
      val keep = Path.of("target", "povray-v3")
      Files.createDirectories(keep)
      val _ = Files.copy(dir.resolve("ours.ppm"), keep.resolve(s"${dir.getFileName}-ours.ppm"))
      val _ = Files.copy(dir.resolve("theirs.ppm"), keep.resolve(s"${dir.getFileName}-theirs.ppm"))
    assert(
      psnr >= 40 && off <= 0.005,
      f"PSNR $psnr%.1f dB, ${100 * off}%.2f%% of pixels off by > 8"
    )

  private def version3(name: String, options: List[String] = Nil, gamma: String = "1.0") =
    inTemporaryDirectory { dir =>
      val xml = new String(getClass.getResourceAsStream(s"/povray/$name.xml").readAllBytes, "UTF-8")
      Files.writeString(dir.resolve("scene.xml"), xml)
      // A model without vn normals, for smooth="auto".
      val bare = Models
        .obj(Models.icosphere(1), "bare")
        .linesIterator
        .filterNot(_.startsWith("vn "))
        .map(l => if l.startsWith("f ") then l.replaceAll("/(\\d*)/\\d+", "/$1") else l)
      Files.writeString(dir.resolve("bare.obj"), bare.mkString("", "\n", "\n"))
      closeTo(dir, options, gamma)
    }

  test("version 3's solids, placed, and the checker pattern match POV-Ray's"):
    version3("solids")

  test("CSG (nested, inherited surfaces, cut faces, placed) matches POV-Ray's"):
    version3("csg")

  test("glass solids and a glass CSG match POV-Ray's at -r 5 and -r 2"):
    version3("glass-solids", List("-r", "5"))
    version3("glass-solids", List("-r", "2"))

  test("inherited and own checkers sit where POV-Ray puts them, under placed children too"):
    version3("inherit")

  test("quick mode on version 3 scenes matches POV-Ray's eye light"):
    version3("solids", List("-q"))
    version3("csg", List("-q"))

  test("-g srgb on a version 3 scene matches POV-Ray's File_Gamma=sRGB"):
    version3("csg", List("-g", "srgb"), "sRGB")

  test("smooth=\"auto\" on a mesh without normals matches POV-Ray's smooth triangles"):
    version3("auto")

  private def inTemporaryDirectory(body: Path => Unit): Unit =
    val dir = Files.createTempDirectory("povray")
    try body(dir)
    finally Files.walk(dir).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)

  for name <- List("few", "spheres", "mesh-5000") do
    test(s"the $name benchmark scene matches POV-Ray's picture in 99.5% of its samples"):
      inTemporaryDirectory { dir =>
        Files.writeString(dir.resolve("scene.xml"), SceneWriter.write(BenchScenes.scene(name)))
        agree(dir, 0.995)
      }

  private def version2(name: String, options: List[String] = Nil, gamma: String = "1.0") =
    inTemporaryDirectory { dir =>
      val xml = new String(getClass.getResourceAsStream(s"/povray/$name.xml").readAllBytes, "UTF-8")
      Files.writeString(dir.resolve("scene.xml"), xml)
      Files.writeString(dir.resolve("coarse.obj"), Models.obj(Models.icosphere(1), "coarse"))
      agree(dir, 0.99, options, gamma)
    }

  test("highlights (phong, phong-size, specular, roughness) match POV-Ray's"):
    version2("highlights")

  test("glass (transmit, ior, total internal reflection, shadows through it) matches POV-Ray's"):
    version2("glass")

  test("area lights' soft shadows match POV-Ray's"):
    version2("area")

  test("version 4's fade on point and area lights matches POV-Ray's fade_distance and fade_power"):
    version2("fade")

  test("smooth meshes match POV-Ray's smooth triangles"):
    version2("smooth")

  test("-g srgb matches POV-Ray's File_Gamma=sRGB, and -g 2.2 its File_Gamma=2.2"):
    version2("highlights", List("-g", "srgb"), "sRGB")
    version2("glass", List("-g", "2.2"), "2.2")
