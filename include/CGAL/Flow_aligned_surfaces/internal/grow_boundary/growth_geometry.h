// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geometry that growing at the boundary (grow_boundary.h) shares between its stages: what to
// grow, the strip it builds, the angles and ratios that shape it, the frames at the boundary, and
// the refusal that leaves the surface untouched.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_GROWTH_GEOMETRY_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_GROWTH_GEOMETRY_H

#include <CGAL/Flow_aligned_surfaces/Growth_report.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// What to grow: the parameters shared by the free function and the class.
struct Growth_options {
  std::optional<Eigen::Vector3d> direction; // unit
  bool across_flow = false;
};

// The tessellated strip, ready to be appended: new vertex i has index m + i (m the number of
// vertices before growing), an index below m is an existing vertex.
struct Boundary_strip {
  std::vector<Eigen::Vector3d> points;           // positions of the new vertices on the current mesh
  std::vector<Eigen::Vector3d> reference_points; // and on the reference mesh, when one was given
  std::vector<std::array<Eigen::Index, 3>> faces;
  Growth_report report;
};

// The cosine of the largest angle between a boundary edge's outward direction and the
// requested direction (growth_direction), or the across-flow direction (across_flow), for the
// edge to be grown: 60 degrees.
constexpr double growth_cone_cosine = 0.5;
// Below this sine, a direction is taken as parallel to the face normal (no in-plane part).
constexpr double parallel_sine = 1e-6;
// Above this convex turn of the boundary between two grown edges, the offset curve goes round
// the vertex on an arc (a fan of triangles) instead of a miter: a rectangle's corners keep their
// miter, and a miter is never longer than sqrt(2) d.
constexpr double fan_turn = CGAL_PI / 2 + 1e-9;
// Beyond this concave turn between two grown edges (an inside angle below 60 degrees), the two
// offsets would meet more than 2 d from the vertex: growing there is refused.
constexpr double max_concave_turn = 2 * CGAL_PI / 3;
// A strip whose height is below this fraction of the mesh's mean edge length is thin: it is not
// remeshed, and its quads whose old edge is longer than mid_vertex_ratio times the height get a
// vertex in the middle of their outer side (a right quad of sides a and d then splits into
// triangles with angles >= 20 degrees for a / d in [2.5, 5.5], two triangles do for a / d <= 2.75).
constexpr double thin_strip = 0.6;
constexpr double mid_vertex_ratio = 2.5;

template <class TriangleMesh, class VertexIndexMap>
Eigen::Vector3d position(const Positions& x, VertexIndexMap vim,
                         typename boost::graph_traits<TriangleMesh>::vertex_descriptor v)
{
  return x.row(static_cast<Eigen::Index>(get(vim, v))).transpose();
}

// Twice the area times the unit normal of the face of `h`.
template <class TriangleMesh, class VertexIndexMap>
Eigen::Vector3d face_cross(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                           typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  const Eigen::Vector3d a = position<TriangleMesh>(x, vim, source(h, tm));
  const Eigen::Vector3d b = position<TriangleMesh>(x, vim, target(h, tm));
  const Eigen::Vector3d c = position<TriangleMesh>(x, vim, target(next(h, tm), tm));
  return (b - a).cross(c - a);
}

// The local frame of a boundary: at a border halfedge h (face(h) is null), the unit normal
// of the face across it, and the outward direction, in that face's plane and orthogonal to h.
template <class TriangleMesh, class VertexIndexMap>
void border_edge_frame(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                       typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                       Eigen::Vector3d& normal, Eigen::Vector3d& outward)
{
  const auto inside = opposite(h, tm);
  normal = face_cross(tm, vim, x, inside).normalized();
  // inside runs counterclockwise about `normal`: the face is on its left, the outside on its right.
  const Eigen::Vector3d along =
      position<TriangleMesh>(x, vim, target(inside, tm)) - position<TriangleMesh>(x, vim, source(inside, tm));
  outward = along.cross(normal).normalized();
}

// The area-weighted unit normal at vertex v (the target of h).
template <class TriangleMesh, class VertexIndexMap>
Eigen::Vector3d vertex_normal(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                              typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (auto g : halfedges_around_target(h, tm))
    if (!is_border(g, tm))
      n += face_cross(tm, vim, x, g);
  return n.normalized();
}

// The orthonormal frame (boundary tangent, outward, normal) at the boundary vertex target(h_in),
// h_in and next(h_in) its two border halfedges: the columns of the result.  Offsets are carried
// from the current mesh to the reference mesh in these coordinates.
template <class TriangleMesh, class VertexIndexMap>
Eigen::Matrix3d boundary_vertex_frame(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h_in)
{
  Eigen::Vector3d n_in, o_in, n_out, o_out;
  border_edge_frame(tm, vim, x, h_in, n_in, o_in);
  border_edge_frame(tm, vim, x, next(h_in, tm), n_out, o_out);
  const Eigen::Vector3d n = vertex_normal(tm, vim, x, h_in);
  Eigen::Vector3d o = o_in + o_out;
  o -= o.dot(n) * n;
  o.normalize();
  Eigen::Matrix3d frame;
  frame.col(0) = n.cross(o);
  frame.col(1) = o;
  frame.col(2) = n;
  return frame;
}

[[noreturn]] inline void throw_growth_error(const std::string& caller, const std::string& what)
{
  throw std::invalid_argument(caller + ": " + what + "; the surface is left untouched");
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_GROWTH_GEOMETRY_H
