"""Grow Boundary in pvbatch: the same grown and re-aligned surfaces as the library called
directly (paraview_reference grow: Flow_aligned_deformation::grow() and run() on the same
aligned surface), in the three growth modes; a closed surface and a surface outside the data
reported with the library's reason, the previous output kept."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
data = XMLImageDataReader(FileName=[setup.field()])

# The aligned surface both start from: a tangential patch after 25 iterations (as in
# test_flow_aligned_surface.py), written by the reference and read here.
PATCH = [-1.8, 0.5, 0.0, 1.0, 0.3, 0.2, 0.8, 800, "planar", "tangential", 25]


def reference(name, distance, mode, steps, iterations):
    """The library's grown surface, the aligned surface it grew (IN.vtp) and its report."""
    surface_in, vtp = setup.path(name + "_in.vtp"), setup.path(name + ".vtp")
    setup.run_reference("grow", setup.field(), surface_in, vtp, *PATCH, distance, mode, steps, iterations)
    with open(vtp + ".txt") as f:
        report = {key: float(value) for key, value in (line.split() for line in f)}
    return surface_in, t.read_polydata(vtp), report


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    if array is None:
        raise AssertionError("the output has no point array '%s'" % name)
    return [array.GetValue(i) for i in range(array.GetNumberOfTuples())]


def check(grow, name, distance, mode, steps, iterations):
    surface_in, expected, report = reference(name, distance, mode, steps, iterations)
    grow.Surface = XMLPolyDataReader(FileName=[surface_in])
    out = t.fetch(grow)
    t.expect_spread_over_ranks(out, name)
    t.expect_same_surface(out, expected, name)
    for key, value in report.items():
        got = t.field_value(out, key)
        if abs(got - value) > 1e-9 * max(1.0, abs(value)):
            raise AssertionError("%s: %s is %.17g, the library's %.17g" % (name, key, got, value))
    if point_array(out, "growth_step") != point_array(expected, "growth_step"):
        raise AssertionError("%s: growth_step differs from the library's" % name)
    if report["number_of_new_vertices"] < 1 or report["added_area"] <= 0:
        raise AssertionError("%s: nothing was grown" % name)
    for array in ["velocity", "velocity_sampled"]:
        if out.GetPointData().GetArray(array) is None:
            raise AssertionError("%s: no point array %s" % (name, array))
    if out.GetCellData().GetArray("normalized_flux") is None:
        raise AssertionError("%s: no cell array normalized_flux" % name)
    flux = t.field_value(out, "normalized_flux")
    print("%s: %d new vertices, added area %.4g, %d iterations, normalized flux %.3g" % (
        name, report["number_of_new_vertices"], report["added_area"], report["number_of_iterations"], flux))
    return out


grow = GrowBoundary(Input=data, Surface=XMLPolyDataReader(FileName=[reference("all", 0.1, "all", 1, 20)[0]]))
grow.Velocity = ["POINTS", "velocity"]
grow.Alignment = "Tangential (stream surface)"
grow.Distance = 0.1
grow.NumberOfIterations = 20
check(grow, "all", 0.1, "all", 1, 20)

grow.GrowthMode = "Across the flow"
grow.NumberOfGrowthSteps = 2
grown = check(grow, "across", 0.1, "across", 2, 20)
if t.field_value(grown, "number_of_factorizations") != 3:
    raise AssertionError("two growth steps: expected three factorizations (the input, then one per step)")
flux = t.field_value(grown, "normalized_flux")
if not 0 <= flux < 0.05:
    raise AssertionError("the grown tangential surface has normalized flux %g after re-aligning" % flux)

grow.GrowthMode = "Along a direction"
grow.GrowthDirection = [0.0, 0.0, 1.0]
grow.NumberOfGrowthSteps = 1
check(grow, "direction", 0.1, "0,0,1", 1, 20)

# Flow-Aligned Surface's output as the surface (the plugin's pipeline): the same as the
# library's growth of the same aligned patch.
_, expected, _ = reference("all", 0.1, "all", 1, 20)
aligned = FlowAlignedSurface(Input=data)
aligned.Velocity = ["POINTS", "velocity"]
aligned.Center, aligned.Normal, aligned.Size, aligned.NumberOfFaces = PATCH[0:3], PATCH[3:6], PATCH[6], PATCH[7]
aligned.NumberOfIterations = PATCH[10]
aligned.UpdatePipeline(PATCH[10])
grow.GrowthMode = "All"
grow.Surface = aligned
good = t.fetch(grow, PATCH[10])
t.expect_same_surface(good, expected, "Flow-Aligned Surface, then Grow Boundary")

# Bad input: a closed surface (the library refuses it), then a surface outside the data; the
# message names the fault and the previous output is kept.
grow.Surface = Sphere(Center=[-1.8, 0.5, 0.0], Radius=0.3)
with t.Messages() as messages:
    kept = t.fetch(grow)
t.expect_message(messages, ["closed", "previous output is kept"], "closed surface")
t.expect_same_surface(kept, good, "closed surface: previous output kept")

grow.Surface = Triangulate(Input=Plane(Origin=[10, 0, 0], Point1=[11, 0, 0], Point2=[10, 1, 0]))
with t.Messages() as messages:
    kept = t.fetch(grow)
t.expect_message(messages, ["has no flow sample", "outside"], "surface outside the data")
t.expect_same_surface(kept, good, "surface outside the data: previous output kept")
print("Grow Boundary: all checks passed")
