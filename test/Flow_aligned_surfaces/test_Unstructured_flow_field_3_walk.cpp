// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unstructured_flow_field_3's walk from the last hit cell: streams of queries along paths with
// steps of 0.1, 0.7 and 2.5 cells (so that the walk crosses zero, one or several faces, or gives
// up and the hierarchy answers) through jittered hexahedra and tetrahedra must return the
// linear field v(p) = A p + b, which both interpolations reproduce exactly, and a cell that
// contains the point; paths leaving the mesh get std::nullopt there and are found again when
// they come back.  And the answer at a point does not depend on the queries before it: the same
// bits in any order and on another thread, at the mesh's vertices (in up to 8 cells), on the
// middles of its edges and anywhere, and the located cell is the smallest containing the point.

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include "jittered_cube_mesh.h"
#include "test_kernel.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <thread>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Unstructured_flow_field_3_walk {

namespace {

using namespace fas_test;
typedef FAS::Unstructured_flow_field_3<K> Field;

const int n = 8; // cubes per axis of [0, 1]^3

Field make_field(bool tetrahedra)
{
  return jittered_cube_field(n, tetrahedra, 3);
}

void check_paths(const Field& field, double step_in_cells)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> start(0.05, 0.95);
  std::normal_distribution<double> g(0., 1.);
  int inside = 0, outside = 0;
  for (int path = 0; path < 40; ++path) {
    double x[3] = {start(rng), start(rng), start(rng)}, d[3] = {g(rng), g(rng), g(rng)};
    for (int s = 0; s < 60; ++s) {
      double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int a = 0; a < 3; ++a)
        x[a] += step_in_cells / n * d[a] / len;
      const Point_3 p(x[0], x[1], x[2]);
      const bool in_cube = x[0] >= 0 && x[0] <= 1 && x[1] >= 0 && x[1] <= 1 && x[2] >= 0 && x[2] <= 1;
      const std::optional<Vector_3> v = field(p);
      ASSERT_EQ(v.has_value(), in_cube) << "step " << step_in_cells << ", path " << path << ", point " << s;
      if (!in_cube) {
        ++outside;
        for (int a = 0; a < 3; ++a) // turn back into the cube
          if (x[a] < 0 || x[a] > 1)
            d[a] = x[a] < 0 ? std::abs(d[a]) : -std::abs(d[a]);
        continue;
      }
      ++inside;
      const std::array<double, 3> expected = linear_field(x);
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR((*v)[a], expected[a], 1e-5) << "component " << a; // the node values are floats
      const std::optional<std::size_t> c = field.locate(p);
      ASSERT_TRUE(c.has_value());
      EXPECT_TRUE(field.evaluate_in_cell(*c, p).has_value());
      for (int a = 0; a < 3; ++a)
        d[a] += 0.3 * g(rng);
    }
  }
  EXPECT_GT(inside, 1000);
  if (step_in_cells > 1.) {
    EXPECT_GT(outside, 0);
  }
}

TEST(UnstructuredFlowField3Walk, PathsThroughHexahedraGetTheLinearField)
{
  const Field field = make_field(false);
  for (double step : {0.1, 0.7, 2.5})
    check_paths(field, step);
}

TEST(UnstructuredFlowField3Walk, PathsThroughTetrahedraGetTheLinearField)
{
  const Field field = make_field(true);
  for (double step : {0.1, 0.7, 2.5})
    check_paths(field, step);
}

// The vertices of the mesh, the middles of its cells' first edges, and random points.
std::vector<Point_3> points_on_shared_faces_and_elsewhere(const Field& field)
{
  std::vector<Point_3> points;
  const auto point = [&](std::size_t i) {
    return Point_3(field.points()[3 * i], field.points()[3 * i + 1], field.points()[3 * i + 2]);
  };
  for (std::size_t i = 0; i < field.number_of_points(); i += 7)
    points.push_back(point(i));
  for (std::size_t c = 0; c < field.number_of_cells(); c += 5) {
    const auto* v = field.connectivity().data() + field.offsets()[c];
    points.push_back(CGAL::midpoint(point(std::size_t(v[0])), point(std::size_t(v[1]))));
  }
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0., 1.);
  for (int i = 0; i < 300; ++i)
    points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

void check_answers_whatever_came_before(const Field& field)
{
  const std::vector<Point_3> points = points_on_shared_faces_and_elsewhere(field);
  std::vector<std::optional<Vector_3>> forward;
  for (const Point_3& p : points)
    forward.push_back(field(p));
  // Backwards, each query after one at a far point, which leaves the hint elsewhere.
  for (std::size_t i = points.size(); i-- > 0;) {
    field(Point_3(1 - points[i].x(), 1 - points[i].y(), 0.5));
    EXPECT_EQ(field(points[i]), forward[i]) << "point " << i << ": " << points[i];
  }
  std::vector<std::optional<Vector_3>> other_thread(points.size());
  std::thread([&] {
    for (std::size_t i = 0; i < points.size(); ++i)
      other_thread[(i * 7) % points.size()] = field(points[(i * 7) % points.size()]);
  }).join();
  EXPECT_EQ(other_thread, forward);
  // Where several cells contain a point, the located one is the smallest.
  for (const Point_3& p : points) {
    const std::optional<std::size_t> c = field.locate(p);
    if (!c)
      continue;
    for (std::size_t d = 0; d < *c; ++d)
      EXPECT_FALSE(field.evaluate_in_cell(d, p)) << "cell " << d << " also contains " << p << ", located in " << *c;
  }
}

TEST(UnstructuredFlowField3Walk, HexahedraAnswerWhateverCameBefore)
{
  check_answers_whatever_came_before(make_field(false));
}

TEST(UnstructuredFlowField3Walk, TetrahedraAnswerWhateverCameBefore)
{
  check_answers_whatever_came_before(make_field(true));
}

} // namespace

} // namespace test_Unstructured_flow_field_3_walk
