// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stream lines (and path lines) from seed points, with the arrays VTK's vtkStreamTracer gives its lines, under
// VTK's names, so that ParaView colours and filters them as its own: per point the `velocity`
// and the `IntegrationTime` (signed: < 0 on the backward half), per line the `SeedIds` (the index
// of its seed point).

#ifndef FAS_DEMO_STREAM_LINES_WITH_ARRAYS_H
#define FAS_DEMO_STREAM_LINES_WITH_ARRAYS_H

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace fas_demo {

/// Stream lines with their arrays (see the file's comment).
template <class Point>
struct Stream_lines {
  std::vector<std::vector<Point>> lines;
  std::vector<double> velocity;         ///< 3 per point, lines after lines
  std::vector<double> integration_time; ///< 1 per point
  std::vector<double> seed_ids;         ///< 1 per line
  /// The arrays as the VTP writers take them: point data, then cell data.
  std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array> point_data() const
  {
    return {{"velocity", 3, velocity}, {"IntegrationTime", 1, integration_time}};
  }
  std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array> cell_data() const
  {
    return {{"SeedIds", 1, seed_ids}};
  }
};

/// The lines `integrate(seed, line, times)` gives through each of `seeds` (a line's points and
/// their IntegrationTime), with the velocity `velocity(point, time)` at each point; a seed whose
/// line has fewer than two points (outside the domain, at rest) gives no line.
template <class Point, class Integrate, class Velocity>
Stream_lines<Point> lines_with_arrays(const std::vector<Point>& seeds, const Integrate& integrate,
                                      const Velocity& velocity)
{
  Stream_lines<Point> result;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    std::vector<Point> line;
    std::vector<double> times;
    integrate(seeds[i], line, times);
    if (line.size() < 2)
      continue;
    for (std::size_t k = 0; k < line.size(); ++k) {
      const auto v = velocity(line[k], times[k]);
      if (v)
        result.velocity.insert(result.velocity.end(), {v->x(), v->y(), v->z()});
      else // no sample (a line that left the domain ends on its boundary): NaN, as VTK's probes
        result.velocity.insert(result.velocity.end(), 3, std::numeric_limits<double>::quiet_NaN());
      result.integration_time.push_back(times[k]);
    }
    result.seed_ids.push_back(double(i));
    result.lines.push_back(std::move(line));
  }
  return result;
}

/// The stream lines of `flow` through each of `seeds`, backward and forward, each half up to
/// `max_length` of arc length.
template <class Flow, class Point>
Stream_lines<Point> integrate_stream_lines(const Flow& flow, const std::vector<Point>& seeds,
                                           double max_length)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  const auto integrate = [&](const Point& seed, std::vector<Point>& line, std::vector<double>& times) {
    FAS::integrate_streamline(
        flow, seed, std::back_inserter(line),
        FAS::parameters::max_length(max_length,
                                    FAS::parameters::integration_direction(
                                        FAS::Integration_direction::BOTH,
                                        FAS::parameters::time_output_iterator(std::back_inserter(times)))));
  };
  return lines_with_arrays(seeds, integrate, [&](const Point& p, double) { return flow(p); });
}

/// The path lines of the unsteady `flow` (called with `(p, t)`) from each of `seeds`, released at
/// `start_time` and integrated forward for `duration`; IntegrationTime is the time since the
/// release, as ParaView's ParticlePath gives it.
template <class UnsteadyFlow, class Point>
Stream_lines<Point> integrate_path_lines(const UnsteadyFlow& flow, const std::vector<Point>& seeds,
                                         double start_time, double duration)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  const auto integrate = [&](const Point& seed, std::vector<Point>& line, std::vector<double>& times) {
    FAS::integrate_pathline(flow, seed, start_time, std::back_inserter(line),
                            FAS::parameters::max_time(
                                duration, FAS::parameters::time_output_iterator(std::back_inserter(times))));
    for (double& t : times) // the path line's times are absolute
      t -= start_time;
  };
  return lines_with_arrays(seeds, integrate,
                           [&](const Point& p, double since) { return flow(p, start_time + since); });
}

} // namespace fas_demo

#endif // FAS_DEMO_STREAM_LINES_WITH_ARRAYS_H
