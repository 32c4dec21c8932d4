// The VTK XML reader without VTK, on files the test writes itself (vtk_xml_test_files.h) in
// every encoding VTK writes: each encoding of the same data set gives exactly the same field,
// holding the values that the test put in (a field linear in space, exact in float at the
// points, and integer fields for the integer types); every kind of data set (.vti, .vtr,
// .vts, .vtu) gives that field; and a .pvd of such files gives the field linear in time too.

#include <gtest/gtest.h>

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "test_files.h"
#include "vtk_xml_test_files.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_VTK_XML_encodings {

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
  return temporary_file("fas_read_VTK_XML_encodings_", name);
}

// v(p, t) = A p + t b + c with integer coefficients: exact in float at the points below
// (multiples of 1/4), so that a reader decoding and interpolating correctly gives it exactly.
Vector exact(const Point& p, double t = 0.)
{
  return Vector(2. * p.x() - p.y() + 3. * p.z() + 4. * t + 1., p.x() + 5. * p.y() - 2. * t - 3.,
                -p.x() + 2. * p.z() + t + 7.);
}

// The test's grid: 4 x 3 x 5 points, the extent starting at (1, 0, 2).
const std::array<int, 6> extent = {{1, 4, 0, 2, 2, 6}};
const std::array<double, 3> origin = {{0.5, -1., 2.}}, spacing = {{0.5, 1., 0.25}};
constexpr std::size_t nx = 4, ny = 3, nz = 5, nodes = nx * ny * nz;

Point node(std::size_t n)
{
  const std::size_t i = n % nx, j = (n / nx) % ny, k = n / (nx * ny);
  return Point(origin[0] + (extent[0] + double(i)) * spacing[0], origin[1] + (extent[2] + double(j)) * spacing[1],
               origin[2] + (extent[4] + double(k)) * spacing[2]);
}

Array velocity(const std::string& type = "Float32", double t = 0.)
{
  Array a{"velocity", type, 3, {}};
  for (std::size_t n = 0; n < nodes; ++n) {
    const Vector v = exact(node(n), t);
    a.values.insert(a.values.end(), {v.x(), v.y(), v.z()});
  }
  return a;
}

// An integer field for the integer types: v(i, j, k) = (i + 2j, j - k, 3k - i), within Int8.
Array integer_velocity(const std::string& type)
{
  Array a{"velocity", type, 3, {}};
  const bool is_unsigned = type[0] == 'U';
  for (std::size_t n = 0; n < nodes; ++n) {
    const double i = double(n % nx), j = double((n / nx) % ny), k = double(n / (nx * ny));
    const double shift = is_unsigned ? 4. : 0.; // unsigned types get non-negative values
    a.values.insert(a.values.end(), {i + 2 * j, j - k + shift, 3 * k - i + shift});
  }
  return a;
}

// The mask: nodes 7 and 33 solid.
Array mask(const std::string& type = "UInt8")
{
  Array a{"inside", type, 1, std::vector<double>(nodes, 1.)};
  a.values[7] = a.values[33] = 0.;
  return a;
}

std::string extent_text()
{
  std::string r;
  for (int i = 0; i < 6; ++i)
    r += (i ? " " : "") + std::to_string(extent[std::size_t(i)]);
  return r;
}

std::string point_data(Writer& w, const Array& v, const Array* m, const std::string& extra_array = "")
{
  return "<PointData Vectors=\"velocity\">\n" + extra_array + w.data_array(v) + (m ? w.data_array(*m) : "") +
         "</PointData>\n<CellData>\n</CellData>\n";
}

std::string image_file(const Encoding& e, const Array& v, const Array* m = nullptr)
{
  Writer w(e);
  const Array pressure{"pressure", "Float64", 1, std::vector<double>(nodes, 2.5)};
  std::string body = "<ImageData WholeExtent=\"" + extent_text() + "\" Origin=\"0.5 -1 2\" Spacing=\"0.5 1 0.25\" "
                     "Direction=\"1 0 0 0 1 0 0 0 1\">\n<Piece Extent=\"" + extent_text() + "\">\n";
  body += point_data(w, v, m, w.data_array(pressure)) + "</Piece>\n</ImageData>\n";
  return w.file("ImageData", body);
}

std::vector<Array> axes()
{
  std::vector<Array> r;
  for (int a = 0; a < 3; ++a) {
    Array c{std::string(1, char('x' + a)), a == 1 ? "Float32" : "Float64", 1, {}};
    const std::size_t n[3] = {nx, ny, nz};
    for (std::size_t i = 0; i < n[a]; ++i)
      c.values.push_back(origin[std::size_t(a)] + (extent[std::size_t(2 * a)] + double(i)) * spacing[std::size_t(a)]);
    r.push_back(c);
  }
  return r;
}

std::string rectilinear_file(const Encoding& e, const Array& v, const Array* m = nullptr)
{
  Writer w(e);
  std::string body = "<RectilinearGrid WholeExtent=\"" + extent_text() + "\">\n<Piece Extent=\"" + extent_text() +
                     "\">\n" + point_data(w, v, m) + "<Coordinates>\n";
  for (const Array& c : axes())
    body += w.data_array(c);
  return w.file("RectilinearGrid", body + "</Coordinates>\n</Piece>\n</RectilinearGrid>\n");
}

Array points(const std::string& type)
{
  Array p{"Points", type, 3, {}};
  for (std::size_t n = 0; n < nodes; ++n)
    p.values.insert(p.values.end(), {node(n).x(), node(n).y(), node(n).z()});
  return p;
}

std::string structured_file(const Encoding& e, const Array& v, const Array* m = nullptr)
{
  Writer w(e);
  std::string body = "<StructuredGrid WholeExtent=\"" + extent_text() + "\">\n<Piece Extent=\"" + extent_text() +
                     "\">\n" + point_data(w, v, m) + "<Points>\n" + w.data_array(points("Float32")) + "</Points>\n";
  return w.file("StructuredGrid", body + "</Piece>\n</StructuredGrid>\n");
}

// The grid's hexahedra as a piece of an unstructured grid: even cells as VTK_HEXAHEDRON, odd
// ones as VTK_VOXEL (points in x, y, z order), Int64 connectivity and offsets, as VTK 9 writes
// them; the points moved by `shift`.
std::string unstructured_piece(Writer& w, const Array& v, const Array* m, const Vector& shift = Vector(0, 0, 0))
{
  Array connectivity{"connectivity", "Int64", 1, {}}, offsets{"offsets", "Int64", 1, {}}, types{"types", "UInt8", 1, {}};
  auto id = [](std::size_t i, std::size_t j, std::size_t k) { return double(i + nx * (j + ny * k)); };
  for (std::size_t k = 0; k + 1 < nz; ++k)
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        const bool voxel = types.values.size() % 2 == 1;
        for (std::size_t dk = 0; dk < 2; ++dk) {
          connectivity.values.insert(connectivity.values.end(), {id(i, j, k + dk), id(i + 1, j, k + dk)});
          if (voxel)
            connectivity.values.insert(connectivity.values.end(), {id(i, j + 1, k + dk), id(i + 1, j + 1, k + dk)});
          else
            connectivity.values.insert(connectivity.values.end(), {id(i + 1, j + 1, k + dk), id(i, j + 1, k + dk)});
        }
        offsets.values.push_back(double(connectivity.values.size()));
        types.values.push_back(voxel ? 11. : 12.);
      }
  Array p = points("Float64");
  for (std::size_t i = 0; i < p.values.size(); ++i)
    p.values[i] += shift[int(i % 3)];
  return "<Piece NumberOfPoints=\"" + std::to_string(nodes) + "\" NumberOfCells=\"" +
         std::to_string(types.values.size()) + "\">\n" + point_data(w, v, m) + "<Points>\n" + w.data_array(p) +
         "</Points>\n<Cells>\n" + w.data_array(connectivity) + w.data_array(offsets) + w.data_array(types) +
         "</Cells>\n</Piece>\n";
}

std::string unstructured_file(const Encoding& e, const Array& v, const Array* m = nullptr)
{
  Writer w(e);
  return w.file("UnstructuredGrid", "<UnstructuredGrid>\n" + unstructured_piece(w, v, m) + "</UnstructuredGrid>\n");
}

// Every encoding VTK writes whose compressor this build has.
std::vector<Encoding> every_encoding()
{
  std::vector<Encoding> r;
  for (Mode mode : {Mode::ASCII, Mode::BINARY, Mode::APPENDED_RAW, Mode::APPENDED_BASE64})
    for (bool wide : {false, true})
      for (bool big : {false, true})
        for (Codec codec : {Codec::NONE, Codec::ZLIB, Codec::LZ4, Codec::LZMA}) {
          if (!codec_available(codec) || (mode == Mode::ASCII && (wide || big || codec != Codec::NONE)))
            continue;
          Encoding e;
          e.mode = mode;
          e.wide_header = wide;
          e.big_endian = big;
          e.codec = codec;
          r.push_back(e);
        }
  return r;
}

// The encodings of the sweeps over data-set kinds and pieces: every one, or under the sanitizers
// (FAS_TEST_SANITIZED, at -O0) a sample in which every pair of values of two of the encoding's
// properties (mode, header width, byte order, compressor) that some encoding has still occurs:
// 13 of the 49 of a build with every compressor, picked greedily (the encoding with the most
// pairs not yet taken, the first one on ties).  EveryEncodingOfAnImageGivesTheValuesWritten
// keeps all of them in both builds.
std::vector<Encoding> swept_encodings()
{
  std::vector<Encoding> all = every_encoding();
#ifndef FAS_TEST_SANITIZED
  return all;
#else
  using Pair = std::array<int, 4>; // property i, property j, value of i, value of j
  auto pairs = [](const Encoding& e) {
    const int values[4] = {int(e.mode), int(e.wide_header), int(e.big_endian), int(e.codec)};
    std::set<Pair> r;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        r.insert(Pair{{i, j, values[i], values[j]}});
    return r;
  };
  std::set<Pair> wanted, taken;
  for (const Encoding& e : all)
    for (const Pair& p : pairs(e))
      wanted.insert(p);
  std::vector<Encoding> sample;
  while (taken != wanted) {
    std::size_t best = 0, best_new = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      std::size_t n = 0;
      for (const Pair& p : pairs(all[i]))
        n += taken.count(p) == 0 ? 1 : 0;
      if (n > best_new) {
        best = i;
        best_new = n;
      }
    }
    for (const Pair& p : pairs(all[best]))
      taken.insert(p);
    sample.push_back(all[best]);
  }
  return sample;
#endif
}

template <class Field>
Field read_or_fail(const std::string& file, const std::string& what)
{
  Field f;
  std::string error;
  EXPECT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, f, FAS::parameters::error_message(&error)))
      << what << ": " << error;
  return f;
}

std::vector<float> expected_values(const Array& v)
{
  return std::vector<float>(v.values.begin(), v.values.end());
}

TEST(ReadVTKXMLEncodings, EveryEncodingOfAnImageGivesTheValuesWritten)
{
  const std::vector<Encoding> encodings = every_encoding();
  std::cout << encodings.size() << " encodings of a .vti (compressors in this build: none"
            << (codec_available(Codec::ZLIB) ? ", zlib" : "") << (codec_available(Codec::LZ4) ? ", LZ4" : "")
            << (codec_available(Codec::LZMA) ? ", LZMA" : "") << ")\n";
  EXPECT_GE(encodings.size(), 13u);
  const Array v = velocity(), m = mask();
  for (const Encoding& e : encodings) {
    const std::string file = temporary("image.vti");
    write_bytes(file, image_file(e, v, &m));
    const Grid g = read_or_fail<Grid>(file, e.describe());
    ASSERT_EQ(g.dimensions(), (Grid::Dimensions{{nx, ny, nz}})) << e.describe();
    EXPECT_EQ(g.origin(), node(0)) << e.describe();
    EXPECT_EQ(g.spacing(), Vector(0.5, 1., 0.25)) << e.describe();
    EXPECT_EQ(g.values(), expected_values(v)) << e.describe();
    EXPECT_EQ(g.mask(), std::vector<unsigned char>(m.values.begin(), m.values.end())) << e.describe();
  }
}

TEST(ReadVTKXMLEncodings, EveryNumberTypeIsDecoded)
{
  const std::vector<std::string> types = {"Int8",  "UInt8",  "Int16", "UInt16",  "Int32",
                                          "UInt32", "Int64", "UInt64", "Float32", "Float64"};
  Encoding binary;
  binary.mode = Mode::BINARY;
  Encoding raw_big;
  raw_big.mode = Mode::APPENDED_RAW;
  raw_big.big_endian = true;
  raw_big.wide_header = true;
  raw_big.codec = codec_available(Codec::ZLIB) ? Codec::ZLIB : Codec::NONE;
  for (const std::string& type : types)
    for (const Encoding& e : {binary, raw_big}) {
      const Array v = integer_velocity(type), m = mask(type);
      const std::string file = temporary("typed.vti");
      write_bytes(file, image_file(e, v, &m));
      const Grid g = read_or_fail<Grid>(file, type + ", " + e.describe());
      EXPECT_EQ(g.values(), expected_values(v)) << type << ", " << e.describe();
      EXPECT_EQ(g.mask(), std::vector<unsigned char>(m.values.begin(), m.values.end())) << type;
    }
}

// The linear field at random points of the grid's box, through any field type.
template <class Field>
void expect_linear_field(const Field& f, const std::string& what)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0., 1.);
  const Point lo = node(0), hi = node(nodes - 1);
  for (int q = 0; q < 50; ++q) {
    const Point p(lo.x() + (hi.x() - lo.x()) * u(rng), lo.y() + (hi.y() - lo.y()) * u(rng),
                  lo.z() + (hi.z() - lo.z()) * u(rng));
    const std::optional<Vector> v = f(p);
    ASSERT_TRUE(v.has_value()) << what << " at " << p;
    const Vector d = *v - exact(p);
    EXPECT_LT(std::sqrt(d.squared_length()), 1e-9) << what << " at " << p;
  }
}

TEST(ReadVTKXMLEncodings, EveryKindOfDataSetGivesTheLinearField)
{
  const Array v = velocity("Float64");
  for (const Encoding& e : swept_encodings()) {
    const std::string what = e.describe();
    write_bytes(temporary("kind.vti"), image_file(e, v));
    write_bytes(temporary("kind.vtr"), rectilinear_file(e, v));
    write_bytes(temporary("kind.vts"), structured_file(e, v));
    write_bytes(temporary("kind.vtu"), unstructured_file(e, v));
    expect_linear_field(read_or_fail<Grid>(temporary("kind.vti"), ".vti, " + what), ".vti, " + what);
    expect_linear_field(read_or_fail<Rectilinear>(temporary("kind.vtr"), ".vtr, " + what), ".vtr, " + what);
    expect_linear_field(read_or_fail<Rectilinear>(temporary("kind.vti"), ".vti as rectilinear, " + what), what);
    for (const char* ext : {"vti", "vtr", "vts", "vtu"}) {
      const Cells c = read_or_fail<Cells>(temporary(std::string("kind.") + ext), std::string(ext) + ", " + what);
      ASSERT_EQ(c.number_of_cells(), (nx - 1) * (ny - 1) * (nz - 1)) << ext << ", " << what;
      EXPECT_EQ(c.cell_types(), std::vector<unsigned char>(c.number_of_cells(), 12)) << ext; // voxels as hexahedra
      expect_linear_field(c, std::string(ext) + " as cells, " + what);
    }
  }
}

// Several pieces of an unstructured grid (as a parallel run writes them) are concatenated: two
// copies of the grid, the second moved by 2 along x and holding the field at its points, and an
// empty piece between them.
TEST(ReadVTKXMLEncodings, PiecesOfAnUnstructuredGridAreConcatenated)
{
  const Vector shift(2, 0, 0);
  Array moved = velocity("Float64");
  for (std::size_t n = 0; n < nodes; ++n) {
    const Vector e = exact(node(n) + shift);
    for (int d = 0; d < 3; ++d)
      moved.values[3 * n + std::size_t(d)] = e[d];
  }
  for (const Encoding& e : swept_encodings()) {
    Writer w(e);
    const std::string file = temporary("pieces.vtu");
    write_bytes(file, w.file("UnstructuredGrid", "<UnstructuredGrid>\n" + unstructured_piece(w, velocity("Float64"), nullptr) +
                                                     "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"/>\n" +
                                                     unstructured_piece(w, moved, nullptr, shift) +
                                                     "</UnstructuredGrid>\n"));
    const Cells c = read_or_fail<Cells>(file, "2 pieces, " + e.describe());
    ASSERT_EQ(c.number_of_points(), 2 * nodes) << e.describe();
    ASSERT_EQ(c.number_of_cells(), 2 * (nx - 1) * (ny - 1) * (nz - 1)) << e.describe();
    expect_linear_field(c, "first piece, " + e.describe());
    for (const Point& p : {node(5) + shift, node(0) + shift + Vector(0.3, 0.4, 0.2), node(nodes - 1) + shift})
      EXPECT_LT(std::sqrt((*c(p) - exact(p)).squared_length()), 1e-9) << p << ", " << e.describe();
  }
  // A mask in one piece only is refused.
  Encoding e;
  Writer w(e);
  const Array m = mask();
  write_bytes(temporary("pieces_mask.vtu"),
              w.file("UnstructuredGrid", "<UnstructuredGrid>\n" + unstructured_piece(w, velocity(), &m) +
                                             unstructured_piece(w, moved, nullptr, shift) + "</UnstructuredGrid>\n"));
  Cells c;
  std::string error;
  EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(temporary("pieces_mask.vtu"), c,
                                                FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("this piece has no mask but the pieces before it have one"), std::string::npos) << error;
}

TEST(ReadVTKXMLEncodings, MaskedCellsAreLeftOut)
{
  Encoding e;
  e.mode = Mode::APPENDED_BASE64;
  const Array v = velocity(), m = mask();
  write_bytes(temporary("masked.vtu"), unstructured_file(e, v, &m));
  const Cells c = read_or_fail<Cells>(temporary("masked.vtu"), "masked .vtu");
  // Node 7 = (3, 1, 0) touches 2 cells, node 33 = (1, 2, 2) touches 4.
  EXPECT_EQ(c.number_of_cells(), 24u - 6u);
  std::string error;
  Cells all;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(
      temporary("masked.vtu"), all,
      FAS::parameters::error_message(&error, FAS::parameters::mask_array_name(std::string()))))
      << error;
  EXPECT_EQ(all.number_of_cells(), 24u);
}

TEST(ReadVTKXMLEncodings, TimeSeriesIsExactAtIntermediateTimes)
{
  const std::filesystem::path folder = temporary("series");
  std::filesystem::create_directories(folder / "steps");
  const std::vector<double> times = {0., 0.5, 2.};
  Encoding e;
  e.codec = codec_available(Codec::ZLIB) ? Codec::ZLIB : Codec::NONE;
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (int i : {2, 0, 1}) { // out of order, relative paths
    const std::string name = "steps/t" + std::to_string(i) + ".vti";
    write_bytes((folder / name).string(), image_file(e, velocity("Float32", times[std::size_t(i)])));
    pvd += "    <DataSet timestep=\"" + number_text(times[std::size_t(i)]) + "\" part=\"0\" file=\"" + name + "\"/>\n";
  }
  write_bytes((folder / "series.pvd").string(), pvd + "  </Collection>\n</VTKFile>\n");
  FAS::Unsteady_flow_field_3<Grid> series;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_PVD_flow_field((folder / "series.pvd").string(), series,
                                           FAS::parameters::error_message(&error)))
      << error;
  ASSERT_EQ(series.number_of_steps(), 3u);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0., 1.), time(0., 2.);
  for (int q = 0; q < 100; ++q) {
    const double t = time(rng);
    const Point lo = node(0), hi = node(nodes - 1);
    const Point p(lo.x() + (hi.x() - lo.x()) * u(rng), lo.y() + (hi.y() - lo.y()) * u(rng),
                  lo.z() + (hi.z() - lo.z()) * u(rng));
    const Vector d = *series(p, t) - exact(p, t);
    EXPECT_LT(std::sqrt(d.squared_length()), 1e-9) << p << ", t = " << t;
  }
}

} // namespace

} // namespace test_read_VTK_XML_encodings
