// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A surface that follows an unsteady flow through its time steps, as the plugin's Flow-Aligned
// Surface does while ParaView plays a time series: aligned once at the first step, then at each
// later step re-aligned from where it is (Time_slice_flow_field_3::set_time(), then run(): the
// same factorization, a warm start).  Per patch size: the wall time of the first alignment, and
// per later step the median and largest wall time of its re-alignment, its iterations, and the
// steps per second that gives (the goal: at least 10 at 5e3 faces, ParaView's playback).  The
// peer in the same run is the cold alignment at a step: a new deformation from the initial patch
// (construction and factorization included), at a few of the steps.
//
// Two flows: the DFG cylinder's 34 steps over one shedding period (a tangential patch beside the
// cylinder, where the wake moves weakly), given as the .pvd; and a swirl whose axis drifts along
// x by 1/24 of the patch per step (strongly unsteady: the surface has to move at each step).
//
//   bench_follow_time_series CYLINDER_UNSTEADY_grid.pvd [runs (3)] [faces (5000 80000)...]

#include "bench_clock.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

// A step of the drifting swirl: about an axis parallel to z, with an axial speed.
using Swirl = FAS::Helical_flow<Kernel>;

struct Patch {
  Point center;
  Vector normal;
  double size;
};

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double wall_ms_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// One run over every step of `flow`: the first alignment's ms, then per later step its ms and
// iterations (appended to `step_ms`, `iterations`; `unconverged` counts the steps that end
// unconverged); the cold alignment's ms at every `cold_every` step (appended to `cold_ms`).
template <class Unsteady>
double follow(const Unsteady& flow, const Patch& patch, std::size_t faces, std::size_t cold_every,
              std::vector<double>& step_ms, std::vector<double>& iterations, std::vector<double>& cold_ms,
              std::size_t& unconverged)
{
  using Slice = FAS::Time_slice_flow_field_3<Unsteady>;
  Slice now(flow, flow.start_time());
  Mesh tm;
  FAS::make_planar_patch(tm, patch.center, patch.normal, patch.size, patch.size, faces);
  const Mesh initial = tm;
  auto start = std::chrono::steady_clock::now();
  FAS::Flow_aligned_deformation<Mesh, Slice> deformation(tm, now, FAS::Alignment::TANGENTIAL);
  unconverged += deformation.run().converged ? 0 : 1;
  const double first_ms = wall_ms_since(start);
  for (std::size_t k = 1; k < flow.number_of_steps(); ++k) {
    now.set_time(flow.time(k));
    start = std::chrono::steady_clock::now();
    const FAS::Alignment_report report = deformation.run();
    step_ms.push_back(wall_ms_since(start));
    iterations.push_back(double(report.number_of_iterations));
    unconverged += report.converged ? 0 : 1;
    if (k % cold_every == 0) {
      Mesh cold = initial;
      Slice at(flow, flow.time(k));
      start = std::chrono::steady_clock::now();
      FAS::Flow_aligned_deformation<Mesh, Slice>(cold, at, FAS::Alignment::TANGENTIAL).run();
      cold_ms.push_back(wall_ms_since(start));
    }
  }
  if (deformation.number_of_factorizations() != 1)
    std::printf("  (warning: %zu factorizations)\n", deformation.number_of_factorizations());
  return first_ms;
}

template <class Unsteady>
void measure(const char* name, const Unsteady& flow, const Patch& patch, std::size_t faces, int runs)
{
  std::vector<double> first, step_ms, iterations, cold_ms;
  std::size_t unconverged = 0;
  for (int r = 0; r < runs; ++r)
    first.push_back(follow(flow, patch, faces, 8, step_ms, iterations, cold_ms, unconverged));
  const double per_step = median(step_ms);
  std::printf(
      "%-22s %7zu faces: first alignment %8.1f ms; per step: median %7.2f ms, max %7.2f ms, "
      "%5.1f iterations (median %.0f) -> %6.1f steps/s; cold alignment %8.1f ms (%.1f x); "
      "%zu alignments unconverged\n",
      name, faces, median(first), per_step, *std::max_element(step_ms.begin(), step_ms.end()),
      [&] {
        double s = 0;
        for (double i : iterations)
          s += i;
        return s / double(iterations.size());
      }(),
      median(iterations), 1e3 / per_step, median(cold_ms), median(cold_ms) / per_step, unconverged);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_follow_time_series SERIES.pvd [runs (3)] [faces...]\n");
    return 2;
  }
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  std::vector<std::size_t> sizes;
  for (int i = 3; i < argc; ++i)
    sizes.push_back(std::size_t(std::atol(argv[i])));
  if (sizes.empty())
    sizes = {5000, 80000};

  FAS::Unsteady_flow_field_3<FAS::Regular_grid_flow_field_3<Kernel>> cylinder;
  std::string error;
  if (!FAS::IO::read_PVD_flow_field(
          argv[1], cylinder,
          FAS::parameters::error_message(&error, FAS::parameters::use_parallelism(true)))) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  std::vector<double> times;
  std::vector<Swirl> swirls;
  for (int k = 0; k < 34; ++k) {
    times.push_back(0.01 * k);
    swirls.emplace_back(0.3, Point(0.025 * k, 0, 0)); // the axis moves 1/24 of the 0.6 patch per step
  }
  const FAS::Unsteady_flow_field_3<Swirl> swirl(times, swirls);

  std::printf("runs: %d (medians over all runs' steps); %zu and %zu steps\n", runs,
              cylinder.number_of_steps(), swirl.number_of_steps());
  for (std::size_t faces : sizes) {
    // Where the main job places its tangential patch in this data: beside the cylinder.
    measure("cylinder (34 steps)", cylinder,
            Patch{Point(0.5128, 0.3191, 0.205), Vector(0.6287, -0.7777, 0), 0.1}, faces, runs);
    measure("drifting swirl", swirl, Patch{Point(1.0, 0, 0), Vector(1, 0, 0), 0.6}, faces, runs);
  }
  return 0;
}
