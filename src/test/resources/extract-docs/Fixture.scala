package fixture.shapes

/** A shape that can be drawn. More text that is not the summary.
  *
  * @param name what it is called
  */
sealed trait Drawable(name: String)

/** A circle of some radius, wrapped
  * over two lines. Then more.
  */
final case class Circle(radius: Double) extends Drawable("circle"):

  /** The area, πr². */
  def area: Double = Math.PI * radius * radius

  /** Never shown: private. */
  private def secret: Int = 42

  def undocumented: Int = 1

/** Helpers for circles */
object Circle:
  /** The unit circle. */
  val Unit: Circle = Circle(1)

  /** Scales a circle. */
  @deprecated("use copy", "1.0")
  def scaled(c: Circle, k: Double): Circle =
    c.copy(radius = c.radius * k)

  /** A kind of colour. */
  enum Colour:
    /** Red, like e.g. a rose. */
    case Red
