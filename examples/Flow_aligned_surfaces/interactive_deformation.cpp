// An interactive session without a window: the surface is aligned a few iterations at a time,
// moved rigidly by the "user" in between, and adapts to the flow at its new place with no new
// factorization; then it is grown across the flow, which refactors once, and re-converges.  A
// visitor prints every iteration's report (flux, largest rotation, times).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
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
  // A stream surface of the Burgers vortex, searched from a tilted disk beside the axis.
  const FAS::Burgers_vortex<Kernel> flow;
  Mesh tm;
  FAS::make_disk_patch(tm, Point(1.0, 0.0, 0.5), Vector(0.0, 1.0, 0.3), 0.5, 2000);

  auto print = [](const FAS::Iteration_report& r) {
    std::cout << "  iteration " << r.iteration << ": flux " << r.normalized_flux << ", largest rotation "
              << r.max_rotation_angle << " rad, GTRANSF " << r.gradient_transformation_ms << " ms, SOLVE "
              << r.solve_ms << " ms" << (r.converged ? " (converged)" : "") << "\n";
  };
  FAS::Flow_aligned_deformation<Mesh, FAS::Burgers_vortex<Kernel>> deformation(
      tm, flow, FAS::Alignment::TANGENTIAL,
      FAS::parameters::max_rotation_angle(0.1, CGAL::parameters::visitor(print)));

  std::cout << "three iterations by hand:\n";
  for (int k = 0; k < 3; ++k)
    deformation.step();

  std::cout << "until converged:\n";
  deformation.run();

  std::cout << "the user drags the surface up the axis and turns it:\n";
  deformation.translate(Vector(0.0, 0.0, 0.5));
  deformation.rotate(Vector(0.0, 0.0, 1.0), 0.3);
  deformation.run();
  std::cout << "  " << deformation.number_of_factorizations() << " factorization so far\n";

  std::cout << "the user grows the surface across the flow by 0.1:\n";
  const FAS::Growth_report growth = deformation.grow(0.1, FAS::parameters::across_flow(true));
  std::cout << "  " << growth.number_of_new_faces << " new faces along " << growth.grown_boundary_length
            << " of boundary, area " << growth.added_area << "\n";
  const FAS::Alignment_report report = deformation.run();

  std::cout << "final flux " << report.normalized_flux << " after " << deformation.number_of_iterations()
            << " iterations and " << deformation.number_of_factorizations() << " factorizations\n";
  return 0;
}
