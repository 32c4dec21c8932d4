// Seed structures from an orthogonal surface (Section 5 of the paper): a disk near a point
// source is aligned orthogonally to the flow (it becomes a piece of a sphere about the
// source), parametrized orthogonally, and cut into seed curves by iso-contours of r; circular
// seed curves come from the heat-method distance, seed points from a spaced sample.  A stream
// surface of the Burgers vortex, parametrized tangentially, gives seed curves that cross the flow.
//
//   seed_curves [--faces N] [--output DIR] [--overwrite] [--quiet]
//
// writes DIR/surface.vtp (r, s and the distance per vertex), DIR/seed_curves.csv and
// DIR/circular_seeds.csv (curve,x,y,z per point), DIR/seed_points.csv (one row per seed, its
// index in the "curve" column), DIR/stream_surface_seed_curves.csv.  (The tests
// SeedCurvesWorkflow.* of test/Flow_aligned_surfaces/test_workflows.cpp check that such seed
// curves are orthogonal to the flow, and that the crossing ones cross it.)

#include "command_line.h"
#include "demo_support.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using namespace fas_demo;
using Polyline = std::vector<Point>;

// Writes "curve,x,y,z" rows; false with the reason in `error` when the file cannot be written.
bool write_polylines_csv(const std::string& filename, const std::vector<Polyline>& curves, std::string& error)
{
  std::ofstream os(filename);
  os.precision(17);
  os << "curve,x,y,z\n";
  for (std::size_t c = 0; c < curves.size(); ++c)
    for (const Point& p : curves[c])
      os << c << "," << p.x() << "," << p.y() << "," << p.z() << "\n";
  if (!os.flush())
    error = "cannot write " + filename;
  return bool(os);
}

int main(int argc, char** argv)
{
  Face_count faces{3000};
  Output_options output;
  po::options_description options = option_group("Options");
  options.add_options()("faces", po::value(&faces)->default_value(faces)->value_name("N"),
                        "the number of triangles of each disk (2 to 10000000)");
  options.add(output_options(output, "seed_curves_output"));
  const Program_help help{
      "seed_curves [options]",
      "Seed structures from an orthogonal surface (Section 5 of the paper): a disk beside a point source\n"
      "is aligned orthogonally and parametrized; seed curves are iso-contours of r, circular seeds\n"
      "iso-contours of the geodesic distance, seed points a spaced sample; a stream surface of the\n"
      "Burgers vortex gives seed curves across the flow.  Writes into the output folder surface.vtp (r,\n"
      "s, distance per vertex), seed_curves.csv, circular_seeds.csv, seed_points.csv and\n"
      "stream_surface_seed_curves.csv (curve,x,y,z per point).  Exit status: 0 on success, 1 when the\n"
      "run fails or the output folder is refused (nothing is written then), 2 for a bad command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options))
    return *status;

  // 1. An orthogonal surface: a tilted disk beside the source becomes a piece of a sphere.
  const FAS::Point_source_flow<Kernel> flow;
  Mesh tm;
  make_orthogonal_disk(tm, flow, faces.value);

  // 2. The orthogonal parametrization (alpha turns the contours) and the circular one.
  auto r = tm.add_property_map<Mesh::Vertex_index, double>("v:r", 0).first;
  auto s = tm.add_property_map<Mesh::Vertex_index, double>("v:s", 0).first;
  auto distance = tm.add_property_map<Mesh::Vertex_index, double>("v:distance", 0).first;
  FAS::parametrize_orthogonal(tm, flow, r, s, FAS::parameters::angle(0.5));
  Mesh::Vertex_index center = *tm.vertices().begin();
  for (auto v : tm.vertices()) // the constrained vertex, where r = 0
    if (std::abs(r[v]) < std::abs(r[center]))
      center = v;
  FAS::compute_geodesic_distance(tm, center, distance);

  // 3. Seed curves: iso-contours of r; circular seeds: iso-contours of the distance.
  std::vector<Polyline> seed_curves, circular_seeds;
  FAS::extract_iso_contours(tm, r, FAS::evenly_spaced_iso_values(tm, r, 7), std::back_inserter(seed_curves));
  FAS::extract_iso_contours(tm, distance, std::vector<double>{0.1, 0.2, 0.3, 0.4},
                            std::back_inserter(circular_seeds));
  std::vector<Point> seed_points;
  FAS::sample_seed_points(tm, 0.1, std::back_inserter(seed_points));
  std::cout << seed_curves.size() << " seed curves, " << circular_seeds.size() << " circular seeds, "
            << seed_points.size() << " seed points\n";

  // 4. A tangential surface (a stream surface of the Burgers vortex): the iso-contours of its
  // tangential parametrization's r cross the flow within the surface.
  const FAS::Burgers_vortex<Kernel> vortex;
  const Tangential_seed_curves tangential = make_tangential_seed_curves(
      vortex, Point(1.0, 0.0, 0.5), Vector(0.0, 1.0, 0.3), 0.5, faces.value, 5);
  const std::vector<Polyline>& crossing_curves = tangential.curves;
  std::cout << "stream surface: flux " << tangential.alignment.normalized_flux << ", "
            << crossing_curves.size() << " seed curves\n";

  Output_folder folder;
  if (!folder.open(output))
    return 1;
  const std::string out = folder.path().string();
  std::vector<FAS::IO::Data_array> arrays = {{"r", 1, {}}, {"s", 1, {}}, {"distance", 1, {}}};
  for (auto v : tm.vertices()) {
    arrays[0].values.push_back(r[v]);
    arrays[1].values.push_back(s[v]);
    arrays[2].values.push_back(distance[v]);
  }
  std::string error;
  std::vector<Polyline> points_as_rows;
  for (const Point& p : seed_points)
    points_as_rows.push_back({p});
  if (!FAS::IO::write_VTP(out + "/surface.vtp", tm, arrays, {}, FAS::parameters::error_message(&error)) ||
      !write_polylines_csv(out + "/seed_curves.csv", seed_curves, error) ||
      !write_polylines_csv(out + "/circular_seeds.csv", circular_seeds, error) ||
      !write_polylines_csv(out + "/seed_points.csv", points_as_rows, error) ||
      !write_polylines_csv(out + "/stream_surface_seed_curves.csv", crossing_curves, error)) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (!folder.commit())
    return 1;
  std::cout << "wrote " << folder.destination().string()
            << "/surface.vtp, seed_curves.csv, circular_seeds.csv, seed_points.csv, "
               "stream_surface_seed_curves.csv\n";
  return 0;
}
