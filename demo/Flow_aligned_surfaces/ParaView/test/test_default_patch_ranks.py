"""Flow-Aligned Surface's default patch does not depend on the number of ranks: created with its
defaults on an input that already has data (as in the GUI, where the panel takes its defaults from
the input), the surface on 2 ranks, each holding a piece of the image, is the surface of one
process to 1e-9 of its diagonal.  ctest runs this script twice in the same WORKDIR: on one process
(paraview_default_patch, which writes the surface) and on 2 ranks (paraview_default_patch_mpi,
which compares with it).
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
ranks = t.number_of_ranks()
ITERATIONS = 5
reader = XMLImageDataReader(FileName=[setup.field()])
reader.UpdatePipeline()
surface = FlowAlignedSurface(Input=reader)
surface.NumberOfIterations = ITERATIONS
out = t.fetch(surface, ITERATIONS)
if out.GetNumberOfCells() < 1000:
    raise AssertionError("the defaults on %d rank(s): %d faces" % (ranks, out.GetNumberOfCells()))
one_process = setup.path("default_patch_one_process.vtp")
if ranks == 1:
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    writer = vtkXMLPolyDataWriter()
    writer.SetDataModeToBinary()  # inline: readable by ParaView's VTK with any expat
    writer.SetInputData(out)
    writer.SetFileName(one_process)
    writer.Write()
    print("one process: the default patch's surface, %d faces, written" % out.GetNumberOfCells())
else:
    if not os.path.exists(one_process):
        raise AssertionError("run paraview_default_patch (one process) first: %s is missing" % one_process)
    t.expect_same_surface(out, t.read_polydata(one_process), "the defaults on %d ranks" % ranks)
    print("%d ranks: the default patch's surface is the one of one process" % ranks)
