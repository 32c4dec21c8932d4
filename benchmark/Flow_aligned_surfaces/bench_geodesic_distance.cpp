// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The heat-method distance of compute_geodesic_distance() beside CGAL's
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
// Then a second table on sphere caps (radius 2, polar angle up to 1.2, the disk
// patch mapped by the inverse azimuthal equidistant projection, as in test_parametrize.cpp), plain
// and with the interior vertices jittered by up to 0.3 of the edge length before the mapping
// (triangles that are not Delaunay): the free compute_geodesic_distance(), intrinsic Delaunay (the
// default) and direct, against CGAL's Heat_method_3 in its Intrinsic_Delaunay (default) and Direct
// modes, source at the pole; mean relative error against the great-circle distance, and the
// median over `runs` interleaved runs (same process) of each call's thread CPU time, with the
// ratios FAS / CGAL per mode.
//
//   bench_geodesic_distance [max_subdivisions (default 6)] [runs (default 9)]

#include "bench_clock.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include "../../test/Flow_aligned_surfaces/sphere_cap_mesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
namespace FAS = CGAL::Flow_aligned_surfaces;
using fas_benchmark::thread_cpu_ms;

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


double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void sphere_cap_table(int runs)
{
  std::printf("\nsphere caps, median thread CPU ms of %d interleaved runs\n", runs);
  std::printf("%6s %7s %8s %8s %8s %8s %8s %8s %8s %8s %7s %7s\n", "jitter", "faces", "FAS_iDT",
              "CGAL_iDT", "FAS_dir", "CGAL_dir", "e_FASiDT", "e_CGiDT", "e_FASdir", "e_CGdir", "r_iDT",
              "r_dir");
  const double R = 2;
  for (double jitter : {0.0, 0.3})
    for (std::size_t faces : {2400u, 9600u, 38400u}) {
      Mesh tm = fas_test::make_sphere_cap<Mesh>(R, 1.2, faces, jitter);
      Vertex pole = *tm.vertices().begin();
      for (Vertex v : tm.vertices())
        if (tm.point(v).z() > tm.point(pole).z())
          pole = v;
      auto maps = [&](const char* name) { return tm.add_property_map<Vertex, double>(name, 0).first; };
      auto fas_idt = maps("v:fas_idt"), fas_direct = maps("v:fas_direct"), cgal_idt = maps("v:cgal_idt"),
           cgal_direct = maps("v:cgal_direct");
      std::vector<double> t[4];
      for (int k = 0; k < runs; ++k) {
        double start = thread_cpu_ms();
        FAS::compute_geodesic_distance(tm, pole, fas_idt);
        t[0].push_back(thread_cpu_ms() - start);
        start = thread_cpu_ms();
        CGAL::Heat_method_3::estimate_geodesic_distances(tm, cgal_idt, pole,
                                                         CGAL::Heat_method_3::Intrinsic_Delaunay());
        t[1].push_back(thread_cpu_ms() - start);
        start = thread_cpu_ms();
        FAS::compute_geodesic_distance(tm, pole, fas_direct, FAS::parameters::intrinsic_delaunay(false));
        t[2].push_back(thread_cpu_ms() - start);
        start = thread_cpu_ms();
        CGAL::Heat_method_3::estimate_geodesic_distances(tm, cgal_direct, pole, CGAL::Heat_method_3::Direct());
        t[3].push_back(thread_cpu_ms() - start);
      }
      const auto error = [&](auto d) {
        double sum = 0;
        for (Vertex v : tm.vertices())
          if (v != pole) {
            const double exact = R * std::acos(std::clamp(tm.point(v).z() / R, -1.0, 1.0));
            sum += std::abs(d[v] - exact) / exact;
          }
        return 100 * sum / double(tm.number_of_vertices() - 1);
      };
      const double m[4] = {median(t[0]), median(t[1]), median(t[2]), median(t[3])};
      std::printf("%6.1f %7zu %8.1f %8.1f %8.1f %8.1f %7.3f%% %7.3f%% %7.3f%% %7.3f%% %7.2f %7.2f\n", jitter,
                  std::size_t(tm.number_of_faces()), m[0], m[1], m[2], m[3], error(fas_idt), error(cgal_idt),
                  error(fas_direct), error(cgal_direct), m[0] / m[1], m[2] / m[3]);
    }
}

int main(int argc, char** argv)
{
  const int max_subdivisions = argc > 1 ? std::atoi(argv[1]) : 6;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 9;
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
  sphere_cap_table(runs);
  return 0;
}
