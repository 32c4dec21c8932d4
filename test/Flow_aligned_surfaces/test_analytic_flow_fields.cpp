// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks every closed-form object of analytic_flow_fields.h against the velocity it claims to
// describe, by finite differences, and every flow against textbook values.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <type_traits>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_analytic_flow_fields {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Matrix3 = std::array<std::array<double, 3>, 3>;

// Central differences: truncation error ~ h^2 |f'''| / 6 and rounding error ~ 1e-16 |f| / h.
// With h = 1e-5 on fields whose length scale is about 1 both are below 1e-9 relative, so
// 1e-6 leaves a wide margin while a wrong sign, factor or exponent gives errors of order 1.
constexpr double h = 1e-5;
constexpr double tol = 1e-6;

double norm(const Vector& v)
{
  return std::sqrt(v.squared_length());
}

template <typename Field>
Vector velocity(const Field& field, const Point& p)
{
  const std::optional<Vector> v = field(p);
  EXPECT_TRUE(v.has_value()) << "no velocity at " << p;
  return v ? *v : Vector(0, 0, 0);
}

Vector unit(int i)
{
  return Vector(i == 0, i == 1, i == 2);
}

template <typename Scalar>
Vector fd_gradient(const Scalar& f, const Point& p)
{
  double g[3];
  for (int i = 0; i < 3; ++i)
    g[i] = (f(p + h * unit(i)) - f(p - h * unit(i))) / (2 * h);
  return Vector(g[0], g[1], g[2]);
}

// J[i][j] = d v_i / d x_j
template <typename Field>
Matrix3 fd_jacobian(const Field& field, const Point& p)
{
  Matrix3 J;
  for (int j = 0; j < 3; ++j) {
    const Vector d = (velocity(field, p + h * unit(j)) - velocity(field, p - h * unit(j))) / (2 * h);
    for (int i = 0; i < 3; ++i)
      J[i][j] = d[i];
  }
  return J;
}

double frobenius_norm(const Matrix3& J)
{
  double s = 0;
  for (const auto& row : J)
    for (double a : row)
      s += a * a;
  return std::sqrt(s);
}

double divergence(const Matrix3& J)
{
  return J[0][0] + J[1][1] + J[2][2];
}

Vector curl(const Matrix3& J)
{
  return Vector(J[2][1] - J[1][2], J[0][2] - J[2][0], J[1][0] - J[0][1]);
}

// Pseudo-random points of the box [lo, hi]^3 accepted by `keep`; the fixed seed makes failures
// reproducible.
std::vector<Point> sample_points(
    std::size_t n, double lo, double hi,
    const std::function<bool(const Point&)>& keep = [](const Point&) { return true; },
    unsigned seed = 20130227)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Point> points;
  while (points.size() < n) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const Point p(x, y, z);
    if (keep(p))
      points.push_back(p);
  }
  return points;
}

double rho(const Point& p)
{
  return std::sqrt(p.x() * p.x() + p.y() * p.y());
}
double radius(const Point& p)
{
  return std::sqrt((p - CGAL::ORIGIN).squared_length());
}

template <typename Field, typename Potential>
void expect_gradient_of_potential(const Field& field, const Potential& potential,
                                  const std::vector<Point>& points)
{
  for (const Point& p : points) {
    const Vector v = velocity(field, p);
    const Vector g = fd_gradient(potential, p);
    EXPECT_LE(norm(g - v), tol * (norm(v) + 1e-3)) << "at " << p << ": grad phi " << g << " vs v " << v;
  }
}

// The largest |cos| of the angle between grad I and v, over the points where both are
// clearly non-zero; at least 90% of the points must count, so that a constant I fails.
template <typename Field, typename Integral>
double max_first_integral_defect(const Field& field, const Integral& integral,
                                 const std::vector<Point>& points)
{
  double worst = 0;
  std::size_t counted = 0;
  for (const Point& p : points) {
    const Vector v = velocity(field, p);
    const Vector g = fd_gradient(integral, p);
    if (norm(v) < 1e-6 || norm(g) < 1e-6)
      continue;
    ++counted;
    worst = std::max(worst, std::abs(g * v) / (norm(g) * norm(v)));
  }
  EXPECT_GE(counted, points.size() * 9 / 10) << "the first integral is nearly constant";
  return worst;
}

template <typename Field>
void expect_divergence_free(const Field& field, const std::vector<Point>& points)
{
  for (const Point& p : points) {
    const Matrix3 J = fd_jacobian(field, p);
    EXPECT_LE(std::abs(divergence(J)), tol * (frobenius_norm(J) + 1e-3)) << "at " << p;
  }
}

template <typename Field>
void expect_curl_free(const Field& field, const std::vector<Point>& points)
{
  for (const Point& p : points) {
    const Matrix3 J = fd_jacobian(field, p);
    EXPECT_LE(norm(curl(J)), tol * (frobenius_norm(J) + 1e-3)) << "at " << p;
  }
}

// For an axisymmetric flow about z: u_rho = -(1/rho) dpsi/dz and u_z = (1/rho) dpsi/drho.
template <typename Field, typename Stream_function>
void expect_meridional_velocity_from_stokes_stream_function(const Field& field, const Stream_function& psi,
                                                            const std::vector<Point>& points)
{
  for (const Point& p : points) {
    const double r = rho(p);
    const Vector e_rho(p.x() / r, p.y() / r, 0);
    const Vector v = velocity(field, p);
    const double dpsi_dz = (psi(p + h * unit(2)) - psi(p - h * unit(2))) / (2 * h);
    const double dpsi_drho = (psi(p + h * e_rho) - psi(p - h * e_rho)) / (2 * h);
    const double scale = tol * (norm(v) + 1e-3);
    EXPECT_NEAR(v * e_rho, -dpsi_dz / r, scale) << "u_rho at " << p;
    EXPECT_NEAR(v.z(), dpsi_drho / r, scale) << "u_z at " << p;
  }
}

template <typename Field>
void expect_vectors_near(const Field& field, const Point& p, const Vector& expected, double eps)
{
  const Vector v = velocity(field, p);
  EXPECT_LE(norm(v - expected), eps) << "at " << p << ": " << v << " instead of " << expected;
}

// ---------------------------------------------------------------------------------------------

template <typename Field>
constexpr bool is_flow_field_3 = std::is_copy_constructible_v<Field>&&
    std::is_same_v<std::invoke_result_t<const Field&, const Point&>, std::optional<Vector>>;

static_assert(is_flow_field_3<FAS::Uniform_flow<K>>);
static_assert(is_flow_field_3<FAS::Linear_flow<K>>);
static_assert(is_flow_field_3<FAS::Helical_flow<K>>);
static_assert(is_flow_field_3<FAS::ABC_flow<K>>);
static_assert(is_flow_field_3<FAS::Hill_spherical_vortex<K>>);
static_assert(is_flow_field_3<FAS::Point_source_flow<K>>);
static_assert(is_flow_field_3<FAS::Cylinder_potential_flow<K>>);
static_assert(is_flow_field_3<FAS::Sphere_potential_flow<K>>);
static_assert(is_flow_field_3<FAS::Burgers_vortex<K>>);
static_assert(is_flow_field_3<FAS::Crawfis_tornado<K>>);

TEST(AnalyticFlowFields, UniformFlowIsConstantAndTheGradientOfItsPotential)
{
  const Vector u(1, -2, 0.5);
  const FAS::Uniform_flow<K> field(u);
  const std::vector<Point> points = sample_points(50, -5, 5);
  for (const Point& p : points)
    EXPECT_EQ(velocity(field, p), u);
  expect_gradient_of_potential(
      field, [&](const Point& p) { return field.potential(p); }, points);
  EXPECT_EQ(FAS::Uniform_flow<K>().velocity(), Vector(1, 0, 0));
}

TEST(AnalyticFlowFields, LinearFlowIsTheMatrixProduct)
{
  const FAS::Linear_flow<K> field(1, 2, 3, 4, 5, 6, 7, 8, 10);
  expect_vectors_near(field, Point(1, -1, 2), Vector(1 - 2 + 6, 4 - 5 + 12, 7 - 8 + 20), 0);
  const FAS::Linear_flow<K>::Matrix a = {{{1, 2, 3}, {4, 5, 6}, {7, 8, 10}}};
  EXPECT_EQ(FAS::Linear_flow<K>(a).matrix(), field.matrix());
  EXPECT_FALSE(field.has_potential());
  EXPECT_EQ(field.divergence(), 16);
  for (const Point& p : sample_points(20, -2, 2))
    EXPECT_NEAR(divergence(fd_jacobian(field, p)), 16, 1e-6);
}

TEST(AnalyticFlowFields, SymmetricLinearFlowIsTheGradientOfItsPotential)
{
  const FAS::Linear_flow<K> field(2, -1, 0.5, -1, 3, 0.25, 0.5, 0.25, -1);
  ASSERT_TRUE(field.has_potential());
  expect_gradient_of_potential(
      field, [&](const Point& p) { return field.potential(p); }, sample_points(50, -3, 3));
}

TEST(AnalyticFlowFields, DefaultLinearFlowIsTheHarmonicSaddle)
{
  const FAS::Linear_flow<K> field;
  EXPECT_TRUE(field.has_potential());
  EXPECT_EQ(field.divergence(), 0);
  // Streamlines (x0 e^t, y0 e^t, z0 e^-2t) keep y/x and (x^2+y^2) z.
  const std::vector<Point> points =
      sample_points(100, -2, 2, [](const Point& p) { return std::abs(p.x()) > 0.1; });
  EXPECT_LE(max_first_integral_defect(
                field, [](const Point& p) { return p.y() / p.x(); }, points),
            tol);
  EXPECT_LE(max_first_integral_defect(
                field, [](const Point& p) { return (p.x() * p.x() + p.y() * p.y()) * p.z(); }, points),
            tol);
  expect_divergence_free(field, points);
}

// Both first integrals of a helical flow are constant along its stream lines at `points`, and the
// flow is divergence-free there.
void expect_helical_first_integrals(const FAS::Helical_flow<K>& field, const std::vector<Point>& points)
{
  EXPECT_LE(max_first_integral_defect(
                field, [&](const Point& p) { return field.first_integral_radius(p); }, points),
            tol);
  EXPECT_LE(max_first_integral_defect(
                field, [&](const Point& p) { return field.first_integral_helicoid(p); }, points),
            tol);
  expect_divergence_free(field, points);
}

TEST(AnalyticFlowFields, HelicalFlowFirstIntegrals)
{
  const double c = 0.7;
  const FAS::Helical_flow<K> field(c);
  expect_vectors_near(field, Point(1, 2, 3), Vector(-2, 1, c), 0);
  const std::vector<Point> points = sample_points(100, -3, 3);
  expect_helical_first_integrals(field, points);

  // The exact flow map (rotation by t about z, rise c t) keeps both integrals.
  for (const Point& p : sample_points(20, -3, 3)) {
    for (double t : {0.3, 1.7, -4.0}) {
      const Point q(std::cos(t) * p.x() - std::sin(t) * p.y(), std::sin(t) * p.x() + std::cos(t) * p.y(),
                    p.z() + c * t);
      EXPECT_NEAR(field.first_integral_radius(q), field.first_integral_radius(p), 1e-12);
      EXPECT_NEAR(field.first_integral_helicoid(q), field.first_integral_helicoid(p), 1e-12);
    }
  }
  // The zero level set of the helicoid integral is the helicoid theta = z / c.
  for (double z : {-2.0, 0.1, 1.5})
    for (double s : {-1.0, 0.5, 2.0})
      EXPECT_NEAR(field.first_integral_helicoid(Point(s * std::cos(z / c), s * std::sin(z / c), z)), 0,
                  1e-14);
}

TEST(AnalyticFlowFields, HelicalFlowAboutAnotherAxisIsTheTranslatedFlow)
{
  const double c = -0.4;
  const Vector a(0.7, -1.2, 2.5);
  const FAS::Helical_flow<K> about_z(c);
  const FAS::Helical_flow<K> field(c, CGAL::ORIGIN + a);
  EXPECT_EQ(field.axis_point(), CGAL::ORIGIN + a);
  expect_vectors_near(field, Point(1, 2, 3), Vector(-(2 - a.y()), 1 - a.x(), c), 0);
  const std::vector<Point> points = sample_points(100, -3, 3);
  for (const Point& p : points) {
    const Vector d = *field(p + a) - *about_z(p);
    EXPECT_LT(std::sqrt(d.squared_length()), 1e-14);
    EXPECT_NEAR(field.first_integral_radius(p + a), about_z.first_integral_radius(p), 1e-12);
    EXPECT_NEAR(field.first_integral_helicoid(p + a), about_z.first_integral_helicoid(p), 1e-12);
  }
  expect_helical_first_integrals(field, points);
  // The axis is at rest but for the axial speed.
  EXPECT_EQ(*field(Point(a.x(), a.y(), -5.)), Vector(0, 0, c));
}

TEST(AnalyticFlowFields, ABCFlowAtHandComputedPoints)
{
  const FAS::ABC_flow<K> field; // A = sqrt 3, B = sqrt 2, C = 1
  const double pi = CGAL_PI;
  // (pi/2, 0, 0): u = A sin 0 + C cos 0, v = B sin(pi/2) + A cos 0, w = C sin 0 + B cos(pi/2)
  expect_vectors_near(field, Point(pi / 2, 0, 0), Vector(1, std::sqrt(2.) + std::sqrt(3.), 0), 1e-15);
  // (0, pi/2, pi/2): u = A, v = A cos(pi/2), w = C + B
  expect_vectors_near(field, Point(0, pi / 2, pi / 2), Vector(std::sqrt(3.), 0, 1 + std::sqrt(2.)), 1e-15);
  const FAS::ABC_flow<K> other(2, 3, 5);
  // (1, 2, 3): (2 sin 3 + 5 cos 2, 3 sin 1 + 2 cos 3, 5 sin 2 + 3 cos 1)
  expect_vectors_near(other, Point(1, 2, 3),
                      Vector(-1.7984941666159775, 0.5444279612227985, 6.167394051732828), 1e-14);
}

TEST(AnalyticFlowFields, ABCFlowIsADivergenceFreeBeltramiField)
{
  const FAS::ABC_flow<K> field(1.3, 0.7, 0.4);
  for (const Point& p : sample_points(50, -4, 4)) {
    const Matrix3 J = fd_jacobian(field, p);
    const Vector v = velocity(field, p);
    EXPECT_LE(norm(curl(J) - v), tol * norm(v)) << "curl v = v fails at " << p;
    EXPECT_LE(std::abs(divergence(J)), tol * frobenius_norm(J));
  }
}

TEST(AnalyticFlowFields, ABCFlowFirstIntegralWithoutC)
{
  const FAS::ABC_flow<K> field(1.3, 0.7, 0);
  const std::vector<Point> points = sample_points(200, -4, 4);
  EXPECT_LE(max_first_integral_defect(
                field, [&](const Point& p) { return field.first_integral(p); }, points),
            tol);
  // The check bites: the integral with the other sign, or the same integral when C != 0, fails.
  EXPECT_GT(max_first_integral_defect(
                field, [](const Point& p) { return 1.3 * std::cos(p.z()) - 0.7 * std::sin(p.x()); }, points),
            0.1);
  const FAS::ABC_flow<K> with_c(1.3, 0.7, 0.5);
  EXPECT_GT(max_first_integral_defect(
                with_c, [](const Point& p) { return 1.3 * std::cos(p.z()) + 0.7 * std::sin(p.x()); }, points),
            0.1);
}

TEST(AnalyticFlowFields, HillSphericalVortexClassicalValues)
{
  const double a = 2, U = 0.5;
  const FAS::Hill_spherical_vortex<K> field(a, U);
  // In the vortex frame the fluid at the center moves at -3U/2 against the stream +U at infinity.
  expect_vectors_near(field, Point(0, 0, 0), Vector(0, 0, -1.5 * U), 1e-15);
  expect_vectors_near(field, Point(3e3, -1e3, 4e3), Vector(0, 0, U), 1e-10 * U);
  // Stagnation points at the poles.
  expect_vectors_near(field, Point(0, 0, a), Vector(0, 0, 0), 1e-15);
  expect_vectors_near(field, Point(0, 0, -a), Vector(0, 0, 0), 1e-15);

  for (const Point& s : sample_points(50, -1, 1, [](const Point& p) { return radius(p) > 0.1; })) {
    const Vector n = (s - CGAL::ORIGIN) / radius(s);
    // No flow through the sphere, and psi and v continuous across it.
    const Point on = CGAL::ORIGIN + a * n;
    EXPECT_NEAR(velocity(field, on) * n, 0, 1e-14);
    EXPECT_NEAR(field.stokes_stream_function(on), 0, 1e-14);
    const Point inside = CGAL::ORIGIN + a * (1 - 1e-9) * n;
    const Point outside = CGAL::ORIGIN + a * (1 + 1e-9) * n;
    EXPECT_LE(norm(velocity(field, inside) - velocity(field, outside)), 1e-8);
    EXPECT_NEAR(field.stokes_stream_function(inside), field.stokes_stream_function(outside), 1e-8);
  }
}

TEST(AnalyticFlowFields, HillSphericalVortexStreamFunctionAndVorticity)
{
  const double a = 2, U = 0.5;
  const FAS::Hill_spherical_vortex<K> field(a, U);
  // Away from the axis (psi/rho) and from the sphere, where the second derivatives jump.
  const std::vector<Point> points = sample_points(
      200, -4, 4, [&](const Point& p) { return rho(p) > 0.05 && std::abs(radius(p) - a) > 1e-3; });
  const auto psi = [&](const Point& p) { return field.stokes_stream_function(p); };
  EXPECT_LE(max_first_integral_defect(field, psi, points), tol);
  expect_meridional_velocity_from_stokes_stream_function(field, psi, points);
  expect_divergence_free(field, points);
  for (const Point& p : points) {
    // Azimuthal vorticity 15 U rho / (2 a^2) inside, none outside.
    const Vector w = curl(fd_jacobian(field, p));
    const double expected = radius(p) < a ? 7.5 * U * rho(p) / (a * a) : 0.;
    const Vector e_theta(-p.y() / rho(p), p.x() / rho(p), 0);
    EXPECT_NEAR(-(w * e_theta), expected, 1e-6) << "at " << p;
    EXPECT_NEAR(norm(w), expected, 1e-6) << "at " << p;
  }
}

TEST(AnalyticFlowFields, PointSourceFlow)
{
  const Point c(1, -1, 2);
  const double q = 3;
  const FAS::Point_source_flow<K> field(c, q);
  EXPECT_FALSE(field(c).has_value());
  // Next to the center the velocity overflows before the distance vanishes.
  const FAS::Point_source_flow<K> at_origin;
  EXPECT_FALSE(at_origin(Point(1e-150, 0, 0)).has_value());
  EXPECT_TRUE(at_origin(Point(1e-100, 0, 0)).has_value());

  const std::vector<Point> points =
      sample_points(100, -2, 4, [&](const Point& p) { return CGAL::squared_distance(p, c) > 0.25; });
  expect_gradient_of_potential(
      field, [&](const Point& p) { return field.potential(p); }, points);
  expect_divergence_free(field, points);
  expect_curl_free(field, points);
  for (const Point& p : points) {
    const Vector d = p - c;
    const double r = norm(d);
    const Vector v = velocity(field, p);
    // Radial, with flux q through every sphere around c.
    EXPECT_LE(norm(CGAL::cross_product(v, d)), 1e-14 * norm(v) * r);
    EXPECT_NEAR(v * d / r * 4 * CGAL_PI * r * r, q, 1e-12 * q);
    // The sphere through p is a level set of the potential.
    EXPECT_NEAR(field.potential(c + r * Vector(0, 0, 1)), field.potential(p), 1e-14);
  }
}

TEST(AnalyticFlowFields, CylinderPotentialFlow)
{
  const double R = 1.5, U = 2;
  const FAS::Cylinder_potential_flow<K> field(R, U);
  EXPECT_FALSE(field(Point(0, 0, 0)).has_value());
  EXPECT_FALSE(field(Point(0.9 * R, 0.4, 7)).has_value());
  EXPECT_FALSE(field(Point(R * (1 - 1e-9), 0, -3)).has_value());

  for (double t = 0; t < 2 * CGAL_PI; t += 0.1) {
    const Point on(R * std::cos(t), R * std::sin(t), 10 * t - 5);
    EXPECT_NEAR(velocity(field, on) * Vector(std::cos(t), std::sin(t), 0), 0, 1e-14 * U);
    EXPECT_NEAR(field.stream_function(on), 0, 1e-14 * U * R);
    // Slip speed on the wall: 2 U |sin theta|.
    EXPECT_NEAR(norm(velocity(field, on)), 2 * U * std::abs(std::sin(t)), 1e-13 * U);
  }
  expect_vectors_near(field, Point(R, 0, 1), Vector(0, 0, 0), 1e-15);
  expect_vectors_near(field, Point(-R, 0, 1), Vector(0, 0, 0), 1e-15);
  expect_vectors_near(field, Point(0, R, -4), Vector(2 * U, 0, 0), 1e-14);
  // Far away: U e_x up to R^2 / rho^2.
  expect_vectors_near(field, Point(3e4, -4e4, 2), Vector(U, 0, 0), 2 * U * R * R / 25e8);

  const std::vector<Point> points =
      sample_points(200, -5, 5, [&](const Point& p) { return rho(p) > R + 1e-3; });
  expect_gradient_of_potential(
      field, [&](const Point& p) { return field.potential(p); }, points);
  const auto psi = [&](const Point& p) { return field.stream_function(p); };
  EXPECT_LE(max_first_integral_defect(field, psi, points), tol);
  EXPECT_LE(max_first_integral_defect(
                field, [](const Point& p) { return p.z(); }, points),
            tol);
  for (const Point& p : points) {
    // v_x = dpsi/dy, v_y = -dpsi/dx fixes the orientation of psi.
    const Vector g = fd_gradient(psi, p);
    expect_vectors_near(field, p, Vector(g.y(), -g.x(), 0), tol * (U + 1e-3));
  }
  expect_divergence_free(field, points);
  expect_curl_free(field, points);
}

TEST(AnalyticFlowFields, SpherePotentialFlow)
{
  const double R = 0.8, U = 3;
  const FAS::Sphere_potential_flow<K> field(R, U);
  EXPECT_FALSE(field(Point(0, 0, 0)).has_value());
  EXPECT_FALSE(field(Point(0.3, -0.2, 0.5)).has_value());
  EXPECT_TRUE(field(Point(0, 0, R)).has_value());

  for (const Point& s : sample_points(100, -1, 1, [](const Point& p) { return radius(p) > 0.1; })) {
    const Vector n = (s - CGAL::ORIGIN) / radius(s);
    const Point on = CGAL::ORIGIN + R * n;
    const Vector v = velocity(field, on);
    EXPECT_NEAR(v * n, 0, 1e-14 * U);
    EXPECT_NEAR(field.stokes_stream_function(on), 0, 1e-14 * U);
    // Slip speed on the wall: 3/2 U sin theta.
    EXPECT_NEAR(norm(v), 1.5 * U * std::sqrt(n.x() * n.x() + n.y() * n.y()), 1e-13 * U);
  }
  expect_vectors_near(field, Point(0, 0, R), Vector(0, 0, 0), 1e-15);
  expect_vectors_near(field, Point(0, 0, -R), Vector(0, 0, 0), 1e-15);
  expect_vectors_near(field, Point(R, 0, 0), Vector(0, 0, 1.5 * U), 1e-14);
  expect_vectors_near(field, Point(1e3, 2e3, -2e3), Vector(0, 0, U), 2 * U * std::pow(R / 3e3, 3));

  const std::vector<Point> points =
      sample_points(200, -3, 3, [&](const Point& p) { return radius(p) > R + 1e-3 && rho(p) > 0.05; });
  expect_gradient_of_potential(
      field, [&](const Point& p) { return field.potential(p); }, points);
  const auto psi = [&](const Point& p) { return field.stokes_stream_function(p); };
  EXPECT_LE(max_first_integral_defect(field, psi, points), tol);
  // Meridional half-planes: the azimuthal angle is a first integral.
  EXPECT_LE(max_first_integral_defect(
                field, [](const Point& p) { return std::atan2(p.y(), p.x()); }, points),
            tol);
  expect_meridional_velocity_from_stokes_stream_function(field, psi, points);
  expect_divergence_free(field, points);
  expect_curl_free(field, points);
}

TEST(AnalyticFlowFields, BurgersVortex)
{
  const double gamma = 3, nu = 0.2, alpha = 0.7;
  const FAS::Burgers_vortex<K> field(gamma, nu, alpha);
  // On the axis only the strain remains, and the field is continuous there.
  expect_vectors_near(field, Point(0, 0, 1.5), Vector(0, 0, 2 * alpha * 1.5), 0);
  expect_vectors_near(field, Point(1e-9, 0, 1.5), Vector(0, 0, 2 * alpha * 1.5), 1e-8);
  // Near the axis: rigid rotation with angular speed Gamma alpha / (4 pi nu).
  const double omega0 = gamma * alpha / (4 * CGAL_PI * nu);
  expect_vectors_near(field, Point(0, 1e-6, 0), Vector(-omega0 * 1e-6, -alpha * 1e-6, 0), 1e-16);
  // Far from the core: potential vortex Gamma / (2 pi rho) plus the radial inflow.
  expect_vectors_near(field, Point(10, 0, 0), Vector(-alpha * 10, gamma / (2 * CGAL_PI * 10), 0), 1e-14);

  const std::vector<Point> points = sample_points(200, -2, 2, [](const Point& p) { return rho(p) > 0.05; });
  const auto psi = [&](const Point& p) { return field.stokes_stream_function(p); };
  EXPECT_LE(max_first_integral_defect(field, psi, points), tol);
  expect_meridional_velocity_from_stokes_stream_function(field, psi, points);
  expect_divergence_free(field, points);
  // The azimuthal angle is not a first integral: the swirl crosses the meridional planes.
  EXPECT_GT(max_first_integral_defect(
                field, [](const Point& p) { return std::atan2(p.y(), p.x()); }, points),
            0.1);
  for (const Point& p : sample_points(50, -2, 2)) {
    // Axial vorticity Gamma alpha / (2 pi nu) exp(-alpha rho^2 / (2 nu)), nothing else.
    const Vector w = curl(fd_jacobian(field, p));
    const double rho2 = p.x() * p.x() + p.y() * p.y();
    const double expected = gamma * alpha / (2 * CGAL_PI * nu) * std::exp(-alpha * rho2 / (2 * nu));
    EXPECT_LE(norm(w - Vector(0, 0, expected)), 1e-6 * (expected + 1)) << "at " << p;
  }
}

TEST(AnalyticFlowFields, CrawfisTornadoAtHandComputedPoints)
{
  // Values computed separately from Crawfis's gen_tornado() loop body with x, y, z set directly.
  const FAS::Crawfis_tornado<K> at0;
  expect_vectors_near(at0, Point(0.3, 0.6, 0.5),
                      Vector(0.11056931648993044, 0.14482954848594876, 0.00393509343971639), 1e-14);
  // Outside the band |r - d| <= r2, where the magnitude factor is 0.8 - |r - d|.
  expect_vectors_near(at0, Point(0.05, 0.95, 0.2), Vector(-0.09344514466694691, -0.021181801245017527, 0),
                      1e-14);
  expect_vectors_near(FAS::Crawfis_tornado<K>(10), Point(0.5, 0.5, 0),
                      Vector(-0.18487121530371145, 0.06421726624562987, 0.018943799796265325), 1e-14);
  expect_vectors_near(FAS::Crawfis_tornado<K>(37), Point(0.9, 0.1, 0.9),
                      Vector(-0.009837409684797106, -0.12081795396635184, 0), 1e-14);
}

TEST(AnalyticFlowFields, CrawfisTornadoDomain)
{
  const FAS::Crawfis_tornado<K> field(3);
  EXPECT_FALSE(field(Point(-1e-9, 0.5, 0.5)).has_value());
  EXPECT_FALSE(field(Point(0.5, 1 + 1e-9, 0.5)).has_value());
  EXPECT_FALSE(field(Point(0.5, 0.5, 2)).has_value());
  EXPECT_FALSE(field(Point(std::nan(""), 0.5, 0.5)).has_value());
  // Defined and finite on the whole closed cube, corners and faces included.
  const int n = 20;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const Point p(double(i) / n, double(j) / n, double(k) / n);
        const Vector v = velocity(field, p);
        ASSERT_TRUE(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z())) << "at " << p;
        EXPECT_LT(norm(v), 10) << "at " << p;
      }
  // The horizontal part is a swirl about the funnel center plus 0.1 times the offset from it.
  for (const Point& p : sample_points(100, 0, 1)) {
    const double z = p.z();
    const double xc = 0.5 + 0.1 * std::sin(0.04 * 3 + 10 * z);
    const double yc = 0.5 + 0.1 * std::cos(0.03 * 3 + 3 * z);
    const Vector d(p.x() - xc, p.y() - yc, 0);
    EXPECT_NEAR(velocity(field, p) * d, 0.1 * d.squared_length(), 1e-15) << "at " << p;
  }
}

} // namespace

} // namespace test_analytic_flow_fields
