// An outside application of the installed package: aligns a small planar patch orthogonally
// to a point source (the exact answer is a piece of a sphere, flux 1) and prints the flux.
// Returns nonzero when the flux is off.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Surface_mesh.h>

#include <exception>
#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  try {
    CGAL::Surface_mesh<Point> tm;
    FAS::make_planar_patch(tm, Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 1.0, 500);
    const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
    const double before = FAS::normalized_flux(tm, source);
    const FAS::Alignment_report report = FAS::align_to_flow(tm, source, FAS::Alignment::ORTHOGONAL);
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
    std::cout << "sparse solver: CHOLMOD\n";
#else
    std::cout << "sparse solver: Eigen SimplicialLDLT\n";
#endif
    std::cout << "faces: " << tm.number_of_faces() << "\n"
              << "normalized flux before: " << before << "\n"
              << "normalized flux after: " << report.normalized_flux << " (" << report.number_of_iterations
              << " iterations, converged: " << (report.converged ? "yes" : "no") << ")\n";
    if (!report.converged || !(report.normalized_flux >= 0.995) || !(before < 0.99)) {
      std::cerr << "consumer: the alignment did not reach the expected flux (>= 0.995 from < 0.99)\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "consumer: " << e.what() << "\n";
    return 2;
  }
}
