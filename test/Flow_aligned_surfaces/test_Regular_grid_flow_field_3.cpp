// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Regular_grid_flow_field_3: trilinear interpolation against closed-form trilinear fields, the
// closed domain box, the node mask, sampling, shared storage and the messages for bad input;
// the tricubic interpolation against fields quadratic in each coordinate, its order of
// convergence, its continuous derivatives and its fallback next to solid nodes.

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>

#include "test_kernel.h"

#include "expect_invalid_argument.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Regular_grid_flow_field_3 {

namespace {

using namespace fas_test;
typedef FAS::Regular_grid_flow_field_3<K> Grid;
typedef Grid::Dimensions Dimensions;

// A general trilinear map R^3 -> R^3: each component has its own 8 coefficients of
// 1, x, y, z, xy, yz, xz, xyz, so swapped components or axes show up.
struct Trilinear_field {
  std::array<std::array<double, 8>, 3> c;

  explicit Trilinear_field(std::mt19937& rng)
  {
    std::uniform_real_distribution<double> u(-2., 2.);
    for (auto& comp : c)
      for (double& a : comp)
        a = u(rng);
  }

  Vector_3 operator()(double x, double y, double z) const
  {
    double r[3];
    for (int d = 0; d < 3; ++d) {
      const auto& a = c[d];
      r[d] = a[0] + a[1] * x + a[2] * y + a[3] * z + a[4] * x * y + a[5] * y * z + a[6] * x * z +
             a[7] * x * y * z;
    }
    return Vector_3(r[0], r[1], r[2]);
  }
};

std::vector<float> node_values(const Point_3& o, const Vector_3& h, const Dimensions& n,
                               const std::function<Vector_3(double, double, double)>& f)
{
  std::vector<float> v;
  v.reserve(3 * n[0] * n[1] * n[2]);
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        const Vector_3 w = f(o.x() + double(i) * h.x(), o.y() + double(j) * h.y(), o.z() + double(k) * h.z());
        v.push_back(float(w.x()));
        v.push_back(float(w.y()));
        v.push_back(float(w.z()));
      }
  return v;
}

Point_3 random_point_in(const CGAL::Bbox_3& b, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0., 1.);
  return Point_3(b.xmin() + u(rng) * (b.xmax() - b.xmin()), b.ymin() + u(rng) * (b.ymax() - b.ymin()),
                 b.zmin() + u(rng) * (b.zmax() - b.zmin()));
}

double max_abs_node_value(const Grid& g)
{
  double m = 0;
  for (float x : g.values())
    m = std::max(m, double(std::abs(x)));
  return m;
}

// Floats carry a relative rounding of 6e-8 per node value; the interpolation is a convex
// combination, so its error stays below that times the largest node value.
void expect_near_vector(const Vector_3& got, const Vector_3& expected, double scale)
{
  const double tol = 1e-6 * scale;
  EXPECT_NEAR(got.x(), expected.x(), tol);
  EXPECT_NEAR(got.y(), expected.y(), tol);
  EXPECT_NEAR(got.z(), expected.z(), tol);
}

// A non-dyadic grid, so that nothing is exact by accident.
const Point_3 kOrigin(-1.3, 0.7, 2.1);
const Vector_3 kSpacing(0.37, 0.21, 0.53);
const Dimensions kDims = {7, 9, 5};

TEST(RegularGridFlowField3, TrilinearFieldIsReproducedAtRandomPoints)
{
  std::mt19937 rng(42);
  for (int trial = 0; trial < 5; ++trial) {
    const Trilinear_field f(rng);
    const Grid g(kOrigin, kSpacing, kDims, node_values(kOrigin, kSpacing, kDims, f));
    const double scale = max_abs_node_value(g);
    for (int s = 0; s < 2000; ++s) {
      const Point_3 p = random_point_in(g.bbox(), rng);
      const std::optional<Vector_3> v = g(p);
      ASSERT_TRUE(v.has_value()) << p;
      expect_near_vector(*v, f(p.x(), p.y(), p.z()), scale);
    }
  }
}

TEST(RegularGridFlowField3, LinearFieldIsReproducedAtRandomPoints)
{
  const auto f = [](double x, double y, double z) {
    return Vector_3(1.5 * x - 2. * y + 0.25 * z + 3., -x + 0.5 * z - 1., 4. * y - 0.75 * x);
  };
  const Grid g(kOrigin, kSpacing.x(), kSpacing.y(), kSpacing.z(), kDims,
               node_values(kOrigin, kSpacing, kDims, f));
  const double scale = max_abs_node_value(g);
  std::mt19937 rng(7);
  for (int s = 0; s < 2000; ++s) {
    const Point_3 p = random_point_in(g.bbox(), rng);
    const std::optional<Vector_3> v = g(p);
    ASSERT_TRUE(v.has_value()) << p;
    expect_near_vector(*v, f(p.x(), p.y(), p.z()), scale);
  }
}

TEST(RegularGridFlowField3, NodeValuesAreReturnedExactlyAtNodes)
{
  // Dyadic origin and spacings: node positions and their cell coordinates are exact, so the
  // stored floats must come back bit for bit, including on the upper boundary nodes.
  const Point_3 o(0.5, -1., 2.);
  const Vector_3 h(0.25, 0.5, 0.125);
  const Dimensions n = {4, 3, 5};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-10.f, 10.f);
  std::vector<float> values(3 * n[0] * n[1] * n[2]);
  for (float& x : values)
    x = u(rng);
  const std::vector<float> copy = values;
  const Grid g(o, h, n, std::move(values));
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        const std::size_t v = i + n[0] * (j + n[1] * k);
        const Vector_3 expected(copy[3 * v], copy[3 * v + 1], copy[3 * v + 2]);
        const Point_3 p(o.x() + double(i) * h.x(), o.y() + double(j) * h.y(), o.z() + double(k) * h.z());
        EXPECT_EQ(g.node_point(i, j, k), p);
        EXPECT_EQ(g.node_value(i, j, k), expected);
        const std::optional<Vector_3> q = g(p);
        ASSERT_TRUE(q.has_value()) << p;
        EXPECT_EQ(*q, expected) << "node " << i << " " << j << " " << k;
      }
}

TEST(RegularGridFlowField3, NodeValuesAreReturnedAtNodesOfANonDyadicGrid)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-10.f, 10.f);
  std::vector<float> values(3 * kDims[0] * kDims[1] * kDims[2]);
  for (float& x : values)
    x = u(rng);
  const Grid g(kOrigin, kSpacing, kDims, values);
  for (std::size_t k = 0; k < kDims[2]; ++k)
    for (std::size_t j = 0; j < kDims[1]; ++j)
      for (std::size_t i = 0; i < kDims[0]; ++i) {
        const std::optional<Vector_3> q = g(g.node_point(i, j, k));
        ASSERT_TRUE(q.has_value());
        // The node position is rounded, so the cell coordinate may be off by an ulp.
        expect_near_vector(*q, g.node_value(i, j, k), 10.);
      }
}

TEST(RegularGridFlowField3, UpperBoundaryIsExactWhereTheCellCoordinateOvershoots)
{
  // With origin 0 and hx = 0.1, the last node x = 3 * 0.1 maps to the cell coordinate
  // 3.0000000000000004: the lower nodes of the last cell must still get a weight of exactly
  // zero, so the upper face is inside although the nodes behind it are solid, and the upper
  // nodes' values come back exactly.
  const Dimensions n = {4, 2, 2};
  ASSERT_GT((3 * 0.1 - 0.) * (1. / 0.1), 3.);
  std::vector<float> values(3 * 16);
  for (std::size_t q = 0; q < values.size(); ++q)
    values[q] = 0.1f * float(q) - 1.f;
  std::vector<unsigned char> mask(16, 1);
  for (std::size_t v = 0; v < 16; ++v)
    if (v % 4 == 2)
      mask[v] = 0;
  const Grid g(Point_3(0, 0, 0), 0.1, 1., 1., n, std::move(values), std::move(mask));
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t j = 0; j < 2; ++j) {
      const std::optional<Vector_3> v = g(g.node_point(3, j, k));
      ASSERT_TRUE(v.has_value()) << j << " " << k;
      EXPECT_EQ(*v, g.node_value(3, j, k));
    }
  EXPECT_TRUE(g(Point_3(g.bbox().xmax(), 0.5, 0.5)).has_value());
  EXPECT_FALSE(g(Point_3(0.25, 0.5, 0.5)).has_value());
}

TEST(RegularGridFlowField3, ClosedBoxIsInsideAndJustOutsideIsNot)
{
  const auto f = [](double x, double y, double z) { return Vector_3(x + 2. * y, y - z, z + x); };
  const Grid g(kOrigin, kSpacing, kDims, node_values(kOrigin, kSpacing, kDims, f));
  const CGAL::Bbox_3 b = g.bbox();
  const double lo[3] = {kOrigin.x(), kOrigin.y(), kOrigin.z()};
  const double hi[3] = {kOrigin.x() + 6. * kSpacing.x(), kOrigin.y() + 8. * kSpacing.y(),
                        kOrigin.z() + 4. * kSpacing.z()};
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(b.min(a), lo[a]);
    EXPECT_EQ(b.max(a), hi[a]);
  }
  const double scale = max_abs_node_value(g);
  const double inf = std::numeric_limits<double>::infinity();
  std::mt19937 rng(11);
  for (int s = 0; s < 200; ++s) {
    const Point_3 r = random_point_in(b, rng);
    for (int a = 0; a < 3; ++a) {
      for (int side = 0; side < 2; ++side) {
        double x[3] = {r.x(), r.y(), r.z()};
        x[a] = side ? hi[a] : lo[a];
        const Point_3 on(x[0], x[1], x[2]);
        const std::optional<Vector_3> v = g(on);
        ASSERT_TRUE(v.has_value()) << "on the boundary: " << on;
        expect_near_vector(*v, f(x[0], x[1], x[2]), scale);
        x[a] = std::nextafter(x[a], side ? inf : -inf);
        EXPECT_FALSE(g(Point_3(x[0], x[1], x[2])).has_value()) << "just outside, axis " << a;
      }
    }
  }
  // The 8 corners of the box, and points with a NaN coordinate.
  for (int q = 0; q < 8; ++q) {
    const Point_3 c((q & 1) ? hi[0] : lo[0], (q & 2) ? hi[1] : lo[1], (q & 4) ? hi[2] : lo[2]);
    ASSERT_TRUE(g(c).has_value()) << c;
    expect_near_vector(*g(c), f(c.x(), c.y(), c.z()), scale);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(g(Point_3(nan, lo[1], lo[2])).has_value());
  EXPECT_FALSE(g(Point_3(lo[0], lo[1], nan)).has_value());
}

// What a reader fills: no node, no point inside (not even on the far side of an empty box).
TEST(RegularGridFlowField3, DefaultConstructedFieldIsEmpty)
{
  const Grid g;
  EXPECT_EQ(g.number_of_nodes(), 0u);
  EXPECT_EQ(g.dimensions(), (Dimensions{{0, 0, 0}}));
  EXPECT_EQ(g.bbox(), CGAL::Bbox_3());
  EXPECT_TRUE(g.values().empty());
  EXPECT_FALSE(g.has_mask());
  for (const Point_3& p : {Point_3(0, 0, 0), Point_3(-1e300, -1e300, -1e300), Point_3(1e300, 1e300, 1e300)})
    EXPECT_FALSE(g(p).has_value()) << p;
  EXPECT_FALSE(g.with_interpolation(FAS::Grid_interpolation::TRICUBIC)(Point_3(0, 0, 0)).has_value());
}

TEST(RegularGridFlowField3, MaskExcludesTheCellsTouchingASolidNode)
{
  // 5 x 5 x 5 nodes of unit spacing, node (2, 2, 2) solid with a NaN value (ignored).
  const Dimensions n = {5, 5, 5};
  const Point_3 o(0., 0., 0.);
  const auto f = [](double x, double y, double z) { return Vector_3(1. + x, 2. + y, 3. + z); };
  std::vector<float> values = node_values(o, Vector_3(1, 1, 1), n, f);
  std::vector<unsigned char> mask(125, 1);
  const std::size_t solid = 2 + 5 * (2 + 5 * 2);
  mask[solid] = 0;
  values[3 * solid] = std::numeric_limits<float>::quiet_NaN();
  const Grid g(o, 1., 1., 1., n, std::move(values), std::move(mask));
  ASSERT_TRUE(g.has_mask());
  EXPECT_FALSE(g.is_fluid(2, 2, 2));
  EXPECT_TRUE(g.is_fluid(2, 2, 1));

  std::size_t outside = 0;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const bool touches = (i == 1 || i == 2) && (j == 1 || j == 2) && (k == 1 || k == 2);
        const Point_3 center(i + 0.5, j + 0.5, k + 0.5);
        const Point_3 near_corner(i + 0.01, j + 0.99, k + 0.5);
        EXPECT_EQ(g(center).has_value(), !touches) << "cell " << i << " " << j << " " << k;
        EXPECT_EQ(g(near_corner).has_value(), !touches) << "cell " << i << " " << j << " " << k;
        if (!touches) {
          expect_near_vector(*g(center), f(i + 0.5, j + 0.5, k + 0.5), 10.);
        }
        outside += touches;
      }
  EXPECT_EQ(outside, 8u);

  // A face of a fluid cell is inside even where a solid cell lies behind it; a face whose
  // nodes include the solid node is not.
  const std::optional<Vector_3> on_fluid_face = g(Point_3(1., 1.5, 1.5));
  ASSERT_TRUE(on_fluid_face.has_value());
  EXPECT_TRUE(std::isfinite(on_fluid_face->x()));
  expect_near_vector(*on_fluid_face, f(1., 1.5, 1.5), 10.);
  EXPECT_FALSE(g(Point_3(2., 1.5, 1.5)).has_value());
  EXPECT_TRUE(g(Point_3(3., 1.5, 1.5)).has_value());
  // The solid node itself, and a fluid node next to it.
  EXPECT_FALSE(g(Point_3(2., 2., 2.)).has_value());
  ASSERT_TRUE(g(Point_3(2., 2., 1.)).has_value());
  EXPECT_EQ(*g(Point_3(2., 2., 1.)), g.node_value(2, 2, 1));
  // The non-finite value at the solid node was replaced, so it cannot leak.
  EXPECT_EQ(g.node_value(2, 2, 2), Vector_3(0, 0, 0));
}

TEST(RegularGridFlowField3, SampleOnGridReproducesALinearField)
{
  const auto f = [](const Point_3& p) -> std::optional<Vector_3> {
    return Vector_3(0.5 * p.x() - p.y() + 2., p.z() - 3. * p.x(), 0.25 * p.y() + p.z() - 1.);
  };
  const Grid g = FAS::sample_on_grid(f, kOrigin, kSpacing, kDims);
  EXPECT_FALSE(g.has_mask());
  EXPECT_TRUE(g.mask().empty());
  EXPECT_EQ(g.dimensions(), kDims);
  EXPECT_EQ(g.origin(), kOrigin);
  EXPECT_EQ(g.spacing(), kSpacing);
  EXPECT_EQ(g.number_of_nodes(), kDims[0] * kDims[1] * kDims[2]);
  EXPECT_EQ(g.values().size(), 3 * g.number_of_nodes());
  const double scale = max_abs_node_value(g);
  std::mt19937 rng(13);
  for (int s = 0; s < 2000; ++s) {
    const Point_3 p = random_point_in(g.bbox(), rng);
    ASSERT_TRUE(g(p).has_value());
    expect_near_vector(*g(p), *f(p), scale);
  }
}

TEST(RegularGridFlowField3, SampleOnGridMasksTheNodesOutsideTheField)
{
  // Defined for x <= 0.5 only: nodes x = 0, 0.5 fluid, x = 1, 1.5 solid (and a NaN node).
  const auto f = [](const Point_3& p) -> std::optional<Vector_3> {
    if (p.x() > 0.5)
      return std::nullopt;
    if (p.y() == 1. && p.z() == 1.)
      return Vector_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    return Vector_3(1, 2, 3);
  };
  const Grid g = FAS::sample_on_grid(f, Point_3(0, 0, 0), Vector_3(0.5, 0.5, 0.5), {4, 3, 3});
  ASSERT_TRUE(g.has_mask());
  EXPECT_TRUE(g.is_fluid(1, 0, 0));
  EXPECT_FALSE(g.is_fluid(2, 0, 0));
  EXPECT_FALSE(g.is_fluid(0, 2, 2));
  EXPECT_EQ(g.node_value(3, 1, 1), Vector_3(0, 0, 0));
  ASSERT_TRUE(g(Point_3(0.25, 0.25, 0.25)).has_value());
  EXPECT_EQ(*g(Point_3(0.25, 0.25, 0.25)), Vector_3(1, 2, 3));
  EXPECT_FALSE(g(Point_3(0.75, 0.25, 0.25)).has_value());
  EXPECT_FALSE(g(Point_3(0.25, 0.75, 0.75)).has_value()); // touches the NaN node (0, 2, 2)
}

TEST(RegularGridFlowField3, CopiesShareStorage)
{
  std::vector<float> values(3 * 8, 1.f);
  const float* data = values.data();
  const Grid g(Point_3(0, 0, 0), Vector_3(1, 1, 1), {2, 2, 2}, std::move(values),
               std::vector<unsigned char>(8, 1));
  // The moved-in arrays are kept, not copied.
  EXPECT_EQ(g.values().data(), data);
  const Grid copy = g;
  EXPECT_EQ(copy.values().data(), g.values().data());
  EXPECT_EQ(copy.mask().data(), g.mask().data());
  Grid assigned = FAS::sample_on_grid([](const Point_3&) { return std::optional<Vector_3>(); },
                                      Point_3(0, 0, 0), Vector_3(1, 1, 1), {2, 2, 2});
  assigned = g;
  EXPECT_EQ(assigned.values().data(), data);
  EXPECT_EQ(*copy(Point_3(0.5, 0.5, 0.5)), Vector_3(1, 1, 1));
}

// ---- Blocks of a larger grid (the pieces of a distributed image) ----

// The nodes first .. first + n - 1 of the whole grid's node arrays.
struct Block_arrays {
  std::vector<float> values;
  std::vector<unsigned char> mask;
};

Block_arrays block_arrays(const Grid& whole, const Dimensions& first, const Dimensions& n)
{
  const Dimensions& N = whole.dimensions();
  Block_arrays b;
  for (std::size_t k = first[2]; k < first[2] + n[2]; ++k)
    for (std::size_t j = first[1]; j < first[1] + n[1]; ++j)
      for (std::size_t i = first[0]; i < first[0] + n[0]; ++i) {
        const std::size_t v = i + N[0] * (j + N[1] * k);
        for (int d = 0; d < 3; ++d)
          b.values.push_back(whole.values()[3 * v + std::size_t(d)]);
        if (!whole.mask().empty())
          b.mask.push_back(whole.mask()[v]);
      }
  return b;
}

bool same_bits(const std::optional<Vector_3>& a, const std::optional<Vector_3>& b)
{
  return a.has_value() == b.has_value() && (!a || (a->x() == b->x() && a->y() == b->y() && a->z() == b->z()));
}

// The whole non-dyadic grid with random node values and a few solid nodes, split as VTK splits
// an image into pieces: along x at node 3 and along y at node 4, neighbours sharing a node layer.
struct Split_grid {
  Grid whole;
  std::vector<Grid> blocks, shifted; // shifted: each block made as a grid of its own
};

Split_grid split_grid()
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-2.f, 2.f);
  const std::size_t nodes = kDims[0] * kDims[1] * kDims[2];
  std::vector<float> values(3 * nodes);
  for (float& x : values)
    x = u(rng);
  std::vector<unsigned char> mask(nodes, 1);
  for (std::size_t v : {17u, 40u, 41u, 150u, 222u})
    mask[v] = 0;
  Split_grid s{Grid(kOrigin, kSpacing, kDims, values, mask), {}, {}};
  const std::array<std::array<std::size_t, 2>, 2> x_pieces = {{{0, 4}, {3, 4}}}; // first, n
  const std::array<std::array<std::size_t, 2>, 2> y_pieces = {{{0, 5}, {4, 5}}};
  for (const auto& x : x_pieces)
    for (const auto& y : y_pieces) {
      const Dimensions first = {x[0], y[0], 0}, n = {x[1], y[1], kDims[2]};
      Block_arrays b = block_arrays(s.whole, first, n);
      s.blocks.push_back(Grid::block(kOrigin, kSpacing, kDims, first, n, b.values, b.mask));
      s.shifted.push_back(Grid(s.whole.node_point(first[0], first[1], first[2]), kSpacing, n, b.values, b.mask));
    }
  return s;
}

// Random points of the box, points on the node planes (the shared faces among them), and points
// a few ulps on either side of them.
std::vector<Point_3> probe_points(const Grid& whole)
{
  std::mt19937 rng(11);
  std::vector<Point_3> points;
  for (int i = 0; i < 20000; ++i)
    points.push_back(random_point_in(whole.bbox(), rng));
  std::uniform_real_distribution<double> u(0., 1.);
  for (int i = 0; i < 20000; ++i) {
    Point_3 p = random_point_in(whole.bbox(), rng);
    const int axis = i % 3;
    // Half of them on the faces the blocks share (x node 3, y node 4).
    const std::size_t node = (i & 8) && axis < 2 ? std::size_t(3 + axis)
                                                 : std::size_t(u(rng) * double(kDims[std::size_t(axis)]));
    double c[3] = {p.x(), p.y(), p.z()};
    c[axis] = CGAL::to_double(whole.node_point(node, node, node)[axis]);
    for (int ulps = i % 4; ulps > 0; --ulps)
      c[axis] = std::nextafter(c[axis], (i & 4) ? 1e300 : -1e300);
    points.push_back(Point_3(c[0], c[1], c[2]));
  }
  return points;
}

TEST(RegularGridFlowField3Block, SamplesBitForBitAsTheWholeGrid)
{
  const Split_grid s = split_grid();
  std::size_t answered_by_two = 0, whole_samples = 0, shifted_differs = 0;
  for (const Point_3& p : probe_points(s.whole)) {
    const std::optional<Vector_3> expected = s.whole(p);
    std::size_t answers = 0;
    for (std::size_t b = 0; b < s.blocks.size(); ++b) {
      const std::optional<Vector_3> got = s.blocks[b](p);
      if (got) {
        ++answers;
        ASSERT_TRUE(same_bits(got, expected)) << "block " << b << " at " << p;
      }
      const std::optional<Vector_3> naive = s.shifted[b](p);
      if (naive && expected && !same_bits(naive, expected))
        ++shifted_differs;
    }
    if (expected) {
      ++whole_samples;
      ASSERT_GE(answers, 1u) << "no block answers at " << p << ", where the whole grid does";
    }
    answered_by_two += answers >= 2 ? 1 : 0;
  }
  EXPECT_GT(whole_samples, 30000u);
  EXPECT_GT(answered_by_two, 500u); // the shared faces were probed (766 points)
  // A block made as a grid of its own (origin at its first node) rounds differently: the test
  // would see that.
  EXPECT_GT(shifted_differs, 100u);
}

TEST(RegularGridFlowField3Block, HasTheGeometryOfItsNodesInTheWholeGrid)
{
  const Split_grid s = split_grid();
  const Grid& b = s.blocks[3]; // nodes (3.., 4.., 0..)
  EXPECT_EQ(b.dimensions(), (Dimensions{4, 5, kDims[2]}));
  EXPECT_EQ(b.origin(), s.whole.node_point(3, 4, 0));
  EXPECT_EQ(b.node_point(2, 1, 3), s.whole.node_point(5, 5, 3));
  EXPECT_EQ(b.node_value(2, 1, 3), s.whole.node_value(5, 5, 3));
  const CGAL::Bbox_3 box = b.bbox(), all = s.whole.bbox();
  EXPECT_EQ(box.xmin(), CGAL::to_double(s.whole.node_point(3, 0, 0).x()));
  EXPECT_EQ(box.xmax(), all.xmax());
  EXPECT_EQ(box.ymin(), CGAL::to_double(s.whole.node_point(0, 4, 0).y()));
  EXPECT_EQ(box.zmin(), all.zmin());
  // A point of the whole grid outside the block: no sample.
  EXPECT_FALSE(b(s.whole.node_point(1, 1, 1)));
}

TEST(RegularGridFlowField3Block, ABlockThatDoesNotFitIsRefused)
{
  const std::vector<float> values(3 * 4 * 5 * 5, 1.f);
  expect_invalid_argument(
    [&] { Grid::block(kOrigin, kSpacing, kDims, {4, 0, 0}, {4, 5, 5}, values); },
    {"Regular_grid_flow_field_3::block", "axis 0", "4..7", "7 nodes"});
  expect_invalid_argument(
    [&] { Grid::block(kOrigin, kSpacing, {1, 9, 5}, {0, 0, 0}, {4, 5, 5}, values); },
    {"dimensions[0]"});
}

TEST(RegularGridFlowField3, BadInputThrowsWithTheArgumentsName)
{
  const Point_3 o(0, 0, 0);
  const Vector_3 h(1, 1, 1);
  const std::vector<float> v8(24, 0.f);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  expect_invalid_argument([&] { Grid(o, h, {2, 2, 2}, std::vector<float>(10)); }, {"values", "10", "24"});
  expect_invalid_argument([&] { Grid(o, h, {2, 2, 2}, std::vector<float>(25)); }, {"values", "25", "24"});
  expect_invalid_argument(
      [&] {
        Grid(o, h, {2, 2, 2}, v8, std::vector<unsigned char>(5, 1));
      },
      {"mask", "5", "8"});
  expect_invalid_argument([&] { Grid(o, h, {2, 1, 2}, std::vector<float>(12)); }, {"dimensions", "1", "2"});
  expect_invalid_argument([&] { Grid(o, h, {0, 2, 2}, std::vector<float>()); }, {"dimensions", "0"});
  expect_invalid_argument([&] { Grid(o, 1., -0.5, 1., {2, 2, 2}, v8); }, {"spacing", "hy", "-0.5"});
  expect_invalid_argument([&] { Grid(o, 0., 1., 1., {2, 2, 2}, v8); }, {"spacing", "hx"});
  expect_invalid_argument([&] { Grid(o, 1., 1., nan, {2, 2, 2}, v8); }, {"spacing", "hz"});
  expect_invalid_argument([&] { Grid(o, Vector_3(1, inf, 1), {2, 2, 2}, v8); }, {"spacing", "hy"});
  expect_invalid_argument([&] { Grid(Point_3(nan, 0, 0), h, {2, 2, 2}, v8); }, {"origin"});

  std::vector<float> with_nan = v8;
  with_nan[3 * 5 + 1] = std::numeric_limits<float>::quiet_NaN();
  expect_invalid_argument([&] { Grid(o, h, {2, 2, 2}, with_nan); }, {"values", "(1, 0, 1)"});
  // The same NaN at a solid node is accepted.
  std::vector<unsigned char> mask(8, 1);
  mask[5] = 0;
  EXPECT_NO_THROW(Grid(o, h, {2, 2, 2}, with_nan, mask));

  // Sizes whose product overflows must be refused before anything is allocated.
  const std::size_t huge = std::size_t(1) << 30;
  expect_invalid_argument([&] { Grid(o, h, {huge, huge, huge}, v8); }, {"dimensions"});
  const auto zero = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(0, 0, 0)); };
  expect_invalid_argument([&] { FAS::sample_on_grid(zero, o, h, {huge, huge, huge}); }, {"dimensions"});
  expect_invalid_argument([&] { FAS::sample_on_grid(zero, o, h, {2, 2, 1}); }, {"dimensions", "1"});
  expect_invalid_argument(
      [&] {
        FAS::sample_on_grid(zero, o, Vector_3(1, 1, 0), {2, 2, 2});
      },
      {"spacing", "hz"});
  const auto too_big = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(1e300, 0, 0)); };
  expect_invalid_argument([&] { FAS::sample_on_grid(too_big, o, h, {2, 2, 2}); }, {"float", "1e+300"});
}

} // namespace

// --- Grid_interpolation::TRICUBIC --------------------------------------------------------------

namespace {

// A field quadratic in each coordinate (products of quadratics and a general quadratic), which
// the Catmull–Rom blend with quadratic extrapolation at the box reproduces exactly.
Vector_3 triquadratic(double x, double y, double z)
{
  return Vector_3((1. + 0.5 * x - 0.3 * x * x) * (2. - y + 0.2 * y * y) * (0.7 + 0.4 * z - 0.25 * z * z),
                  x * x - 2. * x * y + 0.5 * y * z + 0.3 * z * z - x + 1.,
                  (x - 0.2) * (x + 1.1) * (y * y - 0.5) + 2. * z * z * x);
}

Vector_3 smooth_field(double x, double y, double z)
{
  return Vector_3(std::sin(x) * std::cos(y), std::sin(y + z), std::cos(x * z));
}

// The largest component error at `count` random points of the grid's box.
double max_error_at_random_points(const Grid& g, const std::function<Vector_3(double, double, double)>& f,
                                  int count, unsigned seed)
{
  std::mt19937 rng(seed);
  double worst = 0;
  for (int s = 0; s < count; ++s) {
    const Point_3 p = random_point_in(g.bbox(), rng);
    const std::optional<Vector_3> v = g(p);
    EXPECT_TRUE(v.has_value()) << p;
    if (!v)
      continue;
    const Vector_3 d = *v - f(p.x(), p.y(), p.z());
    worst = std::max({worst, std::abs(d.x()), std::abs(d.y()), std::abs(d.z())});
  }
  return worst;
}

Grid smooth_grid(std::size_t nodes_per_axis)
{
  const Point_3 o(0., 0., 0.);
  const double h = 2. / double(nodes_per_axis - 1);
  const Dimensions n = {nodes_per_axis, nodes_per_axis, nodes_per_axis};
  return Grid(o, Vector_3(h, h, h), n, node_values(o, Vector_3(h, h, h), n, smooth_field));
}

} // namespace

TEST(RegularGridFlowField3Tricubic, IsOptInAndSharesTheNodeArrays)
{
  const Grid g = smooth_grid(5);
  EXPECT_EQ(g.interpolation(), FAS::Grid_interpolation::TRILINEAR);
  const Grid c = g.with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  EXPECT_EQ(c.interpolation(), FAS::Grid_interpolation::TRICUBIC);
  EXPECT_EQ(g.interpolation(), FAS::Grid_interpolation::TRILINEAR);
  EXPECT_EQ(c.values().data(), g.values().data());
  EXPECT_EQ(c.with_interpolation(FAS::Grid_interpolation::TRILINEAR)(Point_3(0.3, 0.7, 1.1)),
            g(Point_3(0.3, 0.7, 1.1)));
}

TEST(RegularGridFlowField3Tricubic, ReproducesFieldsQuadraticInEachCoordinateUpToTheBox)
{
  // Trilinear interpolation cannot do this (it is exact for trilinear fields only), so the test
  // sees whether the cubic blend and the extrapolation at the faces are right, in every cell.
  for (const Dimensions& n : {kDims, Dimensions{3, 4, 6}}) {
    const Grid g = Grid(kOrigin, kSpacing, n, node_values(kOrigin, kSpacing, n, triquadratic))
                       .with_interpolation(FAS::Grid_interpolation::TRICUBIC);
    const double scale = max_abs_node_value(g);
    EXPECT_LE(max_error_at_random_points(g, triquadratic, 4000, 11), 5e-6 * scale);
    // The trilinear blend of the same nodes is off by far more.
    EXPECT_GE(max_error_at_random_points(g.with_interpolation(FAS::Grid_interpolation::TRILINEAR),
                                         triquadratic, 4000, 11),
              1e-3 * scale);
  }
}

TEST(RegularGridFlowField3Tricubic, TwoNodesAlongAnAxisAreLinearAlongIt)
{
  // With 2 nodes along z, z is blended linearly: a field quadratic in x and y, linear in z, is
  // reproduced.
  const auto f = [](double x, double y, double z) {
    return Vector_3(x * x * (1. + z), y * y - x * z, 2. - z + x * y);
  };
  const Dimensions n = {5, 4, 2};
  const Grid g = Grid(kOrigin, kSpacing, n, node_values(kOrigin, kSpacing, n, f))
                     .with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  EXPECT_LE(max_error_at_random_points(g, f, 2000, 5), 5e-6 * max_abs_node_value(g));
}

TEST(RegularGridFlowField3Tricubic, ReturnsTheNodeValuesAtTheNodes)
{
  // A dyadic grid, so that the node positions give cell fractions of exactly 0 (a non-dyadic
  // one gives fractions of a few ulps, and values within rounding of the node's).
  const Grid g = smooth_grid(9).with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  for (std::size_t k = 0; k < 9; ++k)
    for (std::size_t j = 0; j < 9; ++j)
      for (std::size_t i = 0; i < 9; ++i) {
        const std::optional<Vector_3> v = g(g.node_point(i, j, k));
        ASSERT_TRUE(v.has_value());
        EXPECT_EQ(*v, g.node_value(i, j, k)) << i << " " << j << " " << k;
      }
}

TEST(RegularGridFlowField3Tricubic, ConvergesWithThirdOrder)
{
  // Halving h divides the error of a third-order interpolation by 8 (of the trilinear one by 4);
  // the error is measured over the whole box, boundary cells included (their one-sided
  // extrapolation has a larger constant, so the coarsest grid here is already fine: 17^3).
  const auto error = [](std::size_t n, FAS::Grid_interpolation interpolation) {
    return max_error_at_random_points(smooth_grid(n).with_interpolation(interpolation), smooth_field, 4000, 3);
  };
  const double e17 = error(17, FAS::Grid_interpolation::TRICUBIC);
  const double e33 = error(33, FAS::Grid_interpolation::TRICUBIC);
  const double e65 = error(65, FAS::Grid_interpolation::TRICUBIC);
  EXPECT_GE(e17 / e33, 5.5) << e17 << " " << e33;
  EXPECT_GE(e33 / e65, 6.5) << e33 << " " << e65;
  const double linear33 = error(33, FAS::Grid_interpolation::TRILINEAR);
  const double linear65 = error(65, FAS::Grid_interpolation::TRILINEAR);
  EXPECT_LE(linear33 / linear65, 4.5) << "the trilinear blend is second order";
  EXPECT_LE(e65, linear65 / 20.) << e65 << " against " << linear65;
}

TEST(RegularGridFlowField3Tricubic, IsContinuouslyDifferentiableAcrossCellFaces)
{
  // One-sided difference quotients ε apart on both sides of a node plane: the trilinear field's
  // derivative jumps there by O(h f''), the tricubic one's agree to O(ε f'').
  const Grid linear = smooth_grid(9);
  const Grid cubic = linear.with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  const double h = 0.25, eps = 1e-6;
  const auto jump = [&](const Grid& g, const Point_3& p, const Vector_3& axis) {
    const Vector_3 right = (*g(p + eps * axis) - *g(p)) / eps;
    const Vector_3 left = (*g(p) - *g(p - eps * axis)) / eps;
    return std::sqrt((right - left).squared_length());
  };
  const Vector_3 axes[3] = {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1)};
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.1, 1.9);
  std::uniform_int_distribution<int> node(1, 7); // interior node planes; 1 and 7 border the boundary cells
  double cubic_total = 0, linear_total = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int a = trial % 3;
    double x[3] = {u(rng), u(rng), u(rng)};
    x[a] = h * node(rng);
    const Point_3 p(x[0], x[1], x[2]);
    const double cubic_jump = jump(cubic, p, axes[a]);
    const double linear_jump = jump(linear, p, axes[a]);
    EXPECT_LE(cubic_jump, 1e-4) << p << " axis " << a;
    cubic_total += cubic_jump;
    linear_total += linear_jump;
  }
  EXPECT_GE(linear_total / 60., 1e-2) << "the trilinear derivative should jump: the test would see nothing";
  EXPECT_LE(cubic_total, 1e-3 * linear_total);
}

TEST(RegularGridFlowField3Tricubic, NextToSolidNodesFallsBackToTrilinear)
{
  // 9^3 nodes, node (4, 4, 4) solid: the domain is the trilinear one; cells with the solid node in
  // their 4^3 stencil are trilinear, the others are the tricubic blend of the unmasked grid.
  const Dimensions n = {9, 9, 9};
  const Point_3 o(0., 0., 0.);
  const Vector_3 h(0.25, 0.25, 0.25);
  std::vector<float> values = node_values(o, h, n, smooth_field);
  std::vector<unsigned char> mask(9 * 9 * 9, 1);
  mask[4 + 9 * (4 + 9 * 4)] = 0;
  const Grid unmasked_cubic = Grid(o, h, n, values).with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  const Grid masked_linear(o, h, n, values, mask);
  const Grid masked_cubic = masked_linear.with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        const Point_3 p(0.25 * (i + u(rng)), 0.25 * (j + u(rng)), 0.25 * (k + u(rng)));
        const std::optional<Vector_3> v = masked_cubic(p);
        ASSERT_EQ(v.has_value(), masked_linear(p).has_value()) << p;
        if (!v)
          continue;
        const auto near_solid = [](int c) { return c >= 2 && c <= 5; }; // 4 in {c-1, ..., c+2}
        if (near_solid(i) && near_solid(j) && near_solid(k))
          EXPECT_EQ(*v, *masked_linear(p)) << p;
        else
          EXPECT_EQ(*v, *unmasked_cubic(p)) << p;
      }
  EXPECT_FALSE(masked_cubic(Point_3(1.1, 1.1, 1.1)).has_value());
  EXPECT_FALSE(masked_cubic(Point_3(2.01, 1.1, 1.1)).has_value()) << "outside the box";
}

} // namespace test_Regular_grid_flow_field_3
