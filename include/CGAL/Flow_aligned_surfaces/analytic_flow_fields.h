// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Analytic steady flows, models of `FlowField_3`, together with what is known about them in
// closed form (potentials, stream functions, first integrals), so that tests and examples can
// compare computed stream surfaces and orthogonal surfaces against exact ones.
//
// All evaluations are carried out in `double` (the flows involve sin, exp, sqrt): `FT` must be
// convertible with `CGAL::to_double()` and constructible from `double`.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_ANALYTIC_FLOW_FIELDS_H
#define CGAL_FLOW_ALIGNED_SURFACES_ANALYTIC_FLOW_FIELDS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/assertions.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// Points computed on an obstacle's wall in floating point (R (cos t, sin t), R n / |n|) land a few
// ulps on either side of it; the exterior formulas are smooth there, so such points still get
// the wall velocity instead of `std::nullopt`.
constexpr double relative_wall_tolerance = 1e-12;

template <typename Point_3>
std::array<double, 3> to_double_coordinates(const Point_3& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <typename Vector_3>
Vector_3 make_vector(double x, double y, double z)
{
  using FT = typename CGAL::Kernel_traits<Vector_3>::Kernel::FT;
  return Vector_3(FT(x), FT(y), FT(z));
}

// Potential flow around a sphere of radius `R` centered at the origin with free stream `U` along
// +z.  It is both `Sphere_potential_flow` and the exterior of `Hill_spherical_vortex`, so one
// formula serves both.
inline std::array<double, 3> sphere_potential_flow_velocity(double x, double y, double z, double R, double U)
{
  const double r2 = x * x + y * y + z * z;
  const double r = std::sqrt(r2);
  const double R3_over_r3 = (R / r) * (R / r) * (R / r);
  const double R3_over_r5 = R3_over_r3 / r2;
  const double k = -1.5 * U * R3_over_r5 * z;
  return {k * x, k * y, U * (1. - R3_over_r3) + 1.5 * U * R3_over_r5 * (x * x + y * y)};
}

inline double sphere_potential_flow_stokes_stream_function(double x, double y, double z, double R, double U)
{
  const double r = std::sqrt(x * x + y * y + z * z);
  const double R_over_r = R / r;
  return 0.5 * U * (x * x + y * y) * (1. - R_over_r * R_over_r * R_over_r);
}

} // namespace internal

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The uniform flow \f$ v(x) = u \f$.
///
/// Domain: \f$ \mathbb{R}^3 \f$.  Potential: \f$ \varphi(x) = u \cdot x \f$ (`potential()`).
/// Stream surfaces: every plane containing the direction \f$ u \f$ (and every cylinder whose
/// rulings are parallel to \f$ u \f$).  Orthogonal surfaces: the planes \f$ u \cdot x = c \f$.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Uniform_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param u the constant velocity
  explicit Uniform_flow(const Vector_3& u = Vector_3(FT(1), FT(0), FT(0))) : m_u(u) {}

  /// returns \f$ u \f$.
  std::optional<Vector_3> operator()(const Point_3&) const { return m_u; }

  /// returns the potential \f$ \varphi(p) = u \cdot (p - O) \f$.
  FT potential(const Point_3& p) const { return m_u * (p - CGAL::ORIGIN); }

  /// returns \f$ u \f$.
  const Vector_3& velocity() const { return m_u; }

private:
  Vector_3 m_u;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The linear flow \f$ v(x) = A x \f$ for a constant \f$ 3 \times 3 \f$ matrix \f$ A \f$.
///
/// Domain: \f$ \mathbb{R}^3 \f$.  Divergence: \f$ \operatorname{tr} A \f$ (`divergence()`).
/// If \f$ A = A^T \f$ (`has_potential()`), the flow is the gradient of the potential
/// \f$ \varphi(x) = \frac{1}{2} x^T A x \f$ (`potential()`), and its orthogonal surfaces are the
/// quadrics \f$ x^T A x = c \f$.
///
/// The default matrix is the harmonic saddle \f$ A = \operatorname{diag}(1, 1, -2) \f$
/// (divergence-free and a gradient): its streamlines are
/// \f$ (x_0 e^t, y_0 e^t, z_0 e^{-2t}) \f$, its first integrals are \f$ y / x \f$ and
/// \f$ (x^2 + y^2) z \f$, so its stream surfaces are the half-planes bounded by the \f$ z \f$-axis
/// and the surfaces of revolution \f$ (x^2 + y^2) z = c \f$; its orthogonal surfaces are the
/// quadrics \f$ x^2 + y^2 - 2 z^2 = c \f$.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Linear_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;
  /// Row-major: `matrix()[i][j]` is \f$ A_{ij} \f$.
  using Matrix = std::array<std::array<FT, 3>, 3>;

  /// builds the harmonic saddle \f$ A = \operatorname{diag}(1, 1, -2) \f$.
  Linear_flow() : Linear_flow(1, 0, 0, 0, 1, 0, 0, 0, -2) {}

  /// \param a the matrix \f$ A \f$, row-major
  explicit Linear_flow(const Matrix& a) : m_a(a) {}

  /// builds \f$ A \f$ from its nine entries, row by row.
  Linear_flow(const FT& a00, const FT& a01, const FT& a02, const FT& a10, const FT& a11, const FT& a12,
              const FT& a20, const FT& a21, const FT& a22)
      : m_a{{{a00, a01, a02}, {a10, a11, a12}, {a20, a21, a22}}}
  {
  }

  /// returns \f$ A (p - O) \f$.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const FT x[3] = {p.x(), p.y(), p.z()};
    FT v[3];
    for (int i = 0; i < 3; ++i)
      v[i] = m_a[i][0] * x[0] + m_a[i][1] * x[1] + m_a[i][2] * x[2];
    return Vector_3(v[0], v[1], v[2]);
  }

  /// returns the matrix \f$ A \f$.
  const Matrix& matrix() const { return m_a; }

  /// returns whether \f$ A \f$ is exactly symmetric, that is, whether the flow has a potential.
  bool has_potential() const
  {
    return m_a[0][1] == m_a[1][0] && m_a[0][2] == m_a[2][0] && m_a[1][2] == m_a[2][1];
  }

  /// returns \f$ \varphi(p) = \frac{1}{2} x^T A x \f$ with \f$ x = p - O \f$.
  /// \pre `has_potential()`
  FT potential(const Point_3& p) const
  {
    CGAL_precondition(has_potential());
    const FT x[3] = {p.x(), p.y(), p.z()};
    FT s(0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        s += x[i] * m_a[i][j] * x[j];
    return s / FT(2);
  }

  /// returns \f$ \operatorname{tr} A \f$, the (constant) divergence of the flow.
  FT divergence() const { return m_a[0][0] + m_a[1][1] + m_a[2][2]; }

private:
  Matrix m_a;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The helical flow \f$ v(x, y, z) = (-y, x, c) \f$: a rigid rotation about the \f$ z \f$-axis
/// with unit angular speed combined with a uniform axial speed \f$ c \f$.  Given a point \f$ a \f$
/// of the axis, the flow is translated by \f$ a \f$: \f$ v(p) = (-(y - a_y), x - a_x, c) \f$, and
/// every formula below holds for \f$ p - a \f$ (a time series of such flows with a moving axis is a
/// swirl that drifts: `follow_unsteady_flow.cpp`).
///
/// Domain: \f$ \mathbb{R}^3 \f$.  Divergence-free; no potential
/// (\f$ \nabla \times v = (0, 0, 2) \f$).  The streamlines are the helices
/// \f$ (\rho \cos(\theta_0 + t), \rho \sin(\theta_0 + t), z_0 + c t) \f$.
///
/// First integrals (\f$ \nabla I \cdot v = 0 \f$):
/// - \f$ I_1 = x^2 + y^2 \f$ (`first_integral_radius()`): the stream surfaces
///   \f$ I_1 = R^2 \f$ are the cylinders about the \f$ z \f$-axis;
/// - for \f$ c \neq 0 \f$, \f$ z - c\,\theta \f$ is constant along streamlines but multivalued; its
///   single-valued form is
///   \f$ I_2 = y \cos(z / c) - x \sin(z / c) = \rho \sin(\theta - z / c) \f$
///   (`first_integral_helicoid()`).  The stream surface \f$ I_2 = 0 \f$ is the helicoid
///   \f$ \theta = z / c \pmod \pi \f$; \f$ I_2 = d \f$ is the ruled surface swept by the line at
///   distance \f$ d \f$ from the axis with direction \f$ (\cos(z/c), \sin(z/c), 0) \f$ in the
///   plane at height \f$ z \f$;
/// - for \f$ c = 0 \f$, \f$ z \f$ itself: the planes \f$ z = \mathrm{const} \f$ are stream surfaces.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Helical_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param axial_speed the constant \f$ z \f$-component \f$ c \f$ of the velocity
  /// \param axis_point a point \f$ a \f$ of the axis, which is parallel to the \f$ z \f$-axis
  explicit Helical_flow(const FT& axial_speed = FT(1),
                        const Point_3& axis_point = Point_3(FT(0), FT(0), FT(0)))
      : m_c(axial_speed), m_a(axis_point)
  {
  }

  /// returns \f$ (-(y - a_y), x - a_x, c) \f$.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    return Vector_3(-(p.y() - m_a.y()), p.x() - m_a.x(), m_c);
  }

  /// returns \f$ (x - a_x)^2 + (y - a_y)^2 \f$.
  FT first_integral_radius(const Point_3& p) const
  {
    const FT x = p.x() - m_a.x(), y = p.y() - m_a.y();
    return x * x + y * y;
  }

  /// returns \f$ y \cos(z / c) - x \sin(z / c) \f$ of \f$ (x, y, z) = p - a \f$.
  /// \pre `axial_speed() != 0`
  FT first_integral_helicoid(const Point_3& p) const
  {
    CGAL_precondition(m_c != FT(0));
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const std::array<double, 3> a = internal::to_double_coordinates(m_a);
    const double phase = (x[2] - a[2]) / CGAL::to_double(m_c);
    return FT((x[1] - a[1]) * std::cos(phase) - (x[0] - a[0]) * std::sin(phase));
  }

  /// returns \f$ c \f$.
  const FT& axial_speed() const { return m_c; }
  /// returns \f$ a \f$.
  const Point_3& axis_point() const { return m_a; }

private:
  FT m_c;
  Point_3 m_a;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The Arnold–Beltrami–Childress flow
/// \f[ v(x, y, z) = (A \sin z + C \cos y,\; B \sin x + A \cos z,\; C \sin y + B \cos x). \f]
///
/// Domain: \f$ \mathbb{R}^3 \f$ (\f$ 2\pi \f$-periodic).  Divergence-free and a Beltrami field:
/// \f$ \nabla \times v = v \f$, so it has no potential.  For general \f$ A, B, C \f$ (the
/// default \f$ \sqrt{3}, \sqrt{2}, 1 \f$ is the classical chaotic case) no first integral is
/// known.
///
/// For \f$ C = 0 \f$ the velocity does not depend on \f$ y \f$ and
/// \f$ I = A \cos z + B \sin x \f$ is a first integral (`first_integral()`):
/// \f$ \nabla I \cdot v = B \cos x \cdot A \sin z - A \sin z \cdot B \cos x = 0 \f$.  Its level
/// sets, cylinders with rulings along \f$ y \f$, are stream surfaces.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class ABC_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param a the coefficient \f$ A \f$
  /// \param b the coefficient \f$ B \f$
  /// \param c the coefficient \f$ C \f$
  explicit ABC_flow(const FT& a = FT(std::sqrt(3.)), const FT& b = FT(std::sqrt(2.)), const FT& c = FT(1))
      : m_a(a), m_b(b), m_c(c)
  {
  }

  /// returns \f$ (A \sin z + C \cos y, B \sin x + A \cos z, C \sin y + B \cos x) \f$.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double a = CGAL::to_double(m_a), b = CGAL::to_double(m_b), c = CGAL::to_double(m_c);
    return internal::make_vector<Vector_3>(a * std::sin(x[2]) + c * std::cos(x[1]),
                                           b * std::sin(x[0]) + a * std::cos(x[2]),
                                           c * std::sin(x[1]) + b * std::cos(x[0]));
  }

  /// returns \f$ A \cos z + B \sin x \f$, a first integral of the flow only when \f$ C = 0 \f$.
  /// \pre `c() == 0`
  FT first_integral(const Point_3& p) const
  {
    CGAL_precondition(m_c == FT(0));
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    return FT(CGAL::to_double(m_a) * std::cos(x[2]) + CGAL::to_double(m_b) * std::sin(x[0]));
  }

  const FT& a() const { return m_a; } ///< returns \f$ A \f$
  const FT& b() const { return m_b; } ///< returns \f$ B \f$
  const FT& c() const { return m_c; } ///< returns \f$ C \f$

private:
  FT m_a, m_b, m_c;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// Hill's spherical vortex of radius \f$ a \f$ centered at the origin with axis \f$ z \f$, in the
/// frame moving with the vortex, where the flow is steady and tends to the uniform stream
/// \f$ U e_z \f$ at infinity (in the frame of the fluid at rest at infinity, the vortex travels
/// with velocity \f$ -U e_z \f$).
///
/// Domain: \f$ \mathbb{R}^3 \f$.  With \f$ \rho^2 = x^2 + y^2 \f$, \f$ r^2 = \rho^2 + z^2 \f$,
/// the Stokes stream function (`stokes_stream_function()`) is
/// \f[ \psi = \begin{cases}
///       -\frac{3}{4} U \rho^2 \left(1 - \frac{r^2}{a^2}\right) & r < a
///       \quad\text{(rotational, } \omega_\theta = \tfrac{15}{2} U \rho / a^2\text{)} \\ %
///       \frac{1}{2} U \rho^2 \left(1 - \frac{a^3}{r^3}\right) & r \geq a
///       \quad\text{(potential flow around the sphere)}
///     \end{cases} \f]
/// continuous with its gradient across \f$ r = a \f$, and the velocity is
/// \f$ u_\rho = -\frac{1}{\rho} \partial_z \psi \f$, \f$ u_z = \frac{1}{\rho} \partial_\rho \psi \f$,
/// no swirl.  Inside this gives
/// \f$ v = \frac{3U}{2a^2} \left(-x z,\; -y z,\; 2\rho^2 + z^2 - a^2\right) \f$; the velocity at
/// the center is \f$ -\frac{3}{2} U e_z \f$.
///
/// Divergence-free.  Stream surfaces: the surfaces of revolution \f$ \psi = \mathrm{const} \f$
/// (among them the sphere \f$ r = a \f$, where \f$ \psi = 0 \f$, and the nested vortex tori
/// inside) and the meridional half-planes bounded by the \f$ z \f$-axis.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Hill_spherical_vortex {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param radius the radius \f$ a \f$ of the vortex
  /// \param speed the speed \f$ U \f$ of the stream at infinity
  /// \pre `radius > 0`
  explicit Hill_spherical_vortex(const FT& radius = FT(1), const FT& speed = FT(1)) : m_a(radius), m_u(speed)
  {
    CGAL_precondition(radius > FT(0));
  }

  /// returns the velocity at `p`.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double a = CGAL::to_double(m_a), U = CGAL::to_double(m_u);
    const double rho2 = x[0] * x[0] + x[1] * x[1];
    if (rho2 + x[2] * x[2] < a * a) {
      const double k = 1.5 * U / (a * a);
      return internal::make_vector<Vector_3>(-k * x[0] * x[2], -k * x[1] * x[2],
                                             k * (2. * rho2 + x[2] * x[2] - a * a));
    }
    const std::array<double, 3> v = internal::sphere_potential_flow_velocity(x[0], x[1], x[2], a, U);
    return internal::make_vector<Vector_3>(v[0], v[1], v[2]);
  }

  /// returns the Stokes stream function \f$ \psi(p) \f$.
  FT stokes_stream_function(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double a = CGAL::to_double(m_a), U = CGAL::to_double(m_u);
    const double rho2 = x[0] * x[0] + x[1] * x[1];
    const double r2 = rho2 + x[2] * x[2];
    if (r2 < a * a)
      return FT(-0.75 * U * rho2 * (1. - r2 / (a * a)));
    return FT(internal::sphere_potential_flow_stokes_stream_function(x[0], x[1], x[2], a, U));
  }

  const FT& radius() const { return m_a; } ///< returns \f$ a \f$
  const FT& speed() const { return m_u; }  ///< returns \f$ U \f$

private:
  FT m_a, m_u;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The point source of strength \f$ q \f$ (volume flux) at \f$ c \f$:
/// \f[ v(x) = \frac{q}{4\pi} \frac{x - c}{|x - c|^3}. \f]
///
/// Domain: \f$ \mathbb{R}^3 \setminus \{c\} \f$ (the operator returns `std::nullopt` at \f$ c \f$
/// and wherever the velocity overflows).  Divergence-free away from \f$ c \f$.
/// Potential: \f$ \varphi(x) = -\frac{q}{4\pi |x - c|} \f$ (`potential()`); the orthogonal
/// surfaces are the spheres centered at \f$ c \f$.  Stream surfaces: the cones with apex
/// \f$ c \f$ (every surface made of rays from \f$ c \f$, planes through \f$ c \f$ included).
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Point_source_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param center the source \f$ c \f$
  /// \param strength the volume flux \f$ q \f$ through any sphere around \f$ c \f$; negative for a
  /// sink
  explicit Point_source_flow(const Point_3& center = Point_3(CGAL::ORIGIN), const FT& strength = FT(1))
      : m_c(center), m_q(strength)
  {
  }

  /// returns the velocity at `p`, or `std::nullopt` at the center.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> d = offset(p);
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (!(r2 > 0.))
      return std::nullopt;
    const double k = CGAL::to_double(m_q) / (4. * CGAL_PI * r2 * std::sqrt(r2));
    const double v[3] = {k * d[0], k * d[1], k * d[2]};
    // Near the center r^3 underflows before r^2 does.
    if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2])))
      return std::nullopt;
    return internal::make_vector<Vector_3>(v[0], v[1], v[2]);
  }

  /// returns \f$ \varphi(p) = -q / (4\pi |p - c|) \f$.
  /// \pre `p != center()`
  FT potential(const Point_3& p) const
  {
    const std::array<double, 3> d = offset(p);
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    CGAL_precondition(r > 0.);
    return FT(-CGAL::to_double(m_q) / (4. * CGAL_PI * r));
  }

  const Point_3& center() const { return m_c; } ///< returns \f$ c \f$
  const FT& strength() const { return m_q; }    ///< returns \f$ q \f$

private:
  std::array<double, 3> offset(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const std::array<double, 3> c = internal::to_double_coordinates(m_c);
    return {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  }

  Point_3 m_c;
  FT m_q;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The planar potential flow around the infinite circular cylinder of radius \f$ R \f$ whose axis
/// is the \f$ z \f$-axis, with free stream \f$ U e_x \f$, extruded along \f$ z \f$.
///
/// Domain: \f$ \rho \geq R \f$ (the operator returns `std::nullopt` for \f$ \rho < R \f$, up to a
/// relative \f$ 10^{-12} \f$ that lets points rounded onto the wall through).  With
/// \f$ \rho^2 = x^2 + y^2 \f$:
/// \f[ v = U \left(1 - R^2 \frac{x^2 - y^2}{\rho^4},\; -2 R^2 \frac{x y}{\rho^4},\; 0\right). \f]
/// Potential (`potential()`):
/// \f$ \varphi = U \left(\rho + \frac{R^2}{\rho}\right) \cos\theta
///     = U x \left(1 + \frac{R^2}{\rho^2}\right) \f$;
/// the orthogonal surfaces are its level sets extruded along \f$ z \f$.  Stream function
/// (`stream_function()`, \f$ v_x = \partial_y \psi \f$, \f$ v_y = -\partial_x \psi \f$):
/// \f$ \psi = U \left(\rho - \frac{R^2}{\rho}\right) \sin\theta
///     = U y \left(1 - \frac{R^2}{\rho^2}\right) \f$.
/// Stream surfaces: the curves \f$ \psi = \mathrm{const} \f$ extruded along \f$ z \f$ (the cylinder
/// \f$ \rho = R \f$ is part of \f$ \psi = 0 \f$), and the planes \f$ z = \mathrm{const} \f$.
/// Divergence- and curl-free.  Stagnation lines at \f$ (\pm R, 0, z) \f$; speed \f$ 2U \f$ at
/// \f$ (0, \pm R, z) \f$.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Cylinder_potential_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param radius the radius \f$ R \f$ of the cylinder
  /// \param speed the free-stream speed \f$ U \f$
  /// \pre `radius > 0`
  explicit Cylinder_potential_flow(const FT& radius = FT(1), const FT& speed = FT(1))
      : m_r(radius), m_u(speed)
  {
    CGAL_precondition(radius > FT(0));
  }

  /// returns the velocity at `p`, or `std::nullopt` inside the cylinder.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double R = CGAL::to_double(m_r), U = CGAL::to_double(m_u);
    const double rho2 = x[0] * x[0] + x[1] * x[1];
    if (rho2 < R * R * (1. - internal::relative_wall_tolerance))
      return std::nullopt;
    const double k = U * (R * R / rho2) / rho2;
    return internal::make_vector<Vector_3>(U - k * (x[0] * x[0] - x[1] * x[1]), -2. * k * x[0] * x[1], 0.);
  }

  /// returns \f$ \varphi(p) = U x (1 + R^2 / \rho^2) \f$.
  /// Meaningful for \f$ \rho \geq R \f$.
  /// \pre `p` is not on the \f$ z \f$-axis
  FT potential(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double R = CGAL::to_double(m_r);
    const double rho2 = x[0] * x[0] + x[1] * x[1];
    CGAL_precondition(rho2 > 0.);
    return FT(CGAL::to_double(m_u) * x[0] * (1. + R * R / rho2));
  }

  /// returns \f$ \psi(p) = U y (1 - R^2 / \rho^2) \f$.
  /// Meaningful for \f$ \rho \geq R \f$.
  /// \pre `p` is not on the \f$ z \f$-axis
  FT stream_function(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double R = CGAL::to_double(m_r);
    const double rho2 = x[0] * x[0] + x[1] * x[1];
    CGAL_precondition(rho2 > 0.);
    return FT(CGAL::to_double(m_u) * x[1] * (1. - R * R / rho2));
  }

  const FT& radius() const { return m_r; } ///< returns \f$ R \f$
  const FT& speed() const { return m_u; }  ///< returns \f$ U \f$

private:
  FT m_r, m_u;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The potential flow around the sphere of radius \f$ R \f$ centered at the origin, with free
/// stream \f$ U e_z \f$.
///
/// Domain: \f$ r \geq R \f$ (the operator returns `std::nullopt` for \f$ r < R \f$, up to a
/// relative \f$ 10^{-12} \f$ that lets points rounded onto the wall through).  With
/// \f$ \rho^2 = x^2 + y^2 \f$, \f$ r^2 = \rho^2 + z^2 \f$:
/// \f[ v = \left(-\frac{3}{2} U R^3 \frac{x z}{r^5},\; -\frac{3}{2} U R^3 \frac{y z}{r^5},\;
///        U \left(1 - \frac{R^3}{r^3}\right) + \frac{3}{2} U R^3 \frac{\rho^2}{r^5}\right). \f]
/// Potential (`potential()`):
/// \f$ \varphi = U \left(r + \frac{R^3}{2 r^2}\right) \cos\theta
///     = U z \left(1 + \frac{R^3}{2 r^3}\right) \f$; the orthogonal surfaces are its level sets.
/// Stokes stream function (`stokes_stream_function()`,
/// \f$ u_\rho = -\frac{1}{\rho} \partial_z \psi \f$, \f$ u_z = \frac{1}{\rho} \partial_\rho \psi \f$):
/// \f$ \psi = \frac{1}{2} U \rho^2 \left(1 - \frac{R^3}{r^3}\right) \f$.
/// Stream surfaces: the surfaces of revolution \f$ \psi = \mathrm{const} \f$ (the sphere is part of
/// \f$ \psi = 0 \f$) and the meridional half-planes bounded by the \f$ z \f$-axis.  Divergence-
/// and curl-free.  Stagnation points at the poles \f$ (0, 0, \pm R) \f$; speed
/// \f$ \frac{3}{2} U \f$ on the equator.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Sphere_potential_flow {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param radius the radius \f$ R \f$ of the sphere
  /// \param speed the free-stream speed \f$ U \f$
  /// \pre `radius > 0`
  explicit Sphere_potential_flow(const FT& radius = FT(1), const FT& speed = FT(1)) : m_r(radius), m_u(speed)
  {
    CGAL_precondition(radius > FT(0));
  }

  /// returns the velocity at `p`, or `std::nullopt` inside the sphere.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double R = CGAL::to_double(m_r);
    if (x[0] * x[0] + x[1] * x[1] + x[2] * x[2] < R * R * (1. - internal::relative_wall_tolerance))
      return std::nullopt;
    const std::array<double, 3> v =
        internal::sphere_potential_flow_velocity(x[0], x[1], x[2], R, CGAL::to_double(m_u));
    return internal::make_vector<Vector_3>(v[0], v[1], v[2]);
  }

  /// returns \f$ \varphi(p) = U z (1 + R^3 / (2 r^3)) \f$.
  /// Meaningful for \f$ r \geq R \f$.
  /// \pre `p` is not the origin
  FT potential(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    CGAL_precondition(r > 0.);
    const double R_over_r = CGAL::to_double(m_r) / r;
    return FT(CGAL::to_double(m_u) * x[2] * (1. + 0.5 * R_over_r * R_over_r * R_over_r));
  }

  /// returns \f$ \psi(p) = \frac{1}{2} U \rho^2 (1 - R^3 / r^3) \f$.
  /// Meaningful for \f$ r \geq R \f$.
  /// \pre `p` is not the origin
  FT stokes_stream_function(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    CGAL_precondition(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] > 0.);
    return FT(internal::sphere_potential_flow_stokes_stream_function(x[0], x[1], x[2], CGAL::to_double(m_r),
                                                                     CGAL::to_double(m_u)));
  }

  const FT& radius() const { return m_r; } ///< returns \f$ R \f$
  const FT& speed() const { return m_u; }  ///< returns \f$ U \f$

private:
  FT m_r, m_u;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// The Burgers vortex about the \f$ z \f$-axis: a viscous vortex of circulation \f$ \Gamma \f$
/// kept steady by the axisymmetric strain of rate \f$ \alpha \f$ against the viscosity
/// \f$ \nu \f$.  In cylindrical coordinates
/// \f[ u_\rho = -\alpha \rho, \quad u_z = 2 \alpha z, \quad
///     u_\theta = \frac{\Gamma}{2 \pi \rho} \left(1 - e^{-\alpha \rho^2 / (2 \nu)}\right), \f]
/// with \f$ u_\theta \to 0 \f$ on the axis (the flow is smooth there: near the axis it rotates
/// rigidly with angular speed \f$ \Gamma \alpha / (4 \pi \nu) \f$).  The core radius is
/// \f$ \sqrt{2 \nu / \alpha} \f$ and the vorticity is
/// \f$ \omega_z = \frac{\Gamma \alpha}{2 \pi \nu} e^{-\alpha \rho^2 / (2 \nu)} \f$.
///
/// Domain: \f$ \mathbb{R}^3 \f$.  Divergence-free; no potential.  Since the flow is
/// axisymmetric, the Stokes stream function of its meridional part,
/// \f$ \psi = \alpha \rho^2 z \f$ (`stokes_stream_function()`; \f$ u_\rho = -\frac{1}{\rho}
/// \partial_z \psi \f$, \f$ u_z = \frac{1}{\rho} \partial_\rho \psi \f$), is a first integral of
/// the full flow: the surfaces of revolution \f$ \rho^2 z = \mathrm{const} \f$ (and the plane
/// \f$ z = 0 \f$) are stream surfaces.  Meridional half-planes are not, because of the swirl.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Burgers_vortex {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// The defaults give a core radius of 1 and \f$ u_\theta \to 1 / \rho \f$ far from the axis.
  /// \param circulation the circulation \f$ \Gamma \f$ at infinity
  /// \param viscosity the kinematic viscosity \f$ \nu \f$
  /// \param strain the strain rate \f$ \alpha \f$
  /// \pre `viscosity > 0` and `strain > 0`
  explicit Burgers_vortex(const FT& circulation = FT(2 * CGAL_PI), const FT& viscosity = FT(0.5),
                          const FT& strain = FT(1))
      : m_gamma(circulation), m_nu(viscosity), m_alpha(strain)
  {
    CGAL_precondition(viscosity > FT(0));
    CGAL_precondition(strain > FT(0));
  }

  /// returns the velocity at `p`.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> x = internal::to_double_coordinates(p);
    const double gamma = CGAL::to_double(m_gamma), nu = CGAL::to_double(m_nu),
                 alpha = CGAL::to_double(m_alpha);
    const double rho2 = x[0] * x[0] + x[1] * x[1];
    // Angular speed u_theta / rho; expm1 keeps it accurate near the axis, where
    // 1 - exp(-s) would cancel.
    const double s = alpha * rho2 / (2. * nu);
    const double omega =
        (s > 0.) ? -std::expm1(-s) * gamma / (2. * CGAL_PI * rho2) : gamma * alpha / (4. * CGAL_PI * nu);
    return internal::make_vector<Vector_3>(-alpha * x[0] - omega * x[1], -alpha * x[1] + omega * x[0],
                                           2. * alpha * x[2]);
  }

  /// returns \f$ \psi(p) = \alpha \rho^2 z \f$.
  FT stokes_stream_function(const Point_3& p) const
  {
    return m_alpha * (p.x() * p.x() + p.y() * p.y()) * p.z();
  }

  const FT& circulation() const { return m_gamma; } ///< returns \f$ \Gamma \f$
  const FT& viscosity() const { return m_nu; }      ///< returns \f$ \nu \f$
  const FT& strain() const { return m_alpha; }      ///< returns \f$ \alpha \f$

private:
  FT m_gamma, m_nu, m_alpha;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// Roger Crawfis's procedural tornado, the field that his `gen_tornado(xs, ys, zs, time)`
/// samples on the grid \f$ (i/(x_s-1), j/(y_s-1), k/(z_s-1)) \f$, evaluated at any point of the
/// unit cube.
///
/// Domain: \f$ [0, 1]^3 \f$ (the operator returns `std::nullopt` outside).  For a time \f$ t \f$,
/// each horizontal slice has a funnel center \f$ (x_c, y_c) \f$, a funnel radius \f$ r \f$ and a
/// damping width \f$ r_2 \f$:
/// \f[ x_c = \tfrac12 + \tfrac1{10} \sin(0.04 t + 10 z), \quad
///     y_c = \tfrac12 + \tfrac1{10} \cos(0.03 t + 3 z), \quad
///     r = \tfrac1{10} + \tfrac25 z^2 + \tfrac1{10} z \sin 8z, \quad
///     r_2 = \tfrac15 + \tfrac1{10} z. \f]
/// With \f$ d = |(x - x_c, y - y_c)| \f$,
/// \f$ s_0 = 1 \f$ if \f$ |r - d| \leq r_2 \f$ and \f$ s_0 = 0.8 - |r - d| \f$ otherwise,
/// \f$ z_0 = \max(0, \tfrac1{10}(\tfrac1{10} - d z)) \f$, \f$ d' = \sqrt{d^2 + z_0^2} \f$ and
/// \f$ s = \frac{(r + r_2 - d')\, s_0}{(d' + 10^{-11})(1 + z)} \f$:
/// \f[ v = \left(s (y - y_c) + \tfrac1{10} (x - x_c),\; -s (x - x_c) + \tfrac1{10} (y - y_c),\;
///        s z_0\right). \f]
/// The horizontal part is a swirl about the funnel center plus the radial outflow
/// \f$ \tfrac1{10} (x - x_c, y - y_c) \f$.
///
/// The field is kept as Crawfis wrote it, including the jump of \f$ s_0 \f$ across
/// \f$ |r - d| = r_2 \f$ that his own comment regrets: it is a robustness test (a discontinuous,
/// neither divergence-free nor potential field).  No exact stream surface or first integral is
/// known.
///
/// \tparam GeomTraits a model of `Kernel`
/// \cgalModels `FlowField_3`
template <typename GeomTraits>
class Crawfis_tornado {
public:
  /// The number type.
  using FT = typename GeomTraits::FT;
  /// The point type.
  using Point_3 = typename GeomTraits::Point_3;
  /// The vector type.
  using Vector_3 = typename GeomTraits::Vector_3;

  /// \param time the time argument of `gen_tornado()`, which turns the funnel; any real value
  explicit Crawfis_tornado(const FT& time = FT(0)) : m_time(time) {}

  /// returns the velocity at `p`, or `std::nullopt` outside the unit cube.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const std::array<double, 3> q = internal::to_double_coordinates(p);
    const double x = q[0], y = q[1], z = q[2];
    if (!(x >= 0. && x <= 1. && y >= 0. && y <= 1. && z >= 0. && z <= 1.))
      return std::nullopt;
    const double t = CGAL::to_double(m_time);
    const double xc = 0.5 + 0.1 * std::sin(0.04 * t + 10. * z);
    const double yc = 0.5 + 0.1 * std::cos(0.03 * t + 3. * z);
    const double r = 0.1 + 0.4 * z * z + 0.1 * z * std::sin(8. * z);
    const double r2 = 0.2 + 0.1 * z;
    const double dx = x - xc, dy = y - yc;
    const double d = std::sqrt(dx * dx + dy * dy);
    const double band = std::abs(r - d);
    const double s0 = (band > r2) ? 0.8 - band : 1.;
    const double z0 = std::max(0., 0.1 * (0.1 - d * z));
    const double d_lifted = std::sqrt(d * d + z0 * z0);
    // The 1e-11 is Crawfis's guard; d_lifted never vanishes, but keeping it reproduces his
    // grids to the last digit.
    const double s = (r + r2 - d_lifted) * s0 / (d_lifted + 1e-11) / (1. + z);
    return internal::make_vector<Vector_3>(s * dy + 0.1 * dx, -s * dx + 0.1 * dy, s * z0);
  }

  const FT& time() const { return m_time; } ///< returns the time \f$ t \f$

private:
  FT m_time;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_ANALYTIC_FLOW_FIELDS_H
