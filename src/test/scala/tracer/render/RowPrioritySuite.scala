package tracer.render

import java.util.concurrent.ConcurrentLinkedQueue
import scala.jdk.CollectionConverters.*
import tracer.image.Colour
import tracer.geometry.{Plane, Sphere}
import tracer.math.Vec3
import tracer.scene.{Light, Scene}
import tracer.testkit.Scenes.{camera, matte}

/** A render's row tasks run at the lowest Java priority, which the launcher's JVM options turn
  * into a nice value above the JIT's (docs/performance.md, round 30), while the caller's thread
  * and the picture stay as they were.
  */
class RowPrioritySuite extends munit.FunSuite:

  private val scene = Scene(
    camera,
    background = Colour(0.1, 0.1, 0.3),
    lights = List(Light(Vec3(-3, 4, -4))),
    objects = List(
      matte(Plane.at(Vec3.UnitY, -1), Colour.grey(0.7), reflection = 0.4),
      matte(Sphere(Vec3(0, 0, 0.5), 1), Colour(0.9, 0.3, 0.2))
    )
  )
  private val config = CameraConfig(1, 1, 0.75, 40, 30)

  /** The priority of the thread of each row report of a render on `threads` threads. */
  private def rowPriorities(threads: Int): List[Int] =
    val seen = ConcurrentLinkedQueue[Int]()
    val _    = Renderer.render(
      scene,
      config,
      threads,
      () => seen.add(Thread.currentThread.getPriority): Unit
    )
    seen.asScala.toList

  test("every row of a render on several threads runs at the lowest priority"):
    val priorities = rowPriorities(3)
    assertEquals(priorities.size, config.rows)
    assertEquals(priorities.distinct, List(Thread.MIN_PRIORITY))

  test("the caller's thread keeps its priority, and the picture is the one-thread render's"):
    val before = Thread.currentThread.getPriority
    val shared = Renderer.render(scene, config, 2)
    assertEquals(Thread.currentThread.getPriority, before)
    assertEquals(shared, Renderer.renderSequential(scene, config))
