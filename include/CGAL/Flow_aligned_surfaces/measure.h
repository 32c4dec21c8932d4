// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well a surface is aligned with a flow.
//
//   normalized_flux = sum_j A_j |n_j . v_j| / |v_j|  /  sum_j A_j
//
// over the faces j whose centroid sample v_j exists, is finite and non-zero: the
// paper's f_n (Section 7) with the per-face flux in absolute value, so it does
// not depend on the orientation.  1 = exactly orthogonal, 0 = exactly tangential.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H
#define CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Calls `visit(j, area, flux)` for every non-degenerate face j of `positions`, with
/// flux = |n_j . v_j| / |v_j| when the centroid sample is usable and -1 otherwise.
template <class FlowField, class GeomTraits, class Visit>
void visit_face_fluxes(const Positions& positions,
                       const std::vector<std::array<Eigen::Index, 3>>& face_vertices, const FlowField& field,
                       const GeomTraits& gt, const Visit& visit)
{
  auto construct_point = gt.construct_point_3_object();
  for (std::size_t j = 0; j < face_vertices.size(); ++j) {
    const auto& face = face_vertices[j];
    const Eigen::Vector3d a = positions.row(face[0]), b = positions.row(face[1]), c = positions.row(face[2]);
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double twice_area = cross.norm();
    if (!(twice_area > 0))
      continue;
    const Eigen::Vector3d centroid = (a + b + c) / 3;
    const Flow_sample s = sample_flow(field, construct_point(centroid.x(), centroid.y(), centroid.z()));
    visit(j, 0.5 * twice_area,
          s.kind == Sample_kind::VALID ? std::abs(cross.dot(s.direction)) / twice_area : -1.0);
  }
}

/// The normalized flux of the faces `face_vertices` over `positions`.
template <class FlowField, class GeomTraits>
double normalized_flux(const Positions& positions,
                       const std::vector<std::array<Eigen::Index, 3>>& face_vertices, const FlowField& field,
                       const GeomTraits& gt)
{
  double flux = 0, area = 0;
  visit_face_fluxes(positions, face_vertices, field, gt,
                    [&](std::size_t, double face_area, double face_flux) {
                      if (face_flux < 0)
                        return;
                      flux += face_area * face_flux;
                      area += face_area;
                    });
  return area > 0 ? flux / area : 0;
}

/// Calls `visit(f, area, flux)` for every non-degenerate face `f` of `tm`, as `visit_face_fluxes()`.
template <class TriangleMesh, class FlowField, class NamedParameters, class Visit>
void visit_mesh_face_fluxes(const TriangleMesh& tm, const FlowField& field, const NamedParameters& np,
                            const std::string& caller, const Visit& visit)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  check_triangle_mesh(tm, caller + ": tm");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  using Geom_traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> ordered_faces(num_faces(tm));
  for (auto f : faces(tm))
    ordered_faces[get(fim, f)] = f;
  const Positions positions = read_positions(vertices_in_index_order(tm, vim), vpm);
  check_finite_positions(positions, caller + ": tm");
  visit_face_fluxes(positions, make_mesh_arrays(tm, vim, fim).face_vertices, field, gt,
                    [&](std::size_t j, double area, double flux) { visit(ordered_faces[j], area, flux); });
}

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Computes the normalized flux of `field` through `tm`:
\f$ f_n = \sum_j A_j |n_j^T v_j| / \|v_j\| \,/\, \sum_j A_j \f$ over the faces whose centroid
sample \f$ v_j \f$ exists, is finite and is not zero.

It is the paper's \f$ f_n \f$ with the flux of each face taken in absolute value, so that it
does not depend on the orientation of the faces: 1 for a surface exactly orthogonal to the
flow, 0 for a stream surface.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with the vertices as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns \f$ f_n \in [0, 1] \f$, or 0 when no face has a usable sample.
\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh.
\sa `Flow_aligned_deformation`, `align_to_flow()`
*/
template <class TriangleMesh, class FlowField, class NamedParameters = parameters::Default_named_parameters>
double normalized_flux(const TriangleMesh& tm, const FlowField& field,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  double flux = 0, area = 0;
  internal::visit_mesh_face_fluxes(tm, field, np, "normalized_flux",
                                   [&](auto, double face_area, double face_flux) {
                                     if (face_flux < 0)
                                       return;
                                     flux += face_area * face_flux;
                                     area += face_area;
                                   });
  return area > 0 ? flux / area : 0;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes the normalized flux \f$ |n_j^T v_j| / \|v_j\| \f$ of every face of `tm` into
`face_flux_map`: 1 where the face is orthogonal to the flow, 0 where it is tangential, and
`-1` where the centroid sample is outside the domain, not finite, or zero, or the face is
degenerate.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam FaceFluxMap a model of `WritablePropertyMap` with the faces as key type and `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param face_flux_map receives the flux of each face
\param np the same named parameters as `normalized_flux()`

\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh.
\sa `normalized_flux()`
*/
template <class TriangleMesh, class FlowField, class FaceFluxMap,
          class NamedParameters = parameters::Default_named_parameters>
void compute_face_normalized_flux(const TriangleMesh& tm, const FlowField& field, FaceFluxMap face_flux_map,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_triangle_mesh(tm, "compute_face_normalized_flux: tm");
  for (auto f : faces(tm))
    put(face_flux_map, f, -1.0);
  internal::visit_mesh_face_fluxes(tm, field, np, "compute_face_normalized_flux",
                                   [&](auto f, double, double flux) { put(face_flux_map, f, flux); });
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H
