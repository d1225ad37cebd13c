package tracer.render

/** The items a [[LightBuffer]] or an [[EyeBuffer]] bins, numbered from 0: each primitive of a [[Bvh]] that is not a
  * mesh, and each face of each of its meshes, with its box.
  *
  * @param boxes  item i's box at 6i (low x, y, z, then high), widened by 10⁻⁷ of its size
  * @param owner  item i's primitive, in the tree's leaf order
  * @param face   item i's face in its mesh's leaf order, or −1 for a primitive that is not a mesh
  * @param corners item i's corners at 9i (x, y, z of each) when it is a triangle (a mesh's face or
  *   a [[tracer.geometry.Triangle]]), else NaN there: a buffer bins a triangle by its own outline
  *   rather than its box's; empty for a buffer that bins every item by its box (a render of
  *   fewer than [[LightBuffer.OutlineRaysPerItem]] rays an item)
  */
final class BufferItems(
    private[render] val boxes: Array[Double],
    private[render] val owner: Array[Int],
    private[render] val face: Array[Int],
    private[render] val corners: Array[Double]
):
  /** The number of items. */
  def size: Int = owner.length

/** Building [[BufferItems]]. */
object BufferItems:
  /** No items. */
  val empty: BufferItems =
    BufferItems(
      Array.emptyDoubleArray,
      Array.emptyIntArray,
      Array.emptyIntArray,
      Array.emptyDoubleArray
    )
