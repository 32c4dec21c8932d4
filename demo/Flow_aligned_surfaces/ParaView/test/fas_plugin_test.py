"""What the plugin's test scripts share: loading the plugin, the reference program (the library
called directly), reading its files and comparing surfaces.

Every script is run by ctest as  pvbatch SCRIPT PLUGIN REFERENCE WORKDIR  (see CMakeLists.txt).
A failed check raises (pvbatch then exits non-zero; sys.exit() is not used, see
../shared/notes/ParaView-on-bookworm.md); success falls off the end.
"""
import os
import subprocess
import sys

from paraview.simple import LoadPlugin
from paraview import servermanager
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


class Setup:
    def __init__(self, ns):
        if len(sys.argv) < 4:
            raise RuntimeError("usage: pvbatch %s PLUGIN REFERENCE WORKDIR" % sys.argv[0])
        self.plugin, self.reference, self.workdir = sys.argv[1:4]
        os.makedirs(self.workdir, exist_ok=True)
        LoadPlugin(self.plugin, remote=False, ns=ns)
        self.filters = ns  # the plugin's filters, by proxy name

    def patch_in_cylinder_flow(self, data, faces, iterations):
        """Flow-Aligned Surface on the cylinder image `data` (point array `velocity`) with the
        tests' usual patch: upstream of the cylinder, 0.8 wide, tilted off the flow."""
        surface = self.filters["FlowAlignedSurface"](Input=data)
        surface.Velocity = ["POINTS", "velocity"]
        surface.Center = [-1.8, 0.5, 0.0]
        surface.Normal = [1.0, 0.3, 0.2]
        surface.Size = 0.8
        surface.NumberOfFaces = faces
        surface.NumberOfIterations = iterations
        return surface

    def path(self, name):
        return os.path.join(self.workdir, name)

    def run_reference(self, *args):
        """Runs the reference program; returns nothing, raises with its message on failure."""
        command = [self.reference] + [str(a) for a in args]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError("%s failed: %s" % (" ".join(command), done.stderr))

    def field(self):
        """The cylinder flow as a VTK image (written once per work directory)."""
        vti = self.path("cylinder.vti")
        if not os.path.exists(vti):
            self.run_reference("field", vti)
        return vti


def number_of_ranks():
    """The number of MPI ranks the filters run on (1 without MPI)."""
    return servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def expect_spread_over_ranks(out, what):
    """On several ranks: `out` (a filter's output) says that the filter sampled the input spread
    over all of them.  Nothing on one rank."""
    ranks = number_of_ranks()
    if ranks == 1:
        return
    for name in ["number_of_ranks", "number_of_ranks_with_cells"]:
        if field_value(out, name) != ranks:
            raise AssertionError("%s: %s is %g on %d ranks" % (what, name, field_value(out, name), ranks))
    print("%s: the input spread over %d ranks, %d exchanges" % (what, ranks, field_value(out, "number_of_exchanges")))


# The script of a ProgrammableSource (OutputDataSetType vtkUnstructuredGrid) that puts the image
# file %(file)r on one rank only (%(rank)r), as unstructured cells, for MPI runs: mode "all"
# (the other rank holds no cells), "none" (no rank holds cells) or "no velocity" (the piece has no
# velocity array).  Fill it in with flow_on_one_rank(rank, mode, file).
FLOW_ON_ONE_RANK = """
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkFiltersCore import vtkAppendFilter
mode = %(mode)r
rank = vtkMultiProcessController.GetGlobalController().GetLocalProcessId()
if rank == %(rank)r and mode != "none":
    reader = vtkXMLImageDataReader()
    reader.SetFileName(%(file)r)
    reader.Update()
    grid = vtkAppendFilter()
    grid.SetOutputPointsPrecision(1)  # double: the image's exact point coordinates
    grid.AddInputData(reader.GetOutput())
    grid.Update()
    self.GetOutput().ShallowCopy(grid.GetOutput())
    if mode == "no velocity":
        self.GetOutput().GetPointData().RemoveArray("velocity")
"""


def flow_on_one_rank(rank, mode, filename):
    """The ProgrammableSource script of FLOW_ON_ONE_RANK for `rank`, `mode` and the image `filename`."""
    return FLOW_ON_ONE_RANK % {"rank": rank, "mode": mode, "file": filename}


def read_polydata(filename):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(filename)
    reader.Update()
    return reader.GetOutput()


def fetch(proxy, time=None):
    """The output of `proxy` (at `time`, an iteration), brought to this process."""
    if time is None:
        proxy.UpdatePipeline()
    else:
        proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def field_value(data, name):
    array = data.GetFieldData().GetArray(name)
    if array is None:
        raise AssertionError("the output has no field data '%s'" % name)
    return array.GetValue(0)


def max_point_distance(a, b):
    """The largest distance between points of the same index, relative to a's bounding-box
    diagonal; raises when the two do not have the same points and triangles."""
    if a.GetNumberOfPoints() != b.GetNumberOfPoints() or a.GetNumberOfCells() != b.GetNumberOfCells():
        raise AssertionError("different sizes: %d points, %d cells against %d points, %d cells" % (
            a.GetNumberOfPoints(), a.GetNumberOfCells(), b.GetNumberOfPoints(), b.GetNumberOfCells()))
    worst = 0.0
    for i in range(a.GetNumberOfPoints()):
        p, q = a.GetPoint(i), b.GetPoint(i)
        worst = max(worst, sum((p[d] - q[d]) ** 2 for d in range(3)) ** 0.5)
    bounds = a.GetBounds()
    diagonal = sum((bounds[2 * d + 1] - bounds[2 * d]) ** 2 for d in range(3)) ** 0.5
    return worst / diagonal


def expect_same_surface(actual, expected, what, tolerance=1e-9):
    d = max_point_distance(actual, expected)
    if not d <= tolerance:
        raise AssertionError("%s: vertices differ by %g of the diagonal (tolerance %g)" % (what, d, tolerance))
    print("%s: same surface (largest difference %.2g of the diagonal)" % (what, d))


class Messages:
    """Collects the messages of VTK's output window (errors and warnings of the filters) while
    active; print() of the script also goes there in pvbatch, so it is restored after use."""

    def __enter__(self):
        self.previous = vtkOutputWindow.GetInstance()
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        return self

    def __exit__(self, *exc):
        vtkOutputWindow.SetInstance(self.previous)
        return False

    def text(self):
        return self.window.GetOutput()


class AbortOnce:
    """While active, sets AbortExecute on `proxy`'s algorithm (what ParaView's Abort button does)
    at the first progress event whose progress `when` accepts; `progress` holds that progress."""

    def __init__(self, proxy, when):
        self.algorithm, self.when, self.progress = proxy.GetClientSideObject(), when, []

    def __enter__(self):
        self.tag = self.algorithm.AddObserver("ProgressEvent", self._observe)
        return self

    def __exit__(self, *exc):
        self.algorithm.RemoveObserver(self.tag)
        return False

    def _observe(self, caller, event):
        if not self.progress and self.when(caller.GetProgress()):
            self.progress.append(caller.GetProgress())
            caller.SetAbortExecute(1)


# ---- helpers of the tests of Parametrize and Seed and Flow Texture ----

def fetch_port(proxy, port):
    """The output `port` of `proxy`, brought to this process."""
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy, idx=port)


def array_values(data, name, cells=False):
    """The values of the point (cell) array `name` of `data` as a list of tuples."""
    attributes = data.GetCellData() if cells else data.GetPointData()
    array = attributes.GetArray(name)
    if array is None:
        raise AssertionError("no %s array '%s'" % ("cell" if cells else "point", name))
    return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]


def expect_same_array(actual, expected, name, cells=False, tolerance=1e-9):
    """The arrays `name` of `actual` and `expected` agree within `tolerance` relative to the
    largest magnitude of the expected values."""
    a, e = array_values(actual, name, cells), array_values(expected, name, cells)
    if len(a) != len(e) or (a and len(a[0]) != len(e[0])):
        raise AssertionError("%s: %d tuples against %d expected" % (name, len(a), len(e)))
    scale = max([abs(x) for t in e for x in t] + [1e-300])
    worst = max([abs(x - y) for s, t in zip(a, e) for x, y in zip(s, t)] + [0.0]) / scale
    if not worst <= tolerance:
        raise AssertionError("%s: differs by %g relative (tolerance %g)" % (name, worst, tolerance))
    print("%s: same values (largest relative difference %.2g)" % (name, worst))


def expect_same_polylines(actual, expected, what, tolerance=1e-9):
    """The same polylines (cells, their points within `tolerance` of the bounding-box diagonal)."""
    if actual.GetNumberOfCells() != expected.GetNumberOfCells():
        raise AssertionError("%s: %d polylines against %d expected" % (
            what, actual.GetNumberOfCells(), expected.GetNumberOfCells()))
    for i in range(expected.GetNumberOfCells()):
        if actual.GetCell(i).GetNumberOfPoints() != expected.GetCell(i).GetNumberOfPoints():
            raise AssertionError("%s: polyline %d has %d points against %d expected" % (
                what, i, actual.GetCell(i).GetNumberOfPoints(), expected.GetCell(i).GetNumberOfPoints()))
    if expected.GetNumberOfPoints() > 0:
        expect_same_surface(actual, expected, what, tolerance)


def output_sizes(proxy, ports):
    """(points, cells) of each output port of `proxy` in `ports`."""
    return [(o.GetNumberOfPoints(), o.GetNumberOfCells()) for o in [fetch_port(proxy, k) for k in ports]]


def expect_error_keeps_outputs(proxy, ports, before, fragments, what):
    """Updating `proxy` reports an error containing every string of `fragments`, and its outputs
    keep the sizes `before` (an output_sizes() of the last good run)."""
    with Messages() as messages:
        after = output_sizes(proxy, ports)
    expect_message(messages, fragments + ["the previous output is kept"], what)
    if after != before:
        raise AssertionError("%s: the previous outputs were not kept (%s, before %s)" % (what, after, before))


def expect_message(messages, fragments, what):
    """The messages collected by `messages` (a Messages) contain every string of `fragments`."""
    text = messages.text()
    for fragment in fragments:
        if fragment not in text:
            raise AssertionError("%s: expected a message with '%s', got: %s" % (what, fragment, text))
    print("%s: %s" % (what, text.strip().splitlines()[-1][:200]))


def aligned_patch_reader(setup, name, patch):
    """The patch of `patch` (align's 11 arguments of paraview_reference) written by the library,
    read in ParaView."""
    from paraview.simple import XMLPolyDataReader
    vtp = setup.path(name + "_patch.vtp")
    setup.run_reference("align", setup.field(), vtp, *patch)
    return XMLPolyDataReader(FileName=[vtp])


def read_text_points(filename):
    """Points written one per line as `x y z`."""
    with open(filename) as f:
        return [tuple(float(x) for x in line.split()) for line in f if line.strip()]


def points_of(data):
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def distance(p, q):
    return sum((p[d] - q[d]) ** 2 for d in range(3)) ** 0.5
