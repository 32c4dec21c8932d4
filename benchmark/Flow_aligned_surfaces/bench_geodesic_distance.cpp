// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Issue 5: the heat-method distance of compute_geodesic_distance() beside CGAL's
// Heat_method_3::estimate_geodesic_distances() on the same meshes (the unit sphere, an
// icosahedron refined by Loop subdivision and pushed onto the sphere), time of the whole call
// and mean relative error against the great-circle distance; and the time of a tangential
// parametrization.  Beside them the same computations with the factorization shared with a
// Flow_aligned_deformation of the sphere in the rotation about z (the sphere is one of its stream
// surfaces), whose constructor factors L + W once for the whole interaction: its
// compute_geodesic_distance() (one factorization of M + tL, two solves) and its
// parametrize_tangential() (no factorization, one back-substitution pair), against one step()
// of the same deformation (GTRANSF + SOLVE).  Plain main(): prints one row per size.
//
//   bench_geodesic_distance [max_subdivisions (default 6)]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
namespace FAS = CGAL::Flow_aligned_surfaces;

template <class F>
double best_of_3_ms(const F& f)
{
  double best = 1e300;
  for (int k = 0; k < 3; ++k) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = std::min(
        best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

int main(int argc, char** argv)
{
  const int max_subdivisions = argc > 1 ? std::atoi(argv[1]) : 6;
  std::printf("%8s %8s %9s %8s %9s %9s %9s %9s %10s %8s %8s %8s\n", "faces", "FAS_ms", "shared_ms", "CGAL_ms",
              "FAS_err", "shared_err", "CGAL_err", "param_ms", "sh_param_ms", "step_ms", "solve_ms",
              "factor_ms");
  Mesh tm;
  CGAL::make_icosahedron(tm, Point(0, 0, 0), 1.0);
  for (int level = 1; level <= max_subdivisions; ++level) {
    CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(1));
    for (Vertex v : tm.vertices())
      tm.point(v) = CGAL::ORIGIN +
                    (tm.point(v) - CGAL::ORIGIN) / std::sqrt((tm.point(v) - CGAL::ORIGIN).squared_length());
    if (level < 3)
      continue;
    const Vertex source = *tm.vertices().begin();
    const Vector s = tm.point(source) - CGAL::ORIGIN;
    auto ours = tm.add_property_map<Vertex, double>("v:ours", 0).first;
    auto cgal = tm.add_property_map<Vertex, double>("v:cgal", 0).first;
    const double ours_ms = best_of_3_ms([&] { FAS::compute_geodesic_distance(tm, source, ours); });
    const double cgal_ms =
        best_of_3_ms([&] { CGAL::Heat_method_3::estimate_geodesic_distances(tm, cgal, source); });
    double ours_error = 0, cgal_error = 0;
    for (Vertex v : tm.vertices()) {
      if (v == source)
        continue;
      const double exact = std::acos(std::clamp((tm.point(v) - CGAL::ORIGIN) * s, -1.0, 1.0));
      ours_error += std::abs(ours[v] - exact) / exact;
      cgal_error += std::abs(cgal[v] - exact) / exact;
    }
    const double n = double(tm.number_of_vertices() - 1);
    // The tangential parametrization in the rotation about z (tangent to the sphere).
    const auto rotation = [](const Point& p) { return std::optional<Vector>(Vector(-p.y(), p.x(), 0)); };
    auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
    auto t = tm.add_property_map<Vertex, double>("v:s", 0).first;
    const double param_ms = best_of_3_ms([&] { FAS::parametrize_tangential(tm, rotation, r, t); });

    // The same with the deformation's factorization (on copies: step() moves the vertices).
    Mesh shared_tm = tm, step_tm = tm;
    using Deformation = FAS::Flow_aligned_deformation<Mesh, decltype(rotation)>;
    const auto construct_start = std::chrono::steady_clock::now();
    const Deformation shared(shared_tm, rotation, FAS::Alignment::TANGENTIAL);
    const double factor_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - construct_start).count();
    auto shared_d = shared_tm.property_map<Vertex, double>("v:ours").first;
    auto shared_r = shared_tm.property_map<Vertex, double>("v:r").first;
    auto shared_s = shared_tm.property_map<Vertex, double>("v:s").first;
    const double shared_ms = best_of_3_ms([&] { shared.compute_geodesic_distance(source, shared_d); });
    const double shared_param_ms = best_of_3_ms([&] { shared.parametrize_tangential(shared_r, shared_s); });
    double shared_error = 0;
    for (Vertex v : shared_tm.vertices())
      if (v != source) {
        const double exact = std::acos(std::clamp((shared_tm.point(v) - CGAL::ORIGIN) * s, -1.0, 1.0));
        shared_error += std::abs(shared_d[v] - exact) / exact;
      }
    Deformation stepping(step_tm, rotation, FAS::Alignment::TANGENTIAL);
    double step_ms = 1e300, solve_ms = 1e300;
    for (int k = 0; k < 3; ++k) {
      const FAS::Iteration_report report = stepping.step();
      step_ms = std::min(step_ms, report.gradient_transformation_ms + report.solve_ms);
      solve_ms = std::min(solve_ms, report.solve_ms);
    }
    std::printf("%8zu %8.1f %9.1f %8.1f %9.5f %9.5f %9.5f %9.2f %10.2f %8.2f %8.2f %8.1f\n",
                std::size_t(tm.number_of_faces()), ours_ms, shared_ms, cgal_ms, ours_error / n,
                shared_error / n, cgal_error / n, param_ms, shared_param_ms, step_ms, solve_ms, factor_ms);
    tm.remove_property_map(ours);
    tm.remove_property_map(cgal);
    tm.remove_property_map(r);
    tm.remove_property_map(t);
  }
  return 0;
}
