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
//
//   gamma_j = angle(v_j, grad r_j) in [0, 180] degrees,   mean = sum_j A_j gamma_j / sum_j A_j,
//   standard deviation = sqrt(sum_j A_j (gamma_j - mean)^2 / sum_j A_j)
//
// for a vertex field r (a tangential parametrization), over the faces where both v_j and the
// constant gradient of r on the face are usable: the paper's (gamma bar, sigma_gamma) (Section 7).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H
#define CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/rotations.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Calls `visit(j, unit_normal, area, sample)` for every non-degenerate face j of `positions`,
/// with the field's sample at its centroid.
template <class FlowField, class GeomTraits, class Visit>
void visit_face_samples(const Positions& positions,
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
    visit(j, Eigen::Vector3d(cross / twice_area), 0.5 * twice_area,
          sample_flow(field, construct_point(centroid.x(), centroid.y(), centroid.z())));
  }
}

/// |n . v| / |v| for a usable sample, -1 otherwise.
inline double face_flux(const Eigen::Vector3d& unit_normal, const Flow_sample& s)
{
  return s.kind == Sample_kind::VALID ? std::abs(unit_normal.dot(s.direction)) : -1.0;
}

/// Calls `visit(j, area, flux)` for every non-degenerate face j of `positions`, with
/// flux = |n_j . v_j| / |v_j| when the centroid sample is usable and -1 otherwise.
template <class FlowField, class GeomTraits, class Visit>
void visit_face_fluxes(const Positions& positions,
                       const std::vector<std::array<Eigen::Index, 3>>& face_vertices, const FlowField& field,
                       const GeomTraits& gt, const Visit& visit)
{
  visit_face_samples(positions, face_vertices, field, gt,
                     [&](std::size_t j, const Eigen::Vector3d& normal, double area, const Flow_sample& s) {
                       visit(j, area, face_flux(normal, s));
                     });
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

/// Calls `visit(f, corners, rows, positions, unit_normal, area, sample)` for every non-degenerate
/// face `f` of `tm`, with the vertices of `f`, the rows of `positions` that hold them, and the
/// other arguments as `visit_face_samples()`.
template <class TriangleMesh, class FlowField, class NamedParameters, class Visit>
void visit_mesh_face_samples(const TriangleMesh& tm, const FlowField& field, const NamedParameters& np,
                             const std::string& caller, const Visit& visit)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto [vpm, gt] = checked_mesh_input(tm, np, caller + ": tm");
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> ordered_faces(num_faces(tm));
  for (auto f : faces(tm))
    ordered_faces[get(fim, f)] = f;
  const auto ordered_vertices = vertices_in_index_order(tm, vim);
  const Positions positions = read_positions(ordered_vertices, vpm);
  check_finite_positions(positions, caller + ": tm");
  const auto face_vertices = make_mesh_arrays(tm, vim, fim).face_vertices;
  visit_face_samples(
      positions, face_vertices, field, gt,
      [&](std::size_t j, const Eigen::Vector3d& normal, double area, const Flow_sample& s) {
        const auto& fv = face_vertices[j];
        const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3> corners{
            ordered_vertices[fv[0]], ordered_vertices[fv[1]], ordered_vertices[fv[2]]};
        visit(ordered_faces[j], corners, fv, positions, normal, area, s);
      });
}

/// Calls `visit(f, area, flux)` for every non-degenerate face `f` of `tm`, as `visit_face_fluxes()`.
template <class TriangleMesh, class FlowField, class NamedParameters, class Visit>
void visit_mesh_face_fluxes(const TriangleMesh& tm, const FlowField& field, const NamedParameters& np,
                            const std::string& caller, const Visit& visit)
{
  visit_mesh_face_samples(tm, field, np, caller,
                          [&](auto f, const auto&, const auto&, const Positions&,
                              const Eigen::Vector3d& normal, double area,
                              const Flow_sample& s) { visit(f, area, face_flux(normal, s)); });
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

namespace internal {

/// Calls `visit(f, area, angle)` for every non-degenerate face `f` of `tm`, with the angle in
/// degrees between the centroid sample and the gradient of `r_map` on `f`, or -1 when the
/// sample is not usable or the gradient is zero or not finite.
template <class TriangleMesh, class FlowField, class RMap, class NamedParameters, class Visit>
void visit_face_alignment_angles(const TriangleMesh& tm, const FlowField& field, RMap r_map,
                                 const NamedParameters& np, const std::string& caller, const Visit& visit)
{
  visit_mesh_face_samples(
      tm, field, np, caller,
      [&](auto f, const auto& corners, const auto& rows, const Positions& positions, const Eigen::Vector3d&,
          double area, const Flow_sample& s) {
        const auto t =
            triangle_gradients(positions.row(rows[0]).transpose(), positions.row(rows[1]).transpose(),
                               positions.row(rows[2]).transpose());
        const Eigen::Vector3d r(CGAL::to_double(get(r_map, corners[0])),
                                CGAL::to_double(get(r_map, corners[1])),
                                CGAL::to_double(get(r_map, corners[2])));
        const Eigen::Vector3d gradient = t ? Eigen::Vector3d(t->gradients * r) : Eigen::Vector3d::Zero();
        const bool usable =
            s.kind == Sample_kind::VALID && gradient.allFinite() && gradient.squaredNorm() > 0;
        visit(f, area, usable ? angle_between(s.direction, gradient) * 180 / CGAL_PI : -1.0);
      });
}

} // namespace internal

/// \ingroup PkgFlowAlignedSurfacesRef
/// The area-weighted statistics of the angle between a flow and the gradient of a vertex field,
/// the result of `alignment_angle_statistics()`.
struct Alignment_angle_statistics {
  double mean = 0;                 ///< \f$ \bar\gamma \f$, degrees
  double standard_deviation = 0;   ///< \f$ \sigma_\gamma \f$, degrees
  double area = 0;                 ///< the total area of the faces measured
  std::size_t number_of_faces = 0; ///< the number of faces measured
};

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Computes the area-weighted mean \f$ \bar\gamma = \sum_j A_j \gamma_j / \sum_j A_j \f$
and standard deviation \f$ \sigma_\gamma = (\sum_j A_j (\gamma_j - \bar\gamma)^2 / \sum_j
A_j)^{1/2} \f$, in degrees, of the angle \f$ \gamma_j \in [0, 180] \f$ between the field's
sample \f$ v_j \f$ at the centroid of face \f$ j \f$ and the (constant) gradient of the
piecewise linear vertex field `r_map` on it: the paper's \f$ (\bar\gamma, \sigma_\gamma) \f$,
which measures how well the \f$ r \f$ of a tangential parametrization follows the flow.

Faces whose sample is outside the domain, not finite or zero, or where the gradient of
\f$ r \f$ is zero or not finite, are left out.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam RMap a model of `ReadablePropertyMap` with the vertices as key type and a number type
convertible to `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param r_map the vertex field, e.g. the `r` of `parametrize_tangential()`
\param np the same named parameters as `normalized_flux()`

\returns the statistics and the number and area of the faces measured.
\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh, or if no
face can be measured.
\sa `parametrize_tangential()`, `compute_face_alignment_angles()`
*/
template <class TriangleMesh, class FlowField, class RMap,
          class NamedParameters = parameters::Default_named_parameters>
Alignment_angle_statistics
alignment_angle_statistics(const TriangleMesh& tm, const FlowField& field, RMap r_map,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "alignment_angle_statistics";
  std::vector<std::array<double, 2>> measured; // area, angle
  internal::visit_face_alignment_angles(tm, field, r_map, np, caller, [&](auto, double area, double angle) {
    if (angle >= 0)
      measured.push_back({area, angle});
  });
  if (measured.empty())
    throw std::invalid_argument(caller +
                                ": no face of tm has both a usable sample of the field and a non-zero, "
                                "finite gradient of r_map");
  Alignment_angle_statistics statistics;
  double weighted = 0;
  for (const auto& m : measured) {
    statistics.area += m[0];
    weighted += m[0] * m[1];
  }
  statistics.mean = weighted / statistics.area;
  double variance = 0;
  for (const auto& m : measured)
    variance += m[0] * (m[1] - statistics.mean) * (m[1] - statistics.mean);
  statistics.standard_deviation = std::sqrt(variance / statistics.area);
  statistics.number_of_faces = measured.size();
  return statistics;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes the angle \f$ \gamma_j \f$ (degrees) of `alignment_angle_statistics()` of every
face of `tm` into `face_angle_map`, and `-1` where it is not defined (the sample is not usable,
the gradient of `r_map` is zero or not finite, or the face is degenerate).

\tparam FaceAngleMap a model of `WritablePropertyMap` with the faces as key type and `double`
as value type

\param face_angle_map receives the angle of each face
\param tm, field, r_map, np as in `alignment_angle_statistics()`

\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh.
\sa `alignment_angle_statistics()`
*/
template <class TriangleMesh, class FlowField, class RMap, class FaceAngleMap,
          class NamedParameters = parameters::Default_named_parameters>
void compute_face_alignment_angles(const TriangleMesh& tm, const FlowField& field, RMap r_map,
                                   FaceAngleMap face_angle_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_triangle_mesh(tm, "compute_face_alignment_angles: tm");
  for (auto f : faces(tm))
    put(face_angle_map, f, -1.0);
  internal::visit_face_alignment_angles(tm, field, r_map, np, "compute_face_alignment_angles",
                                        [&](auto f, double, double angle) { put(face_angle_map, f, angle); });
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H
