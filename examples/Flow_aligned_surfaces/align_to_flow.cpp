// Deforms a disk in one call until the flow of a point source crosses it at right angles: the
// disk becomes a piece of a sphere around the source (a seeding surface).  The input surface is
// a mesh file if one is given, else a tilted disk above the source.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main(int argc, char* argv[])
{
  Surface_mesh sm;
  if (argc > 1) {
    if (!CGAL::IO::read_polygon_mesh(argv[1], sm)) {
      std::cerr << "Invalid input file." << std::endl;
      return 1;
    }
  }
  else // a disk of radius 0.5 with about 4000 triangles, tilted, at distance 1 from the source
    FAS::make_disk_patch(sm, Point_3(0, 0, 1), Vector_3(0.3, 0, 1), 0.5, 4000);

  const FAS::Point_source_flow<Kernel> flow(Point_3(0, 0, 0));
  const FAS::Alignment_report report = FAS::align_to_flow(sm, flow, FAS::Alignment::ORTHOGONAL);

  std::cout << "normalized flux " << report.normalized_flux << " (1: orthogonal) after "
            << report.number_of_iterations << " iterations"
            << (report.converged ? "" : " (not converged)") << std::endl;
  CGAL::IO::write_polygon_mesh("aligned.off", sm, CGAL::parameters::stream_precision(17));
  return 0;
}
