// tracer: a Whitted ray tracer in Scala 3.
ThisBuild / scalaVersion := "3.8.3"
ThisBuild / version      := "2.0.0"
ThisBuild / organization := "tracer"

ThisBuild / scalacOptions ++= Seq(
  "-deprecation",
  "-feature",
  "-unchecked",
  "-Wunused:all",
  // The compiler's own analysis (docs/analysis.md): objects read before they are initialised,
  // values discarded where Unit is expected, and statements whose value is dropped.
  "-Wsafe-init",
  "-Wvalue-discard",
  "-Wnonunit-statement",
  // Until their owners fix them (docs/analysis.md): the only such findings left, in files being
  // rewritten on other branches, are reported as information. Remove these lines then.
  "-Wconf:src=src/main/scala/tracer/(io/OutputFile|render/Bvh|render/Renderer)\\.scala&id=E175:i",
  "-Wconf:src=src/main/scala/tracer/(io/OutputFile|render/Bvh|render/Renderer)\\.scala&id=E176:i",
  "-Werror"
)

lazy val root = project
  .in(file("."))
  .settings(
    name := "tracer",
    libraryDependencies ++= Seq(
      "com.github.scopt"       %% "scopt"            % "4.1.0",
      "org.scala-lang.modules" %% "scala-xml"        % "2.4.0"  % Test,
      "org.scalameta"          %% "munit"            % "1.2.1"  % Test,
      "org.scalameta"          %% "munit-scalacheck" % "1.2.0"  % Test,
      "org.scalacheck"         %% "scalacheck"       % "1.19.0" % Test
    ),
    Compile / mainClass := Some("tracer.cli.Main"),
    // munit registers each test from the suite's constructor, which -Wsafe-init cannot follow
    // (it flags test bodies as reading a half-built suite); the tests keep the other checks.
    Test / scalacOptions -= "-Wsafe-init",
    // tracer.BuildInfo: the build's version, for `tracer --version`.
    Compile / sourceGenerators += Def.task {
      val file = (Compile / sourceManaged).value / "tracer" / "BuildInfo.scala"
      IO.write(
        file,
        s"""package tracer
           |
           |/** Facts about this build, written by sbt (build.sbt). */
           |object BuildInfo:
           |  /** The version of the build, as `tracer --version` prints it. */
           |  val version: String = "${version.value}"
           |""".stripMargin
      )
      Seq(file)
    }.taskValue,
    assembly / mainClass       := Some("tracer.cli.Main"),
    assembly / assemblyJarName := "tracer.jar",
    // The jar's Scala lambdas as plain call sites, which the launcher's start-up cache can hold
    // (project/PlainLambdas.scala; docs/performance.md, round 6).
    assembly := {
      val jar = assembly.value
      PlainLambdas.rewrite(jar, streams.value.log)
      jar
    },
    // System tests start the real command; they need their own JVM and the working directory.
    Test / fork          := true,
    Test / baseDirectory := (ThisBuild / baseDirectory).value,
    // The Vector API's module, so that the four-box walks (render/Lanes.scala) are tested too;
    // they are used only when asked for (-Dtracer.lanes=on), so the other tests walk one box at a
    // time.
    Test / javaOptions ++= Seq("-Xmx2g", "-Xss4m", "--add-modules=jdk.incubator.vector"),
    Test / testOptions += Tests.Argument(TestFrameworks.MUnit, "-b"),
    // The system tests run the real launcher, which needs the assembled jar, and the release.
    Test / test               := (Test / test).dependsOn(assembly, dist).value,
    console / initialCommands := "import java.nio.file.Path, tracer.math.*, tracer.image.*, " +
      "tracer.io.*, tracer.geometry.*, tracer.scene.*, tracer.render.*",
    Compile / console / scalacOptions ~= (_.filterNot(Set("-Werror", "-Wunused:all")))
  )

// tracer.demo: the project's own scenes and tools, outside the renderer's jar — the animation,
// the benchmark scenes, the model and texture generators and the POV-Ray export. Its tests use
// the renderer's test kit.
lazy val demo = project
  .in(file("demo"))
  .dependsOn(root % "compile->compile;test->test")
  .settings(
    name           := "tracer-demo",
    publish / skip := true,
    // scripts/demo.sh (and so bench.sh) puts this jar beside tracer.jar on a classpath.
    Compile / packageBin / artifactPath := baseDirectory.value / "target" / "tracer-demo.jar",
    Test / scalacOptions -= "-Wsafe-init", // as in the root module
    Test / fork          := true,
    Test / baseDirectory := (ThisBuild / baseDirectory).value,
    Test / javaOptions ++= Seq("-Xmx2g", "-Xss4m"),
    Test / testOptions += Tests.Argument(TestFrameworks.MUnit, "-b"),
    // MitsubaSuite runs the real `tracer` command, which needs the assembled jar.
    Test / test               := (Test / test).dependsOn(root / assembly).value,
    Test / testOnly           := (Test / testOnly).dependsOn(root / assembly).evaluated,
    console / initialCommands := (root / console / initialCommands).value + ", tracer.demo.*",
    Compile / console / scalacOptions ~= (_.filterNot(Set("-Werror", "-Wunused:all")))
  )

lazy val bench = project
  .in(file("bench"))
  .dependsOn(root, demo)
  .enablePlugins(JmhPlugin)
  .settings(name := "tracer-bench", publish / skip := true)

// `./sbt lint`: the code analysis — semgrep with the project's rules (lint/semgrep.yml) over
// every Scala source, and docs/analysis.md checked against the suppressions in the tree. The
// script installs its pinned semgrep on first use; a finding fails the build, named by file and
// line. See docs/analysis.md.
lazy val lint = taskKey[Unit]("Runs the code analysis (scripts/lint.sh)")

lint := {
  val base   = (ThisBuild / baseDirectory).value
  val status = scala.sys.process.Process(Seq("bash", "scripts/lint.sh"), base).!
  if (status != 0) sys.error(s"lint: scripts/lint.sh found problems (status $status), see above")
}

// The one command that checks everything: formatting, the code analysis, compilation, Scaladoc,
// then every test (the renderer's, then the demo's).
addCommandAlias(
  "check",
  "; scalafmtCheckAll ; demo/scalafmtCheckAll ; scalafmtSbtCheck ; lint" +
    " ; Test/compile ; demo/Test/compile ; bench/compile ; doc ; demo/doc ; test ; demo/test"
)

// `./sbt movie` (the course's `ant movie`): builds the tracer, writes the frames of the project's
// animation (tracer.demo.Animation, in the demo module) and renders them with scripts/movie.sh
// into target/movie/.
lazy val movie = taskKey[Seq[File]]("Renders the project's movie into target/movie/")

movie := {
  val jar    = (root / assembly).value
  val base   = (ThisBuild / baseDirectory).value
  val dir    = base / "target" / "movie"
  val log    = streams.value.log
  val frames = (demo / Compile / fullClasspath).value.files
  (demo / Compile / runner).value.run("tracer.demo.Animation", frames, Seq(dir.toString), log).get
  val options = sys.env.getOrElse("TRACER_OPTS", "-x 640 -a 2 -g srgb")
  log.info(s"rendering the movie's frames with TRACER_OPTS='$options' (built $jar)")
  Seq("tracer.mp4", "tracer.mpg").map { name =>
    val script = Seq(
      "bash",
      "scripts/movie.sh",
      (base / "tracer").toString,
      (dir / "frames.txt").toString,
      (dir / name).toString
    )
    val status = scala.sys.process.Process(script, base, "TRACER_OPTS" -> options).!
    if (status != 0) sys.error(s"scripts/movie.sh failed with status $status")
    dir / name
  }
}

// `./sbt dist` (the course's `ant dist`): the release, in target/dist/: tracer-<version>.tar.gz,
// which unpacks to tracer-<version>/ (bin/tracer, lib/ with the jar and the launcher, scenes/,
// docs/, scene.xsd, README.md, LICENSE), and tracer_<version>_all.deb, the same files installed under
// /usr/share/tracer with `tracer` on PATH, `man tracer` and the docs in /usr/share/doc/tracer
// (docs/install.md). Both ship root's assembled jar, whatever other modules the build has.
// (`dist` is sbt-native-packager's key, here set for the whole build: it returns target/dist.)
dist := {
  val tarball = (launcher / Universal / packageZipTarball).value
  val deb     = (launcher / Debian / packageBin).value
  val dir     = (ThisBuild / baseDirectory).value / "target" / "dist"
  val v       = version.value
  val out     = Seq(tarball -> dir / s"tracer-$v.tar.gz", deb -> dir / s"tracer_${v}_all.deb")
  IO.delete(dir)
  out.foreach { case (from, to) => IO.copyFile(from, to) }
  streams.value.log.info(s"wrote ${out.map(_._2).mkString(" and ")}")
  dir
}

// The packaging of the release: the launcher (launcher/), the jar, and the files beside them.
lazy val launcher = project
  .in(file("launcher"))
  .enablePlugins(UniversalPlugin, DebianPlugin)
  .settings(
    name                          := "tracer-launcher",
    publish / skip                := true,
    packageName                   := "tracer",
    Universal / packageName       := s"tracer-${version.value}",
    Universal / topLevelDirectory := Some(s"tracer-${version.value}"),
    Universal / mappings          := {
      val base = (ThisBuild / baseDirectory).value
      val dir  = baseDirectory.value
      def tree(from: File, to: String, keep: String => Boolean = _ => true) =
        (from ** "*").get.filter(_.isFile).flatMap { f =>
          IO.relativize(from, f).filter(keep).map(path => f -> s"$to/$path")
        }
      Seq(
        (root / assembly).value -> "lib/tracer.jar",
        dir / "launcher.sh"     -> "lib/launcher.sh",
        dir / "tracer"          -> "bin/tracer",
        base / "README.md"      -> "README.md",
        base / "LICENSE"        -> "LICENSE",
        // The scene format's schema, at the top for editors (/usr/share/tracer/scene.xsd).
        base / "docs" / "scene.xsd" -> "scene.xsd"
      ) ++ tree(dir / "training", "lib/training") ++ tree(base / "docs", "docs") ++
        tree(base / "scenes", "scenes", path => !path.startsWith("bench/")) // generated
    },
    maintainer         := "The tracer authors <tracer@localhost>",
    packageSummary     := "a ray tracer: renders XML scenes to PNG, PPM, PFM or OpenEXR",
    packageDescription := "tracer renders scenes written in a small XML format " +
      "(spheres, planes, triangles, OBJ meshes, solids and CSG, textures, reflection, " +
      "refraction, point and area lights, glowing surfaces) by Whitted's rays or by path " +
      "tracing, to PNG, PPM, PFM or OpenEXR pictures, one frame or a batch of frames in one process.",
    Debian / packageArchitecture       := "all",
    Debian / debianPackageDependencies := Seq(
      "default-jre-headless (>= 2:1.17) | java17-runtime-headless | java-runtime-headless (>= 17)"
    ),
    Debian / linuxPackageMappings := {
      val usr = "/usr/share/tracer"
      val doc = "/usr/share/doc/tracer"
      // README.md and docs/ keep their places relative to each other, so that links still work;
      // the licence is Debian's copyright file.
      val files = (Universal / mappings).value.collect {
        case (f, path) if path == "README.md" || path.startsWith("docs/") => f -> s"$doc/$path"
        case (f, path) if path != "LICENSE"                               => f -> s"$usr/$path"
      }
      val executable = Set(s"$usr/bin/tracer")
      val base       = (ThisBuild / baseDirectory).value
      Seq(
        packageMapping(files.filter(m => executable(m._2)): _*).withPerms("0755"),
        packageMapping(files.filterNot(m => executable(m._2)): _*).withPerms("0644"),
        packageMapping(base / "LICENSE" -> s"$doc/copyright").withPerms("0644"),
        packageMapping(manPage.value -> "/usr/share/man/man1/tracer.1.gz").withPerms("0644")
      )
    },
    Debian / linuxPackageSymlinks += com.typesafe.sbt.packager.linux
      .LinuxSymlink("/usr/bin/tracer", "/usr/share/tracer/bin/tracer"),
    // The gallery's scenes name their schema as ../docs/scene.xsd, as in the archive.
    Debian / linuxPackageSymlinks += com.typesafe.sbt.packager.linux
      .LinuxSymlink("/usr/share/tracer/docs", "/usr/share/doc/tracer/docs"),
    // The one maintainer script: the start-up caches that root's runs made beside the jar go
    // with the package (docs/install.md). No users, groups or services to set up.
    Debian / maintainerScripts := Map(
      "prerm" -> Seq("#!/bin/sh", "set -e", "rm -rf /usr/share/tracer/lib/tracer-java*")
    ),
    // `man tracer`: made from the usage of `--help` by tracer.cli.ManPage, gzipped.
    manPage := {
      val roff = target.value / "tracer.1"
      val gz   = target.value / "tracer.1.gz"
      val cp   = (root / Compile / fullClasspath).value.files
      (root / Compile / runner).value
        .run("tracer.cli.ManPage", cp, Seq(roff.toString), streams.value.log)
        .get
      IO.gzip(roff, gz)
      gz
    }
  )

lazy val manPage = taskKey[File]("Writes `man tracer`, from the usage of --help, gzipped")
