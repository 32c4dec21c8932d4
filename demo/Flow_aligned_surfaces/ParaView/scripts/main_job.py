"""The main job in ParaView, as a pvbatch script: the paper's workflow on the OpenFOAM cylinder
benchmark (../shared/data/CYLINDER_grid.vtk) with the plugin's filters.

    xvfb-run -a -s "-screen 0 1280x1024x24" pvbatch --force-offscreen-rendering \\
        main_job.py PLUGIN DATA OUTPUT_DIR

(PLUGIN: FlowAlignedSurfaces.so of the build tree, lib/paraview-5.11/plugins/FlowAlignedSurfaces/;
without a display drop xvfb-run and --force-offscreen-rendering is not needed for the files.)
It aligns a patch behind the cylinder tangentially (a stream surface) and orthogonally (a seeding
surface), cuts three seed curves out of the orthogonal one (iso-contours of its orthogonal
parametrization), integrates a stream surface from each, forward and backward, writes every
result as a VTP file and saves main_job.png: the aligned surfaces coloured by the per-face
normalized flux, the stream surfaces by their integration time, with the cylinder and colour
bars.
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

if len(sys.argv) != 4:
    raise RuntimeError("usage: pvbatch main_job.py PLUGIN DATA OUTPUT_DIR")
plugin, data_file, output_dir = sys.argv[1:4]
os.makedirs(output_dir, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())
# The VTP files with their data inline (base64, compressed), not appended as ParaView writes by
# default: ParaView 5.11's VTK cannot parse appended data with the expat of an up-to-date Debian
# bookworm, and every VTK reads inline data.
INLINE = {"DataMode": "Binary", "CompressorType": "ZLib"}

data = LegacyVTKReader(FileNames=[data_file])
# The obstacle: where the fluid mask 'inside' changes (the cylinder's wall).
cylinder = Contour(Input=data, ContourBy=["POINTS", "inside"], Isosurfaces=[0.5])

# The patch of the main job (scripts/run-main-job.sh --center 0.8,0.2,0.2 --size 0.15), across
# the flow behind the cylinder, aligned both ways.
surfaces = {}
for name, alignment, normal in [("tangential", "Tangential (stream surface)", [0.3, 1.0, 0.2]),
                                ("orthogonal", "Orthogonal (seeding surface)", [1.0, 0.3, 0.2])]:
    surface = FlowAlignedSurface(registrationName=name, Input=data)
    surface.Velocity = ["POINTS", "velocity"]
    surface.Center = [0.8, 0.2, 0.2]
    surface.Normal = normal
    surface.Size = 0.15
    surface.NumberOfFaces = 5000
    surface.Alignment = alignment
    surface.NumberOfIterations = 100
    surface.UpdatePipeline(100)
    SaveData(os.path.join(output_dir, name + ".vtp"), proxy=surface, **INLINE)
    result = servermanager.Fetch(surface)
    flux = result.GetFieldData().GetArray("normalized_flux").GetValue(0)
    iterations = result.GetFieldData().GetArray("iteration").GetValue(0)
    print("%s: normalized flux %.4f after %d iterations" % (name, flux, iterations))
    surfaces[name] = surface

# Seeding (the paper's Figure 4): seed curves on the orthogonal surface, and the stream surfaces
# they start, integrated both ways up to twice the patch size.
seeds = ParametrizeAndSeed(registrationName="seeds", Input=data, Surface=surfaces["orthogonal"])
seeds.Velocity = ["POINTS", "velocity"]
seeds.Parametrization = "Orthogonal"
seeds.NumberOfSeedCurves = 3
streams = StreamSurfaceFromCurve(registrationName="stream_surfaces", Input=data,
                                 Seeds=OutputPort(seeds, 1))
streams.Velocity = ["POINTS", "velocity"]
streams.IntegrationDirection = "Both"
streams.ArcLengthTimeLines = 1
streams.MaxLength = 0.3
streams.UpdatePipeline()
SaveData(os.path.join(output_dir, "seed_curves.vtp"), proxy=OutputPort(seeds, 1), **INLINE)
SaveData(os.path.join(output_dir, "stream_surfaces.vtp"), proxy=streams, **INLINE)
stream_output = servermanager.Fetch(streams)
print("stream surfaces: %d triangles from %d seed curves" % (
    stream_output.GetNumberOfCells(), servermanager.Fetch(seeds, idx=1).GetNumberOfCells()))

view = CreateView("RenderView")
view.ViewSize = [1200, 700]
view.OrientationAxesVisibility = 1
view.Background = [1, 1, 1]
view.UseColorPaletteForBackground = 0
wall = Show(cylinder, view)
wall.DiffuseColor = [0.6, 0.6, 0.6]
wall.AmbientColor = [0.6, 0.6, 0.6]
ColorBy(wall, None)
outline = Show(data, view)
outline.SetRepresentationType("Outline")
outline.AmbientColor = [0.2, 0.2, 0.2]
outline.DiffuseColor = [0.2, 0.2, 0.2]
for name, surface in surfaces.items():
    display = Show(surface, view)
    ColorBy(display, ("CELLS", "normalized_flux"))
flux_lut = GetColorTransferFunction("normalized_flux")
flux_lut.ApplyPreset("Cool to Warm", True)
flux_lut.RescaleTransferFunction(0.0, 1.0)
bar = GetScalarBar(flux_lut, view)
bar.Title = "normalized flux"
bar.ComponentTitle = ""
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
bar.Visibility = 1
Render(view)  # the first render resets the camera: place it after
curves = Show(OutputPort(seeds, 1), view)
ColorBy(curves, None)
curves.LineWidth = 4
curves.AmbientColor = [0, 0, 0]
curves.DiffuseColor = [0, 0, 0]
stream_display = Show(streams, view)
ColorBy(stream_display, ("POINTS", "IntegrationTime"))
time_lut = GetColorTransferFunction("IntegrationTime")
time_lut.ApplyPreset("Viridis (matplotlib)", True)
time_bar = GetScalarBar(time_lut, view)
time_bar.Title = "integration time (arc length)"
time_bar.ComponentTitle = ""
time_bar.TitleColor = [0, 0, 0]
time_bar.LabelColor = [0, 0, 0]
time_bar.WindowLocation = "Upper Right Corner"
time_bar.Visibility = 1
stream_display.Opacity = 0.85
view.CameraPosition = [0.42, -0.32, 0.62]
view.CameraFocalPoint = [0.78, 0.2, 0.18]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 30
Render(view)
picture = os.path.join(output_dir, "main_job.png")
SaveScreenshot(picture, view, ImageResolution=[1200, 700])
if not os.path.getsize(picture) > 10000:
    raise RuntimeError("the screenshot %s is (nearly) empty" % picture)
Delete(view)  # a live view at exit gives GLXBadContext
del view
print("wrote " + output_dir)
