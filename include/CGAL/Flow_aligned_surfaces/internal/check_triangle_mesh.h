// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks every algorithm of the package makes on its input mesh, with a
// message that names the input and what is wrong.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CHECK_TRIANGLE_MESH_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CHECK_TRIANGLE_MESH_H

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Throws std::invalid_argument when `tm` is empty, not a valid triangle mesh, or has a
/// non-manifold vertex.  `name` is how the caller calls the mesh in messages.
template <class TriangleMesh>
void check_triangle_mesh(const TriangleMesh& tm, const std::string& name)
{
  if (faces(tm).empty())
    throw std::invalid_argument(name + ": the mesh has no faces");
  if (!CGAL::is_valid_polygon_mesh(tm))
    throw std::invalid_argument(name + ": the mesh is not a valid polygon mesh (broken halfedge structure)");
  std::size_t face_index = 0;
  for (auto f : faces(tm)) {
    const std::size_t degree = halfedges_around_face(halfedge(f, tm), tm).size();
    if (degree != 3)
      throw std::invalid_argument(name + ": face " + std::to_string(face_index) + " has " +
                                  std::to_string(degree) + " vertices; the mesh must be a triangle mesh");
    ++face_index;
  }
  std::size_t vertex_index = 0;
  for (auto v : vertices(tm)) {
    if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      throw std::invalid_argument(name + ": vertex " + std::to_string(vertex_index) +
                                  " is isolated (it belongs to no face)");
    if (CGAL::Polygon_mesh_processing::is_non_manifold_vertex(v, tm))
      throw std::invalid_argument(name + ": vertex " + std::to_string(vertex_index) +
                                  " is non-manifold (its faces form more than one fan)");
    ++vertex_index;
  }
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CHECK_TRIANGLE_MESH_H
