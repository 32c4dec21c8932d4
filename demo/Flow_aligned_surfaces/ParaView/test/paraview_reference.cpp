// The library called directly, for the plugin's tests: what each filter of the plugin must
// reproduce, computed without ParaView and written as files the test scripts compare with.
//
//   paraview_reference field OUT.vti
//       the potential flow past the unit cylinder (axis z), sampled on a regular grid
//   paraview_reference align FIELD.vti OUT.vtp CX CY CZ NX NY NZ SIZE FACES planar|disk
//                      tangential|orthogonal ITERATIONS
//       the patch after ITERATIONS iterations (fewer when it converged)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

int usage()
{
  std::cerr << "usage: paraview_reference field OUT.vti\n"
               "       paraview_reference align FIELD.vti OUT.vtp CX CY CZ NX NY NZ SIZE FACES "
               "planar|disk tangential|orthogonal ITERATIONS\n";
  return 2;
}

double number(const char* text) { return std::strtod(text, nullptr); }

int write_field(const std::string& out)
{
  const FAS::Cylinder_potential_flow<K> flow;
  const auto grid = FAS::Regular_grid_flow_field_3<K>::sample(
      flow, K::Point_3(-3, -2, -1), K::Vector_3(0.1, 0.1, 0.1), {{61, 41, 21}});
  std::string error;
  if (!FAS::IO::write_VTI_flow_field(out, grid, &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  return 0;
}

int align(char** argv)
{
  FAS::Sampled_flow_field_3<K> field;
  std::string error;
  if (!FAS::IO::read_flow_field(argv[2], field, &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  const K::Point_3 center(number(argv[4]), number(argv[5]), number(argv[6]));
  const K::Vector_3 normal(number(argv[7]), number(argv[8]), number(argv[9]));
  const double size = number(argv[10]);
  const std::size_t faces = std::size_t(number(argv[11]));
  Mesh tm;
  if (std::string(argv[12]) == "disk")
    FAS::make_disk_patch(tm, center, normal, size / 2, faces);
  else
    FAS::make_planar_patch(tm, center, normal, size, size, faces);
  const FAS::Alignment alignment =
      std::string(argv[13]) == "orthogonal" ? FAS::Alignment::ORTHOGONAL : FAS::Alignment::TANGENTIAL;
  FAS::Flow_aligned_deformation<Mesh, FAS::Sampled_flow_field_3<K>> deformation(tm, field, alignment);
  const std::size_t iterations = std::size_t(number(argv[14]));
  for (std::size_t k = 0; k < iterations; ++k)
    if (deformation.step().converged)
      break;
  if (!FAS::IO::write_VTP(argv[3], tm, {}, {}, CGAL::parameters::default_values(), &error)) {
    std::cerr << error << "\n";
    return 1;
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "field" && argc == 3)
    return write_field(argv[2]);
  if (command == "align" && argc == 15)
    return align(argv);
  return usage();
}
