package tracer.render

import java.io.{PrintWriter, StringWriter}
import java.nio.file.Path
import java.util.spi.ToolProvider

/** The kernels' bytecode, read back with `javap`, calls nothing that boxes a number or asks an
  * array's length by reflection: C2 removes both once it has compiled a method, but the
  * interpreter and C1 pay for them on every call, and these methods run per ray, or per item of
  * a world's build, long before C2 has compiled them (docs/performance.md, round 37: 65 MB of
  * boxed doubles in a 1280×720 run, 3% of a 3840×2160 run in `Array.getLength`).
  */
class KernelBytecodeSuite extends munit.FunSuite:

  /** What a kernel must not call, with why. */
  private val forbidden = List(
    raw"scala/Predef\$$\.(double2Double|int2Integer|long2Long|float2Float)".r ->
      "a boxing conversion (x.isNaN on a Double: write java.lang.Double.isNaN(x))",
    raw"scala/runtime/BoxesRunTime\.box".r                        -> "a boxed number",
    raw"scala/collection/ArrayOps\$$".r                           -> "ArrayOps' generic operations",
    raw"IArray\$$package\$$IArray\$$\.\w+:\(Ljava/lang/Object;".r ->
      "an IArray's generic operation (its length by reflection)",
    raw"scala/runtime/ScalaRunTime\$$\.array_".r            -> "a generic array access",
    raw"java/lang/reflect/Array".r                          -> "an array's length by reflection",
    raw"scala/runtime/RichInt\$$\.(until|to)\$$extension".r ->
      "a Range (a closure called with each number boxed)"
  )

  /** The kernels, by class (as javap names it) and method. */
  private val kernels: List[(String, List[String])] = List(
    "tracer.render.World" -> List(
      "nearestAlong",
      "nearestBounded",
      "nearestFromEye",
      "occludedToward",
      "unboundedDistance",
      "shadowUnboundedDistance"
    ),
    "tracer.render.Bvh" -> List(
      "nearest",
      "nearestOfOne",
      "occluded",
      "anyBlocks",
      "itemBlocks",
      "nearestAmong",
      "ownBlocks",
      "bufferItems"
    ),
    "tracer.render.Bvh$"       -> List("faceItems"),
    "tracer.render.MeshTree"   -> List("nearest", "occludedBelow", "faceDistance", "faceBlocks"),
    "tracer.render.MeshTree$"  -> List("layFace"),
    "tracer.render.Shading"    -> List("trace", "traceFrom", "shade", "light", "lit", "mirror"),
    "tracer.render.Shadows"    -> List("pointToward", "buffered"),
    "tracer.render.Hits$"      -> List("record"),
    "tracer.render.Projection" -> List("directions"),
    "tracer.render.Renderer$WhittedFrame" -> List("rows", "aimed"),
    "tracer.render.LightBuffer"           -> List("cell", "face"),
    "tracer.render.LightBuffer$"          -> List(
      "build",
      "sorted",
      "classify",
      "partOn",
      "count",
      "place",
      "widen",
      "distance"
    ),
    "tracer.render.Outlines$"  -> List("relativeCorners", "outline", "column"),
    "tracer.render.EyeBuffer"  -> List("cell", "behind"),
    "tracer.render.BvhBuilder" -> List("binAll", "binOne", "partition", "cheapest", "enclose"),
    "tracer.io.MeshTransform"  -> List("placeInto"),
    "tracer.geometry.Mesh"     -> List("smoothFace", "texturedFace")
  )

  /** The methods of class `name` as javap prints them: each method's name and its lines. */
  private def methods(name: String): Map[String, Vector[String]] =
    val classes = Path.of(classOf[World].getProtectionDomain.getCodeSource.getLocation.toURI)
    val javap   = ToolProvider
      .findFirst("javap")
      .orElseThrow(() => new AssertionError("no javap in this JDK"))
    val text = StringWriter()
    val out  = PrintWriter(text)
    val code = javap.run(out, out, "-c", "-p", "-cp", classes.toString, name)
    out.flush()
    assertEquals(code, 0, text.toString)
    val header = raw"^  [^ ].*? ([\w$$]+)\(.*\);$$".r
    text.toString.linesIterator
      .foldLeft(Vector.empty[(String, Vector[String])]) { (found, line) =>
        line match
          case header(method)      => found :+ (method -> Vector.empty)
          case _ if found.nonEmpty =>
            found.init :+ (found.last._1 -> (found.last._2 :+ line))
          case _ => found
      }
      .groupMapReduce(_._1)(_._2)(_ ++ _)

  for (cls, names) <- kernels do
    test(s"$cls: ${names.mkString(", ")} neither box nor reflect"):
      val all = methods(cls)
      for method <- names do
        // A private member of an object is compiled as `owner$$$name`.
        val body = all
          .collectFirst {
            case (name, lines) if name == method || name.endsWith("$$" + method) => lines
          }
          .getOrElse(fail(s"$cls has no method $method (renamed?)"))
        for
          line         <- body
          (rule, what) <- forbidden
          if rule.findFirstIn(line).isDefined
        do fail(s"$cls.$method calls $what: ${line.trim}")
