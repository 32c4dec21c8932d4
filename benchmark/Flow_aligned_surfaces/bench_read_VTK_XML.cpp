// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The load time of a VTK XML time series: the package's read_PVD_flow_field() (its own XML
// parser and decoders) against VTK's vtkXMLImageDataReader reading the same step files, in the
// same run (target: at most VTK's time).  Default data: ../shared/data/CYLINDER_UNSTEADY_grid.pvd,
// 34 ImageData files of 151 x 25 x 25 points, inline base64 zlib (level 9), 47 MB.  Each reader
// runs `runs` times (default 7), alternately, after one warm-up read of each (page cache); the
// medians of the wall time and of the process's CPU time (user + system) are printed.  Both on
// one thread (the package's reader without use_parallelism; VTK's reader is serial).  VTK's
// time is its Update() per file: parsing, decoding and decompressing into its arrays.
//
//   bench_read_VTK_XML [runs] [file.pvd]

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef FAS::Regular_grid_flow_field_3<K> Grid;

double cpu_seconds()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Timing {
  std::vector<double> wall, cpu;
};

template <class Read>
void timed(Timing& t, const Read& read)
{
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = cpu_seconds();
  read();
  t.cpu.push_back(cpu_seconds() - c0);
  t.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
}

} // namespace

int main(int argc, char** argv)
{
  const int runs = argc > 1 ? std::atoi(argv[1]) : 7;
  const std::string pvd = argc > 2 ? argv[2] : std::string(FAS_SHARED_DATA_DIR) + "/CYLINDER_UNSTEADY_grid.pvd";
  // The step files, as the package reads them (VTK has no reader of .pvd outside ParaView).
  FAS::Unsteady_flow_field_3<Grid> series;
  std::string error;
  if (!FAS::IO::read_PVD_flow_field(pvd, series, FAS::parameters::error_message(&error))) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(pvd).replace_extension("")))
    if (e.path().extension() == ".vti")
      files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  std::uintmax_t bytes = 0;
  for (const std::string& f : files)
    bytes += std::filesystem::file_size(f);
  std::size_t values = 0;
  auto ours = [&] {
    FAS::Unsteady_flow_field_3<Grid> s;
    if (!FAS::IO::read_PVD_flow_field(pvd, s, FAS::parameters::error_message(&error))) {
      std::fprintf(stderr, "%s\n", error.c_str());
      std::exit(1);
    }
    values = s.number_of_steps() * s.step(0).values().size();
  };
  std::size_t vtk_values = 0;
  auto vtk = [&] {
    vtk_values = 0;
    for (const std::string& f : files) {
      vtkNew<vtkXMLImageDataReader> reader;
      reader->SetFileName(f.c_str());
      reader->Update();
      vtk_values += std::size_t(reader->GetOutput()->GetNumberOfPoints()) * 3;
    }
  };
  Timing t_ours, t_vtk, warm;
  timed(warm, ours);
  timed(warm, vtk);
  for (int r = 0; r < runs; ++r) {
    timed(t_ours, ours);
    timed(t_vtk, vtk);
  }
  std::printf("%s: %zu steps, %zu files, %.1f MB, %zu velocity values (VTK: %zu)\n", pvd.c_str(),
              series.number_of_steps(), files.size(), double(bytes) / 1e6, values, vtk_values);
  std::printf("medians of %d runs:  package read_PVD_flow_field  wall %.3f s  cpu %.3f s\n", runs,
              median(t_ours.wall), median(t_ours.cpu));
  std::printf("                     VTK vtkXMLImageDataReader    wall %.3f s  cpu %.3f s\n", median(t_vtk.wall),
              median(t_vtk.cpu));
  std::printf("ratio package / VTK: wall %.2f  cpu %.2f\n", median(t_ours.wall) / median(t_vtk.wall),
              median(t_ours.cpu) / median(t_vtk.cpu));
  return 0;
}
