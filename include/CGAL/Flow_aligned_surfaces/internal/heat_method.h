// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The heat method (Crane, Weischedel and Wardetzky 2013) of the free compute_geodesic_distance()
// on a triangulation known by its edge lengths only, optionally made intrinsic Delaunay first
// (Bobenko and Springborn 2007; Fisher et al. 2007): every edge whose two opposite angles sum to
// more than pi is flipped inside the flattened pair of triangles, which keeps the surface's
// metric and changes only which geodesic segments serve as edges.  On the (possibly flipped)
// triangulation, with the cotangent Laplacian L (positive semi-definite, L = G^T A G), the lumped
// vertex areas M and t = 5 A_M / |T|:
//
//   (M + t L) h = h_0,   X_j = -grad h / |grad h| on face j,   L d = D X,   d(source) = 0,
//
// where (D X)_i = sum over the faces j of i of A_j grad(phi_i) . X_j = 1/2 (J e_i) . X_j (J the
// quarter turn in the face, e_i the face's edge opposite i).  Each face is laid out in its own 2D
// frame from its edge lengths, so the gradients need no positions.  Only L, M and the per-face
// 2D data are built: no 3n x m gradient matrix, no sparse product.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_HEAT_METHOD_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_HEAT_METHOD_H

#include <CGAL/Flow_aligned_surfaces/internal/Mesh_arrays.h>
#include <CGAL/Flow_aligned_surfaces/internal/solver/Sparse_cholesky.h>
#include <CGAL/Flow_aligned_surfaces/internal/progress_callback.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// A triangulation given by its faces and edge lengths.  Halfedge k of face f (id 3f + k) runs
/// from vertices[f][k] to vertices[f][(k + 1) % 3] and has length lengths[f][k]; twin[f][k] is
/// the id of the opposite halfedge, or -1 on the border (empty until `connect_twins()`).
struct Intrinsic_triangulation {
  std::vector<std::array<Eigen::Index, 3>> vertices;
  std::vector<std::array<double, 3>> lengths;
  std::vector<std::array<std::int64_t, 3>> twin;
  std::size_t number_of_flips = 0;
};

/// The triangulation of `face_vertices` with the Euclidean edge lengths of `positions`, without
/// its twins (`connect_twins()` adds them; only the flips need them).
inline Intrinsic_triangulation make_intrinsic_triangulation(const Positions& positions,
                                                            const std::vector<std::array<Eigen::Index, 3>>& face_vertices)
{
  Intrinsic_triangulation t;
  const std::size_t n = face_vertices.size();
  t.vertices = face_vertices;
  t.lengths.resize(n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k)
      t.lengths[f][k] = (positions.row(face_vertices[f][k]) - positions.row(face_vertices[f][(k + 1) % 3])).norm();
  return t;
}

/// Fills `t.twin` by sorting the halfedges on their (min, max) vertex: a manifold edge has two.
inline void connect_twins(Intrinsic_triangulation& t)
{
  const std::size_t n = t.vertices.size();
  t.twin.assign(n, {-1, -1, -1});
  std::vector<std::pair<std::pair<Eigen::Index, Eigen::Index>, std::int64_t>> keys(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index a = t.vertices[f][k], b = t.vertices[f][(k + 1) % 3];
      keys[3 * f + k] = {{(std::min)(a, b), (std::max)(a, b)}, std::int64_t(3 * f + k)};
    }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i + 1 < keys.size(); ++i)
    if (keys[i].first == keys[i + 1].first) {
      const std::int64_t h = keys[i].second, g = keys[i + 1].second;
      t.twin[std::size_t(h / 3)][std::size_t(h % 3)] = g;
      t.twin[std::size_t(g / 3)][std::size_t(g % 3)] = h;
      ++i;
    }
}

/// Twice the area of a triangle of side lengths a, b, c (Kahan's stable Heron formula); 0 when
/// the lengths violate the triangle inequality by rounding.
inline double twice_triangle_area(double a, double b, double c)
{
  if (a < b)
    std::swap(a, b);
  if (a < c)
    std::swap(a, c);
  if (b < c)
    std::swap(b, c);
  const double product = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return product > 0 ? 0.5 * std::sqrt(product) : 0.0;
}

/// The cotangent of the angle of face f opposite its halfedge k.
inline double opposite_cotangent(const Intrinsic_triangulation& t, std::size_t f, int k)
{
  const auto& l = t.lengths[f];
  const double a = l[k], b = l[(k + 1) % 3], c = l[(k + 2) % 3];
  const double twice_area = twice_triangle_area(a, b, c);
  return (b * b + c * c - a * a) / (2 * twice_area);
}

/// Flips edges until every interior edge is Delaunay (opposite angles summing to at most pi, up
/// to a relative 1e-12 on the cotangents).  Each non-Delaunay edge is flippable: its two
/// triangles form a convex quadrilateral.
inline void make_intrinsic_delaunay(Intrinsic_triangulation& t)
{
  if (t.twin.size() != t.vertices.size())
    connect_twins(t);
  std::vector<std::int64_t> stack;
  std::vector<char> queued(3 * t.vertices.size(), 0);
  for (std::size_t f = 0; f < t.vertices.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (t.twin[f][k] > std::int64_t(3 * f + k)) {
        stack.push_back(std::int64_t(3 * f + k));
        queued[3 * f + k] = 1;
      }
  const auto push = [&](std::int64_t h) {
    if (h < 0)
      return;
    const std::int64_t g = t.twin[std::size_t(h / 3)][std::size_t(h % 3)];
    if (g < 0 || queued[std::size_t(h)] || queued[std::size_t(g)])
      return;
    queued[std::size_t(h)] = 1;
    stack.push_back(h);
  };
  while (!stack.empty()) {
    const std::int64_t h = stack.back();
    stack.pop_back();
    queued[std::size_t(h)] = 0;
    const std::size_t f = std::size_t(h / 3);
    const int k = int(h % 3);
    const std::int64_t twin_h = t.twin[f][k];
    if (twin_h < 0)
      continue;
    const std::size_t g = std::size_t(twin_h / 3);
    const int kk = int(twin_h % 3);
    // A pair whose outer edges meet each other (a vertex of degree 1 or 2) is left as it is.
    const auto inside_pair = [&](std::int64_t o) { return o >= 0 && (std::size_t(o / 3) == f || std::size_t(o / 3) == g); };
    if (g == f || inside_pair(t.twin[f][(k + 1) % 3]) || inside_pair(t.twin[f][(k + 2) % 3]) ||
        inside_pair(t.twin[g][(kk + 1) % 3]) || inside_pair(t.twin[g][(kk + 2) % 3]))
      continue;
    const double cot_c = opposite_cotangent(t, f, k), cot_d = opposite_cotangent(t, g, kk);
    if (!(cot_c + cot_d < -1e-12 * (std::abs(cot_c) + std::abs(cot_d))))
      continue;
    // Face f = (a, b, c) with h = a -> b, face g = (b, a, d); after the flip f = (d, b, c) and
    // g = (c, a, d), sharing the new edge c - d.
    const Eigen::Index b = t.vertices[f][(k + 1) % 3], c = t.vertices[f][(k + 2) % 3];
    const Eigen::Index a = t.vertices[f][k], d = t.vertices[g][(kk + 2) % 3];
    const double l_ab = t.lengths[f][k], l_bc = t.lengths[f][(k + 1) % 3], l_ca = t.lengths[f][(k + 2) % 3];
    const double l_ad = t.lengths[g][(kk + 1) % 3], l_db = t.lengths[g][(kk + 2) % 3];
    const std::int64_t n_bc = t.twin[f][(k + 1) % 3], n_ca = t.twin[f][(k + 2) % 3];
    const std::int64_t n_ad = t.twin[g][(kk + 1) % 3], n_db = t.twin[g][(kk + 2) % 3];
    // The quadrilateral laid out with a = (0, 0), b = (l_ab, 0), c above and d below.
    const double x_c = (l_ab * l_ab + l_ca * l_ca - l_bc * l_bc) / (2 * l_ab);
    const double y_c = std::sqrt((std::max)(0.0, l_ca * l_ca - x_c * x_c));
    const double x_d = (l_ab * l_ab + l_ad * l_ad - l_db * l_db) / (2 * l_ab);
    const double y_d = -std::sqrt((std::max)(0.0, l_ad * l_ad - x_d * x_d));
    const double l_cd = std::hypot(x_c - x_d, y_c - y_d);
    t.vertices[f] = {d, b, c};
    t.lengths[f] = {l_db, l_bc, l_cd};
    t.twin[f] = {n_db, n_bc, std::int64_t(3 * g + 2)};
    t.vertices[g] = {c, a, d};
    t.lengths[g] = {l_ca, l_ad, l_cd};
    t.twin[g] = {n_ca, n_ad, std::int64_t(3 * f + 2)};
    for (std::size_t e : {f, g})
      for (int i = 0; i < 2; ++i) {
        const std::int64_t o = t.twin[e][i];
        if (o >= 0)
          t.twin[std::size_t(o / 3)][std::size_t(o % 3)] = std::int64_t(3 * e + i);
      }
    ++t.number_of_flips;
    for (std::int64_t outer : {std::int64_t(3 * f), std::int64_t(3 * f + 1), std::int64_t(3 * g),
                               std::int64_t(3 * g + 1)})
      push(outer);
  }
}

/// A face laid out in 2D: corner k at p[k], with p[0] = (0, 0) and p[1] on the x axis.
struct Flat_face {
  std::array<Eigen::Vector2d, 3> p;
  double area = 0;
};

inline Flat_face flatten(const std::array<double, 3>& l)
{
  Flat_face face;
  const double x = (l[0] * l[0] + l[2] * l[2] - l[1] * l[1]) / (2 * l[0]);
  face.p[0] = Eigen::Vector2d(0, 0);
  face.p[1] = Eigen::Vector2d(l[0], 0);
  face.p[2] = Eigen::Vector2d(x, std::sqrt((std::max)(0.0, l[2] * l[2] - x * x)));
  face.area = 0.5 * twice_triangle_area(l[0], l[1], l[2]);
  return face;
}

/// The solver of the heat method's two factorizations: Eigen's simplicial LDL^T with its AMD
/// ordering, on the lower triangle.  Measured against CHOLMOD's simplicial LDL^T (the package's
/// default solver) on the benchmark's sphere caps it is 5 to 20 % faster here, where each matrix
/// is factored once and solved once (CHOLMOD's interface copies and transposes the matrix; its
/// faster multi-column back-substitutions, which the deformation's iterations use, do not count).
using Heat_method_solver =
    CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>>;

/// The heat-method distance from `source` on `t` (vertex_component and face_component as in
/// Mesh_arrays; `number_of_vertices` vertices): +infinity on the other components.  Two
/// factorizations, M + tL and L + W (W = the mean diagonal of L at the source and at one vertex
/// of each other component), one solve each; only the lower triangles are assembled.  `callback`
/// hears 1/2 after the heat step and 1 at the end; nothing when it stops the work after the heat
/// step.
inline std::optional<Eigen::VectorXd> heat_method_distance(const Intrinsic_triangulation& t,
                                                           Eigen::Index number_of_vertices,
                                                           const std::vector<std::size_t>& vertex_component,
                                                           const std::vector<std::size_t>& face_component,
                                                           Eigen::Index source, const Progress_callback& callback)
{
  using Triplet = Eigen::Triplet<double>;
  const std::size_t n = t.vertices.size();
  const Eigen::Index m = number_of_vertices;
  const std::size_t component = vertex_component[std::size_t(source)];

  std::vector<Flat_face> flat(n);
  std::vector<Triplet> entries;
  entries.reserve(3 * n + std::size_t(m));
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(m), diagonal = Eigen::VectorXd::Zero(m);
  double area = 0;
  std::size_t faces_in_component = 0;
  for (std::size_t f = 0; f < n; ++f) {
    flat[f] = flatten(t.lengths[f]);
    const double twice_area = 2 * flat[f].area;
    const auto& v = t.vertices[f];
    for (int k = 0; k < 3; ++k) {
      // Edge k (v[k] -> v[k+1]) with the cotangent of the opposite angle at v[k+2].
      const Eigen::Vector2d e1 = flat[f].p[k] - flat[f].p[(k + 2) % 3];
      const Eigen::Vector2d e2 = flat[f].p[(k + 1) % 3] - flat[f].p[(k + 2) % 3];
      const double half_cot = 0.5 * e1.dot(e2) / twice_area;
      const Eigen::Index i = v[k], j = v[(k + 1) % 3];
      entries.emplace_back((std::max)(i, j), (std::min)(i, j), -half_cot);
      diagonal[i] += half_cot;
      diagonal[j] += half_cot;
      mass[v[k]] += flat[f].area / 3;
    }
    if (face_component[f] == component) {
      area += flat[f].area;
      ++faces_in_component;
    }
  }
  for (Eigen::Index i = 0; i < m; ++i)
    entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> L(m, m);
  L.setFromTriplets(entries.begin(), entries.end());

  // Heat step.  M + tL and L + W have the pattern of L: one symbolic analysis (the fill-reducing
  // ordering) serves both factorizations.
  const double time_step = 5 * area / double(faces_in_component);
  Eigen::SparseMatrix<double> heat = time_step * L;
  for (Eigen::Index i = 0; i < m; ++i)
    heat.coeffRef(i, i) += mass[i];
  Heat_method_solver solver;
  solver.solver().analyzePattern(heat);
  factor_pattern_or_throw(solver, heat, "M + t L");
  Eigen::VectorXd h0 = Eigen::VectorXd::Zero(m);
  h0[source] = 1;
  const Eigen::VectorXd h = solver.solver().solve(h0);
  if (!report_progress(callback, 0.5))
    return std::nullopt;

  // Normalized -grad h per face and its divergence D X.
  Eigen::VectorXd divergence = Eigen::VectorXd::Zero(m);
  for (std::size_t f = 0; f < n; ++f) {
    const auto& v = t.vertices[f];
    const Flat_face& face = flat[f];
    std::array<Eigen::Vector2d, 3> rotated_edge; // J e_k for the edge opposite corner k
    Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d e = face.p[(k + 2) % 3] - face.p[(k + 1) % 3];
      rotated_edge[k] = Eigen::Vector2d(-e.y(), e.x());
      gradient += h[v[k]] * rotated_edge[k];
    }
    const double length = gradient.norm();
    if (!(length > 0) || !std::isfinite(length))
      continue;
    const Eigen::Vector2d x = -gradient / length;
    for (int k = 0; k < 3; ++k)
      divergence[v[k]] += 0.5 * rotated_edge[k].dot(x);
  }

  // Poisson step, with a soft constraint at the source and at one vertex of each other
  // component (exact: D X sums to 0 over each component, and is 0 off the source's).
  Eigen::SparseMatrix<double> poisson = L;
  const double weight = L.diagonal().mean();
  std::vector<char> constrained(*std::max_element(vertex_component.begin(), vertex_component.end()) + 1, 0);
  constrained[component] = 1;
  poisson.coeffRef(source, source) += weight;
  for (Eigen::Index i = 0; i < m; ++i)
    if (!constrained[vertex_component[std::size_t(i)]]) {
      constrained[vertex_component[std::size_t(i)]] = 1;
      poisson.coeffRef(i, i) += weight;
    }
  factor_pattern_or_throw(solver, poisson, "L + W");
  Eigen::VectorXd d = solver.solver().solve(divergence);
  const double at_source = d[source];
  for (Eigen::Index i = 0; i < m; ++i)
    d[i] = vertex_component[std::size_t(i)] == component ? d[i] - at_source
                                                         : std::numeric_limits<double>::infinity();
  report_progress(callback, 1.);
  return d;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_HEAT_METHOD_H
