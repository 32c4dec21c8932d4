// The package's main job: place a planar patch in a built-in flow, align it
// tangentially (a stream surface) or orthogonally (a seeding surface), and write
// what a user opens afterwards: the initial and aligned surfaces as PLY and VTP
// (ParaView), the normalized flux of every iteration as CSV, and a JSON summary; and, when built
// with VTK rendering and a display (or Xvfb) is there, pictures of the initial and aligned
// surfaces coloured by flux and of the tangential one with its LIC-like texture (PNG).
// Then the seeding workflow of the paper's Figures 4 and 5 on each aligned surface: its
// parametrization (with the deformation's own factorization) gives seed curves (iso-contours of
// r, VTP), each seeds a stream surface integrated forward and backward (VTP with the seed
// parameter u and the time t), and on the orthogonal surface seed points seed stream lines (VTP);
// pictures of the seed curves on the surface and of the stream surfaces.
//
// Usage: align_patch [--flow NAME | --field FILE [--array NAME]]
//                    [--alignment tangential|orthogonal|both] [--faces N] [--center X,Y,Z]
//                    [--normal X,Y,Z] [--size S] [--output DIR] [--overwrite] [--quiet]
// (`align_patch --help` lists the options with their defaults.)
// Flows: cylinder (default), point-source, sphere, helical, hill, burgers, abc, tornado.
// A data file is any file IO::read_flow_field() reads (legacy VTK grids and cells, VTK XML
// .vti/.vtu/.vts when built with VTK, AmiraMesh, NRRD) with a velocity array (and an optional
// mask array "inside"); without --center the patch is placed at the middle of the data's box,
// and without --normal it faces the flow there (orthogonal) or contains it (tangential).

#include "command_line.h"
#include "demo_support.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
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

struct Placement {
  std::optional<std::array<double, 3>> center, normal;
  std::optional<double> size;
};

// A scene in a flow read from a file: the patch at the given place or in the middle of the data.
std::optional<Scene> make_data_scene(const std::string& file, const std::string& array,
                                     const Placement& placement)
{
  const std::optional<FAS::Sampled_flow_field_3<Kernel>> field = read_data_field(file, array);
  if (!field)
    return std::nullopt;
  const CGAL::Bbox_3 box = field->bbox();
  const Point center = placement.center
                           ? Point((*placement.center)[0], (*placement.center)[1], (*placement.center)[2])
                           : Point((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                                   (box.zmin() + box.zmax()) / 2);
  const auto v = (*field)(center);
  if (!v || v->squared_length() == 0) {
    std::cerr << "error: --center: the flow of " << file << " is not defined (or zero) at " << center
              << "; place the patch in the fluid with --center X,Y,Z\n";
    return std::nullopt;
  }
  const double size =
      placement.size
          ? *placement.size
          : 0.25 * (std::min)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  Vector orthogonal_normal = *v, tangential_normal = CGAL::cross_product(*v, Vector(0, 0, 1));
  if (tangential_normal.squared_length() < 1e-12 * v->squared_length())
    tangential_normal = CGAL::cross_product(*v, Vector(1, 0, 0));
  if (placement.normal)
    orthogonal_normal = tangential_normal =
        Vector((*placement.normal)[0], (*placement.normal)[1], (*placement.normal)[2]);
  return Scene{Flow(*field), center, center, tangential_normal, orthogonal_normal, size};
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

// The seeding workflow on the aligned surface `tm` of `deformation`: seed curves from its
// parametrization, a stream surface from each (forward and backward, arc-length time lines up to
// twice the patch size), and stream lines from seed points on an orthogonal surface; all written
// as VTP, with pictures when `pictures`.  Returns false when a file cannot be written.
bool seed_and_integrate(const std::string& name, Mesh& tm,
                        const FAS::Flow_aligned_deformation<Mesh, Flow>& deformation, const Scene& scene,
                        const std::filesystem::path& out, bool pictures)
{
  const bool tangential = deformation.alignment() == FAS::Alignment::TANGENTIAL;
  auto r = tm.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
  auto s = tm.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
  if (tangential)
    deformation.parametrize_tangential(r, s);
  else
    deformation.parametrize_orthogonal(r, s);
  std::vector<Polyline> seed_curves;
  FAS::extract_iso_contours(tm, r, FAS::evenly_spaced_iso_values(tm, r, 3), std::back_inserter(seed_curves));

  Mesh surfaces;
  auto u = surfaces.add_property_map<Mesh::Vertex_index, double>("v:u", 0).first;
  auto t = surfaces.add_property_map<Mesh::Vertex_index, double>("v:t", 0).first;
  // Forward and backward in one surface per seed curve (t < 0 on the backward half).
  const auto np = FAS::parameters::front_spacing(
      scene.size / 30,
      FAS::parameters::arc_length_time_lines(
          true, FAS::parameters::max_length(
                    2 * scene.size, FAS::parameters::integration_direction(
                                        FAS::Integration_direction::BOTH,
                                        FAS::parameters::seed_parameter_map(
                                            u, FAS::parameters::integration_time_map(t))))));
  for (const Polyline& seed : seed_curves) {
    if (seed.size() < 2)
      continue;
    try {
      FAS::integrate_stream_surface(scene.flow, seed, surfaces, np);
    } catch (const std::exception& e) { // a degenerate contour: skip it, say why
      std::cerr << name << ": seed curve skipped: " << e.what() << "\n";
    }
  }
  std::vector<double> us, ts;
  for (Mesh::Vertex_index v : surfaces.vertices()) {
    us.push_back(u[v]);
    ts.push_back(t[v]);
  }
  std::string error;
  bool ok =
      FAS::IO::write_VTP_polylines((out / (name + "_seed_curves.vtp")).string(), seed_curves, {}, {}, &error);
  ok = ok && (surfaces.is_empty() || write_surface_VTP(out / (name + "_stream_surfaces.vtp"), surfaces,
                                                       scene.flow, {{"u", 1, us}, {"t", 1, ts}}));
  std::size_t number_of_lines = 0;
  if (ok && !tangential) { // seed points on the orthogonal surface seed stream lines (Figure 5)
    std::vector<Point> seed_points;
    FAS::sample_seed_points(tm, scene.size / 6, std::back_inserter(seed_points));
    std::vector<Polyline> lines;
    for (const Point& seed : seed_points) {
      Polyline line;
      FAS::integrate_streamline(
          scene.flow, seed, std::back_inserter(line),
          FAS::parameters::max_length(
              2 * scene.size, FAS::parameters::integration_direction(FAS::Integration_direction::BOTH)));
      if (line.size() > 1)
        lines.push_back(std::move(line));
    }
    number_of_lines = lines.size();
    ok = FAS::IO::write_VTP_polylines((out / (name + "_stream_lines.vtp")).string(), lines, {}, {}, &error);
    if (ok && pictures) { // the stream lines through the seeding surface (Figure 5)
      write_picture(out / (name + "_stream_lines.png"), tm, flux_with_polylines(tm, scene.flow, lines));
    }
  }
  if (!ok) {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  std::cout << name << ": " << seed_curves.size() << " seed curves, stream surfaces of "
            << surfaces.number_of_faces() << " triangles (flux "
            << (surfaces.is_empty() ? FAS::Normalized_flux() : FAS::normalized_flux(surfaces, scene.flow))
            << ")" << (tangential ? std::string() : ", " + std::to_string(number_of_lines) + " stream lines")
            << "\n";
  if (pictures) {
    if (write_picture(out / (name + "_seed_curves.png"), tm,
                      flux_with_polylines(tm, scene.flow, seed_curves)) &&
        !surfaces.is_empty()) {
      // The stream surfaces coloured by their time-line parameter |t| (Figure 3's time lines).
      Surface_rendering by_time;
      double largest = 0;
      for (Mesh::Face_index f : surfaces.faces()) {
        double mean = 0;
        for (Mesh::Vertex_index v : vertices_around_face(surfaces.halfedge(f), surfaces))
          mean += std::abs(t[v]) / 3;
        by_time.face_scalars.push_back(mean);
        largest = std::max(largest, mean);
      }
      by_time.scalar_range = {0, largest > 0 ? largest : 1};
      write_picture(out / (name + "_stream_surfaces.png"), surfaces, by_time);
    }
  }
  tm.remove_property_map(r);
  tm.remove_property_map(s);
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

struct Run_summary {
  std::string alignment;
  std::size_t faces = 0;
  FAS::Alignment_report report;
  FAS::Normalized_flux initial_flux;
  double mean_gtransf_ms = 0, mean_solve_ms = 0;
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
  // Pictures (PNG, through VTK) are extras: without a display the job goes on without them.
  bool pictures = write_flux_picture(out / (name + "_initial.png"), tm, scene.flow);

  std::vector<FAS::Iteration_report> iterations;
  Progress progress(name);
  FAS::Flow_aligned_deformation<Mesh, Flow> deformation(
      tm, scene.flow, alignment,
      CGAL::parameters::number_of_iterations(200).visitor([&](const FAS::Iteration_report& r) {
        iterations.push_back(r);
        progress(r);
      }));
  Run_summary summary;
  summary.alignment = name;
  summary.faces = tm.number_of_faces();
  summary.report = deformation.run();
  // The first iteration reports the flux of the surface it started from: the initial patch.
  summary.initial_flux = iterations.front().normalized_flux;
  for (const auto& r : iterations) {
    summary.mean_gtransf_ms += r.gradient_transformation_ms / iterations.size();
    summary.mean_solve_ms += r.solve_ms / iterations.size();
  }
  if (!write_surface(out / (name + "_aligned"), tm, scene.flow))
    return std::nullopt;
  pictures = pictures && write_flux_picture(out / (name + "_aligned.png"), tm, scene.flow);
  if (pictures && tangential) // the LIC-like texture of the stream surface (Section 6)
    write_textured_picture(out / (name + "_textured.png"), tm, scene.flow, 2 / scene.size);
  if (!seed_and_integrate(name, tm, deformation, scene, out, pictures))
    return std::nullopt;

  auto csv = open_output(out / (name + "_flux.csv"));
  if (!csv)
    return std::nullopt;
  {
    std::ostream& os = *csv;
    // No flux value (no face sampled) is an empty field, not 0.
    os << "iteration,normalized_flux,sampled_area_fraction,max_rotation_angle,max_vertex_step,folds,"
          "outside_samples,invalid_samples,zero_samples,gtransf_ms,solve_ms,converged\n";
    for (const auto& r : iterations)
      os << r.iteration << ',' << csv_field(r.normalized_flux.value) << ','
         << r.normalized_flux.sampled_area_fraction << ',' << r.max_rotation_angle << ',' << r.max_vertex_step
         << ',' << r.number_of_folds << ',' << r.number_of_outside_samples << ','
         << r.number_of_invalid_samples << ',' << r.number_of_zero_samples << ','
         << r.gradient_transformation_ms << ',' << r.solve_ms << ',' << (r.converged ? 1 : 0) << '\n';
    // The flux of the final surface, which no iteration started from.
    os << iterations.size() + 1 << ',' << csv_field(summary.report.normalized_flux.value) << ','
       << summary.report.normalized_flux.sampled_area_fraction << ",,,,,,,,,\n";
  }
  warn_unsampled(name, iterations, summary.report.normalized_flux);
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
  Output_options output;
  // --center, --normal and --size are optional: without them the flow's own placement is taken.
  const auto set_center = [&](const Triple& t) { placement.center = t.value; };
  const auto set_normal = [&](const Triple& t) { placement.normal = t.value; };
  const auto set_size = [&](const Positive_number& x) { placement.size = x.value; };
  const std::string flow_help =
      std::string("a built-in analytic flow: ") + built_in_flow_names() + " (default: cylinder)";
  po::options_description options = option_group("Options (lengths and positions in the flow's units)");
  options.add_options()("flow", po::value(&flow_name)->value_name("NAME"), flow_help.c_str());
  options.add_options()("field", po::value(&field_file)->value_name("FILE"),
                        "a velocity field read from a data file instead of --flow: legacy VTK, VTK XML "
                        "(.vti, .vtu, .vts), AmiraMesh (.am), NRRD (.nrrd, .nhdr), with an optional mask "
                        "array 'inside'");
  options.add_options()("array", po::value(&array)->value_name("NAME"),
                        "the velocity array of --field (default: the file's first vector array)");
  options.add_options()(
      "alignment", po::value(&alignment)->default_value(alignment)->value_name("MODE"),
      "tangential (a stream surface), orthogonal (a seeding surface) or both (one of each)");
  options.add_options()("faces", po::value(&faces)->default_value(faces)->value_name("N"),
                        "the number of triangles of the patch (2 to 10000000)");
  options.add_options()("center", po::value<Triple>()->value_name("X,Y,Z")->notifier(set_center),
                        "the centre of the patch (default: the flow's own placement; with --field, the "
                        "middle of the data's box)");
  options.add_options()("normal", po::value<Triple>()->value_name("X,Y,Z")->notifier(set_normal),
                        "the normal of the patch, any length (default: the flow's own placement; with "
                        "--field, along the flow at the centre for orthogonal, across it for tangential)");
  options.add_options()("size", po::value<Positive_number>()->value_name("S")->notifier(set_size),
                        "the side of the square patch (default: the flow's own; with --field, a quarter of "
                        "the data box's smallest side)");
  options.add(output_options(output, "flow_aligned_surfaces_output"));
  const Program_help help{
      "align_patch [options]",
      "The package's main job: places a square patch in a flow, aligns it tangentially (a stream surface)\n"
      "and orthogonally (a seeding surface) by the Poisson-based deformation, and writes into the output\n"
      "folder, for each alignment: the initial and aligned surfaces (PLY, and VTP with the velocity and\n"
      "the per-face normalized flux), the flux of every iteration (CSV), seed curves, stream surfaces and,\n"
      "for the orthogonal one, stream lines (VTP), pictures (PNG, when built with VTK's rendering), and\n"
      "summary.json (the inputs, the package's version, the results, every file written).  Progress\n"
      "lines (iteration, flux, elapsed time) go to standard output.  Exit status: 0 on success, 1 when\n"
      "the run fails or the output folder is refused (nothing is written then), 2 for a bad command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options))
    return *status;
  if (!flow_name.empty() && !field_file.empty()) {
    std::cerr << "error: --flow and --field exclude each other: give one flow\n";
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
      {"faces", faces.value},
      {"alignment", alignment}};
  if (flow_name.empty())
    flow_name = "cylinder";

  std::optional<Scene> scene;
  if (!field_file.empty()) {
    scene = make_data_scene(field_file, array, placement);
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
  if (!write_summary(out / "summary.json", inputs, flow_name, *scene, runs, folder.files()) ||
      !folder.commit())
    return 1;
  std::cout << "results written to " << folder.destination().string() << "\n";
  return 0;
}
