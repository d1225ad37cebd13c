package tracer.demo

import java.nio.file.{Files, Path}
import java.util.concurrent.TimeUnit
import tracer.image.{Bitmap, Ppm}

/** POV-Ray run on a twin, for the suites that compare its pictures with ours. */
object PovRayRun:

  /** POV-Ray's picture of the twin `pov` (written to `dir/scene.pov`), `width` × `height`, on
    * `threads` threads, without antialiasing, with `File_Gamma=gamma`, read back from a PPM; or
    * why it could not be made: POV-Ray's exit status or its time running out, with its log.
    */
  def render(
      povray: Path,
      pov: String,
      dir: Path,
      width: Int,
      height: Int,
      threads: Int,
      gamma: String = "1.0",
      seconds: Int = 300
  ): Either[String, Bitmap] =
    Files.writeString(dir.resolve("scene.pov"), pov)
    val log     = dir.resolve("povray.log")
    val process = ProcessBuilder(
      povray.toString,
      s"+WT$threads",
      "-A",
      s"+W$width",
      s"+H$height",
      "+Iscene.pov",
      "+Otheirs.ppm",
      "+FP",
      s"File_Gamma=$gamma",
      "-D",
      "-V",
      "-GA"
    ).directory(dir.toFile)
      .redirectErrorStream(true)
      .redirectOutput(log.toFile)
      .start()
    if !process.waitFor(seconds.toLong, TimeUnit.SECONDS) then
      process.destroyForcibly(): Unit
      Left(s"POV-Ray ran out of time:\n${Files.readString(log)}")
    else if process.exitValue != 0 then
      Left(s"POV-Ray exited with ${process.exitValue}:\n${Files.readString(log)}")
    else Ppm.read(Files.readAllBytes(dir.resolve("theirs.ppm")))
