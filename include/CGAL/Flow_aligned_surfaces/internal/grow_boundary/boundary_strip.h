// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The strip that growing at the boundary (grow_boundary.h) adds, built in stages: the border
// loops, the edges selected, each vertex's offset (miter, arc or cap), the raw strip of quads and
// fans on a separate mesh, its remeshing, the numbering of its new vertices (placed on the
// reference mesh too, when there is one) and its faces, checked.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_BOUNDARY_STRIP_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_BOUNDARY_STRIP_H

#include <CGAL/Flow_aligned_surfaces/internal/Box_cell_index.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/grow_boundary/check_grown_surface.h>
#include <CGAL/Flow_aligned_surfaces/internal/grow_boundary/growth_geometry.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// "vertex i (x, y, z)", for messages.
inline std::string vertex_description(const Positions& x, Eigen::Index v)
{
  std::ostringstream os;
  os << "vertex " << v << " (" << x(v, 0) << ", " << x(v, 1) << ", " << x(v, 2) << ")";
  return os.str();
}

inline std::string whole_degrees(double angle)
{
  return std::to_string(int(std::lround(angle * 180 / CGAL_PI)));
}

// The border loops of `tm`, each as its border halfedges in order.
template <class TriangleMesh, class VertexIndexMap>
std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
border_loops(const TriangleMesh& tm, VertexIndexMap vim, Eigen::Index number_of_vertices,
             const std::string& caller)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<char> on_loop(static_cast<std::size_t>(number_of_vertices), 0);
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
  return loops;
}

// Per border edge of `loops`: selected or not.  The flow or the direction only selects the
// edges; every selected edge then moves along its own outward direction, so that the offset
// curve is the same whatever selected it.
template <class TriangleMesh, class VertexIndexMap, class Loops, class Sampler>
std::vector<std::vector<char>>
select_grown_edges(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x, const Loops& loops,
                   const Growth_options& options, const Sampler& sample, const std::string& caller)
{
  std::vector<std::vector<char>> loop_selected(loops.size());
  std::size_t number_of_edges = 0, parallel_to_normal = 0, without_flow = 0, selected = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    loop_selected[l].assign(loops[l].size(), 0);
    for (std::size_t i = 0; i < loops[l].size(); ++i) {
      const auto h = loops[l][i];
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
  return loop_selected;
}

// The mean length of the edges of `tm` at the positions `x`.
template <class TriangleMesh, class VertexIndexMap>
double mean_edge_length(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x)
{
  double total_length = 0;
  std::size_t number_of_mesh_edges = 0;
  for (auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    total_length +=
        (position<TriangleMesh>(x, vim, target(h, tm)) - position<TriangleMesh>(x, vim, source(h, tm)))
            .norm();
    ++number_of_mesh_edges;
  }
  return total_length / static_cast<double>(number_of_mesh_edges);
}

// The offsets of a border vertex (target of h_in, between the border edges h_in and h_out), in
// the tangent plane at the vertex, from the incoming edge's side to the outgoing one's; `corner`
// says whether they are constrained in the remeshing.
struct Vertex_offsets {
  std::vector<Eigen::Vector3d> offsets;
  bool corner = true;
};

template <class TriangleMesh, class VertexIndexMap, class Halfedge>
Vertex_offsets border_vertex_offsets(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                                     Halfedge h_in, Halfedge h_out, bool in, bool out, double distance,
                                     const std::string& caller)
{
  const Eigen::Index bi = static_cast<Eigen::Index>(get(vim, target(h_in, tm)));
  const Eigen::Vector3d b = x.row(bi).transpose();
  const Eigen::Vector3d n = vertex_normal(tm, vim, x, h_in);
  auto tangent = [&](Eigen::Vector3d t) -> Eigen::Vector3d {
    t -= t.dot(n) * n;
    if (!(t.norm() > parallel_sine * (t.norm() + 1)))
      throw_growth_error(caller, "a boundary edge at " + vertex_description(x, bi) +
                                     " is along the surface normal there, so it has no outward direction");
    return t.normalized();
  };
  const Eigen::Vector3d t_in = tangent(b - position<TriangleMesh>(x, vim, source(h_in, tm)));
  const Eigen::Vector3d t_out = tangent(position<TriangleMesh>(x, vim, target(h_out, tm)) - b);
  // The boundary runs with the outside on its left (o = n x t); its turn at the vertex is
  // positive where the surface is convex there: the outside angle is pi + turn.
  const Eigen::Vector3d o_in = n.cross(t_in), o_out = n.cross(t_out);
  const double turn = -std::atan2(t_in.cross(t_out).dot(n), t_in.dot(t_out));
  Vertex_offsets result;
  if (in && out) {
    if (turn > fan_turn) {
      // A sharp convex corner: the arc of radius d about the vertex, in pieces of <= 60 degrees.
      const int pieces = int(std::ceil(turn / (CGAL_PI / 3) - 1e-9));
      for (int j = 0; j <= pieces; ++j) {
        const double theta = turn * j / pieces;
        result.offsets.push_back(distance * (std::cos(theta) * o_in + std::sin(theta) * t_in));
      }
    }
    else {
      // A miter: the intersection of the two edges' offset lines.
      if (turn < -max_concave_turn)
        throw_growth_error(caller, "the boundary has a concave corner of " + whole_degrees(CGAL_PI + turn) +
                                       " degrees at " + vertex_description(x, bi) +
                                       ", too sharp to grow its two sides (at least " +
                                       whole_degrees(CGAL_PI - max_concave_turn) + " degrees are needed)");
      result.offsets.push_back(distance / std::cos(turn / 2) * (o_in + o_out).normalized());
      result.corner = std::abs(turn) >= CGAL_PI / 6;
    }
    return result;
  }
  // An end of a grown run: a cap orthogonal to the grown edge, turned toward it where the old
  // boundary beyond bends into the strip's way, so that 30 degrees stay between them.
  const double outside = CGAL_PI + turn;
  const double beta = (std::min)(CGAL_PI / 2, outside - CGAL_PI / 6);
  if (beta < CGAL_PI / 6)
    throw_growth_error(caller, "the boundary folds back at the end of the grown part at " +
                                   vertex_description(x, bi) + " (an outside angle of " +
                                   whole_degrees(outside) +
                                   " degrees, at least 60 are needed for the strip's end)");
  const Eigen::Vector3d along = out ? t_out : Eigen::Vector3d(-t_in);
  const Eigen::Vector3d away = out ? o_out : o_in;
  result.offsets.push_back(distance / std::sin(beta) * (std::cos(beta) * along + std::sin(beta) * away));
  return result;
}

// The raw strip, on a separate mesh: per old vertex on a grown edge its copy (`inner`) and the
// first and last points of its offset (`outer_in`, `outer_out`: for the incoming and the
// outgoing grown edge; the same point at a miter), and, when growing with a reference mesh, the
// reference position of each strip vertex.
struct Raw_strip {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  using vertex = Mesh::Vertex_index;

  Raw_strip(Eigen::Index number_of_old_vertices, const std::string& caller)
      : inner(std::size_t(number_of_old_vertices)), outer_in(std::size_t(number_of_old_vertices)),
        outer_out(std::size_t(number_of_old_vertices)),
        base(mesh.add_property_map<vertex, Eigen::Index>("v:fas_base", -1).first),
        vertex_constrained(mesh.add_property_map<vertex, bool>("v:fas_constrained", false).first),
        edge_constrained(mesh.add_property_map<Mesh::Edge_index, bool>("e:fas_constrained", false).first),
        caller(caller)
  {
  }

  Eigen::Vector3d point(vertex v) const
  {
    const auto& s = mesh.point(v);
    return Eigen::Vector3d(s.x(), s.y(), s.z());
  }
  vertex add_vertex(const Eigen::Vector3d& p) { return mesh.add_vertex(Epick::Point_3(p.x(), p.y(), p.z())); }
  void set_reference(vertex v, const Eigen::Vector3d& p)
  {
    reference.resize(mesh.number_of_vertices());
    reference[v] = p;
  }
  void add_face(vertex a, vertex b, vertex c)
  {
    if (mesh.add_face(a, b, c) == Mesh::null_face())
      throw std::logic_error(caller + ": building the raw strip failed");
  }

  Mesh mesh; // declared first: the property maps below are made on it
  std::vector<vertex> inner, outer_in, outer_out;
  std::vector<Eigen::Vector3d> reference;
  Mesh::Property_map<vertex, Eigen::Index> base; // the old vertex a strip vertex copies, or -1
  Mesh::Property_map<vertex, bool> vertex_constrained;
  Mesh::Property_map<Mesh::Edge_index, bool> edge_constrained;
  std::string caller;
};

// Adds to `strip` the copy of the border vertex target(h_in) and its offset points, returned in
// order; `reference` (or null) as in make_boundary_strip().
template <class TriangleMesh, class VertexIndexMap, class Halfedge>
std::vector<Raw_strip::vertex>
add_vertex_offsets(Raw_strip& strip, const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                   const Positions* reference, Halfedge h_in, const Vertex_offsets& offsets)
{
  const Eigen::Index bi = static_cast<Eigen::Index>(get(vim, target(h_in, tm)));
  const Eigen::Vector3d b = x.row(bi).transpose();
  strip.inner[bi] = strip.add_vertex(b);
  put(strip.base, strip.inner[bi], bi);
  put(strip.vertex_constrained, strip.inner[bi], true);
  Eigen::Matrix3d frame, reference_frame;
  if (reference) {
    frame = boundary_vertex_frame(tm, vim, x, h_in);
    reference_frame = boundary_vertex_frame(tm, vim, *reference, h_in);
    strip.set_reference(strip.inner[bi], reference->row(bi).transpose());
  }
  std::vector<Raw_strip::vertex> fan;
  for (const Eigen::Vector3d& offset : offsets.offsets) {
    const Raw_strip::vertex v = strip.add_vertex(b + offset);
    fan.push_back(v);
    put(strip.vertex_constrained, v, offsets.corner);
    if (reference)
      strip.set_reference(v,
                          strip.reference[strip.inner[bi]] + reference_frame * (frame.transpose() * offset));
  }
  strip.outer_in[bi] = fan.front();
  strip.outer_out[bi] = fan.back();
  return fan;
}

// Adds the quad p q q' p' of the grown border edge (p, q) (its vertices' offsets are in `strip`),
// counterclockwise like the old faces, split along the shorter diagonal, or, when the strip is
// `thin` and the edge long, into three triangles about a vertex in the middle of its outer side.
// Returns the edge's length.
inline double add_grown_edge(Raw_strip& strip, const Positions& x, bool with_reference, Eigen::Index p,
                             Eigen::Index q, double distance, bool thin)
{
  using vertex = Raw_strip::vertex;
  const vertex pp = strip.outer_out[p], qq = strip.outer_in[q], ip = strip.inner[p], iq = strip.inner[q];
  const Eigen::Vector3d pq = strip.point(iq) - strip.point(ip);
  // An offset edge reversed with respect to its edge: the offset curve folds over.
  bool folds = !((strip.point(qq) - strip.point(pp)).dot(pq) > 0);
  if (with_reference && !folds)
    folds = !((strip.reference[qq] - strip.reference[pp]).dot(strip.reference[iq] - strip.reference[ip]) > 0);
  if (folds) {
    std::ostringstream os;
    os << "the distance " << distance << " is too large for the boundary near " << vertex_description(x, p)
       << ": the offset curve folds over there (grow by a smaller distance, in several steps)";
    throw_growth_error(strip.caller, os.str());
  }
  if (thin && pq.norm() > mid_vertex_ratio * distance) {
    // A thin quad: a vertex in the middle of its outer side makes three triangles whose
    // angles stay above 20 degrees while the edge is at most 5.5 times the distance.
    const vertex mid = strip.add_vertex(0.5 * (strip.point(pp) + strip.point(qq)));
    if (with_reference)
      strip.set_reference(mid, 0.5 * (strip.reference[pp] + strip.reference[qq]));
    strip.add_face(ip, iq, mid);
    strip.add_face(iq, qq, mid);
    strip.add_face(ip, mid, pp);
  }
  else if ((strip.point(ip) - strip.point(qq)).squaredNorm() <=
           (strip.point(iq) - strip.point(pp)).squaredNorm()) {
    strip.add_face(ip, iq, qq);
    strip.add_face(ip, qq, pp);
  }
  else {
    strip.add_face(ip, iq, pp);
    strip.add_face(iq, qq, pp);
  }
  put(strip.edge_constrained, strip.mesh.edge(strip.mesh.halfedge(ip, iq)), true);
  return pq.norm();
}

// Adds to `strip` the offsets, quads and fans of one border loop whose edges `grown` selects;
// appends the grown edges to `grown_edges` and returns the length of the longest.
template <class TriangleMesh, class VertexIndexMap, class Loop>
double add_grown_loop(Raw_strip& strip, const TriangleMesh& tm, VertexIndexMap vim, const Positions& x,
                      const Positions* reference, const Loop& loop, const std::vector<char>& grown,
                      double distance, bool thin,
                      std::vector<std::pair<std::size_t, std::size_t>>& grown_edges, double& grown_length)
{
  const std::size_t k = loop.size();
  // Vertex i is target(loop[i]), between the border edges i (incoming) and i + 1 (outgoing).
  std::vector<std::vector<Raw_strip::vertex>> fans(k);
  for (std::size_t i = 0; i < k; ++i) {
    const bool in = grown[i] != 0, out = grown[(i + 1) % k] != 0;
    if (!in && !out)
      continue;
    const auto offsets =
        border_vertex_offsets(tm, vim, x, loop[i], loop[(i + 1) % k], in, out, distance, strip.caller);
    fans[i] = add_vertex_offsets(strip, tm, vim, x, reference, loop[i], offsets);
  }
  double longest_inner_edge = 0;
  for (std::size_t i = 0; i < k; ++i) {
    if (!grown[i])
      continue;
    const Eigen::Index p = static_cast<Eigen::Index>(get(vim, source(loop[i], tm)));
    const Eigen::Index q = static_cast<Eigen::Index>(get(vim, target(loop[i], tm)));
    grown_edges.emplace_back(std::size_t(p), std::size_t(q));
    const double length = add_grown_edge(strip, x, reference != nullptr, p, q, distance, thin);
    grown_length += length;
    longest_inner_edge = (std::max)(longest_inner_edge, length);
  }
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j + 1 < fans[i].size(); ++j) {
      const Eigen::Index bi = static_cast<Eigen::Index>(get(vim, target(loop[i], tm)));
      strip.add_face(strip.inner[bi], fans[i][j + 1], fans[i][j]);
    }
  return longest_inner_edge;
}

// Tessellates a strip that is not thin to `target_length` by CGAL's isotropic remeshing, the old
// boundary's edges and the corners' offsets protected.
inline void remesh_strip(Raw_strip& strip, double target_length)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Mesh = Raw_strip::Mesh;
  std::vector<Mesh::Edge_index> free_edges;
  for (auto e : strip.mesh.edges())
    if (!get(strip.edge_constrained, e))
      free_edges.push_back(e);
  PMP::split_long_edges(free_edges, 4. / 3. * target_length, strip.mesh,
                        CGAL::parameters::edge_is_constrained_map(strip.edge_constrained));
  const std::vector<Mesh::Face_index> strip_faces(strip.mesh.faces().begin(), strip.mesh.faces().end());
  PMP::isotropic_remeshing(strip_faces, target_length, strip.mesh,
                           CGAL::parameters::number_of_iterations(3)
                               .edge_is_constrained_map(strip.edge_constrained)
                               .vertex_is_constrained_map(strip.vertex_constrained)
                               .protect_constraints(true)
                               .do_project(false));
}

// Places points of the remeshed strip on the reference strip: the closest point of the raw strip
// (before remeshing), then the same triangle and barycentric coordinates on the raw strip's
// reference positions.  The relaxation moves a new vertex off the raw strip by a fraction of the
// target length at most, most often: the closest point is searched among the raw faces whose
// boxes, dilated by a quarter of the target length, hold it, else by CGAL's AABB tree.
class Raw_strip_reference {
  using Epick = Raw_strip::Epick;
  using Mesh = Raw_strip::Mesh;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

public:
  Raw_strip_reference(const Mesh& raw, const std::vector<Eigen::Vector3d>& reference, double target_length)
      : m_raw(raw), m_reference_mesh(raw), m_reach(0.25 * target_length)
  {
    for (auto v : m_reference_mesh.vertices())
      m_reference_mesh.point(v) = Epick::Point_3(reference[v].x(), reference[v].y(), reference[v].z());
    for (auto f : m_raw.faces()) {
      CGAL::Bbox_3 b;
      for (auto v : vertices_around_face(m_raw.halfedge(f), m_raw))
        b += m_raw.point(v).bbox();
      m_faces.push_back(f);
      m_boxes.emplace_back(b.xmin() - m_reach, b.ymin() - m_reach, b.zmin() - m_reach, b.xmax() + m_reach,
                         b.ymax() + m_reach, b.zmax() + m_reach);
    }
    m_cells.emplace(m_boxes);
  }

  Eigen::Vector3d operator()(const Epick::Point_3& p)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    const auto [q, face] = closest_raw_point(p);
    const auto p0 = PMP::construct_point(PMP::locate_in_face(q, face, m_raw), m_reference_mesh);
    return Eigen::Vector3d(p0.x(), p0.y(), p0.z());
  }

private:
  std::pair<Epick::Point_3, Mesh::Face_index> closest_raw_point(const Epick::Point_3& p)
  {
    std::pair<Epick::Point_3, Mesh::Face_index> best(p, Mesh::null_face());
    double best_distance = m_reach * m_reach;
    m_cells->find_meeting(p.bbox(), [&](std::size_t j) {
      const auto h = m_raw.halfedge(m_faces[j]);
      const Epick::Triangle_3 t(m_raw.point(m_raw.source(h)), m_raw.point(m_raw.target(h)),
                                m_raw.point(m_raw.target(m_raw.next(h))));
      const Epick::Point_3 q = Epick::Construct_projected_point_3()(t, p);
      const double d = CGAL::squared_distance(p, q);
      if (d <= best_distance) {
        best_distance = d;
        best = {q, m_faces[j]};
      }
      return false;
    });
    if (best.second == Mesh::null_face()) {
      if (m_tree.empty())
        CGAL::Polygon_mesh_processing::build_AABB_tree(m_raw, m_tree);
      const auto found = m_tree.closest_point_and_primitive(p);
      best = {found.first, found.second};
    }
    return best;
  }

  const Mesh& m_raw;
  Mesh m_reference_mesh;
  double m_reach;
  std::vector<Mesh::Face_index> m_faces;
  std::vector<CGAL::Bbox_3> m_boxes; // m_cells keeps them by reference
  std::optional<Box_cell_index> m_cells;
  Tree m_tree;
};

// Numbers the strip's vertices (an old vertex keeps its index, new vertex i gets m + i), puts the
// new ones in `result.points` (and, with `place_on_reference`, their reference positions in
// `result.reference_points`), then its faces in `result.faces`, refusing a degenerate one, and
// their area in `result.report.added_area`.
template <class PlaceOnReference>
void number_strip(Raw_strip& strip, const Positions& x, const Positions* reference,
                  PlaceOnReference* place_on_reference, Boundary_strip& result)
{
  using vertex = Raw_strip::vertex;
  const Eigen::Index m = x.rows();
  auto index = strip.mesh.add_property_map<vertex, Eigen::Index>("v:fas_index", -1).first;
  for (auto v : strip.mesh.vertices()) {
    if (get(strip.base, v) >= 0) {
      put(index, v, get(strip.base, v));
      continue;
    }
    put(index, v, m + static_cast<Eigen::Index>(result.points.size()));
    const auto& p = strip.mesh.point(v);
    result.points.emplace_back(p.x(), p.y(), p.z());
    if (place_on_reference)
      result.reference_points.push_back((*place_on_reference)(p));
  }
  auto face_area = [&](const std::array<Eigen::Index, 3>& f, const Positions& old,
                       const std::vector<Eigen::Vector3d>& added, const char* which) {
    auto at = [&](Eigen::Index i) -> Eigen::Vector3d {
      return i < m ? Eigen::Vector3d(old.row(i).transpose()) : added[std::size_t(i - m)];
    };
    const auto t = triangle_gradients(at(f[0]), at(f[1]), at(f[2]));
    if (!t)
      throw_growth_error(strip.caller,
                         std::string("growing would create a degenerate face") + which +
                             " (the boundary curves too much for this distance; grow in smaller steps)");
    return t->area;
  };
  for (auto f : strip.mesh.faces()) {
    std::array<Eigen::Index, 3> fv;
    int i = 0;
    for (auto v : vertices_around_face(strip.mesh.halfedge(f), strip.mesh))
      fv[i++] = get(index, v);
    result.report.added_area += face_area(fv, x, result.points, "");
    if (reference)
      face_area(fv, *reference, result.reference_points, " in the reference mesh M_0");
    result.faces.push_back(fv);
  }
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
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  if (!(distance > 0) || !std::isfinite(distance)) {
    std::ostringstream os;
    os << "the distance must be positive and finite (got " << distance << ")";
    throw_growth_error(caller, os.str());
  }
  const auto loops = border_loops(tm, vim, x.rows(), caller);
  const std::vector<std::vector<char>> selected =
      select_grown_edges(tm, vim, x, loops, options, sample, caller);

  // A strip thinner than the edges is built directly, and not remeshed: the remesher could only
  // keep the old boundary's edges, too long for the strip's height, by making thin triangles.
  const double mean_length = mean_edge_length(tm, vim, x);
  const bool thin = distance < thin_strip * mean_length;
  Raw_strip strip(x.rows(), caller);
  Boundary_strip result;
  double grown_length = 0, longest_inner_edge = 0;
  for (std::size_t l = 0; l < loops.size(); ++l)
    longest_inner_edge = (std::max)(longest_inner_edge,
                                    add_grown_loop(strip, tm, vim, x, reference, loops[l], selected[l],
                                                   distance, thin, result.report.grown_edges, grown_length));
  result.report.number_of_grown_edges = result.report.grown_edges.size();

  // Target length: the mesh's mean edge length, raised if needed so that the protected old
  // edges are no longer than 4/3 of it (the remesher's precondition for protected edges).
  const double target_length = (std::max)(mean_length, 0.76 * longest_inner_edge);
  const Raw_strip::Mesh raw = strip.mesh;
  const auto offset_done = Clock::now();
  if (!thin)
    remesh_strip(strip, target_length);
  const auto remeshed = Clock::now();

  std::optional<Raw_strip_reference> place_on_reference;
  if (reference)
    place_on_reference.emplace(raw, strip.reference, target_length);
  number_strip(strip, x, reference, place_on_reference ? &*place_on_reference : nullptr, result);
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

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_GROW_BOUNDARY_BOUNDARY_STRIP_H
