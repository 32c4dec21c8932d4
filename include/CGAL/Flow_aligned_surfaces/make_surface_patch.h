// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The procedural initial surfaces M_0 of the paper: a nearly regular triangulated
// rectangle or disk of any pose, added to a triangle mesh as a new connected component.
//
//   rectangle: (m + 1) rows of vertices, row spacing h = height/m, column spacing
//              s = width/n; even rows hold n + 1 vertices at x = k s, odd rows hold
//              x = 0, 3s/2, 5s/2, ..., width - 3s/2, width: shifted by s/2 inside, with
//              the half cells at the ends merged into their neighbours, so the rectangle
//              is exact and the end triangles keep angles of atan(h/s) ≈ 41° or more
//              (ending odd rows at s/2 would leave 30-60-90 half triangles).  A strip
//              between two rows has 2n - 1 triangles (2 when n = 1), the patch m times
//              that; (m, n) are chosen so that 2h/s is close to √3 (equilateral
//              triangles) and the face count is close to the target.
//   disk:      a center vertex and K concentric rings at radii k R / K holding about
//              c k vertices (c ≈ 6, the classic hexagonal disk); consecutive rings are
//              joined by the shorter-diagonal rule, so the patch has exactly
//              2 (N_1 + ... + N_{K-1}) + N_K faces, and N_K is chosen to hit the target.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_MAKE_SURFACE_PATCH_H
#define CGAL_FLOW_ALIGNED_SURFACES_MAKE_SURFACE_PATCH_H

#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \cond SKIP_IN_MANUAL
namespace internal {

using Patch_vec3 = std::array<double, 3>;

inline double patch_dot(const Patch_vec3& a, const Patch_vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Patch_vec3 patch_cross(const Patch_vec3& a, const Patch_vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

inline bool patch_is_finite(const Patch_vec3& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

[[noreturn]] inline void throw_patch_error(const char* function, const std::string& what)
{
  throw std::invalid_argument(std::string("CGAL::Flow_aligned_surfaces::") + function + "(): " + what);
}

inline void check_patch_size(const char* function, const char* name, double value)
{
  if (!(value > 0) || !std::isfinite(value)) {
    std::ostringstream os;
    os << "`" << name << "` must be positive and finite (got " << value << ")";
    throw_patch_error(function, os.str());
  }
}

inline void check_patch_target(const char* function, std::size_t target, std::size_t minimum)
{
  if (target < minimum) {
    std::ostringstream os;
    os << "`target_number_of_faces` must be at least " << minimum << " (got " << target << ")";
    throw_patch_error(function, os.str());
  }
}

// The orthonormal frame (u, v, n) of a patch: n the unit normal, u the unit width axis,
// v = n × u, so that counterclockwise triangles in (u, v) coordinates have normal n.
struct Patch_frame {
  Patch_vec3 origin, u, v, n;

  Patch_vec3 point(double x, double y) const
  {
    return {
        {origin[0] + x * u[0] + y * v[0], origin[1] + x * u[1] + y * v[1], origin[2] + x * u[2] + y * v[2]}};
  }
};

template <class Point_3, class Vector_3, class NamedParameters>
Patch_frame make_patch_frame(const char* function, const Point_3& center, const Vector_3& normal,
                             const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  Patch_frame f;
  f.origin = {{CGAL::to_double(center.x()), CGAL::to_double(center.y()), CGAL::to_double(center.z())}};
  if (!patch_is_finite(f.origin))
    throw_patch_error(function, "`center` has a coordinate that is not finite");

  const Patch_vec3 n = {
      {CGAL::to_double(normal.x()), CGAL::to_double(normal.y()), CGAL::to_double(normal.z())}};
  const double n_length = std::sqrt(patch_dot(n, n));
  if (!patch_is_finite(n) || !(n_length > 0) || !std::isfinite(n_length))
    throw_patch_error(function, "`normal` must be a non-zero vector with finite coordinates");
  f.n = {{n[0] / n_length, n[1] / n_length, n[2] / n_length}};

  // Default width axis: the coordinate axis least aligned with the normal (the first one
  // on ties), so that a normal along z gives a patch spanned by x (width) and y (height).
  Patch_vec3 a = {{0, 0, 0}};
  std::size_t least = 0;
  for (std::size_t i = 1; i < 3; ++i)
    if (std::abs(f.n[i]) < std::abs(f.n[least]))
      least = i;
  a[least] = 1;

  const bool has_axis = !parameters::is_default_parameter<NamedParameters, internal_np::patch_axis_t>::value;
  if (has_axis) {
    const Vector_3 axis =
        choose_parameter(get_parameter(np, internal_np::patch_axis_t()), Vector_3(CGAL::NULL_VECTOR));
    a = {{CGAL::to_double(axis.x()), CGAL::to_double(axis.y()), CGAL::to_double(axis.z())}};
  }
  const double a_length = std::sqrt(patch_dot(a, a));
  const double a_n = patch_dot(a, f.n);
  Patch_vec3 p = {{a[0] - a_n * f.n[0], a[1] - a_n * f.n[1], a[2] - a_n * f.n[2]}};
  const double p_length = std::sqrt(patch_dot(p, p));
  // An axis within ~1e-6 radians of the normal has no meaningful projection into the plane.
  if (!patch_is_finite(a) || !(p_length > 1e-6 * a_length) || !std::isfinite(p_length))
    throw_patch_error(function, "`patch_axis` must be a non-zero vector with finite coordinates that is not "
                                "parallel to `normal`");
  f.u = {{p[0] / p_length, p[1] / p_length, p[2] / p_length}};
  f.v = patch_cross(f.n, f.u);
  return f;
}

// A patch in the frame's (x, y) coordinates: vertices and counterclockwise triangles.
struct Patch_soup {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t anchor = 0; // the vertex whose incoming border halfedge is returned
};

// Triangulates the strip between two rows of vertices that span the same interval; each
// row is given by the indices of its vertices in the soup and by their abscissas in any
// units (exact integers here, so that ties are decided the same way on every platform).
// The shorter diagonal wins (the usual rule for strips; it keeps the triangles fat).
inline void triangulate_row_strip(const std::vector<std::size_t>& bottom,
                                  const std::vector<long long>& bottom_x, const std::vector<std::size_t>& top,
                                  const std::vector<long long>& top_x,
                                  std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::size_t i = 0, j = 0;
  const std::size_t ie = bottom.size() - 1, je = top.size() - 1;
  while (i < ie || j < je) {
    bool advance_bottom;
    if (i == ie)
      advance_bottom = false;
    else if (j == je)
      advance_bottom = true;
    else
      advance_bottom = std::abs(bottom_x[i + 1] - top_x[j]) <= std::abs(top_x[j + 1] - bottom_x[i]);
    if (advance_bottom) {
      triangles.push_back({{bottom[i], bottom[i + 1], top[j]}});
      ++i;
    }
    else {
      triangles.push_back({{bottom[i], top[j + 1], top[j]}});
      ++j;
    }
  }
}

// Number of faces of the lattice with m strips and n columns.
inline std::size_t planar_lattice_faces(std::size_t m, std::size_t n)
{
  return m * (n == 1 ? 2 : 2 * n - 1);
}

// Picks the number of strips m and of columns n.  Cost: relative face-count error plus a
// quarter of the log-deviation of the shape ratio 2h/s from √3 (a larger weight trades
// count for shape: 0.5 lets the count drift to the 10% limit for no visible gain in the
// smallest angle).  Candidates within 10% of the target whose shape keeps every angle at
// or above 30 degrees (1.16 ≤ 2h/s ≤ 3.4) are preferred, then any within 10%, then the
// closest count.  O(target) arithmetic, negligible beside building the mesh.
inline std::array<std::size_t, 2> choose_planar_lattice(double width, double height, std::size_t target)
{
  const double sqrt3 = std::sqrt(3.0);
  const double T = static_cast<double>(target);
  std::array<std::size_t, 2> best = {{1, 1}};
  int best_class = 3;
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t m = 1; 2 * m <= target + target / 5 + 2; ++m) {
    const double half = (T / static_cast<double>(m) + 1) / 2;
    const std::size_t n_lo = half < 2 ? std::size_t(2) : static_cast<std::size_t>(std::floor(half));
    const std::size_t candidates[3] = {1, n_lo, n_lo + 1};
    for (std::size_t n : candidates) {
      const double F = static_cast<double>(planar_lattice_faces(m, n));
      const double count_error = std::abs(F - T) / T;
      const double ratio = 2 * (height / static_cast<double>(m)) / (width / static_cast<double>(n));
      const double shape_error = std::abs(std::log(ratio / sqrt3));
      const int c = count_error > 0.1 ? 2 : (ratio < 1.16 || ratio > 3.4 ? 1 : 0);
      const double cost = c == 2 ? count_error : count_error + 0.25 * shape_error;
      if (c < best_class || (c == best_class && cost < best_cost)) {
        best_class = c;
        best_cost = cost;
        best = {{m, n}};
      }
    }
  }
  return best;
}

inline Patch_soup make_planar_patch_soup(double width, double height, std::size_t target)
{
  const std::array<std::size_t, 2> mn = choose_planar_lattice(width, height, target);
  const std::size_t m = mn[0], n = mn[1];

  // Abscissas in units of s/2: even rows 0, 2, ..., 2n; odd rows 0, 3, 5, ..., 2n-3, 2n.
  std::vector<long long> even_x, odd_x;
  for (std::size_t k = 0; k <= n; ++k)
    even_x.push_back(static_cast<long long>(2 * k));
  odd_x.push_back(0);
  for (std::size_t k = 1; k + 1 < n; ++k)
    odd_x.push_back(static_cast<long long>(2 * k + 1));
  odd_x.push_back(static_cast<long long>(2 * n));

  Patch_soup soup;
  soup.points.reserve((m / 2 + 1) * even_x.size() + (m / 2 + 1) * odd_x.size());
  soup.triangles.reserve(planar_lattice_faces(m, n));

  // Ends are set explicitly so that the sides of the rectangle are exact.
  auto coordinate = [](long long i, long long end, double length) {
    if (i == 0)
      return -length / 2;
    if (i == end)
      return length / 2;
    return -length / 2 + length * (static_cast<double>(i) / static_cast<double>(end));
  };

  std::vector<std::size_t> previous, current;
  for (std::size_t r = 0; r <= m; ++r) {
    const std::vector<long long>& xs = (r % 2 == 0) ? even_x : odd_x;
    const double y = coordinate(static_cast<long long>(r), static_cast<long long>(m), height);
    current.clear();
    for (long long x : xs) {
      current.push_back(soup.points.size());
      soup.points.push_back({{coordinate(x, static_cast<long long>(2 * n), width), y}});
    }
    if (r > 0)
      triangulate_row_strip(previous, (r % 2 == 1) ? even_x : odd_x, current, xs, soup.triangles);
    previous.swap(current);
  }
  soup.anchor = 0; // the corner center - width/2 u - height/2 v
  return soup;
}

// Number of vertices of each ring of the disk (outermost last) for a target face count.
inline std::vector<std::size_t> choose_disk_rings(std::size_t target)
{
  // c, the number of vertices of ring k divided by k; 6 is the hexagonal disk.
  const double c_ideal = 6;
  const double T = static_cast<double>(target);
  std::size_t K = static_cast<std::size_t>(std::floor(std::sqrt(T / c_ideal)));
  if (K < 1)
    K = 1;
  // Between K and K + 1 rings, keep the one whose ring density c = T / K² is closer to 6.
  auto deviation = [&](std::size_t k) {
    return std::abs(std::log(T / (static_cast<double>(k) * static_cast<double>(k)) / c_ideal));
  };
  if (deviation(K + 1) < deviation(K))
    ++K;
  // Ring k holds round(c k(k+1)/2) - round(c (k-1)k/2) vertices: rounding the partial sums
  // keeps every ring within one vertex of c k, so the outer ring, which closes the count
  // exactly, is within one vertex of c K as well.
  std::vector<std::size_t> rings;
  for (; K >= 1; --K) {
    const double c = T / (static_cast<double>(K) * static_cast<double>(K));
    rings.assign(K, 0);
    std::size_t previous_sum = 0;
    for (std::size_t k = 1; k < K; ++k) {
      const double kk = static_cast<double>(k);
      const std::size_t sum = static_cast<std::size_t>(std::llround(c * kk * (kk + 1) / 2));
      rings[k - 1] = sum - previous_sum;
      previous_sum = sum;
    }
    if (2 * previous_sum >= target)
      continue;
    rings[K - 1] = target - 2 * previous_sum;
    bool increasing = rings[0] >= 3;
    for (std::size_t k = 1; k < K; ++k)
      increasing = increasing && rings[k] > rings[k - 1];
    if (increasing)
      break;
  }
  return rings;
}

inline Patch_soup make_disk_patch_soup(double radius, std::size_t target)
{
  const double two_pi = 2 * std::acos(-1.0);
  Patch_soup soup;

  if (target == 2) { // the inscribed square split by a diagonal; too small for a center vertex
    soup.points = {{{radius, 0}}, {{0, radius}}, {{-radius, 0}}, {{0, -radius}}};
    soup.triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    soup.anchor = 0;
    return soup;
  }

  const std::vector<std::size_t> rings = choose_disk_rings(target);
  const std::size_t K = rings.size();
  std::size_t number_of_points = 1;
  for (std::size_t N : rings)
    number_of_points += N;
  soup.points.reserve(number_of_points);
  soup.triangles.reserve(target);

  soup.points.push_back({{0, 0}});
  std::vector<std::size_t> ring_start(K);
  for (std::size_t k = 0; k < K; ++k) {
    ring_start[k] = soup.points.size();
    const double r = (k + 1 == K) ? radius : radius * (static_cast<double>(k + 1) / static_cast<double>(K));
    const std::size_t N = rings[k];
    for (std::size_t i = 0; i < N; ++i) {
      const double t = two_pi * (static_cast<double>(i) / static_cast<double>(N));
      soup.points.push_back({{i == 0 ? r : r * std::cos(t), i == 0 ? 0. : r * std::sin(t)}});
    }
  }

  // The fan around the center.
  for (std::size_t i = 0; i < rings[0]; ++i)
    soup.triangles.push_back({{0, ring_start[0] + i, ring_start[0] + (i + 1) % rings[0]}});

  // Strips between consecutive rings; both rings have a vertex at angle 0, and the walk
  // starts from the radial edge between them and goes counterclockwise.
  auto squared_distance = [&](std::size_t a, std::size_t b) {
    const double dx = soup.points[a][0] - soup.points[b][0];
    const double dy = soup.points[a][1] - soup.points[b][1];
    return dx * dx + dy * dy;
  };
  for (std::size_t k = 1; k < K; ++k) {
    const std::size_t Na = rings[k - 1], Nb = rings[k];
    auto a = [&](std::size_t i) { return ring_start[k - 1] + i % Na; };
    auto b = [&](std::size_t j) { return ring_start[k] + j % Nb; };
    std::size_t i = 0, j = 0;
    while (i < Na || j < Nb) {
      bool advance_outer;
      if (i == Na)
        advance_outer = true;
      else if (j == Nb)
        advance_outer = false;
      else
        advance_outer = squared_distance(a(i), b(j + 1)) <= squared_distance(b(j), a(i + 1));
      if (advance_outer) {
        soup.triangles.push_back({{a(i), b(j), b(j + 1)}});
        ++j;
      }
      else {
        soup.triangles.push_back({{a(i), b(j), a(i + 1)}});
        ++i;
      }
    }
  }
  soup.anchor = ring_start[K - 1]; // the boundary vertex center + radius u
  return soup;
}

// Adds the soup to `tm` through the BGL face-graph API and returns the border halfedge
// whose target is the anchor vertex.
template <class TriangleMesh, class VertexPointMap, class GeomTraits>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
add_patch_soup(TriangleMesh& tm, VertexPointMap vpm, const GeomTraits& gt, const Patch_frame& frame,
               const Patch_soup& soup)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertices_size_type = typename boost::graph_traits<TriangleMesh>::vertices_size_type;
  using edges_size_type = typename boost::graph_traits<TriangleMesh>::edges_size_type;
  using faces_size_type = typename boost::graph_traits<TriangleMesh>::faces_size_type;
  using FT = typename GeomTraits::FT;

  // A disk-like patch has V - E + F = 1.
  const std::size_t nv = soup.points.size(), nf = soup.triangles.size(), ne = nv + nf - 1;
  reserve(tm, static_cast<vertices_size_type>(num_vertices(tm) + nv),
          static_cast<edges_size_type>(num_edges(tm) + ne), static_cast<faces_size_type>(num_faces(tm) + nf));

  const auto construct_point = gt.construct_point_3_object();
  std::vector<vertex_descriptor> vds(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    vds[i] = add_vertex(tm);
    const Patch_vec3 p = frame.point(soup.points[i][0], soup.points[i][1]);
    put(vpm, vds[i], construct_point(FT(p[0]), FT(p[1]), FT(p[2])));
  }
  std::array<vertex_descriptor, 3> face_vertices;
  for (const std::array<std::size_t, 3>& t : soup.triangles) {
    for (std::size_t i = 0; i < 3; ++i)
      face_vertices[i] = vds[t[i]];
    // Cannot fail on a fresh component built from a valid disk-like soup.
    const face_descriptor f = CGAL::Euler::add_face(face_vertices, tm);
    if (f == boost::graph_traits<TriangleMesh>::null_face())
      throw std::logic_error("CGAL::Flow_aligned_surfaces: adding a patch face failed");
  }

  for (halfedge_descriptor h : halfedges_around_target(vds[soup.anchor], tm))
    if (is_border(h, tm))
      return h;
  CGAL_assertion(false);
  return boost::graph_traits<TriangleMesh>::null_halfedge();
}

} // namespace internal
/// \endcond

/// \ingroup PkgFlowAlignedSurfacesRef
/// adds to `tm` a nearly regular triangulation of the rectangle of size `width` × `height`
/// centered at `center` in the plane orthogonal to `normal` (the paper's procedural `M_0`).
///
/// Let `n` be `normal` normalized, `u` the width axis (the named parameter `patch_axis`
/// projected into the plane and normalized) and `v = n × u`.  The rectangle is
/// `{center + x u + y v : |x| ≤ width/2, |y| ≤ height/2}`.  Its vertices lie on `m + 1` rows
/// spaced `h = height/m` apart; even rows hold `n_c + 1` vertices spaced `s = width/n_c`, odd
/// rows are shifted by `s/2` and keep a vertex at each end (their end cells are `3s/2` wide),
/// so the four sides are exact and no half-size sliver appears at the sides.  The
/// patch has `m (2 n_c - 1)` faces (`2 m` when `n_c = 1`); `m` and `n_c` are chosen so that
/// `2h/s` is close to `√3` (equilateral triangles) and the number of faces is close to
/// `target_number_of_faces`.
///
/// Number of faces: for `target_number_of_faces ≥ 50` it is within 10% of the target (within
/// 6% from 300 on, 2.5% from 1000 on, 0.8% from 10000 on); smaller targets are met as closely
/// as the lattice allows (2 gives the rectangle split by a diagonal).
///
/// Shape: every angle of every triangle is at least 30 degrees whenever the rectangle admits
/// such a lattice with a face count within 10% of the target, which holds for targets of 50 or
/// more when `1/10 ≤ width/height ≤ 10` and for targets of 300 or more when
/// `1/20 ≤ width/height ≤ 20` (measured over all such targets up to 20000); away from the
/// boundary columns the triangles are close to equilateral.
///
/// The patch is added as a new connected component: the faces and vertices already in `tm`
/// are left untouched, and the patch shares no vertex with them.  Every face is oriented so
/// that its normal is `n`.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` (for example `CGAL::Surface_mesh`,
///         `CGAL::Polyhedron_3`, an OpenMesh `TriMesh`)
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param tm the mesh the patch is added to; it may be empty
/// \param center the center of the rectangle
/// \param normal the normal of the patch; need not be unit
/// \param width the side length along the width axis `u`
/// \param height the side length along `v = n × u`
/// \param target_number_of_faces the number of triangles wanted
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
///                    `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for
///                     `CGAL::vertex_point_t` must be available in `TriangleMesh`.}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{patch_axis}
///     \cgalParamDescription{the direction of the width side, projected into the plane of the
///                           patch (`CGAL::Flow_aligned_surfaces::parameters::patch_axis()`)}
///     \cgalParamType{`GeomTraits::Vector_3`}
///     \cgalParamDefault{the coordinate axis least aligned with `normal` (the first one on ties),
///                       projected; for a normal along `z` the width is along `x` and the height
///                       along `y`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `normal` is a non-zero vector; `width` and `height` are positive and finite;
///      `target_number_of_faces ≥ 2`; `patch_axis`, if given, is not parallel to `normal`.
///      A violated precondition throws `std::invalid_argument` whose message names the
///      parameter, before `tm` is modified.
///
/// \returns the border halfedge of the new patch whose target is the corner
///          `center - width/2 u - height/2 v`; its patch face is `face(opposite(h, tm), tm)`.
///
/// \sa `make_disk_patch()`
/// \sa `Flow_aligned_deformation`
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
make_planar_patch(TriangleMesh& tm,
                  const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::Point_3& center,
                  const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::Vector_3& normal,
                  const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::FT& width,
                  const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::FT& height,
                  std::size_t target_number_of_faces,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;

  const char* function = "make_planar_patch";
  const double w = CGAL::to_double(width), h = CGAL::to_double(height);
  internal::check_patch_size(function, "width", w);
  internal::check_patch_size(function, "height", h);
  internal::check_patch_target(function, target_number_of_faces, 2);
  const internal::Patch_frame frame = internal::make_patch_frame(function, center, normal, np);

  GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  return internal::add_patch_soup(tm, vpm, gt, frame,
                                  internal::make_planar_patch_soup(w, h, target_number_of_faces));
}

/// \ingroup PkgFlowAlignedSurfacesRef
/// adds to `tm` a nearly regular triangulation of the disk of radius `radius` centered at
/// `center` in the plane orthogonal to `normal` (the paper's procedural `M_0`).
///
/// Let `n` be `normal` normalized, `u` the named parameter `patch_axis` projected into the
/// plane and normalized, and `v = n × u`.  The patch has a vertex at `center` and `K`
/// concentric rings of vertices at radii `k radius / K`, ring `k` holding `N_k ≈ c k`
/// vertices at equal angles starting on `u` (`c ≈ 6`: the classic hexagonal disk has
/// `N_k = 6k`).  Consecutive rings are joined by the shorter diagonal.  The boundary is the
/// outer ring, whose vertices lie exactly (up to rounding) on the circle; the patch covers
/// the inscribed polygon with `N_K` sides, of area `N_K/2 radius² sin(2π/N_K)`.
///
/// The patch has `2 (N_1 + ... + N_{K-1}) + N_K` faces and `N_K` is chosen so that this is
/// exactly `target_number_of_faces`.  (A target of 2 gives the inscribed square split by a
/// diagonal.)  Every ring holds within one vertex of `c k` vertices.  Every angle of every
/// triangle is at least 30 degrees (measured for every target from 2 to 20000, and about 43
/// degrees for large targets).
///
/// The patch is added as a new connected component: the faces and vertices already in `tm`
/// are left untouched, and the patch shares no vertex with them.  Every face is oriented so
/// that its normal is `n`.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` (for example `CGAL::Surface_mesh`,
///         `CGAL::Polyhedron_3`, an OpenMesh `TriMesh`)
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param tm the mesh the patch is added to; it may be empty
/// \param center the center of the disk
/// \param normal the normal of the patch; need not be unit
/// \param radius the radius of the circle through the boundary vertices
/// \param target_number_of_faces the number of triangles wanted
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `WritablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
///                    `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for
///                     `CGAL::vertex_point_t` must be available in `TriangleMesh`.}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{patch_axis}
///     \cgalParamDescription{the direction, projected into the plane of the patch, from `center`
///                           to the first vertex of every ring
///                           (`CGAL::Flow_aligned_surfaces::parameters::patch_axis()`)}
///     \cgalParamType{`GeomTraits::Vector_3`}
///     \cgalParamDefault{the coordinate axis least aligned with `normal` (the first one on ties),
///                       projected}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `normal` is a non-zero vector; `radius` is positive and finite;
///      `target_number_of_faces ≥ 2`; `patch_axis`, if given, is not parallel to `normal`.
///      A violated precondition throws `std::invalid_argument` whose message names the
///      parameter, before `tm` is modified.
///
/// \returns the border halfedge of the new patch whose target is the boundary vertex
///          `center + radius u`; its patch face is `face(opposite(h, tm), tm)`.
///
/// \sa `make_planar_patch()`
/// \sa `Flow_aligned_deformation`
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
make_disk_patch(TriangleMesh& tm,
                const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::Point_3& center,
                const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::Vector_3& normal,
                const typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::FT& radius,
                std::size_t target_number_of_faces,
                const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;

  const char* function = "make_disk_patch";
  const double r = CGAL::to_double(radius);
  internal::check_patch_size(function, "radius", r);
  internal::check_patch_target(function, target_number_of_faces, 2);
  const internal::Patch_frame frame = internal::make_patch_frame(function, center, normal, np);

  GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  return internal::add_patch_soup(tm, vpm, gt, frame,
                                  internal::make_disk_patch_soup(r, target_number_of_faces));
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_MAKE_SURFACE_PATCH_H
