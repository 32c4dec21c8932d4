"""An OpenFOAM case with several times, as ParaView's reader gives it (a multiblock of the internal
mesh and the boundary patches, U as cell data), in pvbatch: the swirling channel of
openfoam_case.py with the swirl w = 2 at time 1 and w = 4 at time 2.  The filters' outputs have
the case's times; at time 1.5 they sample U interpolated linearly between the two times, which
is the cell value of the swirl w = 3 (U is linear in w): the `velocity` of Flow-Aligned Surface's
vertices, and the stream surface of Stream Surface From Curve, whose vertices keep the distance of
their seed point to the swirl's axis."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t
import openfoam_case

setup = t.Setup(globals())
N = 12
case = OpenFOAMReader(FileName=openfoam_case.write_case(setup.path("case"), n=N, swirls={1: 2.0, 2: 4.0}))
case.MeshRegions = ["internalMesh", "patch/inlet", "patch/outlet", "patch/walls"]
case.CellArrays = ["U"]
case.UpdatePipelineInformation()
if list(case.TimestepValues) != [1.0, 2.0]:
    raise AssertionError("the case's times are %s" % list(case.TimestepValues))

surface = FlowAlignedSurface(Input=case)
surface.Velocity = ["CELLS", "U"]
surface.Center, surface.Normal, surface.Size = [0.5, 0.7, 0.5], [0.0, 1.0, 0.2], 0.3
surface.NumberOfIterations = 20
out = t.fetch(surface, 1.5)
if list(surface.TimestepValues) != [1.0, 2.0] or t.field_value(out, "time") != 1.5:
    raise AssertionError("Flow-Aligned Surface: times %s, the output of time %g" % (
        list(surface.TimestepValues), t.field_value(out, "time")))
velocity = out.GetPointData().GetArray("velocity")
worst, checked = 0.0, 0
for i in range(out.GetNumberOfPoints()):
    p = out.GetPoint(i)
    cell = [min(int(c * N), N - 1) for c in p]
    if any(abs(c * N - round(c * N)) < 1e-6 for c in p):
        continue  # on a face between cells: either cell's value
    exact = openfoam_case.velocity(*[(c + 0.5) / N for c in cell], 3.0)
    worst = max(worst, max(abs(velocity.GetComponent(i, d) - exact[d]) for d in range(3)))
    checked += 1
if checked < 100 or not worst <= 1e-5:
    raise AssertionError("Flow-Aligned Surface at 1.5: U differs from the swirl w = 3 by %g (%d vertices)" % (worst, checked))
print("Flow-Aligned Surface at 1.5: U is the swirl w = 3 within %.2g on %d vertices" % (worst, checked))

line = Line(Point1=[0.0, 0.5, 0.6], Point2=[0.0, 0.5, 0.9], Resolution=6)
stream = StreamSurfaceFromCurve(case, Seeds=line)
stream.Velocity = ["POINTS", "U"]  # the reader's point values: continuous, so the radius is kept
stream.MaxTime = 0.8
out = t.fetch(stream, 1.5)
u = out.GetPointData().GetArray("u")
worst = max(abs(math.hypot(out.GetPoint(i)[1] - 0.5, out.GetPoint(i)[2] - 0.5) - (0.1 + u.GetValue(i)))
            for i in range(out.GetNumberOfPoints()))
if out.GetNumberOfCells() == 0 or not worst <= 1e-5:
    raise AssertionError("stream surface at 1.5: %d faces, a vertex %g off its seed's radius" % (out.GetNumberOfCells(), worst))
print("stream surface at 1.5: radii kept within %.2g on %d vertices" % (worst, out.GetNumberOfPoints()))
