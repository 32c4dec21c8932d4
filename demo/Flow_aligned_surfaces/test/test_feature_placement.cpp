// Where the main job puts its patches in data without --center and --normal
// (feature_placement.h), against flows whose features are known: the potential flow past a
// cylinder of radius 0.5 along z (its obstacle centred on the axis, 1 across, filling the box's
// inner 80% along z; the patches outside it, in the flow, tilted 30 degrees: |n . v| = sin 30
// for the tangential one, cos 30 for the orthogonal one), and a Burgers vortex (no obstacle: the
// largest vorticity is on its axis).

#include "feature_placement.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;

double cosine(const Vector& a, const Vector& b)
{
  return std::abs(a * b) / std::sqrt(a.squared_length() * b.squared_length());
}

TEST(FeaturePlacement, NearTheObstacleTiltedOffTheFlow)
{
  const FAS::Cylinder_potential_flow<K> flow(0.5, 1.0);
  const CGAL::Bbox_3 box(-3, -2, -1, 3, 2, 1);
  const double step = 6.0 / 39; // the lattice's largest spacing
  const auto placed = fas_demo::place_near_feature<Point, Vector>(flow, box, 0.8, CGAL_PI / 6);
  ASSERT_TRUE(placed);
  EXPECT_TRUE(placed->found_obstacle);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(placed->feature, Point(0, 0, 0))), step);
  EXPECT_NEAR(placed->extent[0], 1.0, 2 * step);
  EXPECT_NEAR(placed->extent[1], 1.0, 2 * step);
  EXPECT_NEAR(placed->extent[2], 1.6, 2 * step);
  for (const Point& c : {placed->tangential_center, placed->orthogonal_center}) {
    const auto v = flow(c);
    ASSERT_TRUE(v) << c << " is inside the cylinder";
    // Near: within two patch sizes of the axis.
    EXPECT_LT(std::hypot(c.x(), c.y()), 0.5 + 2 * 0.8) << c;
  }
  EXPECT_NEAR(cosine(placed->tangential_normal, *flow(placed->tangential_center)), std::sin(CGAL_PI / 6), 1e-9);
  EXPECT_NEAR(cosine(placed->orthogonal_normal, *flow(placed->orthogonal_center)), std::cos(CGAL_PI / 6), 1e-9);
  EXPECT_NE(placed->description.find("obstacle"), std::string::npos);

  // A given centre: both patches there, still tilted.
  const auto at = fas_demo::place_near_feature<Point, Vector>(flow, box, 0.8, CGAL_PI / 6, Point(-2, 1, 0));
  ASSERT_TRUE(at);
  EXPECT_EQ(at->tangential_center, Point(-2, 1, 0));
  EXPECT_EQ(at->orthogonal_center, Point(-2, 1, 0));
  EXPECT_NEAR(cosine(at->tangential_normal, *flow(Point(-2, 1, 0))), 0.5, 1e-9);
}

TEST(FeaturePlacement, AtTheLargestVorticityWithoutObstacle)
{
  const FAS::Burgers_vortex<K> flow;
  const CGAL::Bbox_3 box(-1, -1, 0.2, 1, 1, 1.2); // not symmetric in z: a mean flow along z
  const auto placed = fas_demo::place_near_feature<Point, Vector>(flow, box, 0.4, CGAL_PI / 6);
  ASSERT_TRUE(placed);
  EXPECT_FALSE(placed->found_obstacle);
  EXPECT_LT(std::hypot(placed->feature.x(), placed->feature.y()), 2.0 / 39 * 1.5);
  EXPECT_NE(placed->description.find("vorticity"), std::string::npos);
}

// The lattice's sampling order visits each point once, each from a neighbour (one step along one
// axis), fastest along the axis of the smallest step, which is what keeps the queries coherent.
TEST(FeaturePlacement, TheLatticeIsSampledAlongAWalkBetweenNeighbours)
{
  for (const int n : {3, 4, 40}) {
    const std::vector<std::array<int, 3>> visits = fas_demo::lattice_walk(n, {0.5, 0.25, 1.0});
    ASSERT_EQ(visits.size(), std::size_t(n * n * n));
    std::set<std::array<int, 3>> seen(visits.begin(), visits.end());
    EXPECT_EQ(seen.size(), visits.size()) << n;
    EXPECT_EQ(*seen.begin(), (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(*seen.rbegin(), (std::array<int, 3>{n - 1, n - 1, n - 1}));
    for (std::size_t m = 1; m < visits.size(); ++m) {
      int moved = 0;
      for (int a = 0; a < 3; ++a)
        moved += std::abs(visits[m][std::size_t(a)] - visits[m - 1][std::size_t(a)]);
      ASSERT_EQ(moved, 1) << "n = " << n << ", visit " << m;
    }
    EXPECT_EQ(visits[1], (std::array<int, 3>{0, 1, 0}));                  // y first: the smallest step
    EXPECT_EQ(visits[std::size_t(n)], (std::array<int, 3>{1, n - 1, 0})); // then x, back along y
  }
}

TEST(FeaturePlacement, NoFlowAnywhere)
{
  const auto none = [](const Point&) { return std::optional<Vector>(); };
  EXPECT_FALSE((fas_demo::place_near_feature<Point, Vector>(none, CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 0.2, 0.5)));
}

} // namespace
