// Grows a surface at its boundary: the boundary is offset in the surface's tangent plane and the
// new strip is tessellated, first all around, then only on the side that faces a direction.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
namespace FAS = CGAL::Flow_aligned_surfaces;

void print(const char* what, const FAS::Growth_report& report, const Surface_mesh& sm)
{
  std::cout << what << ": " << report.number_of_new_faces << " new faces along "
            << report.grown_boundary_length << " of boundary, area " << report.added_area << "; "
            << sm.number_of_faces() << " faces in all" << std::endl;
}

int main()
{
  // A 1 x 1 square in the plane z = 0 with about 800 triangles.
  Surface_mesh sm;
  FAS::make_planar_patch(sm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 800);

  // All around by 0.1: the square becomes a 1.2 x 1.2 square (area 0.44 added).
  print("all around", FAS::grow_boundary(sm, 0.1), sm);

  // Only the side whose outward direction is within 60 degrees of +x (area 0.12 added).
  print("toward +x", FAS::grow_boundary(sm, 0.1, FAS::parameters::growth_direction(Vector_3(1, 0, 0))), sm);
  return 0;
}
