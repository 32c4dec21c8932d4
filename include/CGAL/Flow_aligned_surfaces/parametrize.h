// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Poisson parametrizations of a triangle mesh guided by a flow (Section 5 of the paper).
// With the operators G (3n x m), A (3n x 3n), L = G^T A G and D = G^T A of
// internal/Poisson_operators.h, a per-face cross field C_j = (a_j, b_j) gives the two vertex
// scalar fields (r, s) (m x 2) that minimize eq. (6)
//
//   e_p(r, s) = ||G r - a||_A^2 + ||G s - b||_A^2,   that is   L (r, s) = D (a, b)   (eq. 7),
//
// solved with one factorization of L + W (W: one soft constraint per connected component,
// which fixes the free constant) and one back-substitution per column; r and s are then
// shifted to 0 at the constrained vertex.
//
//   tangential:  a_j = P_j v_j / |P_j v_j|  (normalized)  or  P_j v_j,   b_j = a_j x n_j
//   orthogonal:  a_j = P_j (R(n_c, alpha) r_c) x v_j  (optionally normalized),  b_j = a_j x n_j
//   geodesic distance (heat method, Crane et al. 2013, on the cotangent operators of the
//                intrinsic Delaunay triangulation by default, internal/heat_method.h):
//                (M + t L) h = h_0,  t = 5 A_M / |T|,  X_j = -(G h)_j / |(G h)_j|,  L d = D X,
//                d(source) = 0.
//
// P_j = I - n_j n_j^T, v_j the field at the centroid of face j, n_c the normal at the
// constrained vertex v_c, r_c a unit vector orthogonal to n_c (second column of the Householder
// Q of n_c, or sigma n_c x the user's gradient_direction), M the lumped (barycentric) vertex areas, A_M the total area and |T| the number of
// faces.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_PARAMETRIZE_H
#define CGAL_FLOW_ALIGNED_SURFACES_PARAMETRIZE_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/Poisson_operators.h>
#include <CGAL/Flow_aligned_surfaces/internal/solver/Sparse_cholesky.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/internal/heat_method.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/parametrization.h>
#include <CGAL/Flow_aligned_surfaces/internal/progress_callback.h>
#include <CGAL/Flow_aligned_surfaces/internal/rotations.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// A face graph flattened into arrays, with its face frames and its Poisson operators.
template <class TriangleMesh>
struct Surface_operators {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

  std::vector<vertex_descriptor> vertices; // in index order
  Mesh_arrays arrays;
  Surface_faces faces;
  Poisson_operators ops;
};

/// Checks `tm` and builds its operators; messages start with `caller`.
template <class TriangleMesh, class NamedParameters>
Surface_operators<TriangleMesh> make_surface_operators(const TriangleMesh& tm, const NamedParameters& np,
                                                       const std::string& caller)
{
  const auto vpm = checked_mesh_input(tm, np, caller + ": tm").vpm;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  Surface_operators<TriangleMesh> s;
  s.vertices = vertices_in_index_order(tm, vim);
  s.arrays = make_mesh_arrays(tm, vim, fim);
  Positions positions = read_positions(s.vertices, vpm);
  check_finite_positions(positions, caller + ": tm");
  auto built = make_poisson_operators(positions, s.arrays.face_vertices, Operators_asked::divergence);
  if (auto* degenerate = std::get_if<Degenerate_face>(&built))
    throw std::invalid_argument(caller + ": tm: face " + std::to_string(degenerate->face) +
                                " is degenerate (zero area)");
  s.ops = std::move(std::get<Poisson_operators>(built));
  Eigen::Index degenerate_face = -1; // none: the operators were built
  s.faces = make_surface_faces(s.arrays, std::move(positions), degenerate_face);
  return s;
}

/// The sparse linear solver of the named parameter `sparse_linear_solver` of `NamedParameters`,
/// the package's default when there is none.
template <class NamedParameters>
using Sparse_linear_solver_parameter = typename CGAL::Default::Get<
    typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t,
                                                       NamedParameters, CGAL::Default>::type,
    Default_sparse_linear_solver>::type;

/// The solution x (m x k) of L x = rhs with x = 0 at `constrained[c]` in each component c:
/// one factorization of L + W with a `SparseLinearSolver`, W = w e_c e_c^T for each
/// constrained vertex, and one back-substitution per column.  Since the rows of D sum to zero over a component (G maps
/// constants to zero), summing the rows of (L + W) x = D y gives w x_c = 0: the soft
/// constraint is exact for any w > 0, and w = mean diag(L) keeps L + W well conditioned.
/// The final shift removes the rounding left at x_c.  `callback` hears `factored` after the
/// factorization; nothing when it stops the work there.
template <class SparseLinearSolver>
std::optional<Eigen::MatrixXd>
solve_constrained_poisson(const Poisson_operators& ops, const std::vector<Eigen::Index>& constrained,
                          const std::vector<std::size_t>& vertex_component, const Eigen::MatrixXd& rhs,
                          const Progress_callback& callback, double factored)
{
  Eigen::SparseMatrix<double> system = ops.L;
  const double weight = ops.L.diagonal().mean();
  for (Eigen::Index v : constrained)
    system.coeffRef(v, v) += weight;
  SparseLinearSolver solver;
  factor_or_throw(solver, system, "L + W");
  if (!report_progress(callback, factored))
    return std::nullopt;
  Eigen::MatrixXd x = solver.solver().solve(rhs);
  shift_to_constraints(x, constrained, vertex_component);
  return x;
}

/// Solves eq. (7) on `s` for the guidance `a` (n x 3, b_j = a_j x n_j) with a
/// `SparseLinearSolver` and writes r and s; `callback` hears 2/3 after the factorization and 1
/// at the end.  Returns false, writing nothing, when the callback stops the work after the
/// factorization.
template <class SparseLinearSolver, class TriangleMesh, class RMap, class SMap>
bool solve_parametrization(const Surface_operators<TriangleMesh>& s, const Positions& a,
                           const std::vector<Eigen::Index>& constrained, RMap r_map, SMap s_map,
                           const std::string& caller, const Progress_callback& callback)
{
  const Eigen::MatrixXd c = cross_field(s.faces, a, caller);
  const std::optional<Eigen::MatrixXd> rs = solve_constrained_poisson<SparseLinearSolver>(
      s.ops, constrained, s.faces.vertex_component, s.ops.D * c, callback, 2. / 3);
  if (!rs)
    return false;
  write_vertex_values(s.vertices, *rs, 0, r_map);
  write_vertex_values(s.vertices, *rs, 1, s_map);
  report_progress(callback, 1.);
  return true;
}

/// The per-call data of the parametrization functions: the checked surface, its constrained
/// vertices and the field sampled at its face centroids.
template <class TriangleMesh>
struct Parametrization_input {
  Surface_operators<TriangleMesh> surface;
  std::vector<Eigen::Index> constrained;
  Positions velocities;
};

template <class TriangleMesh, class FlowField, class NamedParameters>
Parametrization_input<TriangleMesh> make_parametrization_input(const TriangleMesh& tm, const FlowField& field,
                                                               const NamedParameters& np,
                                                               const std::string& caller)
{
  Parametrization_input<TriangleMesh> in{make_surface_operators(tm, np, caller), {}, {}};
  in.constrained = constrained_vertices(in.surface.arrays, in.surface.faces,
                                        chosen_constraint_vertex(in.surface.vertices, np, caller));
  using Geom_traits = typename Checked_mesh_input<TriangleMesh, NamedParameters>::Geom_traits;
  in.velocities = sample_face_velocities(in.surface.faces, field,
                                         parameters::choose_parameter<Geom_traits>(
                                             parameters::get_parameter(np, CGAL::internal_np::geom_traits)));
  return in;
}

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Computes the tangential parametrization \f$ (r, s) \f$ of `tm` in `field`: the
least-squares solution of \f$ \mathbf{L} (\mathbf{r}, \mathbf{s}) = \mathbf{D} (\mathbf{a},
\mathbf{b}) \f$ (the paper's eq. (7)) for the guidance
\f$ a_j = P_j v_j / \|P_j v_j\| \f$ (normalized, the default) or \f$ a_j = P_j v_j \f$, and
\f$ b_j = a_j \times n_j \f$, where \f$ v_j \f$ is the field at the centroid of face \f$ j \f$,
\f$ n_j \f$ its unit normal and \f$ P_j = I - n_j n_j^T \f$.

On a stream surface, \f$ \nabla r \f$ follows the flow: iso-contours of \f$ r \f$ cross the
flow and serve as seed curves, iso-contours of \f$ s \f$ are near stream lines.  Normalized,
the iso-contours of \f$ r \f$ are near-equidistant; unnormalized, \f$ r \f$ is the time-like
coordinate used for LIC, and on a planar surface in a 2D divergence-free flow \f$ s \f$ is
\f$ -\psi \f$ up to a constant (\f$ \psi \f$ the stream function with
\f$ v = (\partial_y \psi, -\partial_x \psi) \f$ in the frame of the normal), in a curl-free
flow \f$ r \f$ is the potential up to a constant.  The normalized \f$ \nabla r \f$ follows the flow
closely where its stream lines are near straight, the unnormalized one where the flow on the
surface has little vorticity (`alignment_angle_statistics()` measures it).  Projecting \f$ v_j \f$ does not change the
unnormalized solution (\f$ \mathbf{G} r \f$ lies in the face's plane).

Faces whose centroid sample is outside the domain, not finite or zero, or whose field is
normal to the face, get \f$ a_j = b_j = 0 \f$ (they only smooth the solution).  Both fields
are 0 at the constrained vertex of each connected component; a component on which no face has
a usable direction gets 0 everywhere.  The system matrix is factored once and solved for both
columns.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam RMap, SMap models of `WritablePropertyMap` with the vertices as key type and a
floating-point value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param r_map receives \f$ r \f$ (along the flow)
\param s_map receives \f$ s \f$ (across the flow)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{normalized}
    \cgalParamDescription{`FAS::parameters::normalized()`: whether \f$ a_j \f$ is normalized}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{constraint_vertex}
    \cgalParamDescription{`FAS::parameters::constraint_vertex()`: the vertex where \f$ r = s = 0 \f$
      in its connected component}
    \cgalParamType{`boost::graph_traits<TriangleMesh>::%vertex_descriptor`}
    \cgalParamDefault{the vertex nearest to the area-weighted barycenter of each connected component}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map, geom_traits}
    \cgalParamDescription{the points of the vertices and the kernel, as in `normalized_flux()`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map, face_index_map}
    \cgalParamDescription{property maps associating indices in `[0, num_vertices(tm))`, `[0, num_faces(tm))`}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{CGAL's progress callback (`CGAL::parameters::callback()`), called with
      `1/3` once the field is sampled at the face centroids, `2/3` once the system is factored and
      `1` once `r_map` and `s_map` are written; if it returns `false` before the last call, the
      function returns `false` and `r_map` and `s_map` are untouched (see \ref fas_progress)}
    \cgalParamType{a callable convertible to `std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{an instance of the sparse linear solver that factors
      \f$ \mathbf{L} + \mathbf{W} \f$ once and solves both columns; only its type is used}
    \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d` wrapping an Eigen sparse
      Cholesky solver, such as `CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>`}
    \cgalParamDefault{CHOLMOD's simplicial \f$ LDL^T \f$ when found, else Eigen's `SimplicialLDLT`
      (as in `align_to_flow()`)}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true`, or `false` when the `callback` stopped the work (nothing written)
\throws std::invalid_argument if `tm` is empty, not a valid manifold triangle mesh, has a
degenerate face or a coordinate that is not finite; if `constraint_vertex` is not a vertex of
`tm`; if no face of `tm` gets a usable direction.  `r_map` and `s_map` are then untouched.
\sa `parametrize_orthogonal()`, `compute_geodesic_distance()`, `extract_iso_contours()`,
`alignment_angle_statistics()`
*/
template <class TriangleMesh, class FlowField, class RMap, class SMap,
          class NamedParameters = parameters::Default_named_parameters>
bool parametrize_tangential(const TriangleMesh& tm, const FlowField& field, RMap r_map, SMap s_map,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "parametrize_tangential";
  const bool normalize =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::normalized_t()), true);
  const internal::Progress_callback callback = internal::progress_callback(np);
  auto in = internal::make_parametrization_input(tm, field, np, caller);
  if (!internal::report_progress(callback, 1. / 3))
    return false;
  const internal::Positions a =
      internal::tangential_guidance(in.surface.faces, std::move(in.velocities), normalize);
  return internal::solve_parametrization<internal::Sparse_linear_solver_parameter<NamedParameters>>(
      in.surface, a, in.constrained, r_map, s_map, caller, callback);
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Computes the orthogonal parametrization \f$ (r, s) \f$ of `tm` in `field`, for a
surface orthogonal to the flow: eq. (7) with the guidance
\f$ a_j = P_j \left( (R(n_c, \alpha)\, r_c) \times v_j \right) \f$ and
\f$ b_j = a_j \times n_j \f$.

\f$ n_c \f$ is the unit normal at the constrained vertex \f$ v_c \f$ (the area-weighted mean
of its faces' normals), \f$ r_c \f$ the unit vector orthogonal to \f$ n_c \f$ given by the
second column of the Householder \f$ Q \f$ of \f$ n_c \f$ (the paper's QR null-space basis),
\f$ R(n_c, \alpha) \f$ the rotation about \f$ n_c \f$ by the user angle \f$ \alpha \f$
(counterclockwise seen from the side \f$ n_c \f$ points to).  To aim the parametrization
without this frame, give `gradient_direction` \f$ g \f$: then
\f$ r_c = \sigma\, n_c \times P_c g / \|P_c g\| \f$ (\f$ P_c = I - n_c n_c^T \f$,
\f$ \sigma = \pm 1 \f$ the sign of the flux through the faces around \f$ v_c \f$), for which
\f$ a_j = \|v_j\|\, P_c g / \|P_c g\| \f$ where \f$ v_j = \sigma \|v_j\| n_c \f$: with
\f$ \alpha = 0 \f$, \f$ \nabla r \f$ at the constrained vertex points along \f$ g \f$ projected
on the tangent plane, whichever way the flow crosses the surface, and \f$ \alpha \f$ turns it
from there.  Where
the surface is orthogonal to the flow, \f$ a_j \f$ lies in the surface and is orthogonal to the
turned direction, so the iso-contours of \f$ r \f$ run near-straight along
\f$ R(n_c, \alpha) r_c \f$; turning \f$ \alpha \f$ by \f$ \pi/2 \f$ on a plane turns
\f$ \nabla r \f$ by \f$ \pi/2 \f$ (\f$ r_{\alpha + \pi/2} = -s_\alpha \f$).  Every curve in an
orthogonal surface is orthogonal to the flow, so all iso-contours are seed curves.  As in the
paper the guidance is unnormalized by default (\f$ \|a_j\| \approx \|v_j\| \f$).  Each
connected component uses the normal at its own constrained vertex.  Unusable faces are treated
as in `parametrize_tangential()`.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam FlowField a model of `FlowField_3`
\tparam RMap, SMap models of `WritablePropertyMap` with the vertices as key type and a
floating-point value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param field the flow field
\param r_map receives \f$ r \f$
\param s_map receives \f$ s \f$
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{angle}
    \cgalParamDescription{`FAS::parameters::angle()`: \f$ \alpha \f$, radians}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{normalized}
    \cgalParamDescription{`FAS::parameters::normalized()`: whether \f$ a_j \f$ is normalized}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{gradient_direction}
    \cgalParamDescription{`FAS::parameters::gradient_direction()`: \f$ g \f$, the direction of
      \f$ \nabla r \f$ at the constrained vertex before the turn by \f$ \alpha \f$ (every
      connected component uses it at its own constrained vertex)}
    \cgalParamType{the kernel's `Vector_3`, finite, not zero, not normal to the surface at the
      constrained vertex}
    \cgalParamDefault{none: \f$ r_c \f$ is the Householder frame's}
  \cgalParamNEnd
  \cgalParamNBegin{constraint_vertex, vertex_point_map, geom_traits, vertex_index_map, face_index_map, callback, sparse_linear_solver}
    \cgalParamDescription{as in `parametrize_tangential()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true`, or `false` when the `callback` stopped the work (nothing written)
\throws std::invalid_argument if `angle` is not finite, if `gradient_direction` is not finite,
zero or normal to the surface at a constrained vertex, and in the cases of
`parametrize_tangential()`.  `r_map` and `s_map` are then untouched.
\sa `parametrize_tangential()`, `compute_geodesic_distance()`, `extract_iso_contours()`
*/
template <class TriangleMesh, class FlowField, class RMap, class SMap,
          class NamedParameters = parameters::Default_named_parameters>
bool parametrize_orthogonal(const TriangleMesh& tm, const FlowField& field, RMap r_map, SMap s_map,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "parametrize_orthogonal";
  const double alpha = internal::orthogonal_parametrization_angle(np, caller);
  const bool normalize =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::normalized_t()), false);
  const internal::Progress_callback callback = internal::progress_callback(np);
  auto in = internal::make_parametrization_input(tm, field, np, caller);
  if (!internal::report_progress(callback, 1. / 3))
    return false;
  const internal::Positions a = internal::orthogonal_guidance(
      in.surface.arrays, in.surface.faces, std::move(in.velocities), in.constrained, alpha, normalize,
      internal::orthogonal_gradient_direction(np, caller), caller);
  return internal::solve_parametrization<internal::Sparse_linear_solver_parameter<NamedParameters>>(
      in.surface, a, in.constrained, r_map, s_map, caller, callback);
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Computes the geodesic distance from `source` on `tm` by the heat method (Crane, Weischedel
and Wardetzky 2013), the paper's circular parametrization, by default on the intrinsic Delaunay
triangulation of `tm` as CGAL's `Heat_method_3` does by default.

Intrinsic Delaunay (the default, `intrinsic_delaunay(true)`): every edge of `tm` whose two
opposite angles sum to more than \f$ \pi \f$ is flipped within the surface (the two triangles
are unfolded into the plane and the other diagonal's length is measured there) until all edges
are Delaunay.  The surface and its metric are those of `tm`; only the triangles over which the
operators are built change, and they have no obtuse angle pair left.  On a mesh that is already
Delaunay nothing changes.  With `intrinsic_delaunay(false)` the operators are those of `tm`'s own
triangles (CGAL's `Direct` mode).

Three steps, with \f$ \mathbf{L} \f$ the cotangent Laplacian of the triangulation (positive
semi-definite; on `tm`'s own triangles the package's \f$ \mathbf{G}^T \mathbf{A} \mathbf{G} \f$)
and \f$ \mathbf{M} \f$ the diagonal of lumped vertex areas (a third of the area of each
triangle at the vertex):
1. heat: \f$ (\mathbf{M} + t \mathbf{L})\, h = h_0 \f$, \f$ h_0 \f$ one at the source and zero
   elsewhere, with \f$ t = 5 A_M / |T| \f$ (\f$ A_M \f$ the area of the source's component,
   \f$ |T| \f$ its number of faces).  This is the paper's \f$ (I - tL) h = h_0 \f$ written with
   the opposite sign convention of \f$ L \f$ and with the mass matrix as Crane et al. have it
   (the identity would make \f$ t \f$ depend on the mesh resolution); the scale of
   \f$ h_0 \f$ does not matter;
2. guidance: \f$ X_j = -\nabla h_j / \|\nabla h_j\| \f$ on each triangle (zero where the
   gradient vanishes);
3. distance: \f$ \mathbf{L} d = \mathbf{D} X \f$ (\f$ \mathbf{D} \f$ the integrated divergence),
   shifted so that \f$ d(\mathrm{source}) = 0 \f$.

The two systems have the same sparsity: one fill-reducing ordering serves both factorizations.

Accuracy (benchmark/Flow_aligned_surfaces/RESULTS.md, "Parametrization and geodesic distance",
sphere caps, mean relative error against
the great-circle distance): on a regular cap as CGAL's, in either mode (1.03 / 0.51 / 0.26 % at
2.4k / 9.6k / 38k faces, CGAL 1.03 / 0.51 / 0.26 %); on the same cap with the vertices jittered
by 0.3 of an edge, so that many triangles are not Delaunay, the default is 0.7 times CGAL's
default's error (0.72 % against 0.97 % at 9.6k faces) and 0.92 times the error of `tm`'s own
triangles.  The boundary condition is the natural (Neumann) one: distances are most accurate
when the boundary is far from the source or near a level set of the distance.  Vertices of other
connected components than the source's get \f$ +\infty \f$.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam DistanceMap a model of `WritablePropertyMap` with the vertices as key type and a
floating-point value type
\tparam NamedParameters a sequence of named parameters

\param tm a triangle mesh
\param source the vertex from which distances are measured
\param distance_map receives the distance of each vertex
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{intrinsic_delaunay}
    \cgalParamDescription{`FAS::parameters::intrinsic_delaunay()`: whether the heat method runs on
      the intrinsic Delaunay triangulation of `tm` (CGAL's `Intrinsic_Delaunay` mode) or on `tm`'s
      own triangles (CGAL's `Direct` mode)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
    \cgalParamDescription{as in `parametrize_tangential()`}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{CGAL's progress callback (`CGAL::parameters::callback()`), called with
      `0.5` after the heat step and `1` once `distance_map` is written; if the first call returns
      `false`, the function returns `false` and `distance_map` is untouched (see \ref fas_progress)}
    \cgalParamType{a callable convertible to `std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true`, or `false` when the `callback` stopped the work (nothing written)
\throws std::invalid_argument if `source` is not a vertex of `tm`, or `tm` is empty, not a
valid manifold triangle mesh, has a degenerate face or a coordinate that is not finite.
`distance_map` is then untouched.
\sa `extract_iso_contours()`, `parametrize_orthogonal()`
*/
template <class TriangleMesh, class DistanceMap, class NamedParameters = parameters::Default_named_parameters>
bool compute_geodesic_distance(const TriangleMesh& tm,
                               typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                               DistanceMap distance_map,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "compute_geodesic_distance";
  const bool intrinsic =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::intrinsic_delaunay_t()), true);
  const auto vpm = internal::checked_mesh_input(tm, np, caller + ": tm").vpm;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto vertices = internal::vertices_in_index_order(tm, vim);
  const Eigen::Index source_index = internal::vertex_index_or_throw(vertices, source, caller + ": source");
  const internal::Mesh_arrays arrays = internal::make_mesh_arrays(tm, vim, fim);
  const internal::Positions positions = internal::read_positions(vertices, vpm);
  internal::check_finite_positions(positions, caller + ": tm");
  std::vector<std::size_t> vertex_component(vertices.size(), 0);
  for (std::size_t j = 0; j < arrays.face_vertices.size(); ++j) {
    const auto& fv = arrays.face_vertices[j];
    const Eigen::Vector3d a = positions.row(fv[0]), b = positions.row(fv[1]), c = positions.row(fv[2]);
    if (!((b - a).cross(c - a).squaredNorm() > 0))
      throw std::invalid_argument(caller + ": tm: face " + std::to_string(j) + " is degenerate (zero area)");
    for (Eigen::Index v : fv)
      vertex_component[std::size_t(v)] = arrays.face_component[j];
  }
  internal::Intrinsic_triangulation triangulation =
      internal::make_intrinsic_triangulation(positions, arrays.face_vertices);
  if (intrinsic)
    internal::make_intrinsic_delaunay(triangulation);
  const std::optional<Eigen::VectorXd> d =
      internal::heat_method_distance(triangulation, positions.rows(), vertex_component, arrays.face_component,
                                     source_index, internal::progress_callback(np));
  if (!d)
    return false;
  internal::write_vertex_values(vertices, Eigen::MatrixXd(*d), 0, distance_map);
  return true;
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_PARAMETRIZE_H
