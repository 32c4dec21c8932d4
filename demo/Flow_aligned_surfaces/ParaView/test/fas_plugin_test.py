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
