"""The manual's ParaView tutorial (page fas_paraview_tutorial) as one script: every block between
two `# [name]` lines is the Python beside the GUI step of that name in the manual, which shows
these very lines.  The test paraview_tutorial_gui runs this file in the ParaView GUI (--script)
and takes its screenshots between the blocks, so that what the manual shows is what was run.

    pvpython tutorial.py PLUGIN CYLINDER_grid.vtk [CASE.foam [CYLINDER_UNSTEADY_grid.pvd]]

(PLUGIN: FlowAlignedSurfaces.so, lib/paraview-5.11/plugins/FlowAlignedSurfaces/ of the build tree;
CASE.foam: an OpenFOAM case with U, "-" for none; without it the OpenFOAM part is left out, and
without the .pvd the unsteady part.)  The textures are
written into the current folder.  In the GUI's Python shell (View > Python Shell) the blocks can
be pasted one by one after setting `cylinder_file` and `case_file`."""
from paraview.simple import *

import os
import sys

# Set by the GUI test: a function called after each block with the block's name.
step = globals().get("step", lambda name: None)
if "cylinder_file" not in globals():  # run as a script, not by the GUI test
    if len(sys.argv) not in (3, 4, 5):
        raise SystemExit("usage: pvpython tutorial.py PLUGIN CYLINDER_grid.vtk [CASE.foam [SERIES.pvd]]")
    LoadPlugin(sys.argv[1], remote=False, ns=globals())
    cylinder_file = sys.argv[2]
    case_file = sys.argv[3] if len(sys.argv) >= 4 and sys.argv[3] != "-" else None
    unsteady_file = sys.argv[4] if len(sys.argv) == 5 else None
    texture_file = os.path.abspath("flow_texture.png")
    path_texture_file = os.path.abspath("path_surface_texture.png")

# [open]
data = LegacyVTKReader(FileNames=[cylinder_file])  # File > Open, then Apply
view = GetActiveViewOrCreate("RenderView")
Show(data, view)  # an image is drawn as its outline
# The obstacle, for orientation: Filters > Contour, Contour By "inside" (0 in the solid) at 0.5.
cylinder = Contour(Input=data, ContourBy=["POINTS", "inside"], Isosurfaces=[0.5])
ColorBy(Show(cylinder, view), None)
view.CameraPosition = [-0.6, -2.2, 1.6]  # the mouse: the channel seen from above the side
view.CameraFocalPoint = [1.25, 0.2, 0.2]
view.CameraViewUp = [0, 0, 1]
Render(view)
# [open]
step("open")

# [apply]
surface = FlowAlignedSurface(Input=data)  # Filters > Flow-Aligned Surfaces > Flow-Aligned Surface
shown = Show(surface, view)  # Apply, with the defaults
ColorBy(shown, ("CELLS", "normalized_flux"))  # the colour selector of the toolbar
shown.SetScalarBarVisibility(view, True)
# 0 (aligned) to 1 (across the flow): the GUI's plugin sets this range; pvpython sets it here.
GetColorTransferFunction("normalized_flux").RescaleTransferFunction(0.0, 1.0)
view.CameraPosition = [0.25, -0.55, 0.75]  # the mouse: closer to the cylinder and the patch
view.CameraFocalPoint = [0.7, 0.2, 0.2]
view.CameraViewUp = [0, 0, 1]
Render(view)
# [apply]
step("apply")

# [drag]
# Dragging the plane widget's centre and its normal arrow sets these two properties.
# Here: in front of the cylinder and beside its axis, where the flow parts around it.
surface.Center = [0.35, 0.25, 0.2]
surface.Normal = [0.0, 1.0, 0.3]
Render(view)  # Apply (or Auto Apply)
# [drag]
step("drag")

# [play]
scene = GetAnimationScene()  # the VCR toolbar: the iterations are time steps 0, 1, ...
scene.UpdateAnimationUsingDataTimeSteps()
scene.Play()
Hide3DWidgets(proxy=surface)  # Properties: Show Plane off
view.CameraPosition = [0.05, -0.3, 0.55]  # the mouse: closer
view.CameraFocalPoint = [0.42, 0.22, 0.2]
Render(view)
# [play]
step("play")

# [grow]
grown = GrowBoundary(Input=data, Surface=surface)  # Filters > Flow-Aligned Surfaces > Grow Boundary
grown_shown = Show(grown, view)
ColorBy(grown_shown, ("POINTS", "growth_step"))
Hide(surface, view)
Render(view)
# [grow]
step("grow")

# [seed]
seeds = ParametrizeAndSeed(Input=data, Surface=grown)  # ... > Parametrize And Seed
# One iso-line of r across the flow (10 by default: on a stream surface they would all start the
# same stream surface).
seeds.NumberOfSeedCurves = 1
seeded = Show(OutputPort(seeds, 0), view)  # port Surface, coloured by r
ColorBy(seeded, ("POINTS", "r"))
curves = Show(OutputPort(seeds, 1), view)  # port Seed Curves
ColorBy(curves, None)
curves.DiffuseColor = curves.AmbientColor = [0, 0, 0]
curves.LineWidth = 3
Show(OutputPort(seeds, 2), view)  # port Seed Points
Hide(grown, view)
Render(view)
# [seed]
step("seed")

# [stream]
stream = StreamSurfaceFromCurve(Input=data, Seeds=OutputPort(seeds, 1))  # Seeds: port Seed Curves
stream.IntegrationDirection = "Both"  # upstream and downstream of the seed curve
stream_shown = Show(stream, view)
ColorBy(stream_shown, ("POINTS", "IntegrationTime"))
Hide(OutputPort(seeds, 0), view)
Hide(OutputPort(seeds, 2), view)
view.CameraPosition = [0.3, -1.3, 1.2]  # the mouse: the whole stream surface
view.CameraFocalPoint = [1.0, 0.2, 0.2]
Render(view)
# [stream]
step("stream")

# [texture]
texture = FlowTexture(Input=data, Surface=stream)  # ... > Flow Texture
SaveData(texture_file, proxy=OutputPort(texture, 1))  # File > Save Data: port Texture as PNG
textured = Show(OutputPort(texture, 0), view)  # port Textured Surface
ColorBy(textured, None)
textured.DiffuseColor = [1, 1, 1]
textured.Texture = CreateTexture(texture_file)  # Properties > Texture > Load
Hide(stream, view)
Hide(OutputPort(seeds, 1), view)
Render(view)
# [texture]
step("texture")

if case_file:
    # [openfoam_open]
    for source in GetSources().values():  # the eye icons: the cylinder's pipeline hidden
        Hide(source, view)
    case = OpenFOAMReader(FileName=case_file)  # File > Open > case.foam
    case.MeshRegions = ["internalMesh", "patch/inlet", "patch/outlet", "patch/walls"]  # Mesh Regions
    case.CellArrays = ["U"]
    case_shown = Show(case, view)  # Apply
    case_shown.SetRepresentationType("Outline")  # the walls would hide what is inside
    ResetCamera(view)
    Render(view)
    # [openfoam_open]
    step("openfoam_open")

    # [openfoam_surface]
    foam_surface = FlowAlignedSurface(Input=case)  # the whole multiblock: mesh and patches
    foam_surface.Velocity = ["CELLS", "U"]  # or ["POINTS", "U"], which the reader interpolates
    foam_shown = Show(foam_surface, view)
    ColorBy(foam_shown, ("CELLS", "normalized_flux"))
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.GoToLast()  # the time controls' "Last Frame"
    # [openfoam_surface]
    step("openfoam_surface")

    # [openfoam_stream]
    foam_seeds = ParametrizeAndSeed(case, Surface=foam_surface)  # the flow first, see the text
    foam_seeds.Velocity = ["CELLS", "U"]  # every filter's Velocity selector: U
    foam_seeds.NumberOfSeedCurves = 1
    foam_curves = Show(OutputPort(foam_seeds, 1), view)
    ColorBy(foam_curves, None)
    foam_curves.DiffuseColor = foam_curves.AmbientColor = [0, 0, 0]
    foam_curves.LineWidth = 3
    foam_stream = StreamSurfaceFromCurve(Input=case, Seeds=OutputPort(foam_seeds, 1))
    foam_stream.Velocity = ["CELLS", "U"]
    foam_stream.IntegrationDirection = "Both"
    ColorBy(Show(foam_stream, view), ("POINTS", "IntegrationTime"))
    Hide(foam_surface, view)
    Render(view)
    # [openfoam_stream]
    step("openfoam_stream")

if globals().get("unsteady_file"):
    # [unsteady_open]
    # The eye icons: the pipelines above hidden.  View > Time Inspector: their times unticked
    # (the steady Flow-Aligned Surfaces have the iterations as time steps of their own).
    for source in GetSources().values():
        for port in range(source.GetNumberOfOutputPorts()):
            Hide(OutputPort(source, port), view)
    GetTimeKeeper().SuppressedTimeSources = list(GetSources().values())
    series = PVDReader(FileName=unsteady_file)  # File > Open > CYLINDER_UNSTEADY_grid.pvd, Apply
    Show(series, view)  # the outline
    obstacle = Contour(Input=series, ContourBy=["POINTS", "inside"], Isosurfaces=[0.5])
    ColorBy(Show(obstacle, view), None)
    Show(AnnotateTime(), view)  # Sources > Annotate Time: the data's time in the view
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()  # the time controls: the data's 34 steps
    view.CameraPosition = [0.75, 0.95, 0.75]  # the mouse: the channel seen from above, behind
    view.CameraFocalPoint = [0.55, 0.25, 0.2]
    view.CameraViewUp = [0, 0, 1]
    Render(view)
    # [unsteady_open]
    step("unsteady_open")

    # [unsteady_surface]
    followed = FlowAlignedSurface(Input=series)  # the defaults, as on the steady cylinder
    followed_shown = Show(followed, view)
    ColorBy(followed_shown, ("CELLS", "normalized_flux"))
    followed_shown.SetScalarBarVisibility(view, True)
    GetColorTransferFunction("normalized_flux").RescaleTransferFunction(0.0, 1.0)
    Hide3DWidgets(proxy=followed)
    scene.Play()  # the data's time: the surface follows the flow from step to step
    # [unsteady_surface]
    step("unsteady_surface")

    # [unsteady_path_surface]
    line = Line(Point1=[0.55, 0.3, 0.05], Point2=[0.55, 0.3, 0.36], Resolution=30)  # Sources > Line
    path = StreamSurfaceFromCurve(Input=series, Seeds=line)
    path.SurfaceType = "Path Surface"
    path.StartTime = series.TimestepValues[0]  # released at the first step, grown up to the view's time
    path_texture = FlowTexture(Input=series, Surface=path)
    path_texture.PathSurface = 1  # the texture follows the path lines, not the flow of one time
    SaveData(path_texture_file, proxy=OutputPort(path_texture, 1))
    path_textured = Show(OutputPort(path_texture, 0), view)
    ColorBy(path_textured, None)
    path_textured.DiffuseColor = [1, 1, 1]
    path_textured.Texture = CreateTexture(path_texture_file)
    Hide(followed, view)
    scene.AnimationTime = series.TimestepValues[-1]  # the end of the period: the whole path surface
    view.CameraPosition = [0.85, 1.9, 0.75]  # the mouse: the path surface from the side it grows on
    view.CameraFocalPoint = [0.8, 0.3, 0.2]
    view.CameraViewUp = [0, 0, 1]
    Render(view)
    # [unsteady_path_surface]
    step("unsteady_path_surface")
