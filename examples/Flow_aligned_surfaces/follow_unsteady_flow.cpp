// A stream surface that follows an unsteady flow.  The flow is a time series of steady steps, as
// a CFD run writes it (read one with read_PVD_flow_field()): here a swirl whose axis drifts along
// x, sampled at five times and interpolated linearly in between.  The surface is aligned at the
// first time, then re-aligned at later times from where it is: a few iterations per time and no
// new factorization.  Its cylinder about the moving axis shows that it follows the flow.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <cmath>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

// The step at time t: a swirl about the axis x = 0.2 t, y = 0, with an axial drift.
using Swirl = FAS::Helical_flow<Kernel>;
Swirl swirl_at(double t) { return Swirl(0.3, Point(0.2 * t, 0.0, 0.0)); }

// The mean distance of the surface's vertices to the axis of `swirl`.
double mean_radius(const Mesh& tm, const Swirl& swirl)
{
  double sum = 0;
  for (Mesh::Vertex_index v : tm.vertices())
    sum += std::sqrt(swirl.first_integral_radius(tm.point(v)));
  return sum / double(tm.number_of_vertices());
}

int main()
{
  std::vector<double> times;
  std::vector<Swirl> steps;
  for (int i = 0; i <= 4; ++i) {
    times.push_back(0.25 * i);
    steps.push_back(swirl_at(times.back()));
  }
  const FAS::Unsteady_flow_field_3<Swirl> flow(times, steps);

  // The flow at one time; the deformation keeps a reference to it and samples it at its time.
  FAS::Time_slice_flow_field_3<FAS::Unsteady_flow_field_3<Swirl>> flow_now(flow, flow.start_time());
  Mesh tm;
  FAS::make_planar_patch(tm, Point(1.0, 0.0, 0.0), Vector(1.0, 0.0, 0.0), 0.6, 0.6, 2000);
  FAS::Flow_aligned_deformation<Mesh, decltype(flow_now)> deformation(tm, flow_now, FAS::Alignment::TANGENTIAL);

  for (double t = flow.start_time(); t <= flow.end_time(); t += 0.125) {
    flow_now.set_time(t); // the next iterations start from the surface of the previous time
    const FAS::Alignment_report report = deformation.run();
    std::cout << "t = " << t << ": " << report.number_of_iterations << " iterations, flux "
              << report.normalized_flux << ", radius about the axis " << mean_radius(tm, swirl_at(t))
              << " (the stream surface: " << 1 - 0.2 * t << ")\n";
  }
  std::cout << deformation.number_of_factorizations() << " factorization\n";
  return 0;
}
