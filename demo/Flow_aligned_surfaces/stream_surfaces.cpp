// The seeding workflow of the paper's Figure 4 (top), end to end: a disk patch aligned
// tangentially to the Burgers vortex (a piece of stream surface) is parametrized tangentially,
// the iso-contours of its r are seed curves across the flow, and each seeds a stream surface
// integrated forward and backward by the advancing front of integrate_stream_surface(), so that
// it interpolates the patch and spans a larger part of the domain.
//
//   stream_surfaces [--faces N] [--spacing H] [--time T] [--output DIR] [--overwrite] [--quiet]
//
// writes DIR/patch.vtp (the aligned patch) and DIR/stream_surface_<i>.vtp (the velocity, u and
// t per vertex -- t < 0 on the backward half -- and the normalized flux per face).  Exits with 1
// if a seed curve gives an empty surface.  (The test StreamSurfacesFromTangentialSeedCurves of
// test/Flow_aligned_surfaces/test_workflows.cpp checks that these surfaces have flux <= 0.01 and
// keep the first integral rho^2 z of the vortex to 1e-5, relative, on every vertex.)

#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>

#include "command_line.h"
#include "demo_support.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace fas_demo;
using Polyline = std::vector<Point>;

int main(int argc, char** argv)
{
  Face_count faces{2000};
  Positive_number spacing{0.02}, time{1.0};
  Output_options output;
  po::options_description options = option_group("Options (lengths and times in the flow's units)");
  options.add_options()("faces", po::value(&faces)->default_value(faces)->value_name("N"),
                        "the number of triangles of the disk (2 to 10000000)")(
      "spacing", po::value(&spacing)->default_value(spacing)->value_name("H"),
      "the front spacing of the stream surfaces: the distance between neighbouring particles")(
      "time", po::value(&time)->default_value(time)->value_name("T"),
      "the integration time of each stream surface, each way from its seed curve");
  options.add(output_options(output, "stream_surfaces_output"));
  const Program_help help{
      "stream_surfaces [options]",
      "The seeding workflow of the paper's Figure 4 (top): a disk aligned tangentially to the Burgers\n"
      "vortex is parametrized tangentially, the iso-contours of its r are seed curves across the flow,\n"
      "and each seeds a stream surface integrated forward and backward.  Writes into the output folder\n"
      "patch.vtp (the aligned disk) and stream_surface_<i>.vtp (velocity, u and t per vertex, t < 0 on\n"
      "the backward half; flux per face).  Exit status: 0 on success, 1 when the run fails (a seed curve\n"
      "gives an empty surface) or the output folder is refused (nothing is written then), 2 for a bad\n"
      "command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options))
    return *status;

  // 1.-3. The aligned patch, its tangential parametrization and the seed curves.
  const Flow flow = FAS::Burgers_vortex<Kernel>();
  const Tangential_seed_curves seeds =
      make_tangential_seed_curves(flow, Point(1.0, 0.0, 0.5), Vector(0.0, 1.0, 0.3), 0.5, faces.value, 5);
  std::cout << "patch: flux " << seeds.alignment.normalized_flux << ", " << seeds.curves.size()
            << " seed curves\n";
  Output_folder folder;
  if (!folder.open(output))
    return 1;
  const std::string out = folder.path().string();
  bool ok = !seeds.curves.empty() && write_surface_VTP(out + "/patch.vtp", seeds.surface, flow);

  // 4. One stream surface per seed curve, forward and backward in one mesh.
  for (std::size_t c = 0; c < seeds.curves.size(); ++c) {
    const Polyline& seed = seeds.curves[c];
    Mesh tm;
    auto u = tm.add_property_map<Mesh::Vertex_index, double>("v:u", 0).first;
    auto t = tm.add_property_map<Mesh::Vertex_index, double>("v:t", 0).first;
    // Forward and backward in one surface, joined at the seed (t < 0 on the backward half).
    const FAS::Stream_surface_report report = FAS::integrate_stream_surface(
        flow, seed, tm,
        FAS::parameters::front_spacing(
            spacing.value, FAS::parameters::max_time(
                         time.value, FAS::parameters::integration_direction(
                                   FAS::Integration_direction::BOTH,
                                   FAS::parameters::seed_parameter_map(
                                       u, FAS::parameters::integration_time_map(t))))));
    const FAS::Normalized_flux flux = FAS::normalized_flux(tm, flow);
    std::cout << "stream surface " << c << ": " << tm.number_of_faces() << " triangles, "
              << report.number_of_time_lines << " + " << report.backward->number_of_time_lines
              << " time lines, " << report.number_of_inserted_particles << " inserted, "
              << report.number_of_removed_particles << " removed, " << report.number_of_tears << " tears ("
              << report.message << "; " << report.backward->message << "), flux " << flux << "\n";
    std::vector<double> us, ts;
    for (Mesh::Vertex_index v : tm.vertices()) {
      us.push_back(u[v]);
      ts.push_back(t[v]);
    }
    ok = ok && tm.number_of_faces() > 0 &&
         write_surface_VTP(out + "/stream_surface_" + std::to_string(c) + ".vtp", tm, flow,
                           {{"u", 1, us}, {"t", 1, ts}});
  }
  if (!ok || !folder.commit())
    return 1;
  std::cout << "wrote " << folder.destination().string() << "/patch.vtp and " << seeds.curves.size()
            << " stream_surface_<i>.vtp\n";
  return 0;
}
