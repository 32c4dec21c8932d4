// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The guard of growing at the boundary (grow_boundary.h): the grown surface must be manifold and
// no new face may cut through another face.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_CHECK_GROWN_SURFACE_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_CHECK_GROWN_SURFACE_H

#include <CGAL/Flow_aligned_surfaces/internal/Box_cell_index.h>
#include <CGAL/Flow_aligned_surfaces/internal/faces_cross.h>
#include <CGAL/Flow_aligned_surfaces/internal/grow_boundary/growth_geometry.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// The guard on the result: the old faces of `tm` (positions `x`) and the new faces (new vertex
// i at `added[i - m]`) must make a manifold surface, and no new face may intersect another face
// other than along their shared vertices or edge.  Throws naming where otherwise.  Only the new
// faces and the old faces whose bounding boxes meet theirs are put in a mesh and tested (they
// include every old face at a vertex of the strip, so the manifold test is complete): on a large
// surface, a test of the whole would cost as much as the rest of the growth.  The pairs of faces
// to test exactly are those of a new face with a near old face or another new face whose boxes
// meet, found in a grid of the new faces' boxes (Box_cell_index): CGAL's self-intersection test
// of the local mesh sorted and scanned all its boxes, old pairs included, and cost 40 % of the
// guard at 5e3 faces.
template <class TriangleMesh, class VertexIndexMap>
void check_grown_surface(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                         const std::vector<Eigen::Vector3d>& added,
                         const std::vector<std::array<Eigen::Index, 3>>& new_faces, const std::string& caller)
{
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Eigen::Index m = x.rows();
  auto at = [&](Eigen::Index v) -> Eigen::Vector3d {
    return v < m ? Eigen::Vector3d(x.row(v).transpose()) : added[std::size_t(v - m)];
  };
  auto box = [&](const std::array<Eigen::Index, 3>& f) {
    const Eigen::Vector3d a = at(f[0]), b = at(f[1]), c = at(f[2]);
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    return CGAL::Bbox_3(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
  };
  std::vector<std::array<Eigen::Index, 3>> old_faces;
  old_faces.reserve(num_faces(tm));
  for (auto f : faces(tm)) {
    std::array<Eigen::Index, 3> fv;
    int i = 0;
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      fv[i++] = Eigen::Index(get(vim, v));
    old_faces.push_back(fv);
  }
  std::vector<CGAL::Bbox_3> new_boxes;
  new_boxes.reserve(new_faces.size());
  for (const auto& f : new_faces)
    new_boxes.push_back(box(f));
  Box_cell_index new_cells(new_boxes);
  // The old faces near the new ones, and the pairs (old face, new face) whose boxes meet, in
  // the order of the old faces: found once, tested exactly once the local mesh is made.
  std::vector<char> near(old_faces.size(), 0);
  std::vector<std::pair<std::size_t, std::size_t>> old_new_pairs;
  for (std::size_t j = 0; j < old_faces.size(); ++j)
    new_cells.find_meeting(box(old_faces[j]), [&](std::size_t k) {
      near[j] = 1;
      old_new_pairs.emplace_back(j, k);
      return false;
    });

  // The local mesh: the near old faces, then the new ones.  A subset of a manifold mesh may be
  // one that Surface_mesh cannot assemble in this order (a vertex whose faces touch in several
  // fans); then the whole surface is taken.
  Mesh local;
  std::vector<Mesh::Vertex_index> local_vertex;
  auto vertex = [&](Eigen::Index v) {
    Mesh::Vertex_index& w = local_vertex[std::size_t(v)];
    if (w == Mesh::null_vertex()) {
      const Eigen::Vector3d p = at(v);
      w = local.add_vertex(Epick::Point_3(p.x(), p.y(), p.z()));
    }
    return w;
  };
  auto add = [&](const std::array<Eigen::Index, 3>& f) {
    return local.add_face(vertex(f[0]), vertex(f[1]), vertex(f[2])) != Mesh::null_face();
  };
  auto add_old_faces = [&](bool all) {
    local.clear();
    local_vertex.assign(std::size_t(m) + added.size(), Mesh::null_vertex());
    for (std::size_t j = 0; j < old_faces.size(); ++j)
      if ((all || near[j]) && !add(old_faces[j]))
        return false;
    return true;
  };
  if (!add_old_faces(false))
    add_old_faces(true);
  const std::size_t number_of_old_faces = local.number_of_faces();

  auto centroid = [&](const std::array<Eigen::Index, 3>& f) {
    const Eigen::Vector3d c = (at(f[0]) + at(f[1]) + at(f[2])) / 3;
    std::ostringstream os;
    os << "(" << c.x() << ", " << c.y() << ", " << c.z() << ")";
    return os.str();
  };
  for (const auto& f : new_faces)
    if (!add(f))
      throw_growth_error(caller, "the new face at " + centroid(f) +
                                     " would make the surface non-manifold (grow by a smaller distance)");
  std::vector<Mesh::Halfedge_index> non_manifold;
  PMP::non_manifold_vertices(local, std::back_inserter(non_manifold));
  for (auto h : non_manifold) // tm was checked to be manifold: only a vertex of a new face can be
    for (auto g : CGAL::halfedges_around_target(h, local))
      if (!local.is_border(g) && std::size_t(local.face(g)) >= number_of_old_faces) {
        const auto& p = local.point(local.target(h));
        std::ostringstream os;
        os << "the grown surface would be non-manifold at the point (" << p
           << ") (grow by a smaller distance)";
        throw_growth_error(caller, os.str());
      }
  // Every pair of faces whose boxes meet, one of them new, is tested as
  // PMP::self_intersections() would test it (the old surface's own intersections are not the
  // growth's doing): the new faces against the near old ones, then against each other.
  auto point = [&](Eigen::Index v) { return local.point(local_vertex[std::size_t(v)]); };
  auto refuse = [&](const std::array<Eigen::Index, 3>& f, const char* what) {
    throw_growth_error(caller, std::string("the new face at ") + centroid(f) + " would cut through " + what +
                                   " (the boundary comes back near itself there; grow by a smaller "
                                   "distance or along fewer edges)");
  };
  for (const auto& f : new_faces)
    if (CGAL::collinear(point(f[0]), point(f[1]), point(f[2])))
      refuse(f, "another new face");
  bool old_face_degenerate = false;
  for (std::size_t p = 0; p < old_new_pairs.size(); ++p) {
    const auto [j, k] = old_new_pairs[p];
    const auto& f = old_faces[j];
    if (p == 0 || j != old_new_pairs[p - 1].first) // the first pair of old face j
      old_face_degenerate = CGAL::collinear(point(f[0]), point(f[1]), point(f[2]));
    if (!old_face_degenerate && faces_cross(f, new_faces[k], point))
      refuse(new_faces[k], "an old face of the surface");
  }
  for (std::size_t j = 0; j < new_faces.size(); ++j)
    new_cells.find_meeting(new_boxes[j], [&](std::size_t k) {
      if (k > j && faces_cross(new_faces[j], new_faces[k], point))
        refuse(new_faces[j], "another new face");
      return false;
    });
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_CHECK_GROWN_SURFACE_H
