// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Iso-contours of a piecewise linear vertex scalar field f on a triangle mesh: for each value c,
// the polylines {x : f(x) = c}.  A vertex is "above" when f >= c (symbolic perturbation: f == c
// counts as f > c), so every face has zero or two edges whose ends differ, and the contour
// crosses such an edge at x = p_u + (c - f_u) / (f_w - f_u) (p_w - p_u), f_u < c <= f_w.  In
// each face the segment runs from the crossing of its above-to-below edge to the crossing of its
// below-to-above edge (in the face's counterclockwise order), which puts higher values on the
// left seen from the normal; segments of neighbouring faces share their crossing point, so they
// chain into polylines that close or end on the border.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_EXTRACT_ISO_CONTOURS_H
#define CGAL_FLOW_ALIGNED_SURFACES_EXTRACT_ISO_CONTOURS_H

#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// The values of `scalar_map` in vertex index order; throws std::invalid_argument naming
/// `caller` and the first vertex whose value is NaN.
template <class TriangleMesh, class ScalarMap, class VertexIndexMap>
std::vector<double> read_scalars(const TriangleMesh& tm, ScalarMap scalar_map, VertexIndexMap vim,
                                 const std::string& caller)
{
  std::vector<double> f(num_vertices(tm));
  for (auto v : vertices(tm))
    f[get(vim, v)] = CGAL::to_double(get(scalar_map, v));
  for (std::size_t i = 0; i < f.size(); ++i)
    if (std::isnan(f[i]))
      throw std::invalid_argument(caller + ": scalar_map: the value of vertex " + std::to_string(i) +
                                  " is not a number");
  return f;
}

// Edge numbers: the `edge_index_map` given, or a dense numbering of our own (a Polyhedron_3
// without ids, for one, has no edge index of its own).
template <class TriangleMesh, class NamedParameters>
auto edge_index_map_or_numbering(const TriangleMesh& tm, const NamedParameters& np)
{
  if constexpr (parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_index_t>::value) {
    auto own = get(CGAL::dynamic_edge_property_t<std::size_t>(), tm);
    std::size_t i = 0;
    for (auto e : edges(tm))
      put(own, e, i++);
    return own;
  }
  else
    return parameters::get_parameter(np, CGAL::internal_np::edge_index);
}

/// The iso-values as doubles; throws std::invalid_argument naming `caller` and the first one
/// that is not finite.
template <class ValueRange>
std::vector<double> read_iso_values(const ValueRange& values, const std::string& caller)
{
  std::vector<double> levels;
  for (const auto& value : values) {
    levels.push_back(CGAL::to_double(value));
    if (!std::isfinite(levels.back()))
      throw std::invalid_argument(caller + ": iso-value " + std::to_string(levels.size() - 1) +
                                  " is not finite");
  }
  return levels;
}

// The iso-contours of the vertex values `f` on `tm`, one iso-value at a time: the crossing point
// of every edge whose ends lie on either side of the value, each crossed edge linked to the next
// and the previous one along the contour (the two crossed edges of a face), and the polylines
// those links chain into.
template <class TriangleMesh, class VertexPointMap, class GeomTraits, class VertexIndexMap,
          class EdgeIndexMap>
class Iso_contour_tracer {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Point_3 = typename GeomTraits::Point_3;
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

public:
  Iso_contour_tracer(const TriangleMesh& tm, const std::vector<double>& f, VertexPointMap vpm,
                     const GeomTraits& gt, VertexIndexMap vim, EdgeIndexMap eim)
      : m_tm(tm), m_f(f), m_vpm(vpm), m_construct_point(gt.construct_point_3_object()), m_vim(vim),
        m_eim(eim), m_next(num_edges(tm)), m_previous(num_edges(tm)), m_crossing(num_edges(tm)),
        m_visited(num_edges(tm))
  {
  }

  // Writes the polylines of the iso-value c to `out`.
  template <class OutputIterator>
  OutputIterator trace(double c, OutputIterator out)
  {
    link_crossings(c);
    for (std::size_t e : m_crossed)
      m_visited[e] = false;
    // Open contours start on the border, at a crossing that no face enters.
    for (std::size_t e : m_crossed)
      if (m_previous[e] == none)
        write_polyline(e, out);
    for (std::size_t e : m_crossed)
      if (!m_visited[e])
        write_polyline(e, out);
    return out;
  }

private:
  // In each face, the link from the crossing of its above-to-below edge to the crossing of its
  // below-to-above edge.
  void link_crossings(double c)
  {
    std::fill(m_next.begin(), m_next.end(), none);
    std::fill(m_previous.begin(), m_previous.end(), none);
    m_crossed.clear();
    for (auto face_h : faces(m_tm)) {
      std::size_t from = none, to = none;
      for (auto h : halfedges_around_face(halfedge(face_h, m_tm), m_tm)) {
        const bool source_above = above(source(h, m_tm), c), target_above = above(target(h, m_tm), c);
        if (source_above == target_above)
          continue;
        const std::size_t e = get(m_eim, edge(h, m_tm));
        (source_above ? from : to) = e;
        if (m_next[e] == none && m_previous[e] == none) { // first time: compute the crossing point
          m_crossed.push_back(e);
          m_crossing[e] = crossing_point(h, source_above, c);
        }
      }
      if (from == none)
        continue;
      m_next[from] = to;
      m_previous[to] = from;
    }
  }

  bool above(vertex_descriptor v, double c) const { return m_f[get(m_vim, v)] >= c; }

  // Where the contour at c crosses the edge of h, whose source is above c or else its target.
  Point_3 crossing_point(halfedge_descriptor h, bool source_above, double c) const
  {
    const vertex_descriptor low = source_above ? target(h, m_tm) : source(h, m_tm);
    const vertex_descriptor high = source_above ? source(h, m_tm) : target(h, m_tm);
    const double f_low = m_f[get(m_vim, low)], f_high = m_f[get(m_vim, high)];
    // An infinite end puts the crossing at the other end.
    const double t = std::isinf(f_high)  ? 0
                     : std::isinf(f_low) ? 1
                                         : (std::min)(1.0, (c - f_low) / (f_high - f_low));
    const std::array<double, 3> p = coordinates(low), q = coordinates(high);
    return m_construct_point(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2]));
  }

  std::array<double, 3> coordinates(vertex_descriptor v) const
  {
    const auto& p = get(m_vpm, v);
    return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }

  // The polyline that follows the links from the crossing of edge `start`, without repeated points,
  // closed by its first point again if it comes back to `start`; none if it shrinks to one point.
  template <class OutputIterator>
  void write_polyline(std::size_t start, OutputIterator& out)
  {
    std::vector<Point_3> polyline;
    std::size_t e = start;
    do {
      m_visited[e] = true;
      if (polyline.empty() || !(polyline.back() == m_crossing[e]))
        polyline.push_back(m_crossing[e]);
      e = m_next[e];
    } while (e != none && e != start);
    const bool closed = e == start;
    if (closed && polyline.size() > 1 && polyline.back() == polyline.front())
      polyline.pop_back();
    if (polyline.size() < 2)
      return;
    if (closed)
      polyline.push_back(polyline.front());
    *out++ = std::move(polyline);
  }

  const TriangleMesh& m_tm;
  const std::vector<double>& m_f;
  VertexPointMap m_vpm;
  decltype(std::declval<const GeomTraits&>().construct_point_3_object()) m_construct_point;
  VertexIndexMap m_vim;
  EdgeIndexMap m_eim;
  std::vector<std::size_t> m_next, m_previous; // along the contour, per edge
  std::vector<Point_3> m_crossing;             // per edge
  std::vector<bool> m_visited;                 // per edge
  std::vector<std::size_t> m_crossed;          // the edges crossed, in the order they are found
};

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes the iso-contours of the piecewise linear vertex field `scalar_map` at each of
`values` to `out`, as polylines (`std::vector<Point_3>`) whose points lie on the edges of `tm`.

The polylines of the first value come first, then those of the next value, and so on.  Each
polyline is oriented with higher values on its left, seen from the side the faces' normals point
to (so it runs counterclockwise around a maximum).  A closed contour repeats its first point at
its end; a contour that reaches the border of `tm` is an open polyline from border to border,
and it is split where it leaves the surface.  A value outside the field's range gives no
polyline.  A vertex whose value equals the iso-value counts as above it (symbolic
perturbation), so contours through vertices are well defined; the point is then the vertex
itself, repeated points are merged, and a contour that shrinks to one point is dropped.
Values \f$ \pm\infty \f$ in `scalar_map` (for instance the distance to an unreachable
component) are allowed.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam ScalarMap a model of `ReadablePropertyMap` with the vertices as key type and a number
type convertible to `double` as value type
\tparam ValueRange a range of numbers convertible to `double`
\tparam OutputIterator an output iterator accepting `std::vector<Point_3>`
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param scalar_map the field
\param values the iso-values
\param out receives the polylines
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map, geom_traits}
    \cgalParamDescription{as in `normalized_flux()`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map, edge_index_map}
    \cgalParamDescription{property maps associating indices in `[0, num_vertices(tm))`, `[0, num_edges(tm))`}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the output iterator past the last polyline.
\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh, if a
value of `scalar_map` is NaN or an iso-value is not finite; nothing is written then.
\sa `evenly_spaced_iso_values()`, `parametrize_tangential()`, `parametrize_orthogonal()`,
`compute_geodesic_distance()`
*/
template <class TriangleMesh, class ScalarMap, class ValueRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator extract_iso_contours(const TriangleMesh& tm, ScalarMap scalar_map, const ValueRange& values,
                                    OutputIterator out,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "extract_iso_contours";
  const auto [vpm, gt] = internal::checked_mesh_input(tm, np, caller + ": tm");
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto eim = internal::edge_index_map_or_numbering(tm, np);
  const std::vector<double> f = internal::read_scalars(tm, scalar_map, vim, caller);
  const std::vector<double> levels = internal::read_iso_values(values, caller);
  internal::Iso_contour_tracer tracer(tm, f, vpm, gt, vim, eim);
  for (const double c : levels)
    out = tracer.trace(c, out);
  return out;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Returns `n` iso-values evenly spaced strictly inside the range of the finite values of
`scalar_map`: \f$ f_{\min} + k (f_{\max} - f_{\min}) / (n + 1) \f$, \f$ k = 1, \dots, n \f$
(the extremes themselves give degenerate contours).  Empty when `n` is 0 or the field is
constant or has no finite value.

\tparam TriangleMesh a model of `VertexListGraph`
\tparam ScalarMap a model of `ReadablePropertyMap` with the vertices as key type and a number
type convertible to `double` as value type

\sa `extract_iso_contours()`
*/
template <class TriangleMesh, class ScalarMap>
std::vector<double> evenly_spaced_iso_values(const TriangleMesh& tm, ScalarMap scalar_map, std::size_t n)
{
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (auto v : vertices(tm)) {
    const double value = CGAL::to_double(get(scalar_map, v));
    if (std::isfinite(value)) {
      low = (std::min)(low, value);
      high = (std::max)(high, value);
    }
  }
  std::vector<double> values;
  if (!(high > low))
    return values;
  for (std::size_t k = 1; k <= n; ++k)
    values.push_back(low + (high - low) * (double(k) / double(n + 1)));
  return values;
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_EXTRACT_ISO_CONTOURS_H
