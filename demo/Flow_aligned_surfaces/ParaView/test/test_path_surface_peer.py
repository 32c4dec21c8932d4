"""Path surfaces beside ParaView's own particle tracer on real unsteady CFD data (pvbatch): the
vortex-shedding cylinder CYLINDER_UNSTEADY_grid.pvd (../shared/data), a seed line across the wake
released at the first time step and integrated over 12 steps.  ParaView's ParticlePath traces the
path lines of the line's points (its own integrator, VTK's interpolation in space and time); every
point of them must lie on the path surface of Stream Surface From Curve (Surface Type Path
Surface): median distance at most 1e-4 of the domain's diagonal, largest at most 1e-3.

    pvbatch test_path_surface_peer.py PLUGIN REFERENCE WORKDIR SERIES.pvd
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance

setup = t.Setup(globals())
data = PVDReader(FileName=sys.argv[4])
times = data.TimestepValues
end = times[12]
line = Line(Point1=[1.0, 0.1, 0.2], Point2=[1.0, 0.3, 0.2], Resolution=10)

tracer = ParticlePath(Input=data, SeedSource=line)
tracer.SelectInputVectors = ["POINTS", "velocity"]
tracer.TerminationTime = end
paths = t.fetch(tracer, end)

path = StreamSurfaceFromCurve(Input=data, Seeds=line)
path.Velocity = ["POINTS", "velocity"]
path.SurfaceType = "Path Surface"
path.StartTime = times[0]
surface = t.fetch(path, end)
if surface.GetNumberOfCells() == 0 or t.field_value(surface, "number_of_lost_particles") != 0:
    raise AssertionError("path surface: %d faces, %g particles lost" % (
        surface.GetNumberOfCells(), t.field_value(surface, "number_of_lost_particles")))

ages = paths.GetPointData().GetArray("ParticleAge")
if paths.GetNumberOfPoints() != 11 * 13 or abs(ages.GetRange()[1] - (end - times[0])) > 1e-6:  # float32 ages
    raise AssertionError("ParticlePath: %d points, ages up to %g" % (paths.GetNumberOfPoints(), ages.GetRange()[1]))
distance = vtkImplicitPolyDataDistance()
distance.SetInput(surface)
d = sorted(abs(distance.EvaluateFunction(paths.GetPoint(i))) for i in range(paths.GetNumberOfPoints()))
b = data.GetDataInformation().GetBounds()
diagonal = math.sqrt(sum((b[2 * i + 1] - b[2 * i]) ** 2 for i in range(3)))
median, largest = d[len(d) // 2] / diagonal, d[-1] / diagonal
if not (median <= 1e-4 and largest <= 1e-3):
    raise AssertionError("ParticlePath's points off the path surface: median %g, largest %g of the diagonal" % (median, largest))
print("ParticlePath's %d points on the path surface: median %.2g, largest %.2g of the diagonal" % (len(d), median, largest))
