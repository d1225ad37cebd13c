package tracer.io

/** The names each element of the scene format allows: its attributes and its child elements. */
private[io] object Vocabulary:
  /** No names at all: for an element without attributes, or without children. */
  val NoNames: Set[String] = Set()

  /** The shapes of versions 1 and 2. */
  val PlainShapes: Set[String] = Set("sphere", "plane", "triangle", "mesh")

  /** The solids of version 3. */
  val Solids: Set[String] = Set("box", "cylinder", "cone", "torus")

  /** The constructive solid geometry elements of version 3. */
  val Combinations: Set[String] = Set("union", "intersection", "difference")

  /** The elements that are shapes. */
  val Shapes: Set[String] = PlainShapes ++ Solids ++ Combinations

  /** What any CSG element may combine: shapes with an inside. */
  val SolidChildren: Set[String] = Set("sphere", "plane") ++ Solids ++ Combinations

  /** What only a union may hold besides: shapes without an inside. */
  val UnionOnlyChildren: Set[String] = Set("triangle", "mesh")

  /** A version 3 element's placement: its children (the `scale` attribute is listed apart). */
  val PlacementChildren: Set[String] = Set("rotate", "translate")

  /** `<camera>`'s attributes. */
  val CameraAttributes: Set[String] = Set("zoom", "width", "height")

  /** `<camera>`'s children. */
  val CameraChildren: Set[String] = Set("location", "lookat", "up")

  /** `<light>`'s attributes (version 4's fall-off). */
  val LightAttributes: Set[String] = Set("fade-distance", "fade-power")

  /** `<light>`'s children. */
  val LightChildren: Set[String] = Set("location", "colour", "color", "area")

  /** `<area>`'s attributes. */
  val AreaAttributes: Set[String] = Set("samples-a", "samples-b")

  /** `<area>`'s children. */
  val AreaChildren: Set[String] = Set("a", "b")

  /** `<mesh>`'s attributes. */
  val MeshAttributes: Set[String] = Set("file", "scale", "smooth")

  /** `<mesh>`'s children. */
  val MeshChildren: Set[String] = Set("rotate", "translate", "surface")

  /** `<sphere>`'s attributes. */
  val SphereAttributes: Set[String] = Set("radius")

  /** `<sphere>`'s children. */
  val SphereChildren: Set[String] = Set("centre", "center", "pole", "equator", "surface")

  /** `<plane>`'s attributes. */
  val PlaneAttributes: Set[String] = Set("distance")

  /** `<plane>`'s children. */
  val PlaneChildren: Set[String] = Set("normal", "point", "surface")

  /** `<triangle>`'s children. */
  val TriangleChildren: Set[String] = Set("corner", "origin", "a", "b", "surface")

  /** `<box>`'s children. */
  val BoxChildren: Set[String] = Set("corner1", "corner2", "surface")

  /** `<cylinder>`'s attributes. */
  val CylinderAttributes: Set[String] = Set("radius", "open")

  /** `<cone>`'s attributes. */
  val ConeAttributes: Set[String] = Set("base-radius", "cap-radius", "open")

  /** `<cylinder>`'s and `<cone>`'s children. */
  val AxisChildren: Set[String] = Set("base", "cap", "surface")

  /** `<torus>`'s attributes. */
  val TorusAttributes: Set[String] = Set("major", "minor")

  /** `<surface>`'s attributes, versions 1 and 2. */
  val SurfaceAttributes: Set[String] =
    Set("diffuse", "reflection", "phong", "phong-size", "specular", "roughness", "transmit", "ior")

  /** `<surface>`'s children. */
  val SurfaceChildren: Set[String] = Set("colour", "color", "texture", "checker", "emission")

  /** `<checker>`'s attributes. */
  val CheckerAttributes: Set[String] = Set("size")

  /** `<checker>`'s children. */
  val CheckerChildren: Set[String] = Set("colour", "color")

  /** `<texture>`'s attributes. */
  val TextureAttributes: Set[String] = Set("file")

  /** A vector element's attributes. */
  val VectorAttributes: Set[String] = Set("x", "y", "z")

  /** A colour element's attributes. */
  val ColourAttributes: Set[String] = Set("r", "g", "b")
