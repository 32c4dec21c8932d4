// Stream lines from seed points on an orthogonal surface (the paper's Figure 5): a disk beside a
// point source is aligned orthogonally to the flow (it becomes a piece of a sphere about the
// source), seed points are spread evenly over it, and a stream line is integrated through each
// seed, backward and forward, by the adaptive Dormand-Prince integrator.
//
//   streamlines [--faces N] [--spacing H] [--length L] [--output DIR] [--overwrite] [--quiet]
//
// writes DIR/surface.vtp (the orthogonal surface, velocity and flux) and DIR/streamlines.vtp (one polyline per
// seed; per point the speed, per line its length and why each direction stopped, as the
// numbers of FAS::Streamline_termination).  (The stream lines of a point source are rays from it:
// the test SeedPointsOnAnOrthogonalSurfaceSeedRays of test/Flow_aligned_surfaces/test_workflows.cpp
// checks that no point is farther than 1e-6 from its seed's ray.)

#include "command_line.h"
#include "demo_support.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

using namespace fas_demo;

int main(int argc, char** argv)
{
  Face_count faces{2000};
  Positive_number spacing{0.15}, length{1.5};
  Output_options output;
  po::options_description options =
      option_group("Options (lengths in the flow's units; the source is at the origin)");
  options.add_options()("faces", po::value(&faces)->default_value(faces)->value_name("N"),
                        "the number of triangles of the disk (2 to 10000000)")(
      "spacing", po::value(&spacing)->default_value(spacing)->value_name("H"),
      "the distance between seed points on the disk (its radius is 0.6)")(
      "length", po::value(&length)->default_value(length)->value_name("L"),
      "the largest arc length of a stream line each way from its seed");
  options.add(output_options(output, "streamlines_output"));
  const Program_help help{
      "streamlines [options]",
      "Stream lines from seed points on an orthogonal surface (the paper's Figure 5): a disk beside a\n"
      "point source is aligned orthogonally, seed points are spread over it, and a stream line is\n"
      "integrated through each, backward and forward.  Writes into the output folder surface.vtp (the\n"
      "surface, velocity and flux) and streamlines.vtp (per point the speed, per line its length and why\n"
      "each direction stopped).  Exit status: 0 on success, 1 when the run fails or the output folder is\n"
      "refused (nothing is written then), 2 for a bad command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options))
    return *status;

  // 1. An orthogonal surface: a tilted disk beside the source becomes a piece of a sphere.
  const FAS::Point_source_flow<Kernel> flow;
  Mesh tm;
  make_orthogonal_disk(tm, flow, faces.value);

  // 2. Seed points spread over it.
  std::vector<Point> seeds;
  FAS::sample_seed_points(tm, spacing.value, std::back_inserter(seeds));

  // 3. A stream line through each seed, both ways, at most `length` of arc length each way.
  std::vector<std::vector<Point>> lines;
  FAS::IO::Data_array speed{"speed", 1, {}}, line_length{"length", 1, {}}, backward{"backward_reason", 1, {}},
      forward{"forward_reason", 1, {}};
  std::map<std::string, int> reasons;
  for (const Point& seed : seeds) {
    std::vector<Point> line;
    const FAS::Streamline_report report =
        FAS::integrate_streamline(flow, seed, std::back_inserter(line),
                                  FAS::parameters::max_length(length.value, FAS::parameters::integration_direction(
                                                                          FAS::Integration_direction::BOTH)));
    ++reasons[std::string(FAS::to_string(report.backward.termination)) + " / " +
              FAS::to_string(report.forward.termination)];
    for (const Point& p : line)
      speed.values.push_back(std::sqrt(flow(p)->squared_length()));
    line_length.values.push_back(report.length());
    backward.values.push_back(double(report.backward.termination));
    forward.values.push_back(double(report.forward.termination));
    lines.push_back(std::move(line));
  }
  std::cout << lines.size() << " stream lines; backward / forward reasons:";
  for (const auto& [name, count] : reasons)
    std::cout << " " << name << " (" << count << ")";
  std::cout << "\n";

  Output_folder folder;
  if (!folder.open(output))
    return 1;
  const std::string out = folder.path().string();
  std::string error;
  if (!write_surface_VTP(out + "/surface.vtp", tm, flow))
    return 1;
  if (!FAS::IO::write_VTP_polylines(out + "/streamlines.vtp", lines, {speed},
                                    {line_length, backward, forward},
                                    FAS::parameters::error_message(&error))) {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (!folder.commit())
    return 1;
  std::cout << "wrote " << folder.destination().string() << "/surface.vtp and streamlines.vtp\n";
  return 0;
}
