package tracer.render

/** Whether the walks test a wide node's four child boxes at once with the Vector API
  * ([[Lanes]]): only when asked for (the system property `tracer.lanes` is `on`, as the launcher
  * sets it for `TRACER_LANES=on`), when the JVM was started with the incubating module
  * `jdk.incubator.vector` (`--add-modules jdk.incubator.vector`) and when the processor holds
  * four doubles in a vector register. Otherwise, and on every JVM without the module, the walks
  * test one box at a time ([[WideWalk.push]]); the answers are the same either way.
  *
  * This object never touches the module's classes itself, so it loads on every JVM.
  */
object LaneSupport:
  /** The name of the Vector API's module. */
  val Module = "jdk.incubator.vector"

  /** True when this JVM has the Vector API's module (whether or not it is asked for). */
  val available: Boolean =
    ModuleLayer.boot().findModule(Module).isPresent && Lanes.wideEnough

  /** True when the walks use [[Lanes]]. */
  val enabled: Boolean = available && sys.props.get("tracer.lanes").contains("on")
