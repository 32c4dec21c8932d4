// The VTK XML reader without VTK on bad input: every kind of bad file (missing, not XML,
// malformed XML, another kind of data set, truncated data, lying sizes and compression headers,
// bad base64 or compressed data, missing or unfit arrays, non-finite velocities, rotated or flat
// images, several pieces, bad cells, bad collections, and the files on which VTK itself
// crashes or allocates gigabytes) gives `false` with a message naming the file, where (byte,
// line) and what is wrong, prints nothing, and leaves the output untouched.

#include <gtest/gtest.h>

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "skip_without_tool.h"
#include "test_files.h"
#include "vtk_xml_test_files.h"

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_VTK_XML_refusals {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;
using Grid = FAS::Regular_grid_flow_field_3<K>;
using Rectilinear = FAS::Rectilinear_grid_flow_field_3<K>;
using Cells = FAS::Unstructured_flow_field_3<K>;
using namespace vtk_xml_test;

std::string temporary(const std::string& name)
{
  return temporary_file("fas_read_VTK_XML_refusals_", name);
}

std::string written(const std::string& name, const std::string& contents)
{
  const std::string file = temporary(name);
  write_bytes(file, contents);
  return file;
}

// A 2 x 2 x 2 ImageData file written by hand, ASCII, with the given attributes and arrays.
std::string hand_written_vti(const std::string& arrays, const std::string& image_attributes = "",
                             const std::string& extent = "0 1 0 1 0 1", const std::string& root_attributes = "")
{
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\"" +
         root_attributes + ">\n<ImageData WholeExtent=\"" + extent + "\" Origin=\"0 0 0\" Spacing=\"1 1 1\" " +
         image_attributes + ">\n<Piece Extent=\"" + extent + "\">\n<PointData>\n" + arrays +
         "</PointData>\n<CellData>\n</CellData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
}

std::string ascii_array(const std::string& type, const std::string& name, int components, const std::string& values)
{
  return "<DataArray type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
         std::to_string(components) + "\" format=\"ascii\">\n" + values + "\n</DataArray>\n";
}

std::string repeated(const std::string& value, int count)
{
  std::string r;
  for (int i = 0; i < count; ++i)
    r += value + " ";
  return r;
}

const std::string velocity = ascii_array("Float32", "velocity", 3, repeated("1 2 3", 8));

// A 2 x 2 x 2 image of `v` (Float32, 3 components) in encoding `e`.
std::string encoded_vti(const Encoding& e, const std::vector<double>& v)
{
  Writer w(e);
  const std::string array = w.data_array(Array{"velocity", "Float32", 3, v});
  return w.file("ImageData", "<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
                             "<Piece Extent=\"0 1 0 1 0 1\">\n<PointData>\n" +
                                 array + "</PointData>\n</Piece>\n</ImageData>\n");
}

std::vector<double> ramp(std::size_t n)
{
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i)
    r[i] = double(i);
  return r;
}

// A grid unlike the ones read, to detect that a failed read changed nothing.
Grid sentinel_grid()
{
  return Grid(Point(-7, -7, -7), Vector(2, 2, 2), {{2, 3, 2}}, std::vector<float>(36, 42.f));
}

void expect_sentinel(const Grid& g)
{
  EXPECT_EQ(g.origin(), Point(-7, -7, -7));
  EXPECT_EQ(g.dimensions(), (Grid::Dimensions{{2, 3, 2}}));
  EXPECT_EQ(g.values(), std::vector<float>(36, 42.f));
}

// The reader fails with all `parts` in the message, prints nothing, and leaves the output as it
// was: an empty field empty, a grid with its values.
template <class Field, class NamedParameters = CGAL::parameters::Default_named_parameters>
void expect_read_fails(const std::string& file, const std::vector<std::string>& parts,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string error;
  Field empty;
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const bool ok = FAS::IO::read_VTK_XML_flow_field(file, empty, FAS::parameters::error_message(&error, np));
  const std::string printed = ::testing::internal::GetCapturedStderr() + ::testing::internal::GetCapturedStdout();
  EXPECT_FALSE(ok) << file;
  EXPECT_EQ(printed, "") << "printed while reading " << file;
  EXPECT_NE(error.find("read_VTK_XML_flow_field: " + file + ": "), std::string::npos) << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "message \"" << error << "\" lacks \"" << part << "\"";
  if constexpr (std::is_same<Field, Grid>::value) {
    Grid g = sentinel_grid();
    EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(file, g, np));
    expect_sentinel(g);
  }
  else {
    EXPECT_EQ(empty.bbox(), CGAL::Bbox_3()); // untouched: empty
  }
}

TEST(ReadVTKXMLRefusals, MissingEmptyAndNonXMLFiles)
{
  expect_read_fails<Grid>(temporary("does_not_exist.vti"), {"no such file"});
  expect_read_fails<Cells>(temporary("does_not_exist.vtu"), {"no such file"});
  expect_read_fails<Grid>(::testing::TempDir(), {"is a directory"});
  const std::string empty = written("empty.vti", "");
  std::string error;
  Grid grid;
  EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(empty, grid, FAS::parameters::error_message(&error)));
  EXPECT_EQ(error, "read_VTK_XML_flow_field: " + empty + ": the file is empty (0 bytes)");
  Cells cells;
  EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(empty, cells, FAS::parameters::error_message(&error)));
  EXPECT_EQ(error, "read_VTK_XML_flow_field: " + empty + ": the file is empty (0 bytes)");
  FAS::Unsteady_flow_field_3<Grid> series;
  EXPECT_FALSE(FAS::IO::read_PVD_flow_field(empty, series, FAS::parameters::error_message(&error)));
  EXPECT_EQ(error, "read_PVD_flow_field: " + empty + ": the file is empty (0 bytes)");

  const std::string garbage = written("garbage.vti", "this is not XML at all\n");
  expect_read_fails<Grid>(garbage, {"line 1, byte 0: 't' where the root element '<' was expected: not an XML file"});
  expect_read_fails<Cells>(garbage, {"not an XML file"});
  expect_read_fails<Grid>(written("html.vti", "<html><body/></html>"), {"not a VTK XML file"});
}

TEST(ReadVTKXMLRefusals, MalformedXMLIsNamedWithItsLineAndByte)
{
  const std::string good = hand_written_vti(velocity);
  expect_read_fails<Grid>(written("cut.vti", good.substr(0, 300)), {"truncated file"});
  std::string mismatched = good;
  mismatched.replace(mismatched.find("</PointData>"), 12, "</PointDatum>");
  expect_read_fails<Grid>(written("mismatched.vti", mismatched),
                          {"the end tag </PointDatum> does not match the start tag <PointData>"});
  std::string twice = good;
  twice.replace(twice.find("<ImageData "), 11, "<ImageData Origin=\"1 1 1\" ");
  expect_read_fails<Grid>(written("twice.vti", twice), {"line 3, byte ", "has two attributes named 'Origin'"});
  expect_read_fails<Grid>(written("quote.vti", hand_written_vti(velocity, "Direction=\"1 0 0")),
                          {"'<' inside an attribute value"});
  expect_read_fails<Grid>(written("after.vti", good + "<VTKFile/>"), {"content after the end of the root element"});
  expect_read_fails<Grid>(written("entity.vti", hand_written_vti(velocity, "Name=\"a &b c\"")), {"'&' starts no entity"});
  std::string deep = "<VTKFile type=\"ImageData\">";
  for (int i = 0; i < 100; ++i)
    deep += "<a>";
  expect_read_fails<Grid>(written("deep.vti", deep), {"nested more than 64 deep"});
}

TEST(ReadVTKXMLRefusals, OtherKindsOfDataSetAreNamed)
{
  const std::string polydata = written(
      "poly.vtp", "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"1\"/></PolyData></VTKFile>");
  expect_read_fails<Grid>(polydata, {"this is a VTK XML file of type \"PolyData\"", "ImageData file (.vti)"});
  expect_read_fails<Cells>(polydata, {"UnstructuredGrid (.vtu)"});
  Encoding e;
  e.mode = Mode::ASCII;
  Writer w(e);
  const std::string vtu = written(
      "kind.vtu", w.file("UnstructuredGrid", "<UnstructuredGrid><Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"/>"
                                             "</UnstructuredGrid>"));
  expect_read_fails<Grid>(vtu, {"this is a VTK XML UnstructuredGrid file (.vtu)",
                                "a Regular_grid_flow_field_3 is read from a VTK XML ImageData file (.vti)"});
  expect_read_fails<Rectilinear>(vtu, {"RectilinearGrid (.vtr)"});
}

TEST(ReadVTKXMLRefusals, TruncatedAndLyingBinaryDataAreRefusedBeforeAllocating)
{
  Encoding raw;
  const std::string good = encoded_vti(raw, ramp(24));
  // Cut in the appended data: the byte count announces more than follows.
  const std::size_t end = good.rfind("\n  </AppendedData>");
  expect_read_fails<Grid>(written("truncated.vti", good.substr(0, end - 40) + good.substr(end)),
                          {"the data of the DataArray 'velocity' announce 96 bytes but only", "truncated file"});
  // A byte count smaller than the array.
  const std::size_t data = good.find("   _") + 4;
  std::string small = good;
  small.replace(data, 4, encode_word(12, raw));
  expect_read_fails<Grid>(written("small.vti", small), {"hold 12 bytes but the array needs 96"});
  // 10^12 points announced by the extent in a file of a few hundred bytes.
  expect_read_fails<Grid>(written("lying.vti", hand_written_vti(velocity, "", "0 9999 0 9999 0 9999")),
                          {"needs 3000000000000 numbers but its text holds", "truncated file or wrong sizes"});
  expect_read_fails<Grid>(written("huge.vti", hand_written_vti(velocity, "", "0 1999999999 0 1999999999 0 1999999999")),
                          {"more than any file holds"});
  expect_read_fails<Cells>(
      written("lying.vtu",
              "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n"
              "<UnstructuredGrid><Piece NumberOfPoints=\"100000000000\" NumberOfCells=\"1\">\n<PointData>" +
                  velocity + "</PointData>\n<Points>" + ascii_array("Float32", "Points", 3, "0 0 0") +
                  "</Points>\n</Piece></UnstructuredGrid></VTKFile>\n"),
      {"needs 300000000000 numbers"});
  // An offset beyond the appended data.
  std::string beyond = good;
  beyond.replace(beyond.find("offset=\"0\""), 10, "offset=\"4" + std::string(59, '2') + "40\"");
  expect_read_fails<Grid>(written("beyond.vti", beyond), {"offset=\"4222222222", "is not a non-negative integer"});
  beyond = good;
  beyond.replace(beyond.find("offset=\"0\""), 10, "offset=\"99999\"");
  expect_read_fails<Grid>(written("beyond.vti", beyond), {"has offset 99999, outside the", "bytes of the appended data"});
}

// The compression header [blocks, block size, last block size, compressed sizes]: each lie is
// refused with what it announces, before anything is allocated from it.
TEST(ReadVTKXMLRefusals, LyingCompressionHeadersAreRefused)
{
  if (!codec_available(Codec::ZLIB))
    FAS_SKIP_WITHOUT_TOOL("no zlib in this build");
  Encoding e;
  e.codec = Codec::ZLIB;
  const std::string good = encoded_vti(e, ramp(24)); // 96 bytes in 2 blocks of 64 bytes
  const std::size_t data = good.find("   _") + 4;
  auto with_header = [&](const std::string& name, std::uint64_t blocks, std::uint64_t size, std::uint64_t last) {
    std::string f = good;
    f.replace(data, 12, encode_word(blocks, e) + encode_word(size, e) + encode_word(last, e));
    return written(name, f);
  };
  ASSERT_EQ(good.substr(data, 12), encode_word(2, e) + encode_word(64, e) + encode_word(32, e));
  expect_read_fails<Grid>(with_header("zero.vti", 2, 0, 0), {"announces 2 blocks of 0 bytes", "lying header"});
  expect_read_fails<Grid>(with_header("last.vti", 2, 64, 65), {"a last block of 65 bytes, more than the block size 64"});
  expect_read_fails<Grid>(with_header("many.vti", 3000000000u, 64, 32),
                          {"announces 3000000000 blocks, whose sizes alone need more than the"});
  expect_read_fails<Grid>(with_header("few.vti", 1, 64, 32), {"holds 32 bytes in 1 blocks but the array needs 96"});
  expect_read_fails<Grid>(with_header("big.vti", 2, 2000000000u, 0),
                          {"block 0 of 2: the ", "compressed bytes cannot expand to the 2000000000 bytes"});
  std::string sizes = good;
  sizes.replace(data + 12, 4, encode_word(100000, e));
  expect_read_fails<Grid>(written("sizes.vti", sizes), {"announces compressed blocks of more bytes than the"});
  std::string corrupt = good;
  corrupt[data + 20 + 3] = static_cast<char>(corrupt[data + 20 + 3] ^ 0x55);
  expect_read_fails<Grid>(written("corrupt.vti", corrupt), {"the compressed DataArray 'velocity' block 0 of 2: "});
  expect_read_fails<Grid>(written("unknown.vti", hand_written_vti(velocity, "", "0 1 0 1 0 1",
                                                                  " compressor=\"vtkZstdDataCompressor\"")),
                          {"compressor=\"vtkZstdDataCompressor\"; expected vtkZLibDataCompressor"});
  expect_read_fails<Grid>(written("header_type.vti", hand_written_vti(velocity, "", "0 1 0 1 0 1",
                                                                      " header_type=\"UInt16\"")),
                          {"header_type=\"UInt16\"; expected UInt32 or UInt64"});
}

TEST(ReadVTKXMLRefusals, BadBase64IsNamedWithItsByte)
{
  Encoding e;
  e.mode = Mode::BINARY;
  std::string bad = encoded_vti(e, ramp(24));
  const std::size_t text = bad.find("format=\"binary\">\n") + 17;
  bad[text + 5] = '*';
  expect_read_fails<Grid>(written("base64.vti", bad),
                          {"byte " + std::to_string(text + 5) + ": the base64 data of the DataArray 'velocity' hold '*'"});
  e.mode = Mode::APPENDED_BASE64;
  bad = encoded_vti(e, ramp(24));
  bad[bad.find("   _") + 12] = '!';
  expect_read_fails<Grid>(written("appended_base64.vti", bad), {"hold '!', which is not base64 here"});
}

// Found by fuzzing VTK's reader (../shared/findings): a zlib block size of 0 made VTK divide by
// zero (SIGFPE); mangled attributes made it allocate 9 GB.  Both are refused with a message.
TEST(ReadVTKXMLRefusals, FilesThatCrashVTKAreRefused)
{
  const std::string findings = std::string(FAS_SHARED_DATA_DIR) + "/../findings/";
  if (!std::filesystem::exists(findings + "VTK_XML_zero_block_size.vts"))
    GTEST_SKIP() << "the findings are not in " << findings;
  if (!codec_available(Codec::ZLIB))
    FAS_SKIP_WITHOUT_TOOL("no zlib in this build");
  expect_read_fails<Cells>(findings + "VTK_XML_zero_block_size.vts",
                           {"byte 849: the compressed DataArray 'velocity' announces 1 blocks of 0 bytes"});
  expect_read_fails<Cells>(findings + "VTK_XML_9GB_allocation.vts",
                           {"there is no 3-component point data array to read as the velocity"});
  // The same file with its velocity named: refused at its mangled points array, allocating nothing.
  expect_read_fails<Cells>(findings + "VTK_XML_9GB_allocation.vts", {"no point data array named 'velocity'"},
                           FAS::parameters::array_name("velocity"));
  // Files the fuzzer found against VTK 9.1, kept in the test data.
  expect_read_fails<Cells>(std::string(FAS_TEST_DATA_DIR) + "/vts_inline_lying_compression_header.vts",
                           {"the DataArray 'velocity' has format=\"appende0d\"; expected ascii, binary or appended"});
  expect_read_fails<Cells>(std::string(FAS_TEST_DATA_DIR) + "/vtu_appended_padding_in_compression_header.vtu",
                           {"there is no 3-component point data array"});
}

TEST(ReadVTKXMLRefusals, MissingAndUnfitArraysAreNamed)
{
  const std::string arrays = written("arrays.vti", hand_written_vti(ascii_array("Float32", "two", 2, repeated("1 2", 8)) +
                                                                    ascii_array("Float64", "pressure", 1, repeated("1", 8))));
  expect_read_fails<Grid>(arrays, {"no 3-component point data array", "'two' (Float32, 2 components)",
                                   "'pressure' (Float64, 1 component)"});
  expect_read_fails<Grid>(arrays, {"no point data array named 'velocity'", "'two'"},
                          FAS::parameters::array_name("velocity"));
  expect_read_fails<Cells>(arrays, {"'two' has 2 components", "3 numbers per point"}, FAS::parameters::array_name("two"));
  const std::string masks =
      written("masks.vti", hand_written_vti(velocity + ascii_array("Float32", "inside", 3, repeated("1 1 1", 8))));
  expect_read_fails<Grid>(masks, {"the mask array 'inside' has 3 components", "1 number per point"});
  expect_read_fails<Grid>(masks, {"no point data array named 'solid' for the mask", "'velocity'"},
                          FAS::parameters::mask_array_name("solid"));
  expect_read_fails<Grid>(written("short.vti", hand_written_vti(ascii_array("Float32", "velocity", 3, repeated("1.0 2.0 3.0", 7)))),
                          {"the data end after 21 of the 24 values of 'velocity'"});
  expect_read_fails<Grid>(written("word.vti", hand_written_vti(ascii_array("Float32", "velocity", 3, "1 2 x" + repeated(" 3", 21)))),
                          {"'x' is not a number (value 2 of the 24 values of 'velocity')"});
  const std::string strings =
      written("string.vti", hand_written_vti(ascii_array("String", "velocity", 3, repeated("1 2 3", 8))));
  expect_read_fails<Grid>(strings, {"no 3-component point data array", "'velocity' (String, 3 components)"});
  expect_read_fails<Grid>(strings, {"the DataArray 'velocity' holds String, not numbers"},
                          FAS::parameters::array_name("velocity"));
  expect_read_fails<Grid>(written("tuples.vti", hand_written_vti("<DataArray type=\"Float32\" Name=\"v\" "
                                                                 "NumberOfComponents=\"3\" NumberOfTuples=\"9\" format=\"ascii\">" +
                                                                 repeated("1 2 3", 8) + "</DataArray>")),
                          {"has NumberOfTuples=\"9\" but the data set has 8 points"});
  expect_read_fails<Grid>(written("components.vti", hand_written_vti("<DataArray type=\"Float32\" Name=\"v\" "
                                                                     "NumberOfComponents=\"1" + std::string(100, '0') +
                                                                     "\" format=\"ascii\">1</DataArray>")),
                          {"NumberOfComponents=\"1000", "is not a non-negative integer"});
}

TEST(ReadVTKXMLRefusals, NonFiniteVelocitiesAtFluidPointsAreNamed)
{
  std::vector<double> v = ramp(24);
  v[3 * 5 + 1] = std::numeric_limits<double>::quiet_NaN();
  Encoding e;
  const std::string nan = written("nan.vti", encoded_vti(e, v));
  expect_read_fails<Grid>(nan, {"at point 5 = (1, 0, 1), component 1", "nan", "finite"});
  expect_read_fails<Cells>(nan, {"at point 5 = (1, 0, 1), component 1"});
  // At a solid point: accepted by the grid; as cells, every cell touches it.
  const std::string masked = written(
      "nan_solid.vti", hand_written_vti(ascii_array("Float64", "velocity", 3, "0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 nan "
                                                                             "17 18 19 20 21 22 23") +
                                        ascii_array("UInt8", "inside", 1, "1 1 1 1 1 0 1 1")));
  Grid grid;
  std::string error;
  EXPECT_TRUE(FAS::IO::read_VTK_XML_flow_field(masked, grid, FAS::parameters::error_message(&error)))
      << error;
  expect_read_fails<Cells>(masked, {"every one of the 1 cells touches a solid point", "no fluid cell"});
}

TEST(ReadVTKXMLRefusals, RotatedFlatAndMultiPieceDataSetsAreRefused)
{
  const std::string rotated = written("rotated.vti", hand_written_vti(velocity, "Direction=\"0 -1 0 1 0 0 0 0 1\""));
  expect_read_fails<Grid>(rotated, {"Direction matrix (0 -1 0 1 0 0 0 0 1)", "not the identity", "not supported"});
  expect_read_fails<Cells>(rotated, {"not the identity"});
  const std::string flat = written(
      "flat.vti", hand_written_vti(ascii_array("Float32", "velocity", 3, repeated("1 2 3", 4)), "", "0 1 0 1 0 0"));
  expect_read_fails<Grid>(flat, {"2 x 2 x 1 points", "at least 2 points along each axis"});
  std::string outside = hand_written_vti(velocity);
  outside.replace(outside.find("WholeExtent=\"0 1"), 16, "WholeExtent=\"1 1");
  expect_read_fails<Grid>(written("outside.vti", outside),
                          {"the piece's Extent \"0 1 0 1 0 1\" reaches outside the WholeExtent \"1 1 0 1 0 1\""});
  // Found by fuzzing: a whole extent beyond any integer type is named as written.
  outside = hand_written_vti(velocity);
  outside.replace(outside.find("WholeExtent=\"0 1"), 16, "WholeExtent=\"5e120 6e120");
  expect_read_fails<Grid>(written("outside.vti", outside), {"reaches outside the WholeExtent \"5.0000000000000002e+120 6.0000000000000005e+120 0 1 0 1\""});
  std::string pieces = hand_written_vti(velocity);
  const std::size_t piece = pieces.find("<Piece"), end = pieces.find("</Piece>") + 9;
  pieces.insert(end, pieces.substr(piece, end - piece));
  expect_read_fails<Grid>(written("pieces.vti", pieces), {"the data set has 2 pieces; only structured files of one piece are read"});
}

std::string one_cell_vtu(const std::string& connectivity, const std::string& offsets, const std::string& types,
                         int cells = 1)
{
  return "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n<UnstructuredGrid><Piece NumberOfPoints=\"8\" "
         "NumberOfCells=\"" + std::to_string(cells) + "\">\n<PointData>" + velocity +
         "</PointData>\n<Points>" + ascii_array("Float32", "Points", 3, "0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1") +
         "</Points>\n<Cells>" + ascii_array("Int64", "connectivity", 1, connectivity) +
         ascii_array("Int64", "offsets", 1, offsets) + ascii_array("UInt8", "types", 1, types) +
         "</Cells>\n</Piece></UnstructuredGrid></VTKFile>\n";
}

TEST(ReadVTKXMLRefusals, BadCellsAreNamed)
{
  Cells field;
  std::string error;
  ASSERT_TRUE(
      FAS::IO::read_VTK_XML_flow_field(written("cell.vtu", one_cell_vtu("0 1 2 3 4 5 6 7", "8", "12")), field,
                                       FAS::parameters::error_message(&error)))
      << error;
  expect_read_fails<Cells>(written("triangle.vtu", one_cell_vtu("0 1 2 3 4 5 6 7 0 1 2", "8 11", "12 5", 2)),
                           {"gives cell 1 the VTK cell type 5 (VTK_TRIANGLE); supported are 10 (VTK_TETRA)"});
  expect_read_fails<Cells>(written("voxel.vtu", one_cell_vtu("0 1 3 2 4", "5", "11")),
                           {"gives cell 0 (VTK_VOXEL) 5 points; expected 8"});
  expect_read_fails<Cells>(written("index.vtu", one_cell_vtu("0 1 2 3 4 5 6 8", "8", "12")),
                           {"holds the point index 8 at 7; expected an index in [0, 8)"});
  expect_read_fails<Cells>(written("no_types.vtu", one_cell_vtu("0 1 2 3 4 5 6 7", "8", "12").replace(
                                                       one_cell_vtu("0 1 2 3 4 5 6 7", "8", "12").find("\"types\""), 7,
                                                       "\"kinds\"")),
                           {"there is no DataArray named 'types'"});
}

// A .pvd of the given (time, file) pairs.
std::string pvd(const std::vector<std::pair<std::string, std::string>>& steps)
{
  std::string r = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& s : steps)
    r += "    <DataSet timestep=\"" + s.first + "\" group=\"\" part=\"0\" file=\"" + s.second + "\"/>\n";
  return r + "  </Collection>\n</VTKFile>\n";
}

// read_PVD_flow_field fails with all `parts` and leaves the output as it was (empty or not).
void expect_PVD_fails(const std::string& file, const std::vector<std::string>& parts)
{
  std::string error;
  FAS::Unsteady_flow_field_3<Grid> series;
  ::testing::internal::CaptureStderr();
  const bool ok = FAS::IO::read_PVD_flow_field(file, series, FAS::parameters::error_message(&error));
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "printed while reading " << file;
  EXPECT_FALSE(ok) << file;
  EXPECT_EQ(series.number_of_steps(), 0u); // untouched
  EXPECT_NE(error.find("read_PVD_flow_field: " + file + ": "), std::string::npos) << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "message \"" << error << "\" lacks \"" << part << "\"";
  FAS::Unsteady_flow_field_3<Grid> kept({1.}, {sentinel_grid()});
  EXPECT_FALSE(FAS::IO::read_PVD_flow_field(file, kept));
  ASSERT_EQ(kept.number_of_steps(), 1u);
  EXPECT_EQ(kept.time(0), 1.);
  expect_sentinel(kept.step(0));
}

TEST(ReadVTKXMLRefusals, BadCollectionsGiveClearMessagesAndChangeNothing)
{
  const std::filesystem::path folder = temporary("bad_series");
  std::filesystem::create_directories(folder);
  const std::string step = (folder / "step.vti").string();
  write_bytes(step, hand_written_vti(velocity));
  auto file = [&](const std::string& name, const std::string& contents) {
    const std::string f = (folder / name).string();
    write_bytes(f, contents);
    return f;
  };
  expect_PVD_fails((folder / "none.pvd").string(), {"no such file"});
  expect_PVD_fails(file("broken.pvd", "<VTKFile type=\"Collection\"><Collection><DataSet"),
                   {"the start tag of <DataSet> does not end (truncated file?)"});
  expect_PVD_fails(file("other.pvd", hand_written_vti("")), {"root element is <VTKFile type=\"ImageData\">"});
  expect_PVD_fails(file("empty.pvd", pvd({})), {"no DataSet element"});
  expect_PVD_fails(file("no_time.pvd", "<VTKFile type=\"Collection\"><Collection><DataSet file=\"step.vti\"/>"
                                       "</Collection></VTKFile>"),
                   {"DataSet element 0: no timestep attribute"});
  expect_PVD_fails(file("bad_time.pvd", pvd({{"0", "step.vti"}, {"soon", "step.vti"}})),
                   {"DataSet element 1", "the timestep 'soon' is not a finite number"});
  expect_PVD_fails(file("repeated.pvd", pvd({{"0", "step.vti"}, {"1", "step.vti"}, {"1.0", "missing.vti"}})),
                   {"same timestep 1", "missing.vti", "step.vti"});
  expect_PVD_fails(file("missing.pvd", pvd({{"0", "step.vti"}, {"0.5", "missing.vti"}, {"1", "step.vti"}})),
                   {"step 1 (timestep 0.5, file " + (folder / "missing.vti").string() + ")", "no such file"});
  file("cells.vtu", one_cell_vtu("0 1 2 3 4 5 6 7", "8", "12"));
  expect_PVD_fails(file("kind.pvd", pvd({{"0", "step.vti"}, {"2", "cells.vtu"}})), {"step 1 (timestep 2", "UnstructuredGrid"});
}

} // namespace

} // namespace test_read_VTK_XML_refusals
