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
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Geom_traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Point_3 = typename Geom_traits::Point_3;
  const std::string caller = "extract_iso_contours";
  const auto [vpm, gt] = internal::checked_mesh_input(tm, np, caller + ": tm");
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  // Edge numbers: the `edge_index_map` given, or a dense numbering of our own (a Polyhedron_3
  // without ids, for one, has no edge index of its own).
  const auto eim = [&] {
    if constexpr (parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_index_t>::value) {
      auto own = get(CGAL::dynamic_edge_property_t<std::size_t>(), tm);
      std::size_t i = 0;
      for (auto e : edges(tm))
        put(own, e, i++);
      return own;
    }
    else
      return parameters::get_parameter(np, CGAL::internal_np::edge_index);
  }();
  const std::vector<double> f = internal::read_scalars(tm, scalar_map, vim, caller);
  std::vector<double> levels;
  for (const auto& value : values) {
    levels.push_back(CGAL::to_double(value));
    if (!std::isfinite(levels.back()))
      throw std::invalid_argument(caller + ": iso-value " + std::to_string(levels.size() - 1) +
                                  " is not finite");
  }
  const auto construct_point = gt.construct_point_3_object();
  // vpm by an init-capture: C++17 lambdas cannot capture a structured binding.
  const auto coordinates = [vpm = vpm](auto v) {
    const auto& p = get(vpm, v);
    return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };

  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  const std::size_t number_of_edges = num_edges(tm);
  std::vector<std::size_t> next(number_of_edges), previous(number_of_edges);
  std::vector<Point_3> crossing(number_of_edges);
  std::vector<bool> visited(number_of_edges);
  std::vector<std::size_t> crossed;
  for (const double c : levels) {
    std::fill(next.begin(), next.end(), none);
    std::fill(previous.begin(), previous.end(), none);
    crossed.clear();
    const auto above = [&](auto v) { return f[get(vim, v)] >= c; };
    for (auto face_h : faces(tm)) {
      std::size_t from = none, to = none;
      for (auto h : halfedges_around_face(halfedge(face_h, tm), tm)) {
        const bool source_above = above(source(h, tm)), target_above = above(target(h, tm));
        if (source_above == target_above)
          continue;
        const std::size_t e = get(eim, edge(h, tm));
        (source_above ? from : to) = e;
        if (next[e] == none && previous[e] == none) { // first time: compute the crossing point
          crossed.push_back(e);
          const auto low = source_above ? target(h, tm) : source(h, tm);
          const auto high = source_above ? source(h, tm) : target(h, tm);
          const double f_low = f[get(vim, low)], f_high = f[get(vim, high)];
          // An infinite end puts the crossing at the other end.
          const double t = std::isinf(f_high)  ? 0
                           : std::isinf(f_low) ? 1
                                               : (std::min)(1.0, (c - f_low) / (f_high - f_low));
          const std::array<double, 3> p = coordinates(low), q = coordinates(high);
          crossing[e] =
              construct_point(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2]));
        }
      }
      if (from == none)
        continue;
      next[from] = to;
      previous[to] = from;
    }

    const auto emit = [&](std::size_t start) {
      std::vector<Point_3> polyline;
      std::size_t e = start;
      do {
        visited[e] = true;
        if (polyline.empty() || !(polyline.back() == crossing[e]))
          polyline.push_back(crossing[e]);
        e = next[e];
      } while (e != none && e != start);
      const bool closed = e == start;
      if (closed && polyline.size() > 1 && polyline.back() == polyline.front())
        polyline.pop_back();
      if (polyline.size() < 2)
        return;
      if (closed)
        polyline.push_back(polyline.front());
      *out++ = std::move(polyline);
    };
    for (std::size_t e : crossed)
      visited[e] = false;
    // Open contours start on the border, at a crossing that no face enters.
    for (std::size_t e : crossed)
      if (previous[e] == none)
        emit(e);
    for (std::size_t e : crossed)
      if (!visited[e])
        emit(e);
  }
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
