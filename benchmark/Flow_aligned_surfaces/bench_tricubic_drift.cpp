// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How much closer stream lines keep the first integral of a sampled flow on the
// tricubic grid field than on the trilinear one, by flow and grid size.  Flows with closed-form
// first integrals I: the ABC flow with C = 0 (I = A cos z + B sin x, A = √3, B = √2) over one
// period [0, 2π]³ and over four [0, 8π]³; the cellular flow (sin x cos y, -cos x sin y, 0.3)
// (I = sin x sin y) over [0, 2π]³; Hill's spherical vortex (radius 1, I = its Stokes stream
// function, a quadratic field inside) over [-1.1, 1.1]³ with seeds within 0.45 of its center.
// Each sampled on n³ nodes, n = 16, 32, 64, 128; 41 seeds per case (fixed generator), lines of
// length 10 forward at tolerance 1e-11 (relative) / 1e-13 (absolute), so that the interpolation,
// not the integrator, sets the drift max_p |I(p) - I(seed)| / range(I).  Prints the median and
// the largest drift over the lines for both interpolations and the ratio of the medians.
//
//   bench_tricubic_drift

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <optional>
#include <random>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

struct Case {
  const char* name;
  std::function<std::optional<Vector>(const Point&)> field;
  std::function<double(const Point&)> integral;
  double range;              // of I, to make the drift relative
  double lo, size;           // the sampled cube [lo, lo + size]^3
  double seed_lo, seed_hi;   // seeds in [seed_lo, seed_hi]^3 ...
  double seed_radius;        // ... and within this distance of the origin (0: no bound)
};

int main()
{
  const double A = std::sqrt(3.), B = std::sqrt(2.);
  const FAS::ABC_flow<K> abc(A, B, 0);
  const FAS::Hill_spherical_vortex<K> hill(1, 1);
  const auto abc_field = [&](const Point& p) { return abc(p); };
  const auto abc_integral = [&](const Point& p) { return CGAL::to_double(abc.first_integral(p)); };
  const Case cases[] = {
      {"ABC C=0, [0,2pi]^3", abc_field, abc_integral, A + B, 0, 2 * CGAL_PI, 0.5, 2 * CGAL_PI - 0.5, 0},
      {"ABC C=0, [0,8pi]^3", abc_field, abc_integral, A + B, 0, 8 * CGAL_PI, 0.5, 8 * CGAL_PI - 0.5, 0},
      {"cellular, [0,2pi]^3",
       [](const Point& p) {
         return std::optional<Vector>(
             Vector(std::sin(p.x()) * std::cos(p.y()), -std::cos(p.x()) * std::sin(p.y()), 0.3));
       },
       [](const Point& p) { return std::sin(p.x()) * std::sin(p.y()); }, 2, 0, 2 * CGAL_PI, 0.5,
       2 * CGAL_PI - 0.5, 0},
      {"Hill, [-1.1,1.1]^3", [&](const Point& p) { return hill(p); },
       [&](const Point& p) { return CGAL::to_double(hill.stokes_stream_function(p)); }, 0.75 * 0.25, -1.1, 2.2,
       -0.45, 0.45, 0.45},
  };
  std::printf("%-22s %5s %14s %14s %14s %14s %9s\n", "flow", "n", "trilin_median", "trilin_max", "tricub_median",
              "tricub_max", "ratio");
  for (const Case& c : cases)
    for (std::size_t n : {16u, 32u, 64u, 128u}) {
      const double h = c.size / double(n - 1);
      const auto grid = FAS::sample_on_grid(c.field, Point(c.lo, c.lo, c.lo), Vector(h, h, h), {n, n, n});
      const auto cubic = grid.with_interpolation(FAS::Grid_interpolation::TRICUBIC);
      std::mt19937 generator(7);
      std::uniform_real_distribution<double> uniform(c.seed_lo, c.seed_hi);
      std::vector<double> drift[2];
      while (drift[0].size() < 41) {
        const Point seed(uniform(generator), uniform(generator), uniform(generator));
        if (c.seed_radius > 0 && (seed - CGAL::ORIGIN).squared_length() > c.seed_radius * c.seed_radius)
          continue;
        for (int k = 0; k < 2; ++k) {
          std::vector<Point> points;
          const auto np = FAS::parameters::max_length(
              10.0, FAS::parameters::relative_tolerance(1e-11, FAS::parameters::absolute_tolerance(1e-13)));
          if (k == 0)
            FAS::integrate_streamline(grid, seed, std::back_inserter(points), np);
          else
            FAS::integrate_streamline(cubic, seed, std::back_inserter(points), np);
          double largest = 0;
          for (const Point& p : points)
            largest = std::max(largest, std::abs(c.integral(p) - c.integral(seed)) / c.range);
          drift[k].push_back(largest);
        }
      }
      for (auto& d : drift)
        std::sort(d.begin(), d.end());
      std::printf("%-22s %5zu %14.2e %14.2e %14.2e %14.2e %9.2f\n", c.name, n, drift[0][20], drift[0].back(),
                  drift[1][20], drift[1].back(), drift[0][20] / drift[1][20]);
      std::fflush(stdout);
    }
  return 0;
}
