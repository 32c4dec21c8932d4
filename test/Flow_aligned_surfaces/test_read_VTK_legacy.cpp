// The legacy VTK reader and writer of grid flow fields: write -> read round trips (ASCII and
// binary) give back the same values, mask and geometry; hand-written files with arrays to skip
// give the values written in them; the real CFD data of ../shared/data give the numbers that
// their .md/.json files state, and a patch placed in the cylinder's wake aligns; and every kind
// of bad input gives `false` with a message naming the file, the place and the fault, leaving
// the field untouched.

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

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
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_VTK_legacy {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Grid = CGAL::Flow_aligned_surfaces::Regular_grid_flow_field_3<K>;
namespace FAS = CGAL::Flow_aligned_surfaces;

std::string temporary(const std::string& name)
{
  return temporary_file("fas_read_VTK_legacy_", name);
}

// A 4 x 3 x 5 grid with irregular values, a non-trivial origin and spacing, and two solid nodes.
Grid sample_grid(bool with_mask)
{
  const Grid::Dimensions n = {{4, 3, 5}};
  std::vector<float> values(3 * 60);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = static_cast<float>(std::sin(0.37 * double(i)) * std::pow(10., double(i % 7) - 3.));
  std::vector<unsigned char> mask;
  if (with_mask) {
    mask.assign(60, 1);
    mask[7] = mask[33] = 0;
  }
  return Grid(Point(0.1, -2.5, 1e-3), Vector(0.1, 1. / 3., 0.7), n, std::move(values), std::move(mask));
}

// A grid unlike the ones read, to detect that a failed read changed nothing.
Grid sentinel_grid()
{
  return Grid(Point(7, 7, 7), Vector(1, 1, 1), Grid::Dimensions{{2, 2, 2}}, std::vector<float>(24, 3.f));
}

void expect_same_grid(const Grid& a, const Grid& b)
{
  EXPECT_EQ(a.dimensions(), b.dimensions());
  EXPECT_EQ(a.origin(), b.origin()); // bitwise: the writer prints 17 digits
  EXPECT_EQ(a.spacing(), b.spacing());
  EXPECT_EQ(a.values(), b.values()); // bitwise: float -> 9 digits or raw bytes -> float
  EXPECT_EQ(a.mask(), b.mask());
  EXPECT_EQ(a.has_mask(), b.has_mask());
}

void expect_untouched(const Grid& g)
{
  expect_same_grid(g, sentinel_grid());
}

// Reads `contents` (written to a file) and expects failure with every one of `parts` in the
// message, and the field untouched.
template <class NamedParameters = FAS::parameters::Default_named_parameters>
void expect_failure(const std::string& name, const std::string& contents,
                    std::initializer_list<std::string> parts,
                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string file = temporary(name);
  write_bytes(file, contents);
  Grid g = sentinel_grid();
  std::string error;
  EXPECT_FALSE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error, np))) << name;
  EXPECT_NE(error.find(file), std::string::npos) << "the message does not name the file: " << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' is not in the message: " << error;
  expect_untouched(g);
}

// The header of a 3 x 3 x 3 ASCII grid, up to and including POINT_DATA (8 lines).
const std::string ascii_header = "# vtk DataFile Version 3.0\n"
                                 "test\n"
                                 "ASCII\n"
                                 "DATASET STRUCTURED_POINTS\n"
                                 "DIMENSIONS 3 3 3\n"
                                 "ORIGIN 0 0 0\n"
                                 "SPACING 1 1 1\n"
                                 "POINT_DATA 27\n";

std::string ascii_values(std::size_t count, const std::string& value = "1")
{
  std::string s;
  for (std::size_t i = 0; i < count; ++i)
    s += value + (i + 1 == count ? "\n" : " ");
  return s;
}

void append_big_endian(std::string& s, double v)
{
  std::uint64_t u;
  std::memcpy(&u, &v, 8);
  for (int b = 7; b >= 0; --b)
    s += static_cast<char>((u >> (8 * b)) & 0xff);
}

// ------------------------------------------------------------------------------------------
// Round trips

TEST(ReadVTKLegacy, BinaryRoundTripKeepsValuesMaskAndGeometry)
{
  for (bool with_mask : {true, false}) {
    const Grid original = sample_grid(with_mask);
    const std::string file = temporary("round_trip.vtk");
    std::string error;
    ASSERT_TRUE(FAS::IO::write_VTK_flow_field(file, original, FAS::parameters::error_message(&error)))
        << error;
    EXPECT_NE(read_bytes(file).find("BINARY\n"), std::string::npos);
    Grid g = sentinel_grid();
    ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
    expect_same_grid(g, original);
    EXPECT_EQ(g.has_mask(), with_mask);
  }
}

TEST(ReadVTKLegacy, AsciiRoundTripKeepsValuesMaskAndGeometry)
{
  const Grid original = sample_grid(true);
  const std::string file = temporary("round_trip_ascii.vtk");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTK_flow_field(
      file, original, FAS::parameters::error_message(&error, CGAL::parameters::use_binary_mode(false))))
      << error;
  const std::string text = read_bytes(file);
  EXPECT_NE(text.find("ASCII\n"), std::string::npos);
  EXPECT_NE(text.find("VECTORS velocity float\n"), std::string::npos);
  EXPECT_NE(text.find("SCALARS inside unsigned_char 1\nLOOKUP_TABLE default\n"), std::string::npos);
  Grid g;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  expect_same_grid(g, original);
}

TEST(ReadVTKLegacy, WriterUsesTheGivenArrayNamesAndTheReaderFindsThem)
{
  const Grid original = sample_grid(true);
  const std::string file = temporary("names.vtk");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTK_flow_field(
      file, original,
      FAS::parameters::error_message(
          &error, FAS::parameters::array_name("U", FAS::parameters::mask_array_name("fluid")))))
      << error;
  Grid g = sentinel_grid();
  // Without the mask's name the reader looks for "inside" and finds no mask.
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  EXPECT_FALSE(g.has_mask());
  EXPECT_EQ(g.values(), original.values());
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(
      file, g,
      FAS::parameters::error_message(
          &error, FAS::parameters::array_name("U", FAS::parameters::mask_array_name("fluid")))))
      << error;
  expect_same_grid(g, original);
  // A name legacy VTK cannot store is refused, and the existing file is kept.
  EXPECT_FALSE(FAS::IO::write_VTK_flow_field(
      file, original, FAS::parameters::error_message(&error, FAS::parameters::array_name("my velocity"))));
  EXPECT_NE(error.find("white space"), std::string::npos) << error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(
      file, g,
      FAS::parameters::error_message(
          &error, FAS::parameters::array_name("U", FAS::parameters::mask_array_name("fluid")))));
}

// ------------------------------------------------------------------------------------------
// Files with more than the reader needs

TEST(ReadVTKLegacy, AsciiFileSkipsFieldDataLookupTablesNormalsAndCellData)
{
  const std::string file = FAS_TEST_DATA_DIR "/grid_3x3x3_mixed_arrays.vtk";
  Grid g = sentinel_grid();
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  EXPECT_EQ(g.dimensions(), (Grid::Dimensions{{3, 3, 3}}));
  EXPECT_EQ(g.origin(), Point(1, -2, 0.5));
  EXPECT_EQ(g.spacing(), Vector(0.5, 0.25, 2)); // from ASPECT_RATIO
  // The first VECTORS array: velocity(i, j, k) = (i, j, k), NORMALS is not a velocity.
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(g.node_value(i, j, k), Vector(double(i), double(j), double(k)));
  // "inside" is the mask by default: only the last node is solid.
  ASSERT_TRUE(g.has_mask());
  EXPECT_FALSE(g.is_fluid(2, 2, 2));
  EXPECT_TRUE(g.is_fluid(1, 1, 1));

  // A 3-component FIELD array by name, an int FIELD array as the mask.
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(
      file, g,
      FAS::parameters::error_message(
          &error, FAS::parameters::array_name("shifted", FAS::parameters::mask_array_name("solid")))))
      << error;
  EXPECT_EQ(g.node_value(0, 2, 1), Vector(1, 2, 1));
  EXPECT_FALSE(g.is_fluid(1, 1, 1));
  EXPECT_TRUE(g.is_fluid(2, 2, 2));

  // The empty mask name reads no mask.
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(
      file, g, FAS::parameters::error_message(&error, FAS::parameters::mask_array_name(""))))
      << error;
  EXPECT_FALSE(g.has_mask());
}

TEST(ReadVTKLegacy, BinaryFileWithDoubleVectorsCellDataAndAnIntMask)
{
  std::string s = "# vtk DataFile Version 3.0\nbinary\nBINARY\nDATASET STRUCTURED_POINTS\n"
                  "DIMENSIONS 2 2 2\nSPACING 0.5 0.5 0.5\nCELL_DATA 1\nSCALARS p double 1\n"
                  "LOOKUP_TABLE default\n";
  append_big_endian(s, 42.);
  s += "\nPOINT_DATA 8\nSCALARS t float 3\nLOOKUP_TABLE default\n" + std::string(8 * 3 * 4, '\xff');
  s += "\nVECTORS velocity double\n";
  for (int v = 0; v < 8; ++v)
    for (int d = 0; d < 3; ++d)
      append_big_endian(s, v + 0.25 * d);
  s += "\nSCALARS inside int\nLOOKUP_TABLE default\n";
  for (int v = 0; v < 8; ++v)
    s += std::string("\0\0\0", 3) + char(v == 3 ? 0 : 2);
  s += "\n";
  const std::string file = temporary("binary_double.vtk");
  write_bytes(file, s);
  Grid g = sentinel_grid();
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  EXPECT_EQ(g.origin(), Point(0, 0, 0)); // VTK's default origin
  EXPECT_EQ(g.spacing(), Vector(0.5, 0.5, 0.5));
  EXPECT_EQ(g.node_value(1, 0, 1), Vector(5, 5.25, 5.5));
  EXPECT_FALSE(g.is_fluid(1, 1, 0));
  EXPECT_TRUE(g.is_fluid(1, 0, 1));
  // The 3-component SCALARS "t" holds NaN bytes (0xff...): chosen by name, it is refused.
  EXPECT_FALSE(FAS::IO::read_VTK_flow_field(
      file, g, FAS::parameters::error_message(&error, FAS::parameters::array_name("t"))));
  EXPECT_NE(error.find("node 0 = (0, 0, 0)"), std::string::npos) << error;
}

// ------------------------------------------------------------------------------------------
// The real data of ../shared/data

std::string shared_file(const std::string& name)
{
  return shared_data_file(name);
}

struct Grid_statistics {
  std::size_t fluid = 0;
  double max_speed = 0, mean_speed = 0;
  std::array<std::size_t, 3> argmax = {{0, 0, 0}};
  double min_component[3] = {1e30, 1e30, 1e30}, max_component[3] = {-1e30, -1e30, -1e30};
};

Grid_statistics statistics(const Grid& g)
{
  Grid_statistics s;
  double sum = 0;
  const auto& n = g.dimensions();
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        if (!g.is_fluid(i, j, k))
          continue;
        const Vector v = g.node_value(i, j, k);
        const double speed = std::sqrt(v.squared_length());
        ++s.fluid;
        sum += speed;
        if (speed > s.max_speed) {
          s.max_speed = speed;
          s.argmax = {{i, j, k}};
        }
        for (int d = 0; d < 3; ++d) {
          s.min_component[d] = std::min(s.min_component[d], v[d]);
          s.max_component[d] = std::max(s.max_component[d], v[d]);
        }
      }
  s.mean_speed = sum / double(s.fluid);
  return s;
}

TEST(ReadVTKLegacy, CylinderGridHasTheStatedGeometryMaskAndVelocities)
{
  const std::string file = shared_file("CYLINDER_grid.vtk");
  if (file.empty())
    GTEST_SKIP() << "CYLINDER_grid.vtk not found in FAS_SHARED_DATA_DIR (../shared/data)";
  Grid g = sentinel_grid();
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  // CYLINDER.md / CYLINDER_stats.json
  EXPECT_EQ(g.dimensions(), (Grid::Dimensions{{251, 42, 42}}));
  EXPECT_EQ(g.number_of_nodes(), 442764u);
  EXPECT_EQ(g.origin(), Point(0, 0, 0));
  EXPECT_EQ(g.spacing(), Vector(0.01, 0.01, 0.01));
  ASSERT_TRUE(g.has_mask());
  const Grid_statistics s = statistics(g);
  EXPECT_EQ(s.fluid, 439782u);                                     // n_inside
  EXPECT_NEAR(s.max_speed, 0.5093556873570264, 1e-6);              // max_|v|
  EXPECT_EQ(s.argmax, (std::array<std::size_t, 3>{{50, 29, 21}})); // at (0.5, 0.29, 0.21)
  EXPECT_NEAR(s.mean_speed, 0.1917532775246725, 1e-6);             // mean_|v|_fluid
  EXPECT_NEAR(s.min_component[0], -0.01661495678126812, 1e-7);     // range_vx
  EXPECT_NEAR(s.max_component[0], 0.49925610423088074, 1e-7);
  EXPECT_NEAR(s.min_component[1], -0.24168924987316132, 1e-7); // range_vy
  EXPECT_NEAR(s.max_component[2], 0.1154070571064949, 1e-7);   // range_vz
  // Inlet maximum of the profile 16 Um y z (H-y)(H-z)/H^4 at face centres: 0.449.
  double inlet_max = 0;
  for (std::size_t k = 0; k < 42; ++k)
    for (std::size_t j = 0; j < 42; ++j)
      inlet_max = std::max(inlet_max, g.node_value(0, j, k).x());
  // The grid samples OpenFOAM's point-interpolated values, 0.4472 where the profile gives 0.4495.
  EXPECT_NEAR(inlet_max, 0.449, 0.003);
  // The cylinder (x-0.5)^2 + (y-0.2)^2 < 0.05^2 is solid: its centre line is outside the field.
  EXPECT_FALSE(g.is_fluid(50, 20, 10));
  EXPECT_FALSE(g(Point(0.5, 0.2, 0.2)).has_value());
  EXPECT_TRUE(g(Point(1.5, 0.2, 0.2)).has_value());
}

TEST(ReadVTKLegacy, CavityGridHasTheStatedGeometryAndVelocities)
{
  const std::string file = shared_file("CAVITY_grid.vtk");
  if (file.empty())
    GTEST_SKIP() << "CAVITY_grid.vtk not found in FAS_SHARED_DATA_DIR (../shared/data)";
  Grid g = sentinel_grid();
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  // CAVITY_stats.json
  EXPECT_EQ(g.dimensions(), (Grid::Dimensions{{65, 65, 65}}));
  EXPECT_EQ(g.number_of_nodes(), 274625u);
  EXPECT_EQ(g.spacing(), Vector(0.015625, 0.015625, 0.015625));
  const Grid_statistics s = statistics(g);
  EXPECT_EQ(s.fluid, 274625u); // n_outside = 0
  EXPECT_NEAR(s.max_speed, 1.0, 1e-6);
  EXPECT_NEAR(s.mean_speed, 0.15733031237598188, 1e-6);
  EXPECT_NEAR(s.min_component[0], -0.2744749188423157, 1e-7);
  EXPECT_NEAR(s.min_component[1], -0.6386241912841797, 1e-7);
  EXPECT_NEAR(s.max_component[1], 0.2471572905778885, 1e-7);
  // Lid (y = 1) points inside the lid move at (1, 0, 0).
  EXPECT_EQ(g.node_value(32, 64, 32), Vector(1, 0, 0));
}

TEST(ReadVTKLegacy, PatchesInTheCylinderWakeAlignToTheFlow)
{
  const std::string file = shared_file("CYLINDER_grid.vtk");
  if (file.empty())
    GTEST_SKIP() << "CYLINDER_grid.vtk not found in FAS_SHARED_DATA_DIR (../shared/data)";
  Grid g = sentinel_grid();
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  // In the near wake (3 diameters behind the cylinder's axis, where the (v, w) secondary flow
  // is strong), more than 0.1 away from every wall and 0.15 from the cylinder.
  expect_patches_align(g, "CYLINDER_grid", Point(0.8, 0.2, 0.2), Vector(0.4, 0.2, 1), Vector(1, 0.8, 0.5),
                       0.15);
}

// ------------------------------------------------------------------------------------------
// Bad input

TEST(ReadVTKLegacyBadInput, MissingFileAndNotVTK)
{
  Grid g = sentinel_grid();
  std::string error;
  const std::string missing = temporary("does_not_exist.vtk");
  EXPECT_FALSE(FAS::IO::read_VTK_flow_field(missing, g, FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find(missing), std::string::npos) << error;
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
  expect_untouched(g);
  EXPECT_FALSE(FAS::IO::read_VTK_flow_field(missing, g)); // no message wanted: no crash either
  expect_failure("not_vtk.vtk", "solid cube\n facet normal 0 0 1\n", {"line 1", "not a legacy VTK file"});
  expect_failure("empty.vtk", "", {"the file is empty"});
  expect_failure("format.vtk", "# vtk DataFile Version 3.0\nt\nXML\n",
                 {"line 3", "unknown file format 'XML'"});
}

TEST(ReadVTKLegacyBadInput, UnknownAndUnsupportedDatasetTypes)
{
  expect_failure("dataset_foo.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET FOO\n",
                 {"line 4", "unknown dataset type 'FOO'"});
  // The other dataset types are read into other fields, which the message names.
  expect_failure("dataset_RECTILINEAR_GRID.vtk",
                 "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET RECTILINEAR_GRID\n",
                 {"line 4", "RECTILINEAR_GRID cannot be read into a Regular_grid_flow_field_3",
                  "Rectilinear_grid_flow_field_3 and Unstructured_flow_field_3"});
  for (const std::string type : {"UNSTRUCTURED_GRID", "STRUCTURED_GRID"})
    expect_failure("dataset_" + type + ".vtk",
                   "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET " + type + "\n",
                   {"line 4", type + " cannot be read into a Regular_grid_flow_field_3",
                    "it is read by Unstructured_flow_field_3"});
  expect_failure("dataset_POLYDATA.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n",
                 {"line 4", "POLYDATA has no volume cells"});
  const std::string cells = shared_file("CYLINDER_cells.vtk");
  if (!cells.empty()) {
    Grid g = sentinel_grid();
    std::string error;
    EXPECT_FALSE(FAS::IO::read_VTK_flow_field(cells, g, FAS::parameters::error_message(&error)));
    EXPECT_NE(error.find("it is read by Unstructured_flow_field_3"), std::string::npos) << error;
    expect_untouched(g);
  }
}

TEST(ReadVTKLegacyBadInput, WrongCountsAndEmptyGrids)
{
  expect_failure("point_data_count.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 3 3\n"
                 "POINT_DATA 26\nVECTORS v float\n" +
                     ascii_values(78),
                 {"line 6", "POINT_DATA 26 does not match DIMENSIONS 3 3 3, which has 27 nodes"});
  expect_failure("cell_data_count.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 3 3\n"
                 "CELL_DATA 27\n",
                 {"line 6", "CELL_DATA 27", "which has 8 cells"});
  expect_failure("empty_grid.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 0 0 0\n"
                 "POINT_DATA 0\n",
                 {"empty grid", "DIMENSIONS 0 0 0"});
  expect_failure("flat_grid.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 3 1\n"
                 "POINT_DATA 9\n",
                 {"DIMENSIONS 3 3 1", "at least 2 nodes along each axis"});
  expect_failure(
      "no_dimensions.vtk",
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nORIGIN 0 0 0\nPOINT_DATA 9\n",
      {"no DIMENSIONS"});
  expect_failure("zero_spacing.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n"
                 "DIMENSIONS 2 2 2\nSPACING 1 0 1\nPOINT_DATA 8\n",
                 {"SPACING component 1", "positive"});
}

TEST(ReadVTKLegacyBadInput, LyingHeadersAreCaughtBeforeAllocating)
{
  // 1e12 nodes announced, a few bytes present: refused from the count, not from a failed
  // allocation (which would take minutes or be killed on a machine with overcommit).
  expect_failure(
      "lying_binary.vtk",
      "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 10000 10000 10000\n"
      "POINT_DATA 1000000000000\nVECTORS velocity float\n\x01\x02\x03\x04",
      {"line 7", "VECTORS 'velocity'", "bytes are left", "truncated file or wrong count"});
  expect_failure(
      "lying_ascii.vtk",
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 10000 10000 10000\n"
      "POINT_DATA 1000000000000\nVECTORS velocity float\n1 2 3\n",
      {"line 7", "bytes are left"});
  expect_failure("overflow.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n"
                 "DIMENSIONS 18446744073709551615 18446744073709551615 2\nPOINT_DATA 1\n",
                 {"too many nodes"});
  expect_failure("lying_lookup_table.vtk", ascii_header + "LOOKUP_TABLE t 99999999999\n0 0 0 1\n",
                 {"line 9", "LOOKUP_TABLE 't'", "bytes are left"});
}

TEST(ReadVTKLegacyBadInput, TruncatedFiles)
{
  for (bool binary : {true, false}) {
    const std::string file = temporary("to_truncate.vtk");
    ASSERT_TRUE(
        FAS::IO::write_VTK_flow_field(file, sample_grid(true), CGAL::parameters::use_binary_mode(binary)));
    const std::string whole = read_bytes(file);
    // Cut in the middle of the velocity values.
    const std::size_t cut = whole.find("VECTORS") + 200;
    expect_failure(binary ? "truncated.vtk" : "truncated_ascii.vtk", whole.substr(0, cut),
                   {"VECTORS 'velocity'", "line 9", "bytes are left", "truncated file or wrong count"});
    // Cut in the mask.
    const std::size_t cut_mask = whole.find("LOOKUP_TABLE default") + 30;
    expect_failure(binary ? "truncated_mask.vtk" : "truncated_mask_ascii.vtk", whole.substr(0, cut_mask),
                   {"SCALARS 'inside'", binary ? "line 12" : "line 71", "bytes are left"});
    // Cut in the header.
    expect_failure("truncated_header.vtk", whole.substr(0, whole.find("ORIGIN") + 9),
                   {"line 6", "the file ends where a number of ORIGIN was expected (truncated file?)"});
  }
}

TEST(ReadVTKLegacyBadInput, EveryTruncationAndRandomCorruptionFailsCleanly)
{
  // No crash, no hang, and either success or a message, for every prefix of a small file and
  // for random byte changes (a poor man's fuzzer; the libFuzzer target goes further).
  std::mt19937 random(12345);
  for (bool binary : {true, false}) {
    const std::string file = temporary("to_mangle.vtk");
    const Grid original = sample_grid(true);
    ASSERT_TRUE(FAS::IO::write_VTK_flow_field(file, original, CGAL::parameters::use_binary_mode(binary)));
    const std::string whole = read_bytes(file);
    std::size_t successes = 0;
    for (std::size_t n = 0; n < whole.size(); n += 3) {
      write_bytes(file, whole.substr(0, n));
      Grid g = sentinel_grid();
      std::string error;
      if (FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) {
        // Only a cut between the velocity and the mask, or after the mask, makes a valid file.
        ++successes;
        // A cut inside the last ASCII number leaves a shorter number, which nothing can detect.
        ASSERT_EQ(g.values().size(), original.values().size());
        const std::size_t last = original.values().size() - 1;
        EXPECT_TRUE(std::equal(g.values().begin(), g.values().begin() + last, original.values().begin()))
            << "prefix of " << n << " bytes";
        if (binary) {
          EXPECT_EQ(g.values()[last], original.values()[last]) << "prefix of " << n << " bytes";
        }
        EXPECT_TRUE(g.mask().empty() || g.mask() == original.mask()) << "prefix of " << n << " bytes";
      }
      else {
        EXPECT_NE(error.find(file), std::string::npos) << error;
        expect_untouched(g);
      }
    }
    EXPECT_LE(successes, 4u);
    for (int trial = 0; trial < 300; ++trial) {
      std::string mangled = whole;
      for (int c = 0; c < 3; ++c)
        mangled[random() % mangled.size()] = static_cast<char>(random() % 256);
      write_bytes(file, mangled);
      Grid g = sentinel_grid();
      std::string error;
      if (!FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) {
        EXPECT_FALSE(error.empty());
      }
    }
  }
}

TEST(ReadVTKLegacyBadInput, NonNumericTokens)
{
  expect_failure("word_in_values.vtk",
                 ascii_header + "VECTORS velocity float\n" + ascii_values(10) + "1 abc 1\n" +
                     ascii_values(68),
                 {"line 11", "'abc' is not a number", "VECTORS 'velocity'"});
  expect_failure("word_in_dimensions.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 x 3\n",
                 {"line 5", "'x' is not a non-negative integer"});
  expect_failure(
      "word_in_origin.vtk",
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 3 3\nORIGIN 0 zero 0\n",
      {"line 6", "'zero' is not a finite number (ORIGIN)"});
  expect_failure("unknown_type.vtk", ascii_header + "VECTORS velocity quaternion\n",
                 {"line 9", "unknown data type 'quaternion'"});
  expect_failure("unknown_keyword.vtk",
                 ascii_header + "VECTORS velocity float\n" + ascii_values(81) + "COLOURS x\n",
                 {"line 11", "unknown keyword 'COLOURS'"});
}

TEST(ReadVTKLegacyBadInput, MissingArraysNameTheArraysPresent)
{
  const std::string file_contents = ascii_header + "SCALARS pressure float\nLOOKUP_TABLE default\n" +
                                    ascii_values(27) + "VECTORS velocity float\n" + ascii_values(81);
  expect_failure("missing_named.vtk", file_contents,
                 {"no point data array named 'U'",
                  "'pressure' (SCALARS float, 1 component), 'velocity' (VECTORS float, 3 components)"},
                 FAS::parameters::array_name("U"));
  expect_failure("missing_mask.vtk", file_contents,
                 {"no point data array named 'fluid' for the mask", "'pressure'"},
                 FAS::parameters::mask_array_name("fluid"));
  expect_failure("no_vectors.vtk",
                 ascii_header + "SCALARS pressure float\nLOOKUP_TABLE default\n" + ascii_values(27),
                 {"no 3-component point data array", "'pressure' (SCALARS float, 1 component)"});
  expect_failure("no_point_data.vtk",
                 "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 3 3 3\n",
                 {"no 3-component point data array", "are: none"});
  expect_failure("scalar_as_velocity.vtk", file_contents,
                 {"'pressure' has 1 components", "3 numbers per node"},
                 FAS::parameters::array_name("pressure"));
}

TEST(ReadVTKLegacyBadInput, NonFiniteValuesNameTheNode)
{
  // Node 5 = (2, 1, 0) of the 3 x 3 x 3 grid, on line 11 of the file.
  std::string values = ascii_values(15) + "1 nan 1\n" + ascii_values(63);
  expect_failure("nan.vtk", ascii_header + "VECTORS velocity float\n" + values,
                 {"line 11", "node 5 = (2, 1, 0), component 1", "nan", "expected a finite number"});
  values = ascii_values(15) + "1 1 -inf\n" + ascii_values(63);
  expect_failure("inf.vtk", ascii_header + "VECTORS velocity float\n" + values,
                 {"line 11", "node 5 = (2, 1, 0), component 2", "-inf"});
  expect_failure("too_large_for_float.vtk",
                 ascii_header + "VECTORS velocity double\n" + ascii_values(80) + "1e300\n",
                 {"node 26 = (2, 2, 2), component 2", "does not fit in a 32-bit float"});
  // Binary: the byte offset of the value.
  std::string s = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                  "POINT_DATA 8\nVECTORS velocity double\n";
  const std::size_t begin = s.size();
  for (int i = 0; i < 24; ++i)
    append_big_endian(s, i == 13 ? std::nan("") : 1.0);
  expect_failure("nan_binary.vtk", s,
                 {"byte " + std::to_string(begin + 13 * 8), "node 4 = (0, 0, 1), component 1"});
  // A NaN at a solid node is accepted and stored as zero, as in Regular_grid_flow_field_3.
  s += "\nSCALARS inside unsigned_char\nLOOKUP_TABLE default\n" + std::string("\1\1\1\1\0\1\1\1", 8);
  const std::string file = temporary("nan_solid.vtk");
  write_bytes(file, s);
  Grid g = sentinel_grid();
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(&error))) << error;
  EXPECT_EQ(g.node_value(0, 0, 1), Vector(0, 0, 0));
}

TEST(ReadVTKLegacyBadInput, MaskOfTheWrongSize)
{
  const std::string velocity = "VECTORS velocity float\n" + ascii_values(81);
  // SCALARS take their count from POINT_DATA: a short mask runs into the next keyword.
  expect_failure("short_mask.vtk",
                 ascii_header + "SCALARS inside unsigned_char\nLOOKUP_TABLE default\n" + ascii_values(20) +
                     velocity,
                 {"line 12", "'VECTORS' is not a number", "SCALARS 'inside'"});
  // A FIELD array carries its own count.
  expect_failure("field_mask.vtk",
                 ascii_header + velocity + "FIELD f 1\ninside 1 20 int\n" + ascii_values(20),
                 {"the mask array 'inside' has 20 tuples but the grid (DIMENSIONS 3 3 3) has 27 nodes"});
  expect_failure("vector_mask.vtk",
                 ascii_header + velocity + "SCALARS inside float 3\nLOOKUP_TABLE default\n" +
                     ascii_values(81),
                 {"the mask array 'inside' has 3 components", "1 number per node (27 values)"});
  expect_failure("nan_mask.vtk",
                 ascii_header + velocity + "SCALARS inside float\nLOOKUP_TABLE default\n" + ascii_values(26) +
                     "nan\n",
                 {"line 14", "the mask 'inside' is NaN at node 26"});
}

} // namespace

} // namespace test_read_VTK_legacy
