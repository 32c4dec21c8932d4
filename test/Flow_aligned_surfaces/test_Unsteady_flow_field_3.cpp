// Unsteady_flow_field_3: for steps sampled from a field linear in time,
// v(p, t) = A p + t b + c, the interpolation in time gives v exactly (up to rounding) at every
// intermediate time, with lambdas, analytic flows, grids and unstructured cells as the steps;
// at a step's own time only that step is queried; outside [t_0, t_n] and where a weighted step
// is undefined the answer is std::nullopt; bad times are refused with their index and values.

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include "expect_invalid_argument.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Unsteady_flow_field_3 {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

// v(p, t) = A p + t b + c, linear in space and in time.
Vector exact(const Point& p, double t)
{
  return Vector(0.5 * p.x() - p.y() + 0.25 * p.z() + 2. * t + 1., p.x() + 0.3 * p.y() - 1.5 * t - 0.5,
                -0.7 * p.z() + 0.2 * p.x() + 0.75 * t + 3.);
}

auto step_at(double t)
{
  return [t](const Point& p) -> std::optional<Vector> { return exact(p, t); };
}

void expect_near(const Vector& a, const Vector& b, double tolerance)
{
  EXPECT_NEAR(a.x(), b.x(), tolerance);
  EXPECT_NEAR(a.y(), b.y(), tolerance);
  EXPECT_NEAR(a.z(), b.z(), tolerance);
}

TEST(UnsteadyFlowField, LambdaStepsAreExactForFieldsLinearInTime)
{
  const std::vector<double> times = {-1., 0.5, 0.75, 4.};
  std::vector<decltype(step_at(0.))> steps;
  for (double t : times)
    steps.push_back(step_at(t));
  const FAS::Unsteady_flow_field_3<decltype(step_at(0.))> field(times, steps);
  EXPECT_EQ(field.number_of_steps(), 4u);
  EXPECT_EQ(field.start_time(), -1.);
  EXPECT_EQ(field.end_time(), 4.);
  EXPECT_EQ(field.time(2), 0.75);
  EXPECT_EQ(*field.step(1)(Point(1, 2, 3)), exact(Point(1, 2, 3), 0.5));

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-3., 3.), time(-1., 4.);
  for (int q = 0; q < 200; ++q) {
    const Point p(coordinate(rng), coordinate(rng), coordinate(rng));
    const double t = time(rng);
    const std::optional<Vector> v = field(p, t);
    ASSERT_TRUE(v.has_value()) << t;
    expect_near(*v, exact(p, t), 1e-12);
  }
  // At the steps' own times, the steps' values, bit for bit.
  for (double t : times)
    EXPECT_EQ(*field(Point(0.1, 0.2, 0.3), t), exact(Point(0.1, 0.2, 0.3), t));
  // A copy answers as the original.
  const auto copy = field;
  EXPECT_EQ(*copy(Point(1, 1, 1), 2.), *field(Point(1, 1, 1), 2.));
}

TEST(UnsteadyFlowField, OutsideTheTimeIntervalIsUndefined)
{
  const FAS::Unsteady_flow_field_3<decltype(step_at(0.))> field({0., 1.}, {step_at(0.), step_at(1.)});
  const Point p(0.3, 0.2, 0.1);
  EXPECT_FALSE(field(p, -1e-300));
  EXPECT_FALSE(field(p, std::nextafter(1., 2.)));
  EXPECT_FALSE(field(p, std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(field(p, std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(field(p, 0.));
  EXPECT_TRUE(field(p, 1.));

  // One step: defined at its time only.
  const FAS::Unsteady_flow_field_3<decltype(step_at(0.))> single({2.}, {step_at(2.)});
  EXPECT_EQ(*single(p, 2.), exact(p, 2.));
  EXPECT_FALSE(single(p, std::nextafter(2., 3.)));
  EXPECT_FALSE(single(p, std::nextafter(2., 1.)));
}

// A step that counts its queries and is defined only where x < limit.
struct Counting_step {
  double t, limit;
  std::shared_ptr<int> calls;
  std::optional<Vector> operator()(const Point& p) const
  {
    ++*calls;
    if (!(p.x() < limit))
      return std::nullopt;
    return exact(p, t);
  }
};

TEST(UnsteadyFlowField, OnlyStepsWithNonzeroWeightAreQueried)
{
  auto c0 = std::make_shared<int>(0), c1 = std::make_shared<int>(0), c2 = std::make_shared<int>(0);
  // Step 1 is defined for x < 0 only, its neighbours everywhere.
  const FAS::Unsteady_flow_field_3<Counting_step> field(
      {0., 1., 2.}, {Counting_step{0., 1e9, c0}, Counting_step{1., 0., c1}, Counting_step{2., 1e9, c2}});
  const Point fluid(-1, 0, 0), solid(1, 0, 0);

  // At t_0 and t_2 exactly, step 1 is not asked, so the field is defined where it is not.
  EXPECT_EQ(*field(solid, 0.), exact(solid, 0.));
  EXPECT_EQ(*field(solid, 2.), exact(solid, 2.));
  EXPECT_EQ(*c1, 0);
  EXPECT_EQ(*c0, 1);
  EXPECT_EQ(*c2, 1);
  // Between the steps, step 1 has a nonzero weight: undefined where it is undefined.
  EXPECT_FALSE(field(solid, 0.5));
  EXPECT_FALSE(field(solid, 1.5));
  EXPECT_FALSE(field(solid, 1.));
  expect_near(*field(fluid, 0.5), exact(fluid, 0.5), 1e-12);
  expect_near(*field(fluid, 1.25), exact(fluid, 1.25), 1e-12);
  // At t_1 exactly, only step 1.
  *c0 = *c2 = 0;
  EXPECT_EQ(*field(fluid, 1.), exact(fluid, 1.));
  EXPECT_EQ(*c0, 0);
  EXPECT_EQ(*c2, 0);
}

TEST(UnsteadyFlowField, AnalyticGridAndUnstructuredSteps)
{
  // Analytic flows: a uniform flow u(t) = t b + c (no dependence on p) at two times.
  typedef FAS::Uniform_flow<K> Uniform;
  const Vector b(2., -1.5, 0.75), c(1., -0.5, 3.);
  const FAS::Unsteady_flow_field_3<Uniform> uniform({1., 3.}, {Uniform(1. * b + c), Uniform(3. * b + c)});
  expect_near(*uniform(Point(5, 5, 5), 2.2), 2.2 * b + c, 1e-12);

  // Grids: trilinear interpolation is exact for fields linear in space.
  typedef FAS::Regular_grid_flow_field_3<K> Grid;
  const std::vector<double> times = {0., 0.4, 1.};
  std::vector<Grid> grids;
  for (double t : times)
    grids.push_back(FAS::sample_on_grid(step_at(t), Point(-1, -1, -1), Vector(0.5, 0.25, 1.), {{5, 9, 3}}));
  const FAS::Unsteady_flow_field_3<Grid> grid_series(times, grids);

  // Cells: one hexahedron and one tetrahedron on its top face, linear in space too.
  typedef FAS::Unstructured_flow_field_3<K> Cells;
  const std::vector<double> points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1,   0,   0, 0,
                                      1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 2};
  std::vector<Cells> cells;
  for (double t : times) {
    std::vector<float> vectors;
    for (std::size_t i = 0; i < points.size(); i += 3) {
      const Vector v = exact(Point(points[i], points[i + 1], points[i + 2]), t);
      vectors.insert(vectors.end(), {float(v.x()), float(v.y()), float(v.z())});
    }
    cells.emplace_back(points, std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 8},
                       std::vector<std::int64_t>{0, 8, 12}, std::vector<unsigned char>{12, 10}, vectors);
  }
  const FAS::Unsteady_flow_field_3<Cells> cell_series(times, cells);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0., 1.), time(0., 1.);
  for (int q = 0; q < 100; ++q) {
    const Point p(unit(rng), unit(rng), unit(rng));
    const double t = time(rng);
    // The steps hold 32-bit floats: the tolerance is their rounding.
    expect_near(*grid_series(p, t), exact(p, t), 2e-6);
    expect_near(*cell_series(p, t), exact(p, t), 2e-6);
  }
  EXPECT_FALSE(cell_series(Point(2, 2, 2), 0.5));
  EXPECT_FALSE(grid_series(Point(2, 2, 2), 0.5));
}

// What read_PVD_flow_field() fills: no step, undefined at every time.
TEST(UnsteadyFlowField, DefaultConstructedSeriesIsEmpty)
{
  auto step = [](const Point&) -> std::optional<Vector> { return Vector(1, 0, 0); };
  const FAS::Unsteady_flow_field_3<decltype(step)> series;
  EXPECT_EQ(series.number_of_steps(), 0u);
  for (double t : {0., -1e300, 1e300})
    EXPECT_FALSE(series(Point(0, 0, 0), t).has_value()) << t;
}

TEST(UnsteadyFlowField, BadTimesAreRefusedWithIndexAndValues)
{
  typedef decltype(step_at(0.)) Step;
  typedef FAS::Unsteady_flow_field_3<Step> Series;
  expect_invalid_argument(
      [] {
        Series({0., 1.}, {step_at(0.)});
      },
      {"times.size() is 2", "steps.size() is 1"});
  expect_invalid_argument([] { Series({}, {}); }, {"no step"});
  expect_invalid_argument(
      [] {
        Series({0., std::numeric_limits<double>::quiet_NaN()}, {step_at(0.), step_at(1.)});
      },
      {"times[1]", "nan", "finite"});
  expect_invalid_argument([] { Series({std::numeric_limits<double>::infinity()}, {step_at(0.)}); },
                          {"times[0]", "inf"});
  expect_invalid_argument(
      [] {
        Series({0., 2., 2.}, {step_at(0.), step_at(1.), step_at(2.)});
      },
      {"times[1] = 2", "times[2] = 2", "strictly increasing"});
  expect_invalid_argument(
      [] {
        Series({0., 2., 1.5}, {step_at(0.), step_at(1.), step_at(2.)});
      },
      {"times[1] = 2", "times[2] = 1.5", "strictly increasing"});
}

} // namespace

} // namespace test_Unsteady_flow_field_3
