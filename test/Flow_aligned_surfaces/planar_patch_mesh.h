// The planar patches of the deformation suites as Surface_mesh values, and the diameter of a
// mesh's bounding box, the scale their comparisons are relative to.

#ifndef FAS_TEST_PLANAR_PATCH_MESH_H
#define FAS_TEST_PLANAR_PATCH_MESH_H

#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>

namespace fas_test {

using Patch_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

/// A square patch of side `size` and about `faces` triangles (make_planar_patch()).
template <class Point, class Vector>
Patch_mesh planar_patch(const Point& center, const Vector& normal, double size, std::size_t faces)
{
  Patch_mesh tm;
  CGAL::Flow_aligned_surfaces::make_planar_patch(tm, center, normal, size, size, faces);
  return tm;
}

/// The diagonal of the bounding box of `tm`.
template <class Mesh>
double diameter(const Mesh& tm)
{
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

} // namespace fas_test

#endif // FAS_TEST_PLANAR_PATCH_MESH_H
