"""The plugin as a user loads it: through PV_PLUGIN_PATH, by name, from the folder given.

Run as: PV_PLUGIN_PATH=DIR pvbatch check_plugin_loaded.py DIR
ParaView loads the plugins of PV_PLUGIN_PATH at startup.  Checks that its plugin manager knows
FlowAlignedSurfaces by name (what LoadDistributedPlugin looks up) with its file in DIR and
loaded, that the process mapped the plugin and its filters' library from DIR only (an installed
plugin must not reach back into the build tree), and that a filter runs.  Raises on failure.
"""
from paraview.simple import *  # the plugin's filters join this namespace when it loads

import os
import sys

from paraview import servermanager

expected_dir = os.path.realpath(sys.argv[1])

plugins = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager().GetLocalInformation()
known = {plugins.GetPluginName(i): i for i in range(plugins.GetNumberOfPlugins())}
if "FlowAlignedSurfaces" not in known:
    raise RuntimeError("PV_PLUGIN_PATH=%s: ParaView knows no plugin FlowAlignedSurfaces (it knows %s)"
                       % (os.environ.get("PV_PLUGIN_PATH"), sorted(known)))
index = known["FlowAlignedSurfaces"]
plugin_file = os.path.realpath(plugins.GetPluginFileName(index))
if os.path.dirname(plugin_file) != expected_dir:
    raise RuntimeError("FlowAlignedSurfaces is %s, not in %s" % (plugin_file, expected_dir))
if not plugins.GetPluginLoaded(index):
    raise RuntimeError("FlowAlignedSurfaces (%s) was found but not loaded" % plugin_file)

# What the dynamic loader mapped: the plugin and the filters' library, from expected_dir.
with open("/proc/self/maps") as maps:
    mapped = {os.path.realpath(line.split(None, 5)[5].strip()) for line in maps
              if len(line.split(None, 5)) == 6 and "FlowAlignedSurfaces" in line}
for library in ("FlowAlignedSurfaces.so", "libFlowAlignedSurfacesFilters.so"):
    places = sorted(m for m in mapped if os.path.basename(m) == library)
    if places != [os.path.join(expected_dir, library)]:
        raise RuntimeError("%s is mapped from %s, expected %s only" % (library, places, expected_dir))

# A filter of the plugin runs: a patch aligned in a rotation about z (a Wavelet gives the grid).
flow = Calculator(Input=Wavelet(WholeExtent=[-5, 5, -5, 5, -5, 5]), ResultArrayName="velocity",
                  Function="-coordsY*iHat + coordsX*jHat + 0.1*kHat")
surface = FlowAlignedSurface(Input=flow, Velocity=["POINTS", "velocity"],
                             Center=[2, 0, 0], Normal=[0, 1, 0], Size=2, NumberOfFaces=200,
                             NumberOfIterations=3)
surface.UpdatePipeline()
cells = surface.GetDataInformation().GetNumberOfCells()
if cells < 100:
    raise RuntimeError("Flow-Aligned Surface from %s made %d faces, expected about 200" % (plugin_file, cells))
print("check_plugin_loaded: FlowAlignedSurfaces loaded by name from %s; Flow-Aligned Surface made %d faces"
      % (expected_dir, cells))
