// The AmiraMesh reader: hand-written files (ASCII, binary little- and big-endian, HxByteRLE)
// whose node values are a known formula give back exactly those values at the nodes that
// BoundingBox places by hand (first and last node), with the mask; every kind of bad input
// gives `false` with a message naming the file, the place and the fault, the field untouched.

#include <CGAL/Flow_aligned_surfaces/IO/read_AmiraMesh.h>

#include "grid_reader_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_AmiraMesh {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using fas_test::Grid;
using Point = Grid::Point_3;
using Vector = Grid::Vector_3;

struct Reader {
  template <class NamedParameters>
  bool operator()(const std::string& file, Grid& g, const NamedParameters& np, std::string* error) const
  {
    return FAS::IO::read_AmiraMesh_flow_field(file, g, FAS::parameters::error_message(error, np));
  }
};
const fas_test::Grid_reader_checks<Reader> checks("fas_read_AmiraMesh_");

// The velocity written at node (i, j, k) of every test file: small integers and quarters, exact
// in every type used.
Vector velocity(std::size_t i, std::size_t j, std::size_t k)
{
  return Vector(double(i) + 10. * double(j) + 100. * double(k), -double(i), 0.25 * double(k));
}

std::string ascii_velocities(std::size_t nx, std::size_t ny, std::size_t nz)
{
  return fas_test::node_values_text({{nx, ny, nz}}, velocity);
}

template <class T>
std::string binary_velocities(std::size_t nx, std::size_t ny, std::size_t nz, bool big_endian)
{
  return fas_test::node_values_binary<T>({{nx, ny, nz}}, velocity, big_endian);
}

// BoundingBox 1 2 -1 0 0 0.5 on 3 x 2 x 2 nodes: hx = 0.5, hy = 1, hz = 0.5.
const std::string parameters = "Parameters {\n"
                               "    Content \"3x2x2 float[3], uniform coordinates {not a block}\",\n"
                               "    Materials {\n"
                               "        Exterior { Id 1 }\n"
                               "        Inside { Color 0.64 0 0.8, BoundingBox 9 9 9 9 9 9 }\n"
                               "    }\n"
                               "    Note \"BoundingBox 5 6 5 6 5 6, }\",\n"
                               "    BoundingBox 1 2 -1 0 0 0.5,\n"
                               "    CoordType \"uniform\"\n"
                               "}\n\n";

void expect_known_field(const Grid& g)
{
  ASSERT_EQ(g.dimensions(), (Grid::Dimensions{{3, 2, 2}}));
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t j = 0; j < 2; ++j)
      for (std::size_t i = 0; i < 3; ++i) {
        // Node positions computed by hand from the BoundingBox (first and last node).
        EXPECT_EQ(g.node_point(i, j, k), Point(1. + 0.5 * double(i), -1. + double(j), 0.5 * double(k)));
        EXPECT_EQ(g.node_value(i, j, k), velocity(i, j, k)) << i << " " << j << " " << k;
      }
  // The last node is the BoundingBox's maximum corner.
  EXPECT_EQ(g.node_point(2, 1, 1), Point(2, 0, 0.5));
  // velocity() is linear, so the trilinear interpolation is exact inside.
  const std::optional<Vector> v = g(Point(1.25, -0.5, 0.25));
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->x(), 0.5 + 5. + 50., 1e-12);
  EXPECT_NEAR(v->y(), -0.5, 1e-12);
  EXPECT_NEAR(v->z(), 0.125, 1e-12);
}

// ------------------------------------------------------------------------------------------
// Good files

TEST(ReadAmiraMesh, AsciiFileGivesTheWrittenValuesAtTheBoundingBoxNodes)
{
  const Grid g =
      checks.read_ok("ascii.am", "# AmiraMesh 3D ASCII 2.0\n\n\ndefine Lattice 3 2 2\n\n" + parameters +
                                     "Lattice { float[3] Data } @1\n\n# Data section follows\n@1\n" +
                                     ascii_velocities(3, 2, 2) + "\n");
  expect_known_field(g);
  EXPECT_FALSE(g.has_mask());
}

TEST(ReadAmiraMesh, AvizoHeaderAndNoDataSectionLine)
{
  // Without '# Data section follows' the data start at the first '@1'.
  const Grid g =
      checks.read_ok("avizo.am", "# Avizo 3D ASCII 2.0\ndefine Lattice 3 2 2\n" + parameters +
                                     "Lattice { double[3] velocity } = @1\n@1\n" + ascii_velocities(3, 2, 2));
  expect_known_field(g);
}

TEST(ReadAmiraMesh, BinaryLittleEndianWithMaskAndOtherLocationsSkipped)
{
  std::string file = "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\n\ndefine Lattice 3 2 2\ndefine Markers 2\n\n" +
                     parameters +
                     "Markers { int[3] Ids } @1\nLattice { float[3] Data } @2\nLattice { byte inside } @3\n"
                     "\n# Data section follows\n@1\n";
  for (int v : {1, 2, 3, 4, 5, 6})
    fas_test::append_binary(file, std::int32_t(v), false);
  file += "\n@2\n" + binary_velocities<float>(3, 2, 2, false) + "\n@3\n";
  for (int n = 0; n < 12; ++n)
    file += static_cast<char>(n == 5 ? 0 : 1); // node 5 = (2, 1, 0) is solid
  file += "\n";
  const Grid g = checks.read_ok("little.am", file);
  expect_known_field(g);
  ASSERT_TRUE(g.has_mask());
  for (std::size_t n = 0; n < 12; ++n)
    EXPECT_EQ(g.is_fluid(n % 3, (n / 3) % 2, n / 6), n != 5);
}

TEST(ReadAmiraMesh, BinaryBigEndianNamedArraysOfOtherTypes)
{
  // '3D BINARY' is big-endian; the velocity is the second 3-component field, chosen by name;
  // the mask is a short field chosen by name.
  std::string file = "# AmiraMesh 3D BINARY 2.0\ndefine Lattice 3 2 2\n" + parameters +
                     "Lattice { float[3] other } @1\nLattice { double[3] velocity } @2\n"
                     "Lattice { short solid } @3\n# Data section follows\n@1\n" +
                     std::string(36 * 4, '\0') + "\n@2\n" + binary_velocities<double>(3, 2, 2, true) +
                     "\n@3\n";
  for (int n = 0; n < 12; ++n)
    fas_test::append_binary(file, std::int16_t(n == 11 ? 0 : -3), true);
  const Grid g =
      checks.read_ok("big.am", file + "\n",
                     FAS::parameters::array_name("velocity", FAS::parameters::mask_array_name("solid")));
  expect_known_field(g);
  EXPECT_TRUE(g.is_fluid(0, 0, 0));
  EXPECT_FALSE(g.is_fluid(2, 1, 1));
  // Integer velocities, big-endian ushort.
  std::string u = "# AmiraMesh 3D BINARY 2.0\ndefine Lattice 2 2 2\nParameters { BoundingBox 0 1 0 1 0 1 }\n"
                  "Lattice { ushort[3] v } @1\n# Data section follows\n@1\n";
  for (int n = 0; n < 24; ++n)
    fas_test::append_binary(u, std::uint16_t(n == 5 ? 65535 : n), true);
  const Grid h = checks.read_ok("ushort.am", u);
  EXPECT_EQ(h.node_value(1, 0, 0), Vector(3, 4, 65535));
  EXPECT_EQ(h.node_value(1, 1, 1), Vector(21, 22, 23));
}

TEST(ReadAmiraMesh, HxByteRLESectionsAreExpanded)
{
  // byte[3] on 2 x 2 x 2 nodes = 24 bytes: a run of 12 zeros (0x0c 0x00), then 12 literal bytes
  // (0x8c, 1 ... 12).
  std::string rle = {'\x0c', '\x00', '\x8c'};
  for (char c = 1; c <= 12; ++c)
    rle += c;
  const Grid g =
      checks.read_ok("rle.am", "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\ndefine Lattice 2 2 2\n"
                               "Parameters { BoundingBox 0 1 0 1 0 1, CoordType \"uniform\" }\n"
                               "Lattice { byte[3] Data } @1(HxByteRLE,15)\n# Data section follows\n@1\n" +
                                   rle + "\n");
  EXPECT_EQ(g.node_value(1, 1, 0), Vector(0, 0, 0));
  EXPECT_EQ(g.node_value(0, 0, 1), Vector(1, 2, 3));
  EXPECT_EQ(g.node_value(1, 1, 1), Vector(10, 11, 12));
}

TEST(ReadAmiraMesh, HxZipSectionsAreInflatedWithZlib)
{
  const std::string raw = binary_velocities<float>(3, 2, 2, false);
  auto file = [&](const std::string& lattice, const std::string& z) {
    return "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\ndefine Lattice " + lattice + "\n" + parameters +
           "Lattice { float[3] Data } @1(HxZip," + std::to_string(z.size()) +
           ")\n# Data section follows\n@1\n" + z + "\n";
  };
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
  // Compressed by zlib itself.
  const std::string z = fas_test::zlib_compress(raw, false);
  expect_known_field(checks.read_ok("hxzip.am", file("3 2 2", z)));
  std::string corrupt = z;
  corrupt[2] = static_cast<char>(corrupt[2] ^ 0x55);
  checks.expect_failure("hxzip_corrupt.am", file("3 2 2", corrupt), {"the HxZip data of 'Data'", "invalid"});
  checks.expect_failure("hxzip_cut.am", file("3 2 2", z.substr(0, z.size() - 10)),
                        {"the HxZip data of 'Data'", "end after"});
  checks.expect_failure("hxzip_more.am", file("2 2 2", z), {"expand to more than the 96 bytes"});
  checks.expect_failure("hxzip_lying.am", file("300 200 200", z), {"cannot expand to the 144000000 bytes"});
#else
  checks.expect_failure("hxzip.am", file("3 2 2", raw), {"HxZip", "needs zlib"});
#endif
}

// ------------------------------------------------------------------------------------------
// Bad input

const std::string little_header = "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\ndefine Lattice 3 2 2\n" +
                                  parameters +
                                  "Lattice { float[3] Data } @1\nLattice { byte inside } @2\n"
                                  "# Data section follows\n@1\n";
const std::string little_file =
    little_header + binary_velocities<float>(3, 2, 2, false) + "\n@2\n" + std::string(12, '\x01') + "\n";
const std::string ascii_header =
    "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 3 2 2\n" + parameters + "Lattice { float[3] Data } @1\n";

TEST(ReadAmiraMeshBadInput, NotAmiraMeshAndMissingParts)
{
  Grid g = fas_test::sentinel_grid();
  std::string error;
  EXPECT_FALSE(FAS::IO::read_AmiraMesh_flow_field(checks.temporary("absent.am"), g,
                                                  FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
  fas_test::expect_untouched(g);
  checks.expect_failure("not_am.am", "# vtk DataFile Version 3.0\n", {"line 1", "not an AmiraMesh file"});
  checks.expect_failure("empty.am", "", {"the file is empty"});
  checks.expect_failure("no_lattice.am",
                        "# AmiraMesh 3D ASCII 2.0\ndefine Markers 3\n# Data section follows\n",
                        {"define Lattice"});
  checks.expect_failure(
      "no_bounding_box.am",
      "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 2 2\nParameters { CoordType \"uniform\" }\n"
      "Lattice { float[3] Data } @1\n# Data section follows\n@1\n" +
          ascii_velocities(2, 2, 2),
      {"BoundingBox"});
  checks.expect_failure("no_data_section.am", ascii_header, {"no data section"});
  checks.expect_failure("missing_section.am",
                        ascii_header + "Lattice { byte inside } @2\n# Data section follows\n@1\n" +
                            ascii_velocities(3, 2, 2),
                        {"section @2", "'inside'", "missing"});
  checks.expect_failure(
      "missing_array.am", ascii_header + "# Data section follows\n@1\n" + ascii_velocities(3, 2, 2),
      {"no lattice field named 'speed'", "'Data' (float[3])"}, FAS::parameters::array_name("speed"));
  checks.expect_failure(
      "missing_mask.am", ascii_header + "# Data section follows\n@1\n" + ascii_velocities(3, 2, 2),
      {"no lattice field named 'fluid' for the mask"}, FAS::parameters::mask_array_name("fluid"));
  checks.expect_failure("unclosed_parameters.am",
                        "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 2 2\nParameters {\n a { b",
                        {"line 3", "not closed"});
}

TEST(ReadAmiraMeshBadInput, UnsupportedCoordinatesCompressionAndTypes)
{
  std::string rectilinear = ascii_header + "# Data section follows\n@1\n" + ascii_velocities(3, 2, 2);
  rectilinear.replace(rectilinear.find("\"uniform\""), 9, "\"rectilinear\"");
  checks.expect_failure("rectilinear.am", rectilinear,
                        {"line 11", "CoordType \"rectilinear\" is not supported"});
  checks.expect_failure("hxfoo.am",
                        "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\ndefine Lattice 2 2 2\n"
                        "Parameters { BoundingBox 0 1 0 1 0 1 }\nLattice { float[3] Data } @1(HxFoo,4)\n"
                        "# Data section follows\n@1\nabcd\n",
                        {"compressed with HxFoo, which is not supported"});
  checks.expect_failure("unknown_type.am",
                        "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 2 2\nLattice { quaternion[3] Data } @1\n",
                        {"line 3", "unknown data type 'quaternion'"});
  checks.expect_failure("flat.am", "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 4 4 1\n# Data section follows\n",
                        {"line 2", "at least 2 nodes"});
  checks.expect_failure("2d.am", "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 4 4\n", {"line 2", "3D lattices"});
  checks.expect_failure(
      "scalar_velocity.am",
      "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 2 2\nParameters { BoundingBox 0 1 0 1 0 1 }\n"
      "Lattice { float Data } @1\n# Data section follows\n@1\n0 0 0 0 0 0 0 0\n",
      {"has 1 components"}, FAS::parameters::array_name("Data"));
}

TEST(ReadAmiraMeshBadInput, TruncatedFilesAndLyingSizes)
{
  const std::size_t data = little_header.size();
  // Cut inside the velocities: their section needs 144 bytes.
  checks.expect_failure("truncated.am", little_file.substr(0, data + 100),
                        {"byte " + std::to_string(data - 3), "section @1", "needs 144 bytes but only 100"});
  // Every cut before the end of the mask fails cleanly.
  checks.expect_every_cut_fails(little_file, little_file.size() - 1, 7);
  // A lattice far larger than the file: caught before anything is allocated.
  std::string lying = little_file;
  lying.replace(lying.find("3 2 2"), 5, "3000 2000 2000");
  checks.expect_failure("lying.am", lying, {"section @1", "bytes but only"});
  std::string overflow = little_file;
  overflow.replace(overflow.find("3 2 2"), 5, "99999999999 99999999999 99999999999");
  checks.expect_failure("overflow.am", overflow, {"line 2", "too many elements"});
  checks.expect_failure("overflow_components.am",
                        "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 2 2\ndefine Markers 1000000000000000\n"
                        "Parameters { BoundingBox 0 1 0 1 0 1 }\nMarkers { float[1024] x } @1\n"
                        "# Data section follows\n@1\n1 2 3\n",
                        {"line 5", "'x' have too many values"});
  // Wrong sizes: the data are for 3 x 2 x 2, the header says 2 x 2 x 2, so '@2' is not where the
  // sizes put it.
  std::string wrong = little_file;
  wrong.replace(wrong.find("3 2 2"), 5, "2 2 2");
  checks.expect_failure("wrong_sizes.am", wrong, {"data section marker", "wrong sizes"});
  checks.expect_failure("lying_rle.am",
                        "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\ndefine Lattice 200 200 200\n"
                        "Parameters { BoundingBox 0 1 0 1 0 1 }\nLattice { float[3] Data } @1(HxByteRLE,4)\n"
                        "# Data section follows\n@1\n\x7f\x01\x7f\x01\n",
                        {"HxByteRLE", "cannot expand"});
  checks.expect_failure("short_rle.am",
                        "# AmiraMesh BINARY-LITTLE-ENDIAN 2.1\ndefine Lattice 2 2 2\n"
                        "Parameters { BoundingBox 0 1 0 1 0 1 }\nLattice { byte[3] Data } @1(HxByteRLE,4)\n"
                        "# Data section follows\n@1\n\x0a\x01\x0a\x01\n",
                        {"HxByteRLE", "end after 20 of 24 bytes"});
  checks.expect_failure("ascii_short.am",
                        ascii_header + "# Data section follows\n@1\n" + ascii_velocities(3, 2, 1),
                        {"section @1", "ends after 18 of its 36 values"});
}

TEST(ReadAmiraMeshBadInput, NonNumericTokensAndNonFiniteValues)
{
  std::string word = ascii_header + "# Data section follows\n@1\n" + ascii_velocities(3, 2, 2);
  const std::size_t at = word.find("\n", word.find("follows\n@1\n") + 11) + 1; // the second node's line
  word.replace(at, 8, "abc     ");
  checks.expect_failure("word.am", word,
                        {"line 18", "byte " + std::to_string(at), "'abc' is not a number", "'Data'"});
  std::string nan = ascii_header + "# Data section follows\n@1\n" + ascii_velocities(3, 2, 2);
  nan.replace(nan.find("\n", nan.find("follows\n@1\n") + 11) + 1, 8, "nan     ");
  checks.expect_failure("nan.am", nan,
                        {"line 18", "node 1 = (1, 0, 0), component 0", "expected a finite number"});
  // A NaN at a solid node is accepted (stored as zero).
  std::string solid = little_file;
  const std::size_t v4 = little_header.size() + 4 * 12; // node 4, component 0
  solid.replace(v4, 4, std::string("\x00\x00\xc0\x7f", 4));
  solid[solid.size() - 1 - 12 + 4] = '\0';
  const Grid g = checks.read_ok("nan_solid.am", solid);
  EXPECT_EQ(g.node_value(1, 1, 0), Vector(0, 0, 0));
  EXPECT_FALSE(g.is_fluid(1, 1, 0));
  // ... but not at a fluid node, in binary either.
  solid[solid.size() - 1 - 12 + 4] = '\1';
  checks.expect_failure("nan_fluid.am", solid,
                        {"byte " + std::to_string(v4), "node 4 = (1, 1, 0)", "at a fluid node"});
  checks.expect_failure("word_in_lattice.am", "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 two 2\n",
                        {"line 2", "'two'"});
  checks.expect_failure(
      "word_in_box.am",
      "# AmiraMesh 3D ASCII 2.0\ndefine Lattice 2 2 2\nParameters { BoundingBox 0 1 0 x 0 1 }\n",
      {"line 3", "'x' is not a finite number"});
}

} // namespace

} // namespace test_read_AmiraMesh
