// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pvpython script the main job writes beside its outputs, open_in_paraview.py: it opens
// every output (the initial and aligned surfaces, the seed curves, stream surfaces and stream
// lines, the obstacle, and the collection of the iterations, NAME_iterations.pvd; in a time
// series the path surfaces as they grow, NAME_path_surfaces.pvd, and the path lines, with the
// time controls on the data's time at the end of the path surfaces) in one render view per
// alignment, with the colouring and the camera of the scene pictures (render_scene_PNG.h):
// surfaces by `normalized_flux` blue to red over [0, 1] with a colour bar, seed curves black,
// stream surfaces translucent yellow, stream lines dark red, the obstacle grey, the domain's
// outline (an Outline of the field file; analytic flows: the pictures' box); a tangential run's
// stream surfaces also with their LIC-like texture in a view of their own; the initial surface and the
// iterations are opened hidden (eye icon in the Pipeline Browser; the iterations animate with
// the time controls).  Paths are relative to the script, so the folder can be moved.
//
//   paraview --script=open_in_paraview.py            (the GUI)
//   pvbatch open_in_paraview.py --screenshot PREFIX  (PREFIX_NAME.png per view, then exits)

#ifndef FAS_DEMO_PARAVIEW_SCRIPT_H
#define FAS_DEMO_PARAVIEW_SCRIPT_H

#include "surface_rendering.h"
#include "write_then_rename.h"

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace fas_demo {

/// One alignment's outputs for the script: NAME_initial.vtp, NAME_aligned.vtp,
/// NAME_seed_curves.vtp, NAME_iterations.pvd, and the optional ones.
struct Paraview_run {
  std::string name; ///< "tangential" or "orthogonal"
  Render_camera camera;
  bool stream_surfaces = false; ///< NAME_stream_surfaces.vtp was written
  bool stream_lines = false;    ///< NAME_stream_lines.vtp was written
  bool obstacle = false;        ///< NAME_obstacle.vtp was written
  /// The LIC-like texture of NAME_stream_surfaces.vtp (its TCoords), a PNG beside the script;
  /// empty: none.
  std::string texture;
  /// The domain's outline: an Outline of this data file (absolute) when it is given, else a box
  /// of `outline_bounds` (xmin, xmax, ymin, ymax, zmin, zmax; the scene pictures' outline).
  std::string field_file;
  std::array<double, 6> outline_bounds{0, 0, 0, 0, 0, 0};
  /// In a time series (`field_file` a .pvd): the release time of the path surfaces and path lines
  /// (NAME_path_surfaces.vtp, NAME_path_lines.vtp instead of the stream surfaces and lines) and
  /// their end.  The view opens at the end, where NAME_path_surfaces.pvd shows them whole.
  std::optional<std::array<double, 2>> path_times;
};

namespace detail {

template <std::size_t N>
inline std::string python_list(const std::array<double, N>& v)
{
  std::ostringstream os;
  os.precision(17);
  os << '[';
  for (std::size_t i = 0; i < N; ++i)
    os << (i ? ", " : "") << v[i];
  os << ']';
  return os.str();
}

// `text` as a Python string literal (a path may hold quotes and backslashes).
inline std::string python_string(const std::string& text)
{
  std::string literal = "'";
  for (char c : text) {
    if (c == '\\' || c == '\'')
      literal += '\\';
    literal += c;
  }
  return literal + "'";
}

} // namespace detail

/// Writes `out`/open_in_paraview.py for `runs` (beside it first, then renamed); `error` says
/// why not.
inline bool write_paraview_script(const std::filesystem::path& out, const std::vector<Paraview_run>& runs,
                                  std::string& error)
{
  std::ostringstream py;
  py << R"(# Opens the outputs of the Flow_aligned_surfaces main job in ParaView with the colouring and
# the camera of its pictures (*_scene.png), one render view per alignment.  Written by align_patch.
#   paraview --script=open_in_paraview.py
#   pvbatch open_in_paraview.py --screenshot PREFIX    (writes PREFIX_<alignment>.png and exits)
import os
import sys

from paraview.simple import *

here = os.path.dirname(os.path.abspath(__file__))
runs = [
)";
  for (const Paraview_run& r : runs)
    py << "    {'name': '" << r.name << "', 'position': " << detail::python_list(r.camera.position)
       << ", 'focal_point': " << detail::python_list(r.camera.focal_point)
       << ", 'view_up': " << detail::python_list(r.camera.view_up)
       << ", 'view_angle': " << r.camera.view_angle
       << ", 'stream_surfaces': " << (r.stream_surfaces ? "True" : "False")
       << ", 'stream_lines': " << (r.stream_lines ? "True" : "False")
       << ", 'obstacle': " << (r.obstacle ? "True" : "False")
       << ", 'texture': " << detail::python_string(r.texture)
       << ", 'field_file': " << detail::python_string(r.field_file)
       << ", 'outline_bounds': " << detail::python_list(r.outline_bounds)
       << ", 'path_times': " << (r.path_times ? detail::python_list(*r.path_times) : std::string("None"))
       << "},\n";
  py << R"(]
screenshot = sys.argv[sys.argv.index('--screenshot') + 1] if '--screenshot' in sys.argv else None

flux = GetColorTransferFunction('normalized_flux')
flux.ApplyPreset('Blue to Red Rainbow', True)
flux.RescaleTransferFunction(0.0, 1.0)
flux.AutomaticRescaleRangeMode = 'Never'
flux.NanColor = [0.6, 0.6, 0.6]


def open_vtp(name, view, visible=True):
    source = XMLPolyDataReader(registrationName=name, FileName=[os.path.join(here, name + '.vtp')])
    display = Show(source, view)
    if not visible:
        Hide(source, view)
    return source, display


def colour_by_flux(display, view):
    ColorBy(display, ('CELLS', 'normalized_flux'))
    display.LookupTable = flux
    display.SetScalarBarVisibility(view, True)


def new_view():
    view = CreateView('RenderView')
    view.ViewSize = [1200, 800]
    view.OrientationAxesVisibility = 1
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    AssignViewToLayout(view)
    views.append(view)
    return view


def domain_outline(run):
    """The domain's outline: an Outline of the field file, or (analytic flows, or a file that
    ParaView cannot open or that has moved) the box of the scene pictures."""
    name = run['name'] + '_domain_outline'
    field = run['field_file']
    if field and field not in fields and os.path.exists(field):  # one reader for both runs
        fields[field] = OpenDataFile(field)
        if fields[field] is not None:
            RenameSource(os.path.basename(field), fields[field])
    if fields.get(field) is not None:
        return Outline(registrationName=name, Input=fields[field])
    b = run['outline_bounds']
    box = Box(registrationName=name, XLength=b[1] - b[0], YLength=b[3] - b[2], ZLength=b[5] - b[4],
              Center=[(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2])
    return Outline(registrationName=name + '_edges', Input=box)


def show_context(run, view, obstacle, outline):
    """The obstacle and the domain's outline, as in the scene pictures."""
    if obstacle is not None:
        display = Show(obstacle, view)
        display.ColorArrayName = ['POINTS', '']  # (only normals: ColorBy(None) refuses it)
        display.AmbientColor = display.DiffuseColor = [0.72, 0.72, 0.76]
    display = Show(outline, view)
    display.ColorArrayName = ['POINTS', '']  # (no arrays: ColorBy(None) refuses it)
    display.AmbientColor = display.DiffuseColor = [0.45, 0.45, 0.45]
    display.LineWidth = 1.5


def place_camera(run, view):
    flux.RescaleTransferFunction(0.0, 1.0)  # Show rescaled it to the data
    Render(view)  # the first render resets the camera: set it afterwards
    view.CameraPosition = run['position']
    view.CameraFocalPoint = run['focal_point']
    view.CameraViewUp = run['view_up']
    view.CameraViewAngle = run['view_angle']
    view.CameraParallelProjection = 0
    Render(view)


views = []
fields = {}
for run in runs:
    name = run['name']
    view = new_view()
    outline = domain_outline(run)
    obstacle = None
    if run['obstacle']:
        obstacle = XMLPolyDataReader(registrationName=name + '_obstacle',
                                     FileName=[os.path.join(here, name + '_obstacle.vtp')])
    show_context(run, view, obstacle, outline)

    _, initial = open_vtp(name + '_initial', view, visible=False)
    colour_by_flux(initial, view)
    _, aligned = open_vtp(name + '_aligned', view)
    colour_by_flux(aligned, view)
    _, curves = open_vtp(name + '_seed_curves', view)
    ColorBy(curves, None)
    curves.AmbientColor = curves.DiffuseColor = [0.02, 0.02, 0.02]
    curves.LineWidth = 4.0
    unsteady = run['path_times'] is not None
    surfaces_source = None
    if run['stream_surfaces']:
        # In a time series the path surfaces as they grow are shown (with the data's time), the
        # whole surfaces' file hidden.
        surfaces_source, surfaces = open_vtp(name + ('_path_surfaces' if unsteady else '_stream_surfaces'), view,
                                             visible=not unsteady)
        if unsteady:
            growing = PVDReader(registrationName=name + '_path_surfaces_over_time',
                                FileName=os.path.join(here, name + '_path_surfaces.pvd'))
            surfaces = Show(growing, view)
        ColorBy(surfaces, None)
        surfaces.AmbientColor = surfaces.DiffuseColor = [0.98, 0.8, 0.3]
        surfaces.Opacity = 0.6
    if run['stream_lines']:
        _, lines = open_vtp(name + ('_path_lines' if unsteady else '_stream_lines'), view)
        ColorBy(lines, None)
        lines.AmbientColor = lines.DiffuseColor = [0.6, 0.05, 0.05]
        lines.LineWidth = 2.0
    iterations = PVDReader(registrationName=name + '_iterations',
                           FileName=os.path.join(here, name + '_iterations.pvd'))
    colour_by_flux(Show(iterations, view), view)
    Hide(iterations, view)
    if unsteady:  # the time controls play the data's time, not the iterations'
        keeper = GetTimeKeeper()
        keeper.SuppressedTimeSources = list(keeper.SuppressedTimeSources) + [iterations]
        animation = GetAnimationScene()
        animation.UpdateAnimationUsingDataTimeSteps()
        animation.AnimationTime = run['path_times'][1]

    bar = GetScalarBar(flux, view)
    bar.Title = 'normalized_flux'
    bar.ComponentTitle = ''
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]

    place_camera(run, view)
    if screenshot:
        SaveScreenshot(screenshot + '_' + name + '.png', view, ImageResolution=[1200, 800])

    # The stream surfaces with their LIC-like texture (the TCoords of their file), opaque, in a
    # view of their own: in the first they coincide with the aligned surface they start from.
    if surfaces_source is not None and run['texture']:
        textured_view = new_view()
        show_context(run, textured_view, obstacle, outline)
        textured = Show(surfaces_source, textured_view)
        ColorBy(textured, None)
        textured.AmbientColor = textured.DiffuseColor = [1.0, 1.0, 1.0]
        textured.Texture = CreateTexture(os.path.join(here, run['texture']))
        place_camera(run, textured_view)
        if screenshot:
            SaveScreenshot(screenshot + '_' + name + '_textured.png', textured_view, ImageResolution=[1200, 800])

if screenshot:  # pvbatch: a live view at exit ends in GLXBadContext
    for view in views:
        Delete(view)
)";
  const std::string path = (out / "open_in_paraview.py").string();
  std::string reason;
  if (write_stream_then_rename(path, reason, [&](std::ostream& os) { os << py.str(); }))
    return true;
  error = "cannot write " + path + ": " + reason;
  return false;
}

} // namespace fas_demo

#endif // FAS_DEMO_PARAVIEW_SCRIPT_H
