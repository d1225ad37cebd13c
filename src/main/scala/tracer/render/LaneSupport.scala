package tracer.render

/** Whether the walks test a wide node's four child boxes at once with the Vector API
  * ([[Lanes]]): only when asked for (the system property `tracer.lanes` is `on`, as the launcher
  * sets it for `TRACER_LANES=on`), when the JVM was started with the incubating module
  * `jdk.incubator.vector` (`--add-modules jdk.incubator.vector`) and when the processor holds
  * four doubles in a vector register. Otherwise, and on every JVM without the module, the walks
  * test one box at a time ([[WideWalk.push]]); the answers are the same either way.
  *
  * This object asks for the module's classes (through [[Lanes]]) only once it has found the
  * module, so it loads on every JVM.
  */
object LaneSupport:
  /** The name of the Vector API's module. */
  val Module = "jdk.incubator.vector"

  /** True when this JVM has the Vector API's module and the processor four doubles a vector
    * (whether or not they are asked for).
    */
  val available: Boolean =
    ModuleLayer.boot().findModule(Module).isPresent && Lanes.wideEnough

  /** True when the walks use [[Lanes]]. */
  val enabled: Boolean = available && sys.props.get("tracer.lanes").contains("on")

  /** The fewest wide nodes of a tree walked with [[Lanes]]. */
  val MinNodes = 16

  /** True when a tree of `nodes` wide nodes is worth walking with [[Lanes]]: a walk of a few
    * nodes gains little from testing four boxes at once, and until C2 compiles it the vector walk
    * is far slower than the scalar one (4K few-object scene, docs/performance.md, round 15).
    */
  def worth(nodes: Int): Boolean = nodes >= MinNodes

  /** Whether a tree of `nodes` wide nodes walks with [[Lanes]]: when [[enabled]] and [[worth]]. */
  def choose(nodes: Int): Boolean = enabled && worth(nodes)
