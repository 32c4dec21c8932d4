"""The filters on data as ParaView gives it: an OpenFOAM case read by ParaView's own OpenFOAMReader
with its boundary patches (a multiblock: the internal mesh and three polygonal patches) and U as
cell data and as the point data the reader interpolates from it.

- Flow-Aligned Surface applied with its defaults makes ONE polydata surface (not one per block),
  converged, with one note that the patches were left out and no warning;
- the Velocity selector's association is what is sampled: the surface's point velocities are,
  at every point, what VTK's probe filter (a peer) gives on the internal mesh for the cell array
  (constant per cell) or for the point array (interpolated), and the two surfaces differ;
- a multiblock without 3D cells (the patches alone) is refused with a message naming the Input.
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t
import openfoam_case

from vtkmodules.vtkFiltersCore import vtkProbeFilter
from vtkmodules.vtkCommonDataModel import vtkPolyData

setup = t.Setup(globals())
ranks = t.number_of_ranks()
case = openfoam_case.write_case(setup.path("swirl"), n=12)
reader = OpenFOAMReader(FileName=case)
reader.MeshRegions = ["internalMesh", "patch/inlet", "patch/outlet", "patch/walls"]
reader.CellArrays = ["U"]
reader.UpdatePipeline(1.0)

# 1. The defaults on the whole multiblock: one converged surface, one note, no warning.
with t.Messages() as m:
    surface = FlowAlignedSurface(Input=reader)
    out = t.fetch(surface, 100)
text = m.text()
if out.GetClassName() != "vtkPolyData" or out.GetNumberOfCells() < 1000:
    raise AssertionError("the defaults on an OpenFOAM multiblock: %s with %d cells" % (
        out.GetClassName(), out.GetNumberOfCells()))
if ranks == 1 and "3 blocks without 3D cells (boundary patches) left out of the flow" not in text:
    raise AssertionError("no note about the boundary patches: %s" % text)
if "Warning" in text or "ERR" in text:
    raise AssertionError("the defaults on an OpenFOAM multiblock gave a warning or an error: %s" % text)
flux, sampled = t.field_value(out, "normalized_flux"), t.field_value(out, "sampled_area_fraction")
if not (flux <= 0.02 and sampled >= 0.95):
    raise AssertionError("the defaults on an OpenFOAM multiblock: flux %g, sampled area %g" % (flux, sampled))
print("OpenFOAM multiblock, defaults: one surface of %d faces, flux %g, sampled %g, velocity %s" % (
    out.GetNumberOfCells(), flux, sampled, list(surface.Velocity)))


# 2. The association chosen is the one sampled, checked against VTK's probe filter.
def internal_mesh():
    data = servermanager.Fetch(reader)
    blocks = data.NewIterator()
    blocks.InitTraversal()
    while not blocks.IsDoneWithTraversal():
        block = blocks.GetCurrentDataObject()
        if block.GetClassName() == "vtkUnstructuredGrid":
            return block
        blocks.GoToNextItem()
    raise AssertionError("the reader gave no internal mesh")


def probed(mesh, points_of, cells):
    """VTK's probe of U (cell or point data only) at the points of `points_of`."""
    source = mesh.NewInstance()
    source.ShallowCopy(mesh)
    (source.GetPointData() if cells else source.GetCellData()).RemoveArray("U")
    points = vtkPolyData()
    points.SetPoints(points_of.GetPoints())
    probe = vtkProbeFilter()
    probe.SetInputData(points)
    probe.SetSourceData(source)
    probe.Update()
    return probe.GetOutput()


def expect_sampled_as_probed(association):
    surface.Velocity = [association, "U"]
    result = t.fetch(surface, 100)
    probe = probed(internal_mesh(), result, association == "CELLS")
    mask = probe.GetPointData().GetArray("vtkValidPointMask")
    expected, actual = probe.GetPointData().GetArray("U"), result.GetPointData().GetArray("velocity")
    same = compared = 0
    for i in range(result.GetNumberOfPoints()):
        if not mask.GetValue(i):
            continue
        compared += 1
        if max(abs(actual.GetComponent(i, c) - expected.GetComponent(i, c)) for c in range(3)) < 1e-5:
            same += 1
    # A point on a face between two cells may be given to either of them (cell data differ there).
    if compared < 0.95 * result.GetNumberOfPoints() or same < 0.98 * compared:
        raise AssertionError("%s U: %d of %d points sampled as VTK's probe filter samples them (%d probed)" % (
            association, same, compared, result.GetNumberOfPoints()))
    print("%s U: %d of %d points as VTK's probe filter" % (association, same, compared))
    return result


if ranks == 1:  # the probe needs the whole mesh on this process
    on_cells = expect_sampled_as_probed("CELLS")
    on_points = expect_sampled_as_probed("POINTS")
    moved = max(t.distance(on_cells.GetPoint(i), on_points.GetPoint(i)) for i in range(on_cells.GetNumberOfPoints()))
    if not moved > 1e-4:
        raise AssertionError("the cell and the point array of U gave the same surface (largest distance %g)" % moved)
    print("cell and point U: surfaces up to %g apart" % moved)

# 3. Only the boundary patches: no volume to sample in, said so with the Input named.
# A reader of its own: ParaView 5.11's OpenFOAM reader hangs on 2 MPI ranks when its MeshRegions
# change after an update (so does MergeBlocks on it), whatever is downstream.
patches = OpenFOAMReader(FileName=case)
patches.MeshRegions = ["patch/inlet", "patch/outlet", "patch/walls"]
patches.CellArrays = ["U"]
surface.Input = patches
surface.Velocity = ["CELLS", "U"]
with t.Messages() as m:
    kept = t.fetch(surface, 100)
if ranks == 1:
    t.expect_message(m, ["the Input (vtkMultiBlockDataSet) has no block with 3D cells", "previous output is kept"],
                     "patches only")
else:
    t.expect_message(m, ["no cells on any of the", "previous output is kept"], "patches only")
if kept.GetNumberOfCells() == 0:
    raise AssertionError("the previous output was not kept")
print("OpenFOAM case: all checks passed")
