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

// The positions of a grown surface's vertices: the old ones (rows of `x`), then the new ones
// (vertex i >= m at `added[i - m]`), and what the guard reads of a face through them.
struct Grown_vertices {
  const Positions& x;
  const std::vector<Eigen::Vector3d>& added;

  std::size_t size() const { return std::size_t(x.rows()) + added.size(); }
  Eigen::Vector3d at(Eigen::Index v) const
  {
    return v < x.rows() ? Eigen::Vector3d(x.row(v).transpose()) : added[std::size_t(v - x.rows())];
  }
  CGAL::Bbox_3 box(const std::array<Eigen::Index, 3>& f) const
  {
    const Eigen::Vector3d a = at(f[0]), b = at(f[1]), c = at(f[2]);
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    return CGAL::Bbox_3(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z());
  }
  // The face's centroid as "(x, y, z)", to say in a message where the face is.
  std::string centroid_text(const std::array<Eigen::Index, 3>& f) const
  {
    const Eigen::Vector3d c = (at(f[0]) + at(f[1]) + at(f[2])) / 3;
    std::ostringstream os;
    os << "(" << c.x() << ", " << c.y() << ", " << c.z() << ")";
    return os.str();
  }
};

// The vertex indices of every face of `tm`, in the order of faces(tm).
template <class TriangleMesh, class VertexIndexMap>
std::vector<std::array<Eigen::Index, 3>> face_vertex_indices(const TriangleMesh& tm, VertexIndexMap vim)
{
  std::vector<std::array<Eigen::Index, 3>> result;
  result.reserve(num_faces(tm));
  for (auto f : faces(tm)) {
    std::array<Eigen::Index, 3> fv;
    int i = 0;
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      fv[i++] = Eigen::Index(get(vim, v));
    result.push_back(fv);
  }
  return result;
}

// The old faces near the new ones (`is_near[j]`), and the pairs (old face, new face) whose boxes
// meet, in the order of the old faces: found once, tested exactly once the local mesh is made.
struct Near_old_faces {
  std::vector<char> is_near;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;

  Near_old_faces(const std::vector<std::array<Eigen::Index, 3>>& old_faces, const Grown_vertices& grown,
                 Box_cell_index& new_cells)
      : is_near(old_faces.size(), 0)
  {
    for (std::size_t j = 0; j < old_faces.size(); ++j)
      new_cells.find_meeting(grown.box(old_faces[j]), [&](std::size_t k) {
        is_near[j] = 1;
        pairs.emplace_back(j, k);
        return false;
      });
  }
};

// The local mesh of the guard: the near old faces, then the new ones, each vertex made when a
// face first uses it.
class Grown_local_mesh {
public:
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;

  explicit Grown_local_mesh(const Grown_vertices& grown) : m_grown(grown) {}

  // A subset of a manifold mesh may be one that Surface_mesh cannot assemble in this order (a
  // vertex whose faces touch in several fans); then the whole surface is taken.
  void add_old_faces(const std::vector<std::array<Eigen::Index, 3>>& old_faces, const std::vector<char>& near)
  {
    if (!add_old_faces(old_faces, near, false))
      add_old_faces(old_faces, near, true);
  }
  // Whether Surface_mesh took the face.
  bool add_face(const std::array<Eigen::Index, 3>& f)
  {
    return m_mesh.add_face(vertex(f[0]), vertex(f[1]), vertex(f[2])) != Mesh::null_face();
  }
  Epick::Point_3 point(Eigen::Index v) const { return m_mesh.point(m_local_vertex[std::size_t(v)]); }
  const Mesh& mesh() const { return m_mesh; }

private:
  bool add_old_faces(const std::vector<std::array<Eigen::Index, 3>>& old_faces, const std::vector<char>& near,
                     bool all)
  {
    m_mesh.clear();
    m_local_vertex.assign(m_grown.size(), Mesh::null_vertex());
    for (std::size_t j = 0; j < old_faces.size(); ++j)
      if ((all || near[j]) && !add_face(old_faces[j]))
        return false;
    return true;
  }
  Mesh::Vertex_index vertex(Eigen::Index v)
  {
    Mesh::Vertex_index& w = m_local_vertex[std::size_t(v)];
    if (w == Mesh::null_vertex()) {
      const Eigen::Vector3d p = m_grown.at(v);
      w = m_mesh.add_vertex(Epick::Point_3(p.x(), p.y(), p.z()));
    }
    return w;
  }

  const Grown_vertices& m_grown;
  Mesh m_mesh;
  std::vector<Mesh::Vertex_index> m_local_vertex;
};

// Adds the new faces to `local` (which holds the old ones) and throws where one of them would make
// the surface non-manifold.
inline void check_grown_surface_manifold(Grown_local_mesh& local, const Grown_vertices& grown,
                                         const std::vector<std::array<Eigen::Index, 3>>& new_faces,
                                         const std::string& caller)
{
  const std::size_t number_of_old_faces = local.mesh().number_of_faces();
  for (const auto& f : new_faces)
    if (!local.add_face(f))
      throw_growth_error(caller, "the new face at " + grown.centroid_text(f) +
                                     " would make the surface non-manifold (grow by a smaller distance)");
  const Grown_local_mesh::Mesh& mesh = local.mesh();
  std::vector<Grown_local_mesh::Mesh::Halfedge_index> non_manifold;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(non_manifold));
  for (auto h : non_manifold) // tm was checked to be manifold: only a vertex of a new face can be
    for (auto g : CGAL::halfedges_around_target(h, mesh))
      if (!mesh.is_border(g) && std::size_t(mesh.face(g)) >= number_of_old_faces) {
        const auto& p = mesh.point(mesh.target(h));
        std::ostringstream os;
        os << "the grown surface would be non-manifold at the point (" << p
           << ") (grow by a smaller distance)";
        throw_growth_error(caller, os.str());
      }
}

// Every pair of faces whose boxes meet, one of them new, is tested as
// PMP::self_intersections() would test it (the old surface's own intersections are not the
// growth's doing): the new faces against the near old ones, then against each other.  Throws
// naming the first new face that cuts through another face.
inline void check_grown_surface_crossings(const Grown_local_mesh& local, const Grown_vertices& grown,
                                          const std::vector<std::array<Eigen::Index, 3>>& old_faces,
                                          const std::vector<std::array<Eigen::Index, 3>>& new_faces,
                                          const Near_old_faces& near_old,
                                          const std::vector<CGAL::Bbox_3>& new_boxes,
                                          Box_cell_index& new_cells, const std::string& caller)
{
  auto point = [&](Eigen::Index v) { return local.point(v); };
  auto refuse = [&](const std::array<Eigen::Index, 3>& f, const char* what) {
    throw_growth_error(caller, std::string("the new face at ") + grown.centroid_text(f) +
                                   " would cut through " + what +
                                   " (the boundary comes back near itself there; grow by a smaller "
                                   "distance or along fewer edges)");
  };
  for (const auto& f : new_faces)
    if (CGAL::collinear(point(f[0]), point(f[1]), point(f[2])))
      refuse(f, "another new face");
  bool old_face_degenerate = false;
  for (std::size_t p = 0; p < near_old.pairs.size(); ++p) {
    const auto [j, k] = near_old.pairs[p];
    const auto& f = old_faces[j];
    if (p == 0 || j != near_old.pairs[p - 1].first) // the first pair of old face j
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
  const Grown_vertices grown{x, added};
  const std::vector<std::array<Eigen::Index, 3>> old_faces = face_vertex_indices(tm, vim);
  std::vector<CGAL::Bbox_3> new_boxes;
  new_boxes.reserve(new_faces.size());
  for (const auto& f : new_faces)
    new_boxes.push_back(grown.box(f));
  Box_cell_index new_cells(new_boxes);
  const Near_old_faces near_old(old_faces, grown, new_cells);
  Grown_local_mesh local(grown);
  local.add_old_faces(old_faces, near_old.is_near);
  check_grown_surface_manifold(local, grown, new_faces, caller);
  check_grown_surface_crossings(local, grown, old_faces, new_faces, near_old, new_boxes, new_cells, caller);
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_CHECK_GROWN_SURFACE_H
