// Seed curves from a flow-orthogonal surface (Section 5 of the paper): a disk beside a point
// source is aligned orthogonally to the flow, parametrized orthogonally, and cut into seed curves
// by iso-contours of r; every curve on it crosses the flow at right angles, so each seeds a stream
// surface that does not degenerate.  Seed points for stream lines are spread over it as well.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>

#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef Surface_mesh::Vertex_index vertex_descriptor;
namespace FAS = CGAL::Flow_aligned_surfaces;

int main()
{
  const FAS::Point_source_flow<Kernel> flow;
  Surface_mesh sm;
  FAS::make_disk_patch(sm, Point_3(0, 0, 1), Vector_3(0.3, 0, 1), 0.6, 3000);
  FAS::align_to_flow(sm, flow, FAS::Alignment::ORTHOGONAL); // a piece of a sphere

  // (r, s) with grad r turned by alpha = 0.5 rad from the reference direction on the surface.
  auto r = sm.add_property_map<vertex_descriptor, double>("v:r", 0).first;
  auto s = sm.add_property_map<vertex_descriptor, double>("v:s", 0).first;
  FAS::parametrize_orthogonal(sm, flow, r, s, FAS::parameters::angle(0.5));

  // Seven seed curves: iso-contours of r at values evenly spaced inside its range.
  std::vector<std::vector<Point_3>> seed_curves;
  FAS::extract_iso_contours(sm, r, FAS::evenly_spaced_iso_values(sm, r, 7), std::back_inserter(seed_curves));
  for (const std::vector<Point_3>& curve : seed_curves)
    std::cout << "seed curve of " << curve.size() << " points from " << curve.front() << " to "
              << curve.back() << std::endl;

  // Seed points no closer than 0.1 to each other.
  std::vector<Point_3> seed_points;
  FAS::sample_seed_points(sm, 0.1, std::back_inserter(seed_points));
  std::cout << seed_points.size() << " seed points" << std::endl;
  return 0;
}
