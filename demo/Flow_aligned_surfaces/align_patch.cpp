// The package's main job: place a planar patch in a built-in flow, align it
// tangentially (a stream surface) or orthogonally (a seeding surface), and write
// what a user opens afterwards: the initial and aligned surfaces as PLY and VTP
// (ParaView), the iterations as a ParaView collection (.pvd), the normalized flux of every
// iteration as CSV, a JSON summary and open_in_paraview.py (every output with the colouring and
// camera of the pictures); and, when built with VTK rendering and a display (or Xvfb) is there,
// pictures (PNG): the scene of each alignment (the initial patch beside the aligned one with
// what it seeds, the obstacle and the domain, as the paper's Figures 4 and 5) and one picture
// per stage in the same context and camera (the initial and aligned surfaces coloured by flux,
// the seed curves, the stream surfaces, the stream lines, the tangential surface with its
// LIC-like texture).
// The seeding workflow of the paper's Figures 4 and 5 on each aligned surface: the tangential
// one grown across the flow first; its parametrization (with the deformation's own
// factorization) gives seed curves (iso-contours of r, VTP), one stream surface per distinct
// seed curve, integrated forward and backward as one mesh (VTP with u, t, SeedIds), and on the
// orthogonal surface seed points seed stream lines (VTP with velocity, IntegrationTime, SeedIds).
//
// In a time series (--field SERIES.pvd) the patches are aligned to the flow at --time, and their
// seeds give path surfaces and path lines over --duration instead (time_series.h): the path
// surfaces also as they grow over the data's times (a .pvd), coloured in their picture by the
// deviation of the flow from its time mean, the tangential one with its texture along its path
// lines (the paper's Figure 8, path-surface half).
//
// Usage: align_patch [--flow NAME | --field FILE [--array NAME] [--time T] [--duration D]]
//                    [--alignment tangential|orthogonal|both] [--faces N] [--center X,Y,Z]
//                    [--normal X,Y,Z] [--size S] [--output DIR] [--overwrite] [--quiet]
// (`align_patch --help` lists the options with their defaults.)
// Flows: cylinder (default), point-source, sphere, helical, hill, burgers, abc, tornado.
// A data file is any file IO::read_flow_field() reads (legacy VTK grids and cells, VTK XML
// .vti/.vtu/.vts when built with VTK, AmiraMesh, NRRD) with a velocity array (and an optional
// mask array "inside"); without --center the patches are placed near the obstacle (or the largest
// vorticity), and without --normal they are tilted 30 degrees off the flow
// (feature_placement.h).

#include "command_line.h"
#include "demo_support.h"
#include "feature_placement.h"
#include "grow_across_flow.h"
#include "growing_path_surfaces.h"
#include "paraview_script.h"
#include "scene_assembly.h"
#include "seeded_surfaces.h"
#include "stream_lines_with_arrays.h"
#include "surface_collection.h"
#include "time_series.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_PNG.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace fas_demo;

struct Scene {
  Flow flow;
  Point tangential_center, orthogonal_center;
  Vector tangential_normal, orthogonal_normal;
  double size;
  std::optional<CGAL::Bbox_3> domain = std::nullopt; // the data's box (analytic flows: none)
  std::string field_file = {};                       // the data file, absolute (analytic flows: none)
  // A time series: `flow` is its flow at the run's time, and the seeds give path surfaces.
  std::optional<Unsteady_run> unsteady = std::nullopt;
};

// A built-in flow with a tangential and an orthogonal placement of the patch in it.
std::optional<Scene> make_scene(const std::string& name)
{
  const std::optional<Flow> flow = make_built_in_flow(name);
  if (!flow)
    return std::nullopt;
  if (name == "cylinder")
    return Scene{
        *flow, Point(-2.0, 0.8, 0), Point(-2.2, 0.6, 0.3), Vector(0.3, 1.0, 0.4), Vector(1.0, 0.4, 0.2), 1.2};
  if (name == "point-source")
    return Scene{*flow, Point(0, 0, 2), Point(0.2, -0.1, 2.0), Vector(1.0, 0.2, 0.1), Vector(0.3, 0.2, 1.0),
                 1.0};
  if (name == "sphere")
    return Scene{
        *flow, Point(0.8, 0.2, -2.0), Point(0.3, 0.2, -2.0), Vector(1.0, 0.3, 0.2), Vector(0.2, 0.1, 1.0),
        1.2};
  if (name == "helical")
    return Scene{
        *flow, Point(1.0, 0.2, 0), Point(1.0, 0.0, 0.0), Vector(1.0, 0.3, 0.2), Vector(0.0, 1.0, 0.3), 0.8};
  if (name == "hill")
    return Scene{
        *flow, Point(0.5, 0.1, 0.2), Point(0.5, 0.0, 0.0), Vector(0.2, 1.0, 0.3), Vector(0.2, 0.1, 1.0), 0.4};
  if (name == "burgers")
    return Scene{*flow, Point(1.0, 0, 0.5), Point(0.8, 0.3, 0.8), Vector(0, 1.0, 0.2), Vector(0.2, 0.1, 1.0),
                 0.6};
  if (name == "abc")
    return Scene{*flow, Point(1, 1, 1), Point(1, 1, 1), Vector(0.3, 0.2, 1.0), Vector(0.5, 0.8, 1.0), 0.5};
  if (name == "tornado")
    return Scene{
        *flow, Point(0.5, 0.3, 0.5), Point(0.5, 0.5, 0.3), Vector(0.1, 1.0, 0.1), Vector(0.1, 0.1, 1.0), 0.3};
  return std::nullopt;
}

// "x,y,z", as --center and --normal take it.
template <class T>
std::string triple_text(const T& p)
{
  std::ostringstream os;
  os.precision(4);
  os << p.x() << ',' << p.y() << ',' << p.z();
  return os.str();
}

struct Placement {
  std::optional<std::array<double, 3>> center, normal;
  std::optional<double> size;
};

// A scene in the flow of data (`box` its domain, read from `file`): the patch at the given place
// or near the flow's main feature.
std::optional<Scene> make_data_scene(const Flow& flow, const CGAL::Bbox_3& box, const std::string& file,
                                     const Placement& placement)
{
  const double size =
      placement.size
          ? *placement.size
          : 0.25 * (std::min)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  const std::optional<Point> given_center =
      placement.center ? std::optional<Point>(
                             Point((*placement.center)[0], (*placement.center)[1], (*placement.center)[2]))
                       : std::nullopt;
  if (given_center) {
    const auto v = flow(*given_center);
    if (!v || v->squared_length() == 0) {
      std::cerr << "error: --center: the flow of " << file << " is not defined (or zero) at " << *given_center
                << "; place the patch in the fluid with --center X,Y,Z\n";
      return std::nullopt;
    }
  }
  // Without --normal: near the main feature (or at --center), tilted 30 degrees off the flow.
  const auto placed = place_near_feature<Point, Vector>(flow, box, size, CGAL_PI / 6, given_center);
  if (!placed) {
    std::cerr << "error: --field: " << file << " has no flow (no finite non-zero velocity) anywhere\n";
    return std::nullopt;
  }
  Scene scene{flow,
              placed->tangential_center,
              placed->orthogonal_center,
              placed->tangential_normal,
              placed->orthogonal_normal,
              size,
              box,
              std::filesystem::absolute(file).lexically_normal().string()};
  if (placement.normal)
    scene.orthogonal_normal = scene.tangential_normal =
        Vector((*placement.normal)[0], (*placement.normal)[1], (*placement.normal)[2]);
  else
    std::cout << "patches placed " << placed->description << ": tangential at --center "
              << triple_text(scene.tangential_center) << " --normal " << triple_text(scene.tangential_normal)
              << ", orthogonal at --center " << triple_text(scene.orthogonal_center) << " --normal "
              << triple_text(scene.orthogonal_normal) << "\n";
  return scene;
}

// --time and --duration, for a time series; nothing where the default is taken.
struct Times {
  std::optional<double> time, duration;
};

// The times of a run in the series `series` read from `file`: the patches aligned at `times.time`
// (default: the first step), path surfaces over `times.duration` (default: to the last step, and
// no further); prints why not and returns nothing when the series or the times do not allow one.
std::optional<Unsteady_run> unsteady_run(const std::string& file, Time_series series, const Times& times)
{
  const double start = series.start_time(), end = series.end_time();
  const auto text = [](double t) {
    std::ostringstream os;
    os.precision(10);
    os << t;
    return os.str();
  };
  if (series.times.size() < 2) {
    std::cerr
        << "error: --field: " << file << " has one time step (t = " << text(start)
        << "); path surfaces need at least two: give a series of several steps, or the step's file itself "
           "for a steady run\n";
    return std::nullopt;
  }
  const double time = times.time.value_or(start);
  if (!(time >= start && time < end)) {
    std::cerr << "error: --time: " << text(time) << " is outside the time steps of " << file << " (from "
              << text(start) << " to " << text(end) << "; the path surfaces need time after it)\n";
    return std::nullopt;
  }
  double duration = times.duration.value_or(end - time);
  if (time + duration > end) {
    std::cerr << "warning: --duration: " << text(duration) << " from t = " << text(time)
              << " reaches past the last time step of " << file << " (t = " << text(end)
              << "); the path surfaces end there, after " << text(end - time) << "\n";
    duration = end - time;
  }
  return Unsteady_run{std::move(series), time, duration};
}

// Whether `file` is a time series: a ParaView collection (.pvd), or a folder of files with times.
bool is_time_series(const std::string& file)
{
  if (std::error_code ec; std::filesystem::is_directory(file, ec))
    return true;
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension == ".pvd";
}

// The scene of a data file: a steady field, or a time series whose flow at the run's time aligns
// the patches (unsteady_run()).
std::optional<Scene> read_data_scene(const std::string& file, const std::string& array,
                                     const Placement& placement, const Times& times)
{
  if (!is_time_series(file)) {
    const std::optional<FAS::Sampled_flow_field_3<Kernel>> field = read_data_field(file, array);
    return field ? make_data_scene(Flow(*field), field->bbox(), file, placement) : std::nullopt;
  }
  std::error_code ec;
  std::optional<Time_series> series = std::filesystem::is_directory(file, ec)
                                          ? read_time_series_folder(file, array)
                                          : read_time_series(file, array);
  std::optional<Unsteady_run> run = series ? unsteady_run(file, std::move(*series), times) : std::nullopt;
  if (!run)
    return std::nullopt;
  std::cout << "time series of " << run->series.times.size() << " steps from t = " << run->series.start_time()
            << " to " << run->series.end_time() << ": the patches aligned to the flow at t = " << run->time
            << ", path surfaces and path lines from there over " << run->duration << "\n";
  std::optional<Scene> scene = make_data_scene(run->series.at(run->time), run->series.box, file, placement);
  if (scene)
    scene->unsteady = std::move(*run);
  return scene;
}

// Opens `path` for writing, or says why not.
std::optional<std::ofstream> open_output(const std::filesystem::path& path)
{
  std::ofstream os(path);
  if (!os) {
    std::cerr << "error: cannot write " << path << "\n";
    return std::nullopt;
  }
  os << std::setprecision(10);
  return os;
}

using Polyline = std::vector<Point>;

// A stage picture of an alignment (initial, aligned, seed curves, ...): its file and what it
// shows, drawn in the context of the alignment's scene picture (stage_picture()).
struct Stage {
  std::string file;
  Scene_view view;
  std::string scalar_name = "normalized_flux";
  std::array<double, 2> scalar_range{0, 1};
};

// `tm` coloured by the normalized flux of its faces, with `lines` over it.
Scene_view flux_view(const Mesh& tm, const Flow& flow, const std::string& title,
                     std::vector<Scene_lines> lines = {})
{
  return Scene_view{{to_scene_surface(tm, face_fluxes(tm, flow), {0.8, 0.8, 0.8})}, std::move(lines), title};
}

// `tm` with the LIC-like `texture` of its parametrization, masked where grad r leaves the flow.
Scene_surface textured_surface(const Mesh& tm, Flow_texture_of_mesh texture)
{
  Scene_surface textured = to_scene_surface(tm, {}, {1, 1, 1});
  textured.texture = std::make_shared<const FAS::Texture_image>(std::move(texture.texture));
  textured.texture_coordinates = std::move(texture.texture_coordinates);
  textured.face_mask = std::move(texture.face_mask);
  return textured;
}

// The mean over each face of `tm` of the vertex values `value` (by vertex index), and the
// largest finite mean (1 when none is positive: a colour range).
std::pair<std::vector<double>, double> face_means(const Mesh& tm, const std::vector<double>& value)
{
  std::vector<double> means;
  double largest = 0;
  for (Mesh::Face_index f : tm.faces()) {
    double mean = 0;
    for (Mesh::Vertex_index v : vertices_around_face(tm.halfedge(f), tm))
      mean += value[v.idx()] / 3;
    means.push_back(mean);
    if (std::isfinite(mean))
      largest = std::max(largest, mean);
  }
  return {std::move(means), largest > 0 ? largest : 1};
}

// The stream surfaces coloured by their time-line parameter |t| (Figure 3's time lines: the mean
// of |t| over each face), or path surfaces by the deviation |v - <v>| of the flow they saw from
// the time mean (where the flow is unsteady), with their seed curves.
Stage seeded_surfaces_stage(const std::string& name, const Seeded_surfaces& seeded,
                            const Scene_lines& seed_curves)
{
  const Mesh& surfaces = seeded.mesh();
  std::vector<double> shown = seeded.deviation;
  if (!seeded.path_surfaces) {
    const auto t = surfaces.property_map<Mesh::Vertex_index, double>("v:t").first;
    for (Mesh::Vertex_index v : surfaces.vertices())
      shown.push_back(std::abs(t[v]));
  }
  auto [by_face, largest] = face_means(surfaces, shown);
  return Stage{name + "_" + seeded.kind() + ".png",
               Scene_view{{to_scene_surface(surfaces, std::move(by_face), {0.8, 0.8, 0.8})},
                          {seed_curves},
                          seeded.path_surfaces ? "path surfaces" : "stream surfaces"},
               seeded.path_surfaces ? "|v - <v>| (deviation from the time mean)"
                                    : "|t| (arc length from the seed curve)",
               {0, largest}};
}

// Seed curves of an aligned surface: iso-contours of its parametrization's r at 3 evenly spaced
// values, each with its value.
struct Seed_curves {
  std::vector<Polyline> curves;
  std::vector<double> curve_values, point_values; // r of each curve and of each of its points
};

Seed_curves take_seed_curves(Mesh& tm, const FAS::Flow_aligned_deformation<Mesh, Flow>& deformation)
{
  auto r = tm.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
  auto s = tm.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
  if (deformation.alignment() == FAS::Alignment::TANGENTIAL)
    deformation.parametrize_tangential(r, s);
  else
    deformation.parametrize_orthogonal(r, s);
  Seed_curves seeds;
  for (double value : FAS::evenly_spaced_iso_values(tm, r, 3)) {
    const std::size_t before = seeds.curves.size();
    FAS::extract_iso_contours(tm, r, std::vector<double>{value}, std::back_inserter(seeds.curves));
    for (std::size_t i = before; i < seeds.curves.size(); ++i) {
      seeds.curve_values.push_back(value);
      seeds.point_values.insert(seeds.point_values.end(), seeds.curves[i].size(), value);
    }
  }
  tm.remove_property_map(r);
  tm.remove_property_map(s);
  return seeds;
}

// The paper's Figure 8 on a tangential surface's seeded surfaces: the LIC-like texture of their
// own tangential parametrization in the flow they saw (3 repeats of the texture along the flow),
// masked where grad r leaves it; nothing (and why) when it cannot be made.
std::optional<Flow_texture_of_mesh> seeded_texture(const std::string& name, const Seeded_surfaces& seeded)
{
  try {
    return flow_texture_of_mesh(seeded.mesh(), seeded.flow, -3);
  } catch (const std::exception& e) {
    std::cerr << name << ": the " << seeded.kind() << " get no texture: " << e.what() << "\n";
    return std::nullopt;
  }
}

// Writes the seeded surfaces (NAME_stream_surfaces.vtp or NAME_path_surfaces.vtp, and path
// surfaces as they grow: NAME_path_surfaces.pvd) with their point data, their flux per face and,
// given a `texture`, its TCoords and texture_mask (the texture image beside them as
// `texture_file`, for ParaView).  False with the reason in `error` when a file cannot be written.
bool write_seeded_surfaces(const std::string& name, const Seeded_surfaces& seeded,
                           const std::optional<Flow_texture_of_mesh>& texture,
                           const std::vector<double>& face_flux, const Scene& scene,
                           const std::filesystem::path& out, std::string& texture_file, std::string& error)
{
  std::vector<FAS::IO::Data_array> point_data = seeded.point_data(), cell_data;
  if (!face_flux.empty())
    cell_data.push_back({"normalized_flux", 1, face_flux});
  if (texture) {
    FAS::IO::Data_array tcoords{"TCoords", 2, {}};
    for (const auto& uv : texture->texture_coordinates)
      tcoords.values.insert(tcoords.values.end(), {uv[0], uv[1]});
    tcoords.texture_coordinates = true;
    point_data.push_back(std::move(tcoords));
    cell_data.push_back({"texture_mask", 1, texture->face_mask});
    // Without libpng the VTP keeps its coordinates; ParaView then shows no texture.
    std::string png_error;
    texture_file = name + "_" + seeded.kind() + "_texture.png";
    if (!FAS::IO::write_PNG((out / texture_file).string(), texture->texture, &png_error)) {
      std::cerr << name << ": " << png_error << "\n";
      texture_file.clear();
    }
  }
  const Mesh& surfaces = seeded.mesh();
  if (!write_mesh_VTP((out / (name + "_" + seeded.kind() + ".vtp")).string(), surfaces, point_data, cell_data,
                      Active_scalars{seeded.path_surfaces ? "time" : "t", ""}, &error))
    return false;
  if (!scene.unsteady)
    return true;
  const auto time = surfaces.property_map<Mesh::Vertex_index, double>("v:time").first;
  std::vector<double> vertex_time;
  for (Mesh::Vertex_index v : surfaces.vertices())
    vertex_time.push_back(time[v]);
  const Unsteady_run& run = *scene.unsteady;
  return write_growing_path_surfaces(out, name, surfaces, vertex_time, point_data, cell_data,
                                     run.series.times, run.time, run.time + run.duration, error);
}

// The flux of the seeded surfaces in the flow they saw, per face and in all, a check of the
// integration; a surface whose front tore and met itself at a vertex (non-manifold there) has
// none, and the rest is written all the same.
std::pair<std::vector<double>, std::optional<FAS::Normalized_flux>> seeded_flux(const std::string& name,
                                                                                const Seeded_surfaces& seeded)
{
  if (seeded.mesh().is_empty())
    return {};
  try {
    return {face_fluxes(seeded.mesh(), seeded.flow), FAS::normalized_flux(seeded.mesh(), seeded.flow)};
  } catch (const std::exception& e) {
    std::cerr << name << ": the " << seeded.kind() << "' flux is not measured: " << e.what() << "\n";
    return {};
  }
}

// Seed points on an orthogonal surface seed stream lines (Figure 5), or in an unsteady flow path
// lines from the run's time over its duration: added to `view`, as a stage and NAME_stream_lines.vtp
// (NAME_path_lines.vtp).  Returns the number of lines, or nothing (the reason in `error`).
std::optional<std::size_t> seed_lines(const std::string& name, const Mesh& tm, const Scene& scene,
                                      const std::filesystem::path& out, Scene_view& view,
                                      std::vector<Stage>& stages, std::string& error)
{
  std::vector<Point> seed_points;
  FAS::sample_seed_points(tm, scene.size / 6, std::back_inserter(seed_points));
  const Stream_lines<Point> lines = scene.unsteady
                                        ? integrate_path_lines(scene.unsteady->series.flow, seed_points,
                                                               scene.unsteady->time, scene.unsteady->duration)
                                        : integrate_stream_lines(scene.flow, seed_points, 2 * scene.size);
  const std::string kind = scene.unsteady ? "path_lines" : "stream_lines";
  view.lines.push_back(to_scene_lines(lines.lines, {0.6, 0.05, 0.05}, 2));
  stages.push_back(
      {name + "_" + kind + ".png",
       flux_view(tm, scene.flow, scene.unsteady ? "path lines" : "stream lines", {view.lines.back()})});
  if (!write_polylines_VTP((out / (name + "_" + kind + ".vtp")).string(), lines.lines, lines.point_data(),
                           lines.cell_data(), Active_scalars{"IntegrationTime", ""}, &error))
    return std::nullopt;
  return lines.lines.size();
}

// The seeding workflow on the aligned surface `tm` of `deformation`: seed curves from its
// parametrization (iso-contours of r, each with its value), one stream surface (unsteady flows:
// path surface) per distinct seed curve (seeded_surfaces.h), and on an orthogonal surface stream
// (path) lines from seed points; all written as VTP, added to `view` (the scene picture's) and to
// `stages` (a stage picture each).  A tangential surface's seeded surfaces carry their LIC-like
// texture (`textured_view`, and the texture image written as `texture_file`, empty when not
// written).  Returns false when a file cannot be written.
bool seed_and_integrate(const std::string& name, Mesh& tm,
                        const FAS::Flow_aligned_deformation<Mesh, Flow>& deformation, const Scene& scene,
                        const std::filesystem::path& out, Scene_view& view, std::vector<Stage>& stages,
                        std::optional<Scene_view>& textured_view, std::string& texture_file)
{
  const bool tangential = deformation.alignment() == FAS::Alignment::TANGENTIAL;
  const Seed_curves seeds = take_seed_curves(tm, deformation);
  const Seeded_surfaces seeded(scene.flow, scene.unsteady, seeds.curves, scene.size / 30, 2 * scene.size);
  for (const std::string& reason : seeded.integrated.skipped_reasons)
    std::cerr << name << ": " << reason << "\n";
  const Mesh& surfaces = seeded.mesh();
  std::string error;
  if (!write_polylines_VTP((out / (name + "_seed_curves.vtp")).string(), seeds.curves,
                           {{"r", 1, seeds.point_values}}, {{"r", 1, seeds.curve_values}},
                           Active_scalars{"r", "r"}, &error)) {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  const auto [face_flux, surfaces_flux] = seeded_flux(name, seeded);
  std::optional<Flow_texture_of_mesh> texture;
  if (tangential && !surfaces.is_empty())
    texture = seeded_texture(name, seeded);
  if (!surfaces.is_empty() &&
      !write_seeded_surfaces(name, seeded, texture, face_flux, scene, out, texture_file, error)) {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  std::optional<std::size_t> number_of_lines = 0;
  if (!tangential && !(number_of_lines = seed_lines(name, tm, scene, out, view, stages, error))) {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  const Scene_lines seed_curve_lines = to_scene_lines(seeds.curves, {0.02, 0.02, 0.02}, 4);
  view.lines.push_back(seed_curve_lines);
  stages.push_back({name + "_seed_curves.png",
                    flux_view(tm, scene.flow, "seed curves (iso-contours of r)", {seed_curve_lines})});
  if (!surfaces.is_empty()) { // the seeded surfaces, translucent, beyond the aligned patch
    view.surfaces.push_back(to_scene_surface(surfaces, {}, {0.98, 0.8, 0.3}, 0.6));
    stages.push_back(seeded_surfaces_stage(name, seeded, seed_curve_lines));
  }
  const std::string what = seeded.path_surfaces ? "path surface" : "stream surface";
  if (texture)
    textured_view =
        Scene_view{{textured_surface(surfaces, std::move(*texture))}, {}, what + ", LIC-like texture"};
  std::cout << name << ": " << seeds.curves.size() << " seed curves, "
            << seeded.integrated.number_of_surfaces() << " distinct " << what << "s of "
            << surfaces.number_of_faces() << " triangles (flux "
            << (surfaces_flux ? *surfaces_flux : FAS::Normalized_flux()) << ")"
            << (tangential ? std::string()
                           : ", " + std::to_string(*number_of_lines) +
                                 (scene.unsteady ? " path" : " stream") + " lines")
            << "\n";
  return true;
}

// The flux speaks only for the faces where the flow was sampled.  When more than 5% of the area
// of the surface had no flow, at the start, during the alignment or at the end, says so and what
// to do about it.
void warn_unsampled(const std::string& name, const std::vector<FAS::Iteration_report>& iterations,
                    const FAS::Normalized_flux& final_flux)
{
  constexpr double largest_unsampled = 0.05;
  double worst = final_flux.sampled_area_fraction;
  for (const auto& r : iterations)
    worst = std::min(worst, r.normalized_flux.sampled_area_fraction);
  if (1 - worst <= largest_unsampled)
    return;
  const auto percent = [](double sampled) {
    return std::to_string(int(std::lround(100 * (1 - sampled)))) + "%";
  };
  std::cerr << "warning: " << name << " surface: " << percent(worst)
            << " of its area had no flow sample (outside the domain, or a zero or non-finite velocity)"
            << " during the alignment, " << percent(final_flux.sampled_area_fraction) << " at the end; "
            << (final_flux.value ? "the flux is measured on the rest only" : "there is no flux value")
            << ".  Place the patch inside the flow (--center, --normal) or make it smaller (--size); with "
               "a data file, check its domain, mask array and velocity array (--array).\n";
}

// The scene picture of one alignment: the initial patch (left) beside the aligned one with its
// seed curves, stream surfaces and stream lines (`aligned`, right), both coloured by the
// normalized flux, with the obstacle and the outline of the domain (analytic flows: of the
// scene), seen by the oblique camera.
Scene_picture scene_picture(const Scene& scene, const Mesh& initial, Scene_view aligned,
                            const std::string& kind, std::optional<Scene_view> textured)
{
  CGAL::Bbox_3 focus = CGAL::bbox_3(initial.points().begin(), initial.points().end());
  for (const Scene_view* view : {&aligned})
    for (const Scene_surface& s : view->surfaces)
      for (const auto& p : s.points)
        focus += CGAL::Bbox_3(p[0], p[1], p[2], p[0], p[1], p[2]);
  focus = expanded(focus, 0.1);
  // The obstacle near the scene, whole when it is not too large: where the flow is not defined.
  // In data, inside its box (just inside: outside it the flow is not defined either, and its
  // faces are no obstacle).
  CGAL::Bbox_3 around = expanded(focus, 0.5);
  if (scene.domain)
    around = box_intersection(around, expanded(*scene.domain, -0.04));
  Flow_domain_lattice obstacle = sample_flow_domain<Point>(scene.flow, around, 100);
  double obstacle_y = 0, obstacle_points = 0;
  for (std::size_t i = 0; i < obstacle.defined.size(); ++i)
    if (obstacle.defined[i] == 0) {
      const std::size_t nx = std::size_t(obstacle.dimensions[0]), ny = std::size_t(obstacle.dimensions[1]);
      const double x = obstacle.origin[0] + double(i % nx) * obstacle.spacing[0],
                   y = obstacle.origin[1] + double((i / nx) % ny) * obstacle.spacing[1],
                   z = obstacle.origin[2] + double(i / (nx * ny)) * obstacle.spacing[2];
      focus += CGAL::Bbox_3(x, y, z, x, y, z);
      obstacle_y += y;
      ++obstacle_points;
    }
  // Seen from the side of the initial patch, so that the obstacle does not hide it.
  const CGAL::Bbox_3 patch = CGAL::bbox_3(initial.points().begin(), initial.points().end());
  const double side =
      obstacle_points > 0 && (patch.ymin() + patch.ymax()) / 2 > obstacle_y / obstacle_points ? 1 : -1;
  if (scene.domain) // no farther than the data
    focus = box_intersection(focus, *scene.domain);
  // The domain's outline where the view shows it: a domain much larger than the scene (a
  // channel around its obstacle) would draw edges across the whole picture, so it is cut at a
  // margin around the scene (its walls near the scene stay where they are).
  const CGAL::Bbox_3 outline_box =
      scene.domain ? box_intersection(*scene.domain, expanded(focus, 0.15)) : focus;
  const Scene_lines outline = box_outline(outline_box);
  Scene_picture picture;
  picture.outline_bounds = {outline_box.xmin(), outline_box.xmax(), outline_box.ymin(),
                            outline_box.ymax(), outline_box.zmin(), outline_box.zmax()};
  picture.views.push_back(flux_view(initial, scene.flow, "initial " + kind + " patch", {outline}));
  aligned.lines.push_back(outline);
  aligned.title = std::string(kind == "tangential" ? "grown, " : "") + "aligned, seeded";
  picture.views.push_back(std::move(aligned));
  if (textured) { // a third view: the stream surface textured (the paper's Figure 8)
    textured->lines.push_back(outline);
    picture.views.push_back(std::move(*textured));
    picture.width = 1800;
  }
  picture.scalar_name = "normalized_flux";
  // The obstacle drawn over the whole outlined box, so that it ends on the outline (capped there,
  // render_scene_PNG.h) rather than on the edge of the region searched for it above.  Just
  // inside a data box: on its faces the flow may not be sampled, which would draw them.
  if (!obstacle.defined.empty())
    obstacle = sample_flow_domain<Point>(scene.flow,
                                         scene.domain ? expanded(outline_box, -0.005) : outline_box, 100);
  picture.obstacle = std::move(obstacle);
  picture.camera = oblique_camera(
      focus, double(picture.width) / double(picture.views.size()) / double(picture.height), side);
  return picture;
}

// The stages before the seeding: the initial patch, the aligned one, and a tangential one with
// the LIC-like texture of Section 6 (2 repeats per patch size).
std::vector<Stage> aligned_stages(const std::string& name, const Mesh& initial, const Mesh& tm,
                                  const Scene& scene)
{
  const std::string aligned_title = name == "tangential" ? "grown, aligned" : "aligned";
  std::vector<Stage> stages{
      {name + "_initial.png", flux_view(initial, scene.flow, "initial " + name + " patch")},
      {name + "_aligned.png", flux_view(tm, scene.flow, aligned_title)}};
  if (name != "tangential")
    return stages;
  try {
    stages.push_back({name + "_textured.png",
                      Scene_view{{textured_surface(tm, flow_texture_of_mesh(tm, scene.flow, 2 / scene.size))},
                                 {},
                                 aligned_title + ", LIC-like texture"},
                      ""});
  } catch (const std::exception& e) {
    std::cerr << name << ": the aligned surface gets no texture: " << e.what() << "\n";
  }
  return stages;
}

// Pictures (PNG, through VTK) are extras: without a display the job goes on without them, and
// the first failure (the reason is the same for all) stops the rest.  The scene NAME_scene.png
// (the paper's Figures 4 and 5: the initial patch beside the aligned one and what it seeds),
// then each stage in the scene's context.
void write_pictures(const std::filesystem::path& out, const std::string& name, const Scene_picture& picture,
                    const std::vector<Stage>& stages)
{
  if (!write_scene_picture(out / (name + "_scene.png"), picture))
    return;
  for (const Stage& stage : stages)
    if (!write_scene_picture(out / stage.file,
                             stage_picture(picture, stage.view, stage.scalar_name, stage.scalar_range)))
      return;
}

struct Run_summary {
  std::string alignment;
  std::size_t faces = 0;
  FAS::Alignment_report report;
  FAS::Normalized_flux initial_flux;
  double mean_gtransf_ms = 0, mean_solve_ms = 0;
  Paraview_run paraview; // what open_in_paraview.py opens of this run, and its camera
};

std::optional<Run_summary> align(const std::string& flow_name, const Scene& scene, FAS::Alignment alignment,
                                 std::size_t faces, const std::filesystem::path& out)
{
  const bool tangential = alignment == FAS::Alignment::TANGENTIAL;
  const std::string name = tangential ? "tangential" : "orthogonal";
  Mesh tm;
  FAS::make_planar_patch(tm, tangential ? scene.tangential_center : scene.orthogonal_center,
                         tangential ? scene.tangential_normal : scene.orthogonal_normal, scene.size,
                         scene.size, faces);
  if (!write_surface(out / (name + "_initial"), tm, scene.flow))
    return std::nullopt;
  const Mesh initial = tm;
  // The iterations as time steps of a ParaView collection, from the initial patch on.
  Surface_collection collection(out, name);
  collection.add(tm, scene.flow);

  std::vector<FAS::Iteration_report> iterations;
  // The flux of the surface each iteration made: an iteration's report measures the surface it
  // started from, and after a growth step that is not the surface the previous iteration made.
  std::vector<FAS::Normalized_flux> flux_after;
  Progress progress(name);
  FAS::Flow_aligned_deformation<Mesh, Flow> deformation(
      tm, scene.flow, alignment,
      CGAL::parameters::number_of_iterations(200)
          .visitor([&](const FAS::Iteration_report& r) {
            iterations.push_back(r);
            flux_after.push_back(FAS::normalized_flux(tm, scene.flow));
            progress(r);
            collection.add(tm, scene.flow);
          })
          .callback(std::function<bool(double)>([&](double done) { return progress(done); })));
  Run_summary summary;
  summary.alignment = name;
  summary.faces = tm.number_of_faces();
  summary.report = deformation.run();
  // The first iteration reports the flux of the surface it started from: the initial patch.
  summary.initial_flux = iterations.front().normalized_flux;
  if (tangential) { // grown across the flow before its seed curves are taken (Figure 4, top)
    const Growth_across_flow growth = grow_across_flow(deformation, scene.size / 2, 2);
    if (!growth.stopped_because.empty())
      std::cerr << name << ": not grown further across the flow: " << growth.stopped_because << "\n";
    std::cout << name << ": grown across the flow in " << growth.number_of_steps << " steps by "
              << growth.number_of_new_faces << " faces, realigned in "
              << growth.alignment.number_of_iterations << " iterations\n";
    if (growth.number_of_steps > 0) {
      summary.report.number_of_iterations += growth.alignment.number_of_iterations;
      summary.report.converged = growth.alignment.converged;
      summary.report.normalized_flux = growth.alignment.normalized_flux;
      summary.report.factor_ms += growth.alignment.factor_ms;
    }
  }
  for (const auto& r : iterations) {
    summary.mean_gtransf_ms += r.gradient_transformation_ms / iterations.size();
    summary.mean_solve_ms += r.solve_ms / iterations.size();
  }
  if (!collection.write_pvd()) {
    std::cerr << "error: " << collection.error() << "\n";
    return std::nullopt;
  }
  if (!write_surface(out / (name + "_aligned"), tm, scene.flow))
    return std::nullopt;
  std::vector<Stage> stages = aligned_stages(name, initial, tm, scene);
  Scene_view aligned_view = flux_view(tm, scene.flow, "aligned");
  std::optional<Scene_view> textured_view;
  std::string texture_file;
  if (!seed_and_integrate(name, tm, deformation, scene, out, aligned_view, stages, textured_view,
                          texture_file))
    return std::nullopt;
  const bool has_stream_surfaces = aligned_view.surfaces.size() > 1, has_stream_lines = !tangential;
  const Scene_picture picture = scene_picture(scene, initial, aligned_view, name, std::move(textured_view));
  write_pictures(out, name, picture, stages);
  // The obstacle of the picture, for ParaView (an extra, as the pictures).
  std::string obstacle_error;
  const bool has_obstacle = !picture.obstacle.defined.empty() &&
                            write_obstacle_VTP(out / (name + "_obstacle.vtp"), picture, obstacle_error);
  if (!obstacle_error.empty())
    std::cerr << name << ": " << obstacle_error << "\n";

  auto csv = open_output(out / (name + "_flux.csv"));
  if (!csv)
    return std::nullopt;
  {
    std::ostream& os = *csv;
    // One row per surface of the .pvd collection: row 0 the initial patch, row k the surface
    // iteration k made, with that iteration's figures; the last row is the final surface.  No
    // flux value (no face sampled) is an empty field, not 0.
    os << "iteration,normalized_flux,sampled_area_fraction,max_rotation_angle,max_vertex_step,folds,"
          "outside_samples,invalid_samples,zero_samples,gtransf_ms,solve_ms,converged\n";
    os << 0 << ',' << csv_field(summary.initial_flux.value) << ','
       << summary.initial_flux.sampled_area_fraction << ",,,,,,,,,\n";
    for (std::size_t k = 0; k < iterations.size(); ++k) {
      const FAS::Iteration_report& r = iterations[k];
      os << r.iteration << ',' << csv_field(flux_after[k].value) << ',' << flux_after[k].sampled_area_fraction
         << ',' << r.max_rotation_angle << ',' << r.max_vertex_step << ',' << r.number_of_folds << ','
         << r.number_of_outside_samples << ',' << r.number_of_invalid_samples << ','
         << r.number_of_zero_samples << ',' << r.gradient_transformation_ms << ',' << r.solve_ms << ','
         << (r.converged ? 1 : 0) << '\n';
    }
  }
  summary.paraview =
      Paraview_run{name,         picture.camera,   has_stream_surfaces,    has_stream_lines, has_obstacle,
                   texture_file, scene.field_file, picture.outline_bounds, std::nullopt};
  if (scene.unsteady)
    summary.paraview.path_times = {scene.unsteady->time, scene.unsteady->time + scene.unsteady->duration};
  warn_unsampled(name, iterations, summary.report.normalized_flux);
  if (!summary.report.converged)
    std::cerr
        << "warning: " << name << " surface: not converged after " << summary.report.number_of_iterations
        << " iterations (flux " << summary.report.normalized_flux
        << "): it may still be moving or folding.  Try a smaller patch (--size), a finer one (--faces), "
           "or another place (--center, --normal).\n";
  std::cout << flow_name << ", " << name << ": " << summary.faces << " faces, flux " << summary.initial_flux
            << " -> " << summary.report.normalized_flux << " in " << summary.report.number_of_iterations
            << " iterations (" << (summary.report.converged ? "converged" : "not converged") << ")\n";
  return summary;
}

// summary.json: what was asked (the command line's inputs; null where the default was taken),
// the package's version, each alignment with the placement it used and what it achieved, and
// every file the run wrote (summary.json too), relative to the output folder.
bool write_summary(const std::filesystem::path& path, const nlohmann::ordered_json& inputs,
                   const std::string& flow_name, const Scene& scene, const std::vector<Run_summary>& runs,
                   const std::vector<std::string>& files)
{
  const auto number = [](const std::optional<double>& x) {
    return x ? nlohmann::json(*x) : nlohmann::json();
  };
  const auto xyz = [](const auto& p) { return nlohmann::json::array({p.x(), p.y(), p.z()}); };
  nlohmann::ordered_json summary;
  summary["program"] = "align_patch";
  summary["package"] = "Flow_aligned_surfaces";
  summary["version"] = package_version();
  summary["inputs"] = inputs;
  summary["flow"] = flow_name;
  if (scene.unsteady) {
    const Unsteady_run& run = *scene.unsteady;
    summary["time_series"] = nlohmann::ordered_json{{"steps", run.series.times.size()},
                                                    {"start_time", run.series.start_time()},
                                                    {"end_time", run.series.end_time()},
                                                    {"time", run.time},
                                                    {"duration", run.duration}};
  }
  summary["runs"] = nlohmann::json::array();
  for (const Run_summary& r : runs) {
    const bool tangential = r.alignment == "tangential";
    summary["runs"].push_back(nlohmann::ordered_json{
        {"alignment", r.alignment},
        {"center", xyz(tangential ? scene.tangential_center : scene.orthogonal_center)},
        {"normal", xyz(tangential ? scene.tangential_normal : scene.orthogonal_normal)},
        {"size", scene.size},
        {"faces", r.faces},
        {"iterations", r.report.number_of_iterations},
        {"converged", r.report.converged},
        {"initial_normalized_flux", number(r.initial_flux.value)},
        {"initial_sampled_area_fraction", r.initial_flux.sampled_area_fraction},
        {"final_normalized_flux", number(r.report.normalized_flux.value)},
        {"final_sampled_area_fraction", r.report.normalized_flux.sampled_area_fraction},
        {"factor_ms", r.report.factor_ms},
        {"mean_gtransf_ms", r.mean_gtransf_ms},
        {"mean_solve_ms", r.mean_solve_ms}});
  }
  std::vector<std::string> written = files;
  written.push_back(path.filename().string());
  std::sort(written.begin(), written.end());
  summary["files"] = written;
  std::ofstream os(path);
  os << summary.dump(2) << "\n";
  if (!os.flush()) {
    std::cerr << "error: cannot write " << path.string() << "\n";
    return false;
  }
  return true;
}

int main(int argc, char** argv)
{
  std::string flow_name, field_file, array, alignment = "both";
  Face_count faces{5000};
  Placement placement;
  Times times;
  Output_options output;
  // --center, --normal and --size are optional: without them the flow's own placement is taken.
  const auto set_center = [&](const Triple& t) { placement.center = t.value; };
  const auto set_normal = [&](const Triple& t) { placement.normal = t.value; };
  const auto set_size = [&](const Positive_number& x) { placement.size = x.value; };
  const auto set_time = [&](double t) { times.time = t; };
  const auto set_duration = [&](const Positive_number& x) { times.duration = x.value; };
  const std::string flow_help =
      std::string("a built-in analytic flow: ") + built_in_flow_names() + " (default: cylinder)";
  po::options_description options = option_group("Options (lengths and positions in the flow's units)");
  options.add_options()("flow", po::value(&flow_name)->value_name("NAME"), flow_help.c_str());
  options.add_options()(
      "field", po::value(&field_file)->value_name("FILE"),
      "a velocity field read from a data file instead of --flow: legacy VTK, VTK XML "
      "(.vti, .vtu, .vts), AmiraMesh (.am), NRRD (.nrrd, .nhdr), with an optional mask "
      "array 'inside'; or a time series, a ParaView collection (.pvd) of VTK XML files or a "
      "folder of VTK XML files whose names end in their time (NAME_<time>.vti): the patches "
      "aligned at --time, path surfaces and path lines over --duration");
  options.add_options()("array", po::value(&array)->value_name("NAME"),
                        "the velocity array of --field (default: the file's first vector array)");
  options.add_options()(
      "time", po::value<double>()->value_name("T")->notifier(set_time),
      "with a time series: the time of the flow the patches are aligned to, and the release "
      "time of the path surfaces (default: the first time step)");
  options.add_options()("duration", po::value<Positive_number>()->value_name("D")->notifier(set_duration),
                        "with a time series: how long the path surfaces and path lines are integrated "
                        "(default: up to the last time step)");
  options.add_options()(
      "alignment", po::value(&alignment)->default_value(alignment)->value_name("MODE"),
      "tangential (a stream surface), orthogonal (a seeding surface) or both (one of each)");
  options.add_options()("faces", po::value(&faces)->default_value(faces)->value_name("N"),
                        "the number of triangles of the patch (2 to 10000000)");
  options.add_options()("center", po::value<Triple>()->value_name("X,Y,Z")->notifier(set_center),
                        "the centre of the patch (default: the flow's own placement; with --field, near "
                        "the obstacle (where the flow is not defined) or the largest vorticity)");
  options.add_options()("normal", po::value<Triple>()->value_name("X,Y,Z")->notifier(set_normal),
                        "the normal of the patch, any length (default: the flow's own placement; with "
                        "--field, 30 degrees off the aligned orientation at the centre)");
  options.add_options()("size", po::value<Positive_number>()->value_name("S")->notifier(set_size),
                        "the side of the square patch (default: the flow's own; with --field, a quarter of "
                        "the data box's smallest side)");
  options.add(output_options(output, "flow_aligned_surfaces_output"));
  const Program_help help{
      "align_patch [options]",
      "The package's main job: places a square patch in a flow, aligns it tangentially (a stream surface)\n"
      "and orthogonally (a seeding surface) by the Poisson-based deformation, and writes into the output\n"
      "folder, for each alignment: the initial and aligned surfaces (PLY, and VTP with the velocity and\n"
      "the per-face normalized flux), the iterations (a ParaView collection, .pvd), the flux of every\n"
      "iteration (CSV), seed curves, one stream surface per distinct seed curve and, for the orthogonal\n"
      "one, stream lines (VTP), pictures (PNG, when built with VTK's rendering: the scene of each\n"
      "alignment, *_scene.png, and one picture per stage in the scene's context: *_initial.png,\n"
      "*_aligned.png, *_seed_curves.png, *_stream_surfaces.png, orthogonal_stream_lines.png,\n"
      "tangential_textured.png), open_in_paraview.py (every output in ParaView, as the pictures show it)\n"
      "and summary.json (the inputs, the package's version, the results, every file written).  With a\n"
      "time series (--field SERIES.pvd): the flow at --time aligns the patches, and their seeds give path\n"
      "surfaces (*_path_surfaces.vtp, and as they grow over time: *_path_surfaces.pvd) and path lines\n"
      "(orthogonal_path_lines.vtp) over --duration instead of stream surfaces and lines.  Progress\n"
      "lines (iteration, flux, elapsed time) go to standard output.  Exit status: 0 on success, 1 when\n"
      "the run fails or the output folder is refused (nothing is written then), 2 for a bad command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options))
    return *status;
  if (!flow_name.empty() && !field_file.empty()) {
    std::cerr << "error: --flow and --field exclude each other: give one flow\n";
    return 2;
  }
  if ((times.time || times.duration) && !is_time_series(field_file)) {
    std::cerr << "error: --time and --duration are for a time series: give one with --field SERIES.pvd\n";
    return 2;
  }
  if (times.time && !std::isfinite(*times.time)) {
    std::cerr << "error: --time: expected a finite time, got " << *times.time << "\n";
    return 2;
  }
  if (!array.empty() && field_file.empty()) {
    std::cerr << "error: --array names a velocity array of --field, and no --field is given\n";
    return 2;
  }
  if (alignment != "tangential" && alignment != "orthogonal" && alignment != "both") {
    std::cerr << "error: --alignment: expected tangential, orthogonal or both, got '" << alignment << "'\n";
    return 2;
  }
  // What was asked, for summary.json; null where the default is taken.
  const auto given = [](const auto& x) { return x ? nlohmann::json(*x) : nlohmann::json(); };
  const nlohmann::ordered_json inputs{
      {"flow",
       field_file.empty() ? nlohmann::json(flow_name.empty() ? "cylinder" : flow_name) : nlohmann::json()},
      {"field", field_file.empty() ? nlohmann::json()
                                   : nlohmann::json(std::filesystem::absolute(field_file).string())},
      {"array", array.empty() ? nlohmann::json() : nlohmann::json(array)},
      {"center", given(placement.center)},
      {"normal", given(placement.normal)},
      {"size", given(placement.size)},
      {"time", given(times.time)},
      {"duration", given(times.duration)},
      {"faces", faces.value},
      {"alignment", alignment}};
  if (flow_name.empty())
    flow_name = "cylinder";

  std::optional<Scene> scene;
  if (!field_file.empty()) {
    scene = read_data_scene(field_file, array, placement, times);
    if (!scene)
      return 1;
    flow_name = std::filesystem::path(field_file).filename().string();
  }
  else {
    scene = make_scene(flow_name);
    if (!scene) {
      std::cerr << "error: --flow: unknown flow '" << flow_name << "' (the flows: " << built_in_flow_names()
                << ")\n";
      return 2;
    }
    if (placement.center)
      scene->tangential_center = scene->orthogonal_center =
          Point((*placement.center)[0], (*placement.center)[1], (*placement.center)[2]);
    if (placement.normal)
      scene->tangential_normal = scene->orthogonal_normal =
          Vector((*placement.normal)[0], (*placement.normal)[1], (*placement.normal)[2]);
    if (placement.size)
      scene->size = *placement.size;
  }
  // Everything goes to a staging folder, moved into place only when the whole run succeeded.
  Output_folder folder;
  if (!folder.open(output, {field_file}))
    return 1;
  const std::filesystem::path& out = folder.path();

  std::vector<Run_summary> runs;
  try {
    for (const auto& [name, value] : {std::pair{"tangential", FAS::Alignment::TANGENTIAL},
                                      std::pair{"orthogonal", FAS::Alignment::ORTHOGONAL}}) {
      if (alignment != "both" && alignment != name)
        continue;
      const auto run = align(flow_name, *scene, value, faces.value, out);
      if (!run)
        return 1;
      runs.push_back(*run);
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }

  // A pvpython script that opens every output as the pictures show it.
  std::vector<Paraview_run> paraview_runs;
  for (const Run_summary& r : runs)
    paraview_runs.push_back(r.paraview);
  if (std::string error; !write_paraview_script(out, paraview_runs, error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (!write_summary(out / "summary.json", inputs, flow_name, *scene, runs, folder.files()) ||
      !folder.commit())
    return 1;
  std::cout << "results written to " << folder.destination().string() << "\n";
  return 0;
}
