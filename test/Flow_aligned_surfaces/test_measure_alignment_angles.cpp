// alignment_angle_statistics and compute_face_alignment_angles against closed forms: linear
// fields whose gradient makes a known angle with a uniform flow, a piecewise uniform flow with
// area-weighted statistics, a slow region left out by min_relative_speed, and the tangential
// parametrization of an exact stream surface.
//
// Where a test quotes the paper's figures (Section 7) it measures what the paper measured, the
// one definition the manual documents: the r of the unnormalized tangential parametrization
// (a_j = v_j, Section 6) over every sampled face (min_relative_speed 0, the default).

#include "centroid_area.h"
#include "expect_invalid_argument.h"
#include "real_data.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_measure_alignment_angles {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;

Mesh::Property_map<Vertex, double> linear_field(Mesh& tm, const Vector_3& w)
{
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  for (Vertex v : tm.vertices())
    r[v] = w * (tm.point(v) - CGAL::ORIGIN);
  return r;
}

TEST(AlignmentAngles, TheGradientOfTheUniformFlowsPotentialIsAlignedAndATurnedOneMakesItsAngle)
{
  // A tilted plane containing u; r = w . x with w in the plane at the angle theta from u.
  const Vector_3 u(1, 2, 0), normal(2, -1, 1.5);
  const auto uniform = [&](const Point_3&) { return std::optional<Vector_3>(u); };
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(1, -1, 2), normal, 1.5, 1.0, 800);
  const Vector_3 a = u / std::sqrt(u.squared_length());
  const Vector_3 n = normal / std::sqrt(normal.squared_length());
  const Vector_3 b = CGAL::cross_product(n, a);
  for (double theta : {0.0, 30.0, 90.0, 150.0}) {
    const double t = theta * CGAL_PI / 180;
    auto r = linear_field(tm, 2.5 * (std::cos(t) * a + std::sin(t) * b));
    const FAS::Alignment_angle_statistics statistics = FAS::alignment_angle_statistics(tm, uniform, r);
    EXPECT_NEAR(statistics.mean, theta, 1e-6);
    EXPECT_NEAR(statistics.standard_deviation, 0, 1e-6);
    EXPECT_EQ(statistics.number_of_faces, tm.number_of_faces());
    EXPECT_NEAR(statistics.area, 1.5, 1e-12);
    tm.remove_property_map(r);
  }
}

TEST(AlignmentAngles, StatisticsAreAreaWeightedAndSkipFacesWithoutASample)
{
  // r = x; the flow is along x where x < 0 (0 degrees), along (1, 1) where 0 <= x < 0.3 (45
  // degrees), outside the domain beyond: mean 45 p, standard deviation 45 sqrt(p (1 - p)) with
  // p the share of the 45-degree area among the measured faces.
  const auto piecewise = [](const Point_3& p) -> std::optional<Vector_3> {
    if (p.x() < 0)
      return Vector_3(3, 0, 0);
    if (p.x() < 0.3)
      return Vector_3(1, 1, 0);
    return std::nullopt;
  };
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 2000);
  auto r = linear_field(tm, Vector_3(1, 0, 0));
  const double aligned = centroid_area(tm, [](const Point_3& c) { return c.x() < 0; }).area;
  const Centroid_area sampled = centroid_area(tm, [](const Point_3& c) { return c.x() < 0.3; });
  const double turned = sampled.area - aligned;
  const std::size_t measured = sampled.number_of_faces;
  const double p = turned / (aligned + turned);
  const FAS::Alignment_angle_statistics statistics = FAS::alignment_angle_statistics(tm, piecewise, r);
  EXPECT_NEAR(statistics.mean, 45 * p, 1e-9);
  EXPECT_NEAR(statistics.standard_deviation, 45 * std::sqrt(p * (1 - p)), 1e-9);
  EXPECT_EQ(statistics.number_of_faces, measured);
  EXPECT_NEAR(statistics.area, aligned + turned, 1e-12);
  // The faces beyond x = 0.3 have no sample: the sampled area fraction, about 0.8.
  EXPECT_NEAR(statistics.sampled_area_fraction, sampled.area / sampled.total_area, 1e-12);
  EXPECT_NEAR(statistics.sampled_area_fraction, 0.8, 0.02);
  EXPECT_EQ(statistics.slow_area_fraction, 0.0);

  auto angles = tm.add_property_map<Mesh::Face_index, double>("f:angle", 0).first;
  FAS::compute_face_alignment_angles(tm, piecewise, r, angles);
  std::size_t undefined = 0;
  for (auto f : tm.faces()) {
    EXPECT_TRUE(angles[f] == -1 || std::abs(angles[f]) < 1e-9 || std::abs(angles[f] - 45) < 1e-9)
        << angles[f];
    undefined += angles[f] == -1;
  }
  EXPECT_EQ(undefined, tm.number_of_faces() - measured);
}

TEST(AlignmentAngles, MinRelativeSpeedLeavesOutTheSlowFacesAndReportsTheirArea)
{
  // r = x; the flow makes 10 degrees with x at speed 1 where y >= -0.3, and 60 degrees at speed
  // 0.01 (1% of the fastest) where y < -0.3, a share p (about 0.2) of the unit square.  Every
  // face (the paper's measure, the default): mean 10 + 50 p, standard deviation
  // 50 sqrt(p (1 - p)).  Faces slower than 2% of the fastest left out: mean 10, deviation 0,
  // and p of the area reported as slow.
  const double fast = 10 * CGAL_PI / 180, slow = 60 * CGAL_PI / 180;
  const auto field = [&](const Point_3& p) -> std::optional<Vector_3> {
    if (p.y() < -0.3)
      return Vector_3(0.01 * std::cos(slow), 0.01 * std::sin(slow), 0);
    return Vector_3(std::cos(fast), std::sin(fast), 0);
  };
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 2000);
  auto r = linear_field(tm, Vector_3(1, 0, 0));
  const Centroid_area slow_region = centroid_area(tm, [](const Point_3& c) { return c.y() < -0.3; });
  const double p = slow_region.area; // the square's area is 1
  const std::size_t slow_faces = slow_region.number_of_faces;
  ASSERT_NEAR(p, 0.2, 0.02);

  const FAS::Alignment_angle_statistics all = FAS::alignment_angle_statistics(tm, field, r);
  EXPECT_NEAR(all.mean, 10 + 50 * p, 1e-9);
  EXPECT_NEAR(all.standard_deviation, 50 * std::sqrt(p * (1 - p)), 1e-9);
  EXPECT_NEAR(all.sampled_area_fraction, 1.0, 1e-12);
  EXPECT_EQ(all.slow_area_fraction, 0.0);
  EXPECT_EQ(all.number_of_faces, tm.number_of_faces());

  for (double threshold : {0.02, 0.5}) { // anything between 0.01 and 1 separates the two
    const FAS::Alignment_angle_statistics fast_only =
        FAS::alignment_angle_statistics(tm, field, r, FAS::parameters::min_relative_speed(threshold));
    EXPECT_NEAR(fast_only.mean, 10, 1e-9) << threshold;
    EXPECT_NEAR(fast_only.standard_deviation, 0, 1e-6) << threshold;
    EXPECT_NEAR(fast_only.slow_area_fraction, p, 1e-12) << threshold;
    EXPECT_NEAR(fast_only.sampled_area_fraction, 1.0, 1e-12) << threshold;
    EXPECT_NEAR(fast_only.area, 1 - p, 1e-12) << threshold;
    EXPECT_EQ(fast_only.number_of_faces, tm.number_of_faces() - slow_faces) << threshold;
  }
  // Below the slow speed's share nothing is left out.
  EXPECT_EQ(FAS::alignment_angle_statistics(tm, field, r, FAS::parameters::min_relative_speed(0.005))
                .slow_area_fraction,
            0.0);

  auto angles = tm.add_property_map<Mesh::Face_index, double>("f:angle", 0).first;
  FAS::compute_face_alignment_angles(tm, field, r, angles, FAS::parameters::min_relative_speed(0.02));
  std::size_t left_out = 0;
  for (auto f : tm.faces()) {
    EXPECT_TRUE(angles[f] == -1 || std::abs(angles[f] - 10) < 1e-9) << angles[f];
    left_out += angles[f] == -1;
  }
  EXPECT_EQ(left_out, slow_faces);

  expect_invalid_argument(
      [&] { FAS::alignment_angle_statistics(tm, field, r, FAS::parameters::min_relative_speed(1.5)); },
      {"alignment_angle_statistics", "min_relative_speed", "[0, 1]"});
}

TEST(AlignmentAngles, TheTangentialParametrizationOfAStreamSurfaceFollowsTheFlow)
{
  // The cylinder x^2 + y^2 = 1 is a stream surface of the helical flow (-y, x, 0.5): a planar
  // patch in (angle, z) wrapped onto two thirds of it.  The paper's best figures (DELTA WING):
  // mean 1.0 degree, standard deviation 0.9.
  const FAS::Helical_flow<K> helical(0.5);
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 4.0, 1.5, 5000);
  for (Vertex v : tm.vertices()) {
    const Point_3 p = tm.point(v);
    tm.point(v) = Point_3(std::cos(p.x()), std::sin(p.x()), p.y());
  }
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  for (bool normalized : {true, false}) {
    FAS::parametrize_tangential(tm, helical, r, s, FAS::parameters::normalized(normalized));
    const FAS::Alignment_angle_statistics statistics = FAS::alignment_angle_statistics(tm, helical, r);
    EXPECT_LE(statistics.mean, 1.0) << normalized;
    EXPECT_LE(statistics.standard_deviation, 0.9) << normalized;
    // s follows the flow nowhere: its gradient is orthogonal to it.
    EXPECT_NEAR(FAS::alignment_angle_statistics(tm, helical, s).mean, 90, 1.0) << normalized;
  }
}

TEST(AlignmentAngles, TheTangentialParametrizationOfADeformedStreamSurfaceFollowsTheFlow)
{
  // A tilted disk beside the axis of the Burgers vortex, aligned tangentially by the deformation
  // (the surface of the example interactive_deformation.cpp), then parametrized.  The paper's
  // best figures (DELTA WING): mean 1.0 degree, standard deviation 0.9.
  const FAS::Burgers_vortex<K> flow;
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(1.0, 0.0, 0.5), Vector_3(0.0, 1.0, 0.3), 0.5, 2000);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::TANGENTIAL);
  ASSERT_LE(report.normalized_flux.value.value(), 0.01);
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  // The paper's measure (unnormalized r, every face) meets them (0.40 and 0.22 degrees): outside
  // its core the vortex is near irrotational, so v is near a gradient on the surface.
  FAS::parametrize_tangential(tm, flow, r, s, FAS::parameters::normalized(false));
  const FAS::Alignment_angle_statistics statistics = FAS::alignment_angle_statistics(tm, flow, r);
  EXPECT_LE(statistics.mean, 1.0);
  EXPECT_LE(statistics.standard_deviation, 0.9);
  EXPECT_EQ(statistics.slow_area_fraction, 0.0);
  EXPECT_EQ(statistics.sampled_area_fraction, 1.0);
}

TEST(AlignmentAngles, OnCFDDataTheTangentialParametrizationFollowsTheFlow)
{
  // The DFG cylinder benchmark (../shared/data/CYLINDER.md): a stream surface in the wake found
  // by the deformation from a tilted square, as in test_read_VTK_legacy.cpp, measured as the
  // paper measured (unnormalized r, every face).  A tangent field is a gradient where its
  // surface curl vanishes: for v, where the flow on the surface has no vorticity.  The wake is
  // sheared, so the paper's STEP figures (2.2 and 2.4 degrees, another flow) are not met here:
  // 3.81 and 4.22 degrees, with no slow face (the normalized r, whose guidance v/|v| is a
  // gradient where stream lines are straight, would give 0.18 and 0.15; it is not what the
  // paper measured).  The bounds are those figures with a 10% margin: a regression guard, not
  // the paper's figures.
  const std::string file = shared_data_file("CYLINDER_grid.vtk");
  if (file.empty())
    GTEST_SKIP() << "CYLINDER_grid.vtk not found in FAS_SHARED_DATA_DIR (../shared/data)";
  // Any grid: the reader replaces it.
  FAS::Regular_grid_flow_field_3<K> field(Point_3(0, 0, 0), Vector_3(1, 1, 1), {{2, 2, 2}},
                                          std::vector<float>(24, 0.f));
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, field, FAS::parameters::error_message(&error))) << error;
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0.8, 0.2, 0.2), Vector_3(0.4, 0.2, 1), 0.15, 0.15, 800);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, field, FAS::Alignment::TANGENTIAL);
  ASSERT_LE(report.normalized_flux.value.value(), 0.02);
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  FAS::parametrize_tangential(tm, field, r, s, FAS::parameters::normalized(false));
  const FAS::Alignment_angle_statistics statistics = FAS::alignment_angle_statistics(tm, field, r);
  RecordProperty("CYLINDER_alignment_mean_degrees", std::to_string(statistics.mean));
  RecordProperty("CYLINDER_alignment_standard_deviation_degrees",
                 std::to_string(statistics.standard_deviation));
  EXPECT_LE(statistics.mean, 4.2);
  EXPECT_LE(statistics.standard_deviation, 4.65);
  EXPECT_EQ(statistics.slow_area_fraction, 0.0);
  EXPECT_EQ(statistics.sampled_area_fraction, 1.0);
}

TEST(AlignmentAngles, NothingToMeasureIsAnError)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 100);
  auto r = linear_field(tm, Vector_3(0, 0, 0));
  const auto uniform = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(1, 0, 0)); };
  expect_invalid_argument([&] { FAS::alignment_angle_statistics(tm, uniform, r); },
                          {"alignment_angle_statistics", "no face", "gradient of r_map"});
}

} // namespace

} // namespace test_measure_alignment_angles
