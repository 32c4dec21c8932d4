"""Flow-Aligned Surface on bad input: a clear message in the output window, no crash, and the
previous output kept."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())


# 1. A data set without a 3-component array (the Wavelet source has one scalar array).
wavelet = Wavelet()
with t.Messages() as m:
    surface = FlowAlignedSurface(Input=wavelet)
    surface.UpdatePipeline()
    out = servermanager.Fetch(surface)
t.expect_message(m, ["Flow-Aligned Surface", "no 3-component", "'RTData' (point data, 1 components)"],
                 "no velocity array")
if out.GetNumberOfPoints() != 0:
    raise AssertionError("an output without a velocity")
Delete(surface)

# 2. A good surface, then the patch moved outside the data: the message names the centre and
#    the data's bounds, and the previous surface stays.
data = XMLImageDataReader(FileName=[setup.field()])
surface = FlowAlignedSurface(Input=data)
surface.Velocity = ["POINTS", "velocity"]
surface.Center = [-1.8, 0.5, 0.0]
surface.Size = 0.8
surface.NumberOfFaces = 400
surface.NumberOfIterations = 5
good = t.fetch(surface, 5)
if good.GetNumberOfPoints() == 0:
    raise AssertionError("no surface from good input")
with t.Messages() as m:
    surface.Center = [20.0, 0.0, 0.0]
    kept = t.fetch(surface, 5)
t.expect_message(m, ["outside the input data set", "(20, 0, 0)", "previous output is kept"], "patch outside")
t.expect_same_surface(kept, good, "previous output kept after the patch left the data", 0.0)

# 3. Back into the data: it works again.
surface.Center = [-1.6, 0.5, 0.0]
again = t.fetch(surface, 5)
if again.GetNumberOfPoints() != good.GetNumberOfPoints() or t.field_value(again, "sampled_area_fraction") != 1:
    raise AssertionError("no surface after moving back into the data")

# 4. A patch partly out of the data: aligned where sampled, with a warning that says so.
with t.Messages() as m:
    surface.Center = [-2.9, 0.5, 0.0]
    partly = t.fetch(surface, 5)
t.expect_message(m, ["has no flow sample", "make it smaller"], "patch partly outside")
if not 0 < t.field_value(partly, "sampled_area_fraction") < 0.95:
    raise AssertionError("the sampled area fraction of a patch half out of the data")
face_flux = partly.GetCellData().GetArray("normalized_flux")
values = [face_flux.GetValue(i) for i in range(face_flux.GetNumberOfTuples())]
unsampled = [v for v in values if math.isnan(v)]
if not unsampled or any(not 0 <= v <= 1 for v in values if not math.isnan(v)):
    raise AssertionError("per-face flux of a patch half out of the data: NaN where unsampled, "
                         "else in [0, 1]; got %d NaN, range %s" % (len(unsampled), (min(values), max(values))))

# 5. Bad parameters: the library's message names the parameter.
with t.Messages() as m:
    surface.Center = [-1.6, 0.5, 0.0]
    surface.Normal = [0.0, 0.0, 0.0]
    kept = t.fetch(surface, 5)
t.expect_message(m, ["normal"], "zero normal")
if kept.GetNumberOfPoints() == 0:
    raise AssertionError("the previous output was not kept after a zero normal")
print("Flow-Aligned Surface, bad input: all checks passed")
