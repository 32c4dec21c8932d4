"""The manual's ParaView tutorial in the GUI, with its screenshots: run by ctest as
  with_xvfb.sh paraview --dr --plugin-search-paths=DIR --plugins=FlowAlignedSurfaces --script=test_tutorial_gui.py
with FAS_TUTORIAL_DATA (CYLINDER_grid.vtk), FAS_TUTORIAL_OUTPUT (a folder) and FAS_TUTORIAL_TESTS (this
file's folder: the GUI runs a --script without __file__) in the environment.

One GUI session (a start costs seconds) runs ../scripts/tutorial.py, the code the manual shows
beside each step, and after each of its blocks grabs the whole main window (pipeline browser,
properties panel, render view: gui_window.py) as FAS_TUTORIAL_OUTPUT/fas_tutorial_<step>.png,
which scripts/make-figures.sh copies into the manual.  FAS_TUTORIAL_UNSTEADY_DATA (CYLINDER_UNSTEADY_grid.pvd) adds the unsteady part.  Checked after each step: the screenshot is
a picture (many colours, and not the previous step's), and the pipeline gives what the manual
says the step gives.  The GUI has no exit status of its own for a script: this one ends the
process with os._exit(0) when every check passed, os._exit(1) with the reason on stderr
otherwise (written to the file descriptor: the GUI keeps sys.stderr for its own shell)."""
import os
import sys
import time
import traceback


def say(text):
    os.write(2, (text + "\n").encode())


try:
    from paraview.simple import *

    here = os.environ["FAS_TUTORIAL_TESTS"]
    sys.path.insert(0, here)
    import gui_window
    import numpy
    import openfoam_case

    output = os.environ["FAS_TUTORIAL_OUTPUT"]
    os.makedirs(output, exist_ok=True)
    window = gui_window.Window()
    window.resize(1280, 960)
    tutorial = os.path.join(here, "..", "scripts", "tutorial.py")
    run = {"__name__": "tutorial", "__file__": tutorial,
           "cylinder_file": os.environ["FAS_TUTORIAL_DATA"],
           "case_file": openfoam_case.write_case(os.path.join(output, "case")),
           "unsteady_file": os.environ.get("FAS_TUTORIAL_UNSTEADY_DATA"),
           "texture_file": os.path.join(output, "flow_texture.png"),
           "path_texture_file": os.path.join(output, "path_surface_texture.png")}
    previous = [None]
    started = [time.time()]

    def field(proxy, name, port=0):
        return servermanager.Fetch(proxy, idx=port).GetFieldData().GetArray(name).GetValue(0)

    def cells(proxy, port=0):
        return servermanager.Fetch(proxy, idx=port).GetNumberOfCells()

    def expect(condition, what):
        if not condition:
            raise AssertionError(what)

    def check_aligned(proxy, what):
        flux, converged = field(proxy, "normalized_flux"), field(proxy, "converged")
        expect(flux <= 0.02 and converged == 1, "%s: flux %g, converged %g" % (what, flux, converged))
        return "flux %.4f at iteration %d, %d faces" % (flux, field(proxy, "iteration"), cells(proxy))

    def check(name):
        """What the manual says the step gives."""
        g = run
        if name == "open":
            info = g["data"].PointData["velocity"]
            expect(info is not None and info.GetNumberOfComponents() == 3, "no 3-component velocity")
            return "velocity read"
        if name in ("apply", "drag"):
            n = cells(g["surface"])
            expect(n >= 1000, "%s: %d faces" % (name, n))
            return "%d faces, centre %s, size %g" % (n, list(g["surface"].Center), g["surface"].Size)
        if name == "play":
            last = g["surface"].TimestepValues[-1]
            expect(g["scene"].AnimationTime == last, "the scene is at %g, not %g" % (g["scene"].AnimationTime, last))
            return check_aligned(g["surface"], "after Play")
        if name == "grow":
            before, after = cells(g["surface"]), cells(g["grown"])
            expect(after > before, "grown: %d faces, %d before" % (after, before))
            return "%d faces from %d" % (after, before)
        if name == "seed":
            n = cells(g["seeds"], 1)
            expect(n >= 1, "%d seed curves" % n)
            return "%d seed curves" % n
        if name in ("stream", "openfoam_stream"):
            n = cells(g[{"stream": "stream", "openfoam_stream": "foam_stream"}[name]])
            expect(n >= 100, "%s: %d faces" % (name, n))
            return "%d faces" % n
        if name == "texture":
            image = servermanager.Fetch(g["texture"], idx=1)
            scalars = image.GetPointData().GetScalars()
            values = numpy.array([scalars.GetTuple(i)[0] for i in range(0, scalars.GetNumberOfTuples(), 7)])
            expect(values.max() - values.min() >= 100 and values.std() >= 20,
                   "texture without contrast: %g..%g, deviation %g" % (values.min(), values.max(), values.std()))
            expect(os.path.getsize(g["texture_file"]) > 1000, "the texture PNG is missing")
            return "texture %g..%g, deviation %.1f" % (values.min(), values.max(), values.std())
        if name == "openfoam_open":
            return "%d blocks" % servermanager.Fetch(g["case"]).GetNumberOfBlocks()
        if name == "openfoam_surface":
            return check_aligned(g["foam_surface"], "OpenFOAM")
        if name == "unsteady_open":
            steps = g["series"].TimestepValues
            expect(len(steps) == 34, "%d time steps" % len(steps))
            return "%d time steps" % len(steps)
        if name == "unsteady_surface":
            last = g["series"].TimestepValues[-1]
            expect(g["scene"].AnimationTime == last, "the scene is at %g, not %g" % (g["scene"].AnimationTime, last))
            expect(field(g["followed"], "time") == last, "the surface is of time %g" % field(g["followed"], "time"))
            return check_aligned(g["followed"], "followed to the last step")
        if name == "unsteady_path_surface":
            first, last = g["series"].TimestepValues[0], g["series"].TimestepValues[-1]
            surface = servermanager.Fetch(g["path_texture"], idx=0)
            start = servermanager.Fetch(g["path"]).GetFieldData().GetArray("start_time").GetValue(0)
            expect(surface.GetNumberOfCells() >= 100 and start == first,
                   "path surface: %d faces, released at %g" % (surface.GetNumberOfCells(), start))
            expect(surface.GetPointData().GetTCoords() is not None, "the path surface has no texture coordinates")
            mask = surface.GetCellData().GetArray("texture_mask")
            kept = sum(1 for i in range(mask.GetNumberOfTuples()) if mask.GetValue(i) < 0.5) / mask.GetNumberOfTuples()
            expect(kept >= 0.8, "the texture is masked on %.0f%% of the faces" % (100 - 100 * kept))
            expect(g["scene"].AnimationTime == last, "the scene is at %g, not %g" % (g["scene"].AnimationTime, last))
            return "%d faces from t = %g to %g, texture kept on %.0f%% of them" % (
                surface.GetNumberOfCells(), first, last, 100 * kept)
        raise AssertionError("no check for step " + name)

    def step(name):
        result = check(name)
        path = os.path.join(output, "fas_tutorial_%s.png" % name)
        pixels = window.save(path)
        expect(os.path.getsize(path) > 10000, "%s: the screenshot is missing or empty" % path)
        colours = len(numpy.unique(pixels.reshape(-1, 3).astype(numpy.uint32) @ [65536, 256, 1]))
        expect(colours >= 1000, "%s: %d colours" % (path, colours))
        if previous[0] is not None and previous[0].shape == pixels.shape:
            changed = numpy.any(previous[0] != pixels, axis=2).mean()
            expect(changed >= 0.005, "%s: only %.2f%% of the pixels differ from the previous step" % (path, 100 * changed))
        previous[0] = pixels
        say("tutorial step %-16s %5.1f s: %s; %s, %d colours" % (name, time.time() - started[0], result,
                                                                os.path.basename(path), colours))
        started[0] = time.time()

    run["step"] = step
    with open(tutorial) as f:
        exec(compile(f.read(), tutorial, "exec"), run)
    expected = ["open", "apply", "drag", "play", "grow", "seed", "stream", "texture",
                "openfoam_open", "openfoam_surface", "openfoam_stream", "unsteady_open", "unsteady_surface",
                "unsteady_path_surface"]
    missing = [n for n in expected if not os.path.exists(os.path.join(output, "fas_tutorial_%s.png" % n))]
    expect(not missing, "steps without a screenshot: %s" % missing)
    say("tutorial: all %d steps checked" % len(expected))
    os._exit(0)
except BaseException:
    say(traceback.format_exc())
    os._exit(1)
