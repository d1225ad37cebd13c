package tracer.cli

import java.io.PrintStream
import java.nio.file.{Files, Path}
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.{Executors, ScheduledExecutorService, TimeUnit}

/** A progress line on a terminal: `tracer: rendering 45% (216 of 480 rows)`, shown only once a
  * render has taken more than a moment, redrawn in place, and erased when the render ends.
  */
final class Progress private (out: PrintStream, totalRows: Int, timer: ScheduledExecutorService):
  private val done = AtomicInteger(0)

  /** Counts one finished row; called from the render threads. */
  def rowDone(): Unit = done.incrementAndGet(): Unit

  private def draw(): Unit =
    val rows = done.get()
    out.print(s"\rtracer: rendering ${100L * rows / totalRows}% ($rows of $totalRows rows)")
    out.flush()

  /** Stops reporting and erases the line. */
  def finish(): Unit =
    timer.shutdownNow()
    timer.awaitTermination(1, TimeUnit.SECONDS)
    out.print("\r\u001b[K")
    out.flush()

/** Starts progress reports where a person can see them. */
object Progress:

  /** How long a render runs before progress is shown. */
  val DelayMillis: Long = 1000

  /** How often the line is redrawn. */
  val PeriodMillis: Long = 250

  /** A progress reporter drawing on `out`, or `None` unless `out` is this process's standard
    * error and that is a terminal.
    */
  def start(out: PrintStream, totalRows: Int): Option[Progress] =
    Option.when(out eq System.err)(()).filter(_ => stderrIsTerminal).map { _ =>
      val timer = Executors.newSingleThreadScheduledExecutor { task =>
        val thread = Thread(task, "tracer-progress")
        thread.setDaemon(true)
        thread
      }
      val progress = Progress(out, totalRows, timer)
      timer.scheduleAtFixedRate(
        () => progress.draw(),
        DelayMillis,
        PeriodMillis,
        TimeUnit.MILLISECONDS
      )
      progress
    }

  /** True when file descriptor 2 is a terminal (Linux: it links to a tty device), or, when the
    * launcher passes standard error on through a filter of its own (`TRACER_LANES=on`), when the
    * system property `tracer.terminal` says the real one is.
    */
  private def stderrIsTerminal: Boolean =
    sys.props.get("tracer.terminal") match
      case Some(said) => said == "true"
      case None       => Progress.isTerminal(2)

  /** True when this process's file descriptor `fd` links to a tty device (Linux's /proc; false
    * wherever that cannot be told).
    */
  private[cli] def isTerminal(fd: Int): Boolean =
    try
      val target = Files.readSymbolicLink(Path.of(s"/proc/self/fd/$fd")).toString
      target.startsWith("/dev/pts/") || target.startsWith("/dev/tty")
    catch case _: Exception => false
