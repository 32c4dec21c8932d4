"""The ParaView GUI with the plugin: run by ctest as
  with_xvfb.sh paraview --dr --plugin-search-paths=DIR --plugins=FlowAlignedSurfaces --script=test_gui.py
with FAS_GUI_FIELD (a VTK image with the velocity) and FAS_GUI_SCREENSHOT (a PNG to write) in the
environment.  The GUI has no exit status of its own for a script: this one ends the process with
os._exit(0) after its checks passed, and os._exit(1) with the reason on stderr otherwise."""
import os
import sys
import traceback

try:
    from paraview.simple import *

    data = XMLImageDataReader(FileName=[os.environ["FAS_GUI_FIELD"]])
    surface = FlowAlignedSurface(Input=data)  # from the plugin the GUI loaded
    surface.Velocity = ["POINTS", "velocity"]
    surface.Center = [-1.8, 0.5, 0.0]
    surface.Normal = [1.0, 0.3, 0.2]
    surface.Size = 1.2
    surface.NumberOfFaces = 2000
    surface.NumberOfIterations = 25
    view = GetActiveViewOrCreate("RenderView")
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = 25.0  # the last iteration, as the time controls would show it
    display = Show(surface, view)
    ColorBy(display, ("CELLS", "normalized_flux"))
    display.SetScalarBarVisibility(view, True)
    # The plugin's GUI side gives the colour map of normalized_flux [0, 1], locked ("Never"
    # rescaled), once the GUI has processed the representation's signals; a range the user sets
    # afterwards is kept when the array is picked again.
    sys.path.insert(0, os.environ["FAS_GUI_TESTS"])
    import gui_window
    gui_window.process_events()
    flux_map = GetColorTransferFunction("normalized_flux")
    points = list(flux_map.RGBPoints)
    mode = flux_map.GetProperty("AutomaticRescaleRangeMode").GetData()
    if mode != "Never" or (points[0], points[-4]) != (0.0, 1.0):
        raise AssertionError("the colour map of normalized_flux: rescale mode %s, range %g to %g" % (
            mode, points[0], points[-4]))
    # The toolbar's colour selector: another array, then normalized_flux again (ColorBy would
    # rescale to the data by itself).
    flux_map.RescaleTransferFunction(0.0, 0.5)
    display.SetScalarColoring("velocity", servermanager.GetAssociationFromString("POINTS"))
    display.SetScalarColoring("normalized_flux", servermanager.GetAssociationFromString("CELLS"))
    gui_window.process_events()
    points = list(flux_map.RGBPoints)
    if (points[0], points[-4]) != (0.0, 0.5):
        raise AssertionError("a range set by the user was not kept: %g to %g" % (points[0], points[-4]))
    outline = Show(data, view)
    outline.SetRepresentationType("Outline")
    view.ViewSize = [800, 600]
    Render(view)  # the first render resets the camera: place it after
    view.CameraPosition = [-4.5, -3.5, 4.0]
    view.CameraFocalPoint = [-1.0, 0.3, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    Render(view)
    # Every filter with its defaults on the real CFD data, each output shown as Apply shows it
    # (defaults_check.py): converged surfaces, seed curves, a stream surface, a visible texture,
    # no warning; the surfaces coloured by normalized_flux on [0, 1].
    folder = os.environ.get("FAS_DEFAULTS_DATA")
    if folder:
        import defaults_check
        defaults_view = CreateView("RenderView")
        def shown(proxy):
            display = Show(proxy, defaults_view)
            gui_window.process_events(0.1)
            if proxy.GetXMLName() == "FlowAlignedSurface":
                display.SetScalarColoring("normalized_flux", servermanager.GetAssociationFromString("CELLS"))
        for name in defaults_check.DATA_SETS:
            print("GUI: " + defaults_check.check_defaults(folder, name, globals(), shown), file=sys.__stdout__)
        gui_window.process_events()
        defaults_points = list(GetColorTransferFunction("normalized_flux").RGBPoints)
        if (defaults_points[0], defaults_points[-4]) != (0.0, 0.5):
            raise AssertionError("the defaults changed the user's range of normalized_flux: %g to %g" % (
                defaults_points[0], defaults_points[-4]))
        Delete(defaults_view)
        SetActiveView(view)
    output = servermanager.Fetch(surface)
    flux = output.GetFieldData().GetArray("normalized_flux").GetValue(0)
    iteration = output.GetFieldData().GetArray("iteration").GetValue(0)
    if output.GetNumberOfCells() < 1000 or not flux < 0.05 or iteration != 25:
        raise AssertionError("the GUI's Flow-Aligned Surface: %d faces, flux %g at iteration %g" % (
            output.GetNumberOfCells(), flux, iteration))
    SaveScreenshot(os.environ["FAS_GUI_SCREENSHOT"], view, ImageResolution=[800, 600])
    print("GUI: Flow-Aligned Surface applied, flux %g at iteration %g" % (flux, iteration),
          file=sys.__stdout__)
    sys.__stdout__.flush()
    os._exit(0)
except BaseException:
    # To the process's own stderr: the GUI keeps sys.stderr for its Python shell.
    traceback.print_exc(file=sys.__stderr__)
    sys.__stderr__.flush()
    os._exit(1)
