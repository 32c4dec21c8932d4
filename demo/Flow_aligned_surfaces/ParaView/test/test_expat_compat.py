"""The expat compatibility library (Expat_compat/): preloaded into pvbatch, ParaView's VTK reads
appended VTK XML data again, whatever the machine's expat.

The script writes a sphere of 6,242 points as a VTP file in each encoding ParaView's writer has
(appended raw, appended base64, inline binary, ASCII; zlib-compressed) and reads each back with
ParaView's own reader: every file must give the sphere's points.  ctest runs it twice: with
LD_PRELOAD naming the library (FAS_EXPECT_APPENDED_READ=1: everything must read), and without
(the platform as it is: inline and ASCII must read; whether appended data read is printed, as a
fact of this machine's expat, not asserted).

    pvbatch test_expat_compat.py WORKDIR
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

workdir = sys.argv[1]
os.makedirs(workdir, exist_ok=True)
expect_appended = os.environ.get("FAS_EXPECT_APPENDED_READ") == "1"
preloaded = "Expat" in os.environ.get("LD_PRELOAD", "")
if expect_appended and not preloaded:
    raise AssertionError("FAS_EXPECT_APPENDED_READ=1 but LD_PRELOAD names no expat library")

sphere = Sphere(ThetaResolution=80, PhiResolution=80)
expected = servermanager.Fetch(sphere).GetNumberOfPoints()
modes = {
    "appended_raw": {"DataMode": "Appended", "EncodeAppendedData": 0},
    "appended_base64": {"DataMode": "Appended", "EncodeAppendedData": 1},
    "inline_binary": {"DataMode": "Binary"},
    "ascii": {"DataMode": "Ascii"},
}
read = {}
for name, options in modes.items():
    path = os.path.join(workdir, name + ".vtp")
    SaveData(path, proxy=sphere, CompressorType="ZLib", **options)
    errors = []
    reader = vtkXMLPolyDataReader()
    reader.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
    reader.SetFileName(path)
    reader.Update()
    read[name] = reader.GetOutput().GetNumberOfPoints() if not errors else 0
    print("%s: %d of %d points read%s" % (name, read[name], expected, ", with errors" if errors else ""))

for name in ["inline_binary", "ascii"]:
    if read[name] != expected:
        raise AssertionError("%s: %d points read, expected %d" % (name, read[name], expected))
appended_read = all(read[name] == expected for name in ["appended_raw", "appended_base64"])
if expect_appended and not appended_read:
    raise AssertionError("with %s preloaded, appended data still do not read: %s" %
                         (os.environ["LD_PRELOAD"], read))
if not preloaded:
    print("without the library, this machine's expat %s appended VTK XML data in ParaView's VTK" %
          ("parses" if appended_read else "does NOT parse"))
