// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unstructured_flow_field_3's walk from the last hit cell: streams of queries along paths with
// steps of 0.1, 0.7 and 2.5 cells (so that the walk crosses zero, one or several faces, or gives
// up and the bucket grid answers) through jittered hexahedra and tetrahedra must return the
// linear field v(p) = A p + b, which both interpolations reproduce exactly, and a cell that
// contains the point; paths leaving the mesh get std::nullopt there and are found again when
// they come back.

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include "test_kernel.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <vector>

namespace {

using namespace fas_test;
typedef FAS::Unstructured_flow_field_3<K> Field;
typedef Field::Index Index;

const int n = 8; // cubes per axis of [0, 1]^3
const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

std::array<double, 3> linear_field(const double* x)
{
  return {{1. + 2. * x[0] - x[1] + 0.5 * x[2], -3. + x[0] + 4. * x[1] - 2. * x[2],
           0.25 - x[0] + x[1] + 3. * x[2]}};
}

// The unit cube in n^3 cubes with interior nodes jittered by up to 0.2 cell, as hexahedra or
// Kuhn tetrahedra.
Field make_field(bool tetrahedra)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2 / n, 0.2 / n);
  std::vector<double> points;
  std::vector<float> vectors;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const int ijk[3] = {i, j, k};
        double x[3];
        for (int a = 0; a < 3; ++a)
          x[a] = double(ijk[a]) / n + (ijk[a] > 0 && ijk[a] < n ? jitter(rng) : 0.);
        points.insert(points.end(), x, x + 3);
        const std::array<double, 3> v = linear_field(x);
        for (double c : v)
          vectors.push_back(static_cast<float>(c));
      }
  static const int kuhn[6][4] = {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 4, 5, 6},
                                 {0, 4, 7, 6}, {0, 3, 7, 6}, {0, 3, 2, 6}};
  std::vector<Index> connectivity, offsets{0};
  std::vector<unsigned char> types;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Index h[8];
        for (int q = 0; q < 8; ++q)
          h[q] = (i + corner[q][0]) + (n + 1) * ((j + corner[q][1]) + (n + 1) * (k + corner[q][2]));
        if (tetrahedra) {
          for (const auto& t : kuhn) {
            for (int q : t)
              connectivity.push_back(h[q]);
            offsets.push_back(static_cast<Index>(connectivity.size()));
            types.push_back(10);
          }
        }
        else {
          connectivity.insert(connectivity.end(), h, h + 8);
          offsets.push_back(static_cast<Index>(connectivity.size()));
          types.push_back(12);
        }
      }
  return Field(points, connectivity, offsets, types, vectors);
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

} // namespace
