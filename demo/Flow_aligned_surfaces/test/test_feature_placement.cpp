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

#include <cmath>

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

TEST(FeaturePlacement, NoFlowAnywhere)
{
  const auto none = [](const Point&) { return std::optional<Vector>(); };
  EXPECT_FALSE((fas_demo::place_near_feature<Point, Vector>(none, CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 0.2, 0.5)));
}

} // namespace
