"""The five filters of the plugin on one process and on several, on the CYLINDER data.

  pvbatch paraview_mpi_filters.py PLUGIN REFERENCE WORKDIR DATA FORM
  mpiexec --allow-run-as-root --oversubscribe -n P pvbatch --mpi paraview_mpi_filters.py \
      PLUGIN REFERENCE WORKDIR DATA FORM

PLUGIN, REFERENCE: the plugin and paraview_reference of a build (the tests' arguments); DATA: the
folder of CYLINDER_cells.vtk, CYLINDER_grid.vtk and CYLINDER_UNSTEADY_grid.pvd (../shared/data).
FORM says how the flow comes in, the same pipeline on any number of ranks:
  cells           CYLINDER_cells.vtk (185,344 hexahedra) by the legacy reader, spread over the
                  ranks by RedistributeDataSet
  image           CYLINDER_grid.vtk as a .vti (written into WORKDIR once), read piece-wise by the
                  ranks (XMLImageDataReader)
  unsteady_cells  CYLINDER_UNSTEADY_grid.pvd (34 images; a copy, below) through
                  RedistributeDataSet: the unstructured pieces of a time series
  unsteady_cells_cached
                  the same, with a Temporal Cache of every step after RedistributeDataSet: the
                  filters of the chain take the steps the first one pulled (the manual,
                  "Distributed Data (MPI)")
  unsteady_image  the same copy, each step's image read piece-wise
The time series is read from a copy written into WORKDIR once, each step uncompressed in appended
form: the XML reader decodes a step stored inline and compressed (the shared files) whole for
every piece asked of it, which would make each rank read longer than one process (the manual,
"Distributed Data (MPI)").

The tutorial's chain (doc: fas_paraview_tutorial): Flow-Aligned Surface with its defaults, Grow
Boundary, Parametrize And Seed (one seed curve), Stream Surface From Curve (both directions; on a
time series a path surface from a line, released at the first step and integrated to the view's
time, 0.1 s later), Flow Texture; on a steady flow at the surface's last iteration (100).  Each filter is created anew 5 times with its inputs up to
date and timed to the end of its update (a first Apply); prints the median, the number of
exchanges and the output's size, and writes each output's points into WORKDIR/FORM_P/FILTER.txt
for compare_mpi_outputs.py; at the end, the peak resident memory of every rank.
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "demo", "Flow_aligned_surfaces", "ParaView", "test"))
import fas_plugin_test as t

if len(sys.argv) != 6:
    raise RuntimeError("usage: pvbatch paraview_mpi_filters.py PLUGIN REFERENCE WORKDIR DATA FORM")
setup = t.Setup(globals())
data_folder, form = sys.argv[4], sys.argv[5]
ranks = t.number_of_ranks()
outputs = setup.path("%s_%d" % (form, ranks))
os.makedirs(outputs, exist_ok=True)


def image_file():
    """CYLINDER_grid.vtk as a .vti, which the XML reader reads piece-wise on every rank."""
    vti = setup.path("CYLINDER_grid.vti")
    if not os.path.exists(vti):
        from vtkmodules.vtkIOLegacy import vtkDataSetReader
        from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
        reader = vtkDataSetReader()
        reader.SetFileName(os.path.join(data_folder, "CYLINDER_grid.vtk"))
        reader.Update()
        writer = vtkXMLImageDataWriter()
        writer.SetInputData(reader.GetOutput())
        writer.SetFileName(vti + ".partial")
        writer.Write()
        os.replace(vti + ".partial", vti)
    return vti


def series_file():
    """CYLINDER_UNSTEADY_grid.pvd copied into WORKDIR once, each step's image uncompressed in
    appended form, so that each rank reads its piece of a step alone."""
    import xml.etree.ElementTree as ElementTree
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLImageDataWriter
    pvd = setup.path("CYLINDER_UNSTEADY_appended.pvd")
    if os.path.exists(pvd):
        return pvd
    source = os.path.join(data_folder, "CYLINDER_UNSTEADY_grid.pvd")
    collection = ElementTree.parse(source)
    os.makedirs(setup.path("CYLINDER_UNSTEADY_appended"), exist_ok=True)
    for step in collection.getroot().iter("DataSet"):
        reader = vtkXMLImageDataReader()
        reader.SetFileName(os.path.join(os.path.dirname(source), step.get("file")))
        reader.Update()
        name = os.path.join("CYLINDER_UNSTEADY_appended", os.path.basename(step.get("file")))
        writer = vtkXMLImageDataWriter()
        writer.SetInputData(reader.GetOutput())
        writer.SetDataModeToAppended()
        writer.EncodeAppendedDataOff()
        writer.SetCompressorTypeToNone()
        writer.SetFileName(setup.path(name))
        writer.Write()
        step.set("file", name)
    collection.write(pvd + ".partial")
    os.replace(pvd + ".partial", pvd)
    return pvd


def flow():
    """The flow as the filters get it, and its time steps (none for a steady flow)."""
    if form == "cells":
        cells = LegacyVTKReader(FileNames=[os.path.join(data_folder, "CYLINDER_cells.vtk")])
        return RedistributeDataSet(Input=cells), []
    if form == "image":
        return XMLImageDataReader(FileName=[image_file()]), []
    series = PVDReader(FileName=series_file())
    if form == "unsteady_cells":
        return RedistributeDataSet(Input=series), series.TimestepValues
    if form == "unsteady_cells_cached":
        cached = TemporalCache(Input=RedistributeDataSet(Input=series),
                               CacheSize=len(series.TimestepValues))
        return cached, series.TimestepValues
    if form == "unsteady_image":
        return series, series.TimestepValues
    raise RuntimeError("FORM is cells, image, unsteady_cells, unsteady_cells_cached or unsteady_image, "
                       "not %r" % form)


data, times = flow()
unsteady = len(times) > 0
# The view's time: on a time series about a third of the period after the first step; on a
# steady flow the last of Flow-Aligned Surface's 100 iterations (its time steps; the other
# filters have none and pass the time on).
view_time = times[0] + 0.1 if unsteady else 100.0
data.UpdatePipeline(view_time)


def update(proxy):
    proxy.UpdatePipeline(view_time)


def timed(name, make, port=0):
    """Creates the filter 5 times, each time updated and then deleted but the last; prints the
    median time, and writes the points of the last one's output `port`."""
    seconds = []
    for run in range(5):
        if run > 0:
            Delete(proxy)
        start = time.perf_counter()
        proxy = make()
        update(proxy)
        seconds.append(time.perf_counter() - start)
    out = servermanager.Fetch(proxy, idx=port)
    exchanges = 0
    if ranks > 1 and out.GetFieldData().GetArray("number_of_exchanges") is not None:
        exchanges = t.field_value(out, "number_of_exchanges")
    print("%-15s %-24s %d %8.3f %9d %8d" % (form, name, ranks, statistics.median(seconds), exchanges,
                                          out.GetNumberOfPoints()))
    lines = out.GetFieldData().GetArray("number_of_time_lines")
    if name == "StreamSurfaceFromCurve" and ranks > 1:
        backward = out.GetFieldData().GetArray("backward_number_of_time_lines")
        total = sum(lines.GetValue(i) for i in range(lines.GetNumberOfTuples()))
        if backward is not None:
            total += sum(backward.GetValue(i) for i in range(backward.GetNumberOfTuples()))
        print("%-15s %-24s %d time lines: %d, exchanges per time line: %.1f" % (
            form, name, ranks, total, exchanges / max(total, 1)))
    sys.stdout.flush()
    with open(os.path.join(outputs, name + ".txt"), "w") as f:
        for i in range(out.GetNumberOfPoints()):
            f.write("%.17g %.17g %.17g\n" % out.GetPoint(i))
    return proxy


print("form            filter                   ranks median_s exchanges   points")
velocity = ["POINTS", "velocity"]


def with_velocity(proxy):
    proxy.Velocity = velocity
    return proxy


surface = timed("FlowAlignedSurface", lambda: with_velocity(FlowAlignedSurface(Input=data)))
grown = timed("GrowBoundary", lambda: with_velocity(GrowBoundary(Input=data, Surface=surface)))


def seeds_on_grown():
    seeds = with_velocity(ParametrizeAndSeed(Input=data, Surface=grown))
    seeds.NumberOfSeedCurves = 1
    return seeds


seeds = timed("ParametrizeAndSeed", seeds_on_grown, port=1)


def stream_surface():
    if unsteady:
        line = Line(Point1=[0.55, 0.3, 0.05], Point2=[0.55, 0.3, 0.36], Resolution=30)
        path = with_velocity(StreamSurfaceFromCurve(Input=data, Seeds=line))
        path.SurfaceType = "Path Surface"
        path.StartTime = times[0]
        return path
    stream = with_velocity(StreamSurfaceFromCurve(Input=data, Seeds=OutputPort(seeds, 1)))
    stream.IntegrationDirection = "Both"
    return stream


stream = timed("StreamSurfaceFromCurve", stream_surface)


def texture():
    texture = with_velocity(FlowTexture(Input=data, Surface=stream))
    if unsteady:
        texture.PathSurface = 1
    return texture


timed("FlowTexture", texture)


def peak_memory_of_ranks():
    """The peak resident memory (VmHWM, MB) of every process running this script on this form
    (the ranks, all on this machine), rank 0's first."""
    mine = os.getpid()
    peaks = []
    for pid in [p for p in os.listdir("/proc") if p.isdigit()]:
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                words = f.read().split(b"\0")
            ranks_command = os.path.basename(words[0]).startswith(b"pvbatch")  # not mpiexec
            if not ranks_command or os.path.basename(sys.argv[0]).encode() not in b" ".join(words) or \
                    form.encode() not in words:
                continue
            with open("/proc/%s/status" % pid) as f:
                kb = next(int(line.split()[1]) for line in f if line.startswith("VmHWM:"))
        except (OSError, StopIteration):
            continue
        peaks.append((int(pid) != mine, kb / 1024.0))
    return [mb for _, mb in sorted(peaks)]


print("%-15s %-24s %d peak MB per rank: %s" % (form, "memory", ranks, ", ".join("%.0f" % mb for mb in peak_memory_of_ranks())))
