"""The cost of Stream Surface From Curve's sample exchanges under MPI.

  pvbatch paraview_mpi_stream_surface.py PLUGIN REFERENCE WORKDIR                 (1 process)
  mpiexec --allow-run-as-root --oversubscribe -n P pvbatch --mpi paraview_mpi_stream_surface.py \
      PLUGIN REFERENCE WORKDIR

PLUGIN, REFERENCE: the plugin and paraview_reference of a build (the tests' arguments).  The
cylinder flow image (61 x 41 x 21 points, read piece-wise by the ranks) and a seed line across
the flow whose surface passes the cylinder and crosses the plane where the pieces meet.  A
particle's next position depends on its last sample: on several ranks the library asks for the
samples of a time line's particles stage by stage, one exchange per Runge-Kutta stage (and per
stage of the particles it re-integrates from the seed where the front stretches).  Prints the median over 5 updates of the filter's wall time, and the
number of exchanges; the difference to the 1-process time, divided by the exchanges, is the
cost of one.
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "demo", "Flow_aligned_surfaces", "ParaView", "test"))
import fas_plugin_test as t

setup = t.Setup(globals())
reader = XMLImageDataReader(FileName=[setup.field()])
line = Line(Point1=[-2.5, 0.3, -0.5], Point2=[-2.5, 1.5, 0.5], Resolution=20)
surface = StreamSurfaceFromCurve(Input=reader, Seeds=line)
surface.Velocity = ["POINTS", "velocity"]
seconds = []
for run in range(5):
    line.Point1 = [-2.5, 0.3 + 0.001 * run, -0.5]  # a new update each time
    start = time.perf_counter()
    out = t.fetch(surface)
    seconds.append(time.perf_counter() - start)
ranks = t.number_of_ranks()
exchanges = t.field_value(out, "number_of_exchanges") if ranks > 1 else 0
print("ranks points exchanges median_s")
print("%d %d %d %.3f" % (ranks, out.GetNumberOfPoints(), exchanges, statistics.median(seconds)))
