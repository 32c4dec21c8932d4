// The NRRD reader: hand-written headers with attached data (ASCII, raw little- and big-endian
// of several types) and a detached .nhdr beside a raw float32 file give back exactly the values
// written at the nodes that spacings/space directions and space origin place by hand; every kind
// of bad input gives `false` with a message naming the file, the place and the fault, the field
// untouched.

#include <CGAL/Flow_aligned_surfaces/IO/read_NRRD.h>

#include "grid_reader_test_helpers.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_NRRD {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using fas_test::Grid;
using Point = Grid::Point_3;
using Vector = Grid::Vector_3;

struct Reader {
  template <class NamedParameters>
  bool operator()(const std::string& file, Grid& g, const NamedParameters& np, std::string* error) const
  {
    return FAS::IO::read_NRRD_flow_field(file, g, FAS::parameters::error_message(error, np));
  }
};
const fas_test::Grid_reader_checks<Reader> checks("fas_read_NRRD_");

// The velocity written at node (i, j, k): small integers, exact in every type used.
Vector velocity(std::size_t i, std::size_t j, std::size_t k)
{
  return Vector(double(i) + 4. * double(j) + 16. * double(k), -double(j), double(k) - 1.);
}

// 4 x 3 x 2 nodes, x fastest, as text or binary.
const std::size_t nx = 4, ny = 3, nz = 2;

std::string ascii_velocities()
{
  return fas_test::node_values_text({{nx, ny, nz}}, velocity);
}

template <class T>
std::string binary_velocities(bool big_endian)
{
  return fas_test::node_values_binary<T>({{nx, ny, nz}}, velocity, big_endian);
}

// Node (i, j, k) at (0.5 + 0.25 i, -1 + 2 j, 3 + 0.5 k), written by hand.
void expect_known_field(const Grid& g)
{
  ASSERT_EQ(g.dimensions(), (Grid::Dimensions{{nx, ny, nz}}));
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        EXPECT_EQ(g.node_point(i, j, k),
                  Point(0.5 + 0.25 * double(i), -1. + 2. * double(j), 3. + 0.5 * double(k)));
        EXPECT_EQ(g.node_value(i, j, k), velocity(i, j, k)) << i << " " << j << " " << k;
      }
  EXPECT_FALSE(g.has_mask());
  // velocity() is linear: the interpolation is exact between nodes.
  const std::optional<Vector> v = g(Point(0.625, 0., 3.25));
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->x(), 0.5 + 2. + 8., 1e-12);
  EXPECT_NEAR(v->y(), -0.5, 1e-12);
  EXPECT_NEAR(v->z(), -0.5, 1e-12);
}

const std::string geometry = "sizes: 3 4 3 2\nspacings: nan 0.25 2 0.5\nspace origin: (0.5, -1,3)\n";

std::string header(const std::string& type, const std::string& rest)
{
  return "NRRD0004\n# a comment\ntype: " + type + "\ndimension: 4\n" + geometry + rest;
}

// ------------------------------------------------------------------------------------------
// Good files

TEST(ReadNRRD, AsciiAttachedDataGiveTheWrittenValuesAtTheNodes)
{
  expect_known_field(checks.read_ok("ascii.nrrd", header("float", "encoding: ascii\nkey:=value: with colon\n"
                                                                  "kinds: vector domain domain domain\n\n") +
                                                      ascii_velocities()));
  // 'text' is a synonym; 'centers' is noted and changes nothing.
  expect_known_field(checks.read_ok(
      "text.nrrd", header("double", "encoding: text\ncenters: ??? cell cell cell\n\n") + ascii_velocities()));
}

TEST(ReadNRRD, RawAttachedDataInBothByteOrdersAndSeveralTypes)
{
  expect_known_field(
      checks.read_ok("float_little.nrrd",
                     header("float", "endian: little\nencoding: raw\n\n") + binary_velocities<float>(false)));
  expect_known_field(checks.read_ok("double_big.nrrd", header("double", "endian: big\nencoding: raw\n\n") +
                                                           binary_velocities<double>(true)));
  expect_known_field(
      checks.read_ok("short_big.nrrd", header("signed short int", "endian: big\nencoding: raw\n\n") +
                                           binary_velocities<std::int16_t>(true)));
  expect_known_field(
      checks.read_ok("int8.nrrd", header("int8", "encoding: raw\n\n") +
                                      binary_velocities<std::int8_t>(false))); // no endian needed
  expect_known_field(checks.read_ok("int64.nrrd", header("int64_t", "endian: little\nencoding: raw\n\n") +
                                                      binary_velocities<std::int64_t>(false)));
}

TEST(ReadNRRD, SpaceDirectionsGiveTheSameNodes)
{
  expect_known_field(checks.read_ok("directions.nrrd",
                                    "NRRD0005\ntype: float\ndimension: 4\nspace: right-anterior-superior\n"
                                    "sizes: 3 4 3 2\nspace directions: none (0.25,0,0) (0, 2, 0) (0,0,0.5)\n"
                                    "space origin: (0.5,-1,3)\nendian: little\nencoding: raw\n\n" +
                                        binary_velocities<float>(false)));
}

TEST(ReadNRRD, DetachedHeaderBesideARawFloat32File)
{
  // The raw file: the values only; the header names it relative to its own folder, and skips a
  // 10-byte preamble in it.
  fas_test::write_bytes(checks.temporary("detached.raw"),
                        std::string(10, 'x') + binary_velocities<float>(false));
  const std::string nhdr = header("float", "endian: little\nencoding: raw\nbyte skip: 10\n"
                                           "data file: fas_read_NRRD_detached.raw\n");
  expect_known_field(checks.read_ok("detached.nhdr", nhdr));
  // byte skip: -1 = the data are the end of the file; line skip counts lines first.
  expect_known_field(
      checks.read_ok("line_skip.nrrd", header("float", "endian: little\nencoding: raw\nline skip: 2\n"
                                                       "byte skip: -1\n\nfirst\nsecond\npadding") +
                                           binary_velocities<float>(false)));
  // array_name is checked against the content field.
  expect_known_field(checks.read_ok(
      "content.nrrd", header("float", "content: wind\nencoding: ascii\n\n") + ascii_velocities(),
      FAS::parameters::array_name("wind")));
}

TEST(ReadNRRD, GzipDataAreInflatedWithZlib)
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
  // Compressed by zlib itself; 'byte skip' counts decompressed bytes.
  const std::string gz = fas_test::zlib_compress("skipme" + binary_velocities<float>(false), true);
  expect_known_field(
      checks.read_ok("gzip.nrrd", header("float", "endian: little\nencoding: gzip\nbyte skip: 6\n\n") + gz));
  fas_test::write_bytes(checks.temporary("detached.raw.gz"),
                        fas_test::zlib_compress(binary_velocities<double>(true), true));
  expect_known_field(checks.read_ok(
      "gz_detached.nhdr",
      header("double", "endian: big\nencoding: gz\ndata file: fas_read_NRRD_detached.raw.gz\n")));
  std::string corrupt = gz;
  corrupt[12] = static_cast<char>(corrupt[12] ^ 0x55);
  checks.expect_failure("gzip_corrupt.nrrd",
                        header("float", "endian: little\nencoding: gzip\nbyte skip: 6\n\n") + corrupt,
                        {"the gzip data of the 72 float values", "byte "});
  std::string lying = header("float", "endian: little\nencoding: gzip\n\n") + gz;
  lying.replace(lying.find("3 4 3 2"), 7, "3 400 300 200");
  checks.expect_failure("gzip_lying.nrrd", lying, {"cannot expand to the 288000000 bytes"});
  checks.expect_failure("gzip_no_endian.nrrd", header("float", "encoding: gzip\n\n") + gz,
                        {"no 'endian' field", "gzip float"});
#else
  checks.expect_failure("gzip.nrrd", header("float", "encoding: gzip\n"),
                        {"line 8", "gzip is not supported by this build"});
#endif
}

// ------------------------------------------------------------------------------------------
// Bad input

const std::string raw_file =
    header("float", "endian: little\nencoding: raw\n\n") + binary_velocities<float>(false);
const std::string ascii_file = header("float", "encoding: ascii\n\n") + ascii_velocities();

TEST(ReadNRRDBadInput, NotNRRDMissingFieldsAndMissingData)
{
  checks.expect_failure("not_nrrd.nrrd", "# AmiraMesh 3D ASCII 2.0\n", {"line 1", "not a NRRD file"});
  checks.expect_failure("empty.nrrd", "", {"the file is empty"});
  checks.expect_failure("no_type.nrrd", "NRRD0004\ndimension: 4\nsizes: 3 2 2 2\n\n", {"no 'type' field"});
  checks.expect_failure("no_sizes.nrrd", "NRRD0004\ntype: float\ndimension: 4\n\n", {"'sizes: 3 nx ny nz'"});
  checks.expect_failure("no_data.nrrd", header("float", "encoding: ascii\n"), {"no data attached"});
  checks.expect_failure("absent_data_file.nhdr",
                        header("float", "encoding: raw\nendian: little\ndata file: nowhere.raw\n"),
                        {"data file", "nowhere.raw", "cannot open"});
  checks.expect_failure("no_endian.nrrd",
                        header("float", "encoding: raw\n\n") + binary_velocities<float>(false),
                        {"no 'endian' field", "float"});
  checks.expect_failure("garbage_line.nrrd", "NRRD0004\ntype float\n", {"line 2", "neither a field"});
}

TEST(ReadNRRDBadInput, UnsupportedLayoutsEncodingsAndTypes)
{
  checks.expect_failure("dimension3.nrrd", "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\n",
                        {"line 3", "dimension is 3", "sizes 3 nx ny nz"});
  checks.expect_failure("vector_last.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 4 3 2 3\n",
                        {"line 4", "first axis has 4 samples"});
  checks.expect_failure("kinds_last.nrrd", header("float", "kinds: domain domain domain vector\n"),
                        {"line 8", "vector axis must come first"});
  checks.expect_failure("rotated.nrrd",
                        "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\n"
                        "space directions: none (0.7,0.7,0) (-0.7,0.7,0) (0,0,1)\n",
                        {"line 5", "rotated, sheared", "not supported"});
  checks.expect_failure("mirrored.nrrd",
                        "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\n"
                        "space directions: none (1,0,0) (0,-1,0) (0,0,1)\n",
                        {"line 5", "axis 2", "not supported"});
  checks.expect_failure(
      "2d_space.nrrd",
      "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\nspace directions: none (1,0) (0,1) (0,0)\n",
      {"line 5", "3 components"});
  checks.expect_failure("unknown_type.nrrd", "NRRD0004\ntype: quaternion\n",
                        {"line 2", "unknown or unsupported type"});
  checks.expect_failure("block.nrrd", "NRRD0004\ntype: block\n", {"line 2", "'block'"});
  checks.expect_failure("list.nhdr", header("float", "data file: LIST\n"),
                        {"several files are not supported"});
  checks.expect_failure("flat.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 4 4 1\n\n",
                        {"at least 2 nodes"});
  checks.expect_failure("mask.nrrd", ascii_file, {"no mask 'inside'"},
                        FAS::parameters::mask_array_name("inside"));
  checks.expect_failure("content.nrrd",
                        header("float", "content: wind\nencoding: ascii\n\n") + ascii_velocities(),
                        {"named 'wind'", "not 'velocity'"}, FAS::parameters::array_name("velocity"));
}

TEST(ReadNRRDBadInput, TruncatedFilesWrongAndLyingSizes)
{
  const std::size_t data = raw_file.size() - 24 * 12;
  checks.expect_failure("truncated.nrrd", raw_file.substr(0, raw_file.size() - 5),
                        {"byte " + std::to_string(data), "need 288 bytes but only 283"});
  checks.expect_every_cut_fails(raw_file, raw_file.size(), 5);
  // A detached data file too short for the sizes: the message names both files.
  fas_test::write_bytes(checks.temporary("short.raw"), binary_velocities<float>(false).substr(0, 100));
  checks.expect_failure(
      "short.nhdr", header("float", "endian: little\nencoding: raw\ndata file: fas_read_NRRD_short.raw\n"),
      {"data file", "fas_read_NRRD_short.raw", "byte 0", "need 72 x 4 bytes but the data have 100"});
  std::string lying = raw_file;
  lying.replace(lying.find("3 4 3 2"), 7, "3 4000 3000 2000");
  checks.expect_failure("lying.nrrd", lying, {"72000000000 float values", "bytes but the data have"});
  std::string overflow = raw_file;
  overflow.replace(overflow.find("3 4 3 2"), 7, "3 99999999999 99999999999 99999999999");
  checks.expect_failure("overflow.nrrd", overflow, {"too many nodes"});
  checks.expect_failure("ascii_short.nrrd",
                        header("float", "encoding: ascii\n\n") + ascii_velocities().substr(0, 40),
                        {"line 10", "need at least 143 bytes of text"});
  checks.expect_failure("ascii_truncated.nrrd",
                        header("float", "encoding: ascii\n\n") + ascii_velocities().substr(0, 56) +
                            std::string(200, ' '),
                        {"data end after", "of the 72 values"});
  checks.expect_failure("skip_past.nrrd",
                        header("float", "endian: little\nencoding: raw\nbyte skip: 100000\n\n") +
                            binary_velocities<float>(false),
                        {"byte skip: 100000", "past the end"});
  checks.expect_failure("line_skip_past.nrrd", header("float", "encoding: ascii\nline skip: 1000\n\n1 2 3\n"),
                        {"the data end after 1 of the 1000 lines"});
}

TEST(ReadNRRDBadInput, NonNumericTokensAndNonFiniteValues)
{
  std::string word = ascii_file;
  const std::size_t at = word.find("\n", word.find("\n\n") + 2) + 1; // the second node's line: "1.000000 ..."
  word.replace(at, 8, "z       ");
  checks.expect_failure("word.nrrd", word,
                        {"line 11", "byte " + std::to_string(at), "'z' is not a number", "value 3 of"});
  std::string nan = ascii_file;
  nan.replace(at, 8, "nan     ");
  checks.expect_failure("nan.nrrd", nan,
                        {"line 11", "node 1 = (1, 0, 0), component 0", "expected a finite number"});
  std::string raw_inf = raw_file;
  const std::size_t node5 = raw_file.size() - 24 * 12 + 5 * 12 + 8; // node 5 = (1, 1, 0), component 2
  raw_inf.replace(node5, 4, std::string("\x00\x00\x80\x7f", 4));
  checks.expect_failure("inf.nrrd", raw_inf,
                        {"byte " + std::to_string(node5), "node 5 = (1, 1, 0), component 2"});
  std::string big = ascii_file;
  big.replace(at, 8, "1e39    ");
  checks.expect_failure("big.nrrd", big, {"does not fit in a 32-bit float"});
  checks.expect_failure("word_spacing.nrrd",
                        "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\nspacings: nan 1 x 1\n",
                        {"line 5", "byte 59", "'x' is not a finite number"});
  checks.expect_failure("negative_spacing.nrrd",
                        "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\nspacings: nan 1 -1 1\n",
                        {"line 5", "expected a positive number"});
  checks.expect_failure("word_origin.nrrd",
                        "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 2 2\nspace origin: (0,a,0)\n",
                        {"line 5", "'a' is not a finite number"});
  checks.expect_failure("word_size.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 2 two 2\n",
                        {"line 4", "'two' is not a non-negative integer"});
}

} // namespace

} // namespace test_read_NRRD
