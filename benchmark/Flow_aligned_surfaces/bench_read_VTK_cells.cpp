// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loading a real solver mesh from a binary legacy VTK file: read_VTK_flow_field() into an
// Unstructured_flow_field_3 (parse, checks, and the point location built, ready to query)
// beside VTK's vtkUnstructuredGridReader (parse into a vtkUnstructuredGrid, nothing built for
// queries) of the VTK the package was configured with, on the same file.  Each run is the first
// load of a fresh process (this program started again with --load), as a program that opens the
// file sees it: alternating in one process, each reader would find the pages the other freed
// (measured: VTK's time halved or doubled with the other reader's allocations).  The file is
// in the page cache (read once by both readers first).  `runs` times each (default 9), ours
// by default and with use_parallelism(true); medians of wall time and of the process's CPU
// time (user + system, getrusage: with TBB the sum over its threads), and their ratios.
// Target: ours at most VTK's time.
//
//   bench_read_VTK_cells [runs] [data folder, default ../shared/data]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkVersion.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <sys/resource.h>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

// Milliseconds of CPU (user + system) of this process so far.
double process_cpu_ms()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return 1e3 * double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-3 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Times {
  std::vector<double> wall_ms, cpu_ms;
};

// Times one call of `load`, which returns the number of cells it read.
template <class Load>
std::size_t time_once(const Load& load, Times& t)
{
  const double cpu0 = process_cpu_ms();
  const auto wall0 = std::chrono::steady_clock::now();
  const std::size_t cells = load();
  t.wall_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall0).count());
  t.cpu_ms.push_back(process_cpu_ms() - cpu0);
  return cells;
}

std::size_t load_ours(const std::string& file, bool parallel)
{
  FAS::Unstructured_flow_field_3<K> field;
  std::string error;
  if (!FAS::IO::read_VTK_flow_field(file, field,
                                    FAS::parameters::use_parallelism(parallel, FAS::parameters::error_message(&error)))) {
    std::fprintf(stderr, "bench_read_VTK_cells: %s\n", error.c_str());
    std::exit(1);
  }
  return field.number_of_cells();
}

std::size_t load_VTK(const std::string& file)
{
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->ReadAllVectorsOn();
  reader->Update();
  const vtkIdType cells = reader->GetOutput()->GetNumberOfCells();
  if (cells == 0 || reader->GetOutput()->GetPointData()->GetVectors() == nullptr) {
    std::fprintf(stderr, "bench_read_VTK_cells: vtkUnstructuredGridReader read no cells or no vectors from %s\n",
                 file.c_str());
    std::exit(1);
  }
  return static_cast<std::size_t>(cells);
}

// One load of `file` by `reader` ("ours", "ours-parallel" or "VTK") in a fresh process (this
// program, started again): the wall and CPU milliseconds of the load as it prints them.
std::pair<double, double> load_in_a_fresh_process(const char* self, const char* reader, const std::string& file)
{
  const std::string command = std::string("'") + self + "' --load " + reader + " '" + file + "'";
  FILE* child = popen(command.c_str(), "r");
  double wall = -1, cpu = -1;
  if (child == nullptr || std::fscanf(child, "%lf %lf", &wall, &cpu) != 2 || pclose(child) != 0 || wall < 0) {
    std::fprintf(stderr, "bench_read_VTK_cells: '%s' failed\n", command.c_str());
    std::exit(1);
  }
  return {wall, cpu};
}

// Returns whether ours took at most VTK's median wall time.
bool compare(const char* self, const std::string& file, int runs)
{
  Times ours, parallel, vtk;
  const std::size_t cells = load_ours(file, false);
  if (load_VTK(file) != cells) {
    std::fprintf(stderr, "bench_read_VTK_cells: the two readers disagree on the cells of %s\n", file.c_str());
    std::exit(1);
  }
  const auto add = [](Times& t, std::pair<double, double> wall_cpu) {
    t.wall_ms.push_back(wall_cpu.first);
    t.cpu_ms.push_back(wall_cpu.second);
  };
  for (int r = 0; r < runs; ++r) {
    add(ours, load_in_a_fresh_process(self, "ours", file));
    add(vtk, load_in_a_fresh_process(self, "VTK", file));
    add(parallel, load_in_a_fresh_process(self, "ours-parallel", file));
  }
  const double ratio_wall = median(ours.wall_ms) / median(vtk.wall_ms);
  const double ratio_cpu = median(ours.cpu_ms) / median(vtk.cpu_ms);
  std::printf("| %s | %zu | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.1f | %.2f |\n",
              file.substr(file.find_last_of('/') + 1).c_str(), cells, median(ours.wall_ms),
              median(ours.cpu_ms), median(vtk.wall_ms), median(vtk.cpu_ms), ratio_wall, ratio_cpu,
              median(parallel.wall_ms), median(parallel.wall_ms) / median(vtk.wall_ms));
  return ratio_wall <= 1.;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc == 4 && std::string(argv[1]) == "--load") { // one timed load, for compare()
    const std::string reader = argv[2], file = argv[3];
    Times t;
    time_once([&] { return reader == "VTK" ? load_VTK(file) : load_ours(file, reader == "ours-parallel"); }, t);
    std::printf("%.3f %.3f\n", t.wall_ms[0], t.cpu_ms[0]);
    return 0;
  }
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
  const std::string folder = argc > 2 ? argv[2] : "../shared/data";
  std::printf("read_VTK_flow_field() into Unstructured_flow_field_3 (point location built) against "
              "vtkUnstructuredGridReader of VTK %s; medians of %d alternating runs, each the first load "
              "of a fresh process\n\n",
              vtkVersion::GetVTKVersion(), runs);
  std::printf("| file | cells | ours wall ms | ours CPU ms | VTK wall ms | VTK CPU ms | ratio wall | ratio CPU | "
              "ours, use_parallelism(true), wall ms | its ratio wall |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  bool met = true;
  for (const char* name : {"CYLINDER_cells.vtk", "CAVITY_cells.vtk"})
    met = compare(argv[0], folder + "/" + name, runs) && met;
  std::printf("\nours at most VTK's wall time: %s\n", met ? "met" : "missed");
  return 0;
}
