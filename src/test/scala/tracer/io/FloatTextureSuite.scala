package tracer.io

import java.io.{ByteArrayInputStream, ByteArrayOutputStream, PrintStream}
import java.nio.file.{Files, Path}
import tracer.cli.Main
import tracer.image.{Bitmap, Colour, Exr, Pfm, Png, Raster}
import tracer.scene.Texture

/** Textures from floating-point files (version 4): `.pfm` (colour and grey) and `.exr` texels
  * used as they are, above 1 included, while 8-bit textures keep their exact colours.
  */
class FloatTextureSuite extends munit.FunSuite:

  private val dir = FunFixture[Path](
    _ => Files.createTempDirectory("tracer-texture"),
    d => Files.walk(d).sorted(java.util.Comparator.reverseOrder()).forEach(Files.delete)
  )

  private val hdr = Colour(4, 0.5, 2)

  private def write(path: Path, raster: Raster, exr: Boolean): Unit =
    val out = Files.newOutputStream(path)
    try if exr then Exr.write(raster, out) else Pfm.write(raster, out)
    finally out.close()

  test(
    "a floating-point texel is its value; an 8-bit one is sample / maxval in doubles, as before"
  ):
    val floats = Raster.fromChannels(2, 1, Array(4f, 0.5f, 2f, 0.1f, 0.2f, 0.3f))
    assertEquals(Texture(floats).colourAt(0.25, 0.5), hdr)
    // 0.1f widened is not 0.1: the raster's value as stored.
    assertEquals(
      Texture(floats).colourAt(0.75, 0.5),
      Colour(0.1f.toDouble, 0.2f.toDouble, 0.3f.toDouble)
    )
    val bytes = Bitmap.fromSamples(1, 1, 255, Vector(51, 1, 254))
    // 51/255 in doubles, not 51/255 rounded to a float and widened.
    assertEquals(Texture(bytes).colourAt(0.5, 0.5), Colour(51 / 255.0, 1 / 255.0, 254 / 255.0))
    assertNotEquals((51 / 255.0).toFloat.toDouble, 51 / 255.0)

  dir.test("the texture loader reads PFM (PF and Pf), OpenEXR, PPM and PNG by content"): d =>
    val picture = Raster.tabulate(3, 2)((x, y) => Colour(x + 0.5, y * 3.0, 7))
    write(d.resolve("a.pfm"), picture, exr = false)
    write(d.resolve("b.exr"), picture, exr = true)
    Files.write(
      d.resolve("grey.pfm"),
      "Pf\n1 1\n-1.0\n".getBytes ++ java.nio.ByteBuffer
        .allocate(4)
        .order(java.nio.ByteOrder.LITTLE_ENDIAN)
        .putFloat(2.5f)
        .array
    )
    Files.write(d.resolve("c.img"), Png.encode(Bitmap.fill(1, 1, Colour(0, 1, 0))))
    val load = TextureFiles.loader(d)
    assertEquals(load("a.pfm"), Right(picture))
    assertEquals(load("b.exr"), Right(picture))
    assertEquals(load("grey.pfm"), Right(Raster.fromChannels(1, 1, Array(2.5f, 2.5f, 2.5f))))
    assertEquals(load("c.img"), Right(Bitmap.fill(1, 1, Colour(0, 1, 0))))
    Files.writeString(d.resolve("bad.pfm"), "PF\n2 2\n-1.0\n")
    assert(load("bad.pfm").left.exists(_.contains("expected 48 bytes")), load("bad.pfm").toString)

  private def render(d: Path, texture: String, args: String*): Unit =
    val scene =
      s"""<scene><camera><location x="0" y="0" z="-5"/><lookat x="0" y="0" z="0"/></camera>
         |<light><location x="0" y="0" z="-5"/></light>
         |<sphere radius="1"><centre x="0" y="0" z="0"/><surface><texture file="$texture"/></surface></sphere>
         |</scene>""".stripMargin
    Files.writeString(d.resolve("scene.xml"), scene)
    val err    = ByteArrayOutputStream()
    val status = Main.run(
      List("-i", "scene.xml", "-x", "3", "-y", "3", "-w", "1", "-h", "1") ++ args,
      ByteArrayInputStream(Array.emptyByteArray),
      PrintStream(ByteArrayOutputStream()),
      PrintStream(err),
      d
    )
    assertEquals(status, 0, err.toString)

  dir.test("a .pfm or .exr texture above 1 renders as its value: the centre pixel is the texel"):
    d =>
      // A uniform texture: every texel (4, 0.5, 2). The centre pixel's ray meets the ball head on,
      // under a light at the eye: quick mode and full mode both give the texel times cos 0 = 1.
      val uniform = Raster.tabulate(4, 2)((_, _) => hdr)
      for (name, exr) <- List(("t.pfm", false), ("t.exr", true)) do
        write(d.resolve(name), uniform, exr)
        render(d, name, "-q", "o.pfm")
        assertEquals(Pfm.read(Files.readAllBytes(d.resolve("o.pfm"))).map(_(1, 1)), Right(hdr))
        render(d, name, "o.pfm")
        // Full mode: diffuse 1 under a white light at the eye, S0 1e-4 off the surface.
        val lit = Pfm.read(Files.readAllBytes(d.resolve("o.pfm"))).map(_(1, 1)).toOption.get
        assertEqualsDouble(lit.r, 4, 1e-5)
        assertEqualsDouble(lit.g, 0.5, 1e-6)
        // An 8-bit output brings the bright texel into range, keeping its hue (4 : 0.5 : 2).
        render(d, name, "-q", "o.ppm")
        val b = tracer.image.Ppm.read(Files.readAllBytes(d.resolve("o.ppm"))).toOption.get
        assertEquals((0 until 3).map(b.sample(1, 1, _)).toList, List(255, 32, 128))
