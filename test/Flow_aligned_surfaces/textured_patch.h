// The textured patch of the flow texture IO tests: a 3 x 2 planar patch with the texture
// coordinates uv = (x, 2 y + 0.5) and a NaN at vertex 0.

#ifndef FAS_TEST_TEXTURED_PATCH_H
#define FAS_TEST_TEXTURED_PATCH_H

#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>

namespace fas_test {

typedef CGAL::Surface_mesh<Point_3> Textured_mesh;
typedef std::array<double, 2> UV;

inline Textured_mesh::Property_map<Textured_mesh::Vertex_index, UV> textured_patch(Textured_mesh& tm)
{
  typedef Textured_mesh::Vertex_index Vertex;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 3.0, 2.0, 60);
  auto uv = tm.add_property_map<Vertex, UV>("v:uv").first;
  for (Vertex v : tm.vertices())
    uv[v] = {tm.point(v).x(), 2 * tm.point(v).y() + 0.5};
  uv[Vertex(0)][0] = std::nan("");
  return uv;
}

} // namespace fas_test

#endif // FAS_TEST_TEXTURED_PATCH_H
