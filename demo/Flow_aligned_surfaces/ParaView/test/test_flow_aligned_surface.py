"""Flow-Aligned Surface in pvbatch: the same surfaces as the library called directly, every
iteration a time step, and a moved patch re-aligned without a new factorization."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
data = XMLImageDataReader(FileName=[setup.field()])


def reference(name, center, normal, size, faces, shape, alignment, iterations):
    vtp = setup.path(name + ".vtp")
    setup.run_reference("align", setup.field(), vtp, *center, *normal, size, faces, shape, alignment, iterations)
    return t.read_polydata(vtp)


center, normal = [-1.8, 0.5, 0.0], [1.0, 0.3, 0.2]
surface = FlowAlignedSurface(Input=data)
surface.Velocity = ["POINTS", "velocity"]
surface.Center = center
surface.Normal = normal
surface.Size = 0.8
surface.NumberOfFaces = 800
surface.Alignment = "Tangential (stream surface)"
surface.NumberOfIterations = 25

# The iterations are the time steps 0..25.
surface.UpdatePipelineInformation()
steps = list(surface.TimestepValues)
if steps != [float(k) for k in range(26)]:
    raise AssertionError("time steps %s, expected 0..25" % steps)

# Iteration 25 and iteration 3 (a time step played back) equal the library's.
out = t.fetch(surface, 25)
t.expect_same_surface(out, reference("tangential_25", center, normal, 0.8, 800, "planar", "tangential", 25),
                      "tangential, iteration 25")
t.expect_same_surface(t.fetch(surface, 3),
                      reference("tangential_3", center, normal, 0.8, 800, "planar", "tangential", 3),
                      "tangential, iteration 3 (time step 3)")
flux = t.field_value(out, "normalized_flux")
if not 0 <= flux < 0.05:
    raise AssertionError("tangential surface after 25 iterations has normalized flux %g" % flux)
if t.field_value(out, "number_of_factorizations") != 1:
    raise AssertionError("one factorization expected")
for name in ["velocity", "velocity_sampled"]:
    if out.GetPointData().GetArray(name) is None:
        raise AssertionError("no point array " + name)
if out.GetCellData().GetArray("normalized_flux") is None:
    raise AssertionError("no cell array normalized_flux")
if abs(t.field_value(out, "sampled_area_fraction") - 1) > 1e-12:
    raise AssertionError("the patch lies in the data: every face should be sampled")

# A rigid move (translation, then rotation): the same surface as the library's on a patch made
# at the new pose, with no new factorization.
center = [-1.6, 0.7, 0.1]
surface.Center = center
out = t.fetch(surface, 25)
t.expect_same_surface(out, reference("moved", center, normal, 0.8, 800, "planar", "tangential", 25),
                      "translated patch")
normal = [1.0, -0.2, 0.4]
surface.Normal = normal
out = t.fetch(surface, 25)
t.expect_same_surface(out, reference("rotated", center, normal, 0.8, 800, "planar", "tangential", 25),
                      "rotated patch")
if t.field_value(out, "number_of_factorizations") != 1:
    raise AssertionError("a rigid move refactored: %g factorizations" % t.field_value(out, "number_of_factorizations"))
surface.UpdatePropertyInformation()
if surface.GetPropertyValue("NumberOfFactorizations") != 1:
    raise AssertionError("the information property NumberOfFactorizations is not 1")

# η, θmax and ε do not enter L + W: changing them re-runs the iterations with the same
# factorization; a smaller η moves the surface less in 3 iterations, and η back at 0.1 gives the
# library's surface again.
surface.MaxRotationAngle = 0.02
surface.MaxDihedralAngle = 1.2
surface.ConvergenceAngle = 1e-5
slower = t.fetch(surface, 3)
if t.max_point_distance(slower, reference("rotated_3", center, normal, 0.8, 800, "planar", "tangential", 3)) < 1e-3:
    raise AssertionError("a smaller Max Rotation Angle did not slow the first iterations")
if t.field_value(slower, "number_of_factorizations") != 1:
    raise AssertionError("changing η, θmax and ε refactored")
surface.MaxRotationAngle = 0.1
surface.MaxDihedralAngle = 1.5707963267948966
surface.ConvergenceAngle = 1e-6
t.expect_same_surface(t.fetch(surface, 25), reference("rotated", center, normal, 0.8, 800, "planar", "tangential", 25),
                      "η, θmax and ε back at their values")
if t.field_value(t.fetch(surface, 25), "number_of_factorizations") != 1:
    raise AssertionError("changing η, θmax and ε back refactored")

# Orthogonal alignment of a disk: a new alignment needs no factorization either; a new patch does.
surface.Alignment = "Orthogonal (seeding surface)"
out = t.fetch(surface, 25)
t.expect_same_surface(out, reference("orthogonal", center, normal, 0.8, 800, "planar", "orthogonal", 25),
                      "orthogonal")
if t.field_value(out, "number_of_factorizations") != 1:
    raise AssertionError("a new alignment refactored")
surface.PatchShape = "Disk"
surface.NumberOfFaces = 600
out = t.fetch(surface, 25)
t.expect_same_surface(out, reference("disk", center, normal, 0.8, 600, "disk", "orthogonal", 25),
                      "orthogonal disk")
if t.field_value(out, "number_of_factorizations") != 2:
    raise AssertionError("a new patch must be factored once")
flux = t.field_value(out, "normalized_flux")
if not flux > 0.95:
    raise AssertionError("orthogonal disk after 25 iterations has normalized flux %g" % flux)
print("Flow-Aligned Surface: all checks passed")
