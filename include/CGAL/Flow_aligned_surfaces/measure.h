// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well a surface is aligned with a flow.
//
//   normalized_flux = sum_j A_j |n_j . v_j| / |v_j|  /  sum_j A_j
//
// over the faces j whose centroid sample v_j exists, is finite and non-zero (the sampled
// faces): the paper's f_n (Section 7) with the per-face flux in absolute value, so it does
// not depend on the orientation.  1 = exactly orthogonal, 0 = exactly tangential.
//
//   gamma_j = angle(v_j, grad r_j) in [0, 180] degrees,   mean = sum_j A_j gamma_j / sum_j A_j,
//   standard deviation = sqrt(sum_j A_j (gamma_j - mean)^2 / sum_j A_j)
//
// for a vertex field r (a tangential parametrization), over the sampled faces where the
// constant gradient of r on the face is usable and, optionally, the flow is not slow
// (|v_j| >= min_relative_speed * max_k |v_k|): the paper's (gamma bar, sigma_gamma) (Section 7).
//
// Every measure also gives the sampled area fraction (sampled area / area); with no sampled
// face there is no value.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H
#define CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/batched_sampling.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/rotations.h>
#include <CGAL/Flow_aligned_surfaces/Normalized_flux.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Calls `visit(j, unit_normal, area, sample)` for every non-degenerate face j of `positions`,
/// with the field's sample at its centroid (all of them in one batch when the field answers
/// batches).
template <class FlowField, class GeomTraits, class Visit>
void visit_face_samples(const Positions& positions,
                        const std::vector<std::array<Eigen::Index, 3>>& face_vertices, const FlowField& field,
                        const GeomTraits& gt, const Visit& visit)
{
  auto construct_point = gt.construct_point_3_object();
  std::vector<std::size_t> faces;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> areas;
  std::vector<typename GeomTraits::Point_3> centroids;
  for (std::size_t j = 0; j < face_vertices.size(); ++j) {
    const auto& face = face_vertices[j];
    const Eigen::Vector3d a = positions.row(face[0]), b = positions.row(face[1]), c = positions.row(face[2]);
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double twice_area = cross.norm();
    if (!(twice_area > 0))
      continue;
    const Eigen::Vector3d centroid = (a + b + c) / 3;
    faces.push_back(j);
    normals.push_back(cross / twice_area);
    areas.push_back(0.5 * twice_area);
    centroids.push_back(construct_point(centroid.x(), centroid.y(), centroid.z()));
  }
  const std::vector<Flow_sample> samples = sample_flow_at(field, centroids);
  for (std::size_t k = 0; k < faces.size(); ++k)
    visit(faces[k], normals[k], areas[k], samples[k]);
}

/// |n . v| / |v| for a usable sample, nothing otherwise.
inline std::optional<double> face_flux(const Eigen::Vector3d& unit_normal, const Flow_sample& s)
{
  if (s.kind != Sample_kind::VALID)
    return std::nullopt;
  return std::abs(unit_normal.dot(s.direction));
}

/// Calls `visit(j, area, flux)` for every non-degenerate face j of `positions`, with
/// flux = |n_j . v_j| / |v_j| when the centroid sample is usable and empty otherwise.
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
Normalized_flux normalized_flux(const Positions& positions,
                                const std::vector<std::array<Eigen::Index, 3>>& face_vertices,
                                const FlowField& field, const GeomTraits& gt)
{
  Normalized_flux_sum sum;
  visit_face_fluxes(
      positions, face_vertices, field, gt,
      [&](std::size_t, double area, const std::optional<double>& flux) { sum.add(area, flux); });
  return sum.result();
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
sample \f$ v_j \f$ exists, is finite and is not zero (the <em>sampled</em> faces), and the
share of the area of `tm` they cover.

It is the paper's \f$ f_n \f$ with the flux of each face taken in absolute value, so that it
does not depend on the orientation of the faces: 1 for a surface exactly orthogonal to the
flow, 0 for a stream surface.  It speaks only for the sampled faces: read it together with
`Normalized_flux::sampled_area_fraction`.  A surface of which no face is sampled (it has left
the domain, or the flow vanishes on it) has no value, never 0, which would read as "perfectly
tangential".

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

\returns \f$ f_n \in [0, 1] \f$ in `value`, empty when no face is sampled, and the sampled
area fraction.
\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh.
\sa `Normalized_flux`, `Flow_aligned_deformation`, `align_to_flow()`
*/
template <class TriangleMesh, class FlowField, class NamedParameters = parameters::Default_named_parameters>
Normalized_flux normalized_flux(const TriangleMesh& tm, const FlowField& field,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Normalized_flux_sum sum;
  internal::visit_mesh_face_fluxes(
      tm, field, np, "normalized_flux",
      [&](auto, double area, const std::optional<double>& flux) { sum.add(area, flux); });
  return sum.result();
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
  internal::visit_mesh_face_fluxes(
      tm, field, np, "compute_face_normalized_flux",
      [&](auto f, double, const std::optional<double>& flux) { put(face_flux_map, f, flux ? *flux : -1.0); });
}

namespace internal {

/// The angle of one face for `alignment_angle_statistics()`.
template <class FaceDescriptor>
struct Face_alignment_angle {
  FaceDescriptor face;
  double area = 0;
  bool sampled = false; ///< the centroid sample is usable
  bool slow = false;    ///< sampled, but slower than `min_relative_speed` times the fastest face
  double angle = -1;    ///< degrees; -1 when not sampled, slow, or the gradient of r is unusable
};

/// The alignment angle of every non-degenerate face `f` of `tm` (the angle in degrees between
/// the centroid sample and the gradient of `r_map` on `f`), with the faces slower than the
/// named parameter `min_relative_speed` times the fastest sampled face marked slow.
template <class TriangleMesh, class FlowField, class RMap, class NamedParameters>
std::vector<Face_alignment_angle<typename boost::graph_traits<TriangleMesh>::face_descriptor>>
face_alignment_angles(const TriangleMesh& tm, const FlowField& field, RMap r_map, const NamedParameters& np,
                      const std::string& caller)
{
  const double min_relative_speed =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::min_relative_speed_t()), 0.0);
  if (!(min_relative_speed >= 0 && min_relative_speed <= 1))
    throw std::invalid_argument(caller + ": min_relative_speed = " + std::to_string(min_relative_speed) +
                                " is not in [0, 1]");
  std::vector<Face_alignment_angle<typename boost::graph_traits<TriangleMesh>::face_descriptor>> result;
  std::vector<double> speeds;
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
        const bool sampled = s.kind == Sample_kind::VALID;
        const bool usable = sampled && gradient.allFinite() && gradient.squaredNorm() > 0;
        result.push_back(
            {f, area, sampled, false, usable ? angle_between(s.direction, gradient) * 180 / CGAL_PI : -1.0});
        speeds.push_back(sampled ? s.velocity.stableNorm() : 0.0);
      });
  if (min_relative_speed > 0 && !speeds.empty()) {
    const double threshold = min_relative_speed * *std::max_element(speeds.begin(), speeds.end());
    for (std::size_t j = 0; j < result.size(); ++j)
      if (result[j].sampled && speeds[j] < threshold) {
        result[j].slow = true;
        result[j].angle = -1;
      }
  }
  return result;
}

} // namespace internal

/// \ingroup PkgFlowAlignedSurfacesRef
/// The area-weighted statistics of the angle between a flow and the gradient of a vertex field,
/// the result of `alignment_angle_statistics()`, with the shares of the area that were sampled
/// and that were left out as slow.
struct Alignment_angle_statistics {
  double mean = 0;                 ///< \f$ \bar\gamma \f$, degrees
  double standard_deviation = 0;   ///< \f$ \sigma_\gamma \f$, degrees
  double area = 0;                 ///< the total area of the faces measured
  std::size_t number_of_faces = 0; ///< the number of faces measured
  /// the area of the faces where the flow has a usable sample divided by the area of the
  /// surface, as `Normalized_flux::sampled_area_fraction`
  double sampled_area_fraction = 0;
  /// the area of the sampled faces left out because the flow there is slower than
  /// `min_relative_speed` times the fastest face, divided by the area of the surface
  double slow_area_fraction = 0;
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
\f$ r \f$ is zero or not finite, are left out; so are, with `min_relative_speed` \f$ s > 0 \f$,
the <em>slow</em> faces, where \f$ \|v_j\| < s \max_k \|v_k\| \f$ (the maximum over the sampled
faces of `tm`).  The result gives the shares of the area that were sampled and that were left
out as slow.

<b>What the paper's figures are.</b>  The figures of Section 7 (DELTA WING 1.0 and 0.9, STEP 2.2
and 2.4, TURBINE 2.7 and 5.7 degrees) measure the \f$ r \f$ of its LIC-like textures, the
<em>unnormalized</em> tangential parametrization \f$ a_j = v_j \f$ of Section 6
(`parametrize_tangential()` with `FAS::parameters::normalized(false)`), over the whole surface:
the paper excludes no slow region and names its larger deviations "outlier regions, which are
masked by blending".  The default \f$ s = 0 \f$ follows it.  The unnormalized energy weighs each
face by \f$ \|v_j\|^2 \f$, so where the flow almost stops (near a recirculation bubble or a wall)
\f$ \nabla r \f$ is barely constrained and its angles there can dominate \f$ \sigma_\gamma \f$
although they cover little area: `min_relative_speed` (e.g. 0.02) leaves them out and
`slow_area_fraction` says how much was left out.  The paper does not say whether its averages
are area-weighted; these are.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam RMap a model of `ReadablePropertyMap` with the vertices as key type and a number type
convertible to `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param r_map the vertex field, e.g. the `r` of `parametrize_tangential()`
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{min_relative_speed}
    \cgalParamDescription{`FAS::parameters::min_relative_speed()`: faces where the speed of the
      flow is below this fraction of the largest speed sampled on `tm` are left out}
    \cgalParamType{`double` in \f$ [0, 1] \f$}
    \cgalParamDefault{`0` (every sampled face is measured, as in the paper)}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map, geom_traits}
    \cgalParamDescription{as in `normalized_flux()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the statistics, the number and area of the faces measured, and the sampled and slow
area fractions.
\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh, if
`min_relative_speed` is not in \f$ [0, 1] \f$, or if no face can be measured (there is no value).
\sa `parametrize_tangential()`, `compute_face_alignment_angles()`
*/
template <class TriangleMesh, class FlowField, class RMap,
          class NamedParameters = parameters::Default_named_parameters>
Alignment_angle_statistics
alignment_angle_statistics(const TriangleMesh& tm, const FlowField& field, RMap r_map,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "alignment_angle_statistics";
  const auto faces = internal::face_alignment_angles(tm, field, r_map, np, caller);
  Alignment_angle_statistics statistics;
  double total_area = 0, sampled_area = 0, slow_area = 0, weighted = 0;
  for (const auto& f : faces) {
    total_area += f.area;
    sampled_area += f.sampled ? f.area : 0;
    slow_area += f.slow ? f.area : 0;
    if (f.angle < 0)
      continue;
    statistics.area += f.area;
    weighted += f.area * f.angle;
    ++statistics.number_of_faces;
  }
  if (statistics.number_of_faces == 0)
    throw std::invalid_argument(
        caller + ": no face of tm has a usable sample of the field, a non-zero, finite gradient of r_map" +
        (slow_area > 0 ? " and a speed above min_relative_speed times the largest one" : "") +
        " (sampled area fraction " + std::to_string(total_area > 0 ? sampled_area / total_area : 0) + ")");
  statistics.sampled_area_fraction = sampled_area / total_area;
  statistics.slow_area_fraction = slow_area / total_area;
  statistics.mean = weighted / statistics.area;
  double variance = 0;
  for (const auto& f : faces)
    if (f.angle >= 0)
      variance += f.area * (f.angle - statistics.mean) * (f.angle - statistics.mean);
  statistics.standard_deviation = std::sqrt(variance / statistics.area);
  return statistics;
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Writes the angle \f$ \gamma_j \f$ (degrees) of `alignment_angle_statistics()` of every
face of `tm` into `face_angle_map`, and `-1` where it is not defined (the sample is not usable,
the gradient of `r_map` is zero or not finite, or the face is degenerate) or the face is left
out as slow by `min_relative_speed`.

\tparam FaceAngleMap a model of `WritablePropertyMap` with the faces as key type and `double`
as value type

\param face_angle_map receives the angle of each face
\param tm, field, r_map, np as in `alignment_angle_statistics()`

\throws std::invalid_argument if `tm` is empty or not a valid manifold triangle mesh, or if
`min_relative_speed` is not in \f$ [0, 1] \f$.
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
  for (const auto& f : internal::face_alignment_angles(tm, field, r_map, np, "compute_face_alignment_angles"))
    put(face_angle_map, f.face, f.angle);
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_MEASURE_H
