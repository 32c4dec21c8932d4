// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A face graph flattened into arrays, in the order of its vertex and face index
// maps: positions (m x 3), the three vertex indices of each face, the pairs of
// faces across each interior edge, and the connected components of the faces.
// The numerical code works on these arrays only, so it is the same for every
// model of FaceListGraph.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_MESH_ARRAYS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_MESH_ARRAYS_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;
/// The same stored row by row: the three coordinates of a vertex side by side, for the loops
/// over faces that read the vertices of each face.
using Row_positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct Mesh_arrays {
  std::vector<std::array<Eigen::Index, 3>> face_vertices;
  struct Interior_edge {
    std::size_t faces[2];     // p, q
    Eigen::Index vertices[2]; // the shared edge
  };
  std::vector<Interior_edge> interior_edges;
  std::vector<std::size_t> face_component; // connected component of each face
  std::size_t number_of_components = 0;
};

/// The connected component of each of the first `number_of_vertices` vertices: that of its
/// faces (0 for a vertex on no face).
inline std::vector<std::size_t> vertex_components(const Mesh_arrays& arrays, std::size_t number_of_vertices)
{
  std::vector<std::size_t> component(number_of_vertices, 0);
  for (std::size_t j = 0; j < arrays.face_vertices.size(); ++j)
    for (Eigen::Index v : arrays.face_vertices[j])
      component[std::size_t(v)] = arrays.face_component[j];
  return component;
}

/// The vertices of `tm` in the order of the index map `vim`.
template <class TriangleMesh, class VertexIndexMap>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
vertices_in_index_order(const TriangleMesh& tm, VertexIndexMap vim)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> ordered(num_vertices(tm));
  for (auto v : vertices(tm))
    ordered[get(vim, v)] = v;
  return ordered;
}

/// The positions (m x 3) of `ordered_vertices` into `x`, row i for the vertex of index i; the
/// storage of `x` is reused when it has the right size.
template <class VertexDescriptor, class VertexPointMap, class Matrix>
void read_positions(const std::vector<VertexDescriptor>& ordered_vertices, VertexPointMap vpm,
                    Eigen::PlainObjectBase<Matrix>& x)
{
  x.resize(static_cast<Eigen::Index>(ordered_vertices.size()), 3);
  Eigen::Index i = 0;
  for (auto v : ordered_vertices) {
    const auto& p = get(vpm, v);
    x.row(i++) << CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z());
  }
}

/// The positions (m x 3) of `ordered_vertices`, row i for the vertex of index i.
template <class VertexDescriptor, class VertexPointMap>
Positions read_positions(const std::vector<VertexDescriptor>& ordered_vertices, VertexPointMap vpm)
{
  Positions x;
  read_positions(ordered_vertices, vpm, x);
  return x;
}

/// Throws std::invalid_argument naming `name` and the first vertex (in index order) with a
/// NaN or infinite coordinate, if any.
template <class Matrix>
void check_finite_positions(const Eigen::MatrixBase<Matrix>& x, const std::string& name)
{
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    if (!x.row(i).allFinite())
      throw std::invalid_argument(name + ": vertex " + std::to_string(i) +
                                  " has a coordinate that is not finite");
}

template <class VertexDescriptor, class VertexPointMap, class GeomTraits, class Matrix>
void write_positions(const Eigen::MatrixBase<Matrix>& x, const std::vector<VertexDescriptor>& ordered_vertices,
                     VertexPointMap vpm, const GeomTraits& gt)
{
  auto construct_point = gt.construct_point_3_object();
  Eigen::Index i = 0;
  for (auto v : ordered_vertices) {
    const auto r = x.row(i++);
    put(vpm, v, construct_point(r[0], r[1], r[2]));
  }
}

/// \pre `tm` is a triangle mesh.
template <class TriangleMesh, class VertexIndexMap, class FaceIndexMap>
Mesh_arrays make_mesh_arrays(const TriangleMesh& tm, VertexIndexMap vim, FaceIndexMap fim)
{
  Mesh_arrays arrays;
  arrays.face_vertices.resize(num_faces(tm));
  for (auto f : faces(tm)) {
    auto& fv = arrays.face_vertices[get(fim, f)];
    int i = 0;
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      fv[i++] = static_cast<Eigen::Index>(get(vim, v));
  }

  // Union-find over the faces, joined across interior edges.
  std::vector<std::size_t> parent(num_faces(tm));
  for (std::size_t i = 0; i < parent.size(); ++i)
    parent[i] = i;
  auto root = [&parent](std::size_t i) {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  // One reservation: growing by doubling would touch about twice the memory, and fresh memory
  // is expensive on its first touch (a page fault per 4 KiB).
  arrays.interior_edges.reserve(num_edges(tm));
  for (auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    if (is_border_edge(h, tm))
      continue;
    const std::size_t p = get(fim, face(h, tm)), q = get(fim, face(opposite(h, tm), tm));
    arrays.interior_edges.push_back({{p, q},
                                     {static_cast<Eigen::Index>(get(vim, source(h, tm))),
                                      static_cast<Eigen::Index>(get(vim, target(h, tm)))}});
    parent[root(p)] = root(q);
  }
  // Components numbered in the order of their first face; `parent`, no longer needed once every
  // face knows its root, then maps a root to its component.
  arrays.face_component.resize(parent.size());
  for (std::size_t f = 0; f < parent.size(); ++f)
    arrays.face_component[f] = root(f);
  std::vector<std::size_t>& component_of_root = parent;
  std::fill(component_of_root.begin(), component_of_root.end(), std::size_t(-1));
  for (std::size_t f = 0; f < parent.size(); ++f) {
    std::size_t& c = component_of_root[arrays.face_component[f]];
    if (c == std::size_t(-1))
      c = arrays.number_of_components++;
    arrays.face_component[f] = c;
  }
  return arrays;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_MESH_ARRAYS_H
