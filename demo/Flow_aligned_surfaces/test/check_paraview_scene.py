# The main job's ParaView scene, checked in pvbatch: runs align_patch (argv[1]) into a fresh
# folder (argv[2]), then checks against what is known without the script:
# - each NAME_iterations.pvd lists exactly the files of NAME_iterations/, all of which exist,
#   one per iteration of NAME_flux.csv (its rows with a time) plus the initial patch, with the
#   time steps 0, 1, 2, ... (PVDReader reports as many);
# - every VTP file the job wrote (its iteration steps included) is read by ParaView's own VTK
#   reader, on this machine's expat, without an error and with points (appended data would not
#   be, with the expat of an up-to-date Debian bookworm);
# - open_in_paraview.py, run with --screenshot, opens every output the job wrote (a source per
#   .vtp and .pvd), colours by normalized_flux over [0, 1], and writes one picture per
#   alignment that is not blank.
# Raises on failure (pvbatch then exits non-zero).
import csv
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

from paraview.simple import *
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

align_patch, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
subprocess.run([align_patch, '--faces', '400', '--output', out], check=True)


def check(condition, message):
    if not condition:
        raise RuntimeError('check_paraview_scene: ' + message)


for name in ('tangential', 'orthogonal'):
    pvd = os.path.join(out, name + '_iterations.pvd')
    entries = ET.parse(pvd).getroot().find('Collection').findall('DataSet')
    listed = [e.get('file') for e in entries]
    folder = os.path.join(out, name + '_iterations')
    present = sorted(name + '_iterations/' + f for f in os.listdir(folder))
    check(sorted(listed) == present, '%s lists %s, the folder holds %s' % (pvd, listed, present))
    check([float(e.get('timestep')) for e in entries] == list(range(len(entries))),
          '%s: time steps are not 0, 1, 2, ...' % pvd)
    with open(os.path.join(out, name + '_flux.csv')) as f:
        iterations = [row for row in csv.DictReader(f) if row['gtransf_ms'] != '']
    check(len(listed) == len(iterations) + 1,
          '%s has %d files for %d iterations' % (pvd, len(listed), len(iterations)))
    reader = PVDReader(FileName=pvd)
    reader.UpdatePipelineInformation()
    check(len(reader.TimestepValues) == len(listed), 'PVDReader sees %d time steps' % len(reader.TimestepValues))
    Delete(reader)

# Every VTP file, read by ParaView's VTK.
vtp_files = [os.path.join(folder, f) for folder, _, files in os.walk(out) for f in files if f.endswith('.vtp')]
check(len(vtp_files) > 10, 'only %d VTP files written' % len(vtp_files))
for vtp in vtp_files:
    check('format="appended"' not in open(vtp, 'rb').read().decode('latin-1'), vtp + ' has appended data')
    errors = []
    reader = vtkXMLPolyDataReader()
    reader.AddObserver('ErrorEvent', lambda caller, event: errors.append(event))
    reader.SetFileName(vtp)
    reader.Update()
    check(reader.GetOutput().GetNumberOfPoints() > 0 and not errors, "ParaView's VTK cannot read " + vtp)
print('%d VTP files read by ParaView\'s VTK' % len(vtp_files))

# The script, as a user runs it.
sys.argv = [os.path.join(out, 'open_in_paraview.py'), '--screenshot', os.path.join(out, 'paraview')]
exec(compile(open(sys.argv[0]).read(), sys.argv[0], 'exec'), {'__file__': sys.argv[0], '__name__': '__main__'})

outputs = [f[:-4] for f in os.listdir(out) if f.endswith('.vtp') or f.endswith('.pvd')]
for output in outputs:
    check(FindSource(output) is not None, 'open_in_paraview.py did not open ' + output)
lut = GetColorTransferFunction('normalized_flux')
points = lut.RGBPoints
check(abs(points[0]) < 1e-12 and abs(points[-4] - 1) < 1e-12, 'normalized_flux is coloured over %s' % points[::4])
for name in ('tangential', 'orthogonal'):
    picture = os.path.join(out, 'paraview_' + name + '.png')
    check(os.path.exists(picture), picture + ' not written')
    png = vtkPNGReader()
    png.SetFileName(picture)
    png.Update()
    scalars = png.GetOutput().GetPointData().GetScalars()
    drawn = sum(1 for i in range(0, scalars.GetNumberOfTuples(), 7) if scalars.GetTuple(i)[:3] != (255.0, 255.0, 255.0))
    check(drawn > 500, '%s is (nearly) blank: %d of every 7th pixels drawn' % (picture, drawn))
print('check_paraview_scene: %d outputs opened, pictures written' % len(outputs))
