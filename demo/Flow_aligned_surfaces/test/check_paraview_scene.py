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
#   alignment that is not blank;
# - the tangential stream surfaces carry their LIC-like texture: TCoords, the active texture
#   coordinates, whose u grows along the flow (its gradient parallel to the velocity on the
#   faces the mask keeps), and texture_mask in [0, 1] per face; the script shows them textured
#   in a view of their own (a picture with many colours);
# - the script draws the domain's outline: with a data file (argv[3], given to --field), an
#   Outline of the file whose bounds are the file's own as ParaView reads it; else a box around
#   every surface the job wrote;
# - with a time series (a .pvd, the run at its second step): path surfaces instead of stream
#   surfaces (their texture checked as above against the velocity they saw), whose
#   NAME_path_surfaces.pvd lists the data's times after the release, then the end, each step
#   with no vertex of a later time; the script leaves ParaView's time at the end of the path
#   surfaces, a time of the data's, and the iterations out of the time controls.
# Raises on failure (pvbatch then exits non-zero).
import csv
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

from paraview.simple import *
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

align_patch, out = sys.argv[1], sys.argv[2]
field = os.path.abspath(sys.argv[3]) if len(sys.argv) > 3 else None
shutil.rmtree(out, ignore_errors=True)
unsteady = field is not None and field.endswith('.pvd')
data_times = []
if unsteady:
    data_times = [float(e.get('timestep')) for e in ET.parse(field).getroot().find('Collection').findall('DataSet')]
subprocess.run([align_patch, '--faces', '400', '--output', out] + (['--field', field] if field else [])
               + (['--time', repr(data_times[1])] if unsteady else []), check=True)
seeded = 'path_surfaces' if unsteady else 'stream_surfaces'


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


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


# The texture coordinates of the tangential stream surfaces: u is the time-like coordinate of the
# tangential parametrization, so on each face the mask keeps (mask 0: grad r along the surface
# follows the flow) its gradient is parallel to the velocity projected on the face.
surfaces = read_vtp(os.path.join(out, 'tangential_%s.vtp' % seeded))
tcoords = surfaces.GetPointData().GetTCoords()
check(tcoords is not None and tcoords.GetName() == 'TCoords' and tcoords.GetNumberOfComponents() == 2
      and tcoords.GetNumberOfTuples() == surfaces.GetNumberOfPoints(),
      'tangential_%s.vtp: TCoords is not the active texture coordinates, 2 per point' % seeded)
mask = surfaces.GetCellData().GetArray('texture_mask')
check(mask is not None and mask.GetNumberOfTuples() == surfaces.GetNumberOfCells()
      and all(0 <= mask.GetValue(i) <= 1 for i in range(mask.GetNumberOfTuples())),
      'tangential_%s.vtp: texture_mask is not one value in [0, 1] per face' % seeded)
velocity = surfaces.GetPointData().GetArray('velocity')


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


weighted_cos, kept_area = 0.0, 0.0
for c in range(surfaces.GetNumberOfCells()):
    ids = surfaces.GetCell(c).GetPointIds()
    if ids.GetNumberOfIds() != 3 or mask.GetValue(c) > 0.1:
        continue
    p = [surfaces.GetPoint(ids.GetId(k)) for k in range(3)]
    u = [tcoords.GetTuple2(ids.GetId(k))[0] for k in range(3)]
    if any(x != x for x in u):
        continue
    e1, e2 = sub(p[1], p[0]), sub(p[2], p[0])
    n = cross(e1, e2)
    area2 = dot(n, n)
    if area2 == 0:
        continue
    # grad u on the face: ((u1-u0) (n x e2) + (u2-u0) (e1 x n)) / |n|^2
    a_, b_ = cross(n, e2), cross(e1, n)
    grad = [((u[1] - u[0]) * a_[i] + (u[2] - u[0]) * b_[i]) / area2 for i in range(3)]
    v = [sum(velocity.GetTuple3(ids.GetId(k))[i] for k in range(3)) / 3 for i in range(3)]
    v = [v[i] - dot(v, n) / area2 * n[i] for i in range(3)]  # projected on the face
    lengths = (dot(grad, grad) * dot(v, v)) ** 0.5
    if lengths == 0:
        continue
    area = area2 ** 0.5 / 2
    weighted_cos += area * abs(dot(grad, v)) / lengths
    kept_area += area
check(kept_area > 0, 'tangential_%s.vtp: the mask keeps no face' % seeded)
check(weighted_cos / kept_area > 0.95,
      'the texture coordinate u of the stream surfaces does not follow the flow: mean |cos| %g'
      % (weighted_cos / kept_area))
print('TCoords: u follows the flow (mean |cos| %.4f on the kept faces)' % (weighted_cos / kept_area))

# The path surfaces as they grow: the data's times after the release, then the end.
if unsteady:
    with open(os.path.join(out, 'summary.json')) as f:
        run = json.load(f)['time_series']
    end = run['time'] + run['duration']
    for name in ('tangential', 'orthogonal'):
        pvd = os.path.join(out, name + '_path_surfaces.pvd')
        entries = ET.parse(pvd).getroot().find('Collection').findall('DataSet')
        times = [float(e.get('timestep')) for e in entries]
        expected = [t for t in data_times if run['time'] < t < end] + [end]
        check(len(times) == len(expected) and all(abs(a - b) <= 1e-9 for a, b in zip(times, expected)),
              '%s lists the times %s, expected %s' % (pvd, times, expected))
        for e in entries:
            step = read_vtp(os.path.join(out, e.get('file')))
            vertex_time = step.GetPointData().GetArray('time')
            latest = vertex_time.GetRange()[1] if step.GetNumberOfPoints() else -1e300
            check(latest <= float(e.get('timestep')) + 1e-9,
                  '%s at %s has a vertex of time %s' % (pvd, e.get('timestep'), latest))
    print('path surfaces over time: %d and %d steps' % (len(times), len(expected)))

# The script, as a user runs it.
sys.argv = [os.path.join(out, 'open_in_paraview.py'), '--screenshot', os.path.join(out, 'paraview')]
exec(compile(open(sys.argv[0]).read(), sys.argv[0], 'exec'), {'__file__': sys.argv[0], '__name__': '__main__'})

outputs = [f[:-4] for f in os.listdir(out) if f.endswith('.vtp') or f.endswith('.pvd')]
for output in outputs:
    check(FindSource(output) is not None, 'open_in_paraview.py did not open ' + output)
if unsteady:
    animation_time = GetAnimationScene().AnimationTime
    check(abs(animation_time - end) <= 1e-9, 'the script leaves the time at %s, not %s' % (animation_time, end))
    suppressed = list(GetTimeKeeper().SuppressedTimeSources)
    for name in ('tangential', 'orthogonal'):
        check(FindSource(name + '_iterations') in suppressed, name + '_iterations drive the time controls')
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

def drawn_colours(picture):
    png = vtkPNGReader()
    png.SetFileName(picture)
    png.Update()
    scalars = png.GetOutput().GetPointData().GetScalars()
    return set(scalars.GetTuple(i)[:3] for i in range(scalars.GetNumberOfTuples())) - {(255.0, 255.0, 255.0)}


textured_picture = os.path.join(out, 'paraview_tangential_textured.png')
check(os.path.exists(textured_picture), textured_picture + ' not written')
colours = len(drawn_colours(textured_picture))
check(colours > 2000, '%s has %d colours: no texture' % (textured_picture, colours))

# The domain's outline.
for name in ('tangential', 'orthogonal'):
    outline = FindSource(name + '_domain_outline')
    check(outline is not None, 'open_in_paraview.py draws no outline of the domain for ' + name)
    bounds = outline.GetDataInformation().GetBounds()
    if field:
        data = OpenDataFile(field)
        data.UpdatePipeline()
        expected = data.GetDataInformation().GetBounds()
        size = max(expected[1] - expected[0], expected[3] - expected[2], expected[5] - expected[4])
        # (the outline's points are float, the file's coordinates may be double)
        check(all(abs(bounds[i] - expected[i]) <= 1e-6 * size for i in range(6)),
              'the outline of %s has bounds %s, the file %s' % (name, bounds, expected))
    else:
        for f in os.listdir(out):
            if f.startswith(name) and f.endswith('.vtp') and not f.endswith('_obstacle.vtp'):
                b = read_vtp(os.path.join(out, f)).GetBounds()
                inside = all(bounds[2 * i] - 1e-9 <= b[2 * i] and b[2 * i + 1] <= bounds[2 * i + 1] + 1e-9
                             for i in range(3))
                check(inside, '%s (bounds %s) is not inside the outline %s' % (f, b, bounds))
print('check_paraview_scene: %d outputs opened, pictures written' % len(outputs))
