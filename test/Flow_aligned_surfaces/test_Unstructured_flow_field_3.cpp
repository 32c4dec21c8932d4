// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unstructured_flow_field_3: linear fields reproduced on tetrahedra, wedges and pyramids,
// trilinear(-in-parameter) fields on distorted hexahedra, agreement with
// Regular_grid_flow_field_3 on the same grid, holes and the outside, shared faces, cell
// interiors that no other piece of the mesh reaches, threads, shared storage and the messages
// for bad input.

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/cell_shape_functions.h>

#include "test_kernel.h"

#include "expect_invalid_argument.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Unstructured_flow_field_3 {

namespace {

using namespace fas_test;
typedef FAS::Unstructured_flow_field_3<K> Field;
typedef Field::Index Index;

// The hexahedron corners in VTK order as offsets (di, dj, dk) from the cell's first node.
const int hex_corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

// A structured block of n[0] x n[1] x n[2] cells whose nodes sit at `position(i, j, k)`,
// written as an unstructured mesh of cells of one kind.
struct Block {
  std::array<int, 3> n;
  std::vector<double> points;
  std::vector<Index> connectivity, offsets{0};
  std::vector<unsigned char> types;

  Block(std::array<int, 3> cells, const std::function<std::array<double, 3>(int, int, int)>& position)
      : n(cells)
  {
    for (int k = 0; k <= n[2]; ++k)
      for (int j = 0; j <= n[1]; ++j)
        for (int i = 0; i <= n[0]; ++i) {
          const std::array<double, 3> x = position(i, j, k);
          points.insert(points.end(), x.begin(), x.end());
        }
  }

  Index node(int i, int j, int k) const { return i + (n[0] + 1) * (j + (n[1] + 1) * k); }

  std::array<Index, 8> hex(int i, int j, int k) const
  {
    std::array<Index, 8> h;
    for (int q = 0; q < 8; ++q)
      h[q] = node(i + hex_corner[q][0], j + hex_corner[q][1], k + hex_corner[q][2]);
    return h;
  }

  void add(unsigned char type, std::initializer_list<Index> ids)
  {
    connectivity.insert(connectivity.end(), ids.begin(), ids.end());
    offsets.push_back(static_cast<Index>(connectivity.size()));
    types.push_back(type);
  }

  Index add_point(const std::array<double, 3>& x)
  {
    points.insert(points.end(), x.begin(), x.end());
    return static_cast<Index>(points.size() / 3 - 1);
  }

  // kind: 12 hexahedra, 10 six tetrahedra per cell (Kuhn split along 0-6, conforming),
  // 13 two wedges per cell (split along 0-2 / 4-6), 14 six pyramids per cell around an extra
  // centre point.  `skip` removes cells.
  void fill(int kind, const std::function<bool(int, int, int)>& skip = nullptr)
  {
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
          if (skip && skip(i, j, k))
            continue;
          const std::array<Index, 8> h = hex(i, j, k);
          if (kind == 12) {
            add(12, {h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]});
          }
          else if (kind == 10) {
            const int path[6][2] = {{1, 2}, {3, 2}, {1, 5}, {4, 5}, {3, 7}, {4, 7}};
            for (const auto& p : path)
              add(10, {h[0], h[p[0]], h[p[1]], h[6]});
          }
          else if (kind == 13) {
            add(13, {h[0], h[1], h[2], h[4], h[5], h[6]});
            add(13, {h[0], h[2], h[3], h[4], h[6], h[7]});
          }
          else {
            std::array<double, 3> c = {0., 0., 0.};
            for (int q = 0; q < 8; ++q)
              for (int a = 0; a < 3; ++a)
                c[a] += points[3 * h[q] + a] / 8.;
            const Index apex = add_point(c);
            const int faces[6][4] = {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                     {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
            for (const auto& f : faces)
              add(14, {h[f[0]], h[f[1]], h[f[2]], h[f[3]], apex});
          }
        }
  }

  std::vector<float> values(const std::function<std::array<double, 3>(const double*)>& f) const
  {
    std::vector<float> v;
    for (std::size_t p = 0; p < points.size(); p += 3) {
      const std::array<double, 3> w = f(&points[p]);
      for (double c : w)
        v.push_back(static_cast<float>(c));
    }
    return v;
  }

  // With float_points, the points are given (and kept) as float.
  Field field(std::vector<float> v, bool float_points = false) const
  {
    if (float_points)
      return Field(std::vector<float>(points.begin(), points.end()), connectivity, offsets, types,
                   std::move(v));
    return Field(points, connectivity, offsets, types, std::move(v));
  }
};

// Random dyadic numbers (multiples of 1/8 in [-2, 2]): nodal values of the test fields are then
// exact in float, so the fields are reproduced to rounding.
double dyadic(std::mt19937& rng)
{
  return std::uniform_int_distribution<int>(-16, 16)(rng) / 8.;
}

struct Linear_field {
  double a[3], B[3][3];
  explicit Linear_field(std::mt19937& rng)
  {
    for (int d = 0; d < 3; ++d) {
      a[d] = dyadic(rng);
      for (int e = 0; e < 3; ++e)
        B[d][e] = dyadic(rng);
    }
  }
  std::array<double, 3> operator()(const double* x) const
  {
    std::array<double, 3> r;
    for (int d = 0; d < 3; ++d)
      r[d] = a[d] + B[d][0] * x[0] + B[d][1] * x[1] + B[d][2] * x[2];
    return r;
  }
};

// A general trilinear map: 8 coefficients of 1, x, y, z, xy, yz, xz, xyz per component.
struct Trilinear_field {
  std::array<std::array<double, 8>, 3> c;
  explicit Trilinear_field(std::mt19937& rng)
  {
    for (auto& comp : c)
      for (double& a : comp)
        a = dyadic(rng);
  }
  std::array<double, 3> operator()(const double* x) const
  {
    std::array<double, 3> r;
    for (int d = 0; d < 3; ++d) {
      const auto& a = c[d];
      r[d] = a[0] + a[1] * x[0] + a[2] * x[1] + a[3] * x[2] + a[4] * x[0] * x[1] + a[5] * x[1] * x[2] +
             a[6] * x[0] * x[2] + a[7] * x[0] * x[1] * x[2];
    }
    return r;
  }
};

// Nodes of a grid with spacing 1/2 moved by random multiples of 1/64 (at most 1/8, a quarter of
// the spacing, so every cell stays valid and non-degenerate) : non-parallelepiped cells with
// exactly representable coordinates.
// With flat_i >= 0, the nodes i = flat_i keep their x, so the faces between the cells i =
// flat_i - 1 and flat_i are planar.
std::function<std::array<double, 3>(int, int, int)> distorted_grid(unsigned seed, int flat_i = -1)
{
  return [seed, flat_i](int i, int j, int k) {
    std::mt19937 rng(seed + 7919u * unsigned(i) + 104729u * unsigned(j) + 1299709u * unsigned(k));
    std::uniform_int_distribution<int> u(-8, 8);
    const double dx = u(rng) / 64.;
    return std::array<double, 3>{1. + 0.5 * i + (i == flat_i ? 0. : dx), -2. + 0.5 * j + u(rng) / 64.,
                                 0.5 * k + u(rng) / 64.};
  };
}

// The position of parameters (r, s, t) in hexahedron `h` of `b`: the VTK trilinear map,
// written independently of the header.
std::array<double, 3> hex_map(const Block& b, const std::array<Index, 8>& h, const double* rst)
{
  std::array<double, 3> x = {0., 0., 0.};
  for (int q = 0; q < 8; ++q) {
    double w = 1.;
    for (int a = 0; a < 3; ++a)
      w *= hex_corner[q][a] ? rst[a] : 1. - rst[a];
    for (int a = 0; a < 3; ++a)
      x[a] += w * b.points[3 * h[q] + a];
  }
  return x;
}

Point_3 to_point(const std::array<double, 3>& x)
{
  return Point_3(x[0], x[1], x[2]);
}

void expect_near(const Vector_3& v, const std::array<double, 3>& e, double tol, const Point_3& p)
{
  EXPECT_NEAR(v.x(), e[0], tol) << "at " << p;
  EXPECT_NEAR(v.y(), e[1], tol) << "at " << p;
  EXPECT_NEAR(v.z(), e[2], tol) << "at " << p;
}

// Checks that a linear field is reproduced on a distorted block of 3 x 4 x 2 cells of one kind
// (hexahedra, or hexahedra split into tetrahedra, wedges or pyramids, whose boundary faces are
// flat where the hexahedra's are bilinear): every point farther than the largest node move
// from the undistorted block's boundary is inside, and every value returned, there or
// anywhere in a box around the block, is exact.
void check_linear_field_is_reproduced(int kind, bool float_points = false)
{
  std::mt19937 rng{static_cast<unsigned>(kind)};
  Block b({3, 4, 2}, distorted_grid(unsigned(kind)));
  b.fill(kind);
  const Linear_field f(rng);
  const Field field = b.field(b.values(f), float_points);
  ASSERT_EQ(field.points().float_data() != nullptr, float_points);
  const double lo[3] = {1., -2., 0.}, hi[3] = {2.5, 0., 1.};
  const double margin = 0.15; // > the largest node move, 1/8
  int found = 0;
  for (int q = 0; q < 2000; ++q) {
    const bool interior = q % 2 == 0;
    std::array<double, 3> x;
    for (int a = 0; a < 3; ++a) {
      const double m = interior ? margin : -0.3;
      x[a] = std::uniform_real_distribution<double>(lo[a] + m, hi[a] - m)(rng);
    }
    const Point_3 p = to_point(x);
    const std::optional<Vector_3> v = field(p);
    if (interior) {
      ASSERT_TRUE(v) << "cell type " << kind << ": no cell contains " << p;
    }
    if (!v)
      continue;
    ++found;
    expect_near(*v, f(x.data()), 1e-12, p);
  }
  EXPECT_GT(found, 1200);
}

// What a reader fills: no point, no cell, no point inside.
TEST(UnstructuredFlowField3, DefaultConstructedFieldIsEmpty)
{
  const Field f;
  EXPECT_EQ(f.number_of_points(), 0u);
  EXPECT_EQ(f.number_of_cells(), 0u);
  EXPECT_EQ(f.points().size(), 0u);
  EXPECT_EQ(f.bbox(), CGAL::Bbox_3());
  for (const Point_3& p : {Point_3(0, 0, 0), Point_3(-1e300, -1e300, -1e300), Point_3(1e300, 1e300, 1e300)}) {
    EXPECT_FALSE(f(p).has_value()) << p;
    EXPECT_FALSE(f.locate(p).has_value()) << p;
  }
}

TEST(UnstructuredFlowField3, LinearFieldIsReproducedOnTetrahedra)
{
  check_linear_field_is_reproduced(10);
}
TEST(UnstructuredFlowField3, LinearFieldIsReproducedOnHexahedra)
{
  check_linear_field_is_reproduced(12);
}
// The block's coordinates are multiples of 1/64, exact in float: float points give the same
// exact answers.
TEST(UnstructuredFlowField3, LinearFieldIsReproducedWithFloatPoints)
{
  for (int kind : {10, 12, 13, 14})
    check_linear_field_is_reproduced(kind, true);
}
TEST(UnstructuredFlowField3, LinearFieldIsReproducedOnWedges)
{
  check_linear_field_is_reproduced(13);
}
TEST(UnstructuredFlowField3, LinearFieldIsReproducedOnPyramids)
{
  check_linear_field_is_reproduced(14);
}

TEST(UnstructuredFlowField3, TrilinearFieldInTheParametersIsReproducedOnDistortedHexahedra)
{
  // Node (i, j, k) carries g(i, j, k) with g trilinear, so the isoparametric interpolation at
  // the point of parameters (r, s, t) in cell (i, j, k) is g(i + r, j + s, k + t).
  std::mt19937 rng(3);
  Block b({3, 3, 3}, distorted_grid(11));
  b.fill(12);
  const Trilinear_field g(rng);
  std::vector<float> values;
  for (int k = 0; k <= 3; ++k)
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 3; ++i) {
        const double ijk[3] = {double(i), double(j), double(k)};
        for (double c : g(ijk))
          values.push_back(float(c));
      }
  const Field field = b.field(values);
  std::uniform_real_distribution<double> u(0., 1.);
  for (int q = 0; q < 1000; ++q) {
    const int c[3] = {int(rng() % 3), int(rng() % 3), int(rng() % 3)};
    const double rst[3] = {u(rng), u(rng), u(rng)};
    const Point_3 p = to_point(hex_map(b, b.hex(c[0], c[1], c[2]), rst));
    const double global[3] = {c[0] + rst[0], c[1] + rst[1], c[2] + rst[2]};
    const std::optional<Vector_3> v = field(p);
    ASSERT_TRUE(v) << "no cell contains " << p;
    expect_near(*v, g(global), 1e-9, p);
  }
}

TEST(UnstructuredFlowField3, AHexahedronsPolynomialMapStepsAsItsShapeFunctionsDo)
{
  // The Newton step of a hexahedron from its map's polynomial coefficients is the step from its
  // shape functions, up to rounding, on distorted cells; both refuse a flat cell.
  namespace I = FAS::internal;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2), parameter(-0.3, 1.3);
  for (int q = 0; q < 200; ++q) {
    double X[8][3];
    for (int i = 0; i < 8; ++i)
      for (int a = 0; a < 3; ++a)
        X[i][a] = hex_corner[i][a] * (1. + a) + jitter(rng);
    const double p[3] = {parameter(rng), 2 * parameter(rng), 3 * parameter(rng)};
    const double xi[3] = {parameter(rng), parameter(rng), parameter(rng)};
    double from_shapes[3], from_polynomial[3];
    ASSERT_TRUE(I::newton_step(I::VTK_cell_type::HEXAHEDRON, X, 8, p, xi, from_shapes));
    ASSERT_TRUE(I::Hexahedron_map(X).newton_step(p, xi, from_polynomial));
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(from_polynomial[a], from_shapes[a], 1e-11 * (1. + std::abs(from_shapes[a])))
          << "cell " << q;
  }
  double flat[8][3];
  for (int i = 0; i < 8; ++i)
    flat[i][0] = hex_corner[i][0], flat[i][1] = hex_corner[i][1], flat[i][2] = 0.;
  const double p[3] = {0.5, 0.5, 0.}, xi[3] = {0.5, 0.5, 0.5};
  double d[3];
  EXPECT_FALSE(I::newton_step(I::VTK_cell_type::HEXAHEDRON, flat, 8, p, xi, d));
  EXPECT_FALSE(I::Hexahedron_map(flat).newton_step(p, xi, d));
}

TEST(UnstructuredFlowField3, AParallelepipedIsInvertedByOneNewtonStep)
{
  // A parallelepiped's map x = o + A xi is affine: one Newton step from the centre finds xi, in
  // the cell or outside it (as the walk needs).  A hexahedron with one corner moved is not
  // affine and takes more steps to the same accuracy.
  namespace I = FAS::internal;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> entry(-0.3, 0.3), parameter(-0.5, 1.5);
  for (int q = 0; q < 100; ++q) {
    double A[3][3], o[3], X[8][3];
    for (int a = 0; a < 3; ++a) {
      o[a] = 10. * entry(rng);
      for (int b = 0; b < 3; ++b)
        A[a][b] = (a == b ? 1. + a : 0.) + entry(rng);
    }
    for (int i = 0; i < 8; ++i)
      for (int a = 0; a < 3; ++a)
        X[i][a] = o[a] + A[a][0] * hex_corner[i][0] + A[a][1] * hex_corner[i][1] + A[a][2] * hex_corner[i][2];
    const double truth[3] = {parameter(rng), parameter(rng), parameter(rng)};
    double p[3];
    for (int a = 0; a < 3; ++a)
      p[a] = o[a] + A[a][0] * truth[0] + A[a][1] * truth[1] + A[a][2] * truth[2];
    EXPECT_TRUE(I::Hexahedron_map(X).is_affine()) << "cell " << q;
    double xi[3];
    I::newton_start(I::VTK_cell_type::HEXAHEDRON, xi);
    ASSERT_EQ(I::newton_iterations(I::VTK_cell_type::HEXAHEDRON, X, 8, p, xi), I::Newton_outcome::CONVERGED);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(xi[a], truth[a], 1e-12) << "cell " << q;
    X[6][0] += 0.1;
    EXPECT_FALSE(I::Hexahedron_map(X).is_affine()) << "cell " << q;
  }
}

TEST(UnstructuredFlowField3, TrilinearFieldIsReproducedOnAParallelepipedGrid)
{
  std::mt19937 rng(5);
  Block b({4, 3, 2}, [](int i, int j, int k) {
    return std::array<double, 3>{-1. + 0.25 * i, 0.5 * j, 2. + 0.125 * k};
  });
  b.fill(12);
  const Trilinear_field f(rng);
  const Field field = b.field(b.values(f));
  std::uniform_real_distribution<double> u(0., 1.);
  for (int q = 0; q < 1000; ++q) {
    const std::array<double, 3> x = {-1. + u(rng), 1.5 * u(rng), 2. + 0.25 * u(rng)};
    const Point_3 p = to_point(x);
    const std::optional<Vector_3> v = field(p);
    ASSERT_TRUE(v) << "no cell contains " << p;
    expect_near(*v, f(x.data()), 1e-9, p);
  }
}

TEST(UnstructuredFlowField3, AgreesWithRegularGridFlowField3OnTheSameGrid)
{
  std::mt19937 rng(17);
  const Point_3 origin(0.5, -1., 2.);
  const Vector_3 h(0.3, 0.7, 0.45);
  const FAS::Regular_grid_flow_field_3<K>::Dimensions dims = {6, 5, 7};
  std::uniform_real_distribution<float> uf(-3.f, 3.f);
  std::vector<float> values(3 * dims[0] * dims[1] * dims[2]);
  for (float& v : values)
    v = uf(rng);
  const FAS::Regular_grid_flow_field_3<K> grid(origin, h, dims, values);
  // Same node numbering (i fastest), same node positions.
  Block b({int(dims[0]) - 1, int(dims[1]) - 1, int(dims[2]) - 1}, [&](int i, int j, int k) {
    const Point_3 p = grid.node_point(std::size_t(i), std::size_t(j), std::size_t(k));
    return std::array<double, 3>{p.x(), p.y(), p.z()};
  });
  b.fill(12);
  const Field field = b.field(values);

  const CGAL::Bbox_3 box = grid.bbox();
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  int inside = 0;
  for (int q = 0; q < 3000; ++q) {
    const Point_3 p(box.xmin() + u(rng) * (box.xmax() - box.xmin()),
                    box.ymin() + u(rng) * (box.ymax() - box.ymin()),
                    box.zmin() + u(rng) * (box.zmax() - box.zmin()));
    const std::optional<Vector_3> a = grid(p), c = field(p);
    ASSERT_EQ(bool(a), bool(c)) << "at " << p;
    if (!a)
      continue;
    ++inside;
    EXPECT_NEAR(a->x(), c->x(), 1e-6) << "at " << p;
    EXPECT_NEAR(a->y(), c->y(), 1e-6) << "at " << p;
    EXPECT_NEAR(a->z(), c->z(), 1e-6) << "at " << p;
  }
  EXPECT_GT(inside, 1000);
}

TEST(UnstructuredFlowField3, PointsOfTheMeshGetTheirOwnValues)
{
  // Vertices are where most cells meet and where the pyramids' map is singular (the apex).
  for (int kind : {10, 12, 13, 14}) {
    SCOPED_TRACE(kind);
    std::mt19937 rng{static_cast<unsigned>(kind + 60)};
    Block b({2, 3, 2}, distorted_grid(61));
    b.fill(kind);
    std::uniform_real_distribution<float> u(-3.f, 3.f);
    std::vector<float> values(b.points.size());
    for (float& v : values)
      v = u(rng);
    const Field field = b.field(values);
    for (std::size_t i = 0; i < b.points.size() / 3; ++i) {
      const Point_3 p(b.points[3 * i], b.points[3 * i + 1], b.points[3 * i + 2]);
      const std::optional<Vector_3> v = field(p);
      ASSERT_TRUE(v) << "point " << i << " " << p;
      expect_near(*v, {values[3 * i], values[3 * i + 1], values[3 * i + 2]}, 1e-9, p);
    }
  }
}

TEST(UnstructuredFlowField3, OutsideAndInAHoleIsNullopt)
{
  for (int kind : {10, 12, 13, 14}) {
    // Unit cells on [0, 4]^3 without the 8 cells of [1, 3]^3.
    Block b({4, 4, 4}, [](int i, int j, int k) {
      return std::array<double, 3>{double(i), double(j), double(k)};
    });
    b.fill(kind,
           [](int i, int j, int k) { return i >= 1 && i <= 2 && j >= 1 && j <= 2 && k >= 1 && k <= 2; });
    const Field field = b.field(b.values([](const double* x) {
      return std::array<double, 3>{x[0], x[1], x[2]};
    }));
    SCOPED_TRACE(kind);
    EXPECT_FALSE(field(Point_3(2., 2., 2.)));
    EXPECT_FALSE(field(Point_3(1.5, 2.7, 1.1)));
    EXPECT_FALSE(field(Point_3(2.999, 1.001, 2.5)));
    EXPECT_FALSE(field(Point_3(-0.001, 2., 2.)));
    EXPECT_FALSE(field(Point_3(2., 4.001, 2.)));
    EXPECT_FALSE(field(Point_3(100., 100., 100.)));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(field(Point_3(nan, 2., 2.)));
    // Just beside the hole, on its wall, and on the outer boundary: inside.
    EXPECT_TRUE(field(Point_3(0.999, 2., 2.)));
    EXPECT_TRUE(field(Point_3(1., 2., 2.)));
    EXPECT_TRUE(field(Point_3(3., 1.5, 2.5)));
    EXPECT_TRUE(field(Point_3(0., 2.5, 2.5)));
    EXPECT_TRUE(field(Point_3(4., 4., 4.)));
    const std::optional<Vector_3> v = field(Point_3(3.25, 0.5, 3.75));
    ASSERT_TRUE(v);
    EXPECT_NEAR(v->x(), 3.25, 1e-12);
    EXPECT_NEAR(v->y(), 0.5, 1e-12);
    EXPECT_NEAR(v->z(), 3.75, 1e-12);
  }
}

TEST(UnstructuredFlowField3, SharedFacesGiveTheSameValueFromEitherCell)
{
  // Two columns of cells meeting at the face i = 1 of a distorted 2 x 1 x 1 block, for each
  // conforming pair of cell kinds, with a trilinear (not linear) field: values on the shared
  // face still agree because each face is interpolated from its own points only.  The shared
  // face is kept planar so that its two triangles (tetrahedra) and its bilinear patch
  // (hexahedra, wedges, pyramids) are the same set.
  const int pairs[7][2] = {{12, 12}, {12, 14}, {14, 12}, {12, 13}, {13, 13}, {10, 10}, {14, 14}};
  for (const auto& pair : pairs) {
    SCOPED_TRACE(std::to_string(pair[0]) + " | " + std::to_string(pair[1]));
    std::mt19937 rng(unsigned(23 + pair[0] * 100 + pair[1]));
    Block b({2, 1, 1}, distorted_grid(29, 1));
    b.fill(pair[0], [](int i, int, int) { return i != 0; });
    const std::size_t left_cells = b.types.size();
    b.fill(pair[1], [](int i, int, int) { return i != 1; });
    const Trilinear_field f(rng);
    const Field field = b.field(b.values(f));
    std::uniform_real_distribution<double> u(0., 1.);
    for (int q = 0; q < 200; ++q) {
      const double rst[3] = {1., u(rng), u(rng)};
      const Point_3 p = to_point(hex_map(b, b.hex(0, 0, 0), rst));
      const std::optional<Vector_3> located = field(p);
      ASSERT_TRUE(located) << "no cell contains " << p;
      bool left = false, right = false;
      for (std::size_t c = 0; c < field.number_of_cells(); ++c) {
        const std::optional<Vector_3> v = field.evaluate_in_cell(c, p);
        if (!v)
          continue;
        (c < left_cells ? left : right) = true;
        EXPECT_NEAR(v->x(), located->x(), 1e-12) << "cell " << c << " at " << p;
        EXPECT_NEAR(v->y(), located->y(), 1e-12) << "cell " << c << " at " << p;
        EXPECT_NEAR(v->z(), located->z(), 1e-12) << "cell " << c << " at " << p;
      }
      EXPECT_TRUE(left && right) << "the face point " << p << " is not in a cell on each side";
    }
  }
}

TEST(UnstructuredFlowField3, APointInACellsInteriorIsInNoOtherPiece)
{
  // The two columns of a distorted 2 x 1 x 1 block as two pieces, each a field of its own (the
  // pieces of a mesh on two processes), for each conforming pair of cell kinds.  Where a piece
  // says a point is in a cell's interior, the other piece does not contain it; points on the
  // shared face are in neither interior; and nearly every point of a cell is in one.
  const int pairs[7][2] = {{12, 12}, {12, 14}, {14, 12}, {12, 13}, {13, 13}, {10, 10}, {14, 14}};
  for (const auto& pair : pairs) {
    SCOPED_TRACE(std::to_string(pair[0]) + " | " + std::to_string(pair[1]));
    std::mt19937 rng(unsigned(31 + pair[0] * 100 + pair[1]));
    const auto position = distorted_grid(37, 1);
    Block left_cells({2, 1, 1}, position), right_cells({2, 1, 1}, position);
    left_cells.fill(pair[0], [](int i, int, int) { return i != 0; });
    right_cells.fill(pair[1], [](int i, int, int) { return i != 1; });
    const Trilinear_field f(rng);
    const Field left = left_cells.field(left_cells.values(f)),
                right = right_cells.field(right_cells.values(f));
    std::uniform_real_distribution<double> u(0., 1.);
    int inside = 0, in_an_interior = 0;
    for (int q = 0; q < 2000; ++q) {
      // Half of the points on the shared face (r = 1 in the left cell), half anywhere in the cells.
      const bool on_face = q % 2 == 0;
      const double r = on_face ? 1. : 2. * u(rng);
      const bool left_cell = r <= 1.;
      const double rst[3] = {left_cell ? r : r - 1., u(rng), u(rng)};
      const Point_3 p = to_point(left_cell ? hex_map(left_cells, left_cells.hex(0, 0, 0), rst)
                                           : hex_map(right_cells, right_cells.hex(1, 0, 0), rst));
      const bool in_left = left.is_in_cell_interior(p), in_right = right.is_in_cell_interior(p);
      if (on_face) {
        EXPECT_FALSE(in_left || in_right) << "the shared face's point " << p << " is in a cell's interior";
        continue;
      }
      // (The split cells' flat faces leave out some points of the hexahedra's curved ones.)
      if (!left(p) && !right(p))
        continue;
      ++inside;
      in_an_interior += in_left || in_right ? 1 : 0;
      if (in_left) {
        EXPECT_TRUE(left(p)) << p;
        EXPECT_FALSE(right(p)) << "the right piece contains " << p << ", in the interior of a left cell";
      }
      if (in_right) {
        EXPECT_TRUE(right(p)) << p;
        EXPECT_FALSE(left(p)) << "the left piece contains " << p << ", in the interior of a right cell";
      }
    }
    EXPECT_GT(inside, 900);
    EXPECT_GT(in_an_interior, inside * 99 / 100);
  }
  // Outside the mesh, nothing is in a cell's interior.
  Block b({2, 1, 1}, distorted_grid(37, 1));
  b.fill(12);
  std::mt19937 rng(41);
  const Field field = b.field(b.values(Trilinear_field(rng)));
  for (const Point_3& p : {Point_3(0., -1.75, 0.25), Point_3(3., -1.75, 0.25), Point_3(1.5, -1.75, -1.)})
    EXPECT_FALSE(field.is_in_cell_interior(p)) << p;
}

TEST(UnstructuredFlowField3, BadInputThrowsWithTheArgumentsName)
{
  // Two tetrahedra sharing a face.
  const std::vector<double> pts = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<Index> conn = {0, 1, 2, 3, 1, 2, 3, 4};
  const std::vector<Index> offs = {0, 4, 8};
  const std::vector<unsigned char> types = {10, 10};
  const std::vector<float> vec(15, 1.f);
  EXPECT_NO_THROW(Field(pts, conn, offs, types, vec));
  EXPECT_NO_THROW(Field(std::vector<float>(pts.begin(), pts.end()), conn, {4, 8}, types, vec));
  // 64-bit indices (VTK's vtkIdType) are accepted and narrowed; those beyond 32 bits refused.
  std::vector<std::int64_t> conn64(conn.begin(), conn.end()), offs64(offs.begin(), offs.end());
  EXPECT_EQ(Field(pts, conn64, offs64, types, vec).connectivity(), conn);
  conn64[5] = std::int64_t(1) << 31;
  expect_invalid_argument([&] { Field(pts, conn64, offs64, types, vec); },
                          {"connectivity[5]", "2147483648", "2^31"});

  std::vector<double> p7(pts.begin(), pts.begin() + 7);
  expect_invalid_argument([&] { Field(p7, conn, offs, types, vec); }, {"points.size()", "7"});
  expect_invalid_argument([&] { Field(pts, conn, offs, types, std::vector<float>(12)); },
                          {"vectors.size()", "12", "15"});
  expect_invalid_argument([&] { Field(pts, conn, offs, {}, vec); }, {"cell_types", "empty"});
  expect_invalid_argument([&] { Field(pts, conn, {0, 4, 8, 8}, types, vec); }, {"offsets.size()", "4"});
  expect_invalid_argument([&] { Field(pts, conn, {1, 4, 8}, types, vec); }, {"offsets[0]", "1"});
  expect_invalid_argument([&] { Field(pts, conn, {0, 4, 7}, types, vec); }, {"offset", "7", "8"});
  expect_invalid_argument([&] { Field(pts, conn, offs, {10, 11}, vec); }, {"cell_types[1]", "11"});
  expect_invalid_argument([&] { Field(pts, conn, offs, {10, 12}, vec); }, {"cell 1", "hexahedron", "8"});
  std::vector<Index> bad = conn;
  bad[6] = 5;
  expect_invalid_argument([&] { Field(pts, bad, offs, types, vec); }, {"connectivity[6]", "5"});
  bad[6] = -1;
  expect_invalid_argument([&] { Field(pts, bad, offs, types, vec); }, {"connectivity[6]", "-1"});
  std::vector<double> nan_pts = pts;
  nan_pts[3 * 2 + 1] = std::numeric_limits<double>::quiet_NaN();
  expect_invalid_argument([&] { Field(nan_pts, conn, offs, types, vec); }, {"points[7]", "point 2", "nan"});
  std::vector<float> inf_vec = vec;
  inf_vec[3 * 4 + 2] = std::numeric_limits<float>::infinity();
  expect_invalid_argument([&] { Field(pts, conn, offs, types, inf_vec); }, {"vectors[14]", "point 4", "inf"});
}

TEST(UnstructuredFlowField3, CopiesShareStorage)
{
  Block b({2, 2, 2}, [](int i, int j, int k) {
    return std::array<double, 3>{double(i), double(j), double(k)};
  });
  b.fill(10);
  std::vector<float> v = b.values([](const double*) { return std::array<double, 3>{1., 2., 3.}; });
  const float* data = v.data();
  const Field field(b.points, b.connectivity, b.offsets, b.types, std::move(v));
  // The moved-in vectors are kept, not copied.
  EXPECT_EQ(field.vectors().data(), data);
  const Field copy = field;
  EXPECT_EQ(copy.vectors().data(), data);
  EXPECT_EQ(copy.points().double_data(), field.points().double_data());
  EXPECT_EQ(copy.connectivity().data(), field.connectivity().data());
  EXPECT_EQ(copy.number_of_cells(), 48u);
  EXPECT_EQ(*copy(Point_3(0.5, 1.5, 0.25)), Vector_3(1, 2, 3));
}

TEST(UnstructuredFlowField3, ConcurrentQueriesFromSeveralThreads)
{
  // Each thread walks its own coherent path through the same field (and so keeps its own
  // hint); every answer must be the exact one.
  Block b({6, 6, 6}, distorted_grid(41));
  b.fill(10);
  std::mt19937 rng(43);
  const Linear_field f(rng);
  const Field field = b.field(b.values(f));
  std::vector<int> failures(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      const Field local = field; // a copy shares the storage and the hint key
      for (int q = 0; q < 5000; ++q) {
        const double s = q / 5000.;
        const double rst[3] = {0.5, 0.5, 0.5};
        // Centres of the inner 4 x 4 x 4 cells, moved by at most 0.2 < 0.5 - 1/8: inside.
        const std::array<Index, 8> h =
            b.hex(1 + int(s * 4) % 4, 1 + (t + int(s * 12)) % 4, 1 + (2 * t + q / 1000) % 4);
        std::array<double, 3> x = hex_map(b, h, rst);
        x[0] += 0.2 * std::sin(40. * s + t);
        x[1] += 0.2 * std::cos(30. * s);
        const std::optional<Vector_3> v = (t % 2 ? local : field)(to_point(x));
        const std::array<double, 3> e = f(x.data());
        if (!v || std::abs(v->x() - e[0]) > 1e-12 || std::abs(v->y() - e[1]) > 1e-12 ||
            std::abs(v->z() - e[2]) > 1e-12)
          ++failures[t];
      }
    });
  for (std::thread& th : threads)
    th.join();
  for (int t = 0; t < 4; ++t)
    EXPECT_EQ(failures[t], 0) << "thread " << t;
}

TEST(UnstructuredFlowField3, AlternatingBetweenFieldsOnOneThreadIsCorrect)
{
  // A thread keeps the walk caches of the last 4 fields it queried; 6 fields queried in turn
  // (the same point in each) evict and reuse them.  Each query must use its own field's hint
  // and neighbours only, even where another field's hint cell index exists in it.
  std::mt19937 rng(47);
  std::vector<Block> blocks;
  std::vector<Linear_field> flows;
  std::vector<Field> fields;
  for (int m = 0; m < 6; ++m) {
    blocks.emplace_back(std::array<int, 3>{3, 3, 3}, distorted_grid(51 + 2 * m));
    blocks.back().fill(10 + 2 * (m % 2));
    flows.emplace_back(rng);
    fields.push_back(blocks.back().field(blocks.back().values(flows.back())));
  }
  std::uniform_real_distribution<double> u(1.2, 2.3);
  for (int q = 0; q < 500; ++q) {
    const std::array<double, 3> x = {u(rng), u(rng) - 3., u(rng) - 1.};
    const Point_3 p = to_point(x);
    // In turn: 2 fields (as an unsteady field between two steps), then all 6.
    const int count = q < 250 ? 2 : 6;
    for (int m = 0; m < count; ++m) {
      const std::optional<Vector_3> v = fields[std::size_t(m)](p);
      ASSERT_TRUE(v) << "field " << m << " at " << p;
      expect_near(*v, flows[std::size_t(m)](x.data()), 1e-12, p);
    }
  }
}

TEST(UnstructuredFlowField3, FaceNeighboursAreFound)
{
  Block b({2, 1, 1}, [](int i, int j, int k) {
    return std::array<double, 3>{double(i), double(j), double(k)};
  });
  b.fill(12);
  const Field field = b.field(std::vector<float>(3 * b.points.size() / 3, 0.f));
  EXPECT_EQ(field.face_neighbours(0), std::vector<std::size_t>{1});
  EXPECT_EQ(field.face_neighbours(1), std::vector<std::size_t>{0});
  Block t({1, 1, 1}, [](int i, int j, int k) {
    return std::array<double, 3>{double(i), double(j), double(k)};
  });
  t.fill(14);
  const Field pyramids = t.field(std::vector<float>(t.points.size(), 0.f));
  // Each pyramid touches the four pyramids around its base through its triangles.
  for (std::size_t c = 0; c < 6; ++c)
    EXPECT_EQ(pyramids.face_neighbours(c).size(), 4u) << c;
}

} // namespace

} // namespace test_Unstructured_flow_field_3
