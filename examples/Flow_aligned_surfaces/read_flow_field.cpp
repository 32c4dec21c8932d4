// Reads a velocity field from a data file of any supported format (legacy VTK, VTK XML,
// AmiraMesh, NRRD) and queries it like any flow.  Without a file given, a point source sampled on
// a 16 x 16 x 16 grid is written first as a legacy VTK file and read back.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Sampled_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>

#include <iostream>
#include <optional>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : "point_source.vtk";
  if (argc == 1) {
    const FAS::Regular_grid_flow_field_3<Kernel> grid = FAS::sample_on_grid(
        FAS::Point_source_flow<Kernel>(), Point_3(-1.5, -1.5, 0.25), Vector_3(0.2, 0.2, 0.2), {16, 16, 16});
    FAS::IO::write_VTK_flow_field(filename, grid);
  }

  // The field holds whichever grid the file has (uniform, rectilinear, or cells).
  FAS::Sampled_flow_field_3<Kernel> field;
  std::string error;
  if (!FAS::IO::read_flow_field(filename, field, FAS::parameters::error_message(&error))) {
    std::cerr << error << std::endl; // names the file, the place in it and what is wrong
    return 1;
  }

  const CGAL::Bbox_3 box = field.bbox();
  const Point_3 center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                       (box.zmin() + box.zmax()) / 2);
  std::cout << filename << ": domain " << box << std::endl;
  if (const std::optional<Vector_3> v = field(center))
    std::cout << "velocity at the center " << center << ": " << *v << std::endl;
  else
    std::cout << "the center " << center << " is outside the domain" << std::endl;
  return 0;
}
