// integrate_streamline() and integrate_pathline() against answers known in closed form: linear
// flows (the matrix exponential, Eigen's own), first integrals of Hill's vortex and of the ABC
// flow with C = 0, exit points of a box, a sink, arc lengths of a helix, a path line of an
// unsteady field with a closed-form solution, a linear field sampled on a grid (reproduced
// exactly by trilinear interpolation); and bad input.

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_integrate_streamline {

namespace {

using namespace fas_test;
using FAS::Integration_direction;
using FAS::Streamline_termination;

const double pi = std::acos(-1.);

Eigen::Vector3d to_eigen(const Point_3& p)
{
  return Eigen::Vector3d(p.x(), p.y(), p.z());
}

// A flow x' = A x as a lambda (the analytic Linear_flow is the same flow; the lambda keeps the
// matrix in Eigen for the exponential).
auto linear_field(const Eigen::Matrix3d& A)
{
  return [A](const Point_3& p) -> std::optional<Vector_3> {
    const Eigen::Vector3d v = A * to_eigen(p);
    return Vector_3(v[0], v[1], v[2]);
  };
}

TEST(integrate_streamline, linear_flows_match_the_matrix_exponential)
{
  Eigen::Matrix3d spiral, saddle, shear;
  spiral << -0.1, -1., 0., 1., -0.1, 0., 0., 0., 0.2; // a focus in the xy-plane, growth along z
  saddle << 1., 0., 0., 0., 1., 0., 0., 0., -2.;
  shear << 0., 1., 0., 0., 0., 1., -0.5, 0., 0.; // non-normal
  const Eigen::Vector3d x0(0.8, -0.3, 0.5);
  for (const Eigen::Matrix3d& A : {spiral, saddle, shear})
    for (double rtol : {1e-6, 1e-9}) {
      const double T = 3.;
      std::vector<Point_3> points;
      const FAS::Streamline_report r = FAS::integrate_streamline(
          linear_field(A), Point_3(x0[0], x0[1], x0[2]), std::back_inserter(points),
          FAS::parameters::max_time(T,
                                    FAS::parameters::output_time_step(
                                        0.5, FAS::parameters::relative_tolerance(
                                                 rtol, FAS::parameters::absolute_tolerance(rtol * 1e-2)))));
      EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_TIME);
      EXPECT_EQ(r.backward.termination, Streamline_termination::NOT_INTEGRATED);
      EXPECT_DOUBLE_EQ(r.forward.integration_time, T);
      ASSERT_EQ(points.size(), 7u) << "the seed and the samples at 0.5, 1, ..., 3";
      for (std::size_t k = 0; k < points.size(); ++k) {
        const Eigen::Vector3d exact = (A * (0.5 * double(k))).exp() * x0;
        // The global error of a tolerance-per-step method: a few tolerances over ~30 steps.
        EXPECT_LT((to_eigen(points[k]) - exact).norm(), 20. * rtol * exact.norm()) << "k = " << k;
      }
    }
}

TEST(integrate_streamline, linear_flow_backward_and_both)
{
  Eigen::Matrix3d A;
  A << -0.1, -1., 0., 1., -0.1, 0., 0., 0., 0.2;
  const Eigen::Vector3d x0(0.8, -0.3, 0.5);
  std::vector<Point_3> points;
  const auto r = FAS::integrate_streamline(
      linear_field(A), Point_3(x0[0], x0[1], x0[2]), std::back_inserter(points),
      FAS::parameters::max_time(
          2., FAS::parameters::output_time_step(
                  1., FAS::parameters::integration_direction(Integration_direction::BOTH))));
  EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_TIME);
  EXPECT_EQ(r.backward.termination, Streamline_termination::MAX_TIME);
  ASSERT_EQ(r.number_of_points, 5u);
  ASSERT_EQ(points.size(), 5u);
  // Flow order: x(-2), x(-1), seed, x(1), x(2).
  for (int k = -2; k <= 2; ++k) {
    const Eigen::Vector3d exact = (A * double(k)).exp() * x0;
    EXPECT_LT((to_eigen(points[std::size_t(k + 2)]) - exact).norm(), 1e-7) << "t = " << k;
  }
  EXPECT_EQ(points[2], Point_3(x0[0], x0[1], x0[2]));
}

TEST(integrate_streamline, first_integral_of_Hills_vortex)
{
  // Inside, ψ = -3/4 U ρ² (1 - r²/a²) (Stokes stream function, derived from
  // v = 3U/(2a²) (-xz, -yz, 2ρ² + z² - a²)) and the azimuth y/x are constant along lines.
  // Relative to ψ0, which is small near the axis (the second seed, ψ0 = -5.9e-3), the default
  // tolerance 1e-8 gives drifts 8.6e-8, 5.3e-7, 5.9e-8; 1e-9 gives 8.8e-9, 1.6e-8, 6.0e-9.
  const double a = 1., U = 1.;
  FAS::Hill_spherical_vortex<K> hill(a, U);
  const auto psi = [&](const Point_3& p) {
    const double rho2 = p.x() * p.x() + p.y() * p.y(), r2 = rho2 + p.z() * p.z();
    return -0.75 * U * rho2 * (1. - r2 / (a * a));
  };
  for (const Point_3& seed : {Point_3(0.5, 0.2, 0.1), Point_3(0.1, 0.05, -0.6), Point_3(-0.7, 0.3, 0.)}) {
    std::vector<Point_3> points;
    const auto r = FAS::integrate_streamline(
        hill, seed, std::back_inserter(points),
        FAS::parameters::max_length(
            20., FAS::parameters::relative_tolerance(1e-9, FAS::parameters::absolute_tolerance(1e-11))));
    EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_LENGTH);
    EXPECT_GT(points.size(), 20u);
    const double psi0 = psi(seed), azimuth0 = std::atan2(seed.y(), seed.x());
    double worst = 0, worst_azimuth = 0;
    for (const Point_3& p : points) {
      worst = std::max(worst, std::abs(psi(p) - psi0) / std::abs(psi0));
      worst_azimuth = std::max(worst_azimuth, std::abs(std::atan2(p.y(), p.x()) - azimuth0));
      EXPECT_LT((p - CGAL::ORIGIN).squared_length(), a * a) << "a vortex line stays inside";
    }
    EXPECT_LE(worst, 1e-7) << "seed " << seed;
    EXPECT_LE(worst_azimuth, 1e-9) << "seed " << seed;
  }
}

TEST(integrate_streamline, first_integral_of_ABC_with_C_zero)
{
  // v = (A sin z, B sin x + A cos z, B cos x) (C = 0) is independent of y.  With I = A cos z +
  // B sin x: ∇I = (B cos x, 0, -A sin z), and ∇I · v = AB cos x sin z - AB sin z cos x = 0.
  const double A = std::sqrt(3.), B = std::sqrt(2.);
  FAS::ABC_flow<K> abc(A, B, 0.);
  const auto I = [&](const Point_3& p) { return A * std::cos(p.z()) + B * std::sin(p.x()); };
  // The scale of I is A + B; compare the drift with it (I itself may cross 0).
  for (const Point_3& seed : {Point_3(0.3, 0.1, 0.2), Point_3(2., 1., 4.), Point_3(4.5, 3., 1.)}) {
    std::vector<Point_3> points;
    const auto r = FAS::integrate_streamline(
        abc, seed, std::back_inserter(points),
        FAS::parameters::max_length(30.,
                                    FAS::parameters::integration_direction(Integration_direction::BOTH)));
    EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_LENGTH);
    EXPECT_EQ(r.backward.termination, Streamline_termination::MAX_LENGTH);
    EXPECT_DOUBLE_EQ(r.length(), 60.);
    double worst = 0;
    for (const Point_3& p : points)
      worst = std::max(worst, std::abs(I(p) - I(seed)) / (A + B));
    EXPECT_LE(worst, 1e-7) << "seed " << seed;
    EXPECT_GT(worst, 0.) << "exactly constant: the test would not see a drift";
  }
}

// The helix x' = (-y, x, c) from (1, 0, 0): x(τ) = (cos τ, sin τ, c τ), speed sqrt(1 + c²).
const double c_helix = 0.5;
const FAS::Helical_flow<K> helix(c_helix);
Eigen::Vector3d helix_point(double tau)
{
  return Eigen::Vector3d(std::cos(tau), std::sin(tau), c_helix * tau);
}

TEST(integrate_streamline, max_length_lands_on_the_limit)
{
  const double speed = std::sqrt(1. + c_helix * c_helix);
  for (double L : {1., 7.3}) {
    std::vector<Point_3> points;
    const auto r = FAS::integrate_streamline(helix, Point_3(1., 0., 0.), std::back_inserter(points),
                                             FAS::parameters::max_length(L));
    EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_LENGTH);
    EXPECT_DOUBLE_EQ(r.forward.length, L);
    // Arc length and position within the global error of the tolerance 1e-8 over τ ≤ 6.5.
    EXPECT_NEAR(r.forward.integration_time, L / speed, 5e-8);
    EXPECT_LT((to_eigen(points.back()) - helix_point(L / speed)).norm(), 5e-8);
    EXPECT_EQ(points.size(), r.number_of_points);
    EXPECT_EQ(points.size(), r.forward.number_of_accepted_steps + 1);
  }
  // Samples every Δs of arc length: at τ = k Δs / speed.
  std::vector<Point_3> points;
  const auto r =
      FAS::integrate_streamline(helix, Point_3(1., 0., 0.), std::back_inserter(points),
                                FAS::parameters::max_length(2.05, FAS::parameters::output_length_step(0.25)));
  ASSERT_EQ(points.size(), 10u) << "seed, 8 samples, the end";
  for (std::size_t k = 0; k < 9; ++k)
    EXPECT_LT((to_eigen(points[k]) - helix_point(0.25 * double(k) / speed)).norm(), 2e-8) << k;
  EXPECT_LT((to_eigen(points.back()) - helix_point(2.05 / speed)).norm(), 2e-8);
  EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_LENGTH);
}

TEST(integrate_streamline, leaves_a_box_on_its_boundary)
{
  // The helix in the box |y| ≤ 0.5 leaves at angle ±π/6: at (cos π/6, ±1/2, ±c π/6).
  const auto boxed = [](const Point_3& p) -> std::optional<Vector_3> {
    if (std::abs(p.y()) > 0.5 || std::abs(p.x()) > 2. || std::abs(p.z()) > 2.)
      return std::nullopt;
    return helix(p);
  };
  std::vector<Point_3> points;
  const auto r =
      FAS::integrate_streamline(boxed, Point_3(1., 0., 0.), std::back_inserter(points),
                                FAS::parameters::integration_direction(Integration_direction::BOTH));
  EXPECT_EQ(r.forward.termination, Streamline_termination::LEFT_DOMAIN);
  EXPECT_EQ(r.backward.termination, Streamline_termination::LEFT_DOMAIN);
  const Eigen::Vector3d exit_forward = helix_point(pi / 6), exit_backward = helix_point(-pi / 6);
  // Within the boundary tolerance 1e-10 + 1e-8 |x| plus the integration error.
  EXPECT_LT((to_eigen(points.back()) - exit_forward).norm(), 3e-8);
  EXPECT_LT((to_eigen(points.front()) - exit_backward).norm(), 3e-8);
  EXPECT_LE(points.back().y(), 0.5);
  EXPECT_GE(points.front().y(), -0.5);
  EXPECT_NEAR(r.forward.integration_time, pi / 6, 3e-8);
  for (std::size_t i = 1; i < points.size(); ++i)
    EXPECT_GT(points[i].z(), points[i - 1].z()) << "flow order";
}

TEST(integrate_streamline, stagnation_at_a_sink)
{
  // x' = -x: the straight line to the origin, of length |x0|; the speed falls to 1e-10 |x0|.
  FAS::Linear_flow<K> sink(-1, 0, 0, 0, -1, 0, 0, 0, -1);
  std::vector<Point_3> points;
  const auto r = FAS::integrate_streamline(sink, Point_3(0.3, 0.4, 1.2), std::back_inserter(points));
  EXPECT_EQ(r.forward.termination, Streamline_termination::STAGNATION);
  EXPECT_NEAR(r.forward.length, 1.3, 1e-8);
  EXPECT_LT(std::sqrt((points.back() - CGAL::ORIGIN).squared_length()), 1.3e-10 * 1.0001);
  EXPECT_LT(r.forward.number_of_accepted_steps, 500u);
}

TEST(integrate_streamline, max_number_of_steps)
{
  std::vector<Point_3> points;
  const auto r = FAS::integrate_streamline(helix, Point_3(1., 0., 0.), std::back_inserter(points),
                                           FAS::parameters::max_number_of_steps(7));
  EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_NUMBER_OF_STEPS);
  EXPECT_EQ(r.forward.number_of_accepted_steps, 7u);
  EXPECT_EQ(points.size(), 8u);
  for (const Point_3& p : points) // on the helix: radius 1, angle z / c
    EXPECT_NEAR(std::atan2(p.y(), p.x()), std::remainder(p.z() / c_helix, 2 * pi), 1e-8);
}

// v(x, t) = (-y, x, t) given by two steps at t = 0 and t = 2 (linear in time, so
// Unsteady_flow_field_3 is exact); from (1, 0, 0.2) at t0 = 0.5: x(t) = R(t - t0) x0 in xy,
// z = z0 + (t² - t0²)/2.
struct Rising_rotation_step {
  double t;
  std::optional<Vector_3> operator()(const Point_3& p) const { return Vector_3(-p.y(), p.x(), t); }
};
const FAS::Unsteady_flow_field_3<Rising_rotation_step> rising_rotation({0., 2.},
                                                                       {Rising_rotation_step{0.},
                                                                        Rising_rotation_step{2.}});
const double t0_rising = 0.5;
Eigen::Vector3d rising_rotation_path(double t)
{
  const double t0 = t0_rising;
  return Eigen::Vector3d(std::cos(t - t0), std::sin(t - t0), 0.2 + 0.5 * (t * t - t0 * t0));
}

TEST(integrate_pathline, unsteady_field_with_a_closed_form)
{
  const auto& field = rising_rotation;
  const double t0 = t0_rising;
  const auto exact = rising_rotation_path;
  std::vector<Point_3> points;
  const auto r = FAS::integrate_pathline(
      field, Point_3(1., 0., 0.2), t0, std::back_inserter(points),
      FAS::parameters::max_time(
          0.4, FAS::parameters::output_time_step(
                   0.1, FAS::parameters::integration_direction(Integration_direction::BOTH))));
  // Backward to t = 0.1 (max time), forward to t = 0.9 (max time).
  EXPECT_EQ(r.backward.termination, Streamline_termination::MAX_TIME);
  EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_TIME);
  ASSERT_EQ(points.size(), 9u);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double t = 0.1 + 0.1 * double(k);
    EXPECT_LT((to_eigen(points[k]) - exact(t)).norm(), 1e-8) << "t = " << t;
  }
  // Forward without a limit: the field ends at t = 2, where the line stops.
  points.clear();
  const auto r2 = FAS::integrate_pathline(field, Point_3(1., 0., 0.2), t0, std::back_inserter(points));
  EXPECT_EQ(r2.forward.termination, Streamline_termination::LEFT_DOMAIN);
  EXPECT_NEAR(r2.forward.integration_time, 1.5, 1e-8);
  EXPECT_LT((to_eigen(points.back()) - exact(2.)).norm(), 1e-7);
}

TEST(integrate_pathline, writes_the_time_of_every_step)
{
  // At the integrator's own steps (no output step) the times are not known in advance: every
  // point must be the closed-form path line at the time written beside it.
  const auto& field = rising_rotation;
  const double t0 = t0_rising;
  const auto exact = rising_rotation_path;
  std::vector<Point_3> points;
  std::vector<double> times;
  const auto r = FAS::integrate_pathline(
      field, Point_3(1., 0., 0.2), t0, std::back_inserter(points),
      FAS::parameters::time_output_iterator(
          std::back_inserter(times), FAS::parameters::integration_direction(Integration_direction::BOTH)));
  ASSERT_EQ(times.size(), points.size());
  ASSERT_GT(points.size(), 10u);
  EXPECT_DOUBLE_EQ(times.front(), t0 - r.backward.integration_time);
  EXPECT_DOUBLE_EQ(times.back(), t0 + r.forward.integration_time);
  EXPECT_NEAR(times.front(), 0., 1e-8) << "backward to the start of the field's time range";
  EXPECT_NEAR(times.back(), 2., 1e-8) << "forward to its end";
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (k > 0) {
      EXPECT_GT(times[k], times[k - 1]);
    }
    EXPECT_LT((to_eigen(points[k]) - exact(times[k])).norm(), 1e-7) << "t = " << times[k];
  }
  EXPECT_EQ(std::count(times.begin(), times.end(), t0), 1) << "the seed, once, at t0";
}

TEST(integrate_pathline, ends_where_the_series_ends_at_max_time)
{
  // A time series from 6.5 to 6.833373 integrated from its start for max_time = 6.833373 - 6.5
  // (whose sum with 6.5 rounds past the series' end): the line ends at max_time, on the last
  // step's flow, not as a line leaving the field's time range short of it.
  const FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>> flow(
      {6.5, 6.833373}, {FAS::Uniform_flow<K>(Vector_3(1, 0, 0)), FAS::Uniform_flow<K>(Vector_3(1, 1, 0))});
  const double duration = 6.833373 - 6.5;
  std::vector<Point_3> points;
  const auto r = FAS::integrate_pathline(flow, Point_3(0, 0, 0), 6.5, std::back_inserter(points),
                                         FAS::parameters::max_time(duration));
  EXPECT_EQ(r.forward.termination, Streamline_termination::MAX_TIME);
  EXPECT_EQ(r.forward.integration_time, duration);
  EXPECT_NEAR(points.back().x(), duration, 1e-9);
}

TEST(integrate_streamline, writes_signed_integration_times)
{
  // A stream line's times are the signed integration times: negative on the backward half.
  Eigen::Matrix3d A;
  A << -0.1, -1., 0., 1., -0.1, 0., 0., 0., 0.2;
  const Eigen::Vector3d x0(0.8, -0.3, 0.5);
  std::vector<Point_3> points;
  std::vector<double> times;
  FAS::integrate_streamline(
      linear_field(A), Point_3(x0[0], x0[1], x0[2]), std::back_inserter(points),
      FAS::parameters::max_time(
          2., FAS::parameters::integration_direction(
                  Integration_direction::BOTH, FAS::parameters::time_output_iterator(std::back_inserter(times)))));
  ASSERT_EQ(times.size(), points.size());
  EXPECT_DOUBLE_EQ(times.front(), -2.);
  EXPECT_DOUBLE_EQ(times.back(), 2.);
  for (std::size_t k = 0; k < points.size(); ++k)
    EXPECT_LT((to_eigen(points[k]) - (A * times[k]).exp() * x0).norm(), 1e-7) << "t = " << times[k];
}

TEST(integrate_streamline, linear_field_on_a_grid)
{
  // Trilinear interpolation reproduces a linear field, so on the grid the line is the matrix
  // exponential up to the nodes' float rounding (~1e-7 relative); it stops on the grid's box.
  Eigen::Matrix3d A;
  A << 0.1, -1., 0., 1., 0.1, 0., 0., 0., 0.3;
  const auto grid =
      FAS::sample_on_grid(linear_field(A), Point_3(-1., -1., -1.), Vector_3(0.1, 0.1, 0.1), {21, 21, 21});
  const Eigen::Vector3d x0(0.5, 0., -0.3); // leaves through z = -1 at t = ln(10/3)/0.3 ≈ 4.01
  std::vector<Point_3> points;
  const auto r = FAS::integrate_streamline(grid, Point_3(x0[0], x0[1], x0[2]), std::back_inserter(points),
                                           FAS::parameters::output_time_step(0.25));
  EXPECT_EQ(r.forward.termination, Streamline_termination::LEFT_DOMAIN);
  ASSERT_EQ(points.size(), 18u) << "the seed, 16 samples, the exit";
  EXPECT_NEAR(r.forward.integration_time, std::log(10. / 3.) / 0.3, 1e-5);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Eigen::Vector3d exact = (A * (0.25 * double(k))).exp() * x0;
    EXPECT_LT((to_eigen(points[k]) - exact).norm(), 1e-5) << k;
  }
  // The spiral grows (trace > 0) and leaves through a side of the box [-1, 1]^3.
  const Eigen::Vector3d last = to_eigen(points.back());
  EXPECT_NEAR(last.z(), -1., 1e-7);
  EXPECT_GE(last.z(), -1.);
  const Eigen::Vector3d exact_last = (A * r.forward.integration_time).exp() * x0;
  EXPECT_LT((last - exact_last).norm(), 1e-5);
}

TEST(integrate_streamline, seed_outside_and_zero_field)
{
  const auto ball = [](const Point_3& p) -> std::optional<Vector_3> {
    if ((p - CGAL::ORIGIN).squared_length() > 1.)
      return std::nullopt;
    return Vector_3(1., 0., 0.);
  };
  std::vector<Point_3> points;
  const auto r =
      FAS::integrate_streamline(ball, Point_3(2., 0., 0.), std::back_inserter(points),
                                FAS::parameters::integration_direction(Integration_direction::BOTH));
  EXPECT_TRUE(points.empty());
  EXPECT_EQ(r.number_of_points, 0u);
  EXPECT_FALSE(r.seed_inside_domain());
  EXPECT_EQ(r.forward.termination, Streamline_termination::SEED_OUTSIDE_DOMAIN);
  EXPECT_EQ(r.backward.termination, Streamline_termination::SEED_OUTSIDE_DOMAIN);
  EXPECT_STREQ(FAS::to_string(r.forward.termination), "SEED_OUTSIDE_DOMAIN");

  const auto zero = [](const Point_3&) -> std::optional<Vector_3> { return CGAL::NULL_VECTOR; };
  const auto z =
      FAS::integrate_streamline(zero, Point_3(1., 2., 3.), std::back_inserter(points),
                                FAS::parameters::integration_direction(Integration_direction::BOTH));
  EXPECT_EQ(z.forward.termination, Streamline_termination::STAGNATION);
  EXPECT_EQ(z.backward.termination, Streamline_termination::STAGNATION);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0], Point_3(1., 2., 3.));
  EXPECT_EQ(z.length(), 0.);
}

TEST(integrate_streamline, bad_input_is_refused_naming_the_parameter)
{
  namespace P = FAS::parameters;
  std::vector<Point_3> points;
  const Point_3 seed(1., 0., 0.);
  const auto run = [&](const auto& np) {
    return [&, np] { FAS::integrate_streamline(helix, seed, std::back_inserter(points), np); };
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double bad : {0., -1e-8, nan, inf}) {
    expect_invalid_argument(run(P::relative_tolerance(bad)), {"integrate_streamline", "relative_tolerance"});
    expect_invalid_argument(run(P::absolute_tolerance(bad)), {"absolute_tolerance"});
    expect_invalid_argument(run(P::max_length(bad)), {"max_length"});
    expect_invalid_argument(run(P::max_time(bad)), {"max_time"});
    expect_invalid_argument(run(P::output_time_step(bad)), {"output_time_step"});
    expect_invalid_argument(run(P::output_length_step(bad)), {"output_length_step"});
  }
  expect_invalid_argument(run(P::max_number_of_steps(0)), {"max_number_of_steps"});
  expect_invalid_argument(run(P::output_time_step(0.1, P::output_length_step(0.1))),
                          {"output_time_step", "output_length_step"});
  expect_invalid_argument(
      [&] { FAS::integrate_streamline(helix, Point_3(nan, 0., 0.), std::back_inserter(points)); },
      {"integrate_streamline", "seed", "nan"});
  const auto steady_as_unsteady = [](const Point_3& p, double) { return helix(p); };
  expect_invalid_argument(
      [&] { FAS::integrate_pathline(steady_as_unsteady, seed, nan, std::back_inserter(points)); },
      {"integrate_pathline", "t0"});
  EXPECT_TRUE(points.empty()) << "nothing written on bad input";
}

} // namespace

} // namespace test_integrate_streamline
