// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The constructor of Flow_aligned_deformation as an outside program sees it.
// An outside program builds one deformation, once, in a fresh process; bench_deformation builds
// many in one long-lived process.  This program does what the outside program does, in a fresh
// child process per size and case, and splits the constructor into its phases
// (Flow_aligned_deformation::construction_report(): checks, mesh arrays, operators, constraint
// choice, symbolic analysis, numeric factorization).  The setup is Table 1's: a 1 x 1 planar
// patch (make_planar_patch) centered at (0, 0, 0.2), its normal e_z tilted by 0.3 rad about e_x,
// in the point source of strength 4 pi at (0, 0, -1.6) sampled on a 128^3 grid over [-1, 1]^3
// (Regular_grid_flow_field_3, trilinear), held by std::cref.
//
// Cases, each in its own child process (medians over the processes):
//   first          the first construction of the process (what the outside program timed)
//   second         the next construction, same process, a new mesh of the same size
//   after_small    the first one of this size, after one construction on an 800-face patch
//                  (separates one-time initialization from size-dependent first-touch costs)
//   shuffled       as `second`, with the vertices and faces indexed in a random order (a mesh
//                  read from a file or built by another tool is rarely in make_planar_patch's
//                  row-by-row order)
// For each: wall ms, thread CPU ms, minor page faults, and the phases (wall ms).  Each child also
// measures what a first touch of fresh memory costs on this machine (a page of 4 KiB of a new
// anonymous mapping written once, 32 MiB of them): the faults times that cost estimate how much
// of the constructor is the operating system's, not the package's (item 2's "measured reason";
// on the benchmarks' virtual machine a first touch costs about 10 us, on bare metal about 0.3).
//
//   bench_construction [--sizes 800,5000,20000,80000,320000] [--processes 5]
//
// Run single-threaded as the other benchmarks (OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1; the
// default solver starts no thread anyway) and at `nice -n 10` on a shared machine.

#include "bench_clock.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using fas_benchmark::first_touch_us;
using fas_benchmark::minor_faults;
using fas_benchmark::thread_cpu_ms;

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Grid = FAS::Regular_grid_flow_field_3<K>;
using Field = std::reference_wrapper<const Grid>;
using Deformation = FAS::Flow_aligned_deformation<Mesh, Field>;



Grid make_grid()
{
  const std::size_t nodes = 128;
  const FAS::Point_source_flow<K> source(K::Point_3(0, 0, -1.6), 4 * CGAL_PI);
  const double h = 2. / double(nodes - 1);
  return FAS::sample_on_grid(source, K::Point_3(-1, -1, -1), K::Vector_3(h, h, h), {nodes, nodes, nodes});
}

void make_patch(Mesh& tm, std::size_t faces)
{
  FAS::make_planar_patch(tm, K::Point_3(0, 0, 0.2), K::Vector_3(0, -std::sin(0.3), std::cos(0.3)), 1.0, 1.0,
                         faces);
}

// One measured construction: wall ms, thread CPU ms, minor page faults, then the phases of
// construction_report() in its order.  Printed by the child, parsed by the parent.
using Figures = std::array<double, 9>;

template <class... NamedParameters>
Figures construct(Mesh& tm, const Field& field, const NamedParameters&... np)
{
  const long faults = minor_faults();
  const double cpu = thread_cpu_ms();
  const auto start = std::chrono::steady_clock::now();
  Deformation deformation(tm, field, FAS::Alignment::ORTHOGONAL, np...);
  const auto end = std::chrono::steady_clock::now();
  Figures f;
  f[0] = std::chrono::duration<double, std::milli>(end - start).count();
  f[1] = thread_cpu_ms() - cpu;
  f[2] = double(minor_faults() - faults);
  const FAS::Construction_report& r = deformation.construction_report();
  f[3] = r.check_ms;
  f[4] = r.mesh_arrays_ms;
  f[5] = r.operators_ms;
  f[6] = r.constraints_ms;
  f[7] = r.analyze_ms;
  f[8] = r.factorize_ms;
  return f;
}

void print(const std::string& name, const Figures& f)
{
  std::cout << name;
  for (double x : f)
    std::cout << ' ' << x;
  std::cout << '\n';
}

// The child: one fresh process, one size, every case that can share it.
int child(std::size_t target_faces, const std::string& mode)
{
  std::cout << "first_touch_us " << first_touch_us() << '\n';
  const Grid grid = make_grid();
  const Field field = std::cref(grid);
  if (mode == "after_small") {
    Mesh small;
    make_patch(small, 800);
    construct(small, field);
    Mesh tm;
    make_patch(tm, target_faces);
    print("after_small", construct(tm, field));
    return 0;
  }
  {
    Mesh tm;
    make_patch(tm, target_faces);
    std::cout << "faces " << num_faces(tm) << '\n';
    print("first", construct(tm, field));
  }
  {
    Mesh tm;
    make_patch(tm, target_faces);
    print("second", construct(tm, field));
  }
  {
    Mesh tm;
    make_patch(tm, target_faces);
    std::vector<std::size_t> vertex_order(num_vertices(tm)), face_order(num_faces(tm));
    std::iota(vertex_order.begin(), vertex_order.end(), std::size_t(0));
    std::iota(face_order.begin(), face_order.end(), std::size_t(0));
    std::mt19937 rng(18);
    std::shuffle(vertex_order.begin(), vertex_order.end(), rng);
    std::shuffle(face_order.begin(), face_order.end(), rng);
    auto vim = tm.add_property_map<Mesh::Vertex_index, std::size_t>("v:shuffled").first;
    auto fim = tm.add_property_map<Mesh::Face_index, std::size_t>("f:shuffled").first;
    for (auto v : vertices(tm))
      vim[v] = vertex_order[std::size_t(v)];
    for (auto f : faces(tm))
      fim[f] = face_order[std::size_t(f)];
    print("shuffled", construct(tm, field, CGAL::parameters::vertex_index_map(vim).face_index_map(fim)));
  }
  return 0;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? std::nan("") : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::size_t> parse_sizes(const std::string& list)
{
  std::vector<std::size_t> sizes;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    sizes.push_back(std::stoul(item));
  return sizes;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {800, 5000, 20000, 80000, 320000};
  int processes = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--child" && i + 2 < argc)
      return child(std::stoul(argv[i + 1]), argv[i + 2]);
    if (a == "--sizes" && i + 1 < argc)
      sizes = parse_sizes(argv[++i]);
    else if (a == "--processes" && i + 1 < argc)
      processes = std::stoi(argv[++i]);
    else {
      std::cerr << "usage: bench_construction [--sizes 800,5000,...] [--processes N]\n";
      return 2;
    }
  }

  std::cout
      << "Medians over " << processes << " fresh processes per case; wall/phase ms, CPU = thread CPU ms, "
      << "faults = minor page faults; first touch = faults x the cost of a first touch measured in the "
      << "same process (us per page below the table)\n\n"
      << "| faces | case | wall ms | CPU ms | faults | check | arrays | operators | constraints | analyze | "
         "factorize | first touch ms | wall - first touch |\n"
         "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<double> touch_costs;
  for (std::size_t size : sizes) {
    std::map<std::string, std::vector<Figures>> runs;
    std::map<std::string, std::vector<double>> first_touch_ms;
    std::size_t face_count = 0;
    for (int p = 0; p < processes; ++p)
      for (const char* mode : {"all", "after_small"}) {
        const std::string command = std::string(argv[0]) + " --child " + std::to_string(size) + " " + mode;
        FILE* pipe = popen(command.c_str(), "r");
        if (!pipe) {
          std::cerr << "cannot run " << command << '\n';
          return 1;
        }
        char line[1024];
        double touch_us = std::nan("");
        while (fgets(line, sizeof line, pipe)) {
          std::istringstream in(line);
          std::string name;
          in >> name;
          if (name == "faces") {
            in >> face_count;
            continue;
          }
          if (name == "first_touch_us") {
            in >> touch_us;
            touch_costs.push_back(touch_us);
            continue;
          }
          Figures f;
          for (double& x : f)
            in >> x;
          runs[name].push_back(f);
          first_touch_ms[name].push_back(f[2] * touch_us * 1e-3);
        }
        if (pclose(pipe) != 0) {
          std::cerr << command << " failed\n";
          return 1;
        }
      }
    for (const char* name : {"first", "after_small", "second", "shuffled"}) {
      std::cout << "| " << face_count << " | " << name;
      for (std::size_t k = 0; k < Figures().size(); ++k) {
        std::vector<double> values;
        for (const Figures& f : runs[name])
          values.push_back(f[k]);
        char cell[32];
        std::snprintf(cell, sizeof cell, k == 2 ? "%.0f" : "%.3g", median(values));
        std::cout << " | " << cell;
      }
      std::vector<double> rest;
      for (std::size_t r = 0; r < runs[name].size(); ++r)
        rest.push_back(runs[name][r][0] - first_touch_ms[name][r]);
      char touch[32], without[32];
      std::snprintf(touch, sizeof touch, "%.3g", median(first_touch_ms[name]));
      std::snprintf(without, sizeof without, "%.3g", median(rest));
      std::cout << " | " << touch << " | " << without << " |\n";
    }
  }
  if (!touch_costs.empty()) {
    const auto range = std::minmax_element(touch_costs.begin(), touch_costs.end());
    std::cout << "\nA first touch of a page of fresh memory: " << median(touch_costs)
              << " us (median over the processes; min " << *range.first << ", max " << *range.second << ")\n";
  }
  return 0;
}
