// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading a ~100 MB BINARY legacy VTK file (STRUCTURED_POINTS, 198^3 nodes: VECTORS float and
// an unsigned_char mask, 100.9 MB) with read_VTK_flow_field(..., use_parallelism(true)), against `cat FILE > /dev/null`
// in the same run (target: <= 2 x cat).  The file is written once into a temporary folder by
// the package's writer, read once by cat to warm the page cache, then cat and the reader are
// timed alternately, `runs` times each (default 7); the medians and their ratio are printed.
// Wall-clock times (steady_clock); cat's include starting the shell and cat (~1 ms).  For the
// reader, the process's CPU time (user + system, getrusage; with TBB the sum over its threads)
// and minor page faults per read are printed too, and for cat the CPU time of the shell and
// cat (RUSAGE_CHILDREN): on a loaded machine the wall time includes waiting for a core.
//
//   bench_read_VTK [runs] [folder]

#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef FAS::Regular_grid_flow_field_3<K> Grid;

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU seconds (user + system) and minor page faults of this process (or of its waited-for
// children) so far.
std::pair<double, long> usage(int who = RUSAGE_SELF)
{
  rusage u;
  getrusage(who, &u);
  return {double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
              1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec),
          u.ru_minflt};
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

int main(int argc, char** argv)
{
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  std::string folder = argc > 2 ? argv[2] : (std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp");
  const std::string file = folder + "/fas_bench_read_" + std::to_string(getpid()) + ".vtk";

  const std::size_t n = 198, nodes = n * n * n;
  {
    std::vector<float> values(3 * nodes);
    std::vector<unsigned char> mask(nodes, 1);
    for (std::size_t v = 0; v < nodes; ++v) {
      const double x = double(v % n) / n, y = double((v / n) % n) / n, z = double(v / (n * n)) / n;
      values[3 * v] = float(std::sin(6. * y) + z);
      values[3 * v + 1] = float(std::cos(5. * z) - x);
      values[3 * v + 2] = float(x * y);
      if ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + (z - 0.5) * (z - 0.5) < 0.01)
        mask[v] = 0;
    }
    const Grid g(K::Point_3(0, 0, 0), K::Vector_3(1. / n, 1. / n, 1. / n), Grid::Dimensions{{n, n, n}},
                 std::move(values), std::move(mask));
    if (!FAS::IO::write_VTK_flow_field(file, g)) {
      std::fprintf(stderr, "bench_read_VTK: cannot write %s\n", file.c_str());
      return 1;
    }
  }
  std::FILE* f = std::fopen(file.c_str(), "rb");
  std::fseek(f, 0, SEEK_END);
  const double size_mb = double(std::ftell(f)) / 1e6;
  std::fclose(f);

  const std::string cat = "cat '" + file + "' > /dev/null";
  if (std::system(cat.c_str()) != 0) // warms the page cache
    return 1;
  std::vector<double> t_cat, cpu_cat, t_read, cpu_read, faults_read;
  for (int r = 0; r < runs; ++r) {
    const auto c0 = usage(RUSAGE_CHILDREN);
    auto t0 = std::chrono::steady_clock::now();
    if (std::system(cat.c_str()) != 0)
      return 1;
    t_cat.push_back(seconds_since(t0));
    cpu_cat.push_back(usage(RUSAGE_CHILDREN).first - c0.first);
    Grid field;
    const auto u0 = usage();
    t0 = std::chrono::steady_clock::now();
    std::string error;
    if (!FAS::IO::read_VTK_flow_field(
            file, field, FAS::parameters::error_message(&error, FAS::parameters::use_parallelism(true)))) {
      std::fprintf(stderr, "bench_read_VTK: %s\n", error.c_str());
      return 1;
    }
    t_read.push_back(seconds_since(t0));
    const auto u1 = usage();
    cpu_read.push_back(u1.first - u0.first);
    faults_read.push_back(double(u1.second - u0.second));
  }
  std::remove(file.c_str());
  const double c = median(t_cat), rd = median(t_read);
  std::printf(
      "file: %.1f MB BINARY STRUCTURED_POINTS %zu^3 (VECTORS float + SCALARS unsigned_char), %d runs\n",
      size_mb, n, runs);
  std::printf("cat FILE > /dev/null: median %.1f ms (min %.1f, max %.1f)\n", 1e3 * c,
              1e3 * *std::min_element(t_cat.begin(), t_cat.end()),
              1e3 * *std::max_element(t_cat.begin(), t_cat.end()));
  std::printf("read_VTK_flow_field:  median %.1f ms (min %.1f, max %.1f), %.0f MB/s\n", 1e3 * rd,
              1e3 * *std::min_element(t_read.begin(), t_read.end()),
              1e3 * *std::max_element(t_read.begin(), t_read.end()), size_mb / rd);
  std::printf("read_VTK_flow_field CPU (user + sys): median %.1f ms (min %.1f, max %.1f); minor page faults: "
              "median %.0f\n",
              1e3 * median(cpu_read), 1e3 * *std::min_element(cpu_read.begin(), cpu_read.end()),
              1e3 * *std::max_element(cpu_read.begin(), cpu_read.end()), median(faults_read));
  std::printf("cat CPU (user + sys of the shell and cat): median %.1f ms (min %.1f, max %.1f)\n",
              1e3 * median(cpu_cat), 1e3 * *std::min_element(cpu_cat.begin(), cpu_cat.end()),
              1e3 * *std::max_element(cpu_cat.begin(), cpu_cat.end()));
  std::printf("ratio read / cat: %.2f wall (target <= 2: %s), %.2f CPU\n", rd / c,
              rd <= 2. * c ? "met" : "missed", median(cpu_read) / median(cpu_cat));
  return 0;
}
