"""Flow-Aligned Surface's default patch does not depend on the number of ranks nor on the view's
time: created with its defaults on an input that already has data (as in the GUI, where the panel
takes its defaults from the input), the surface on 2 ranks, each holding a piece of the image, is
the surface of one process to 1e-9 of its diagonal; on a time series whose data at hand are a
later step than the first, the same holds for the surface followed to that step.  ctest runs this
script twice in the same WORKDIR: on one process (paraview_default_patch, which writes the
surfaces) and on 2 ranks (paraview_default_patch_mpi, which compares with them).
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
ranks = t.number_of_ranks()
ITERATIONS = 5


def same_on_every_number_of_ranks(out, name):
    if out.GetNumberOfCells() < 1000:
        raise AssertionError("%s on %d rank(s): %d faces" % (name, ranks, out.GetNumberOfCells()))
    one_process = setup.path(name + "_one_process.vtp")
    if ranks == 1:
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        writer = vtkXMLPolyDataWriter()
        writer.SetDataModeToBinary()  # inline: readable by ParaView's VTK with any expat
        writer.SetInputData(out)
        writer.SetFileName(one_process)
        writer.Write()
        print("%s on one process: %d faces, written" % (name, out.GetNumberOfCells()))
        return
    if not os.path.exists(one_process):
        raise AssertionError("run paraview_default_patch (one process) first: %s is missing" % one_process)
    t.expect_same_surface(out, t.read_polydata(one_process), "%s on %d ranks" % (name, ranks))
    print("%s on %d ranks: the surface of one process" % (name, ranks))


reader = XMLImageDataReader(FileName=[setup.field()])
reader.UpdatePipeline()
surface = FlowAlignedSurface(Input=reader)
surface.NumberOfIterations = ITERATIONS
same_on_every_number_of_ranks(t.fetch(surface, ITERATIONS), "default_patch")

pvd = setup.path("swirl.pvd")
if not os.path.exists(pvd):
    setup.run_reference("unsteady_field", pvd)
series = PVDReader(FileName=pvd)
later = series.TimestepValues[2]
series.UpdatePipeline(later)  # the data at hand: a later step than the first
followed = FlowAlignedSurface(Input=series)
same_on_every_number_of_ranks(t.fetch(followed, later), "default_patch_followed")
