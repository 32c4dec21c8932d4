// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One Flow_aligned_deformation::grow() — offset of the whole boundary, tessellation of
// the strip, placement in M_0, rebuilding the operators and refactoring L + W — on planar
// patches of about 5e3 and 8e4 faces (targets: 20 ms and 300 ms).  The surface: a 1 x 1
// patch (make_planar_patch) tilted by 0.3 rad from the sphere of the point source at the
// origin through (0, 0, 1.8), after three iterations of the orthogonal deformation (so that M_k
// differs from M_0); it grows by twice its mean edge length h (sqrt(2 / (sqrt(3) F)) of the
// unit square).  Setup is not timed (manual time: the wall clock of grow() alone); the counters
// split it: offset_ms (selection, offset, raw strip), remesh_ms (split_long_edges and
// isotropic_remeshing), m0_map_ms (new vertices located in M_0, appended to the mesh, mesh
// arrays), check_ms (the grown surface checked: manifold, no new face cutting through another),
// factor_ms (operators on M_0 and the factorization), split by construction_report() into
// operators_ms, constraints_ms, analyze_ms (symbolic analysis) and factorize_ms (numeric).  Single-threaded: run with
// OMP_NUM_THREADS=1 (CHOLMOD links OpenMP).  With CHOLMOD, the same with the supernodal LL^T
// solver (template parameter SparseLinearSolver), which factors faster at 8e4 faces.  grow_cpu_ms is the thread CPU time of grow(), the
// figure to trust on a shared machine; construct_ms the constructor (operators and the first
// factorization), for comparison with the refactorization; first_touch_ms the page faults of
// grow() times the cost of one first touch of fresh memory measured on this machine
// (fas_benchmark::first_touch_us()).
//
//   OMP_NUM_THREADS=1 bench_grow --benchmark_repetitions=7 --benchmark_report_aggregates_only=true

#include "bench_clock.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Sparse>
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <memory>

namespace {

using fas_benchmark::first_touch_us;
using fas_benchmark::minor_faults;
using fas_benchmark::thread_cpu_ms;



using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace FAS = CGAL::Flow_aligned_surfaces;
using Flow = FAS::Point_source_flow<K>;
using Default_deformation = FAS::Flow_aligned_deformation<Mesh, Flow>;
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
// The alternative the solver comparison of Table 1 names for frequent refactorization.
using Supernodal_deformation = FAS::Flow_aligned_deformation<
    Mesh, Flow, CGAL::Default, CGAL::Default,
    CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>>>;
#endif

template <class Deformation>
void BM_grow_and_refactor(benchmark::State& state)
{
  const std::size_t faces = static_cast<std::size_t>(state.range(0));
  const double h = std::sqrt(2.0 / (std::sqrt(3.0) * double(faces)));
  double cpu = 0, construct = 0, offset = 0, remesh = 0, map = 0, check = 0, factor = 0, new_faces = 0, total_faces = 0;
  double operators = 0, constraints = 0, analyze = 0, factorize = 0, faults = 0;
  const Flow flow(K::Point_3(0, 0, 0), 1.0); // held by reference by the deformation
  for (auto _ : state) {
    Mesh tm;
    FAS::make_planar_patch(tm, K::Point_3(0, 0, 1.8), K::Vector_3(0, std::sin(0.3), std::cos(0.3)), 1.0, 1.0,
                           faces);
    const auto constructing = std::chrono::steady_clock::now();
    auto deformation =
        std::make_unique<Deformation>(tm, flow, FAS::Alignment::ORTHOGONAL);
    construct +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - constructing).count();
    deformation->run(3);
    const long faults_start = minor_faults();
    const double cpu_start = thread_cpu_ms();
    const auto start = std::chrono::steady_clock::now();
    const FAS::Growth_report report = deformation->grow(2 * h);
    const auto end = std::chrono::steady_clock::now();
    cpu += thread_cpu_ms() - cpu_start;
    faults += double(minor_faults() - faults_start);
    state.SetIterationTime(std::chrono::duration<double>(end - start).count());
    offset += report.offset_ms;
    remesh += report.remesh_ms;
    map += report.reference_map_ms;
    check += report.check_ms;
    factor += report.factor_ms;
    const FAS::Construction_report& rebuild = deformation->construction_report();
    operators += rebuild.operators_ms;
    constraints += rebuild.constraints_ms;
    analyze += rebuild.analyze_ms;
    factorize += rebuild.factorize_ms;
    new_faces += double(report.number_of_new_faces);
    total_faces += double(tm.number_of_faces());
    benchmark::DoNotOptimize(deformation);
  }
  const double n = double(state.iterations());
  state.counters["grow_cpu_ms"] = cpu / n;
  state.counters["construct_ms"] = construct / n;
  state.counters["offset_ms"] = offset / n;
  state.counters["remesh_ms"] = remesh / n;
  state.counters["m0_map_ms"] = map / n;
  state.counters["check_ms"] = check / n;
  state.counters["factor_ms"] = factor / n;
  state.counters["minor_faults"] = faults / n;
  // The share of grow() that is first touches of fresh memory, at this machine's cost per touch.
  state.counters["first_touch_ms"] = faults / n * first_touch_us() * 1e-3;
  state.counters["operators_ms"] = operators / n;
  state.counters["constraints_ms"] = constraints / n;
  state.counters["analyze_ms"] = analyze / n;
  state.counters["factorize_ms"] = factorize / n;
  state.counters["new_faces"] = new_faces / n;
  state.counters["faces_after"] = total_faces / n;
}

BENCHMARK_TEMPLATE(BM_grow_and_refactor, Default_deformation)
    ->Arg(5000)
    ->Arg(80000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
BENCHMARK_TEMPLATE(BM_grow_and_refactor, Supernodal_deformation)
    ->Arg(5000)
    ->Arg(80000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
#endif

} // namespace
