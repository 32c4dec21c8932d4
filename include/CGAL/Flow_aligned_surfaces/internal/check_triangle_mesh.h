// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks every algorithm of the package makes on its input mesh, with a
// message that names the input and what is wrong.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CHECK_TRIANGLE_MESH_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CHECK_TRIANGLE_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <stdexcept>
#include <string>
#include <vector>

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
  {
    std::size_t vertex_index = 0;
    for (auto v : vertices(tm)) {
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        throw std::invalid_argument(name + ": vertex " + std::to_string(vertex_index) +
                                    " is isolated (it belongs to no face)");
      ++vertex_index;
    }
  }
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
  // A vertex is manifold when the halfedges pointing to it form a single fan: its cycle holds
  // all of them and at most one border halfedge (Surface_mesh links the fans of a bow tie
  // into one cycle through their border halfedges).  Linear in the size of the mesh, where
  // PMP's per-vertex test allocates per call and is quadratic over the whole mesh.
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<std::size_t> incoming(num_vertices(tm), 0);
  for (auto h : halfedges(tm))
    ++incoming[get(vim, target(h, tm))];
  std::size_t vertex_index = 0;
  for (auto v : vertices(tm)) {
    std::size_t fan = 0, borders = 0;
    for (auto h : halfedges_around_target(halfedge(v, tm), tm)) {
      ++fan;
      borders += is_border(h, tm) ? 1 : 0;
    }
    if (fan != incoming[get(vim, v)] || borders > 1)
      throw std::invalid_argument(name + ": vertex " + std::to_string(vertex_index) +
                                  " is non-manifold (its faces form more than one fan)");
    ++vertex_index;
  }
}

/// What every read-only algorithm takes from a mesh and its named parameters once
/// `check_triangle_mesh()` has accepted the mesh: the vertex point map (`vertex_point_map`, by
/// default the mesh's own) and the geometric traits (`geom_traits`, by default the kernel of the
/// points).
template <class TriangleMesh, class NamedParameters>
struct Checked_mesh_input {
  using Geom_traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Vertex_point_map = typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  Vertex_point_map vpm;
  Geom_traits gt;
};

/// Checks `tm` (messages start with `name`) and reads its vertex point map and traits from `np`.
template <class TriangleMesh, class NamedParameters>
Checked_mesh_input<TriangleMesh, NamedParameters>
checked_mesh_input(const TriangleMesh& tm, const NamedParameters& np, const std::string& name)
{
  using Input = Checked_mesh_input<TriangleMesh, NamedParameters>;
  check_triangle_mesh(tm, name);
  return Input{
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                         get_const_property_map(CGAL::vertex_point, tm)),
      CGAL::parameters::choose_parameter<typename Input::Geom_traits>(
          CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits))};
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CHECK_TRIANGLE_MESH_H
