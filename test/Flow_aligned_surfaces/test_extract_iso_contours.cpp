// extract_iso_contours and evenly_spaced_iso_values against closed forms: straight contours of
// linear functions, circles of distance fields (exact and from the heat method), contours split
// by a hole, orientation, values through vertices and outside the range.

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_extract_iso_contours {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Scalar_map = Mesh::Property_map<Vertex, double>;
using Polyline = std::vector<Point_3>;

Scalar_map sample(Mesh& tm, const std::function<double(const Point_3&)>& f)
{
  auto map = tm.add_property_map<Vertex, double>("v:f", 0).first;
  for (Vertex v : tm.vertices())
    map[v] = f(tm.point(v));
  return map;
}

std::vector<Polyline> contours(const Mesh& tm, Scalar_map f, const std::vector<double>& values)
{
  std::vector<Polyline> result;
  FAS::extract_iso_contours(tm, f, values, std::back_inserter(result));
  return result;
}

// Whether `p` lies on a border edge of `tm`.
bool on_border(const Mesh& tm, const Point_3& p)
{
  for (auto h : tm.halfedges())
    if (tm.is_border(h) &&
        CGAL::squared_distance(K::Segment_3(tm.point(tm.source(h)), tm.point(tm.target(h))), p) < 1e-24)
      return true;
  return false;
}

double length(const Polyline& p)
{
  double l = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    l += std::sqrt(CGAL::squared_distance(p[i - 1], p[i]));
  return l;
}

// Twice the signed area enclosed by a polyline in the plane z = const, seen from +z.
double twice_signed_area(const Polyline& p)
{
  double a = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    a += p[i - 1].x() * p[i].y() - p[i].x() * p[i - 1].y();
  return a;
}

TEST(ExtractIsoContours, ContoursOfALinearFunctionAreStraightSegmentsAcrossThePatch)
{
  // f = (x + 2 y) on the rectangle [-1, 1] x [-0.6, 0.6] (normal +z): the contour f = c is the
  // segment of the line x + 2 y = c inside the rectangle.
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 2.0, 1.2, 3000);
  auto f = sample(tm, [](const Point_3& p) { return p.x() + 2 * p.y(); });
  for (double c : {-1.5, -0.2, 0.0, 0.7, 1.9}) {
    const std::vector<Polyline> result = contours(tm, f, {c});
    ASSERT_EQ(result.size(), 1u) << c;
    const Polyline& p = result[0];
    for (const Point_3& q : p)
      EXPECT_NEAR(q.x() + 2 * q.y(), c, 1e-12);
    // The chord: y from max(-0.6, (c - 1)/2) to min(0.6, (c + 1)/2), x = c - 2 y.
    const double y0 = (std::max)(-0.6, (c - 1) / 2), y1 = (std::min)(0.6, (c + 1) / 2);
    EXPECT_NEAR(length(p), (y1 - y0) * std::sqrt(5.0), 1e-12) << c;
    // Higher values on the left seen from +z: n x direction has a positive component along grad f.
    const Vector_3 direction = p.back() - p.front();
    EXPECT_GT(CGAL::cross_product(Vector_3(0, 0, 1), direction) * Vector_3(1, 2, 0), 0);
    EXPECT_FALSE(p.front() == p.back()); // open
  }
}

TEST(ExtractIsoContours, ContoursThroughVerticesAreStraightWithoutRepeatedPoints)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 800);
  auto f = sample(tm, [](const Point_3& p) { return p.y(); });
  // The value of a row of vertices, exactly.
  const double c = tm.point(*std::next(tm.vertices().begin(), 40)).y();
  const std::vector<Polyline> result = contours(tm, f, {c});
  ASSERT_EQ(result.size(), 1u);
  for (std::size_t i = 0; i < result[0].size(); ++i) {
    EXPECT_EQ(result[0][i].y(), c);
    if (i > 0) {
      EXPECT_FALSE(result[0][i] == result[0][i - 1]);
    }
  }
  EXPECT_NEAR(length(result[0]), 1.0, 1e-12);
}

TEST(ExtractIsoContours, ContoursOfTheDistanceAreClosedCirclesInsideAndOpenArcsAcrossTheBorder)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 20000);
  const Point_3 o(0.3, 0, 0);
  auto f = sample(tm, [&](const Point_3& p) { return std::sqrt(CGAL::squared_distance(p, o)); });
  // Radius 0.5 < 0.7: a closed circle; radius 1 > 0.7: an arc ending on the unit circle.
  const std::vector<Polyline> result = contours(tm, f, {0.5, 1.0});
  ASSERT_EQ(result.size(), 2u);
  const Polyline& circle = result[0];
  EXPECT_TRUE(circle.front() == circle.back());
  for (const Point_3& q : circle)
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(q, o)), 0.5, 1e-3);
  // Higher values (outside) on the left: clockwise seen from +z.
  EXPECT_NEAR(twice_signed_area(circle) / 2, -CGAL_PI * 0.25, 1e-3);
  const Polyline& arc = result[1];
  EXPECT_FALSE(arc.front() == arc.back());
  for (const Point_3& end : {arc.front(), arc.back()})
    EXPECT_TRUE(on_border(tm, end));
  for (const Point_3& q : arc)
    EXPECT_NEAR(std::sqrt(CGAL::squared_distance(q, o)), 1.0, 1e-3);
}

TEST(ExtractIsoContours, ContoursOfTheHeatMethodDistanceAreCirclesOfTheRightRadius)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 10000);
  Vertex center = *tm.vertices().begin();
  for (Vertex v : tm.vertices())
    if (tm.point(v) == Point_3(0, 0, 0))
      center = v;
  ASSERT_EQ(tm.point(center), Point_3(0, 0, 0));
  auto d = tm.add_property_map<Vertex, double>("v:d", 0).first;
  FAS::compute_geodesic_distance(tm, center, d);
  const std::vector<double> radii = {0.3, 0.5, 0.8};
  const std::vector<Polyline> result = contours(tm, d, radii);
  ASSERT_EQ(result.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(result[i].front() == result[i].back());
    double mean_radius = 0;
    for (const Point_3& q : result[i])
      mean_radius += std::hypot(q.x(), q.y());
    mean_radius /= double(result[i].size());
    EXPECT_NEAR(mean_radius, radii[i], 0.01 * radii[i]);
  }
}

TEST(ExtractIsoContours, AContourIsSplitWhereItLeavesTheSurface)
{
  // An annulus (the disk minus the faces within 0.4 of the center): the line x = 0.05 crosses
  // the hole, so its contour is two pieces, each from the outer border to the inner one.
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 4000);
  std::vector<Mesh::Face_index> inside;
  for (auto face : tm.faces()) {
    Vector_3 sum(0, 0, 0);
    for (Vertex v : tm.vertices_around_face(tm.halfedge(face)))
      sum = sum + (tm.point(v) - CGAL::ORIGIN);
    if (sum.squared_length() / 9 < 0.16)
      inside.push_back(face);
  }
  for (auto face : inside)
    CGAL::Euler::remove_face(tm.halfedge(face), tm);
  tm.collect_garbage();
  auto f = sample(tm, [](const Point_3& p) { return p.x(); });
  const std::vector<Polyline> result = contours(tm, f, {0.05});
  ASSERT_EQ(result.size(), 2u);
  for (const Polyline& p : result) {
    EXPECT_FALSE(p.front() == p.back());
    for (const Point_3& q : p)
      EXPECT_NEAR(q.x(), 0.05, 1e-12);
    // One end on the outer circle, the other on the hole's border (radius about 0.4).
    EXPECT_TRUE(on_border(tm, p.front()));
    EXPECT_TRUE(on_border(tm, p.back()));
    const double r0 = std::hypot(p.front().x(), p.front().y()), r1 = std::hypot(p.back().x(), p.back().y());
    EXPECT_GT((std::max)(r0, r1), 0.99);
    EXPECT_LT((std::min)(r0, r1), 0.5);
    for (const Point_3& q : p)
      EXPECT_GT(std::hypot(q.x(), q.y()), 0.3);
  }
}

TEST(ExtractIsoContours, ValuesOutsideTheRangeOrAtAnExtremeGiveNothing)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 500);
  auto f = sample(tm, [](const Point_3& p) { return p.x() * p.x() + p.y() * p.y(); });
  EXPECT_TRUE(contours(tm, f, {-1.0, 0.0, 1.0 + 1e-9, 7.0}).empty()); // 0: the minimum, one vertex
}

TEST(ExtractIsoContours, EvenlySpacedValuesAreInsideTheRange)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 2.0, 1.0, 200);
  auto f = sample(tm, [](const Point_3& p) { return p.x(); });
  const std::vector<double> values = FAS::evenly_spaced_iso_values(tm, f, 3);
  ASSERT_EQ(values.size(), 3u);
  EXPECT_NEAR(values[0], -0.5, 1e-15);
  EXPECT_NEAR(values[1], 0.0, 1e-15);
  EXPECT_NEAR(values[2], 0.5, 1e-15);
  EXPECT_EQ(contours(tm, f, values).size(), 3u);
  for (Vertex v : tm.vertices())
    f[v] = 2;
  EXPECT_TRUE(FAS::evenly_spaced_iso_values(tm, f, 3).empty());
}

TEST(ExtractIsoContours, BadInputIsRefusedAndNothingWritten)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 100);
  auto f = sample(tm, [](const Point_3& p) { return p.x(); });
  std::vector<Polyline> result;
  expect_invalid_argument(
      [&] {
        FAS::extract_iso_contours(tm, f, std::vector<double>{0.1, std::numeric_limits<double>::infinity()},
                                  std::back_inserter(result));
      },
      {"extract_iso_contours", "iso-value 1", "not finite"});
  f[*std::next(tm.vertices().begin(), 5)] = std::numeric_limits<double>::quiet_NaN();
  expect_invalid_argument(
      [&] { FAS::extract_iso_contours(tm, f, std::vector<double>{0.1}, std::back_inserter(result)); },
      {"extract_iso_contours", "scalar_map", "vertex 5", "not a number"});
  EXPECT_TRUE(result.empty());
}

} // namespace

} // namespace test_extract_iso_contours
