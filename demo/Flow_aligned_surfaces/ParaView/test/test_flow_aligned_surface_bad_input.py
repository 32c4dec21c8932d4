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
t.expect_message(m, ["outside the Input", "Center (20, 0, 0)", "previous output is kept"], "patch outside")
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

# 5. Properties out of range: the message names the panel's property and its range, nothing is
#    clamped silently, and the previous output stays.
for prop, value, words in [
        ("Normal", [0.0, 0.0, 0.0], ["the property Normal", "non-zero"]),
        ("Size", -0.5, ["the property Size is -0.5", "> 0"]),
        ("NumberOfFaces", 100000000, ["the property Number Of Faces is 1e+08", "from 2 to 10,000,000"]),
        ("NumberOfFaces", -5, ["the property Number Of Faces is -5", "from 2 to 10,000,000"]),
        ("MaxRotationAngle", 0.0, ["the property Max Rotation Angle is 0", "(0, pi]"]),
        ("NumberOfIterations", -1, ["the property Number Of Iterations is -1"])]:
    surface.Center = [-1.6, 0.5, 0.0]
    surface.Normal = [1.0, 0.3, 0.2]
    good = t.fetch(surface, 5)
    with t.Messages() as m:
        surface.SetPropertyWithName(prop, value)
        kept = t.fetch(surface, 5)
    t.expect_message(m, words + ["previous output is kept"], "%s = %s" % (prop, value))
    t.expect_same_surface(kept, good, "previous output kept after %s = %s" % (prop, value), 0.0)
    surface.SetPropertyWithName(prop, {"Normal": [1.0, 0.3, 0.2], "Size": 0.8, "NumberOfFaces": 400,
                                       "MaxRotationAngle": 0.1, "NumberOfIterations": 5}[prop])

# 6. Abort (what ParaView's Abort button sets, here from a progress observer): the filter stops
#    after the iteration in progress, says so, shows the last computed iteration, and the next
#    time step asked for goes on from there.
surface.Center = [-1.7, 0.5, 0.0]
surface.NumberOfIterations = 40
surface.ConvergenceAngle = 0.0
with t.AbortOnce(surface, lambda progress: progress > 0.3) as abort, t.Messages() as m:
    cancelled = t.fetch(surface, 40)
aborts = abort.progress
t.expect_message(m, ["cancelled after iteration", "goes on from there"], "abort")
stopped_at = t.field_value(cancelled, "iteration")
if not 5 <= stopped_at < 20 or cancelled.GetNumberOfPoints() == 0:
    raise AssertionError("abort at progress %s: the output shows iteration %g" % (aborts, stopped_at))
resumed = t.fetch(surface, 39)  # the next time step asked for (Play in the GUI)
if t.field_value(resumed, "iteration") != 39:
    raise AssertionError("after an abort, the next update reaches iteration %g" % t.field_value(resumed, "iteration"))
print("Flow-Aligned Surface, bad input: all checks passed (abort stopped at iteration %g)" % stopped_at)
