// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The per-face pieces of the parametrizations of Section 5 of the paper, shared by the free
// functions of parametrize.h (which factor the operators of the surface they are given) and by
// Flow_aligned_deformation (which reuses its factored L + W on M_0):
//
//   face frames     n_j (unit normal), centroid, area of face j of the surface M_k
//   guidance        tangential  a_j = P_j v_j (/ |P_j v_j|),
//                   orthogonal  a_j = P_j (R(n_c, alpha) r_c) x v_j (/ |.|), r_c from the
//                               Householder frame of n_c or from the user's gradient direction,
//                   heat method a_j = -grad h / |grad h|,          b_j = a_j x n_j
//   constraint      the vertex nearest to the area-weighted barycenter of each component, where
//                   the solution is shifted to 0
//
// with P_j = I - n_j n_j^T, v_j the field at the centroid, n_c the normal at the constrained
// vertex and r_c the second column of the Householder Q of n_c.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_PARAMETRIZATION_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_PARAMETRIZATION_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/batched_sampling.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/solver/Sparse_cholesky.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/rotations.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// The vertex positions of a surface and the frames of its faces (face order of `Mesh_arrays`).
struct Surface_faces {
  Positions positions;      // m x 3
  Positions face_normals;   // n x 3, unit
  Positions face_centroids; // n x 3
  Eigen::VectorXd face_areas;
  std::vector<std::size_t> vertex_component;

  Eigen::Index number_of_faces() const { return face_areas.size(); }
};

/// The frames of the faces of `arrays` at `positions`; nothing for a face of zero area, whose
/// index is returned in `degenerate_face` (-1 when every face has an area).
inline Surface_faces make_surface_faces(const Mesh_arrays& arrays, Positions positions,
                                        Eigen::Index& degenerate_face)
{
  Surface_faces s;
  const Eigen::Index n = Eigen::Index(arrays.face_vertices.size());
  s.positions = std::move(positions);
  s.face_normals.resize(n, 3);
  s.face_centroids.resize(n, 3);
  s.face_areas.resize(n);
  s.vertex_component = vertex_components(arrays, std::size_t(s.positions.rows()));
  degenerate_face = -1;
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& fv = arrays.face_vertices[std::size_t(j)];
    const Eigen::Vector3d a = s.positions.row(fv[0]), b = s.positions.row(fv[1]), c = s.positions.row(fv[2]);
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double twice_area = cross.norm();
    if (!(twice_area > 0) && degenerate_face < 0)
      degenerate_face = j;
    s.face_normals.row(j) = twice_area > 0 ? Eigen::Vector3d(cross / twice_area) : Eigen::Vector3d::Zero();
    s.face_centroids.row(j) = (a + b + c) / 3;
    s.face_areas[j] = 0.5 * twice_area;
  }
  return s;
}

/// The index of `v` in `vertices`; throws std::invalid_argument naming `what` when `v` is not
/// among them.
template <class VertexDescriptor>
Eigen::Index vertex_index_or_throw(const std::vector<VertexDescriptor>& vertices, const VertexDescriptor& v,
                                   const std::string& what)
{
  const auto found = std::find(vertices.begin(), vertices.end(), v);
  if (found == vertices.end())
    throw std::invalid_argument(what + " is not a vertex of tm");
  return static_cast<Eigen::Index>(found - vertices.begin());
}

/// The vertex named by `constraint_vertex` in `np`, as an index into `vertices`, or -1.
template <class VertexDescriptor, class NamedParameters>
Eigen::Index chosen_constraint_vertex(const std::vector<VertexDescriptor>& vertices,
                                      const NamedParameters& np, const std::string& caller)
{
  if constexpr (!parameters::is_default_parameter<NamedParameters, internal_np::constraint_vertex_t>::value)
    return vertex_index_or_throw(
        vertices, VertexDescriptor(parameters::get_parameter(np, internal_np::constraint_vertex_t())),
        caller + ": constraint_vertex");
  else
    return -1;
}

/// One constrained vertex per connected component: the vertex nearest to the component's
/// area-weighted barycenter (the lowest index among vertices equally near, up to a tolerance
/// that makes the choice independent of rounding), or `chosen` (when >= 0) in its component.
inline std::vector<Eigen::Index> constrained_vertices(const Mesh_arrays& arrays, const Surface_faces& s,
                                                      Eigen::Index chosen)
{
  const std::size_t components = arrays.number_of_components;
  std::vector<Eigen::Vector3d> barycenter(components, Eigen::Vector3d::Zero());
  std::vector<double> area(components, 0);
  for (Eigen::Index j = 0; j < s.number_of_faces(); ++j) {
    const std::size_t c = arrays.face_component[std::size_t(j)];
    barycenter[c] += s.face_areas[j] * s.face_centroids.row(j).transpose();
    area[c] += s.face_areas[j];
  }
  const double tolerance =
      1e-10 * (s.positions.colwise().maxCoeff() - s.positions.colwise().minCoeff()).squaredNorm();
  std::vector<Eigen::Index> nearest(components, -1);
  std::vector<double> nearest_distance(components, std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < s.positions.rows(); ++i) {
    const std::size_t c = s.vertex_component[std::size_t(i)];
    const double d = (s.positions.row(i).transpose() - barycenter[c] / area[c]).squaredNorm();
    if (d < nearest_distance[c] - tolerance) {
      nearest_distance[c] = d;
      nearest[c] = i;
    }
  }
  if (chosen >= 0)
    nearest[s.vertex_component[std::size_t(chosen)]] = chosen;
  return nearest;
}

/// Shifts every column of x (m x k) to 0 at `constrained[c]` in each component c.
inline void shift_to_constraints(Eigen::MatrixXd& x, const std::vector<Eigen::Index>& constrained,
                                 const std::vector<std::size_t>& vertex_component)
{
  Eigen::MatrixXd at_constraint(Eigen::Index(constrained.size()), x.cols());
  for (std::size_t c = 0; c < constrained.size(); ++c)
    at_constraint.row(Eigen::Index(c)) = x.row(constrained[c]);
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    x.row(i) -= at_constraint.row(Eigen::Index(vertex_component[std::size_t(i)]));
}

/// The unit normal at vertex i: the area-weighted mean of its faces' normals.
inline Eigen::Vector3d vertex_normal(const Mesh_arrays& arrays, const Surface_faces& s, Eigen::Index i)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (Eigen::Index j = 0; j < s.number_of_faces(); ++j) {
    const auto& fv = arrays.face_vertices[std::size_t(j)];
    if (fv[0] == i || fv[1] == i || fv[2] == i)
      n += s.face_areas[j] * s.face_normals.row(j).transpose();
  }
  return n.normalized();
}

/// Samples `field` at every face centroid (in one batch when the field answers batches); rows of
/// faces without a usable sample (outside the domain, not finite, or zero) are zero.
template <class FlowField, class GeomTraits>
Positions sample_face_velocities(const Surface_faces& s, const FlowField& field, const GeomTraits& gt)
{
  auto construct_point = gt.construct_point_3_object();
  std::vector<typename GeomTraits::Point_3> centroids;
  for (Eigen::Index j = 0; j < s.number_of_faces(); ++j)
    centroids.push_back(construct_point(s.face_centroids(j, 0), s.face_centroids(j, 1), s.face_centroids(j, 2)));
  const std::vector<Flow_sample> samples = sample_flow_at(field, centroids);
  Positions v = Positions::Zero(s.number_of_faces(), 3);
  for (Eigen::Index j = 0; j < s.number_of_faces(); ++j)
    if (samples[std::size_t(j)].kind == Sample_kind::VALID)
      v.row(j) = samples[std::size_t(j)].velocity.transpose();
  return v;
}

/// Projects a_j into the plane of face j and normalizes it when asked; a direction within
/// 1e-9 (relative) of the normal, or zero, has no usable projection and becomes zero.
inline Eigen::Vector3d project_guidance(const Eigen::Vector3d& a, const Eigen::Vector3d& n, bool normalize)
{
  const Eigen::Vector3d p = a - n.dot(a) * n;
  const double length = p.norm();
  if (!(length > 1e-9 * a.norm()) || !std::isfinite(length))
    return Eigen::Vector3d::Zero();
  return normalize ? Eigen::Vector3d(p / length) : p;
}

/// The tangential guidance a_j = P_j v_j, normalized when asked.
inline Positions tangential_guidance(const Surface_faces& s, Positions velocities, bool normalize)
{
  for (Eigen::Index j = 0; j < velocities.rows(); ++j)
    velocities.row(j) =
        project_guidance(velocities.row(j).transpose(), s.face_normals.row(j).transpose(), normalize)
            .transpose();
  return velocities;
}

/// The sign of the flux of `velocities` through the faces around vertex i (their area-weighted
/// n_j . v_j): +1 where the flow leaves the surface on the side of its normals, and where no face
/// around i has a sample.
inline double flux_sign_at_vertex(const Mesh_arrays& arrays, const Surface_faces& s, const Positions& velocities,
                                  Eigen::Index i)
{
  double flux = 0;
  for (Eigen::Index j = 0; j < s.number_of_faces(); ++j) {
    const auto& fv = arrays.face_vertices[std::size_t(j)];
    if (fv[0] == i || fv[1] == i || fv[2] == i)
      flux += s.face_areas[j] * s.face_normals.row(j).dot(velocities.row(j));
  }
  return flux < 0 ? -1.0 : 1.0;
}

/// The second column of the Householder Q of the 3-vector n, as Eigen's HouseholderQR gives it
/// (its `makeHouseholder()` convention: Q = I - tau v v^T, v = (1, essential), beta = -sign(n_0)|n|),
/// in closed form: instantiating HouseholderQR cost GCC 4.6 s in every file that included
/// this header.  A unit vector orthogonal to n when n is not zero.
inline Eigen::Vector3d householder_second_column(const Eigen::Vector3d& n)
{
  const double tail_squared_norm = n.tail<2>().squaredNorm();
  if (tail_squared_norm <= (std::numeric_limits<double>::min)())
    return Eigen::Vector3d::UnitY(); // Q = I: n is along the first axis already
  double beta = std::sqrt(n(0) * n(0) + tail_squared_norm);
  if (n(0) >= 0)
    beta = -beta;
  const Eigen::Vector2d essential = n.tail<2>() / (n(0) - beta);
  const double tau = (beta - n(0)) / beta;
  const double t = tau * essential(0);
  return Eigen::Vector3d(-t, 1 - t * essential(0), -t * essential(1));
}

/// The direction r_c that the orthogonal guidance turns by alpha about n_c in the component of
/// the constrained vertex i: by default the second column of the Householder Q of n_c; with
/// `gradient_direction` g, sigma n_c x P g / |P g| (sigma the flux sign at i), for which
/// a_j = P_j (r_c x v_j) = |v_j| P g / |P g| where v_j = sigma |v_j| n_c: grad r points along g.
/// Throws std::invalid_argument naming `caller` when g is normal to the surface at i.
inline Eigen::Vector3d orthogonal_reference_direction(const Mesh_arrays& arrays, const Surface_faces& s,
                                                      const Positions& velocities, Eigen::Index i,
                                                      const std::optional<Eigen::Vector3d>& gradient_direction,
                                                      const std::string& caller)
{
  const Eigen::Vector3d n_c = vertex_normal(arrays, s, i);
  if (!gradient_direction) {
    return householder_second_column(n_c);
  }
  const Eigen::Vector3d g = *gradient_direction - n_c.dot(*gradient_direction) * n_c;
  if (!(g.norm() > 1e-6 * gradient_direction->norm()))
    throw std::invalid_argument(caller + ": gradient_direction is normal to the surface at the constrained vertex " +
                                std::to_string(i) + " (it has no direction in the tangent plane)");
  return flux_sign_at_vertex(arrays, s, velocities, i) * n_c.cross(g.normalized());
}

/// The user direction of `gradient_direction` in `np`, checked finite and not zero, or nothing.
template <class NamedParameters>
std::optional<Eigen::Vector3d> orthogonal_gradient_direction(const NamedParameters& np, const std::string& caller)
{
  if constexpr (!parameters::is_default_parameter<NamedParameters, internal_np::gradient_direction_t>::value) {
    const auto& g = parameters::get_parameter(np, internal_np::gradient_direction_t());
    const Eigen::Vector3d d(CGAL::to_double(g.x()), CGAL::to_double(g.y()), CGAL::to_double(g.z()));
    if (!d.allFinite() || !(d.squaredNorm() > 0))
      throw std::invalid_argument(caller + ": gradient_direction must be finite and not zero");
    return d;
  }
  else
    return std::nullopt;
}

/// The orthogonal guidance a_j = P_j (R(n_c, alpha) r_c) x v_j, normalized when asked, with n_c
/// the normal at the constrained vertex of face j's component and r_c from
/// `orthogonal_reference_direction()`.
inline Positions orthogonal_guidance(const Mesh_arrays& arrays, const Surface_faces& s, Positions velocities,
                                     const std::vector<Eigen::Index>& constrained, double alpha,
                                     bool normalize,
                                     const std::optional<Eigen::Vector3d>& gradient_direction,
                                     const std::string& caller)
{
  std::vector<Eigen::Vector3d> direction(constrained.size());
  for (std::size_t c = 0; c < constrained.size(); ++c) {
    const Eigen::Vector3d n_c = vertex_normal(arrays, s, constrained[c]);
    direction[c] = rotation_matrix(n_c, alpha) * orthogonal_reference_direction(arrays, s, velocities, constrained[c],
                                                                                gradient_direction, caller);
  }
  for (Eigen::Index j = 0; j < velocities.rows(); ++j) {
    const Eigen::Vector3d turned = direction[arrays.face_component[std::size_t(j)]];
    velocities.row(j) = project_guidance(turned.cross(velocities.row(j).transpose()),
                                         s.face_normals.row(j).transpose(), normalize)
                            .transpose();
  }
  return velocities;
}

/// The cross field C (3n x 2): column 0 stacks a_j, column 1 stacks b_j = a_j x n_j.  Throws
/// std::invalid_argument when no face has a usable direction.
inline Eigen::MatrixXd cross_field(const Surface_faces& s, const Positions& a, const std::string& caller)
{
  const Eigen::Index n = s.number_of_faces();
  Eigen::MatrixXd c(3 * n, 2);
  bool any = false;
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Vector3d aj = a.row(j).transpose();
    c.block<3, 1>(3 * j, 0) = aj;
    c.block<3, 1>(3 * j, 1) = aj.cross(s.face_normals.row(j).transpose());
    any = any || aj.squaredNorm() > 0;
  }
  if (!any)
    throw std::invalid_argument(
        caller + ": the field gives no usable direction on any face of tm (every centroid sample "
                 "is outside the domain, not finite, zero, or normal to its face)");
  return c;
}

/// The heat step of the heat method from vertex `source`: h = (M + t L)^{-1} h_0, with L and
/// the face areas of `ops`, M the lumped (barycentric) vertex areas, h_0 = 1 at `source` and 0
/// elsewhere, and t = 5 A_M / |T| over the faces of the source's component.  One factorization
/// with a `SparseLinearSolver` and one solve.
template <class SparseLinearSolver>
Eigen::VectorXd heat_step(const Poisson_operators& ops, const Mesh_arrays& arrays, Eigen::Index source,
                          std::size_t component)
{
  const Eigen::Index m = ops.number_of_vertices();
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(m);
  double area = 0;
  Eigen::Index faces_in_component = 0;
  for (Eigen::Index j = 0; j < ops.number_of_faces(); ++j) {
    for (Eigen::Index v : arrays.face_vertices[std::size_t(j)])
      mass[v] += ops.face_areas[j] / 3;
    if (arrays.face_component[std::size_t(j)] == component) {
      area += ops.face_areas[j];
      ++faces_in_component;
    }
  }
  const double t = 5 * area / double(faces_in_component);
  Eigen::SparseMatrix<double> system = t * ops.L;
  for (Eigen::Index i = 0; i < m; ++i)
    system.coeffRef(i, i) += mass[i];
  SparseLinearSolver solver;
  factor_or_throw(solver, system, "M + t L");
  Eigen::VectorXd h0 = Eigen::VectorXd::Zero(m);
  h0[source] = 1;
  return solver.solver().solve(h0);
}

/// The user angle alpha of the orthogonal parametrization (`angle`, default 0); throws
/// std::invalid_argument naming `caller` when it is not finite.
template <class NamedParameters>
double orthogonal_parametrization_angle(const NamedParameters& np, const std::string& caller)
{
  const double alpha =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::angle_t()), 0.0);
  if (!std::isfinite(alpha))
    throw std::invalid_argument(caller + ": angle must be finite (got " + std::to_string(alpha) + ")");
  return alpha;
}

/// The heat method's guidance X_j = -grad h / |grad h| on the faces of `s` (3n x 1), zero where
/// the gradient vanishes.
inline Eigen::MatrixXd normalized_negative_gradient(const Mesh_arrays& arrays, const Surface_faces& s,
                                                    const Eigen::VectorXd& h)
{
  const Eigen::Index n = s.number_of_faces();
  Eigen::MatrixXd guidance = Eigen::MatrixXd::Zero(3 * n, 1);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& fv = arrays.face_vertices[std::size_t(j)];
    const auto t = triangle_gradients(s.positions.row(fv[0]).transpose(), s.positions.row(fv[1]).transpose(),
                                      s.positions.row(fv[2]).transpose());
    if (!t)
      continue;
    const Eigen::Vector3d g = t->gradients * Eigen::Vector3d(h[fv[0]], h[fv[1]], h[fv[2]]);
    const double length = g.norm();
    if (length > 0 && std::isfinite(length))
      guidance.block<3, 1>(3 * j, 0) = -g / length;
  }
  return guidance;
}

/// Writes column `column` of x to `map`, vertex i of `vertices` taking row i.
template <class VertexDescriptor, class Map>
void write_vertex_values(const std::vector<VertexDescriptor>& vertices, const Eigen::MatrixXd& x,
                         Eigen::Index column, Map map)
{
  using Value = typename boost::property_traits<Map>::value_type;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    put(map, vertices[i], Value(x(Eigen::Index(i), column)));
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_PARAMETRIZATION_H
