// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow that an integrated path surface saw: at a point of the surface, an unsteady flow at
// the time at which the surface passed there, interpolated linearly from the times of the
// vertices of the face that holds the point.  A model of FlowField_3, so that the tangential
// parametrization and the flow texture of a path surface follow its path lines.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_PATH_SURFACE_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_PATH_SURFACE_FLOW_FIELD_3_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The flow on a path surface, a model of `FlowField_3`: at a point `p` of the triangle mesh
/// `tm` (a path surface, or any surface whose vertices carry times), the unsteady field at `p`
/// and at the time interpolated at `p` from the times of the vertices of its face
/// (barycentric), `field(p, t(p))`.  A point off the surface is projected onto its closest
/// point first for the time.
///
/// A path surface is tangent to the path lines, that is to \f$ v(x, t) \f$ at the time
/// \f$ t \f$ at which its particles passed \f$ x \f$, not to the flow of any one time.  Given
/// this field, `parametrize_tangential()` makes \f$ \nabla r \f$ follow the path lines, and
/// `compute_flow_texture_mask()` measures against them, so that the LIC-like texture of
/// \ref fas_textures follows the path lines (the paper's Figure 8, the path surfaces of the
/// unsteady cylinder).  With `integrate_stream_surface()`'s `integration_time_map` \f$ \tau \f$
/// the vertex time is \f$ t_0 + \tau \f$.
///
/// The surface is located with an AABB tree built at construction (`CGAL::AABB_tree`, through
/// `Polygon_mesh_processing::locate_with_AABB_tree()`), shared by the copies; the mesh is held by
/// reference and must outlive the field and stay unchanged (the time map, a light handle, is
/// copied).
/// Queries are `const` and may run concurrently.
///
/// \tparam UnsteadyFlowField a model of `UnsteadyFlowField_3`
/// \tparam TriangleMesh a model of `FaceListGraph` with the internal vertex point map
/// \tparam VertexTimeMap a model of `ReadablePropertyMap` with the vertices as key type and a
///         floating-point value type (the time of each vertex)
///
/// \cgalModels `FlowField_3`
///
/// \sa `integrate_stream_surface()`, `Unsteady_flow_field_3`, `Time_slice_flow_field_3`
template <typename UnsteadyFlowField, typename TriangleMesh, typename VertexTimeMap>
class Path_surface_flow_field_3 {
  using Vertex_point_map = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type;
  using Point_3 = typename boost::property_traits<Vertex_point_map>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, Vertex_point_map>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

public:
  /// \name Creation
  /// @{

  /// the flow `field` on the surface `tm` whose vertex `v` was passed at time `get(times, v)`.
  /// \throws std::invalid_argument if `tm` has no face or is not a triangle mesh
  Path_surface_flow_field_3(const UnsteadyFlowField& field, const TriangleMesh& tm, VertexTimeMap times)
      : m_field(field), m_tm(&tm), m_times(times), m_tree(std::make_shared<Tree>())
  {
    if (faces(tm).empty())
      throw std::invalid_argument("Path_surface_flow_field_3: the surface has no face");
    if (!CGAL::is_triangle_mesh(tm))
      throw std::invalid_argument("Path_surface_flow_field_3: the surface is not a triangle mesh");
    Polygon_mesh_processing::build_AABB_tree(tm, *m_tree);
    m_tree->accelerate_distance_queries(); // built now: concurrent queries only read it
  }
  /// @}

  /// \name Evaluation
  /// @{

  /// the time interpolated at the point of the surface closest to `p`
  double time(const Point_3& p) const
  {
    const auto location = Polygon_mesh_processing::locate_with_AABB_tree(p, *m_tree, *m_tm);
    const auto h = halfedge(location.first, *m_tm);
    const auto& w = location.second;
    return CGAL::to_double(w[0]) * CGAL::to_double(get(m_times, source(h, *m_tm))) +
           CGAL::to_double(w[1]) * CGAL::to_double(get(m_times, target(h, *m_tm))) +
           CGAL::to_double(w[2]) * CGAL::to_double(get(m_times, target(next(h, *m_tm), *m_tm)));
  }

  /// returns `field(p, time(p))`
  auto operator()(const Point_3& p) const -> decltype(std::declval<const UnsteadyFlowField&>()(p, 0.))
  {
    return m_field(p, time(p));
  }

  /// returns `field(p, time(p))` for each of `points`, in one batch of `field` (its
  /// `sample(points, times)`, see `UnsteadyFlowField_3`); only where `UnsteadyFlowField` answers
  /// batches
  template <class Field = UnsteadyFlowField>
  auto sample(const std::vector<Point_3>& points) const
      -> decltype(std::declval<const Field&>().sample(points, std::vector<double>()))
  {
    std::vector<double> times;
    times.reserve(points.size());
    for (const Point_3& p : points)
      times.push_back(time(p));
    return m_field.sample(points, times);
  }
  /// @}

private:
  UnsteadyFlowField m_field;
  const TriangleMesh* m_tm;
  VertexTimeMap m_times;
  std::shared_ptr<Tree> m_tree;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_PATH_SURFACE_FLOW_FIELD_3_H
