// Integrates the stream line through a seed point of the ABC flow, backward and forward, by the
// adaptive Dormand-Prince integrator, and says why each direction stopped.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>

#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  const FAS::ABC_flow<Kernel> flow;
  std::vector<Point_3> line; // the backward half reversed, then the forward half
  const FAS::Streamline_report report = FAS::integrate_streamline(
      flow, Point_3(1, 1, 1), std::back_inserter(line),
      FAS::parameters::max_length(
          10.0, FAS::parameters::integration_direction(FAS::Integration_direction::BOTH)));

  std::cout << line.size() << " points from " << line.front() << " to " << line.back() << std::endl;
  std::cout << "backward: " << FAS::to_string(report.backward.termination) << " after length "
            << report.backward.length << ", forward: " << FAS::to_string(report.forward.termination)
            << " after length " << report.forward.length << std::endl;
  return 0;
}
