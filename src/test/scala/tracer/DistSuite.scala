package tracer

import java.nio.file.{Files, Path}
import java.util.zip.GZIPInputStream
import scala.jdk.CollectionConverters.*
import tracer.testkit.Processes
import tracer.testkit.Processes.{Exit, run}

/** System tests of the release that `./sbt dist` writes (docs/install.md): the archive unpacked
  * and run as a user would, and the Debian package's contents; as root, the package installed,
  * run and removed.
  *
  * They need target/dist; `./sbt test` builds it first (build.sbt), and without it they stop
  * with a clear message.
  */
class DistSuite extends munit.FunSuite:

  // The cache test trains the launcher's start-up cache three times (a new jar and new training
  // scenes each make a new one), each a render of every training scene: on a busy two-core
  // machine that outlasts munit's 30 seconds.
  override val munitTimeout = scala.concurrent.duration.Duration(5, "min")

  private val home    = Path.of("").toAbsolutePath
  private val version = BuildInfo.version
  private val dist    = home.resolve("target/dist")
  private val tarball = dist.resolve(s"tracer-$version.tar.gz")
  private val deb     = dist.resolve(s"tracer_${version}_all.deb")
  private val scene   = home.resolve("scenes/showcase.xml")

  override def beforeAll(): Unit =
    assume(Files.exists(tarball), s"$tarball is missing: run ./sbt dist (./sbt test does it first)")

  private val work = FunFixture[Path](
    _ =>
      val d = Files.createTempDirectory("tracer dist")
      // Open to everybody: the archive's user may be another one (below).
      assertEquals(run(Seq("chmod", "777", d.toString), home).status, 0)
      d
    ,
    d => Processes.deleteTree(d)
  )

  /** The picture `./tracer` makes of the showcase scene at `width` pixels, as bytes. */
  private def reference(d: Path, width: Int): Array[Byte] =
    val out = d.resolve(s"reference-$width.png")
    val e = run(Seq(home.resolve("tracer").toString, "-x", s"$width", "-i", s"$scene", s"$out"), d)
    assertEquals(e, Exit(0, "", ""))
    Files.readAllBytes(out)

  private def unpack(d: Path): Path =
    val install = Files.createDirectories(d.resolve("install"))
    assertEquals(run(Seq("tar", "-xzf", tarball.toString), install).status, 0)
    install.resolve(s"tracer-$version")

  /** The status that dpkg records for the package tracer, if it records one. */
  private def status(d: Path): Option[String] =
    val e = run(Seq("dpkg-query", "-W", "-f=${Status}", "tracer"), d)
    Option.when(e.status == 0 && e.out.nonEmpty)(e.out)

  /** Where the package installs the page `page` of the repository (README.md, docs/…). */
  private def installedDoc(page: String): String = s"/usr/share/doc/tracer/$page"

  /** The cache files in `dir` and below: the launcher's start-up caches, by name. */
  private def caches(dir: Path): List[String] =
    if !Files.exists(dir) then Nil
    else
      Files
        .walk(dir)
        .iterator
        .asScala
        .map(_.getFileName.toString)
        .filter(n => n.startsWith("tracer-java") && (n.endsWith(".aot") || n.endsWith(".jsa")))
        .toList
        .sorted

  work.test(
    "the archive unpacks to tracer-VERSION/: bin/tracer, the jar, docs, scenes, the schema, " +
      "README, LICENSE"
  ): d =>
    val top = unpack(d)
    assertEquals(Files.list(d.resolve("install")).iterator.asScala.toList, List(top))
    for path <- List(
        "bin/tracer",
        "lib/tracer.jar",
        "lib/launcher.sh",
        "README.md",
        "LICENSE",
        "docs/cli.md",
        "docs/install.md",
        "scenes/showcase.xml",
        "scenes/models/knot.obj",
        "scene.xsd",
        "docs/scene.xsd"
      )
    do assert(Files.isRegularFile(top.resolve(path)), path)
    assertEquals(
      Files.readString(top.resolve("scene.xsd")),
      Files.readString(home.resolve("docs/scene.xsd"))
    )
    assert(Files.isExecutable(top.resolve("bin/tracer")))
    // One launcher logic: the very file that ./tracer sources.
    assertEquals(
      Files.readString(top.resolve("lib/launcher.sh")),
      Files.readString(home.resolve("launcher/launcher.sh"))
    )
    assert(!Files.exists(top.resolve("scenes/bench")), "no benchmark scenes")

  work.test(
    "bin/tracer, read-only and from another directory under an empty HOME, renders the bytes of " +
      "./tracer, keeps its cache in the user's cache directory, survives a broken or stale cache, " +
      "and makes a new one for new training scenes"
  ): d =>
    val top       = unpack(d)
    val expected  = reference(d, 64)
    val user      = Files.createDirectories(d.resolve("empty home"))
    val elsewhere = Files.createDirectories(d.resolve("elsewhere"))
    assertEquals(run(Seq("chmod", "777", user.toString, elsewhere.toString), d).status, 0)
    // A read-only install: as root, that takes another user (root writes anywhere); else chmod.
    val asUser =
      if Processes.isRoot then
        assume(Files.isExecutable(Path.of("/usr/bin/setpriv")), "needs setpriv to run as nobody")
        Seq("/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups")
      else
        assertEquals(run(Seq("chmod", "-R", "a-w", top.toString), d).status, 0)
        Nil
    val env                  = Map("HOME" -> Some(user.toString), "XDG_CACHE_HOME" -> None)
    def render(name: String) =
      val out = elsewhere.resolve(name)
      val e   = run(
        // The install's own copy of the scene: another user may not read the source tree.
        asUser ++ Seq(
          s"$top/bin/tracer",
          "-x",
          "64",
          "-i",
          s"$top/scenes/showcase.xml",
          out.toString
        ),
        elsewhere,
        env
      )
      assertEquals(e, Exit(0, "", ""), name)
      assert(Files.readAllBytes(out).sameElements(expected), s"$name differs from ./tracer's")

    render("first.png") // makes the cache
    val made = caches(user)
    assertEquals(made.length, 1, s"one cache in the user's cache directory: $made")
    assertEquals(caches(top), Nil, "nothing written into the install")
    render("cached.png")

    val file = Files
      .walk(user)
      .iterator
      .asScala
      .find(_.getFileName.toString == made.head)
      .getOrElse(fail(s"${made.head} not found"))
    Files.writeString(file, "not a cache") // broken: the JVM must go on without it, silently
    render("broken.png")

    // A new jar (here: the same bytes, another time) makes a new cache and drops the old one.
    val jar = top.resolve("lib/tracer.jar")
    assertEquals(run(Seq("chmod", "u+w", top.resolve("lib").toString), d).status, 0)
    Files.setLastModifiedTime(jar, java.nio.file.attribute.FileTime.fromMillis(86_400_000L))
    render("new-jar.png")
    val remade = caches(user)
    assertEquals(remade.length, 1, s"$remade")
    assertNotEquals(remade, made)

    // So does a changed training scene (here: another time on one of them).
    val scene = top.resolve("lib/training/triangles-1000.xml")
    assert(Files.exists(scene), s"$scene is missing")
    Files.setLastModifiedTime(scene, java.nio.file.attribute.FileTime.fromMillis(86_400_000L))
    render("new-training.png")
    val retrained = caches(user)
    assertEquals(retrained.length, 1, s"$retrained")
    assertNotEquals(retrained, remade)

  test("the .deb depends on a Java runtime >= 17 and installs tracer, its man page and its docs"):
    assume(Files.exists(deb), s"$deb is missing: run ./sbt dist")
    assume(Files.isExecutable(Path.of("/usr/bin/dpkg-deb")), "needs dpkg-deb")
    val field = (name: String) => run(Seq("dpkg-deb", "-f", deb.toString, name), home).out.trim
    assertEquals(field("Package"), "tracer")
    assertEquals(field("Version"), version)
    assertEquals(field("Architecture"), "all")
    assert(field("Depends").contains("java17-runtime-headless"), field("Depends"))
    assert(field("Depends").startsWith("default-jre-headless (>= 2:1.17) | "), field("Depends"))
    val listing           = run(Seq("dpkg-deb", "-c", deb.toString), home).out.linesIterator.toList
    def has(path: String) =
      listing.exists(l => l.endsWith(s" .$path") || l.contains(s" .$path -> "))
    for path <- List(
        "/usr/bin/tracer",
        "/usr/share/tracer/bin/tracer",
        "/usr/share/tracer/lib/tracer.jar",
        "/usr/share/tracer/lib/launcher.sh",
        "/usr/share/man/man1/tracer.1.gz",
        "/usr/share/doc/tracer/copyright",
        installedDoc("README.md"),
        installedDoc("docs/cli.md"),
        "/usr/share/tracer/scenes/showcase.xml",
        "/usr/share/tracer/scene.xsd",
        installedDoc("docs/scene.xsd")
      )
    do assert(has(path), s"$path not in the package:\n${listing.mkString("\n")}")
    assert(
      listing.exists(_.contains(" ./usr/share/tracer/docs -> /usr/share/doc/tracer/docs")),
      "the gallery's ../docs/scene.xsd leads to the schema"
    )
    assert(
      listing.exists(_.contains(" ./usr/bin/tracer -> /usr/share/tracer/bin/tracer")),
      "tracer on PATH is a link to the launcher"
    )
    assert(
      listing.exists(l => l.startsWith("-rwxr-xr-x") && l.endsWith("/usr/share/tracer/bin/tracer"))
    )

  work.test(
    "as root: apt-get installs the .deb, `tracer` renders from PATH, dpkg -r removes it all"
  ): d =>
    assume(Files.exists(deb), s"$deb is missing: run ./sbt dist")
    assume(Processes.isRoot, "installing a package needs root")
    assume(Files.isExecutable(Path.of("/usr/bin/apt-get")), "needs apt-get")
    assume(status(d).isEmpty, s"tracer is known to dpkg already: ${status(d)}")
    val expected = reference(d, 32)
    val apt      = Map("DEBIAN_FRONTEND" -> Some("noninteractive"))
    try
      val installed = run(Seq("apt-get", "install", "-y", "-q", deb.toString), d, apt)
      assertEquals(installed.status, 0, installed.out + installed.err)
      val e = run(Seq("tracer", "-x", "32", "-i", s"$scene", "out.png"), d)
      assertEquals(e, Exit(0, "", ""))
      assert(Files.readAllBytes(d.resolve("out.png")).sameElements(expected))
      val man  = Path.of("/usr/share/man/man1/tracer.1.gz")
      val page = String(GZIPInputStream(Files.newInputStream(man)).readAllBytes())
      assert(page.startsWith(s".TH TRACER 1"), page.take(80))
      assert(Files.isRegularFile(Path.of(installedDoc("docs/install.md"))))
      assert(Files.isRegularFile(Path.of("/usr/share/tracer/scene.xsd")))
      assert(Files.isRegularFile(Path.of("/usr/share/tracer/scenes/../docs/scene.xsd")))
    finally
      val removed = run(Seq("dpkg", "-r", "tracer"), d)
      assertEquals(removed.status, 0, removed.out + removed.err)
      assert(!removed.err.contains("not empty"), removed.err)
      // Removed whole: no configuration files or scripts kept (no "rc" state left to purge).
      assertEquals(status(d), None)
    for path <- List(
        "/usr/bin/tracer",
        "/usr/share/tracer",
        "/usr/share/man/man1/tracer.1.gz",
        "/usr/share/doc/tracer"
      )
    do assert(!Files.exists(Path.of(path)), s"$path is left behind")
