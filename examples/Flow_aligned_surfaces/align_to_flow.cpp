// The whole method in one call: a planar patch placed in a flow is deformed into a
// surface orthogonal to the flow, a seeding surface for stream surfaces.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  // A point source at the origin: its orthogonal surfaces are the spheres around it.
  const FAS::Point_source_flow<Kernel> flow;

  // A 1 x 1 square of about 2000 triangles above the source, tilted by about 17 degrees.
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 1), Vector(0.3, 0, 1), 1.0, 1.0, 2000);

  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::ORTHOGONAL);

  // The normalized flux is 1 for a surface exactly orthogonal to the flow.
  std::cout << report.number_of_iterations << " iterations, "
            << (report.converged ? "converged" : "not converged") << ", normalized flux "
            << report.normalized_flux << "\n";
  return 0;
}
