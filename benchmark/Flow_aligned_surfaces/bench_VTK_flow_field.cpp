// The cost of one query of VTK_flow_field_3 (VTK's vtkStaticCellLocator and cell
// interpolation) beside the package's own fields on the same data, ../shared/data's CYLINDER:
// the grid (vtkImageData against Regular_grid_flow_field_3) and the solver's cells
// (vtkUnstructuredGrid against Unstructured_flow_field_3, read by the package's reader or made of
// the vtkUnstructuredGrid by make_unstructured_flow_field()); random points in the grid's box, and
// coherent ones (1000 points along each of 200 lines across the box, as a deformation or an
// integration queries).  Medians of 5 passes, in ns per query, in one run.  Plain main().
//
//   bench_VTK_flow_field [data folder, default ../shared/data]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/VTK_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/make_unstructured_flow_field.h>
#include <CGAL/Random.h>

#include <vtkDataSetReader.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

template <class Field>
double ns_per_query(const Field& field, const std::vector<Point>& points)
{
  std::vector<double> passes;
  double sum = 0;
  for (int pass = 0; pass < 5; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    for (const Point& p : points)
      if (const auto v = field(p))
        sum += v->x();
    const auto end = std::chrono::steady_clock::now();
    passes.push_back(std::chrono::duration<double, std::nano>(end - start).count() / double(points.size()));
  }
  if (sum == 0.123456789)
    std::puts(""); // keeps the queries
  std::sort(passes.begin(), passes.end());
  return passes[2];
}

vtkSmartPointer<vtkDataSet> read_with_VTK(const std::string& file)
{
  vtkNew<vtkDataSetReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return vtkSmartPointer<vtkDataSet>(reader->GetOutput());
}

double ms_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int main(int argc, char** argv)
{
  const std::string folder = argc > 1 ? argv[1] : "../shared/data";
  const std::string grid_file = folder + "/CYLINDER_grid.vtk", cells_file = folder + "/CYLINDER_cells.vtk";
  FAS::Regular_grid_flow_field_3<K> grid;
  FAS::Unstructured_flow_field_3<K> cells;
  std::string error;
  if (!FAS::IO::read_VTK_flow_field(grid_file, grid, FAS::parameters::error_message(&error)) ||
      !FAS::IO::read_VTK_flow_field(cells_file, cells, FAS::parameters::error_message(&error))) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const vtkSmartPointer<vtkDataSet> image = read_with_VTK(grid_file), mesh = read_with_VTK(cells_file);
  auto start = std::chrono::steady_clock::now();
  const FAS::VTK_flow_field_3<K> on_image(image.Get());
  const double image_ms = ms_since(start);
  start = std::chrono::steady_clock::now();
  const FAS::VTK_flow_field_3<K> on_mesh(mesh.Get());
  const double mesh_ms = ms_since(start);
  start = std::chrono::steady_clock::now();
  const std::optional<FAS::Unstructured_flow_field_3<K>> converted = FAS::make_unstructured_flow_field<K>(mesh.Get());
  const double converted_ms = ms_since(start);
  if (!converted) {
    std::fprintf(stderr, "make_unstructured_flow_field() refused %s\n", cells_file.c_str());
    return 1;
  }

  CGAL::Random random(1);
  const CGAL::Bbox_3 b = grid.bbox();
  std::vector<Point> scattered, coherent;
  for (int i = 0; i < 200000; ++i)
    scattered.emplace_back(random.get_double(b.xmin(), b.xmax()), random.get_double(b.ymin(), b.ymax()),
                           random.get_double(b.zmin(), b.zmax()));
  for (int line = 0; line < 200; ++line) {
    const double y = random.get_double(b.ymin(), b.ymax()), z = random.get_double(b.zmin(), b.zmax());
    for (int i = 0; i < 1000; ++i)
      coherent.emplace_back(b.xmin() + (b.xmax() - b.xmin()) * i / 1000., y, z);
  }
  std::printf("construction: VTK_flow_field_3 (its locator) on the vtkImageData of %lld cells %.0f ms, on the "
              "vtkUnstructuredGrid of %lld cells %.0f ms; make_unstructured_flow_field() %.0f ms\n",
              (long long)image->GetNumberOfCells(), image_ms, (long long)mesh->GetNumberOfCells(), mesh_ms,
              converted_ms);
  std::printf("%-10s  %14s  %14s  %14s  %14s  %14s\n", "points", "Regular_grid", "VTK image", "Unstructured",
              "made of VTK", "VTK cells");
  for (const auto& [name, points] : {std::pair{"scattered", &scattered}, std::pair{"coherent", &coherent}})
    std::printf("%-10s  %11.1f ns  %11.1f ns  %11.1f ns  %11.1f ns  %11.1f ns\n", name, ns_per_query(grid, *points),
                ns_per_query(on_image, *points), ns_per_query(cells, *points), ns_per_query(*converted, *points),
                ns_per_query(on_mesh, *points));
  return 0;
}
