// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rectilinear_grid_flow_field_3: on unevenly spaced axes, a global trilinear polynomial (which
// is trilinear in every cell, so trilinear interpolation must return it) at random points; the
// closed box; the node mask; agreement with Regular_grid_flow_field_3 on evenly spaced axes;
// shared storage; and the messages for bad coordinates and arrays.

#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>

#include "test_kernel.h"

#include "expect_invalid_argument.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <random>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Rectilinear_grid_flow_field_3 {

namespace {

using namespace fas_test;
typedef FAS::Rectilinear_grid_flow_field_3<K> Field;
typedef Field::Coordinates Coordinates;

// Uneven, dyadic coordinates (so the node values of the polynomial below are exact floats).
const Coordinates kAxes = {
    {{-1., -0.75, 0., 0.125, 2., 2.5}, {0.5, 0.625, 1.5, 4.}, {-2., -1.875, -1., 0.5, 0.75}}};

// A trilinear polynomial with small dyadic coefficients, different per component.
Vector_3 trilinear(double x, double y, double z)
{
  return Vector_3(1. + 2. * x - y + 0.5 * z + 0.25 * x * y - 0.5 * y * z + x * z - 0.125 * x * y * z,
                  -3. + x + 0.5 * y * z - 0.25 * x * y * z, 0.5 - z + 2. * x * y + 0.375 * x * z);
}

std::vector<float> node_values(const Coordinates& X, Vector_3 (*f)(double, double, double))
{
  std::vector<float> v;
  for (double z : X[2])
    for (double y : X[1])
      for (double x : X[0]) {
        const Vector_3 w = f(x, y, z);
        v.insert(v.end(), {float(w.x()), float(w.y()), float(w.z())});
      }
  return v;
}

Point_3 random_point_in(const CGAL::Bbox_3& b, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0., 1.);
  return Point_3(b.xmin() + u(rng) * (b.xmax() - b.xmin()), b.ymin() + u(rng) * (b.ymax() - b.ymin()),
                 b.zmin() + u(rng) * (b.zmax() - b.zmin()));
}

// The node values are exact and the blend has a few roundings of values below 100.
void expect_near_vector(const Vector_3& got, const Vector_3& expected)
{
  EXPECT_NEAR(got.x(), expected.x(), 1e-12);
  EXPECT_NEAR(got.y(), expected.y(), 1e-12);
  EXPECT_NEAR(got.z(), expected.z(), 1e-12);
}

TEST(RectilinearGridFlowField3, TrilinearPolynomialIsReproducedOnUnevenAxes)
{
  const Field g(kAxes, node_values(kAxes, trilinear));
  EXPECT_EQ(g.dimensions(), (Field::Dimensions{{6, 4, 5}}));
  EXPECT_EQ(g.number_of_nodes(), 120u);
  EXPECT_EQ(g.bbox(), CGAL::Bbox_3(-1., 0.5, -2., 2.5, 4., 0.75));
  std::mt19937 rng(3);
  for (int s = 0; s < 5000; ++s) {
    const Point_3 p = random_point_in(g.bbox(), rng);
    const std::optional<Vector_3> v = g(p);
    ASSERT_TRUE(v.has_value()) << p;
    expect_near_vector(*v, trilinear(p.x(), p.y(), p.z()));
  }
  // The nodes, the cell faces and the corners of the box.
  for (std::size_t k = 0; k < 5; ++k)
    for (std::size_t j = 0; j < 4; ++j)
      for (std::size_t i = 0; i < 6; ++i) {
        const Point_3 p = g.node_point(i, j, k);
        EXPECT_EQ(p, Point_3(kAxes[0][i], kAxes[1][j], kAxes[2][k]));
        ASSERT_TRUE(g(p).has_value()) << p;
        EXPECT_EQ(*g(p), g.node_value(i, j, k));
        EXPECT_EQ(g.node_value(i, j, k), trilinear(p.x(), p.y(), p.z()));
      }
  EXPECT_EQ(g.coordinates(1), kAxes[1]);
}

TEST(RectilinearGridFlowField3, OneCellGivesTheClosedFormTrilinearBlend)
{
  // One cell [0, 1] x [0, 2] x [0, 4] with arbitrary corner values: the blend at (x, y, z)
  // has the weights (1-u or u)(1-v or v)(1-w or w), u = x, v = y/2, w = z/4.
  const Coordinates X = {{{0., 1.}, {0., 2.}, {0., 4.}}};
  std::vector<float> values(24);
  for (int i = 0; i < 24; ++i)
    values[i] = float(std::sin(1.7 * i + 0.3));
  const Field g(X, values);
  const double x = 0.3, y = 1.1, z = 3.7, u = x, v = y / 2., w = z / 4.;
  double expected[3] = {0, 0, 0};
  for (int q = 0; q < 8; ++q) {
    const double weight = ((q & 1) ? u : 1 - u) * ((q & 2) ? v : 1 - v) * ((q & 4) ? w : 1 - w);
    for (int d = 0; d < 3; ++d)
      expected[d] += weight * values[3 * q + d];
  }
  expect_near_vector(*g(Point_3(x, y, z)), Vector_3(expected[0], expected[1], expected[2]));
}

TEST(RectilinearGridFlowField3, AgreesWithTheRegularGridOnEvenAxes)
{
  const Point_3 o(-1.3, 0.7, 2.1);
  const Vector_3 h(0.37, 0.21, 0.53);
  const FAS::Regular_grid_flow_field_3<K>::Dimensions n = {{7, 9, 5}};
  Coordinates X;
  for (int a = 0; a < 3; ++a)
    for (std::size_t i = 0; i < n[a]; ++i)
      X[a].push_back(o[a] + double(i) * h[a]);
  std::vector<float> values(3 * 7 * 9 * 5);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = float(std::cos(0.37 * double(i)));
  std::vector<unsigned char> mask(7 * 9 * 5, 1);
  mask[100] = mask[200] = 0;
  const FAS::Regular_grid_flow_field_3<K> regular(o, h, n, values, mask);
  const Field rectilinear(X, values, mask);
  EXPECT_EQ(rectilinear.bbox(), regular.bbox());
  std::mt19937 rng(11);
  std::size_t outside = 0;
  for (int s = 0; s < 5000; ++s) {
    const Point_3 p = random_point_in(regular.bbox(), rng);
    const std::optional<Vector_3> a = regular(p), b = rectilinear(p);
    ASSERT_EQ(a.has_value(), b.has_value()) << p;
    outside += !a;
    if (a) {
      EXPECT_NEAR(a->x(), b->x(), 1e-12);
      EXPECT_NEAR(a->y(), b->y(), 1e-12);
      EXPECT_NEAR(a->z(), b->z(), 1e-12);
    }
  }
  EXPECT_GT(outside, 0u); // the mask was exercised
}

TEST(RectilinearGridFlowField3, OutsideTheClosedBoxIsNullopt)
{
  const Field g(kAxes, node_values(kAxes, trilinear));
  EXPECT_TRUE(g(Point_3(2.5, 4., 0.75)).has_value());
  EXPECT_TRUE(g(Point_3(-1., 0.5, -2.)).has_value());
  EXPECT_FALSE(g(Point_3(std::nextafter(2.5, 3.), 1., 0.)).has_value());
  EXPECT_FALSE(g(Point_3(0., std::nextafter(0.5, 0.), 0.)).has_value());
  EXPECT_FALSE(g(Point_3(0., 1., 0.76)).has_value());
  EXPECT_FALSE(g(Point_3(std::nan(""), 1., 0.)).has_value());
}

TEST(RectilinearGridFlowField3, MaskExcludesTheCellsTouchingASolidNode)
{
  // Node (2, 1, 2) solid, with a NaN value (ignored and stored as zero).
  std::vector<float> values = node_values(kAxes, trilinear);
  std::vector<unsigned char> mask(120, 1);
  const std::size_t solid = 2 + 6 * (1 + 4 * 2);
  mask[solid] = 0;
  values[3 * solid + 1] = std::numeric_limits<float>::quiet_NaN();
  const Field g(kAxes, values, mask);
  ASSERT_TRUE(g.has_mask());
  EXPECT_FALSE(g.is_fluid(2, 1, 2));
  EXPECT_TRUE(g.is_fluid(2, 1, 1));
  EXPECT_EQ(g.node_value(2, 1, 2), Vector_3(0, 0, 0));
  EXPECT_EQ(g.mask(), mask);
  std::size_t outside = 0;
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t i = 0; i < 5; ++i) {
        const bool touches = (i == 1 || i == 2) && (j == 0 || j == 1) && (k == 1 || k == 2);
        const Point_3 c(0.5 * (kAxes[0][i] + kAxes[0][i + 1]), 0.5 * (kAxes[1][j] + kAxes[1][j + 1]),
                        0.5 * (kAxes[2][k] + kAxes[2][k + 1]));
        EXPECT_EQ(g(c).has_value(), !touches) << i << " " << j << " " << k;
        outside += touches;
      }
  EXPECT_EQ(outside, 8u);
  // The face x = X[1] of the fluid cell (0, 1, 2) is inside; the face x = X[2], which holds
  // the solid node, is not; nor is the solid node.
  const Point_3 fluid_face(kAxes[0][1], 0.5 * (kAxes[1][1] + kAxes[1][2]), 0.5 * (kAxes[2][2] + kAxes[2][3]));
  ASSERT_TRUE(g(fluid_face).has_value());
  expect_near_vector(*g(fluid_face), trilinear(fluid_face.x(), fluid_face.y(), fluid_face.z()));
  EXPECT_FALSE(g(Point_3(kAxes[0][2], fluid_face.y(), fluid_face.z())).has_value());
  EXPECT_FALSE(g(g.node_point(2, 1, 2)).has_value());
}

// What a reader fills: no node, no point inside.
TEST(RectilinearGridFlowField3, DefaultConstructedFieldIsEmpty)
{
  const Field g;
  EXPECT_EQ(g.number_of_nodes(), 0u);
  EXPECT_EQ(g.bbox(), CGAL::Bbox_3());
  EXPECT_TRUE(g.coordinates(0).empty());
  EXPECT_TRUE(g.values().empty());
  EXPECT_FALSE(g.has_mask());
  for (const Point_3& p : {Point_3(0, 0, 0), Point_3(-1e300, -1e300, -1e300), Point_3(1e300, 1e300, 1e300)})
    EXPECT_FALSE(g(p).has_value()) << p;
}

TEST(RectilinearGridFlowField3, CopiesShareStorage)
{
  const Field g(kAxes, node_values(kAxes, trilinear));
  const Field copy = g;
  EXPECT_EQ(&copy.values(), &g.values());
  EXPECT_EQ(&copy.coordinates(0), &g.coordinates(0));
  EXPECT_EQ(*copy(Point_3(0.3, 1., -0.5)), *g(Point_3(0.3, 1., -0.5)));
}

TEST(RectilinearGridFlowField3, BadInputThrowsWithTheAxisAndIndex)
{
  const std::vector<float> values = node_values(kAxes, trilinear);
  Coordinates X = kAxes;
  X[1][2] = X[1][1];
  expect_invalid_argument([&] { Field(X, values); },
                          {"Rectilinear_grid_flow_field_3", "coordinates[1][2] (y of node 2) is 0.625",
                           "not greater than coordinates[1][1] = 0.625", "strictly increasing"});
  X = kAxes;
  X[2][3] = -5.;
  expect_invalid_argument([&] { Field(X, values); }, {"coordinates[2][3] (z of node 3) is -5"});
  X = kAxes;
  X[0][4] = std::numeric_limits<double>::infinity();
  expect_invalid_argument([&] { Field(X, values); }, {"coordinates[0][4] (x of node 4) is inf", "finite"});
  X = kAxes;
  X[0][0] = std::nan("");
  expect_invalid_argument([&] { Field(X, values); }, {"coordinates[0][0]", "nan"});
  X = kAxes;
  X[2] = {1.};
  expect_invalid_argument([&] { Field(X, std::vector<float>(72)); },
                          {"dimensions[2] (nz) is 1", "at least 2 nodes"});
  expect_invalid_argument([&] { Field(kAxes, std::vector<float>(359)); },
                          {"values.size() is 359", "6 x 4 x 5", "3*nx*ny*nz = 360"});
  expect_invalid_argument([&] { Field(kAxes, values, std::vector<unsigned char>(119, 1)); },
                          {"mask.size() is 119", "nx*ny*nz = 120"});
  std::vector<float> bad = values;
  bad[3 * 7 + 2] = std::numeric_limits<float>::infinity();
  expect_invalid_argument([&] { Field(kAxes, bad); },
                          {"values of fluid node (1, 1, 0)", "values[21..23]", "expected finite numbers"});
}

} // namespace

} // namespace test_Rectilinear_grid_flow_field_3
