// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Growing a surface at its boundary (Section 4 of the paper, after Schulze et al.): an offset
// curve tangential to the surface is computed at the boundary and the strip between them is
// tessellated.  The whole boundary, or the edges selected by a direction or by the flow (across
// it), is offset: every selected edge moves by d along its own outward direction in the tangent
// plane, whatever selected it, so a straight side moves by exactly d at any pose.  Between two
// grown edges the offset curve takes the miter (the offset lines' intersection) where the
// boundary turns by at most 90 degrees (concave turns up to 120), and an arc of radius d about
// the vertex (a fan of triangles) at a sharper convex turn; a run of grown edges ends in a cap
// orthogonal to its last edge (turned so as to keep 30 degrees from the old boundary beyond).
// A strip thinner than the mesh's edges is triangulated directly (a vertex in the middle of the
// outer side of a long quad), a wider one by CGAL's isotropic remeshing with the old boundary
// protected.  A final guard refuses a result that would not be manifold or in which a new face
// would cut through the surface.  Nothing is removed from the mesh: descriptors and index maps
// stay valid.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_GROW_BOUNDARY_H
#define CGAL_FLOW_ALIGNED_SURFACES_GROW_BOUNDARY_H

#include <CGAL/Flow_aligned_surfaces/internal/Box_cell_index.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/faces_cross.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/progress_callback.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/*!
\ingroup PkgFlowAlignedSurfacesRef
What `grow_boundary()` and `Flow_aligned_deformation::grow()` did.
*/
struct Growth_report {
  std::size_t number_of_new_vertices = 0; ///< vertices added to the mesh
  std::size_t number_of_new_faces = 0;    ///< faces added to the mesh
  double grown_boundary_length = 0;       ///< length of the boundary part that was offset (before growing)
  double added_area = 0;                  ///< total area of the new faces
  double offset_ms = 0;                   ///< time spent selecting the boundary and building the raw strip
  double remesh_ms = 0;        ///< time spent tessellating the strip (split and isotropic remeshing)
  double reference_map_ms = 0; ///< time spent placing the new vertices in \f$ M_0 \f$ and appending them
  double factor_ms = 0;        ///< time spent rebuilding and refactoring the operators (the class only)
  double check_ms = 0; ///< time spent checking the grown surface (manifold, no face cutting through another)
  std::size_t number_of_grown_edges = 0; ///< boundary edges that were grown (the size of `grown_edges`)
  /// The boundary edges that were grown, each as the indices of its two vertices (source and
  /// target of its border halfedge): positions in the order of `vertices(tm)` before growing for
  /// `grow_boundary()`, indices into `Flow_aligned_deformation::vertices()` for `grow()`.
  std::vector<std::pair<std::size_t, std::size_t>> grown_edges;
  /// whether the `callback` named parameter returned `false` once the strip was built: nothing
  /// was then added to the mesh (the counts are 0, the times those of the work done)
  bool stopped = false;
};

/// \cond SKIP_IN_MANUAL
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

// The fraction of a growth reported once the strip is built (offset, tessellated, checked), the
// last moment at which a stop leaves the mesh untouched; appending it (and, in the class,
// refactoring) is the rest.
constexpr double strip_built_fraction = 0.5;

// The report of a growth stopped before its strip was appended: nothing added, the times kept.
inline Growth_report stopped_growth(const Growth_report& built)
{
  Growth_report report;
  report.offset_ms = built.offset_ms;
  report.remesh_ms = built.remesh_ms;
  report.reference_map_ms = built.reference_map_ms;
  report.check_ms = built.check_ms;
  report.stopped = true;
  return report;
}

template <class Options>
Growth_options read_growth_options(const Options& np, const char* caller)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Growth_options options;
  options.across_flow = choose_parameter(get_parameter(np, internal_np::across_flow_t()), false);
  if constexpr (!parameters::is_default_parameter<Options, internal_np::growth_direction_t>::value) {
    const auto d = get_parameter(np, internal_np::growth_direction_t());
    const Eigen::Vector3d v(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z()));
    if (!v.allFinite() || !(v.norm() > 0))
      throw std::invalid_argument(std::string(caller) +
                                  ": growth_direction must be a non-zero vector with finite coordinates");
    options.direction = v.normalized();
  }
  return options;
}

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

/*
Selects the boundary edges to grow, offsets their vertices and tessellates the strip; reads
`tm` only.  `x` are the current positions in the order of `vim`; `reference`, when not null,
the reference positions in the same order, on which the same strip is built with each offset
expressed in the reference mesh's own boundary frame.  `sample(p)` returns the Flow_sample at
the point p (Eigen::Vector3d).  Throws std::invalid_argument naming `caller` and what is wrong.
*/
template <class TriangleMesh, class VertexIndexMap, class Sampler>
Boundary_strip make_boundary_strip(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                                   const Positions* reference, double distance, const Growth_options& options,
                                   const Sampler& sample, const std::string& caller)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();

  if (!(distance > 0) || !std::isfinite(distance)) {
    std::ostringstream os;
    os << "the distance must be positive and finite (got " << distance << ")";
    throw_growth_error(caller, os.str());
  }

  // The border loops, each as its border halfedges in order.
  const Eigen::Index m = x.rows();
  std::vector<char> on_loop(static_cast<std::size_t>(m), 0);
  std::vector<std::vector<halfedge_descriptor>> loops;
  for (halfedge_descriptor h : halfedges(tm)) {
    if (!is_border(h, tm) || on_loop[get(vim, target(h, tm))])
      continue;
    loops.emplace_back();
    halfedge_descriptor g = h;
    do {
      loops.back().push_back(g);
      on_loop[get(vim, target(g, tm))] = 1;
      g = next(g, tm);
    } while (g != h);
  }
  if (loops.empty())
    throw_growth_error(caller, "the mesh has no boundary (it is closed), so there is nothing to grow");

  // Per border edge: selected or not.  The flow or the direction only selects the edges; every
  // selected edge then moves along its own outward direction, so that the offset curve is the
  // same whatever selected it.
  std::vector<std::vector<char>> loop_selected(loops.size());
  std::size_t number_of_edges = 0, parallel_to_normal = 0, without_flow = 0, selected = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    loop_selected[l].assign(loops[l].size(), 0);
    for (std::size_t i = 0; i < loops[l].size(); ++i) {
      const halfedge_descriptor h = loops[l][i];
      ++number_of_edges;
      Eigen::Vector3d normal, outward;
      border_edge_frame(tm, vim, x, h, normal, outward);
      bool facing = true;
      if (options.direction) {
        Eigen::Vector3d in_plane = *options.direction - options.direction->dot(normal) * normal;
        if (in_plane.norm() <= parallel_sine) {
          ++parallel_to_normal;
          facing = false;
        }
        else
          facing = outward.dot(in_plane.normalized()) >= growth_cone_cosine;
      }
      if (options.across_flow) {
        const Eigen::Vector3d midpoint = 0.5 * (position<TriangleMesh>(x, vim, source(h, tm)) +
                                                position<TriangleMesh>(x, vim, target(h, tm)));
        const Flow_sample s = sample(midpoint);
        const Eigen::Vector3d across = normal.cross(s.direction);
        if (s.kind != Sample_kind::VALID || across.norm() <= parallel_sine) {
          ++without_flow;
          facing = false;
        }
        else
          facing = facing && std::abs(across.normalized().dot(outward)) >= growth_cone_cosine;
      }
      loop_selected[l][i] = facing ? 1 : 0;
      selected += facing ? 1 : 0;
    }
  }
  if (options.direction && parallel_to_normal == number_of_edges)
    throw_growth_error(caller, "growth_direction is parallel to the surface normal at every boundary edge");
  if (options.across_flow && without_flow == number_of_edges)
    throw_growth_error(caller, "across_flow: the flow is zero, undefined or along the normal at every "
                               "boundary edge, so no direction across it exists");
  if (selected == 0) {
    std::string what = "no boundary edge faces ";
    if (options.direction)
      what += "growth_direction";
    if (options.direction && options.across_flow)
      what += " and ";
    if (options.across_flow)
      what += "across the flow";
    throw_growth_error(caller,
                       what + " (an edge is grown when its outward direction is within 60 degrees of it)");
  }

  // The raw strip, on a separate mesh.
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Strip_mesh = CGAL::Surface_mesh<Epick::Point_3>;
  using strip_vertex = Strip_mesh::Vertex_index;
  Strip_mesh strip;
  // Per old vertex: its copy in the strip, and the first and last points of its offset (for the
  // incoming and the outgoing grown edge; the same point at a miter).
  std::vector<strip_vertex> inner(static_cast<std::size_t>(m)), outer_in(static_cast<std::size_t>(m)),
      outer_out(static_cast<std::size_t>(m));
  std::vector<Eigen::Vector3d> raw_reference; // reference position of each strip vertex
  auto base = strip.add_property_map<strip_vertex, Eigen::Index>("v:fas_base", -1).first;
  auto vertex_constrained = strip.add_property_map<strip_vertex, bool>("v:fas_constrained", false).first;
  auto edge_constrained =
      strip.add_property_map<Strip_mesh::Edge_index, bool>("e:fas_constrained", false).first;
  auto to_point = [](const Eigen::Vector3d& p) { return Epick::Point_3(p.x(), p.y(), p.z()); };
  auto point = [&](strip_vertex v) {
    const auto& s = strip.point(v);
    return Eigen::Vector3d(s.x(), s.y(), s.z());
  };
  auto add_face = [&](strip_vertex a, strip_vertex b, strip_vertex c) {
    if (strip.add_face(a, b, c) == Strip_mesh::null_face())
      throw std::logic_error(caller + ": building the raw strip failed");
  };
  auto where = [&](Eigen::Index v) {
    std::ostringstream os;
    os << "vertex " << v << " (" << x(v, 0) << ", " << x(v, 1) << ", " << x(v, 2) << ")";
    return os.str();
  };
  auto degrees = [](double angle) { return std::to_string(int(std::lround(angle * 180 / CGAL_PI))); };

  // A strip thinner than the edges is built directly, and not remeshed: the remesher could only
  // keep the old boundary's edges, too long for the strip's height, by making thin triangles.
  double total_length = 0;
  std::size_t number_of_mesh_edges = 0;
  for (auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    total_length +=
        (position<TriangleMesh>(x, vim, target(h, tm)) - position<TriangleMesh>(x, vim, source(h, tm)))
            .norm();
    ++number_of_mesh_edges;
  }
  const double mean_length = total_length / static_cast<double>(number_of_mesh_edges);
  const bool thin = distance < thin_strip * mean_length;

  Growth_report report;
  double grown_length = 0, longest_inner_edge = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::size_t k = loops[l].size();
    const std::vector<char>& grown = loop_selected[l];
    // The offset of every vertex on a grown edge, in the tangent plane at the vertex; vertex i is
    // target(loops[l][i]), between the border edges i (incoming) and i + 1 (outgoing).
    std::vector<std::vector<strip_vertex>> fans(k);
    for (std::size_t i = 0; i < k; ++i) {
      const bool in = grown[i] != 0, out = grown[(i + 1) % k] != 0;
      if (!in && !out)
        continue;
      const halfedge_descriptor h_in = loops[l][i], h_out = loops[l][(i + 1) % k];
      const Eigen::Index bi = static_cast<Eigen::Index>(get(vim, target(h_in, tm)));
      const Eigen::Vector3d b = x.row(bi).transpose();
      const Eigen::Vector3d n = vertex_normal(tm, vim, x, h_in);
      auto tangent = [&](Eigen::Vector3d t) -> Eigen::Vector3d {
        t -= t.dot(n) * n;
        if (!(t.norm() > parallel_sine * (t.norm() + 1)))
          throw_growth_error(caller, "a boundary edge at " + where(bi) +
                                         " is along the surface normal there, so it has no outward direction");
        return t.normalized();
      };
      const Eigen::Vector3d t_in = tangent(b - position<TriangleMesh>(x, vim, source(h_in, tm)));
      const Eigen::Vector3d t_out = tangent(position<TriangleMesh>(x, vim, target(h_out, tm)) - b);
      // The boundary runs with the outside on its left (o = n x t); its turn at the vertex is
      // positive where the surface is convex there: the outside angle is pi + turn.
      const Eigen::Vector3d o_in = n.cross(t_in), o_out = n.cross(t_out);
      const double turn = -std::atan2(t_in.cross(t_out).dot(n), t_in.dot(t_out));
      std::vector<Eigen::Vector3d> offsets; // from the incoming edge's side to the outgoing one's
      bool corner = true;
      if (in && out) {
        if (turn > fan_turn) {
          // A sharp convex corner: the arc of radius d about the vertex, in pieces of <= 60 degrees.
          const int pieces = int(std::ceil(turn / (CGAL_PI / 3) - 1e-9));
          for (int j = 0; j <= pieces; ++j) {
            const double theta = turn * j / pieces;
            offsets.push_back(distance * (std::cos(theta) * o_in + std::sin(theta) * t_in));
          }
        }
        else {
          // A miter: the intersection of the two edges' offset lines.
          if (turn < -max_concave_turn)
            throw_growth_error(caller, "the boundary has a concave corner of " + degrees(CGAL_PI + turn) +
                                           " degrees at " + where(bi) +
                                           ", too sharp to grow its two sides (at least " +
                                           degrees(CGAL_PI - max_concave_turn) + " degrees are needed)");
          offsets.push_back(distance / std::cos(turn / 2) * (o_in + o_out).normalized());
          corner = std::abs(turn) >= CGAL_PI / 6;
        }
      }
      else {
        // An end of a grown run: a cap orthogonal to the grown edge, turned toward it where the old
        // boundary beyond bends into the strip's way, so that 30 degrees stay between them.
        const double outside = CGAL_PI + turn;
        const double beta = (std::min)(CGAL_PI / 2, outside - CGAL_PI / 6);
        if (beta < CGAL_PI / 6)
          throw_growth_error(caller, "the boundary folds back at the end of the grown part at " + where(bi) +
                                         " (an outside angle of " + degrees(outside) +
                                         " degrees, at least 60 are needed for the strip's end)");
        const Eigen::Vector3d along = out ? t_out : Eigen::Vector3d(-t_in);
        const Eigen::Vector3d away = out ? o_out : o_in;
        offsets.push_back(distance / std::sin(beta) * (std::cos(beta) * along + std::sin(beta) * away));
      }

      inner[bi] = strip.add_vertex(to_point(b));
      put(base, inner[bi], bi);
      put(vertex_constrained, inner[bi], true);
      Eigen::Matrix3d frame, reference_frame;
      if (reference) {
        frame = boundary_vertex_frame(tm, vim, x, h_in);
        reference_frame = boundary_vertex_frame(tm, vim, *reference, h_in);
        raw_reference.resize(strip.number_of_vertices());
        raw_reference[inner[bi]] = reference->row(bi).transpose();
      }
      for (const Eigen::Vector3d& offset : offsets) {
        const strip_vertex v = strip.add_vertex(to_point(b + offset));
        fans[i].push_back(v);
        put(vertex_constrained, v, corner);
        if (reference) {
          raw_reference.resize(strip.number_of_vertices());
          raw_reference[v] = raw_reference[inner[bi]] + reference_frame * (frame.transpose() * offset);
        }
      }
      outer_in[bi] = fans[i].front();
      outer_out[bi] = fans[i].back();
    }
    // The quads of the grown edges (p, q): p q q' p', counterclockwise like the old faces, split
    // along the shorter diagonal; then the fans at the vertices.
    for (std::size_t i = 0; i < k; ++i) {
      if (!grown[i])
        continue;
      const halfedge_descriptor h = loops[l][i];
      const Eigen::Index p = static_cast<Eigen::Index>(get(vim, source(h, tm)));
      const Eigen::Index q = static_cast<Eigen::Index>(get(vim, target(h, tm)));
      report.grown_edges.emplace_back(std::size_t(p), std::size_t(q));
      const strip_vertex pp = outer_out[p], qq = outer_in[q];
      const Eigen::Vector3d pq = point(inner[q]) - point(inner[p]);
      grown_length += pq.norm();
      longest_inner_edge = (std::max)(longest_inner_edge, pq.norm());
      // An offset edge reversed with respect to its edge: the offset curve folds over.
      bool folds = !((point(qq) - point(pp)).dot(pq) > 0);
      if (reference && !folds)
        folds = !((raw_reference[qq] - raw_reference[pp]).dot(raw_reference[inner[q]] - raw_reference[inner[p]]) >
                  0);
      if (folds) {
        std::ostringstream os;
        os << "the distance " << distance << " is too large for the boundary near " << where(p)
           << ": the offset curve folds over there (grow by a smaller distance, in several steps)";
        throw_growth_error(caller, os.str());
      }
      if (thin && pq.norm() > mid_vertex_ratio * distance) {
        // A thin quad: a vertex in the middle of its outer side makes three triangles whose
        // angles stay above 20 degrees while the edge is at most 5.5 times the distance.
        const strip_vertex mid = strip.add_vertex(to_point(0.5 * (point(pp) + point(qq))));
        if (reference) {
          raw_reference.resize(strip.number_of_vertices());
          raw_reference[mid] = 0.5 * (raw_reference[pp] + raw_reference[qq]);
        }
        add_face(inner[p], inner[q], mid);
        add_face(inner[q], qq, mid);
        add_face(inner[p], mid, pp);
      }
      else if ((point(inner[p]) - point(qq)).squaredNorm() <= (point(inner[q]) - point(pp)).squaredNorm()) {
        add_face(inner[p], inner[q], qq);
        add_face(inner[p], qq, pp);
      }
      else {
        add_face(inner[p], inner[q], pp);
        add_face(inner[q], qq, pp);
      }
      put(edge_constrained, strip.edge(strip.halfedge(inner[p], inner[q])), true);
    }
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = 0; j + 1 < fans[i].size(); ++j) {
        const Eigen::Index bi = static_cast<Eigen::Index>(get(vim, target(loops[l][i], tm)));
        add_face(inner[bi], fans[i][j + 1], fans[i][j]);
      }
  }

  // Target length: the mesh's mean edge length, raised if needed so that the protected old
  // edges are no longer than 4/3 of it (the remesher's precondition for protected edges).
  const double target_length = (std::max)(mean_length, 0.76 * longest_inner_edge);
  const Strip_mesh raw = strip;
  const auto offset_done = Clock::now();

  namespace PMP = CGAL::Polygon_mesh_processing;
  if (!thin) {
    std::vector<Strip_mesh::Edge_index> free_edges;
    for (auto e : strip.edges())
      if (!get(edge_constrained, e))
        free_edges.push_back(e);
    PMP::split_long_edges(free_edges, 4. / 3. * target_length, strip,
                          CGAL::parameters::edge_is_constrained_map(edge_constrained));
    const std::vector<Strip_mesh::Face_index> strip_faces(strip.faces().begin(), strip.faces().end());
    PMP::isotropic_remeshing(strip_faces, target_length, strip,
                             CGAL::parameters::number_of_iterations(3)
                                 .edge_is_constrained_map(edge_constrained)
                                 .vertex_is_constrained_map(vertex_constrained)
                                 .protect_constraints(true)
                                 .do_project(false));
  }
  const auto remeshed = Clock::now();

  // Number the new vertices and place them on the reference strip: same triangle of the raw
  // strip, same barycentric coordinates.
  Boundary_strip result;
  result.report.number_of_grown_edges = report.grown_edges.size();
  result.report.grown_edges = std::move(report.grown_edges);
  auto index = strip.add_property_map<strip_vertex, Eigen::Index>("v:fas_index", -1).first;
  // The closest point of the raw strip to a new vertex (which the relaxation moved off the raw
  // strip by a fraction of the target length at most, most often): among the raw faces whose
  // boxes, dilated by a quarter of the target length, hold it, else by CGAL's AABB tree.
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Strip_mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, Primitive>>;
  Tree tree;
  Strip_mesh raw_reference_mesh;
  std::vector<Strip_mesh::Face_index> raw_faces;
  std::vector<CGAL::Bbox_3> raw_boxes;
  const double reach = 0.25 * target_length;
  std::optional<Box_cell_index> raw_cells;
  if (reference) {
    raw_reference_mesh = raw;
    for (auto v : raw_reference_mesh.vertices())
      raw_reference_mesh.point(v) = to_point(raw_reference[v]);
    for (auto f : raw.faces()) {
      CGAL::Bbox_3 b;
      for (auto v : vertices_around_face(raw.halfedge(f), raw))
        b += raw.point(v).bbox();
      raw_faces.push_back(f);
      raw_boxes.emplace_back(b.xmin() - reach, b.ymin() - reach, b.zmin() - reach, b.xmax() + reach,
                             b.ymax() + reach, b.zmax() + reach);
    }
    raw_cells.emplace(raw_boxes);
  }
  auto closest_raw_point = [&](const Epick::Point_3& p) {
    std::pair<Epick::Point_3, Strip_mesh::Face_index> best(p, Strip_mesh::null_face());
    double best_distance = reach * reach;
    raw_cells->find_meeting(p.bbox(), [&](std::size_t j) {
      const auto h = raw.halfedge(raw_faces[j]);
      const Epick::Triangle_3 t(raw.point(raw.source(h)), raw.point(raw.target(h)),
                                raw.point(raw.target(raw.next(h))));
      const Epick::Point_3 q = Epick::Construct_projected_point_3()(t, p);
      const double d = CGAL::squared_distance(p, q);
      if (d <= best_distance) {
        best_distance = d;
        best = {q, raw_faces[j]};
      }
      return false;
    });
    if (best.second == Strip_mesh::null_face()) {
      if (tree.empty())
        PMP::build_AABB_tree(raw, tree);
      const auto found = tree.closest_point_and_primitive(p);
      best = {found.first, found.second};
    }
    return best;
  };
  for (auto v : strip.vertices()) {
    if (get(base, v) >= 0) {
      put(index, v, get(base, v));
      continue;
    }
    put(index, v, m + static_cast<Eigen::Index>(result.points.size()));
    const auto& p = strip.point(v);
    result.points.emplace_back(p.x(), p.y(), p.z());
    if (reference) {
      const auto [q, face] = closest_raw_point(p);
      const auto p0 = PMP::construct_point(PMP::locate_in_face(q, face, raw), raw_reference_mesh);
      result.reference_points.emplace_back(p0.x(), p0.y(), p0.z());
    }
  }

  auto check_face = [&](const std::array<Eigen::Index, 3>& f, const Positions& old,
                        const std::vector<Eigen::Vector3d>& added, const char* which) {
    auto at = [&](Eigen::Index i) -> Eigen::Vector3d {
      return i < m ? Eigen::Vector3d(old.row(i).transpose()) : added[std::size_t(i - m)];
    };
    const auto t = triangle_gradients(at(f[0]), at(f[1]), at(f[2]));
    if (!t)
      throw_growth_error(caller,
                         std::string("growing would create a degenerate face") + which +
                             " (the boundary curves too much for this distance; grow in smaller steps)");
    return t->area;
  };
  for (auto f : strip.faces()) {
    std::array<Eigen::Index, 3> fv;
    int i = 0;
    for (auto v : vertices_around_face(strip.halfedge(f), strip))
      fv[i++] = get(index, v);
    result.report.added_area += check_face(fv, x, result.points, "");
    if (reference)
      check_face(fv, *reference, result.reference_points, " in the reference mesh M_0");
    result.faces.push_back(fv);
  }
  const auto mapped = Clock::now();
  check_grown_surface(tm, vim, x, result.points, result.faces, caller);
  result.report.number_of_new_vertices = result.points.size();
  result.report.number_of_new_faces = result.faces.size();
  result.report.grown_boundary_length = grown_length;
  result.report.offset_ms = std::chrono::duration<double, std::milli>(offset_done - start).count();
  result.report.remesh_ms = std::chrono::duration<double, std::milli>(remeshed - offset_done).count();
  result.report.reference_map_ms = std::chrono::duration<double, std::milli>(mapped - remeshed).count();
  result.report.check_ms = std::chrono::duration<double, std::milli>(Clock::now() - mapped).count();
  return result;
}

/*
Adds the strip's vertices (with the positions `strip.points`) and faces to `tm`, faces in the
order of a breadth-first search from the old boundary so that each one is attached along an
edge; `ordered_vertices` are the existing vertices in index order.  Returns the new vertices.
*/
template <class TriangleMesh, class VertexPointMap, class GeomTraits>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> append_strip(
    TriangleMesh& tm, VertexPointMap vpm, const GeomTraits& gt,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& ordered_vertices,
    const Boundary_strip& strip)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const Eigen::Index m = static_cast<Eigen::Index>(ordered_vertices.size());
  auto construct_point = gt.construct_point_3_object();
  std::vector<vertex_descriptor> added;
  added.reserve(strip.points.size());
  for (const Eigen::Vector3d& p : strip.points) {
    added.push_back(add_vertex(tm));
    put(vpm, added.back(), construct_point(p.x(), p.y(), p.z()));
  }
  auto descriptor = [&](Eigen::Index i) {
    return i < m ? ordered_vertices[std::size_t(i)] : added[std::size_t(i - m)];
  };

  // Breadth-first over the strip's faces, seeded with those on an old edge (two old vertices).
  const std::size_t n = strip.faces.size();
  std::vector<std::vector<std::size_t>> faces_of_vertex(strip.points.size());
  for (std::size_t j = 0; j < n; ++j)
    for (Eigen::Index v : strip.faces[j])
      if (v >= m)
        faces_of_vertex[std::size_t(v - m)].push_back(j);
  std::vector<char> queued(n, 0);
  std::deque<std::size_t> queue;
  for (std::size_t j = 0; j < n; ++j) {
    int old = 0;
    for (Eigen::Index v : strip.faces[j])
      old += v < m ? 1 : 0;
    if (old >= 2) {
      queue.push_back(j);
      queued[j] = 1;
    }
  }
  std::size_t number_added = 0;
  while (number_added < n) {
    if (queue.empty()) // cannot happen on a strip built from the boundary; keep going anyway
      for (std::size_t j = 0; j < n; ++j)
        if (!queued[j]) {
          queue.push_back(j);
          queued[j] = 1;
          break;
        }
    const std::size_t j = queue.front();
    queue.pop_front();
    const auto& f = strip.faces[j];
    const std::array<vertex_descriptor, 3> vs = {{descriptor(f[0]), descriptor(f[1]), descriptor(f[2])}};
    if (CGAL::Euler::add_face(vs, tm) == boost::graph_traits<TriangleMesh>::null_face())
      throw std::logic_error("CGAL::Flow_aligned_surfaces: appending a face of the grown strip failed");
    ++number_added;
    for (Eigen::Index v : f)
      if (v >= m)
        for (std::size_t k : faces_of_vertex[std::size_t(v - m)])
          if (!queued[k]) {
            queued[k] = 1;
            queue.push_back(k);
          }
  }
  return added;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Grows `tm` at its boundary by `distance`: offsets the whole boundary, or the part of it
selected by the named parameters, by `distance` in the surface's tangent plane, and tessellates
the new strip with near-regular triangles.

Every boundary edge \f$ e \f$ has an outward direction \f$ o_e \f$: in the plane of its face,
orthogonal to the edge, pointing away from the face.  An edge is grown when
- no `growth_direction` \f$ d \f$ is given, or the projection \f$ d_e \f$ of \f$ d \f$ on the plane
  of its face satisfies \f$ o_e \cdot d_e / \|d_e\| \ge \cos 60° = 1/2 \f$, and
- `across_flow` is `false`, or the direction across the flow at the edge's midpoint,
  \f$ a_e = n_e \times v / \|v\| \f$, satisfies \f$ |a_e \cdot o_e| \ge 1/2 \f$: the edge's
  outward direction is within 60° of across the flow, on either side.

The direction or the flow only selects the edges: every grown edge moves by `distance` along its
own outward direction (taken in the tangent plane at each of its vertices, normal to the area
weighted vertex normal), so that a straight side moves by exactly `distance` and the added area
is `distance` times the grown length plus what the corners add, whatever the patch's pose
against the flow.  At a vertex between two grown edges the offset curve takes
- the miter, the intersection of the two edges' offset lines, where the boundary turns by at
  most 90° outward (a rectangle grows into the larger rectangle) or at most 120° inward;
- an arc of radius `distance` about the vertex, in pieces of at most 60° (a fan of triangles),
  where it turns outward by more than 90°;

and a run of grown edges ends in a cap orthogonal to its end edge, turned toward the run where
the old boundary beyond bends into the strip's way so that 30° stay between them.
The strip between the old and the new boundary is tessellated with triangles of about the
mesh's mean edge length by `CGAL::Polygon_mesh_processing::split_long_edges()` and
`CGAL::Polygon_mesh_processing::isotropic_remeshing()` (three iterations, target length the mean
edge length of `tm`, raised to 3/4 of the longest grown edge if that is larger), with the old
boundary edges and vertices and the corners of the new boundary protected, and without projecting
the relaxed vertices back onto the strip (the strip is a first-order offset in the tangent planes
anyway; the projection was 40 % of the remeshing's time and changed neither the triangles'
angles nor the strip's smoothness measurably).  A strip thinner
than 0.6 times the mean edge length is triangulated directly instead: each grown edge's quad in
two triangles, or in three with a vertex in the middle of its outer side when the edge is longer
than 2.5 times `distance`; its smallest angle stays at or above 20° while the old boundary edges
are at most 5.5 times `distance` (they are not split).  The strip is built on a separate mesh and
appended to `tm`: nothing is removed from `tm`, its vertices and faces keep their descriptors and
its index maps stay valid.  The result is then checked: the grown surface must be manifold and
no new face may intersect another face of the surface (beyond a shared vertex or edge),
otherwise the growth is refused and `tm` is left untouched.

The offset is first order: on a curved surface the strip lies in the tangent planes of the
boundary; grow in several small steps to follow a curved surface.

\tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph` whose faces are
        triangles (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, OpenMesh meshes)
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm a valid manifold triangle mesh with a boundary
\param distance the offset, positive and finite
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadWritePropertyMap` with the vertices as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type}
  \cgalParamNEnd
  \cgalParamNBegin{growth_direction}
    \cgalParamDescription{grow only the boundary edges whose outward direction is within 60° of
      this direction (`CGAL::Flow_aligned_surfaces::parameters::growth_direction()`)}
    \cgalParamType{`GeomTraits::Vector_3`, non-zero}
    \cgalParamDefault{the whole boundary is grown}
  \cgalParamNEnd
  \cgalParamNBegin{across_flow}
    \cgalParamDescription{grow only the boundary edges whose outward direction is within 60° of
      across the flow, on either side (`CGAL::Flow_aligned_surfaces::parameters::across_flow()`): on a
      tangential surface, the sides along the streamlines, which then move outward across them;
      needs `flow_field`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{flow_field}
    \cgalParamDescription{the flow for `across_flow` (`CGAL::Flow_aligned_surfaces::parameters::flow_field()`)}
    \cgalParamType{a model of `FlowField_3`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{CGAL's progress callback (`CGAL::parameters::callback()`), called with
      `0.5` once the strip is built (offset, tessellated and checked) and with `1` once it is
      added to `tm`; if the first call returns `false`, `tm` is left untouched and the report's
      `stopped` is set (see \ref fas_progress)}
    \cgalParamType{a callable convertible to `std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was grown: new vertices and faces, the grown boundary edges and their length, the
         added area.
\throws std::invalid_argument, before `tm` is modified, if `tm` is not a valid manifold triangle
        mesh or is closed, `distance` is not positive and finite, `growth_direction` is zero,
        parallel to the normal at every boundary edge or faces no boundary edge, `across_flow`
        is given without `flow_field`, the flow is zero or undefined at every boundary edge, no
        edge faces across the flow, or growing is impossible at this distance: the boundary has
        a concave corner sharper than 60° between two grown edges or folds back at the end of a
        grown part, the offset curve folds over (a concave part whose radius of curvature is
        below `distance`), a new face would be degenerate, or the grown surface would be
        non-manifold or cut through itself (parts of the boundary closer than about twice
        `distance`).  The message says why and where (the vertex or the point).

\sa `Flow_aligned_deformation::grow()`
*/
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Growth_report grow_boundary(TriangleMesh& tm, double distance,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  const char* caller = "grow_boundary()";

  internal::check_triangle_mesh(tm, std::string(caller) + ": tm");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tm));
  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const internal::Growth_options options = internal::read_growth_options(np, caller);

  // Indices in iteration order: valid whatever the mesh's own index maps hold.
  auto vim = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> ordered;
  for (auto v : vertices(tm)) {
    put(vim, v, ordered.size());
    ordered.push_back(v);
  }
  const internal::Positions x = internal::read_positions(ordered, vpm);
  internal::check_finite_positions(x, std::string(caller) + ": tm");

  auto construct_point = gt.construct_point_3_object();
  internal::Boundary_strip strip;
  if constexpr (parameters::is_default_parameter<NamedParameters, internal_np::flow_field_t>::value) {
    if (options.across_flow)
      internal::throw_growth_error(caller, "across_flow needs the flow: pass it with the named parameter "
                                           "flow_field");
    strip = internal::make_boundary_strip(
        tm, vim, x, nullptr, distance, options,
        [](const Eigen::Vector3d&) { return internal::Flow_sample(); }, caller);
  }
  else {
    // By reference: get_parameter() would copy the field.
    const auto& field = CGAL::parameters::get_parameter_reference(np, internal_np::flow_field_t());
    strip = internal::make_boundary_strip(
        tm, vim, x, nullptr, distance, options,
        [&](const Eigen::Vector3d& p) {
          return internal::sample_flow(field, construct_point(p.x(), p.y(), p.z()));
        },
        caller);
  }
  const internal::Progress_callback callback = internal::progress_callback(np);
  if (!internal::report_progress(callback, internal::strip_built_fraction))
    return internal::stopped_growth(strip.report);
  internal::append_strip(tm, vpm, gt, ordered, strip);
  internal::report_progress(callback, 1.);
  return strip.report;
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_GROW_BOUNDARY_H
