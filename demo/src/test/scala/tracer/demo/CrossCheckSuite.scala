package tracer.demo

import java.io.{ByteArrayInputStream, ByteArrayOutputStream, PrintStream}
import java.nio.file.{Files, Path}
import tracer.cli.Main
import tracer.image.{Bitmap, Ppm}
import tracer.io.SceneXml
import tracer.testkit.Tools

/** Random scenes ([[RandomScenes]]) drawn by POV-Ray 3.7 from their twins ([[PovRay]]) agree
  * with ours: PSNR at least 40 dB, and at most 0.5% of the pixels with a channel more than 8
  * levels apart, leaving out pixels where either picture is at 254 or more in some channel
  * (there POV-Ray clips each channel and we keep the hue: docs/rendering.md). That is the
  * criterion of version 3's scenes, held by every seed here; the scenes are small (120×90) and
  * many, so that one test covers the combinations no hand-made scene does.
  */
class CrossCheckSuite extends munit.FunSuite:

  private val povray = Tools.find("povray").getOrElse(Path.of("/usr/bin/povray"))

  // As PovRaySuite: skipped without POV-Ray, failed without it in CI.
  override def beforeAll(): Unit =
    Tools.require("povray", "apt-get install povray"): Unit

  private val (width, height) = (120, 90)

  /** The seeds checked: 1 to 40, or the range `FIRST-LAST` that `CROSSCHECK_SEEDS` names (to
    * search further: `CROSSCHECK_SEEDS=1000-1500 ./sbt "demo/testOnly *CrossCheckSuite"`).
    */
  private val seeds: Seq[Long] = sys.env.get("CROSSCHECK_SEEDS") match
    case None        => 1L to 40L
    case Some(range) =>
      range.split('-').toList.flatMap(_.toLongOption) match
        case List(first, last) if first <= last => first to last
        case _ => sys.error(s"CROSSCHECK_SEEDS=$range: not a range FIRST-LAST")

  test("the first 40 seeds cover every element and finish the scenes may hold"):
    val texts  = (1L to 40L).map(RandomScenes.scene(_).xml)
    val wanted = List(
      "<sphere",
      "<plane",
      "<box",
      "<cylinder",
      "<cone",
      "<torus",
      "<triangle",
      "<mesh",
      "<union",
      "<intersection",
      "<difference",
      "<area",
      "fade-distance",
      "<checker",
      "<up",
      "<rotate",
      "scale=",
      "open=\"true\"",
      "smooth=\"auto\"",
      "smooth=\"true\"",
      "reflection=",
      "phong=",
      "phong-size=",
      "specular=",
      "roughness=",
      "transmit=",
      "ior="
    )
    assertEquals(wanted.filterNot(w => texts.exists(_.contains(w))), Nil)
    val nested = texts.exists(t =>
      scala.xml.XML
        .loadString(t)
        .descendant
        .exists(e => combinations(e.label) && e.child.exists(c => combinations(c.label)))
    )
    assert(nested, "no combination inside another")

  private val combinations = Set("union", "intersection", "difference")

  for seed <- seeds do
    test(s"random scene $seed draws as POV-Ray draws its twin"):
      check(seed, quick = false)

  // Quick mode (-q) against the twin's light at the eye, on the first half of the seeds.
  for seed <- seeds.take(seeds.length / 2) do
    test(s"random scene $seed in quick mode draws as POV-Ray's eye light does"):
      check(seed, quick = true)

  private def check(seed: Long, quick: Boolean): Unit =
    val dir = Files.createTempDirectory("crosscheck")
    try
      val random = RandomScenes.scene(seed)
      Files.writeString(dir.resolve("scene.xml"), random.xml)
      Files.createDirectories(dir.resolve("models"))
      RandomScenes.models.foreach((name, text) =>
        Files.writeString(dir.resolve(s"models/$name"), text)
      )
      val ours        = render(dir, random.depth, quick)
      val theirs      = povrayRender(dir, random.depth, quick)
      val (psnr, off) = compare(ours, theirs)
      assertEquals((ours.width, ours.height), (theirs.width, theirs.height))
      assert(
        psnr >= 40 && off <= 0.5,
        f"PSNR $psnr%.1f dB, $off%.3f%% of unclipped pixels off by more than 8 levels\n${random.xml}"
      )
    finally Files.walk(dir).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)

  private def render(dir: Path, depth: Int, quick: Boolean): Bitmap =
    val err    = ByteArrayOutputStream()
    val status = Main.run(
      (if quick then List("-q") else Nil) ++ List(
        "-r",
        depth.toString,
        "-x",
        width.toString,
        "-y",
        height.toString,
        "-i",
        "scene.xml",
        "ours.ppm"
      ),
      ByteArrayInputStream(Array.emptyByteArray),
      PrintStream(ByteArrayOutputStream()),
      PrintStream(err),
      dir
    )
    assertEquals(status, 0, err.toString)
    Ppm.read(Files.readAllBytes(dir.resolve("ours.ppm"))).fold(fail(_), identity)

  private def povrayRender(dir: Path, depth: Int, quick: Boolean): Bitmap =
    val scene = SceneXml.load(dir.resolve("scene.xml"), dir).fold(fail(_), identity)
    val pov   = PovRay.write(scene, depth, quick = quick, pixels = Some((width, height)))
    // One thread: POV-Ray's shadow cache makes its picture depend on the order of its pixels.
    PovRayRun.render(povray, pov, dir, width, height, threads = 1).fold(fail(_), identity)

  /** The PSNR over every sample (dB) and the share of pixels (%), of those where neither picture
    * reaches 254 in a channel, with a channel more than 8 levels apart.
    */
  private def compare(a: Bitmap, b: Bitmap): (Double, Double) =
    val pixels = for x <- 0 until a.width; y <- 0 until a.height
    yield (0 until 3).map(c => (a.sample(x, y, c), b.sample(x, y, c)))
    val mse  = pixels.flatten.map((p, q) => (p - q).toDouble * (p - q)).sum / (3 * pixels.length)
    val psnr = if mse == 0 then Double.PositiveInfinity else 10 * Math.log10(255.0 * 255 / mse)
    val unclipped = pixels.filter(_.forall((p, q) => p < 254 && q < 254))
    val off       = unclipped.count(_.exists((p, q) => Math.abs(p - q) > 8))
    (psnr, 100.0 * off / pixels.length)
