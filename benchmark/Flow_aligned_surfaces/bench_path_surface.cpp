// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Path surfaces and path lines on real unsteady CFD data, our side of the comparison with
// ParaView's ParticlePath (vtkParticlePathFilter), whose side is paraview_particle_path.py.
// Data: the vortex-shedding cylinder ../shared/data/CYLINDER_UNSTEADY_grid.pvd (34 steps over
// one period, t = 6.5 ... 6.833373), read with IO::read_PVD_flow_field() into an
// Unsteady_flow_field_3<Regular_grid_flow_field_3>: trilinear in space, linear in time, which
// is also how vtkParticlePathFilter interpolates an image series, so both tracers integrate
// the same field and their drift from one reference is their integration error alone.
//
// Seeds: 57 points on the segment x = 1.0, z = 0.15625, y = 0.09375 ... 0.3125 in the near
// wake (just past the recirculation bubble, off the mid-plane so that the lines are 3D), 1/256
// apart: numbers exact in float, so that a tracer keeping its seeds in float has the same
// points, and segments exactly equal, so that the path surface's first front is the seeds.  All are
// released at the first step and integrated to the last.
//
// Rows, each timed as the median of `runs` runs (the 1e-12 row: a third of them), wall time and
// the thread's CPU time, the field read before (its reading timed apart):
// - the path surface at its defaults (front spacing = the seeds' spacing, tolerances
//   1e-10 / 1e-12), at the stream lines' tolerances 1e-8 / 1e-10, and at 1e-12 / 1e-14: the
//   floor of the comparison below (its vertices are the integrator's dense output, the
//   reference's points ends of integrations);
// - our path lines, integrate_pathline() per seed at its defaults (1e-8 / 1e-10).
// Points are what a tracer writes: the surface's vertices (its time lines every h / median
// speed, plus the particles it inserts where the front stretches), the path lines' step ends,
// ParticlePath's one point per particle and data step.  Points per second therefore rewards
// the denser output; the wall time for the same seeds over the same time is the figure to
// compare first, and both are printed.
//
// Drift: the reference is each seed's path line by integrate_pathline() at tolerance 1e-12
// (absolute 1e-14), evaluated exactly at every time asked for (restarted at each such time,
// its last point the dense output at it).  A surface vertex whose seed parameter u is a seed
// point's (the path line of that seed, while the particle is kept) is compared with that
// seed's reference at the vertex's time t0 + tau; a path-line point with the reference at its
// own time.  Distances are relative to the data's diagonal (2.566); median and max over the
// points after the release (the seeds themselves left out).  The surface's other vertices (the
// particles inserted between seeds) have no reference and are only counted.  The reference at
// the data's step times is written to OUTPUT with the seeds, for paraview_particle_path.py to
// measure ParticlePath's points the same way.
//
//   bench_path_surface [runs (7)] [OUTPUT (path_surface_reference.txt)] [SERIES.pvd]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Surface_mesh.h>

#include "bench_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Grid = FAS::Regular_grid_flow_field_3<K>;
using Series = FAS::Unsteady_flow_field_3<Grid>;
using Mesh = CGAL::Surface_mesh<Point>;

double median(std::vector<double> v)
{
  if (v.empty())
    return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Timing {
  std::vector<double> wall_ms, cpu_ms;
  void run(const std::function<void()>& f)
  {
    const double c0 = fas_benchmark::thread_cpu_ms();
    const auto w0 = std::chrono::steady_clock::now();
    f();
    wall_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count());
    cpu_ms.push_back(fas_benchmark::thread_cpu_ms() - c0);
  }
};

// Each seed's reference path line at tolerance 1e-12, at exactly the times asked for.
class Reference {
public:
  Reference(const Series& field, const std::vector<Point>& seeds, double t0)
      : m_field(field), m_seeds(seeds), m_t0(t0), m_times(seeds.size())
  {
  }
  void ask(std::size_t seed, double t) { m_times[seed][t] = Point(); }
  // Integrates, restarting at each time asked for: every time is then an end of a piece, where
  // the integrator writes its dense output exactly at the limit.
  void compute()
  {
    const auto np = FAS::parameters::relative_tolerance(1e-12, FAS::parameters::absolute_tolerance(1e-14));
    for (std::size_t s = 0; s < m_seeds.size(); ++s) {
      Point x = m_seeds[s];
      double t = m_t0;
      for (auto& [time, p] : m_times[s]) {
        if (time > t) {
          std::vector<Point> points;
          const FAS::Streamline_report r = FAS::integrate_pathline(m_field, x, t, std::back_inserter(points),
                                                                   FAS::parameters::max_time(time - t, np));
          if (r.forward.termination != FAS::Streamline_termination::MAX_TIME) {
            std::fprintf(stderr, "reference of seed %zu stopped at t = %.9g (%s) before %.9g\n", s,
                         t + r.forward.integration_time, FAS::to_string(r.forward.termination), time);
            std::exit(1);
          }
          x = points.back();
          t = time;
        }
        p = x;
      }
    }
  }
  const Point& at(std::size_t seed, double t) const { return m_times[seed].at(t); }
  const std::map<double, Point>& line(std::size_t seed) const { return m_times[seed]; }

private:
  const Series& m_field;
  const std::vector<Point>& m_seeds;
  double m_t0;
  std::vector<std::map<double, Point>> m_times;
};

// The points a tracer wrote that belong to a seed's path line: (seed, time, position).
struct Sample {
  std::size_t seed;
  double t;
  Point p;
};

struct Row {
  std::string name;
  Timing timing;
  std::size_t points = 0;
  std::vector<Sample> samples;
  std::string note;
};

// The surface's vertices whose seed parameter is a seed point's.
std::vector<Sample> seed_vertices(const Mesh& tm, Mesh::Property_map<Mesh::Vertex_index, double> u,
                                  Mesh::Property_map<Mesh::Vertex_index, double> tau, double seed_spacing,
                                  std::size_t number_of_seeds, double t0)
{
  std::vector<Sample> out;
  for (Mesh::Vertex_index v : tm.vertices()) {
    const double k = u[v] / seed_spacing, r = std::round(k);
    if (std::abs(k - r) < 1e-9 && r >= 0 && r < double(number_of_seeds))
      out.push_back({std::size_t(r), t0 + tau[v], tm.point(v)});
  }
  return out;
}

void path_surface(Row& row, int runs, const Series& field, const std::vector<Point>& seeds,
                  double seed_spacing, double t0, double duration, double rtol, double atol)
{
  Mesh tm;
  FAS::Stream_surface_report report;
  for (int run = 0; run < runs; ++run) {
    tm.clear();
    auto u = tm.add_property_map<Mesh::Vertex_index, double>("v:u", 0.).first;
    auto tau = tm.add_property_map<Mesh::Vertex_index, double>("v:tau", 0.).first;
    const auto np = FAS::parameters::start_time(
        t0, FAS::parameters::max_time(duration, FAS::parameters::seed_parameter_map(
                                                    u, FAS::parameters::integration_time_map(tau))));
    row.timing.run([&] {
      if (rtol > 0)
        report = FAS::integrate_stream_surface(
            field, seeds, tm,
            FAS::parameters::relative_tolerance(rtol, FAS::parameters::absolute_tolerance(atol, np)));
      else
        report = FAS::integrate_stream_surface(field, seeds, tm, np);
    });
  }
  auto u = tm.property_map<Mesh::Vertex_index, double>("v:u").first;
  auto tau = tm.property_map<Mesh::Vertex_index, double>("v:tau").first;
  row.points = tm.number_of_vertices();
  row.samples = seed_vertices(tm, u, tau, seed_spacing, seeds.size(), t0);
  char note[256];
  std::snprintf(note, sizeof note,
                "%zu time lines (step %.4g), %zu faces, %zu inserted, %zu removed, %zu lost, %s",
                report.number_of_time_lines, report.time_line_step, std::size_t(tm.number_of_faces()),
                report.number_of_inserted_particles, report.number_of_removed_particles,
                report.number_of_lost_particles, FAS::to_string(report.termination));
  row.note = note;
}

void path_lines(Row& row, int runs, const Series& field, const std::vector<Point>& seeds, double t0,
                double duration)
{
  std::vector<std::vector<Point>> points(seeds.size());
  std::vector<std::vector<double>> times(seeds.size());
  std::string reasons;
  for (int run = 0; run < runs; ++run) {
    reasons.clear();
    row.timing.run([&] {
      for (std::size_t s = 0; s < seeds.size(); ++s) {
        points[s].clear();
        times[s].clear();
        const FAS::Streamline_report r = FAS::integrate_pathline(
            field, seeds[s], t0, std::back_inserter(points[s]),
            FAS::parameters::max_time(duration,
                                      FAS::parameters::time_output_iterator(std::back_inserter(times[s]))));
        if (r.forward.termination != FAS::Streamline_termination::MAX_TIME)
          reasons += std::string(FAS::to_string(r.forward.termination)) + " ";
      }
    });
  }
  row.points = 0;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    row.points += points[s].size();
    for (std::size_t i = 0; i < points[s].size(); ++i)
      row.samples.push_back({s, times[s][i], points[s][i]});
  }
  row.note = reasons.empty() ? std::string("every line reached the last time") : "stopped early: " + reasons;
}

} // namespace

int main(int argc, char** argv)
{
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  const std::string output = argc > 2 ? argv[2] : "path_surface_reference.txt";
  const std::string pvd =
      argc > 3 ? argv[3] : std::string(FAS_SHARED_DATA_DIR) + "/CYLINDER_UNSTEADY_grid.pvd";

  Series field;
  std::string error;
  Timing reading;
  for (int run = 0; run < std::max(3, runs / 2); ++run) {
    reading.run([&] {
      if (!FAS::IO::read_PVD_flow_field(pvd, field, FAS::parameters::error_message(&error))) {
        std::fprintf(stderr, "%s\n", error.c_str());
        std::exit(1);
      }
    });
  }
  const CGAL::Bbox_3 box = field.step(0).bbox();
  const double diagonal = std::sqrt((box.xmax() - box.xmin()) * (box.xmax() - box.xmin()) +
                                    (box.ymax() - box.ymin()) * (box.ymax() - box.ymin()) +
                                    (box.zmax() - box.zmin()) * (box.zmax() - box.zmin()));
  const double t0 = field.start_time(), t1 = field.end_time();
  // t0 + (t1 - t0) may round above t1, where the series has no value.
  double duration = t1 - t0;
  while (t0 + duration > t1)
    duration = std::nextafter(duration, 0.);

  const std::size_t number_of_seeds = 57;
  const double seed_spacing = 1. / 256.;
  std::vector<Point> seeds;
  for (std::size_t i = 0; i < number_of_seeds; ++i)
    seeds.emplace_back(1.0, 0.09375 + double(i) * seed_spacing, 0.15625);

  std::vector<Row> rows(4);
  rows[0].name = "path surface, defaults (1e-10 / 1e-12)";
  path_surface(rows[0], runs, field, seeds, seed_spacing, t0, duration, 0, 0);
  rows[1].name = "path surface, 1e-8 / 1e-10";
  path_surface(rows[1], runs, field, seeds, seed_spacing, t0, duration, 1e-8, 1e-10);
  rows[2].name = "path lines, defaults (1e-8 / 1e-10)";
  path_lines(rows[2], runs, field, seeds, t0, duration);
  rows[3].name = "path surface, 1e-12 / 1e-14";
  path_surface(rows[3], std::max(1, runs / 3), field, seeds, seed_spacing, t0, duration, 1e-12, 1e-14);

  Reference reference(field, seeds, t0);
  for (std::size_t s = 0; s < seeds.size(); ++s)
    for (std::size_t i = 0; i < field.number_of_steps(); ++i)
      reference.ask(s, std::min(field.time(i), t0 + duration));
  for (const Row& row : rows)
    for (const Sample& x : row.samples)
      reference.ask(x.seed, x.t);
  Timing reference_timing;
  reference_timing.run([&] { reference.compute(); });

  std::printf(
      "%s: %zu steps, t = %.6f ... %.6f, diagonal %.4f; %zu seeds on x = 1, z = 0.15625, y = %.5f ... %.5f\n",
      pvd.c_str(), field.number_of_steps(), t0, t1, diagonal, seeds.size(), seeds.front().y(),
      seeds.back().y());
  std::printf("read_PVD_flow_field: %.1f ms wall, %.1f ms CPU (median of %zu)\n", median(reading.wall_ms),
              median(reading.cpu_ms), reading.wall_ms.size());
  std::printf("reference path lines (1e-12 / 1e-14, restarted at %zu times): %.1f ms\n",
              reference.line(0).size(), reference_timing.wall_ms[0]);
  std::printf("%-40s %9s %9s %8s %11s %11s %11s %8s  %s\n", "tracer (median of runs)", "wall_ms", "cpu_ms",
              "points", "points/s", "drift_med", "drift_max", "compared", "notes");
  for (const Row& row : rows) {
    std::vector<double> drift;
    for (const Sample& x : row.samples)
      if (x.t > t0)
        drift.push_back(std::sqrt(CGAL::squared_distance(x.p, reference.at(x.seed, x.t))) / diagonal);
    const double wall = median(row.timing.wall_ms);
    std::printf("%-40s %9.2f %9.2f %8zu %11.4g %11.3g %11.3g %8zu  %s\n", row.name.c_str(), wall,
                median(row.timing.cpu_ms), row.points, double(row.points) / (wall * 1e-3), median(drift),
                drift.empty() ? std::nan("") : *std::max_element(drift.begin(), drift.end()), drift.size(),
                row.note.c_str());
  }

  // For paraview_particle_path.py: the seeds and the reference at the data's step times.
  std::FILE* f = std::fopen(output.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "cannot write %s\n", output.c_str());
    return 1;
  }
  std::fprintf(f, "# bench_path_surface: seeds and reference path lines (1e-12) at the step times\n");
  std::fprintf(f, "series %s\nstart %.17g\nend %.17g\ndiagonal %.17g\n", pvd.c_str(), t0, t0 + duration,
               diagonal);
  for (std::size_t s = 0; s < seeds.size(); ++s)
    std::fprintf(f, "seed %zu %.17g %.17g %.17g\n", s, seeds[s].x(), seeds[s].y(), seeds[s].z());
  for (std::size_t s = 0; s < seeds.size(); ++s)
    for (std::size_t i = 0; i < field.number_of_steps(); ++i) {
      const double t = std::min(field.time(i), t0 + duration);
      const Point& p = reference.at(s, t);
      std::fprintf(f, "reference %zu %.17g %.17g %.17g %.17g\n", s, t, p.x(), p.y(), p.z());
    }
  std::fclose(f);
  std::printf("seeds and reference written to %s\n", output.c_str());
  return 0;
}
