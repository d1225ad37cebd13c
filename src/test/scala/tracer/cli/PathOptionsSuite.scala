package tracer.cli

import java.nio.file.{Files, Path}
import tracer.testkit.InProcess

/** Path mode's options through the real command, in-process: `-m`, `-s`, `--seed`, `--sampler`
  * and their rules (docs/cli.md).
  */
class PathOptionsSuite extends munit.FunSuite with InProcess:

  private val dir = scratch("tracer-path-options")

  private val scene =
    """<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
      |<background r="0.2" g="0.3" b="0.4"/>
      |<light><location x="-3" y="3" z="-5"/><colour r="1" g="1" b="1"/></light>
      |<sphere radius="1"><centre x="0" y="0" z="0"/><surface phong="0.5"><colour r="1" g="0.5" b="0"/></surface></sphere>
      |</scene>""".stripMargin

  private def run(cwd: Path, args: String*): Run = inProcess(cwd, scene, args)

  private val refused = List(
    List("-m", "path", "-a", "2")              -> "-a",
    List("-m", "path", "-a", "1")              -> "-a",
    List("-m", "path", "-q")                   -> "-q",
    List("-m", "pathway")                      -> "-m must be whitted or path",
    List("-m", "path", "-s", "0")              -> "-s must be an integer from 1 to 1048576",
    List("-m", "path", "-s", "1048577")        -> "-s must be an integer from 1 to 1048576",
    List("-s", "16")                           -> "-s needs -m path",
    List("-m", "whitted", "-s", "16")          -> "-s needs -m path",
    List("--seed", "3")                        -> "--seed needs -m path",
    List("-m", "path", "--seed", "-1")         -> "--seed must be an integer of at least 0",
    List("-m", "path", "--seed", "2147483648") -> "--seed",
    List("--sampler", "independent")           -> "--sampler needs -m path",
    List("-m", "path", "--sampler", "halton")  -> "--sampler must be sobol or independent"
  )

  for (args, message) <- refused do
    dir.test(s"${args.mkString(" ")} is a usage error: one line, status 2, nothing written"): d =>
      val r = run(d, (args :+ "out.png")*)
      assertEquals(r.status, 2, r.err)
      assertEquals(r.out, "")
      assert(r.err.startsWith("tracer: ") && r.err.linesIterator.size == 1, r.err)
      assert(r.err.contains(message), s"'${r.err.trim}' does not mention '$message'")
      assert(!Files.exists(d.resolve("out.png")))

  dir.test("-m path renders; the bytes are the same for every -p and differ for another --seed"):
    d =>
      val common = List("-m", "path", "-s", "8", "-x", "24", "-y", "18", "-r", "3")
      assertEquals(run(d, (common ++ List("-p", "1", "a.png"))*).status, 0)
      assertEquals(run(d, (common ++ List("-p", "3", "b.png"))*).status, 0)
      assertEquals(run(d, (common ++ List("--seed", "9", "c.png"))*).status, 0)
      assertEquals(run(d, (common ++ List("--sampler", "independent", "e.png"))*).status, 0)
      def bytes(name: String) = Files.readAllBytes(d.resolve(name)).toList
      assertEquals(bytes("a.png"), bytes("b.png"))
      assertNotEquals(bytes("a.png"), bytes("c.png"))
      assertNotEquals(bytes("a.png"), bytes("e.png"))

  dir.test("-m whitted is the default: the same bytes as no -m"): d =>
    assertEquals(run(d, "-x", "16", "-y", "12", "a.ppm").status, 0)
    assertEquals(run(d, "-m", "whitted", "-x", "16", "-y", "12", "b.ppm").status, 0)
    assertEquals(
      Files.readAllBytes(d.resolve("a.ppm")).toList,
      Files.readAllBytes(d.resolve("b.ppm")).toList
    )
