"""Flow Texture in pvbatch: the same texture coordinates, mask and texture as the library called
directly, closed-form facts of the cylinder flow, an abort, and a surface outside the data."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
data = XMLImageDataReader(FileName=[setup.field()])


def patch_file(name, patch):
    return t.aligned_patch_reader(setup, name, patch)


def set_properties(filter, p):
    filter.Scale, filter.Offset, filter.MinRelativeSpeed = p["scale"], p["offset"], p["min_speed"]
    filter.Texture = "Arrows" if p["texture"] == "arrows" else "Noise (LIC-like)"
    filter.TextureWidth, filter.TextureHeight = p["width"], p["height"]
    filter.FilterLength, filter.NoiseSeed = p["filter"], p["seed"]
    filter.ArrowsAlong, filter.ArrowsAcross = p["along"], p["across"]


def expect_same_as_library(filter, name, patch, p):
    prefix = setup.path(name)
    setup.run_reference("texture", setup.field(), prefix, *patch, p["scale"], p["offset"], p["min_speed"],
                        p["texture"], p["width"], p["height"], p["filter"], p["seed"], p["along"], p["across"])
    expected = t.read_polydata(prefix + "_surface.vtp")
    out = t.fetch_port(filter, 0)
    t.expect_spread_over_ranks(out, name)
    for array in ["r", "s", "texture_coordinates"]:
        t.expect_same_array(out, expected, array)
    t.expect_same_array(out, expected, "texture_mask", cells=True)
    tcoords = out.GetPointData().GetTCoords()
    if tcoords is None or tcoords.GetName() != "texture_coordinates":
        raise AssertionError("texture_coordinates is not the point data's TCoords")
    image = t.fetch_port(filter, 1)
    if list(image.GetDimensions()) != [p["width"], p["height"], 1]:
        raise AssertionError("texture dimensions %s" % (image.GetDimensions(),))
    texels = t.read_text_points(prefix + "_texture.txt")
    rgb = image.GetPointData().GetScalars()
    if rgb is None or rgb.GetNumberOfComponents() != 3 or rgb.GetNumberOfTuples() != len(texels):
        raise AssertionError("the texture is not %d RGB texels" % len(texels))
    for i, texel in enumerate(texels):
        want = tuple(float(math.floor(255 * min(max(c, 0.0), 1.0) + 0.5)) for c in texel)
        if rgb.GetTuple3(i) != want:
            raise AssertionError("%s: texel %d is %s, the library's %s" % (name, i, rgb.GetTuple3(i), want))
    print("%s: the library's texture (%d x %d)" % (name, p["width"], p["height"]))
    return out


def column(data, name, component=0, cells=False):
    return [v[component] for v in t.array_values(data, name, cells)]


# 1. A stream surface of the cylinder flow, with a noise texture.
stream = [-1.8, 0.5, 0.0, 1.0, 0.3, 0.2, 0.8, 800, "planar", "tangential", 25]
stream_surface = patch_file("stream", stream)
texture = FlowTexture(Input=data, Surface=stream_surface)
texture.Velocity = ["POINTS", "velocity"]
noise = dict(scale=0.4, offset=0.25, min_speed=0.02, texture="noise", width=64, height=32, filter=12, seed=5,
             along=4, across=4)
set_properties(texture, noise)
out = expect_same_as_library(texture, "noise", stream, noise)
u, v = column(out, "texture_coordinates", 0), column(out, "texture_coordinates", 1)
r, s = column(out, "r"), column(out, "s")
worst = max(max(abs(a - (0.4 * b + 0.25)) for a, b in zip(u, r)), max(abs(a - 0.4 * b) for a, b in zip(v, s)))
if not worst <= 1e-12:
    raise AssertionError("(u, v) is not (0.4 r + 0.25, 0.4 s): off by %g" % worst)
mask = column(out, "texture_mask", cells=True)
if not (min(mask) >= 0 and max(mask) <= 1 and sum(mask) / len(mask) < 0.1):
    raise AssertionError("stream surface: mask outside [0, 1] or a mean above 0.1 (%g)" % (sum(mask) / len(mask)))

# 2. The arrow texture, and Min Relative Speed masking the slow faces too.
masked = sum(1 for m in mask if m == 1.0)
arrows = dict(noise, texture="arrows", width=64, height=64, along=4, across=8, min_speed=0.8)
set_properties(texture, arrows)
out = expect_same_as_library(texture, "arrows", stream, arrows)
slow = sum(1 for m in column(out, "texture_mask", cells=True) if m == 1.0)
if not slow > masked + 100:
    raise AssertionError("Min Relative Speed 0.8 masks %d faces, 0.02 masked %d" % (slow, masked))
print("Min Relative Speed 0.8 masks %d faces of %d (0.02: %d)" % (slow, len(mask), masked))

# 3. The plane z = 0, a stream surface of the cylinder flow (curl-free): u is the potential
# times the scale up to a constant, and the texture follows the flow everywhere (mask near 0).
plane = [-2.0, 0.9, 0.0, 0.0, 0.0, 1.0, 1.0, 800, "planar", "tangential", 0]
texture.Surface = patch_file("plane", plane)
set_properties(texture, noise)
out = expect_same_as_library(texture, "plane", plane, noise)
points = t.points_of(out)
exact = [0.4 * x[0] * (1 + 1 / (x[0] ** 2 + x[1] ** 2)) for x in points]
u = column(out, "texture_coordinates", 0)
d = [a - b for a, b in zip(u, exact)]
mean = sum(d) / len(d)
worst = max(abs(x - mean) for x in d) / (max(exact) - min(exact))
if not worst <= 5e-3:
    raise AssertionError("plane: u differs from 0.4 potential by %g of its range" % worst)
mask = column(out, "texture_mask", cells=True)
if not max(mask) <= 0.02:
    raise AssertionError("plane: the texture is masked (largest mask %g) where it follows the flow" % max(mask))
print("plane: u = 0.4 potential within %.2g of its range, largest mask %.2g" % (worst, max(mask)))

# 4. A surface orthogonal to the flow: the gradient of r cannot follow the flow, the mask hides it.
across = [-1.8, 0.5, 0.0, 1.0, 0.3, 0.2, 0.8, 800, "planar", "orthogonal", 25]
texture.Surface = patch_file("across", across)
out = expect_same_as_library(texture, "across", across, noise)
mask = column(out, "texture_mask", cells=True)
if not sum(mask) / len(mask) > 0.9:
    raise AssertionError("orthogonal surface: mean mask %g, expected near 1" % (sum(mask) / len(mask)))
print("orthogonal surface: mean mask %.3g" % (sum(mask) / len(mask)))

# 5. The texture saved as PNG (to be loaded as the representation's Texture): the same texels.
# (ParaView has no PNG writer for data on several ranks: there, the MPI run skips this.)
if t.number_of_ranks() == 1:
    png = setup.path("texture.png")
    SaveData(png, proxy=OutputPort(texture, 1))
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    saved, image = reader.GetOutput(), t.fetch_port(texture, 1)
    if saved.GetDimensions() != image.GetDimensions() or any(
            saved.GetPointData().GetScalars().GetTuple3(i) != image.GetPointData().GetScalars().GetTuple3(i)
            for i in range(image.GetNumberOfPoints())):
        raise AssertionError("the texture saved as PNG is not the texture")
    print("the texture saved as PNG has the same texels")

# 6. Abort (what ParaView's Abort button sets, here from a progress observer at the first stage
# the parametrization reports): a warning and the previous outputs kept; the next change computes
# them (the texture coordinates u = scale r + offset move by the change of the offset).
before = t.output_sizes(texture, range(2))
u_before = column(t.fetch_port(texture, 0), "texture_coordinates", 0)
offset = texture.Offset
texture.Offset = offset + 0.5
with t.AbortOnce(texture, lambda progress: 0 < progress < 1) as abort, t.Messages() as messages:
    after = t.output_sizes(texture, range(2))
t.expect_message(messages, ["Flow Texture: cancelled before the parametrization was solved",
                            "the previous output is kept"], "abort")
if after != before or abs(abort.progress[0] - 1.0 / 3) > 1e-12:
    raise AssertionError("abort at progress %s: outputs %s, before %s" % (abort.progress, after, before))
texture.Offset = offset + 0.25
u = column(t.fetch_port(texture, 0), "texture_coordinates", 0)
worst = max(abs(a - (b + 0.25)) for a, b in zip(u, u_before))
if len(u) != len(u_before) or worst > 1e-9:
    raise AssertionError("after an abort, the next change gives u off by %g" % worst)
print("Flow Texture: aborted at progress %.3f, previous outputs kept, then computed" % abort.progress[0])

# 7. A surface outside the data: a message naming the fault, no crash, the previous outputs kept.
before = t.output_sizes(texture, range(2))
moved = Transform(Input=texture.Surface, Transform="Transform")
moved.Transform.Translate = [100.0, 0.0, 0.0]
texture.Surface = moved
t.expect_error_keeps_outputs(texture, range(2), before, ["Flow Texture: parametrize_tangential"],
                             "surface outside the data")
# A point that belongs to no triangle (point i must stay vertex i, it cannot be dropped).
texture.Surface = AppendGeometry(Input=[patch_file("plane_again", plane), PointSource(NumberOfPoints=1)])
t.expect_error_keeps_outputs(texture, range(2), before, ["point 449 belongs to no triangle", "Filters > Clean"], "isolated point")
# A fresh Flow Texture whose first update fails has no earlier output to keep: one message, its
# own, and the texture all the same (an empty image would make the pipeline complain of its extent).
fresh = FlowTexture(Input=texture.Input, Surface=moved)
fresh.Velocity = ["POINTS", "velocity"]
with t.Messages() as messages:
    fresh.UpdatePipeline()
text = messages.text()
if "Flow Texture: parametrize_tangential" not in text or "extent" in text:
    raise AssertionError("a first update that fails says: %s" % text)
if t.fetch_port(fresh, 1).GetNumberOfPoints() != 128 * 128:
    raise AssertionError("a first update that fails gives no texture")
print("Flow Texture: all checks passed")
