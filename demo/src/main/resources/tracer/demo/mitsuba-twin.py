# The Mitsuba 3 twin of a tracer scene, written by tracer.demo.Mitsuba (docs/mitsuba.md).
#
#   scripts/mitsuba.sh twin.py OUT.pfm [--variant scalar_rgb|llvm_ad_rgb] [--seed S] [--spp N]
#                                      [--threads T] [--time]
#
# Renders the scene below and writes the picture as a Portable FloatMap (linear RGB, 32-bit
# floats). With --time it prints "load: S s" and "render: S s" on stdout.
import argparse
import struct
import time

import drjit as dr
import mitsuba as mi

arguments = argparse.ArgumentParser(description="Renders a tracer scene's Mitsuba 3 twin.")
arguments.add_argument("output", help="the .pfm file to write")
arguments.add_argument("--variant", default="scalar_rgb")
arguments.add_argument("--seed", type=int, default=0)
arguments.add_argument("--spp", type=int, default=0, help="samples a pixel (default: the twin's)")
arguments.add_argument("--threads", type=int, default=0, help="threads (default: all)")
arguments.add_argument("--time", action="store_true", help="print the load and render times")
options = arguments.parse_args()
started = time.perf_counter()
mi.set_variant(options.variant)
if options.threads > 0:
    dr.set_thread_count(options.threads)


class TracerLight(mi.Emitter):
    """A point light as the tracer's: irradiance pi * C * A(d) * cos at distance d, where
    A(d) = 2 / (1 + (d / D)^n) with fade, else 1 (Mitsuba's own point light falls off as 1/d^2)."""

    def __init__(self, props):
        mi.Emitter.__init__(self, props)
        self.position = mi.ScalarPoint3f(props["position"])
        self.colour = mi.ScalarColor3f(props["colour"])
        self.fade_distance = props.get("fade_distance", 0.0)
        self.fade_power = props.get("fade_power", 0.0)
        self.m_flags = mi.EmitterFlags.DeltaPosition

    def sample_direction(self, it, sample, active=True):
        ds = mi.DirectionSample3f()
        ds.p = mi.Point3f(self.position)
        ds.n = mi.Normal3f(0)
        ds.uv = mi.Point2f(0)
        ds.time = it.time
        ds.pdf = mi.Float(1)
        ds.delta = mi.Bool(True)
        ds.emitter = mi.EmitterPtr(self) if hasattr(mi, "EmitterPtr") else self
        d = ds.p - it.p
        ds.dist = dr.norm(d)
        ds.d = d / ds.dist
        fade = mi.Float(1)
        if self.fade_distance > 0:
            fade = 2 / (1 + dr.power(ds.dist / self.fade_distance, self.fade_power))
        return ds, mi.Spectrum(dr.pi * mi.Color3f(self.colour) * fade)

    def pdf_direction(self, it, ds, active=True):
        return mi.Float(0)

    def eval_direction(self, it, ds, active=True):
        return mi.Spectrum(0)

    def eval(self, si, active=True):
        return mi.Spectrum(0)

    def bbox(self):
        return mi.ScalarBoundingBox3f(self.position)

    def traverse(self, callback):
        pass

    def to_string(self):
        return f"TracerLight[position={self.position}, colour={self.colour}]"


class TracerMixture(mi.BSDF):
    """f = sum of the lobes' own f (each carries its weight), sampled by choosing lobe i with
    probability p_i (its weight over the sum). A smooth lobe's sample is weighed by the whole
    smooth part (sum of f over sum of p_j * pdf_j), a delta lobe's by its own value over p_i, so
    delta and smooth lobes mix exactly (Mitsuba 3.9.1's blendbsdf does not, with a delta lobe)."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        count = props["count"]
        self.lobes = [props[f"lobe_{i}"] for i in range(count)]
        weights = [props[f"weight_{i}"] for i in range(count)]
        total = sum(weights)
        self.chance = [w / total for w in weights]
        self.cumulative = [sum(self.chance[: i + 1]) for i in range(count)]
        self.delta = [mi.has_flag(lobe.flags(), mi.BSDFFlags.Delta) for lobe in self.lobes]
        flags = 0
        components = []
        for lobe in self.lobes:
            flags = flags | lobe.flags()
            components += [lobe.flags(k) for k in range(lobe.component_count())]
        self.m_flags = flags
        self.m_components = components

    def sample(self, ctx, si, sample1, sample2, active=True):
        bs = mi.BSDFSample3f()
        bs.wo = mi.Vector3f(0)
        bs.pdf = mi.Float(0)
        bs.eta = mi.Float(1)
        bs.sampled_type = mi.UInt32(0)
        bs.sampled_component = mi.UInt32(0)
        weight = mi.Spectrum(0)
        low = 0.0
        smooth = mi.Bool(False)
        for i, lobe in enumerate(self.lobes):
            high = 1.0 if i == len(self.lobes) - 1 else self.cumulative[i]
            chosen = (sample1 >= low) & (sample1 < high) if i > 0 else sample1 < high
            if i == len(self.lobes) - 1:
                chosen = sample1 >= low
            rescaled = dr.clip((sample1 - low) / max(high - low, 1e-30), 0.0, 0.99999994)
            lbs, lweight = lobe.sample(ctx, si, rescaled, sample2, active & chosen)
            bs.wo = dr.select(chosen, lbs.wo, bs.wo)
            bs.eta = dr.select(chosen, lbs.eta, bs.eta)
            bs.sampled_type = dr.select(chosen, lbs.sampled_type, bs.sampled_type)
            bs.sampled_component = dr.select(chosen, lbs.sampled_component, bs.sampled_component)
            if self.delta[i]:
                bs.pdf = dr.select(chosen, lbs.pdf * self.chance[i], bs.pdf)
                weight = dr.select(chosen, lweight / self.chance[i], weight)
            else:
                smooth = smooth | (chosen & (lbs.pdf > 0))
            low = high
        # A smooth lobe's direction: weighed by every smooth lobe (the delta ones give 0 there).
        f, pdf = self.eval_pdf(ctx, si, bs.wo, active & smooth)
        bs.pdf = dr.select(smooth, pdf, bs.pdf)
        # The division is by 1 where pdf is 0: scalar_rgb evaluates both sides of a select.
        weight = dr.select(smooth, dr.select(pdf > 0, f / dr.select(pdf > 0, pdf, 1.0), 0), weight)
        return bs, weight

    def eval(self, ctx, si, wo, active=True):
        return self.eval_pdf(ctx, si, wo, active)[0]

    def pdf(self, ctx, si, wo, active=True):
        return self.eval_pdf(ctx, si, wo, active)[1]

    def eval_pdf(self, ctx, si, wo, active=True):
        f = mi.Spectrum(0)
        pdf = mi.Float(0)
        for i, lobe in enumerate(self.lobes):
            if not self.delta[i]:
                lf, lpdf = lobe.eval_pdf(ctx, si, wo, active)
                f += lf
                pdf += self.chance[i] * lpdf
        return f, pdf

    def traverse(self, callback):
        pass

    def to_string(self):
        return f"TracerMixture[chance={self.chance}]"


mi.register_emitter("tracer_light", lambda props: TracerLight(props))
mi.register_bsdf("tracer_mixture", lambda props: TracerMixture(props))


def rgb(r, g, b):
    return {"type": "rgb", "value": [r, g, b]}


def reflectance(r, g, b):
    """A lobe's weight: above 1 (diffuse 1.5, or a clear surface's weights divided by 1 - t) as
    an unbounded sRGB value, which Mitsuba refuses as plain "rgb" where a reflectance goes."""
    if max(r, g, b) > 1:
        return {"type": "srgb", "color": [r, g, b], "unbounded": True}
    return rgb(r, g, b)


def mixture(*lobes):
    """The tracer_mixture of (weight, bsdf) pairs."""
    d = {"type": "tracer_mixture", "count": len(lobes)}
    for i, (weight, lobe) in enumerate(lobes):
        d[f"weight_{i}"] = float(weight)
        d[f"lobe_{i}"] = lobe
    return d


def mesh(name, positions, normals, bsdf, emitter=None):
    """A mesh of separate triangles: corners (x, y, z each) three by three, in their order, so
    that Mitsuba's face normal (p1 - p0) x (p2 - p0) is the tracer's; with vertex normals if given."""
    props = mi.Properties()
    props["bsdf"] = mi.load_dict(bsdf)
    if emitter is not None:
        props["emitter"] = mi.load_dict(emitter)
    corners = len(positions) // 3
    shape = mi.Mesh(name, corners, corners // 3, props, has_vertex_normals=normals is not None)
    params = mi.traverse(shape)
    params["vertex_positions"] = type(params["vertex_positions"])(positions)
    params["faces"] = type(params["faces"])(range(corners))
    if normals is not None:
        params["vertex_normals"] = type(params["vertex_normals"])(normals)
    params.update()
    return shape


def look_at(eye, target, up):
    """Mitsuba's look_at followed by a mirror of the camera's x: the tracer's world is left-handed."""
    return mi.ScalarTransform4f().look_at(origin=eye, target=target, up=up) @ mi.ScalarTransform4f().scale([-1, 1, 1])


def matrix(rows):
    return mi.ScalarTransform4f(rows)


def write_pfm(path, image):
    """A colour Portable FloatMap: little-endian (scale -1), rows from the bottom up."""
    bitmap = mi.Bitmap(image)
    width, height = bitmap.size()
    values = list(dr.ravel(mi.TensorXf(bitmap)))
    channels = bitmap.channel_count()
    rows = []
    for y in reversed(range(height)):
        start = y * width * channels
        row = values[start : start + width * channels]
        rows.append(b"".join(struct.pack("<fff", *row[x * channels : x * channels + 3]) for x in range(width)))
    with open(path + ".partial", "wb") as out:
        out.write(f"PF\n{width} {height}\n-1.0\n".encode("ascii"))
        out.write(b"".join(rows))
    import os

    os.replace(path + ".partial", path)


def render(scene):
    loaded = mi.load_dict(scene)
    spp = options.spp if options.spp > 0 else 0
    begun = time.perf_counter()
    image = mi.render(loaded, seed=options.seed, spp=spp)
    dr.eval(image)
    dr.sync_thread()
    rendered = time.perf_counter()
    if options.time:
        print(f"load: {begun - started:.3f} s")
        print(f"render: {rendered - begun:.3f} s")
    write_pfm(options.output, image)
