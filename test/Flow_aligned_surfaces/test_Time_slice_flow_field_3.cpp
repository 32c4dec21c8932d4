// Time_slice_flow_field_3: an unsteady field seen at a time the caller changes.  It answers
// field(p, t) exactly, and Flow_aligned_deformation holding it follows the flow through time
// with no new factorization.  Against analytic unsteady flows whose aligned surfaces are known:
//  - orthogonal: a point source moving along x, v = (p - c(t)) / |p - c(t)|^3, whose orthogonal
//    surfaces are the spheres about c(t); the surface warm-started at t and the one aligned cold
//    at t from the initial patch lie on the same sphere, the one through the patch's centre;
//  - tangential: a swirl about the axis x = 0.2 t, y = 0 (plus an axial drift), whose cylinders
//    about the axis are stream surfaces; a patch tangent to the cylinder of radius 1 at t = 0
//    follows the axis: at time t it lies on the cylinder of radius 1 - 0.2 t, and re-aligns in
//    fewer iterations than an alignment from the initial patch.

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Time_slice_flow_field_3 {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;

Point_3 source_at(double t) { return Point_3(0.3 * t, 0., 0.); }

std::optional<Vector_3> moving_source(const Point_3& p, double t)
{
  const Vector_3 d = p - source_at(t);
  const double r = std::sqrt(d.squared_length());
  return d / (r * r * r);
}

double axis_x_at(double t) { return 0.2 * t; }

std::optional<Vector_3> drifting_swirl(const Point_3& p, double t)
{
  return FAS::Helical_flow<K>(0.3, Point_3(axis_x_at(t), 0., 0.))(p);
}

using Unsteady = std::optional<Vector_3> (*)(const Point_3&, double);
using Slice = FAS::Time_slice_flow_field_3<Unsteady>;
using Deformation = FAS::Flow_aligned_deformation<Mesh, Slice>;

// The largest deviation of the vertices' distances from `center` (to the axis through `center`
// along z when `cylinder`) from `radius`.
double largest_deviation(const Mesh& tm, const Point_3& center, bool cylinder, double radius)
{
  double largest = 0;
  for (Mesh::Vertex_index v : tm.vertices()) {
    Vector_3 d = tm.point(v) - center;
    if (cylinder)
      d = Vector_3(d.x(), d.y(), 0.);
    largest = std::max(largest, std::abs(std::sqrt(d.squared_length()) - radius));
  }
  return largest;
}

TEST(TimeSliceFlowField, AnswersTheUnsteadyFieldAtItsTime)
{
  const Unsteady swirl = &drifting_swirl;
  Slice slice(swirl, 0.25);
  EXPECT_EQ(slice.time(), 0.25);
  const Point_3 p(0.5, -1., 2.);
  EXPECT_EQ(*slice(p), *drifting_swirl(p, 0.25));
  slice.set_time(-3.);
  EXPECT_EQ(*slice(p), *drifting_swirl(p, -3.));
  EXPECT_EQ(slice.unsteady_field(), swirl);
}

TEST(TimeSliceFlowField, InterpolatesATimeSeriesAtItsTime)
{
  // Two steps of the swirl; its velocity is linear in t, so the series is exact in between,
  // and it has no velocity outside [0, 1].
  auto step = [](double t) { return [t](const Point_3& p) { return drifting_swirl(p, t); }; };
  using Step = decltype(step(0.));
  const FAS::Unsteady_flow_field_3<Step> series({0., 1.}, {step(0.), step(1.)});
  FAS::Time_slice_flow_field_3<FAS::Unsteady_flow_field_3<Step>> slice(series, 0.375);
  const Point_3 p(1.5, 0.25, -1.);
  const Vector_3 expected = *drifting_swirl(p, 0.375);
  EXPECT_NEAR(slice(p)->x(), expected.x(), 1e-15);
  EXPECT_NEAR(slice(p)->y(), expected.y(), 1e-15);
  EXPECT_NEAR(slice(p)->z(), expected.z(), 1e-15);
  slice.set_time(1.5);
  EXPECT_FALSE(slice(p));
}

TEST(TimeSliceFlowField, RefusesATimeThatIsNotFinite)
{
  expect_invalid_argument([] { Slice(&drifting_swirl, std::nan("")); }, {"Time_slice_flow_field_3", "nan"});
  Slice slice(&drifting_swirl, 1.);
  expect_invalid_argument([&] { slice.set_time(std::numeric_limits<double>::infinity()); },
                          {"Time_slice_flow_field_3", "inf"});
  EXPECT_EQ(slice.time(), 1.);
}

TEST(TimeSliceFlowField, OrthogonalSurfaceFollowsAMovingSource)
{
  // The patch's centre (0, 0, 1) stays where it is: the sphere about c(t) through it.
  Mesh initial;
  FAS::make_planar_patch(initial, Point_3(0., 0., 1.), Vector_3(0., 0., 1.), 0.6, 0.6, 2000);
  Mesh tm = initial;
  Slice slice(&moving_source, 0.);
  Deformation deformation(tm, slice, FAS::Alignment::ORTHOGONAL);
  ASSERT_TRUE(deformation.run(100).converged);
  for (double t : {0.25, 0.5, 1.}) {
    SCOPED_TRACE(t);
    const double radius = std::sqrt((Point_3(0., 0., 1.) - source_at(t)).squared_length());
    slice.set_time(t);
    ASSERT_TRUE(deformation.run(100).converged);
    EXPECT_LT(largest_deviation(tm, source_at(t), false, radius), 5e-4);

    Mesh cold = initial;
    Slice cold_slice(&moving_source, t);
    Deformation cold_deformation(cold, cold_slice, FAS::Alignment::ORTHOGONAL);
    ASSERT_TRUE(cold_deformation.run(100).converged);
    // The same sphere; the vertices of the two slide apart on it by about 3% of the distance the
    // source moved (the path changes where the faces sit on the level set, not the level set).
    EXPECT_LT(largest_deviation(cold, source_at(t), false, radius), 5e-4);
    double largest_distance = 0;
    for (Mesh::Vertex_index v : tm.vertices())
      largest_distance = std::max(largest_distance, std::sqrt(CGAL::squared_distance(tm.point(v), cold.point(v))));
    EXPECT_LT(largest_distance, 0.05 * std::sqrt((source_at(t) - source_at(0.)).squared_length()));
  }
  EXPECT_EQ(deformation.number_of_factorizations(), 1u);
}

TEST(TimeSliceFlowField, TangentialSurfaceFollowsADriftingSwirl)
{
  // Tangent at t = 0 to the cylinder of radius 1 about the axis, at the axis' side x = 1.
  Mesh initial;
  FAS::make_planar_patch(initial, Point_3(1., 0., 0.), Vector_3(1., 0., 0.), 0.6, 0.6, 2000);
  Mesh tm = initial;
  Slice slice(&drifting_swirl, 0.);
  Deformation deformation(tm, slice, FAS::Alignment::TANGENTIAL);
  ASSERT_TRUE(deformation.run(100).converged);
  EXPECT_LT(largest_deviation(tm, Point_3(axis_x_at(0.), 0., 0.), true, 1.), 1e-2);
  for (double t : {0.25, 0.5, 1.}) {
    SCOPED_TRACE(t);
    slice.set_time(t);
    const FAS::Alignment_report warm = deformation.run(100);
    ASSERT_TRUE(warm.converged);
    ASSERT_TRUE(warm.normalized_flux.value);
    EXPECT_LT(*warm.normalized_flux.value, 5e-3);
    EXPECT_LT(largest_deviation(tm, Point_3(axis_x_at(t), 0., 0.), true, 1. - axis_x_at(t)), 2e-2);

    Mesh cold = initial;
    Slice cold_slice(&drifting_swirl, t);
    Deformation cold_deformation(cold, cold_slice, FAS::Alignment::TANGENTIAL);
    const FAS::Alignment_report from_the_patch = cold_deformation.run(100);
    ASSERT_TRUE(from_the_patch.converged);
    EXPECT_LT(warm.number_of_iterations, from_the_patch.number_of_iterations);
  }
  EXPECT_EQ(deformation.number_of_factorizations(), 1u);
}

} // namespace

} // namespace test_Time_slice_flow_field_3
