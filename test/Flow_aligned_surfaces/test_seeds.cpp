// sample_seed_points and project_polyline against what is known independently: the seeds lie on
// the surface, keep the spacing, cover the surface and cannot outnumber a disk packing; a drawn
// polyline projects onto a plane orthogonally and onto a sphere radially, at the asked step.

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_seeds {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;

TEST(Seeds, SeedPointsLieOnTheSurfaceKeepTheSpacingAndCoverIt)
{
  const double spacing = 0.1;
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(1, 2, 3), Vector_3(0, 0, 1), 2.0, 1.0, 2000);
  std::vector<Point_3> seeds;
  FAS::sample_seed_points(tm, spacing, std::back_inserter(seeds));
  for (const Point_3& p : seeds) {
    EXPECT_EQ(p.z(), 3.0);
    EXPECT_LE(std::abs(p.x() - 1), 1.0 + 1e-12);
    EXPECT_LE(std::abs(p.y() - 2), 0.5 + 1e-12);
  }
  for (std::size_t i = 0; i < seeds.size(); ++i)
    for (std::size_t k = i + 1; k < seeds.size(); ++k)
      ASSERT_GE(CGAL::squared_distance(seeds[i], seeds[k]), spacing * spacing);
  // Disks of radius spacing/2 about the seeds are disjoint and lie in the rectangle grown by
  // spacing/2: N pi spacing^2/4 <= (2 + spacing)(1 + spacing).
  EXPECT_LE(double(seeds.size()), (2 + spacing) * (1 + spacing) / (CGAL_PI * spacing * spacing / 4));
  // Coverage: every point of a fine grid over the rectangle is within 1.5 spacing of a seed.
  double farthest = 0;
  for (double x = 0; x <= 2.0; x += 0.02)
    for (double y = 0; y <= 1.0; y += 0.02) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point_3& p : seeds)
        nearest = (std::min)(nearest, CGAL::squared_distance(p, Point_3(x, 1.5 + y, 3)));
      farthest = (std::max)(farthest, std::sqrt(nearest));
    }
  EXPECT_LE(farthest, 1.5 * spacing);
  // The same seed gives the same points; another seed other points.
  std::vector<Point_3> again, other;
  FAS::sample_seed_points(tm, spacing, std::back_inserter(again));
  FAS::sample_seed_points(tm, spacing, std::back_inserter(other), CGAL::parameters::random_seed(7));
  EXPECT_EQ(again, seeds);
  EXPECT_NE(other, seeds);
}

TEST(Seeds, APolylineAboveAPlaneProjectsOrthogonallyAtTheStep)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 2.0, 2.0, 2000);
  // A zig-zag 0.7 above the plane, inside the patch.
  const std::vector<Point_3> drawn = {Point_3(-0.8, -0.5, 0.7), Point_3(-0.2, 0.6, 0.7),
                                      Point_3(0.3, -0.4, 0.7), Point_3(0.8, 0.5, 0.7)};
  const double step = 0.05;
  std::vector<Point_3> curve;
  FAS::project_polyline(tm, drawn, std::back_inserter(curve), FAS::parameters::resampling_step(step));
  ASSERT_GE(curve.size(), 2u);
  EXPECT_LE(CGAL::squared_distance(curve.front(), Point_3(-0.8, -0.5, 0)), 1e-24);
  EXPECT_LE(CGAL::squared_distance(curve.back(), Point_3(0.8, 0.5, 0)), 1e-24);
  double length = 0;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    EXPECT_NEAR(curve[i].z(), 0, 1e-15);
    if (i == 0)
      continue;
    const double d = std::sqrt(CGAL::squared_distance(curve[i - 1], curve[i]));
    length += d;
    EXPECT_LE(d, step * (1 + 1e-9)) << i;
  }
  // The projected zig-zag's length, with its corners cut by at most one step each.
  double exact = 0;
  for (std::size_t i = 1; i < drawn.size(); ++i)
    exact += std::hypot(drawn[i].x() - drawn[i - 1].x(), drawn[i].y() - drawn[i - 1].y());
  EXPECT_LE(length, exact + 1e-12);
  EXPECT_GE(length, exact - 2 * step);
  // Samples every step of arc length along the projected curve, and its end.
  EXPECT_NEAR(double(curve.size()), std::ceil(exact / step) + 1, 1.0);
}

TEST(Seeds, APolylineAroundASphereProjectsRadially)
{
  // The unit sphere: an icosahedron refined by Loop subdivision and pushed onto the sphere.
  Mesh tm;
  CGAL::make_icosahedron(tm, Point_3(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(4));
  for (auto v : tm.vertices())
    tm.point(v) = CGAL::ORIGIN +
                  (tm.point(v) - CGAL::ORIGIN) / std::sqrt((tm.point(v) - CGAL::ORIGIN).squared_length());
  // A closed square of side 2.4 at height 0.3: radial projection known point by point.
  const std::vector<Point_3> drawn = {Point_3(-1.2, -1.2, 0.3), Point_3(1.2, -1.2, 0.3),
                                      Point_3(1.2, 1.2, 0.3), Point_3(-1.2, 1.2, 0.3),
                                      Point_3(-1.2, -1.2, 0.3)};
  std::vector<Point_3> curve;
  FAS::project_polyline(tm, drawn, std::back_inserter(curve));
  EXPECT_EQ(curve.front(), curve.back());
  const double chord_sag = 0.01; // edges of about 0.07 sag below the sphere by under 1e-3
  for (const Point_3& p : curve) {
    const double r = std::sqrt((p - CGAL::ORIGIN).squared_length());
    EXPECT_NEAR(r, 1.0, chord_sag);
  }
  // Radially: the projection of (-1.2, -1.2, 0.3) is that direction on the sphere.
  const Vector_3 corner = drawn[0] - CGAL::ORIGIN;
  EXPECT_LE(std::sqrt(CGAL::squared_distance(curve.front(),
                                             CGAL::ORIGIN + corner / std::sqrt(corner.squared_length()))),
            chord_sag);
}

TEST(Seeds, BadInputIsRefusedAndNothingWritten)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 100);
  std::vector<Point_3> out;
  for (double spacing : {0.0, -1.0, std::numeric_limits<double>::infinity()})
    expect_invalid_argument([&] { FAS::sample_seed_points(tm, spacing, std::back_inserter(out)); },
                            {"sample_seed_points", "spacing must be positive and finite"});
  expect_invalid_argument([&] { FAS::sample_seed_points(tm, 1e-6, std::back_inserter(out)); },
                          {"sample_seed_points", "too small", "5e7"});
  expect_invalid_argument([&] { FAS::project_polyline(tm, std::vector<Point_3>(), std::back_inserter(out)); },
                          {"project_polyline", "no point"});
  const std::vector<Point_3> bad = {Point_3(0, 0, 1),
                                    Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0)};
  expect_invalid_argument([&] { FAS::project_polyline(tm, bad, std::back_inserter(out)); },
                          {"project_polyline", "point 1", "not finite"});
  const std::vector<Point_3> good = {Point_3(0, 0, 1), Point_3(0.5, 0, 1)};
  expect_invalid_argument(
      [&] {
        FAS::project_polyline(tm, good, std::back_inserter(out), FAS::parameters::resampling_step(0.0));
      },
      {"project_polyline", "resampling_step must be positive"});
  EXPECT_TRUE(out.empty());
}

} // namespace

} // namespace test_seeds
