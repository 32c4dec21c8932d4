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

#include <CGAL/Flow_aligned_surfaces/Growth_report.h>
#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/grow_boundary/boundary_strip.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/batched_sampling.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/progress_callback.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
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
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \cond SKIP_IN_MANUAL
namespace internal {

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

// The samples of `field` at the midpoints of the border edges of `tm` (as the growth across the
// flow computes them), in one batch, into `samples` (at time 0).
template <class TriangleMesh, class VertexIndexMap, class FlowField, class GeomTraits>
void sample_border_midpoints(const TriangleMesh& tm, VertexIndexMap vim, const Positions& x, const FlowField& field,
                             const GeomTraits& gt, Replay_samples<Flow_sample>& samples)
{
  auto construct_point = gt.construct_point_3_object();
  std::vector<Eigen::Vector3d> midpoints;
  std::vector<typename GeomTraits::Point_3> points;
  for (auto h : halfedges(tm))
    if (is_border(h, tm)) {
      const Eigen::Vector3d m =
          0.5 * (position<TriangleMesh>(x, vim, source(h, tm)) + position<TriangleMesh>(x, vim, target(h, tm)));
      midpoints.push_back(m);
      points.push_back(construct_point(m.x(), m.y(), m.z()));
    }
  const std::vector<Flow_sample> sampled = sample_flow_at(field, points);
  for (std::size_t k = 0; k < midpoints.size(); ++k)
    samples.add(midpoints[k], 0., sampled[k]);
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
    using Field = std::decay_t<decltype(field)>;
    constexpr bool batched = internal::has_batch_sampling_v<Field, typename Geom_traits::Point_3>;
    // A field that answers batches gets the midpoints of the border edges, where growth across the
    // flow samples it, in one batch.
    internal::Replay_samples<internal::Flow_sample> midpoints;
    if constexpr (batched)
      if (options.across_flow)
        sample_border_midpoints(tm, vim, x, field, gt, midpoints);
    strip = internal::make_boundary_strip(
        tm, vim, x, nullptr, distance, options,
        [&](const Eigen::Vector3d& p) {
          if constexpr (batched)
            if (const internal::Flow_sample* known = midpoints.known(p, 0.))
              return *known;
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
