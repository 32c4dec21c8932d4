// The Dormand-Prince 5(4) integrator against closed-form solutions: x' = λ x (order of the
// method, error within the tolerance), a rotation (dense output), flows leaving a domain (the
// exit point located by bisection), a zero field (stagnation).

#include <CGAL/Flow_aligned_surfaces/internal/Dormand_prince_integrator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Dormand_prince_integrator {

namespace {

using CGAL::Flow_aligned_surfaces::internal::Dormand_prince_integrator;
using CGAL::Flow_aligned_surfaces::internal::Integration_tolerances;
using CGAL::Flow_aligned_surfaces::internal::Step_result;
using Eigen::Vector3d;

// Integrates to τ = T with the dense output landing on T; every loop is bounded.
template <class Field>
Vector3d integrate_to(const Field& f, const Vector3d& x0, double T, Integration_tolerances tol,
                      int direction = 1, std::size_t* steps = nullptr)
{
  Dormand_prince_integrator<Field> dp(f, x0, 0., direction, tol);
  EXPECT_TRUE(dp.is_start_inside());
  for (int i = 0; i < 100000 && dp.parameter() < T; ++i)
    EXPECT_EQ(dp.step(), Step_result::ACCEPTED);
  if (steps)
    *steps = dp.number_of_accepted_steps();
  return dp.dense_output(T);
}

const double lambda = 0.7;
const auto exponential_field = [](const Vector3d& x, double) -> std::optional<Vector3d> {
  return lambda * x;
};

TEST(Dormand_prince_integrator, fifth_order_with_constant_steps)
{
  // Constant steps h = 1/n (initial = max step, a tolerance every step meets): the global error
  // of y' = λ y at τ = 1 falls like h^5.
  const Vector3d x0(1., -2., 0.5);
  const Vector3d exact = std::exp(lambda) * x0;
  double previous_error = 0;
  for (int n : {4, 8, 16}) {
    Integration_tolerances tol;
    tol.relative = 1e6;
    tol.initial_step = tol.max_step = 1. / n;
    std::size_t steps = 0;
    const Vector3d x = integrate_to(exponential_field, x0, 1., tol, 1, &steps);
    EXPECT_EQ(steps, static_cast<std::size_t>(n));
    const double error = (x - exact).norm();
    if (previous_error > 0) {
      const double order = std::log2(previous_error / error);
      EXPECT_GT(order, 4.7) << "n = " << n;
      EXPECT_LT(order, 5.3) << "n = " << n;
    }
    previous_error = error;
  }
}

TEST(Dormand_prince_integrator, adaptive_error_follows_the_tolerance)
{
  // Backward in τ for y' = λ y is y' = -λ y: x(1) = e^{-λ} x0.  The global error stays within a
  // small multiple of the tolerance and shrinks with it.
  const Vector3d x0(1., -2., 0.5);
  for (int direction : {1, -1}) {
    const Vector3d exact = std::exp(direction * lambda * 3.) * x0;
    for (double rtol : {1e-6, 1e-9}) {
      Integration_tolerances tol;
      tol.relative = rtol;
      tol.absolute = rtol * 1e-2;
      const Vector3d x = integrate_to(exponential_field, x0, 3., tol, direction);
      EXPECT_LT((x - exact).norm() / exact.norm(), 10. * rtol) << "direction " << direction;
      EXPECT_GT((x - exact).norm() / exact.norm(), 1e-4 * rtol) << "the tolerance is not used";
    }
  }
}

TEST(Dormand_prince_integrator, dense_output_of_a_rotation)
{
  // x' = (-y, x, 1): x(τ) = (cos τ, sin τ, τ) from (1, 0, 0).  Within each accepted step the
  // 4th-order extension is as accurate as the steps' ends (local error O(h^5)).
  const auto f = [](const Vector3d& x, double) -> std::optional<Vector3d> {
    return Vector3d(-x[1], x[0], 1.);
  };
  const auto exact = [](double t) { return Vector3d(std::cos(t), std::sin(t), t); };
  Integration_tolerances tol;
  tol.relative = 1e-7;
  tol.absolute = 1e-9;
  Dormand_prince_integrator<decltype(f)> dp(f, Vector3d(1., 0., 0.), 0., 1, tol);
  double worst_inside = 0, worst_ends = 0;
  for (int i = 0; i < 10000 && dp.parameter() < 10.; ++i) {
    ASSERT_EQ(dp.step(), Step_result::ACCEPTED);
    EXPECT_EQ(dp.dense_output(dp.parameter()), dp.position());
    EXPECT_EQ(dp.dense_output(dp.previous_parameter()), dp.previous_position());
    worst_ends = std::max(worst_ends, (dp.position() - exact(dp.parameter())).norm());
    for (double theta : {0.25, 0.5, 0.75}) {
      const double tau = dp.previous_parameter() + theta * (dp.parameter() - dp.previous_parameter());
      worst_inside = std::max(worst_inside, (dp.dense_output(tau) - exact(tau)).norm());
    }
  }
  EXPECT_GE(dp.number_of_accepted_steps(), 10u);
  EXPECT_LT(worst_ends, 1e-5);
  EXPECT_LT(worst_inside, 2. * worst_ends + 1e-7);

  // With constant steps the dense output's error at mid-step falls like h^5 (one step, local).
  double previous_error = 0;
  for (double h : {0.4, 0.2, 0.1}) {
    Integration_tolerances fixed;
    fixed.relative = 1e6;
    fixed.initial_step = fixed.max_step = h;
    Dormand_prince_integrator<decltype(f)> one(f, Vector3d(1., 0., 0.), 0., 1, fixed);
    ASSERT_EQ(one.step(), Step_result::ACCEPTED);
    const double error = (one.dense_output(0.5 * h) - exact(0.5 * h)).norm();
    if (previous_error > 0) {
      EXPECT_GT(std::log2(previous_error / error), 4.5) << "h = " << h;
    }
    previous_error = error;
  }
}

TEST(Dormand_prince_integrator, uniform_flow_leaving_a_box)
{
  // v = (1, 0.5, 0) from (0.2, 0.3, 0.5) in the unit box leaves through x = 1 at τ = 0.8, at
  // (1, 0.7, 0.5); the last point is inside and within the boundary tolerance of it.
  const auto f = [](const Vector3d& x, double) -> std::optional<Vector3d> {
    if ((x.array() < 0.).any() || (x.array() > 1.).any())
      return std::nullopt;
    return Vector3d(1., 0.5, 0.);
  };
  for (double boundary : {0., 1e-4}) {
    Integration_tolerances tol;
    tol.boundary = boundary;
    const double expected_tolerance = boundary > 0 ? boundary : tol.absolute + tol.relative * 1.;
    Dormand_prince_integrator<decltype(f)> dp(f, Vector3d(0.2, 0.3, 0.5), 0., 1, tol);
    Step_result r = Step_result::ACCEPTED;
    for (int i = 0; i < 1000 && r == Step_result::ACCEPTED; ++i)
      r = dp.step();
    ASSERT_EQ(r, Step_result::LEFT_DOMAIN);
    const Vector3d exit(1., 0.7, 0.5);
    EXPECT_LE(dp.position()[0], 1.);
    EXPECT_LE((dp.position() - exit).norm(), expected_tolerance);
    EXPECT_NEAR(dp.parameter(), 0.8, expected_tolerance);
    EXPECT_EQ(dp.time(), dp.parameter());
  }
}

TEST(Dormand_prince_integrator, rotation_leaving_a_half_space_backward)
{
  // v = (y, -x, 0) backward (so the point turns counterclockwise) from (1, 0, 0) in y < 0.5, t0
  // = 2: the circle meets y = 0.5 at angle π/6, at (cos π/6, 0.5, 0), at time t = 2 - π/6.
  const auto f = [](const Vector3d& x, double) -> std::optional<Vector3d> {
    if (x[1] >= 0.5)
      return std::nullopt;
    return Vector3d(x[1], -x[0], 0.);
  };
  Integration_tolerances tol;
  tol.relative = 1e-10;
  tol.absolute = 1e-12;
  Dormand_prince_integrator<decltype(f)> dp(f, Vector3d(1., 0., 0.), 2., -1, tol);
  Step_result r = Step_result::ACCEPTED;
  for (int i = 0; i < 1000 && r == Step_result::ACCEPTED; ++i)
    r = dp.step();
  ASSERT_EQ(r, Step_result::LEFT_DOMAIN);
  const double pi = std::acos(-1.);
  EXPECT_LT(dp.position()[1], 0.5);
  EXPECT_LE((dp.position() - Vector3d(std::cos(pi / 6), 0.5, 0.)).norm(), 1e-9);
  EXPECT_NEAR(dp.time(), 2. - pi / 6, 1e-9);
}

TEST(Dormand_prince_integrator, start_outside_and_zero_field)
{
  const auto outside = [](const Vector3d&, double) -> std::optional<Vector3d> { return std::nullopt; };
  Dormand_prince_integrator<decltype(outside)> a(outside, Vector3d(0., 0., 0.), 0., 1);
  EXPECT_FALSE(a.is_start_inside());

  const auto nan_field = [](const Vector3d&, double) -> std::optional<Vector3d> {
    return Vector3d(std::nan(""), 0., 0.);
  };
  Dormand_prince_integrator<decltype(nan_field)> b(nan_field, Vector3d(0., 0., 0.), 0., 1);
  EXPECT_FALSE(b.is_start_inside()) << "a non-finite velocity is outside the domain";

  const auto zero = [](const Vector3d&, double) -> std::optional<Vector3d> { return Vector3d::Zero(); };
  Dormand_prince_integrator<decltype(zero)> c(zero, Vector3d(1., 2., 3.), 0., 1);
  ASSERT_TRUE(c.is_start_inside());
  EXPECT_EQ(c.step(), Step_result::STAGNATION);
  EXPECT_EQ(c.position(), Vector3d(1., 2., 3.));
}

TEST(Dormand_prince_integrator, sink_stagnates)
{
  // x' = -x: |f| decays like e^{-τ}; the default stagnation speed 1e-10 |f(x0)| is reached near
  // τ = ln 1e10 ≈ 23, in a bounded number of steps.
  const auto f = [](const Vector3d& x, double) -> std::optional<Vector3d> { return Vector3d(-x); };
  Dormand_prince_integrator<decltype(f)> dp(f, Vector3d(1., 1., 1.), 0., 1);
  Step_result r = Step_result::ACCEPTED;
  for (int i = 0; i < 10000 && r == Step_result::ACCEPTED; ++i)
    r = dp.step();
  EXPECT_EQ(r, Step_result::STAGNATION);
  EXPECT_LE(dp.position().norm(), 1e-10 * std::sqrt(3.));
  EXPECT_GT(dp.parameter(), std::log(1e10));
  EXPECT_LT(dp.number_of_accepted_steps(), 1000u);
}

} // namespace

} // namespace test_Dormand_prince_integrator
