"""Parametrize And Seed in pvbatch: the same parametrizations, seed curves and seed points as the
library called directly, closed-form facts of the cylinder flow, and bad surfaces."""
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


def reference(name, patch, method, normalization="default", alpha=0.0, source="centroid", curves=8,
              spacing=0.1, seed=0, delaunay="delaunay"):
    """The library's surface, seed curves and seed points for the same arguments."""
    prefix = setup.path(name)
    setup.run_reference("parametrize", setup.field(), prefix, *patch, method, normalization, alpha, source,
                        curves, spacing, seed, delaunay)
    return (t.read_polydata(prefix + "_surface.vtp"), t.read_polydata(prefix + "_curves.vtp"),
            t.read_text_points(prefix + "_seeds.txt"))


def expect_same_as_library(filter, expected, arrays, what):
    surface, curves, seeds = expected
    out = t.fetch_port(filter, 0)
    t.expect_spread_over_ranks(out, what)
    for name in arrays:
        t.expect_same_array(out, surface, name)
    got_curves = t.fetch_port(filter, 1)
    t.expect_same_polylines(got_curves, curves, what + ": seed curves")
    t.expect_same_array(got_curves, curves, arrays[0])
    t.expect_same_array(got_curves, curves, arrays[0], cells=True)
    got_seeds = t.points_of(t.fetch_port(filter, 2))
    if len(got_seeds) != len(seeds):
        raise AssertionError("%s: %d seed points against %d" % (what, len(got_seeds), len(seeds)))
    worst = max([t.distance(p, q) for p, q in zip(got_seeds, seeds)] + [0.0])
    if not worst <= 1e-12:
        raise AssertionError("%s: seed points differ by %g" % (what, worst))
    print("%s: the library's %d seed curves and %d seed points" % (what, curves.GetNumberOfCells(), len(seeds)))
    return out


# 1. Tangential, normalized (the default), on a stream surface of the cylinder flow.
stream = [-1.8, 0.5, 0.0, 1.0, 0.3, 0.2, 0.8, 800, "planar", "tangential", 25]
stream_surface = patch_file("stream", stream)
p = ParametrizeAndSeed(Input=data, Surface=stream_surface)
p.Velocity = ["POINTS", "velocity"]
p.NumberOfSeedCurves = 8
p.SeedPointSpacing = 0.1
out = expect_same_as_library(p, reference("tangential", stream, "tangential"), ["r", "s"], "tangential")
if out.GetNumberOfPoints() != stream_surface.GetDataInformation().GetNumberOfPoints():
    raise AssertionError("the surface output has another number of points than the input")

# Seed points: no two closer than the spacing, and a near-maximal set (about 0.7 area / spacing^2).
seeds = t.points_of(t.fetch_port(p, 2))
closest = min(t.distance(a, b) for i, a in enumerate(seeds) for b in seeds[:i])
if not closest >= 0.1:
    raise AssertionError("two seed points are %g apart, closer than the spacing 0.1" % closest)

# 2. Unnormalized tangential on the plane z = 0, a stream surface of the cylinder flow (which is
# curl-free and divergence-free): r is the potential and s is -psi (or psi, by the orientation),
# up to constants and the discretization.
plane = [-2.0, 0.9, 0.0, 0.0, 0.0, 1.0, 1.0, 800, "planar", "tangential", 0]
plane_surface = patch_file("plane", plane)
p.Surface = plane_surface
p.GuidanceNormalization = "Unnormalized"
out = expect_same_as_library(p, reference("unnormalized", plane, "tangential", "unnormalized"), ["r", "s"],
                             "tangential, unnormalized")


def potential(x):
    rho2 = x[0] ** 2 + x[1] ** 2
    return x[0] * (1 + 1 / rho2)


def stream_function(x):
    rho2 = x[0] ** 2 + x[1] ** 2
    return x[1] * (1 - 1 / rho2)


def expect_equal_up_to_constant(values, exact, what, tolerance):
    """max |values - exact - mean| <= tolerance * (range of exact), for exact or -exact."""
    span = max(exact) - min(exact)
    best = None
    for sign in (1, -1):
        d = [v - sign * e for v, e in zip(values, exact)]
        mean = sum(d) / len(d)
        worst = max(abs(x - mean) for x in d) / span
        best = worst if best is None else min(best, worst)
    if not best <= tolerance:
        raise AssertionError("%s: differs from the closed form by %g of its range (tolerance %g)" % (
            what, best, tolerance))
    print("%s: closed form within %.2g of its range" % (what, best))


points = t.points_of(out)
r = [v[0] for v in t.array_values(out, "r")]
s = [v[0] for v in t.array_values(out, "s")]
expect_equal_up_to_constant(r, [potential(x) for x in points], "unnormalized r = potential", 5e-3)
expect_equal_up_to_constant(s, [stream_function(x) for x in points], "unnormalized s = -stream function", 5e-3)

# 3. Orthogonal, alpha = 0.3, on an orthogonal surface: the library's values, and iso-contours
# that are near-straight lines (every curve on an orthogonal surface is a seed curve).
across = [-1.8, 0.5, 0.0, 1.0, 0.3, 0.2, 0.8, 800, "planar", "orthogonal", 25]
p.Surface = patch_file("across", across)
p.Parametrization = "Orthogonal"
p.GuidanceNormalization = "Default (tangential normalized, orthogonal not)"
p.Angle = 0.3
p.SeedPointSpacing = 0.15
p.RandomSeed = 7
expect_same_as_library(p, reference("orthogonal", across, "orthogonal", alpha=0.3, spacing=0.15, seed=7),
                       ["r", "s"], "orthogonal")
curves = t.fetch_port(p, 1)
bend = 0.0
for i in range(curves.GetNumberOfCells()):
    ids = curves.GetCell(i).GetPointIds()
    line = [curves.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())]
    a, b = line[0], line[-1]
    chord = [b[d] - a[d] for d in range(3)]
    length = math.sqrt(sum(c * c for c in chord))
    worst = 0.0
    for x in line:
        ax = [x[d] - a[d] for d in range(3)]
        along = sum(ax[d] * chord[d] for d in range(3)) / length
        worst = max(worst, math.sqrt(max(0.0, sum(c * c for c in ax) - along * along)))
    if not worst <= 0.05 * length:
        raise AssertionError("orthogonal seed curve %d bends %g from its chord of length %g" % (i, worst, length))
    bend = max(bend, worst / length)
print("orthogonal: the %d seed curves are near-straight (largest bend %.2g of the chord)" % (
    curves.GetNumberOfCells(), bend))

# 4. Circular on a disk in the plane z = 0: the geodesic distance is the Euclidean distance from
# the source vertex there, and each seed curve is a circle of its value around it.
disk = [-2.0, 0.9, 0.0, 0.0, 0.0, 1.0, 1.0, 1500, "disk", "tangential", 0]
p.Surface = patch_file("disk", disk)
p.Parametrization = "Circular (geodesic distance)"
p.SeedPointSpacing = 0.1
p.RandomSeed = 0
out = expect_same_as_library(p, reference("circular", disk, "circular"), ["geodesic_distance"], "circular")
source_id = int(t.field_value(out, "source_point_id"))
source = out.GetPoint(source_id)
if not t.distance(source, (-2.0, 0.9, 0.0)) < 0.05:
    raise AssertionError("the source vertex %s is not near the disk's centroid" % (source,))
d = [v[0] for v in t.array_values(out, "geodesic_distance")]
worst = max(abs(d[i] - t.distance(out.GetPoint(i), source)) for i in range(out.GetNumberOfPoints()))
if not worst <= 0.02 * 0.5:
    raise AssertionError("geodesic distance on the disk differs from the Euclidean one by %g" % worst)
curves = t.fetch_port(p, 1)
values = t.array_values(curves, "geodesic_distance")
worst = max(abs(t.distance(curves.GetPoint(i), source) - values[i][0]) for i in range(curves.GetNumberOfPoints()))
if not worst <= 0.02 * 0.5:
    raise AssertionError("circular seed curves are off their circles by %g" % worst)
print("circular: distance and seed curves within %.2g of the Euclidean circles" % worst)

# A given source point, on the surface's own triangles (a deformed disk, whose triangles are not
# all Delaunay: the intrinsic Delaunay triangulation, the default, gives other distances there).
stream_disk = [-1.8, 0.5, 0.0, 1.0, 0.3, 0.2, 0.8, 800, "disk", "tangential", 25]
p.Surface = patch_file("stream_disk", stream_disk)
p.SourceAtCentroid = 0
p.SourcePoint = [-1.8, 0.6, 0.1]
p.IntrinsicDelaunay = 0
expect_same_as_library(p, reference("circular_point", stream_disk, "circular", source="-1.8,0.6,0.1",
                                    delaunay="direct"), ["geodesic_distance"], "circular from a point")

# 5. The workflow in one pipeline: Flow-Aligned Surface into Parametrize And Seed.
aligned = setup.patch_in_cylinder_flow(data, faces=800, iterations=25)
chained = ParametrizeAndSeed(Input=data, Surface=aligned)
chained.Velocity = ["POINTS", "velocity"]
with t.Messages() as messages:
    chained_out = t.fetch_port(chained, 0)
if "ERROR" in messages.text() or chained_out.GetPointData().GetArray("r") is None:
    raise AssertionError("Flow-Aligned Surface into Parametrize And Seed failed: " + messages.text())
if t.fetch_port(chained, 1).GetNumberOfCells() < 10:
    raise AssertionError("the chained pipeline gives fewer than 10 seed curves")

# 6. Bad surfaces: no triangles, and a surface outside the data.  A message naming the fault,
# no crash, and the previous outputs kept.
p.Parametrization = "Tangential"
p.Surface = stream_surface
before = t.output_sizes(p, range(3))
p.Surface = Line(Point1=[-2, 0, 0], Point2=[-1.5, 0.5, 0])
t.expect_error_keeps_outputs(p, range(3), before, ["Surface input (port 1) has no polygons"], "no triangles")
p.Surface = Transform(Input=stream_surface, Transform="Transform")
p.Surface.Transform.Translate = [100.0, 0.0, 0.0]
t.expect_error_keeps_outputs(p, range(3), before, ["Parametrize And Seed: parametrize_tangential"],
                             "surface outside the data")

# 7. Abort (what ParaView's Abort button sets, here from a progress observer at the first stage
# the parametrization reports): a warning and the previous outputs kept; the next change computes
# them.
p.Surface = stream_surface
p.NumberOfSeedCurves = 3
before = t.output_sizes(p, range(3))
p.NumberOfSeedCurves = 4
with t.AbortOnce(p, lambda progress: 0 < progress < 1) as abort, t.Messages() as messages:
    after = t.output_sizes(p, range(3))
stages = abort.progress
t.expect_message(messages, ["cancelled before the parametrization was solved", "the previous output is kept"],
                 "abort")
if after != before or abs(stages[0] - 1.0 / 3) > 1e-12:
    raise AssertionError("abort at progress %s: outputs %s, before %s" % (stages, after, before))
p.NumberOfSeedCurves = 5
values = t.fetch_port(p, 1).GetCellData().GetArray("r")
if len({values.GetValue(i) for i in range(values.GetNumberOfTuples())}) != 5:
    raise AssertionError("after an abort, the next change did not compute the 5 seed curves")
print("Parametrize And Seed: all checks passed")
