"""The filters that take a surface or seed curves, on 2 MPI ranks (mpiexec -n 2 pvbatch --mpi,
see CMakeLists.txt), with that input spread over the ranks as well: its pieces are brought
together on rank 0 (shared points merged, line pieces joined into one polyline), and the result
is the library's for the whole input.  Then the flow on one rank only (rank 0, which runs the
algorithm, holds no cells; the filter says once that redistributing would spread the sampling)
and on none (a message, the previous output kept).  The serial test
scripts, run on 2 ranks as well, cover the flow spread over the ranks with whole surfaces."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import builtins  # paraview.simple's names include a max() for arrays
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
if t.number_of_ranks() != 2:
    raise AssertionError("run on 2 ranks (mpiexec -n 2 pvbatch --mpi), not %d" % t.number_of_ranks())
data = XMLImageDataReader(FileName=[setup.field()])

# A ProgrammableSource script: this rank's part of the polygonal data of FILE, split at x = SPLIT
# by cell centroid (rank 0 the cells below, rank 1 the others); the points that the two parts
# share are in both, and each part has its own point order, as pieces of a distributed surface do.
SPLIT_SCRIPT = """
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonCore import vtkPoints
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
reader = vtkXMLPolyDataReader()
reader.SetFileName(%(file)r)
reader.Update()
whole = reader.GetOutput()
points, ids = vtkPoints(), {}
points.SetDataTypeToDouble()
cells = vtkCellArray()
for c in range(whole.GetNumberOfCells()):
    cell = whole.GetCell(c)
    n = cell.GetNumberOfPoints()
    centroid = 0.0  # (no sum(): the programmable source's sum is numpy's)
    for k in range(n):
        centroid += whole.GetPoint(cell.GetPointId(k))[0] / n
    if (centroid < %(split)r) != (rank == 0):
        continue
    # Points in the reverse order of their first use: another order than the whole surface's.
    part = []
    for k in range(n):
        i = cell.GetPointId(k)
        if i not in ids:
            ids[i] = points.InsertNextPoint(whole.GetPoint(i))
        part.append(ids[i])
    cells.InsertNextCell(n)
    for i in part:
        cells.InsertCellPoint(i)
out = vtkPolyData()
out.SetPoints(points)
if whole.GetNumberOfPolys() > 0:
    out.SetPolys(cells)
else:
    out.SetLines(cells)
self.GetOutput().ShallowCopy(out)
"""


def split_source(filename, split):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = SPLIT_SCRIPT % {"file": filename, "split": split}
    return source


def values_by_point(data, name):
    """{point coordinates: value} of the point array `name`."""
    array = data.GetPointData().GetArray(name)
    return {data.GetPoint(i): array.GetValue(i) for i in range(data.GetNumberOfPoints())}


# 1. An aligned surface spread over both ranks, into Parametrize And Seed: rank 0 gets the whole
# surface (same points, same triangles) and the library's parametrization of it.
stream = [0.0, 1.6, 0.1, 1.0, 0.3, 0.2, 0.8, 800, "planar", "tangential", 25]
whole = setup.path("stream_patch.vtp")
setup.run_reference("align", setup.field(), whole, *stream)
prefix = setup.path("stream")
setup.run_reference("parametrize", setup.field(), prefix, *stream, "tangential", "default", 0.0, "centroid", 8,
                    0.1, 0, "delaunay")
expected = t.read_polydata(prefix + "_surface.vtp")
p = ParametrizeAndSeed(Input=data, Surface=split_source(whole, 0.0))
p.Velocity = ["POINTS", "velocity"]
p.NumberOfSeedCurves = 8
p.SeedPointSpacing = 0.1
out = t.fetch_port(p, 0)
t.expect_spread_over_ranks(out, "split surface")
if (out.GetNumberOfPoints(), out.GetNumberOfCells()) != (expected.GetNumberOfPoints(), expected.GetNumberOfCells()):
    raise AssertionError("split surface: %d points, %d triangles gathered, the whole surface has %d, %d" % (
        out.GetNumberOfPoints(), out.GetNumberOfCells(), expected.GetNumberOfPoints(), expected.GetNumberOfCells()))
for name in ["r", "s"]:
    got, want = values_by_point(out, name), values_by_point(expected, name)
    if set(got) != set(want):
        raise AssertionError("split surface: the gathered points are not the surface's")
    scale = builtins.max(abs(v) for v in want.values())
    worst = builtins.max(abs(got[x] - want[x]) for x in want) / scale
    if not worst <= 1e-9:
        raise AssertionError("split surface: %s differs from the library's by %g relative" % (name, worst))
    print("split surface: %s is the library's (largest relative difference %.2g)" % (name, worst))

# 2. A seed line spread over both ranks (its segments split at x = -2.5, the two parts sharing a
# point), into Stream Surface From Curve: one seed curve, and the library's surface of the line.
line = [(-2.9 + 0.04 * i, 0.3 + 0.06 * i, -0.5 + 0.05 * i) for i in range(21)]
seeds_txt = setup.path("line_seeds.txt")
with open(seeds_txt, "w") as f:
    f.write(" ".join(repr(c) for q in line for c in q) + "\n")
line_vtp = setup.path("line.vtp")
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
points, segments = vtkPoints(), vtkCellArray()
points.SetDataTypeToDouble()
for q in line:
    points.InsertNextPoint(q)
for i in range(20):
    segments.InsertNextCell(2)
    segments.InsertCellPoint(i)
    segments.InsertCellPoint(i + 1)
polyline = vtkPolyData()
polyline.SetPoints(points)
polyline.SetLines(segments)
writer = vtkXMLPolyDataWriter()
writer.SetFileName(line_vtp)
writer.SetInputData(polyline)
writer.SetDataModeToBinary()  # inline: ParaView 5.11 cannot parse appended data with the current expat
writer.Write()
reference_vtp = setup.path("line_surface.vtp")
setup.run_reference("stream", setup.field(), seeds_txt, reference_vtp, "forward_time")
surface = StreamSurfaceFromCurve(Input=data, Seeds=split_source(line_vtp, -2.5))
surface.Velocity = ["POINTS", "velocity"]
surface.MaxTime = 2.0
surface.TimeLineStep = 0.1
out = t.fetch(surface)
t.expect_spread_over_ranks(out, "split seed line")
curves = out.GetFieldData().GetAbstractArray("termination").GetNumberOfValues()
if curves != 1:
    raise AssertionError("split seed line: %d seed curves, expected the line as one" % curves)
t.expect_same_surface(out, t.read_polydata(reference_vtp), "split seed line")

# 3. The flow on one rank only, as unstructured cells (sampled through VTK's cell locator and
# interpolation functions, not the image's grid: so the library's surface only within 1e-6).  On
# rank 1 only, rank 0 (which integrates) holds no cells and every sample comes from rank 1; on
# rank 0 only, every sample is rank 0's own.  The two surfaces are the same to the last bit.  The
# filter says, once, that redistributing the data would spread the sampling.  Then on no rank: a
# message, the previous output kept.
pieces = ProgrammableSource(OutputDataSetType="vtkUnstructuredGrid")
surface.Input = pieces
on_rank = {}
for rank in [0, 1]:
    pieces.Script = t.flow_on_one_rank(rank, "all", setup.field())
    with t.Messages() as messages:
        on_rank[rank] = t.fetch(surface)
    if ("Redistribute DataSet" in messages.text()) != (rank == 0):
        raise AssertionError("flow on rank %d only: the note on redistributing the data %s:\n%s" % (
            rank, "is missing" if rank == 0 else "comes a second time", messages.text()))
    t.expect_same_surface(on_rank[rank], t.read_polydata(reference_vtp), "flow on rank %d only" % rank, 1e-6)
    if t.field_value(on_rank[rank], "number_of_ranks_with_cells") != 1:
        raise AssertionError("flow on rank %d only: %g ranks with cells" % (
            rank, t.field_value(on_rank[rank], "number_of_ranks_with_cells")))
t.expect_same_surface(on_rank[1], on_rank[0], "flow on rank 1 only against rank 0 only", 0.0)
pieces.Script = t.flow_on_one_rank(1, "none", setup.field())
with t.Messages() as messages:
    kept = t.fetch(surface)
t.expect_message(messages, ["Stream Surface From Curve", "the input has no cells on any of the 2 ranks",
                            "the previous output is kept"], "flow on no rank")
t.expect_same_surface(kept, on_rank[0], "flow on no rank: the previous output", 0.0)
print("inputs spread over 2 ranks: all checks passed")
