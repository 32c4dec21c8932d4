// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The legacy VTK reader on every dataset type: hand-written ASCII and binary RECTILINEAR_GRID,
// STRUCTURED_GRID, UNSTRUCTURED_GRID (both forms of CELLS) and STRUCTURED_POINTS files holding a
// linear field v(p) = A p + b at dyadic points (exact in float), which tetrahedra, wedges,
// pyramids and (isoparametric) hexahedra reproduce exactly, at random points in the cells; the
// node mask; every kind of bad input (message parts checked, output untouched); and the real
// CFD data of ../shared/data: the counts their .md states, the cells and grid forms agreeing at
// the grid nodes, and patches aligning in them.

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include "real_data.h"
#include "test_files.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_VTK_legacy_datasets {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Grid = FAS::Regular_grid_flow_field_3<K>;
using Rectilinear = FAS::Rectilinear_grid_flow_field_3<K>;
using Cells = FAS::Unstructured_flow_field_3<K>;
using P3 = std::array<double, 3>;

std::string temporary(const std::string& name)
{
  return temporary_file("fas_read_VTK_legacy_datasets_", name);
}

// The linear field: small dyadic coefficients, so its values at dyadic points are exact floats.
P3 linear(const P3& p)
{
  return {{1. + p[0] + 2. * p[1] - p[2], -2. + 0.5 * p[0] - 3. * p[1] + 2. * p[2],
           0.5 - 2. * p[0] + p[1] + 0.25 * p[2]}};
}

// A legacy VTK file under construction: text lines, and value lists in ASCII or big-endian
// binary of a given VTK type.
struct Vtk_file {
  bool binary;
  std::string s;

  Vtk_file(bool binary_, const std::string& dataset, const std::string& version = "3.0") : binary(binary_)
  {
    s = "# vtk DataFile Version " + version + "\nhand-written test file\n" +
        (binary ? "BINARY\n" : "ASCII\n") + "DATASET " + dataset + "\n";
  }

  Vtk_file& line(const std::string& l)
  {
    s += l + "\n";
    return *this;
  }

  Vtk_file& values(const std::string& type, const std::vector<double>& v)
  {
    if (!binary) {
      std::ostringstream os;
      os.precision(17);
      for (std::size_t i = 0; i < v.size(); ++i)
        os << v[i] << (i + 1 == v.size() ? "\n" : " ");
      s += os.str();
      return *this;
    }
    for (double x : v) {
      std::uint64_t u = 0;
      int bytes = 4;
      if (type == "float") {
        const float f = static_cast<float>(x);
        std::uint32_t w;
        std::memcpy(&w, &f, 4);
        u = w;
      }
      else if (type == "double") {
        std::memcpy(&u, &x, 8);
        bytes = 8;
      }
      else if (type == "vtktypeint64") {
        u = static_cast<std::uint64_t>(static_cast<std::int64_t>(x));
        bytes = 8;
      }
      else { // int
        u = static_cast<std::uint32_t>(static_cast<std::int32_t>(x));
      }
      for (int b = bytes - 1; b >= 0; --b)
        s += static_cast<char>((u >> (8 * b)) & 0xff);
    }
    s += "\n";
    return *this;
  }

  // POINT_DATA with the linear field at `points` (x, y, z per point) as VECTORS velocity.
  Vtk_file& velocity(const std::vector<double>& points)
  {
    std::vector<double> v;
    for (std::size_t p = 0; p < points.size(); p += 3) {
      const P3 w = linear({{points[p], points[p + 1], points[p + 2]}});
      v.insert(v.end(), w.begin(), w.end());
    }
    line("POINT_DATA " + std::to_string(points.size() / 3)).line("VECTORS velocity float");
    return values("float", v);
  }
};

// Expects the field at `p` to be the linear field, up to the rounding of the cells' Newton
// inversion (values below 20).
template <class Field>
void expect_linear_at(const Field& f, const P3& p, double tolerance)
{
  const std::optional<Vector> v = f(Point(p[0], p[1], p[2]));
  ASSERT_TRUE(v.has_value()) << p[0] << " " << p[1] << " " << p[2];
  const P3 w = linear(p);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR((*v)[d], w[d], tolerance) << p[0] << " " << p[1] << " " << p[2];
}

// The trilinear map of a hexahedron (8 points in VTK order) at parametric (r, s, t).
P3 hex_point(const std::array<P3, 8>& x, double r, double s, double t)
{
  const int bits[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  P3 p = {{0, 0, 0}};
  for (int q = 0; q < 8; ++q) {
    const double w = (bits[q][0] ? r : 1 - r) * (bits[q][1] ? s : 1 - s) * (bits[q][2] ? t : 1 - t);
    for (int a = 0; a < 3; ++a)
      p[a] += w * x[q][a];
  }
  return p;
}

// A random convex combination of the given points (inside their convex hull).
P3 convex_point(const std::vector<P3>& x, std::mt19937& rng)
{
  std::exponential_distribution<double> e(1.);
  std::vector<double> w(x.size());
  double sum = 0;
  for (double& wi : w)
    sum += (wi = e(rng));
  P3 p = {{0, 0, 0}};
  for (std::size_t q = 0; q < x.size(); ++q)
    for (int a = 0; a < 3; ++a)
      p[a] += w[q] / sum * x[q][a];
  return p;
}

// ------------------------------------------------------------------------------------------
// The test files

// RECTILINEAR_GRID 4 x 3 x 5 with uneven dyadic coordinates.
const std::array<std::vector<double>, 3> kAxes = {
    {{0., 0.5, 1.25, 3.}, {-1., 0., 0.25}, {0., 1., 1.5, 2., 4.}}};

std::vector<double> grid_points(const std::array<std::vector<double>, 3>& X)
{
  std::vector<double> p;
  for (double z : X[2])
    for (double y : X[1])
      for (double x : X[0])
        p.insert(p.end(), {x, y, z});
  return p;
}

std::string rectilinear_file(bool binary, const std::string& type)
{
  Vtk_file f(binary, "RECTILINEAR_GRID");
  f.line("DIMENSIONS 4 3 5");
  const char* names[3] = {"X", "Y", "Z"};
  for (int a = 0; a < 3; ++a)
    f.line(std::string(names[a]) + "_COORDINATES " + std::to_string(kAxes[a].size()) + " " + type)
        .values(type, kAxes[a]);
  return f.velocity(grid_points(kAxes)).s;
}

// STRUCTURED_GRID 3 x 3 x 4: a lattice with dyadic, non-affine displacements, so that the
// hexahedra are not parallelepipeds (their faces are not planar).
P3 curvilinear_node(int i, int j, int k)
{
  return {{i + 0.25 * j + 0.125 * ((i * k) % 2), j + 0.125 * i * i - 0.0625 * k,
           0.75 * k + 0.125 * ((i + j) % 2)}};
}

std::string structured_grid_file(bool binary)
{
  std::vector<double> points;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const P3 x = curvilinear_node(i, j, k);
        points.insert(points.end(), x.begin(), x.end());
      }
  Vtk_file f(binary, "STRUCTURED_GRID");
  f.line("DIMENSIONS 3 3 4").line("POINTS 36 double").values("double", points);
  return f.velocity(points).s;
}

// UNSTRUCTURED_GRID: a distorted hexahedron, a pyramid on its top face, a wedge and a
// tetrahedron, apart from each other.
const std::vector<P3> kPoints = {{{0, 0, 0}},        {{1, 0, -0.125}}, {{1.125, 1, 0}},  {{0, 1, 0}},
                                 {{0, 0, 1}},        {{1, 0, 1}},      {{1, 1, 1}},      {{0, 1, 1}},
                                 {{0.5, 0.5, 1.75}}, {{2, 0, 0}},      {{3, 0, 0}},      {{2, 1, 0}},
                                 {{2, 0, 1}},        {{3, 0, 1.25}},   {{2, 1, 1}},      {{2, 0, 2}},
                                 {{3, 0, 2}},        {{2, 1, 2}},      {{2.25, 0.25, 3}}};
const std::vector<std::vector<int>> kCells = {
    {0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 8}, {9, 10, 11, 12, 13, 14}, {15, 16, 17, 18}};
const std::vector<double> kTypes = {12, 14, 13, 10};

std::vector<double> flat(const std::vector<P3>& points)
{
  std::vector<double> r;
  for (const P3& p : points)
    r.insert(r.end(), p.begin(), p.end());
  return r;
}

// The file up to and including CELL_TYPES; `new_form` writes the OFFSETS/CONNECTIVITY form of
// file version 5.1, else the per-cell lists.  With `types` = kVoxelTypes, the first cell is
// written as a VTK_VOXEL: its points in voxel order (x fastest, then y, then z).
const std::vector<double> kVoxelTypes = {11, 14, 13, 10};
Vtk_file unstructured_geometry(bool binary, bool new_form, const std::vector<double>& types = kTypes)
{
  Vtk_file f(binary, "UNSTRUCTURED_GRID", new_form ? "5.1" : "3.0");
  f.line("POINTS 19 float").values("float", flat(kPoints));
  std::vector<double> list, offsets{0}, connectivity;
  std::vector<std::vector<int>> cells = kCells;
  if (types == kVoxelTypes)
    cells[0] = {0, 1, 3, 2, 4, 5, 7, 6};
  for (const std::vector<int>& c : cells) {
    list.push_back(double(c.size()));
    for (int p : c) {
      list.push_back(p);
      connectivity.push_back(p);
    }
    offsets.push_back(double(connectivity.size()));
  }
  if (new_form) {
    f.line("CELLS 5 23").line("OFFSETS vtktypeint64").values("vtktypeint64", offsets);
    f.line("CONNECTIVITY vtktypeint64").values("vtktypeint64", connectivity);
  }
  else {
    f.line("CELLS 4 27").values("int", list);
  }
  return f.line("CELL_TYPES 4").values("int", types);
}

std::string unstructured_file(bool binary, bool new_form)
{
  return unstructured_geometry(binary, new_form).velocity(flat(kPoints)).s;
}

// STRUCTURED_POINTS 4 x 3 x 3 with a mask: node (1, 1, 1) solid.
std::string structured_points_file(bool binary)
{
  Vtk_file f(binary, "STRUCTURED_POINTS");
  f.line("DIMENSIONS 4 3 3").line("ORIGIN -1 0.5 2").line("SPACING 0.5 0.25 1");
  std::vector<double> points;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        points.insert(points.end(), {-1 + 0.5 * i, 0.5 + 0.25 * j, 2. + k});
  f.velocity(points).line("SCALARS inside int").line("LOOKUP_TABLE default");
  std::vector<double> inside(36, 1.);
  inside[1 + 4 * (1 + 3 * 1)] = 0.;
  return f.values("int", inside).s;
}

template <class Field>
Field read_ok(const std::string& name, const std::string& contents)
{
  const std::string file = temporary(name);
  write_bytes(file, contents);
  Field field;
  std::string error;
  const bool read = FAS::IO::read_VTK_flow_field(file, field, FAS::parameters::error_message(&error));
  EXPECT_TRUE(read) << name << ": " << error;
  if (!read)
    throw std::runtime_error(name + ": " + error);
  return field;
}

// ------------------------------------------------------------------------------------------
// Each dataset type holds the linear field exactly

// The checks of each dataset read: the geometry as written, the linear field at random points.
void expect_rectilinear(const Rectilinear& r, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0., 1.);
  EXPECT_EQ(r.dimensions(), (Rectilinear::Dimensions{{4, 3, 5}}));
  for (int a = 0; a < 3; ++a)
    EXPECT_EQ(r.coordinates(a), kAxes[a]);
  for (int s = 0; s < 500; ++s)
    expect_linear_at(r, {{3. * u(rng), -1. + 1.25 * u(rng), 4. * u(rng)}}, 1e-12);
}

void expect_curvilinear(const Cells& c, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0., 1.);
  EXPECT_EQ(c.number_of_points(), 36u);
  EXPECT_EQ(c.number_of_cells(), 2u * 2u * 3u);
  EXPECT_EQ(c.points()[3 * 35 + 0], curvilinear_node(2, 2, 3)[0]);
  for (int s = 0; s < 500; ++s) {
    const int i = int(rng() % 2), j = int(rng() % 2), k = int(rng() % 3);
    const std::array<P3, 8> x = {{curvilinear_node(i, j, k), curvilinear_node(i + 1, j, k),
                                  curvilinear_node(i + 1, j + 1, k), curvilinear_node(i, j + 1, k),
                                  curvilinear_node(i, j, k + 1), curvilinear_node(i + 1, j, k + 1),
                                  curvilinear_node(i + 1, j + 1, k + 1), curvilinear_node(i, j + 1, k + 1)}};
    expect_linear_at(c, hex_point(x, u(rng), u(rng), u(rng)), 1e-9);
  }
}

std::vector<double> as_doubles(const Cells::Point_coordinates& x)
{
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < r.size(); ++i)
    r[i] = x[i];
  return r;
}

void expect_mixed_cells(const Cells& c, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0., 1.);
  EXPECT_EQ(c.number_of_points(), 19u);
  EXPECT_EQ(as_doubles(c.points()), flat(kPoints));
  EXPECT_EQ(c.cell_types(), (std::vector<unsigned char>{12, 14, 13, 10}));
  EXPECT_EQ(c.offsets(), (std::vector<Cells::Index>{0, 8, 13, 19, 23}));
  EXPECT_EQ(c.connectivity(), (std::vector<Cells::Index>{0, 1, 2,  3,  4,  5,  6,  7,  4,  5,  6, 7,
                                                         8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18}));
  std::array<P3, 8> hex;
  for (int q = 0; q < 8; ++q)
    hex[q] = kPoints[q];
  for (int s = 0; s < 200; ++s) {
    expect_linear_at(c, hex_point(hex, u(rng), u(rng), u(rng)), 1e-9);
    for (std::size_t cell = 1; cell < kCells.size(); ++cell) {
      std::vector<P3> x;
      for (int p : kCells[cell])
        x.push_back(kPoints[p]);
      expect_linear_at(c, convex_point(x, rng), 1e-9);
    }
  }
  // Between the cells.
  EXPECT_FALSE(c(Point(1.5, 0.5, 0.5)).has_value());
  EXPECT_FALSE(c(Point(2.5, 0.75, 1.5)).has_value());
}

TEST(ReadVTKLegacyDatasets, RectilinearGridIntoRectilinearAndCells)
{
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0., 1.);
  for (bool binary : {false, true})
    for (const std::string type : {"double", "float"}) {
      const std::string name = std::string("rectilinear_") + (binary ? "binary_" : "ascii_") + type + ".vtk";
      const std::string contents = rectilinear_file(binary, type);
      expect_rectilinear(read_ok<Rectilinear>(name, contents), rng);
      const Cells c = read_ok<Cells>(name, contents);
      EXPECT_EQ(c.number_of_points(), 60u);
      EXPECT_EQ(c.number_of_cells(), 3u * 2u * 4u);
      EXPECT_EQ(as_doubles(c.points()), grid_points(kAxes));
      for (int s = 0; s < 500; ++s)
        expect_linear_at(c, {{3. * u(rng), -1. + 1.25 * u(rng), 4. * u(rng)}}, 1e-9);
    }
}

TEST(ReadVTKLegacyDatasets, StructuredGridIntoCells)
{
  std::mt19937 rng(2);
  for (bool binary : {false, true})
    expect_curvilinear(read_ok<Cells>(binary ? "curvilinear_binary.vtk" : "curvilinear_ascii.vtk",
                                      structured_grid_file(binary)),
                       rng);
}

TEST(ReadVTKLegacyDatasets, UnstructuredGridInBothCellsForms)
{
  std::mt19937 rng(3);
  for (bool binary : {false, true})
    for (bool new_form : {false, true}) {
      SCOPED_TRACE(std::string(binary ? "binary" : "ascii") + (new_form ? " 5.1" : " legacy"));
      const Cells c = read_ok<Cells>("cells.vtk", unstructured_file(binary, new_form));
      EXPECT_NE(c.points().float_data(), nullptr); // POINTS float: kept as float
      expect_mixed_cells(c, rng);
    }
}

TEST(ReadVTKLegacyDatasets, VoxelsAreReadAsTheSameHexahedra)
{
  // The hexahedron written as a VTK_VOXEL (points 0 1 3 2 4 5 7 6) is read as the hexahedron
  // 0 ... 7 of type 12: the same field as from the hexahedron, the linear field exactly.
  std::mt19937 rng(4);
  for (bool binary : {false, true})
    for (bool new_form : {false, true}) {
      SCOPED_TRACE(std::string(binary ? "binary" : "ascii") + (new_form ? " 5.1" : " legacy"));
      const Cells c = read_ok<Cells>(
          "voxel.vtk", unstructured_geometry(binary, new_form, kVoxelTypes).velocity(flat(kPoints)).s);
      expect_mixed_cells(c, rng);
    }
}

TEST(ReadVTKLegacyDatasets, FilesWrittenByVTKItself)
{
  // data/make_vtk_legacy_datasets.cpp wrote them with VTK 9.1's legacy writers, from the same
  // geometry as the hand-written files; VTK adds a FIELD array (pressure) to the point data.
  std::mt19937 rng(5);
  std::string error;
  for (const std::string name : {"vtk_unstructured_5.1_binary.vtk", "vtk_unstructured_5.1_ascii.vtk",
                                 "vtk_unstructured_4.2_binary.vtk", "vtk_unstructured_4.2_ascii.vtk"}) {
    SCOPED_TRACE(name);
    Cells c;
    ASSERT_TRUE(
        FAS::IO::read_VTK_flow_field(FAS_TEST_DATA_DIR "/" + name, c, FAS::parameters::error_message(&error)))
        << error;
    expect_mixed_cells(c, rng);
    // The 1-component FIELD array is seen, and refused as a velocity.
    EXPECT_FALSE(FAS::IO::read_VTK_flow_field(
        FAS_TEST_DATA_DIR "/" + name, c,
        FAS::parameters::error_message(&error, FAS::parameters::array_name("pressure"))));
    EXPECT_NE(error.find("'pressure' has 1 components"), std::string::npos) << error;
  }
  Cells s;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(FAS_TEST_DATA_DIR "/vtk_structured_grid_binary.vtk", s,
                                           FAS::parameters::error_message(&error)))
      << error;
  expect_curvilinear(s, rng);
  Rectilinear r;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(FAS_TEST_DATA_DIR "/vtk_rectilinear_grid_ascii.vtk", r,
                                           FAS::parameters::error_message(&error)))
      << error;
  expect_rectilinear(r, rng);
}

TEST(ReadVTKLegacyDatasets, MetadataAfterGeometryArraysIsSkipped)
{
  // VTK 9 writes METADATA blocks (ended by an empty line) after POINTS and other arrays.
  for (bool binary : {false, true}) {
    std::string s = unstructured_file(binary, true);
    const std::string after = "\nCELLS 5 23";
    s.insert(s.find(after) + 1,
             "METADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 3\n\n");
    const Cells c = read_ok<Cells>("metadata.vtk", s);
    EXPECT_EQ(c.number_of_cells(), 4u);
    expect_linear_at(c, {{2.25, 0.25, 0.25}}, 1e-9);
  }
}

TEST(ReadVTKLegacyDatasets, StructuredPointsIntoAllThreeFieldsAgree)
{
  // The regular grid reader is the peer: the rectilinear field must give the same values, the
  // cells field the same up to its Newton inversion, and all three the same domain under the
  // mask (the 8 cells around the solid node (1, 1, 1) are out).
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0., 1.);
  for (bool binary : {false, true}) {
    const std::string contents = structured_points_file(binary);
    const std::string name = binary ? "points_binary.vtk" : "points_ascii.vtk";
    const Grid g = read_ok<Grid>(name, contents);
    const Rectilinear r = read_ok<Rectilinear>(name, contents);
    const Cells c = read_ok<Cells>(name, contents);
    ASSERT_TRUE(r.has_mask());
    EXPECT_FALSE(r.is_fluid(1, 1, 1));
    EXPECT_EQ(r.coordinates(0), (std::vector<double>{-1, -0.5, 0, 0.5}));
    EXPECT_EQ(c.number_of_cells(), 3u * 2u * 2u - 8u); // the cells not touching (1, 1, 1)
    std::size_t outside = 0;
    for (int s = 0; s < 1000; ++s) {
      const P3 p = {{-1. + 1.5 * u(rng), 0.5 + 0.5 * u(rng), 2. + 2. * u(rng)}};
      const Point q(p[0], p[1], p[2]);
      const std::optional<Vector> a = g(q);
      ASSERT_EQ(a.has_value(), r(q).has_value()) << q;
      ASSERT_EQ(a.has_value(), c(q).has_value()) << q;
      if (!a) {
        ++outside;
        continue;
      }
      expect_linear_at(r, p, 1e-12);
      expect_linear_at(c, p, 1e-9);
    }
    EXPECT_GT(outside, 100u);
  }
}

TEST(ReadVTKLegacyDatasets, MaskRemovesTheCellsTouchingASolidPoint)
{
  // The pyramid's apex (point 8) is solid, with a NaN velocity that must not matter.
  for (bool binary : {false, true}) {
    Vtk_file f = unstructured_geometry(binary, false);
    std::vector<double> v;
    for (const P3& p : kPoints) {
      const P3 w = linear(p);
      v.insert(v.end(), w.begin(), w.end());
    }
    v[3 * 8 + 1] = std::nan("");
    std::vector<double> inside(19, 1.);
    inside[8] = 0.;
    f.line("POINT_DATA 19").line("VECTORS velocity float").values("float", v);
    f.line("SCALARS inside int 1").line("LOOKUP_TABLE default").values("int", inside);
    const Cells c = read_ok<Cells>("masked_cells.vtk", f.s);
    EXPECT_EQ(c.cell_types(), (std::vector<unsigned char>{12, 13, 10}));
    EXPECT_FALSE(c(Point(0.5, 0.5, 1.25)).has_value()); // inside the removed pyramid
    expect_linear_at(c, {{0.5, 0.5, 0.5}}, 1e-9);
    // Without the mask the NaN is at a point of a cell: refused, naming the point.
    const std::string file = temporary("masked_cells.vtk");
    Cells u;
    std::string error;
    EXPECT_FALSE(FAS::IO::read_VTK_flow_field(
        file, u, FAS::parameters::error_message(&error, FAS::parameters::mask_array_name(""))));
    EXPECT_NE(error.find("at point 8, component 1, is nan"), std::string::npos) << error;
    EXPECT_EQ(u.bbox(), CGAL::Bbox_3()); // untouched: empty
  }
}

// ------------------------------------------------------------------------------------------
// Bad input: `false`, a message naming the file, the place and the fault, the field untouched

template <class Field>
Field sentinel();
template <>
Rectilinear sentinel<Rectilinear>()
{
  return Rectilinear({{{7, 8}, {7, 8}, {7, 8}}}, std::vector<float>(24, 3.f));
}
template <>
Cells sentinel<Cells>()
{
  return Cells(std::vector<double>{7, 7, 7, 8, 7, 7, 7, 8, 7, 7, 7, 8}, {0, 1, 2, 3}, {0, 4}, {10},
               std::vector<float>(12, 3.f));
}

void expect_sentinel(const Rectilinear& f)
{
  EXPECT_EQ(f.coordinates(0), (std::vector<double>{7, 8}));
  EXPECT_EQ(f.values(), std::vector<float>(24, 3.f));
}
void expect_sentinel(const Cells& f)
{
  EXPECT_EQ(f.number_of_cells(), 1u);
  EXPECT_EQ(f.vectors(), std::vector<float>(12, 3.f));
}

template <class Field>
void expect_failure(const std::string& name, const std::string& contents,
                    std::initializer_list<std::string> parts)
{
  const std::string file = temporary(name);
  write_bytes(file, contents);
  Field f = sentinel<Field>();
  std::string error;
  EXPECT_FALSE(FAS::IO::read_VTK_flow_field(file, f, FAS::parameters::error_message(&error))) << name;
  EXPECT_NE(error.find(file), std::string::npos) << "the message does not name the file: " << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' is not in the message: " << error;
  expect_sentinel(f);
}

TEST(ReadVTKLegacyDatasetsBadInput, UnsupportedCellTypesNameTheCellAndTheType)
{
  for (bool binary : {false, true})
    for (bool new_form : {false, true}) {
      std::vector<double> types = kTypes;
      types[2] = 42;
      expect_failure<Cells>(
          "type_42.vtk", unstructured_geometry(binary, new_form, types).velocity(flat(kPoints)).s,
          {binary ? "byte " : "line ", "cell 2 has VTK type 42 (VTK_POLYHEDRON)",
           "supported: 10 (VTK_TETRA), 11 (VTK_VOXEL), 12 (VTK_HEXAHEDRON), 13 (VTK_WEDGE), "
           "14 (VTK_PYRAMID)"});
      types[2] = 25;
      expect_failure<Cells>("type_25.vtk",
                            unstructured_geometry(binary, new_form, types).velocity(flat(kPoints)).s,
                            {"cell 2 has VTK type 25 (VTK_QUADRATIC_HEXAHEDRON)"});
    }
}

TEST(ReadVTKLegacyDatasetsBadInput, PointIndexOutOfRangeNamesTheCellAndTheValue)
{
  for (bool binary : {false, true}) {
    Vtk_file f(binary, "UNSTRUCTURED_GRID");
    f.line("POINTS 19 float").values("float", flat(kPoints));
    f.line("CELLS 2 11").values("int", {4, 15, 16, 17, 18, 5, 4, 5, 6, 7, 19});
    f.line("CELL_TYPES 2").values("int", {10, 14});
    expect_failure<Cells>("index_19.vtk", f.velocity(flat(kPoints)).s,
                          {"cell 1 has the point index 19", "expected an index in [0, 19) (POINTS 19)"});
    Vtk_file g(binary, "UNSTRUCTURED_GRID", "5.1");
    g.line("POINTS 19 float").values("float", flat(kPoints));
    g.line("CELLS 3 9").line("OFFSETS vtktypeint64").values("vtktypeint64", {0, 4, 9});
    g.line("CONNECTIVITY vtktypeint64").values("vtktypeint64", {15, 16, 17, 18, 4, 5, -1, 7, 8});
    g.line("CELL_TYPES 2").values("int", {10, 14});
    expect_failure<Cells>("index_negative.vtk", g.velocity(flat(kPoints)).s,
                          {"cell 1 has the point index -1"});
  }
}

TEST(ReadVTKLegacyDatasetsBadInput, CountsThatDoNotMatchGiveBothNumbers)
{
  for (bool binary : {false, true}) {
    Vtk_file f(binary, "UNSTRUCTURED_GRID");
    f.line("POINTS 19 float").values("float", flat(kPoints));
    f.line("CELLS 1 5").values("int", {4, 15, 16, 17, 18}).line("CELL_TYPES 2").values("int", {10, 10});
    expect_failure<Cells>("cell_types_count.vtk", f.s, {"CELL_TYPES 2 does not match the 1 cells of CELLS"});

    // A tetrahedron listed with 5 points.
    Vtk_file g(binary, "UNSTRUCTURED_GRID");
    g.line("POINTS 19 float").values("float", flat(kPoints));
    g.line("CELLS 1 6").values("int", {5, 15, 16, 17, 18, 0}).line("CELL_TYPES 1").values("int", {10});
    expect_failure<Cells>("cell_size.vtk", g.velocity(flat(kPoints)).s,
                          {"cell 0 (VTK_TETRA) lists 5 points; expected 4"});

    // The list is longer, or shorter, than its cells.
    Vtk_file h(binary, "UNSTRUCTURED_GRID");
    h.line("POINTS 19 float").values("float", flat(kPoints));
    h.line("CELLS 1 7").values("int", {4, 15, 16, 17, 18, 0, 1}).line("CELL_TYPES 1").values("int", {10});
    expect_failure<Cells>("cells_extra.vtk", h.velocity(flat(kPoints)).s,
                          {"CELLS 1 7: the 1 cells end after 5 values, not 7"});
    Vtk_file k(binary, "UNSTRUCTURED_GRID");
    k.line("POINTS 19 float").values("float", flat(kPoints));
    k.line("CELLS 2 7").values("int", {4, 15, 16, 17, 18, 4, 1}).line("CELL_TYPES 2").values("int", {10, 10});
    expect_failure<Cells>("cells_short.vtk", k.velocity(flat(kPoints)).s,
                          {"CELLS 2 7: the values end inside cell 1 of 2"});

    // 5.1 form: offsets that do not fit the types or the connectivity.
    Vtk_file m(binary, "UNSTRUCTURED_GRID", "5.1");
    m.line("POINTS 19 float").values("float", flat(kPoints));
    m.line("CELLS 3 9").line("OFFSETS vtktypeint64").values("vtktypeint64", {0, 5, 9});
    m.line("CONNECTIVITY vtktypeint64").values("vtktypeint64", {15, 16, 17, 18, 4, 5, 6, 7, 8});
    m.line("CELL_TYPES 2").values("int", {10, 14});
    expect_failure<Cells>("offsets_type.vtk", m.velocity(flat(kPoints)).s,
                          {"cell 0 (VTK_TETRA) has OFFSETS 0 and 5, so 5 points; expected 4"});
    Vtk_file n(binary, "UNSTRUCTURED_GRID", "5.1");
    n.line("POINTS 19 float").values("float", flat(kPoints));
    n.line("CELLS 2 5").line("OFFSETS vtktypeint64").values("vtktypeint64", {0, 4});
    n.line("CONNECTIVITY vtktypeint64").values("vtktypeint64", {15, 16, 17, 18, 4});
    n.line("CELL_TYPES 1").values("int", {10});
    expect_failure<Cells>("offsets_last.vtk", n.velocity(flat(kPoints)).s,
                          {"the last offset is 4 but CONNECTIVITY has 5 values"});

    // Grids: per-axis coordinates and points against DIMENSIONS.
    Vtk_file r(binary, "RECTILINEAR_GRID");
    r.line("DIMENSIONS 4 3 5").line("X_COORDINATES 3 double").values("double", {0, 1, 2});
    expect_failure<Rectilinear>(
        "x_count.vtk", r.s,
        {"line 6", "X_COORDINATES 3 does not match DIMENSIONS 4 3 5, which has 4 nodes along x"});
    Vtk_file s(binary, "STRUCTURED_GRID");
    s.line("DIMENSIONS 3 3 4").line("POINTS 35 double").values("double", std::vector<double>(105, 0.));
    expect_failure<Cells>("points_count.vtk", s.s,
                          {"line 6", "POINTS 35 does not match DIMENSIONS 3 3 4, which has 36 nodes"});
    // POINT_DATA against POINTS.
    expect_failure<Cells>("point_data_count.vtk",
                          unstructured_geometry(binary, false).line("POINT_DATA 18").s,
                          {"POINT_DATA 18 does not match POINTS 19, which has 19 nodes"});
  }
}

TEST(ReadVTKLegacyDatasetsBadInput, MissingPartsEmptyGridsAndLyingHeaders)
{
  const std::string head = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  expect_failure<Cells>("no_cell_types.vtk",
                        Vtk_file(false, "UNSTRUCTURED_GRID")
                            .line("POINTS 1 float")
                            .values("float", {0, 0, 0})
                            .line("CELLS 0 0")
                            .s,
                        {"has no CELL_TYPES"});
  expect_failure<Cells>(
      "no_cells.vtk",
      Vtk_file(false, "UNSTRUCTURED_GRID").line("POINTS 1 float").values("float", {0, 0, 0}).s,
      {"has no CELLS"});
  expect_failure<Cells>("no_points.vtk", Vtk_file(false, "STRUCTURED_GRID").line("DIMENSIONS 2 2 2").s,
                        {"the STRUCTURED_GRID dataset has no POINTS"});
  expect_failure<Rectilinear>("no_z.vtk",
                              Vtk_file(false, "RECTILINEAR_GRID")
                                  .line("DIMENSIONS 2 2 2")
                                  .line("X_COORDINATES 2 float")
                                  .values("float", {0, 1})
                                  .line("Y_COORDINATES 2 float")
                                  .values("float", {0, 1})
                                  .s,
                              {"has no Z_COORDINATES"});
  expect_failure<Cells>(
      "empty_cells.vtk",
      Vtk_file(false, "UNSTRUCTURED_GRID").line("POINTS 0 float").line("CELLS 0 0").line("CELL_TYPES 0").s,
      {"empty grid: POINTS 0 and 0 cells"});
  expect_failure<Cells>("too_many_cells.vtk",
                        Vtk_file(false, "UNSTRUCTURED_GRID")
                            .line("POINTS 1 float")
                            .values("float", {0, 0, 0})
                            .line("CELLS 5 3")
                            .s,
                        {"CELLS 5 3: 5 cells cannot be listed in 3 values"});
  // Lying counts are refused from the bytes left, before anything is allocated.
  expect_failure<Cells>("lying_points.vtk", head + "POINTS 1000000000000 float\n\x01\x02",
                        {"line 5", "POINTS needs 1000000000000 x 3 values", "bytes are left"});
  expect_failure<Cells>("lying_cells.vtk",
                        head + "POINTS 1 float\n" + std::string(12, '\0') + "\nCELLS 10 4000000000000\n\x01",
                        {"line 7", "CELLS needs 4000000000000 x 1 values", "bytes are left"});
  expect_failure<Cells>("lying_offsets.vtk",
                        "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 float\n" +
                            std::string(12, '\0') + "\nCELLS 99999999999 4\nOFFSETS vtktypeint64\n\x01",
                        {"OFFSETS needs 99999999999 x 1 values", "bytes are left"});
  expect_failure<Rectilinear>(
      "lying_coordinates.vtk",
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 2\n"
      "X_COORDINATES 100000000 float\n0 1\n",
      {"line 6", "X_COORDINATES needs 100000000 x 1 values", "bytes are left"});
  expect_failure<Cells>("keyword.vtk", Vtk_file(false, "UNSTRUCTURED_GRID").line("SPACING 1 1 1").s,
                        {"line 5", "unexpected keyword 'SPACING' in the UNSTRUCTURED_GRID geometry",
                         "expected POINTS, CELLS, CELL_TYPES"});
  expect_failure<Rectilinear>("cells_into_rectilinear.vtk", head,
                              {"line 4",
                               "UNSTRUCTURED_GRID cannot be read into a Rectilinear_grid_flow_field_3",
                               "read by Unstructured_flow_field_3"});
}

TEST(ReadVTKLegacyDatasetsBadInput, BadCoordinatesNameTheAxisOrPoint)
{
  for (bool binary : {false, true}) {
    // Not increasing: the field's message, naming the file.
    Vtk_file f(binary, "RECTILINEAR_GRID");
    f.line("DIMENSIONS 2 3 2").line("X_COORDINATES 2 double").values("double", {0, 1});
    f.line("Y_COORDINATES 3 double").values("double", {0, 2, 1});
    f.line("Z_COORDINATES 2 double").values("double", {0, 1});
    f.velocity(std::vector<double>(36, 0.));
    expect_failure<Rectilinear>("decreasing.vtk", f.s,
                                {"Rectilinear_grid_flow_field_3: coordinates[1][2] (y of node 2) is 1",
                                 "not greater than coordinates[1][1] = 2"});
    // Non-finite: the reader's message, with the place.
    Vtk_file g(binary, "RECTILINEAR_GRID");
    g.line("DIMENSIONS 2 2 2").line("X_COORDINATES 2 double").values("double", {0, std::nan("")});
    g.line("Y_COORDINATES 2 double").values("double", {0, 1});
    g.line("Z_COORDINATES 2 double").values("double", {0, 1});
    g.velocity(std::vector<double>(24, 0.));
    expect_failure<Rectilinear>("nan_coordinate.vtk", g.s, {"X_COORDINATES: value 1 is nan"});
    std::vector<double> points = flat(kPoints);
    points[3 * 5 + 2] = HUGE_VAL;
    Vtk_file h(binary, "UNSTRUCTURED_GRID");
    h.line("POINTS 19 double").values("double", points);
    h.line("CELLS 1 5").values("int", {4, 15, 16, 17, 18}).line("CELL_TYPES 1").values("int", {10});
    expect_failure<Cells>("inf_point.vtk", h.velocity(flat(kPoints)).s,
                          {"POINTS: coordinate 2 of point 5 is inf; expected a finite number"});
  }
}

TEST(ReadVTKLegacyDatasetsBadInput, TheFieldsConstructorErrorsNameTheFile)
{
  // A spacing whose far nodes overflow to infinity passes the reader's checks; the fields'
  // constructors refuse the coordinates, and the reader returns their message with the file.
  Vtk_file f(false, "STRUCTURED_POINTS");
  f.line("DIMENSIONS 3 2 2").line("SPACING 1e308 1 1").velocity(std::vector<double>(36, 0.));
  expect_failure<Cells>(
      "overflowing_points.vtk", f.s,
      {"Unstructured_flow_field_3: points[6] (coordinate 0 of point 2) is inf", "expected a finite number"});
  expect_failure<Rectilinear>("overflowing_coordinates.vtk", f.s,
                              {"Rectilinear_grid_flow_field_3: coordinates[0][2] (x of node 2) is inf"});
}

TEST(ReadVTKLegacyDatasetsBadInput, MaskThatRemovesEveryCell)
{
  Vtk_file f = unstructured_geometry(false, false);
  f.velocity(flat(kPoints)).line("SCALARS inside float").line("LOOKUP_TABLE default");
  std::vector<double> inside(19, 1.);
  inside[4] = inside[10] = inside[15] = 0.;
  expect_failure<Cells>("all_masked.vtk", f.values("float", inside).s,
                        {"every one of the 4 cells touches a solid node of the mask 'inside'"});
}

// ------------------------------------------------------------------------------------------
// The real data of ../shared/data

struct Real_data_set {
  const char* name;
  std::size_t points, cells; // NAME.md, "Files" (and NAME_stats.json, native_mesh)
  double bounds[6];          // NAME_stats.json, native_mesh.bounds (float coordinates)
};

const Real_data_set kCylinder = {
    "CYLINDER", 197505, 185344, {0., 2.5, 0., 0.4099999964237213, 0., 0.4099999964237213}};
const Real_data_set kCavity = {"CAVITY", 185193, 175616, {0., 1., 0., 1., 0., 1.}};

// A file of ../shared/data as read: the field, or the reason it could not be read.
template <class Field>
struct Real_data_read {
  std::optional<Field> field;
  std::string error;
};

// The files read so far, by name: the tests below read each of them up to three times, and a
// read of a cells file is most of the time of a test (2 s under the sanitizers).
template <class Field>
std::map<std::string, Real_data_read<Field>>& real_data_reads()
{
  static std::map<std::string, Real_data_read<Field>> reads;
  return reads;
}

// The suite lets the files go when it ends (tens of MB each), rather than holding them until the
// process exits, for whatever runs after it (and LeakSanitizer's scan at exit).
class ReadVTKLegacyRealData : public ::testing::Test
{
protected:
  static void TearDownTestSuite()
  {
    real_data_reads<Cells>().clear();
    real_data_reads<Grid>().clear();
  }
};

// The `_cells.vtk` or `_grid.vtk` form of a data set, or nothing if it is absent; each file is
// read once per run of the suite.  A file that could not be read fails every test that asks for it.
template <class Field>
const std::optional<Field>& read_real(const Real_data_set& d, const char* form)
{
  auto& reads = real_data_reads<Field>();
  const std::string name = std::string(d.name) + form;
  auto found = reads.find(name);
  if (found == reads.end()) {
    Real_data_read<Field> r;
    const std::string file = shared_data_file(name);
    if (!file.empty()) {
      Field f;
      if (FAS::IO::read_VTK_flow_field(file, f, FAS::parameters::error_message(&r.error)))
        r.field = std::move(f);
      else if (r.error.empty())
        r.error = "reading " + file + " failed without a message";
    }
    found = reads.emplace(name, std::move(r)).first;
  }
  if (!found->second.field && !found->second.error.empty())
    ADD_FAILURE() << found->second.error;
  return found->second.field;
}

const std::optional<Cells>& read_real_cells(const Real_data_set& d)
{
  return read_real<Cells>(d, "_cells.vtk");
}
const std::optional<Grid>& read_real_grid(const Real_data_set& d)
{
  return read_real<Grid>(d, "_grid.vtk");
}

#define FAS_SKIP_WITHOUT(field, what)                                                                        \
  if (!(field))                                                                                              \
  GTEST_SKIP() << what << " not found in FAS_SHARED_DATA_DIR (../shared/data)"

void expect_stated_counts(const Real_data_set& d, const Cells& c)
{
  EXPECT_EQ(c.number_of_points(), d.points) << d.name;
  EXPECT_EQ(c.number_of_cells(), d.cells) << d.name;
  EXPECT_TRUE(
      std::all_of(c.cell_types().begin(), c.cell_types().end(), [](unsigned char t) { return t == 12; }))
      << d.name << ": all VTK_HEXAHEDRON";
  const CGAL::Bbox_3 b = c.bbox();
  EXPECT_EQ(b, CGAL::Bbox_3(d.bounds[0], d.bounds[2], d.bounds[4], d.bounds[1], d.bounds[3], d.bounds[5]))
      << d.name;
}

TEST_F(ReadVTKLegacyRealData, CylinderCellsHaveTheStatedCounts)
{
  const std::optional<Cells>& c = read_real_cells(kCylinder);
  FAS_SKIP_WITHOUT(c, "CYLINDER_cells.vtk");
  expect_stated_counts(kCylinder, *c);
  // CYLINDER.md: point_velocity_max_mag 0.5112851129877584 (over the points).
  double max_speed = 0;
  for (std::size_t p = 0; p < c->vectors().size(); p += 3)
    max_speed = std::max(max_speed, std::sqrt(double(c->vectors()[p]) * c->vectors()[p] +
                                              double(c->vectors()[p + 1]) * c->vectors()[p + 1] +
                                              double(c->vectors()[p + 2]) * c->vectors()[p + 2]));
  EXPECT_NEAR(max_speed, 0.5112851129877584, 1e-7);
  // The cylinder (x-0.5)^2 + (y-0.2)^2 < 0.05^2 has no cells.
  EXPECT_FALSE((*c)(Point(0.5, 0.2, 0.2)).has_value());
  EXPECT_TRUE((*c)(Point(1.5, 0.2, 0.2)).has_value());
}

TEST_F(ReadVTKLegacyRealData, CavityCellsHaveTheStatedCounts)
{
  const std::optional<Cells>& c = read_real_cells(kCavity);
  FAS_SKIP_WITHOUT(c, "CAVITY_cells.vtk");
  expect_stated_counts(kCavity, *c);
}

// The grid forms are vtkProbeFilter's trilinear interpolation, in the native hexahedra, of the
// same point values, at grid nodes clipped to the mesh bounds (NAME.md, "Resampled grid"),
// stored as float.  So at the grid nodes (clipped the same way) the cells field must give the
// grid values up to the grid's float rounding: half an ulp of |v| <= 1 is 6e-8 per component,
// 1e-7 for |dv|; the tolerance 2e-7 leaves as much again for the two Newton inversions (ours
// and VTK's), and the mean must stay below 5e-8 (the rounding of values mostly below 0.5).
// Every fluid grid node must be inside a cell (the mask is where vtkProbeFilter found none).
struct Agreement {
  std::size_t compared = 0, cells_undefined = 0;
  double max_difference = 0, mean_difference = 0;
};

// Every grid node; under the sanitizers (FAS_TEST_SANITIZED, at -O0), where locating the nodes in
// the cells is three quarters of these tests' time, every 5th node in storage order (spread over
// the whole grid).
#ifdef FAS_TEST_SANITIZED
constexpr std::size_t node_stride = 5;
#else
constexpr std::size_t node_stride = 1;
#endif

Agreement compare_at_grid_nodes(const Grid& g, const Cells& c)
{
  Agreement r;
  const CGAL::Bbox_3 b = c.bbox();
  const auto& n = g.dimensions();
  double sum = 0;
  std::size_t node = 0;
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        if (node++ % node_stride != 0 || !g.is_fluid(i, j, k))
          continue;
        const Point p = g.node_point(i, j, k);
        const Point clipped(std::min(std::max(p.x(), b.xmin()), b.xmax()),
                            std::min(std::max(p.y(), b.ymin()), b.ymax()),
                            std::min(std::max(p.z(), b.zmin()), b.zmax()));
        const std::optional<Vector> v = c(clipped);
        if (!v) {
          ++r.cells_undefined;
          continue;
        }
        const double d = std::sqrt((*v - g.node_value(i, j, k)).squared_length());
        ++r.compared;
        sum += d;
        r.max_difference = std::max(r.max_difference, d);
      }
  r.mean_difference = sum / double(r.compared);
  return r;
}

void expect_forms_agree(const Real_data_set& d, double max_tolerance, double mean_tolerance)
{
  const std::optional<Grid>& g = read_real_grid(d);
  const std::optional<Cells>& c = read_real_cells(d);
  if (!g || !c)
    return;
  const Agreement a = compare_at_grid_nodes(*g, *c);
  std::ostringstream summary;
  summary << "compared " << a.compared << ", cells undefined at " << a.cells_undefined << ", max |dv| "
          << a.max_difference << ", mean |dv| " << a.mean_difference;
  ::testing::Test::RecordProperty(std::string(d.name) + "_cells_vs_grid", summary.str());
  EXPECT_LE(a.max_difference, max_tolerance) << d.name;
  EXPECT_LE(a.mean_difference, mean_tolerance) << d.name;
  EXPECT_EQ(a.cells_undefined, 0u) << d.name;
}

TEST_F(ReadVTKLegacyRealData, CylinderCellsAndGridAgreeAtTheGridNodes)
{
  FAS_SKIP_WITHOUT(!shared_data_file("CYLINDER_grid.vtk").empty() &&
                       !shared_data_file("CYLINDER_cells.vtk").empty(),
                   "CYLINDER_grid.vtk or CYLINDER_cells.vtk");
  expect_forms_agree(kCylinder, 2e-7, 5e-8);
}

TEST_F(ReadVTKLegacyRealData, CavityCellsAndGridAgreeAtTheGridNodes)
{
  FAS_SKIP_WITHOUT(!shared_data_file("CAVITY_grid.vtk").empty() &&
                       !shared_data_file("CAVITY_cells.vtk").empty(),
                   "CAVITY_grid.vtk or CAVITY_cells.vtk");
  expect_forms_agree(kCavity, 2e-7, 5e-8);
}

// The patch of the grid test of test_read_VTK_legacy.cpp, in the cylinder's near wake.
TEST_F(ReadVTKLegacyRealData, PatchesInTheCylinderCellsAlign)
{
  const std::optional<Cells>& c = read_real_cells(kCylinder);
  FAS_SKIP_WITHOUT(c, "CYLINDER_cells.vtk");
  expect_patches_align(*c, "CYLINDER_cells", Point(0.8, 0.2, 0.2), Vector(0.4, 0.2, 1), Vector(1, 0.8, 0.5),
                       0.15);
}

// In the cavity, below the primary vortex's centre, more than 0.2 from every wall.
const Point kCavityCenter(0.5, 0.3, 0.35);

TEST_F(ReadVTKLegacyRealData, PatchesInTheCavityGridAlign)
{
  const std::optional<Grid>& g = read_real_grid(kCavity);
  FAS_SKIP_WITHOUT(g, "CAVITY_grid.vtk");
  expect_patches_align(*g, "CAVITY_grid", kCavityCenter, Vector(1, 0.6, 0.5), Vector(0.3, 1, 0.4), 0.15);
}

TEST_F(ReadVTKLegacyRealData, PatchesInTheCavityCellsAlign)
{
  const std::optional<Cells>& c = read_real_cells(kCavity);
  FAS_SKIP_WITHOUT(c, "CAVITY_cells.vtk");
  expect_patches_align(*c, "CAVITY_cells", kCavityCenter, Vector(1, 0.6, 0.5), Vector(0.3, 1, 0.4), 0.15);
}

} // namespace

namespace {

TEST(ReadVTKLegacyDatasetsBadInput, EveryTruncationAndRandomCorruptionFailsCleanly)
{
  // No crash, no hang, and either success or a message naming the file, for every prefix and
  // for random byte changes of each kind of file (the sanitizer build checks the memory).
  std::mt19937 rng(77);
  std::vector<std::pair<std::string, std::string>> files;
  for (bool binary : {false, true}) {
    files.emplace_back("UNSTRUCTURED_GRID legacy", unstructured_file(binary, false));
    files.emplace_back("UNSTRUCTURED_GRID 5.1", unstructured_file(binary, true));
    files.emplace_back("STRUCTURED_GRID", structured_grid_file(binary));
    files.emplace_back("RECTILINEAR_GRID", rectilinear_file(binary, "float"));
  }
  const std::string file = temporary("to_mangle.vtk");
  for (const auto& [kind, whole] : files) {
    SCOPED_TRACE(kind);
    auto read = [&](const std::string& contents) {
      write_bytes(file, contents);
      Cells c;
      Rectilinear r;
      std::string error;
      if (!FAS::IO::read_VTK_flow_field(file, c, FAS::parameters::error_message(&error))) {
        EXPECT_NE(error.find(file), std::string::npos) << error;
        EXPECT_EQ(c.bbox(), CGAL::Bbox_3()); // untouched: empty
      }
      if (!FAS::IO::read_VTK_flow_field(file, r, FAS::parameters::error_message(&error))) {
        EXPECT_EQ(r.bbox(), CGAL::Bbox_3()); // untouched: empty
      }
    };
    for (std::size_t n = 0; n < whole.size(); n += 7)
      read(whole.substr(0, n));
    for (int trial = 0; trial < 200; ++trial) {
      std::string mangled = whole;
      for (int c = 0; c < 3; ++c)
        mangled[rng() % mangled.size()] = static_cast<char>(rng() % 256);
      read(mangled);
    }
  }
}

} // namespace

} // namespace test_read_VTK_legacy_datasets
