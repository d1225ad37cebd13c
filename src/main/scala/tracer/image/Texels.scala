package tracer.image

/** The pixels of a texture file: 8- or 16-bit samples (PPM, PNG), whose colours are sample /
  * maxval, or linear floats (PFM, OpenEXR), used as they are.
  */
type Texels = Bitmap | Raster
