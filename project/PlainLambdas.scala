import java.io.{ByteArrayOutputStream, File}
import java.nio.file.{Files, StandardCopyOption}
import java.util.zip.{ZipEntry, ZipFile, ZipOutputStream}
import org.objectweb.asm.{
  ClassReader,
  ClassVisitor,
  ClassWriter,
  Handle,
  MethodVisitor,
  Opcodes,
  Type
}
import sbt.util.Logger
import scala.collection.JavaConverters._

/** The assembled jar's Scala lambdas made plain `LambdaMetafactory.metafactory` call sites, so
  * that the launcher's start-up cache holds their classes (docs/performance.md, round 6).
  *
  * Scala compiles every function literal to an `invokedynamic` of
  * `LambdaMetafactory.altMetafactory` with `FLAG_SERIALIZABLE` (and often `FLAG_BRIDGES`, for
  * bridge methods of the instantiated types, which no interface of a Scala function declares).
  * Neither the JDK 25 AOT cache nor an AppCDS archive keeps the class of such a lambda: the JVM
  * spins it afresh in every run, about a millisecond each in a cold JVM, and a small render spins
  * 400 of them (scala-library's, scopt's and ours) — 60% of its run. Rewritten to `metafactory`
  * with the same three arguments, the call site makes the same function, not serializable (the
  * tracer serialises no function), and the cache keeps it.
  *
  * Only call sites whose functional interface is a Scala function (`scala.FunctionN`,
  * `scala.runtime.function.JProcedureN`, the specialised `scala.runtime.java8.JFunctionN$mc…$sp`)
  * or one of the JDK's that the tracer's code passes function literals to (`java.util.function`'s,
  * `Callable`, `Runnable`: a thread's scratch buffer, a band of the PNG encoder; round 23), and
  * that ask for no marker interfaces, are rewritten; every other call site stays as it is. The
  * bridges such a call site asks for are its instantiated method type, which none of these
  * interfaces declares, so no caller can reach them.
  */
object PlainLambdas {

  private val FlagSerializable = 1
  private val FlagBridges      = 4

  private val Metafactory = new Handle(
    Opcodes.H_INVOKESTATIC,
    "java/lang/invoke/LambdaMetafactory",
    "metafactory",
    "(Ljava/lang/invoke/MethodHandles$Lookup;Ljava/lang/String;Ljava/lang/invoke/MethodType;" +
      "Ljava/lang/invoke/MethodType;Ljava/lang/invoke/MethodHandle;Ljava/lang/invoke/MethodType;)" +
      "Ljava/lang/invoke/CallSite;",
    false
  )

  private val ScalaFunction =
    ("scala/Function[0-9]+|scala/runtime/function/JProcedure[0-9]+|" +
      "scala/runtime/java8/JFunction[0-9]+\\$mc[A-Za-z]+\\$sp|" +
      "java/util/function/[A-Za-z]+|java/util/concurrent/Callable|java/lang/Runnable").r

  /** Rewrites `jar` in place when it holds such call sites; a jar without any (one already
    * rewritten) is left alone, its time and all, so the launcher's cache stays valid.
    */
  def rewrite(jar: File, log: Logger): Unit = {
    val zip                = new ZipFile(jar)
    val (entries, changed) =
      try {
        val all = zip.entries().asScala.toList.map { entry =>
          val bytes = readAll(zip, entry)
          val plain =
            if (entry.getName.endsWith(".class") && !entry.getName.startsWith("META-INF/"))
              plainLambdas(bytes)
            else None
          (entry, plain.map(_._1).getOrElse(bytes), plain.fold(0)(_._2))
        }
        (all, all.map(_._3).sum)
      } finally zip.close()
    if (changed > 0) {
      val partial = new File(jar.getPath + ".partial")
      val out     = new ZipOutputStream(Files.newOutputStream(partial.toPath))
      try
        entries.foreach { case (entry, bytes, _) =>
          val copy = new ZipEntry(entry.getName)
          copy.setTime(entry.getTime)
          out.putNextEntry(copy)
          out.write(bytes)
          out.closeEntry()
        }
      finally out.close()
      Files.move(partial.toPath, jar.toPath, StandardCopyOption.REPLACE_EXISTING)
      log.info(s"PlainLambdas: $changed lambda call sites of ${jar.getName} made plain")
    }
  }

  private def readAll(zip: ZipFile, entry: ZipEntry): Array[Byte] = {
    val in = zip.getInputStream(entry)
    try {
      val out    = new ByteArrayOutputStream(Math.max(entry.getSize, 64L).toInt)
      val buffer = new Array[Byte](8192)
      var n      = in.read(buffer)
      while (n >= 0) { out.write(buffer, 0, n); n = in.read(buffer) }
      out.toByteArray
    } finally in.close()
  }

  /** The class file with its Scala lambdas made plain and how many there were, or `None` when it
    * has none (or is one this ASM cannot read).
    */
  private def plainLambdas(bytes: Array[Byte]): Option[(Array[Byte], Int)] =
    try {
      val reader  = new ClassReader(bytes)
      val writer  = new ClassWriter(reader, 0)
      var changed = 0
      reader.accept(
        new ClassVisitor(Opcodes.ASM9, writer) {
          override def visitMethod(
              access: Int,
              name: String,
              desc: String,
              signature: String,
              exceptions: Array[String]
          ): MethodVisitor =
            new MethodVisitor(
              Opcodes.ASM9,
              super.visitMethod(access, name, desc, signature, exceptions)
            ) {
              override def visitInvokeDynamicInsn(
                  name: String,
                  desc: String,
                  bootstrap: Handle,
                  args: AnyRef*
              ): Unit =
                if (plain(desc, bootstrap, args)) {
                  changed += 1
                  super.visitInvokeDynamicInsn(name, desc, Metafactory, args(0), args(1), args(2))
                } else super.visitInvokeDynamicInsn(name, desc, bootstrap, args: _*)
            }
        },
        0
      )
      if (changed == 0) None else Some((writer.toByteArray, changed))
    } catch { case _: IllegalArgumentException => None } // a class file newer than this ASM

  /** True for an `altMetafactory` call site of a Scala function without marker interfaces. */
  private def plain(desc: String, bootstrap: Handle, args: Seq[AnyRef]): Boolean =
    bootstrap.getOwner == "java/lang/invoke/LambdaMetafactory" &&
      bootstrap.getName == "altMetafactory" && args.length >= 4 && (args(3) match {
        case flags: Integer =>
          (flags & ~(FlagSerializable | FlagBridges)) == 0 &&
          ScalaFunction.pattern.matcher(Type.getReturnType(desc).getInternalName).matches
        case _ => false
      })
}
