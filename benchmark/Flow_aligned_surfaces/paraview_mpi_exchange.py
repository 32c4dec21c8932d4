"""The cost per iteration of Flow-Aligned Surface's sample exchange under MPI.

  mpiexec --allow-run-as-root --oversubscribe -n P pvbatch --mpi paraview_mpi_exchange.py \
      PLUGIN REFERENCE WORKDIR [FACES ...]

PLUGIN, REFERENCE: the plugin and paraview_reference of a build (the test's arguments).  The
cylinder flow image (61 x 41 x 21 points) is read piece-wise by the ranks; a tangential patch
across the plane where the pieces meet is aligned for up to 10 iterations (fewer when it converges), 5 times per size (each
time from a slightly moved patch, so every iteration is computed anew: the factorization
stays).  Prints per size the medians over the 5 runs of the filter's own figures:
exchange_ms_per_iteration (points collected, broadcast, sampled on every rank, reduced to rank
0) and step_ms_per_iteration (the library's step() on rank 0).
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "demo", "Flow_aligned_surfaces", "ParaView", "test"))
import fas_plugin_test as t
from paraview import servermanager

setup = t.Setup(globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if ranks < 2:
    raise RuntimeError("run on 2 ranks or more: one process exchanges nothing")
sizes = [int(a) for a in sys.argv[4:]] or [800, 5000, 20000, 80000]
reader = XMLImageDataReader(FileName=[setup.field()])
print("ranks faces iterations exchange_ms step_ms exchange/step sampling_ranks")
for faces in sizes:
    surface = FlowAlignedSurface(Input=reader)
    surface.Velocity = ["POINTS", "velocity"]
    surface.Normal = [1.0, 0.3, 0.2]
    surface.Size = 0.8
    surface.NumberOfFaces = faces
    surface.NumberOfIterations = 10
    exchange, step, sampling = [], [], 0
    for run in range(5):
        surface.Center = [0.0, 1.6 + 0.001 * run, 0.1]
        out = t.fetch(surface, 10)
        step.append(t.field_value(out, "step_ms_per_iteration"))
        exchange.append(t.field_value(out, "exchange_ms_per_iteration"))
        iterations = int(t.field_value(out, "iterations_computed"))
        sampling = int(t.field_value(out, "number_of_sampling_ranks"))
    e = statistics.median(exchange)
    s = statistics.median(step)
    print("%d %d %d %.3f %.3f %.2f %d" % (ranks, faces, iterations, e, s, e / s, sampling))
    Delete(surface)
