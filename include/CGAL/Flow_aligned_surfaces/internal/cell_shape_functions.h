// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells of `Unstructured_flow_field_3`, tetrahedra, hexahedra, wedges and pyramids with
// VTK's point orders and parametric coordinates xi = (r, s, t): their shape functions N_i(xi)
// and derivatives, their faces, the reference cell (with the inside tolerance), and the
// inversion of the isoparametric map x(xi) = sum_i N_i(xi) X_i = p by Newton's method.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CELL_SHAPE_FUNCTIONS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CELL_SHAPE_FUNCTIONS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// The VTK cell types of the supported cells (the values of `Unstructured_flow_field_3::Cell_type`).
struct VTK_cell_type {
  enum : unsigned char { TETRA = 10, HEXAHEDRON = 12, WEDGE = 13, PYRAMID = 14 };
};

// Where a point lies in a cell: its parametric coordinates and the n shape function values
// there, the weights of the cell's points.
struct Cell_parametric_point {
  int n = 0;
  double N[8];
  double xi[3];
};

// Parametric tolerance of the inside test: dimensionless, far above the rounding of a Newton
// solution (~1e-15 for well-shaped cells) so that a point on a shared face is inside both
// cells, and far below any distance that matters for sampling a flow.
constexpr double cell_inside_tolerance = 1e-10;
// A point farther than this inside a cell's reference cell is in no other conforming cell.
constexpr double cell_interior_margin = 1e-9;

inline int number_of_cell_points(unsigned char t)
{
  switch (t) {
  case VTK_cell_type::TETRA:
    return 4;
  case VTK_cell_type::HEXAHEDRON:
    return 8;
  case VTK_cell_type::WEDGE:
    return 6;
  case VTK_cell_type::PYRAMID:
    return 5;
  default:
    return 0;
  }
}

inline const char* cell_type_name(unsigned char t)
{
  switch (t) {
  case VTK_cell_type::TETRA:
    return "tetrahedron";
  case VTK_cell_type::HEXAHEDRON:
    return "hexahedron";
  case VTK_cell_type::WEDGE:
    return "wedge";
  case VTK_cell_type::PYRAMID:
    return "pyramid";
  default:
    return "unsupported";
  }
}

inline int number_of_cell_faces(unsigned char t)
{
  return t == VTK_cell_type::TETRA ? 4 : t == VTK_cell_type::HEXAHEDRON ? 6 : 5;
}

// The local point indices of face f of a cell of type t (VTK's numbering), a triangle padded
// with -1 at the end.  Hexahedron: faces r = 0, r = 1, s = 0, s = 1, t = 0, t = 1; tetrahedron:
// s = 0, r + s + t = 1, r = 0, t = 0; wedge: t = 0, t = 1, s = 0, r + s = 1, r = 0; pyramid:
// t = 0, s = 0, r = 1, s = 1, r = 0 (see `cell_exit_face()`).
inline const std::array<int, 4>& cell_face_points(unsigned char t, int f)
{
  static const std::array<int, 4> tet[4] = {{0, 1, 3, -1}, {1, 2, 3, -1}, {2, 0, 3, -1}, {0, 2, 1, -1}};
  static const std::array<int, 4> hex[6] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                            {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const std::array<int, 4> wedge[5] = {
      {0, 1, 2, -1}, {3, 5, 4, -1}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  static const std::array<int, 4> pyramid[5] = {
      {0, 3, 2, 1}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};
  return (t == VTK_cell_type::TETRA        ? tet
          : t == VTK_cell_type::HEXAHEDRON ? hex
          : t == VTK_cell_type::WEDGE      ? wedge
                                           : pyramid)[f];
}

// The face of a cell of type t through which the parametric point xi (outside the reference
// cell) leaves it the most: the face whose defining inequality xi violates by the largest
// amount, or -1 if it violates none.
inline int cell_exit_face(unsigned char t, const double* xi)
{
  const double r = xi[0], s = xi[1], u = xi[2];
  double violation[6];
  int n = 0;
  switch (t) {
  case VTK_cell_type::TETRA:
    n = 4, violation[0] = -s, violation[1] = r + s + u - 1., violation[2] = -r, violation[3] = -u;
    break;
  case VTK_cell_type::HEXAHEDRON:
    n = 6, violation[0] = -r, violation[1] = r - 1., violation[2] = -s, violation[3] = s - 1.,
    violation[4] = -u, violation[5] = u - 1.;
    break;
  case VTK_cell_type::WEDGE:
    n = 5, violation[0] = -u, violation[1] = u - 1., violation[2] = -s, violation[3] = r + s - 1.,
    violation[4] = -r;
    break;
  default: // VTK_cell_type::PYRAMID; above the apex (t > 1) there is no face
    n = 5, violation[0] = -u, violation[1] = -s, violation[2] = r - 1., violation[3] = s - 1.,
    violation[4] = -r;
  }
  int best = -1;
  double largest = cell_inside_tolerance;
  for (int f = 0; f < n; ++f)
    if (violation[f] > largest) // false for NaN
      largest = violation[f], best = f;
  return best;
}

// Shape functions N and their derivatives dN/d(r, s, t) at xi, in VTK's conventions.
inline int cell_shape_functions(unsigned char type, const double* xi, double* N, double (*dN)[3])
{
  const double r = xi[0], s = xi[1], t = xi[2];
  switch (type) {
  case VTK_cell_type::TETRA: {
    const double n[4] = {1. - r - s - t, r, s, t};
    const double d[4][3] = {{-1., -1., -1.}, {1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}};
    for (int i = 0; i < 4; ++i) {
      N[i] = n[i];
      for (int a = 0; a < 3; ++a)
        dN[i][a] = d[i][a];
    }
    return 4;
  }
  case VTK_cell_type::HEXAHEDRON: {
    // Corner i has parameters (r_i, s_i, t_i) with VTK's ordering.
    static const int rc[8] = {0, 1, 1, 0, 0, 1, 1, 0}, sc[8] = {0, 0, 1, 1, 0, 0, 1, 1},
                     tc[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i) {
      const double fr = rc[i] ? r : 1. - r, fs = sc[i] ? s : 1. - s, ft = tc[i] ? t : 1. - t;
      const double gr = rc[i] ? 1. : -1., gs = sc[i] ? 1. : -1., gt = tc[i] ? 1. : -1.;
      N[i] = fr * fs * ft;
      dN[i][0] = gr * fs * ft;
      dN[i][1] = fr * gs * ft;
      dN[i][2] = fr * fs * gt;
    }
    return 8;
  }
  case VTK_cell_type::WEDGE: {
    const double l[3] = {1. - r - s, r, s};
    const double dl[3][2] = {{-1., -1.}, {1., 0.}, {0., 1.}};
    for (int i = 0; i < 3; ++i) {
      N[i] = l[i] * (1. - t);
      N[i + 3] = l[i] * t;
      dN[i][0] = dl[i][0] * (1. - t);
      dN[i][1] = dl[i][1] * (1. - t);
      dN[i][2] = -l[i];
      dN[i + 3][0] = dl[i][0] * t;
      dN[i + 3][1] = dl[i][1] * t;
      dN[i + 3][2] = l[i];
    }
    return 6;
  }
  default: { // VTK_cell_type::PYRAMID, VTK's vtkPyramid::InterpolationFunctions
    const double rm = 1. - r, sm = 1. - s, tm = 1. - t;
    N[0] = rm * sm * tm;
    N[1] = r * sm * tm;
    N[2] = r * s * tm;
    N[3] = rm * s * tm;
    N[4] = t;
    const double d[5][3] = {{-sm * tm, -rm * tm, -rm * sm},
                            {sm * tm, -r * tm, -r * sm},
                            {s * tm, r * tm, -r * s},
                            {-s * tm, rm * tm, -rm * s},
                            {0., 0., 1.}};
    for (int i = 0; i < 5; ++i)
      for (int a = 0; a < 3; ++a)
        dN[i][a] = d[i][a];
    return 5;
  }
  }
}

// Whether xi is in the reference cell of `type` grown by `e` on every side (shrunk for e < 0).
inline bool in_reference_cell(unsigned char type, const double* xi, double e = cell_inside_tolerance)
{
  const double r = xi[0], s = xi[1], t = xi[2];
  const bool t_ok = t >= -e && t <= 1. + e;
  switch (type) {
  case VTK_cell_type::TETRA:
    return r >= -e && s >= -e && t >= -e && r + s + t <= 1. + e;
  case VTK_cell_type::WEDGE:
    return r >= -e && s >= -e && r + s <= 1. + e && t_ok;
  default:
    return r >= -e && r <= 1. + e && s >= -e && s <= 1. + e && t_ok;
  }
}

// The largest coordinate difference between a cell's points and its first one: the scale of the
// residual test of `invert_cell_map()`.
inline double cell_extent(const double (*X)[3], int n)
{
  double size = 0.;
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      size = (std::max)(size, std::abs(X[i][a] - X[0][a]));
  return size;
}

// Where Newton's method starts: the cell's parametric centre, always, so that a point's
// inversion in a cell gives the same bits whatever was inverted before.
inline void newton_start(unsigned char type, double (&xi)[3])
{
  switch (type) {
  case VTK_cell_type::TETRA:
    xi[0] = xi[1] = xi[2] = 0.25;
    break;
  case VTK_cell_type::WEDGE:
    xi[0] = xi[1] = 1. / 3.;
    xi[2] = 0.5;
    break;
  case VTK_cell_type::PYRAMID:
    xi[0] = xi[1] = 0.5;
    xi[2] = 0.25;
    break;
  default:
    xi[0] = xi[1] = xi[2] = 0.5;
  }
}

// The determinant of a 3 x 3 matrix, expanded along its first row.
inline double determinant_3(const double (&M)[3][3])
{
  return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
         M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
         M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
}

// The solution d of J d = res by Cramer's rule, `det` being the determinant of J.
inline void solve_by_cramer(const double (&J)[3][3], const double (&res)[3], double det, double (&d)[3])
{
  for (int b = 0; b < 3; ++b) {
    double M[3][3];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        M[a][c] = c == b ? res[a] : J[a][c];
    d[b] = determinant_3(M) / det;
  }
}

// Newton's step d with the Jacobian J and the residual res (J d = res); false where J is
// singular or not finite.
inline bool newton_step_from(const double (&J)[3][3], const double (&res)[3], double (&d)[3])
{
  const double det = determinant_3(J);
  if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
    return false;
  solve_by_cramer(J, res, det, d);
  return true;
}

// Newton's step d from xi toward x(xi) = p for the cell of type `type` with points X; false
// where the Jacobian is singular or not finite.
inline bool newton_step(unsigned char type, const double (*X)[3], int n, const double* p,
                        const double (&xi)[3], double (&d)[3])
{
  double N[8], dN[8][3];
  cell_shape_functions(type, xi, N, dN);
  double res[3] = {p[0], p[1], p[2]};
  double J[3][3] = {{0., 0., 0.}, {0., 0., 0.}, {0., 0., 0.}};
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      res[a] -= N[i] * X[i][a];
      for (int b = 0; b < 3; ++b)
        J[a][b] += X[i][a] * dN[i][b];
    }
  return newton_step_from(J, res, d);
}

// A hexahedron's trilinear map as a polynomial in (r, s, t), VTK's corner order:
// x = c0 + c1 r + c2 s + c3 t + c4 rs + c5 rt + c6 st + c7 rst.  A Newton step from these
// coefficients takes half the arithmetic of one from the eight shape functions and their
// derivatives, and gives the same step up to rounding.
class Hexahedron_map {
public:
  explicit Hexahedron_map(const double (*X)[3])
  {
    for (int a = 0; a < 3; ++a) {
      m_c[0][a] = X[0][a];
      m_c[1][a] = X[1][a] - X[0][a];
      m_c[2][a] = X[3][a] - X[0][a];
      m_c[3][a] = X[4][a] - X[0][a];
      m_c[4][a] = (X[0][a] - X[1][a]) + (X[2][a] - X[3][a]);
      m_c[5][a] = (X[0][a] - X[1][a]) + (X[5][a] - X[4][a]);
      m_c[6][a] = (X[0][a] - X[3][a]) + (X[7][a] - X[4][a]);
      m_c[7][a] = ((X[1][a] - X[0][a]) + (X[3][a] - X[2][a])) + ((X[4][a] - X[5][a]) + (X[6][a] - X[7][a]));
    }
  }

  // Whether the map is affine (a parallelepiped) up to rounding: every bilinear and trilinear
  // coefficient at most 1e-14 times the largest linear one.  One Newton step then solves it, as
  // for a tetrahedron (its error, about that ratio times the squared parametric distance from
  // the start, is at rounding level too).  Most cells of a block-structured mesh are boxes.
  bool is_affine() const
  {
    double linear = 0., nonlinear = 0.;
    for (int a = 0; a < 3; ++a) {
      for (int k = 1; k < 4; ++k)
        linear = (std::max)(linear, std::abs(m_c[k][a]));
      for (int k = 4; k < 8; ++k)
        nonlinear = (std::max)(nonlinear, std::abs(m_c[k][a]));
    }
    return nonlinear <= 1e-14 * linear;
  }

  // Newton's step d from xi toward x(xi) = p, as `newton_step()`.
  bool newton_step(const double* p, const double (&xi)[3], double (&d)[3]) const
  {
    const double r = xi[0], s = xi[1], t = xi[2];
    double res[3], J[3][3];
    for (int a = 0; a < 3; ++a) {
      const double c1 = m_c[1][a], c2 = m_c[2][a], c3 = m_c[3][a], c4 = m_c[4][a], c5 = m_c[5][a],
                   c6 = m_c[6][a], c7 = m_c[7][a];
      res[a] = p[a] -
               (m_c[0][a] + c1 * r + c2 * s + c3 * t + c4 * r * s + c5 * r * t + c6 * s * t + c7 * r * s * t);
      J[a][0] = c1 + c4 * s + c5 * t + c7 * s * t;
      J[a][1] = c2 + c4 * r + c6 * t + c7 * r * t;
      J[a][2] = c3 + c5 * r + c6 * s + c7 * r * s;
    }
    return newton_step_from(J, res, d);
  }

private:
  double m_c[8][3];
};

// How Newton's iteration of `invert_cell_map()` ended: at a step small enough, stopped without
// that (diverging, a singular Jacobian, or out of iterations), or far from the reference cell.
enum class Newton_outcome { CONVERGED, STOPPED, FAR_OUTSIDE };

inline Newton_outcome newton_iterations(unsigned char type, const double (*X)[3], int n, const double* p,
                                        double (&xi)[3])
{
  // Affine maps (tetrahedra, parallelepipeds) are solved by one step; the trilinear map in a few
  // for reasonable cells.  The cap bounds the cost of points that are far outside a cell (in
  // its bounding box only).
  std::optional<Hexahedron_map> hexahedron;
  if (type == VTK_cell_type::HEXAHEDRON)
    hexahedron.emplace(X);
  const bool affine = type == VTK_cell_type::TETRA || (hexahedron && hexahedron->is_affine());
  const int max_iterations = affine ? 1 : 12;
  for (int it = 0; it < max_iterations; ++it) {
    double d[3];
    if (!(hexahedron ? hexahedron->newton_step(p, xi, d) : newton_step(type, X, n, p, xi, d)))
      return Newton_outcome::STOPPED;
    double step = 0.;
    for (int a = 0; a < 3; ++a) {
      xi[a] += d[a];
      step = (std::max)(step, std::abs(d[a]));
    }
    if (!(step < 1e3)) // diverging: far outside the cell
      return Newton_outcome::STOPPED;
    // Newton's error after a step of size h is about C h^2 (C: the map's second derivatives
    // over its first, O(1) in parametric units for usable cells), so after a step below 1e-8
    // xi is as accurate as rounding allows, without one more step to see it.
    if (step < 1e-8 || affine)
      return Newton_outcome::CONVERGED;
    if (it >= 3) {
      // Far from the reference cell after a few steps: p is not in this cell.
      bool far = false;
      for (int a = 0; a < 3; ++a)
        far = far || xi[a] < -0.5 || xi[a] > 1.5;
      if (far)
        return Newton_outcome::FAR_OUTSIDE;
    }
  }
  return Newton_outcome::STOPPED;
}

// Whether x(xi) is p up to rounding, relative to the cell's extent `size`: the step criterion can
// miss a solution near the pyramid's apex, where the map is singular.
inline bool residual_at_rounding_level(unsigned char type, const double (*X)[3], int n, const double* p,
                                       const double (&xi)[3], double size)
{
  double N[8], dN[8][3];
  cell_shape_functions(type, xi, N, dN);
  double err = 0.;
  for (int a = 0; a < 3; ++a) {
    double x = 0.;
    for (int i = 0; i < n; ++i)
      x += N[i] * X[i][a];
    err = (std::max)(err, std::abs(x - p[a]));
  }
  return err <= 1e-12 * size;
}

// Inverts the map x(xi) = p of the cell of type `type` with points X by Newton's method from
// the cell's parametric center.  Returns whether
// it converged and xi is in the reference cell, with the shape function values and xi in hit;
// else, if `estimate` is not null, stores there the last iterate (exact where the iteration
// converged outside the reference cell, NaN or huge where it diverged), for the walk.
inline bool invert_cell_map(unsigned char type, const double (*X)[3], int n, const double* p,
                            Cell_parametric_point& hit, double* estimate = nullptr)
{
  const double size = cell_extent(X, n);
  double xi[3];
  newton_start(type, xi);
  auto reject = [&] {
    if (estimate != nullptr)
      for (int a = 0; a < 3; ++a)
        estimate[a] = xi[a];
    return false;
  };
  const Newton_outcome outcome = newton_iterations(type, X, n, p, xi);
  if (outcome == Newton_outcome::FAR_OUTSIDE ||
      (outcome == Newton_outcome::STOPPED && !residual_at_rounding_level(type, X, n, p, xi, size)))
    return reject();
  if (type == VTK_cell_type::PYRAMID && xi[2] >= 1. - 1e-8) {
    // At the apex r and s are undetermined and irrelevant.
    xi[0] = (std::min)((std::max)(xi[0], 0.), 1.);
    xi[1] = (std::min)((std::max)(xi[1], 0.), 1.);
  }
  if (!in_reference_cell(type, xi))
    return reject();
  double dN[8][3];
  hit.n = cell_shape_functions(type, xi, hit.N, dN);
  for (int a = 0; a < 3; ++a)
    hit.xi[a] = xi[a];
  return true;
}

// The n points of a cell with point indices v, as doubles: X[i] = point i of the cell.
template <typename T>
void gather_cell_points(const std::vector<T>& points, const std::int32_t* v, int n, double (*X)[3])
{
  for (int i = 0; i < n; ++i) {
    const T* x = points.data() + 3 * static_cast<std::size_t>(v[i]);
    X[i][0] = static_cast<double>(x[0]);
    X[i][1] = static_cast<double>(x[1]);
    X[i][2] = static_cast<double>(x[2]);
  }
}

// The bounding box of the n points X, enlarged by the inside tolerance (relative to the cell
// size), so that the box never rejects a point the exact test accepts.
inline void cell_points_box(const double (*X)[3], int n, double* b)
{
  for (int a = 0; a < 3; ++a) {
    double lo = X[0][a], hi = X[0][a];
    for (int i = 1; i < n; ++i) {
      lo = (std::min)(lo, X[i][a]);
      hi = (std::max)(hi, X[i][a]);
    }
    const double pad = 1e-8 * (hi - lo) + 1e-300;
    b[a] = lo - pad;
    b[a + 3] = hi + pad;
  }
}

inline bool in_cell_box(const double* b, const double* x)
{
  return x[0] >= b[0] && x[0] <= b[3] && x[1] >= b[1] && x[1] <= b[4] && x[2] >= b[2] && x[2] <= b[5];
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_CELL_SHAPE_FUNCTIONS_H
