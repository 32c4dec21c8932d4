// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cost of one query of Regular_grid_flow_field_3 (target: <= 50 ns at coherent positions) on a
// 128^3 grid sampled from the ABC flow.  One benchmark iteration is one query, so the reported
// time is ns/query.  Coherent: consecutive points 0.05 cells apart on a smooth closed path,
// as when integrating a stream line or sampling face centroids of a mesh in order.  Random:
// uniform in the box, so almost every query misses the caches.  The masked variants add a solid
// ball to measure the mask test.  Repetitions report median and spread:
//
//   bench_grid_sampling --benchmark_filter=Grid
//
// Precomputed query points keep the path's trigonometry out of the timing.

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <vector>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef FAS::Regular_grid_flow_field_3<K> Grid;

constexpr std::size_t kNodes = 128;
constexpr double kTwoPi = 6.283185307179586;
// A power of two, so that the index wraps with a mask; 2^16 points fill 1.5 MB.
constexpr std::size_t kNumberOfPoints = std::size_t(1) << 16;

// The ABC flow on [0, 2π]^3, optionally without a ball of radius 1 at the center.
Grid make_grid(bool with_solid_ball)
{
  const auto abc = [with_solid_ball](const Point_3& p) -> std::optional<Vector_3> {
    const double x = p.x() - kTwoPi / 2, y = p.y() - kTwoPi / 2, z = p.z() - kTwoPi / 2;
    if (with_solid_ball && x * x + y * y + z * z < 1.)
      return std::nullopt;
    const double a = std::sqrt(3.), b = std::sqrt(2.), c = 1.;
    return Vector_3(a * std::sin(p.z()) + c * std::cos(p.y()), b * std::sin(p.x()) + a * std::cos(p.z()),
                    c * std::sin(p.y()) + b * std::cos(p.x()));
  };
  const double h = kTwoPi / double(kNodes - 1);
  return FAS::sample_on_grid(abc, Point_3(0, 0, 0), Vector_3(h, h, h), {kNodes, kNodes, kNodes});
}

const Grid& grid(bool with_solid_ball)
{
  static const Grid plain = make_grid(false);
  static const Grid masked = make_grid(true);
  return with_solid_ball ? masked : plain;
}

// A Lissajous-like path through the whole box, at most 0.05 cells per step.
std::vector<Point_3> coherent_points()
{
  const double center = kTwoPi / 2, radius = 0.45 * kTwoPi;
  const double h = kTwoPi / double(kNodes - 1);
  std::vector<Point_3> points;
  points.reserve(kNumberOfPoints);
  double s = 0;
  for (std::size_t q = 0; q < kNumberOfPoints; ++q) {
    points.emplace_back(center + radius * std::cos(s), center + radius * std::sin(1.3 * s),
                        center + radius * std::sin(0.7 * s + 1.));
    // The path's speed is at most about 1.8 radius per unit of s.
    s += 0.05 * h / (1.8 * radius);
  }
  return points;
}

std::vector<Point_3> random_points()
{
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0., kTwoPi);
  std::vector<Point_3> points;
  points.reserve(kNumberOfPoints);
  for (std::size_t q = 0; q < kNumberOfPoints; ++q)
    points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

void run_queries(benchmark::State& state, const Grid& g, const std::vector<Point_3>& points)
{
  std::size_t q = 0, inside = 0;
  for (auto _ : state) {
    const std::optional<Vector_3> v = g(points[q]);
    inside += v.has_value();
    benchmark::DoNotOptimize(v);
    q = (q + 1) & (kNumberOfPoints - 1);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["inside"] = double(inside) / double(state.iterations());
}

void BM_Grid_coherent(benchmark::State& state)
{
  static const std::vector<Point_3> points = coherent_points();
  run_queries(state, grid(false), points);
}

void BM_Grid_random(benchmark::State& state)
{
  static const std::vector<Point_3> points = random_points();
  run_queries(state, grid(false), points);
}

void BM_Grid_masked_coherent(benchmark::State& state)
{
  static const std::vector<Point_3> points = coherent_points();
  run_queries(state, grid(true), points);
}

void BM_Grid_masked_random(benchmark::State& state)
{
  static const std::vector<Point_3> points = random_points();
  run_queries(state, grid(true), points);
}

// The unmasked grid's samples, interpolated tricubically (a copy sharing them).
const Grid& tricubic_grid()
{
  static const Grid cubic = grid(false).with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  return cubic;
}

void BM_Grid_tricubic_coherent(benchmark::State& state)
{
  static const std::vector<Point_3> points = coherent_points();
  run_queries(state, tricubic_grid(), points);
}

void BM_Grid_tricubic_random(benchmark::State& state)
{
  static const std::vector<Point_3> points = random_points();
  run_queries(state, tricubic_grid(), points);
}

// The grid's copy is what a deformation holds; it must cost a few pointer copies.
void BM_Grid_copy(benchmark::State& state)
{
  const Grid& g = grid(false);
  for (auto _ : state) {
    Grid copy = g;
    benchmark::DoNotOptimize(copy);
  }
}

} // namespace

BENCHMARK(BM_Grid_coherent)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_Grid_random)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_Grid_masked_coherent)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_Grid_masked_random)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_Grid_tricubic_coherent)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_Grid_tricubic_random)->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(BM_Grid_copy)->Repetitions(7)->ReportAggregatesOnly(true);
