// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The constructor of a Flow_aligned_deformation (operators + one factorization)
// on a 2e4-face planar patch in the point source |v| = 1/r^2, with the default solver (CHOLMOD
// simplicial LDL^T: no BLAS, no OpenMP) and with CHOLMOD's own choice (its supernodal switch,
// fas_benchmark::Cholmod_auto_LDLT: OpenMP loops and the system's BLAS), alternating, in one run.
// Prints the threads each kind left in the process (the default runs first, so that the
// supernodal threads cannot be counted against it), and the median, min and max constructor
// times of each.  Run it on a loaded machine to see the spread the spinning threads cause.
//
//   bench_threads [faces=20000] [rounds=7]

#include "bench_solvers.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace FAS = CGAL::Flow_aligned_surfaces;

std::optional<K::Vector_3> point_source(const K::Point_3& p)
{
  const K::Vector_3 d = p - K::Point_3(0, 0, -1.6);
  const double r2 = d.squared_length();
  return d / (r2 * std::sqrt(r2));
}

std::size_t number_of_threads()
{
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++n;
  return n;
}

template <class Solver>
double construct_ms(std::size_t faces)
{
  Mesh tm;
  FAS::make_planar_patch(tm, K::Point_3(0, 0, 0.2), K::Vector_3(0.3, 0, 1), 1.0, 1.0, faces);
  auto field = &point_source;
  const auto start = std::chrono::steady_clock::now();
  FAS::Flow_aligned_deformation<Mesh, decltype(field), CGAL::Default, CGAL::Default, Solver> d(
      tm, field, FAS::Alignment::ORTHOGONAL);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void print(const char* name, std::vector<double> t, std::size_t threads)
{
  std::sort(t.begin(), t.end());
  std::printf("%-34s threads gained %zu  constructor ms: median %.1f  min %.1f  max %.1f\n", name, threads,
              t[t.size() / 2], t.front(), t.back());
}

} // namespace

int main(int argc, char** argv)
{
  const std::size_t faces = argc > 1 ? std::stoul(argv[1]) : 20000;
  const int rounds = argc > 2 ? std::stoi(argv[2]) : 7;
  std::ifstream load("/proc/loadavg");
  std::string load_average;
  std::getline(load, load_average);
  std::printf("faces %zu, rounds %d, load average before: %s\n", faces, rounds, load_average.c_str());
  using Default = FAS::internal::Default_sparse_linear_solver;
  std::vector<double> ours, former;
  const std::size_t t0 = number_of_threads();
  ours.push_back(construct_ms<Default>(faces));
  const std::size_t t1 = number_of_threads();
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
  using Former = CGAL::Eigen_solver_traits<fas_benchmark::Cholmod_auto_LDLT<Eigen::SparseMatrix<double>>>;
  former.push_back(construct_ms<Former>(faces));
  const std::size_t t2 = number_of_threads();
  for (int r = 1; r < rounds; ++r) {
    ours.push_back(construct_ms<Default>(faces));
    former.push_back(construct_ms<Former>(faces));
  }
  print("default (CHOLMOD simplicial)", ours, t1 - t0);
  print("CHOLMOD auto (supernodal switch)", former, t2 - t1);
#else
  print("default (Eigen SimplicialLDLT)", ours, t1 - t0);
#endif
  return 0;
}
