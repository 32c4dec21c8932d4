// read_flow_field(): a file of each supported format lands in the right alternative of
// Sampled_flow_field_3 and gives back the linear field it holds,
//   v(p) = (1 + x + 2y - z, -2 + x/2 - 3y + 2z, 1/2 - 2x + y + z/4),
// which every grid and cell type reproduces exactly; a file of no supported format, a missing
// file and a reader's failure give false with a message naming the file, and the field kept.

#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_session.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/Sampled_flow_field_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include "read_flow_field_test_helpers.h"
#include "real_data.h"
#include "test_files.h"
#include "vtk_xml_test_files.h"

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <random>
#include <sstream>
#include <string>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_flow_field {

namespace {

using namespace fas_read_flow_field_test;

std::string data_file(const std::string& name)
{
  return std::string(FAS_TEST_DATA_DIR) + "/" + name;
}

// The node values of linear_grid() as text, one node a line, x fastest.
std::string linear_grid_values_text()
{
  const Sampled::Regular_grid grid = linear_grid();
  std::ostringstream s;
  s.precision(9);
  for (std::size_t k = 0; k < 5; ++k)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t i = 0; i < 4; ++i) {
        const Vector v = grid.node_value(i, j, k);
        s << v.x() << " " << v.y() << " " << v.z() << "\n";
      }
  return s.str();
}

// What read_flow_field() fills: an empty uniform grid, undefined everywhere.
TEST(SampledFlowField3, DefaultConstructedFieldIsAnEmptyGrid)
{
  const Sampled field;
  ASSERT_NE(field.get_if<Sampled::Regular_grid>(), nullptr);
  EXPECT_EQ(field.get_if<Sampled::Regular_grid>()->number_of_nodes(), 0u);
  EXPECT_EQ(field.bbox(), CGAL::Bbox_3());
  EXPECT_FALSE(field(Point(0, 0, 0)).has_value());
}

TEST(ReadFlowField, LegacyVTKDatasetsGoToTheirFields)
{
  const std::string regular = scratch("structured_points.vtk");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTK_flow_field(regular, linear_grid(), FAS::parameters::error_message(&error)))
      << error;
  expect_reads_linear_field<Sampled::Regular_grid>(regular);
  expect_reads_linear_field<Sampled::Rectilinear_grid>(data_file("vtk_rectilinear_grid_ascii.vtk"));
  expect_reads_linear_field<Sampled::Unstructured_grid>(data_file("vtk_structured_grid_binary.vtk"));
  expect_reads_linear_field<Sampled::Unstructured_grid>(data_file("vtk_unstructured_4.2_binary.vtk"));
  expect_reads_linear_field<Sampled::Unstructured_grid>(data_file("vtk_unstructured_5.1_ascii.vtk"));
}

TEST(ReadFlowField, AmiraMeshAndNRRD)
{
  // BoundingBox: the first and last nodes of linear_grid().
  const std::string am = scratch("grid.am");
  write_bytes(am, "# AmiraMesh 3D ASCII 2.0\n\ndefine Lattice 4 3 5\n\nParameters {\n"
                  "    BoundingBox 0.25 1.75 -1 -0.5 0.5 3.5,\n    CoordType \"uniform\"\n}\n\n"
                  "Lattice { float[3] Data } @1\n\n# Data section follows\n@1\n" +
                      linear_grid_values_text());
  expect_reads_linear_field<Sampled::Regular_grid>(am);

  const std::string nrrd = scratch("grid.nrrd");
  write_bytes(nrrd, "NRRD0004\ntype: float\ndimension: 4\nsizes: 3 4 3 5\nencoding: ascii\n"
                    "space dimension: 3\nspace origin: (0.25,-1,0.5)\n"
                    "space directions: none (0.5,0,0) (0,0.25,0) (0,0,0.75)\n\n" +
                        linear_grid_values_text());
  expect_reads_linear_field<Sampled::Regular_grid>(nrrd);
}

// VTK XML files are read without the VTK library: a .vti into the uniform grid, a .vtr into the
// rectilinear grid, a .vts (the same grid's points) into cells.
TEST(ReadFlowField, VTKXMLFilesGoToTheirFields)
{
  const std::string vti = scratch("grid.vti");
  std::string error;
  const Sampled::Regular_grid grid = linear_grid();
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(vti, grid, FAS::parameters::error_message(&error))) << error;
  expect_reads_linear_field<Sampled::Regular_grid>(vti);

  vtk_xml_test::Encoding e;
  e.mode = vtk_xml_test::Mode::BINARY;
  const vtk_xml_test::Array velocity{"velocity", "Float32", 3,
                                     std::vector<double>(grid.values().begin(), grid.values().end())};
  const auto& n = grid.dimensions();
  const std::string extent = "0 " + std::to_string(n[0] - 1) + " 0 " + std::to_string(n[1] - 1) + " 0 " +
                             std::to_string(n[2] - 1);
  vtk_xml_test::Writer w(e);
  std::string body = "<RectilinearGrid WholeExtent=\"" + extent + "\"><Piece Extent=\"" + extent + "\">" +
                     "<PointData Vectors=\"velocity\">" + w.data_array(velocity) + "</PointData><Coordinates>";
  vtk_xml_test::Array points{"Points", "Float64", 3, {}};
  for (int a = 0; a < 3; ++a) {
    vtk_xml_test::Array axis{"axis", "Float64", 1, {}};
    for (std::size_t i = 0; i < n[std::size_t(a)]; ++i)
      axis.values.push_back(grid.origin()[a] + double(i) * grid.spacing()[a]);
    body += w.data_array(axis);
  }
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i) {
        const Point p = grid.node_point(i, j, k);
        points.values.insert(points.values.end(), {p.x(), p.y(), p.z()});
      }
  const std::string vtr = scratch("grid.vtr");
  write_bytes(vtr, w.file("RectilinearGrid", body + "</Coordinates></Piece></RectilinearGrid>"));
  expect_reads_linear_field<Sampled::Rectilinear_grid>(vtr);
  vtk_xml_test::Writer ws(e);
  const std::string vts = scratch("grid.vts");
  write_bytes(vts, ws.file("StructuredGrid", "<StructuredGrid WholeExtent=\"" + extent + "\"><Piece Extent=\"" +
                                                 extent + "\"><PointData>" + ws.data_array(velocity) +
                                                 "</PointData><Points>" + ws.data_array(points) +
                                                 "</Points></Piece></StructuredGrid>"));
  expect_reads_linear_field<Sampled::Unstructured_grid>(vts);
}

TEST(ReadFlowField, FailuresNameTheFileAndKeepTheField)
{
  Sampled field(linear_grid());
  const Point probe(0.5, -0.75, 1.);
  const Vector before = *field(probe);
  std::string error;

  const std::string text = scratch("notes.txt");
  write_bytes(text, "velocity, but as prose\n");
  EXPECT_FALSE(FAS::IO::read_flow_field(text, field, FAS::parameters::error_message(&error)));
  for (const char* part : {"notes.txt", "unknown file format", "velocity, but", "# vtk DataFile", "NRRD"})
    EXPECT_NE(error.find(part), std::string::npos) << "\"" << error << "\" lacks \"" << part << "\"";

  const std::string missing = scratch("no_such_file.vtk");
  EXPECT_FALSE(FAS::IO::read_flow_field(missing, field, FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("no_such_file.vtk"), std::string::npos) << error;
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;

  // A reader's own message comes through: here the legacy reader's, about a missing array.
  EXPECT_FALSE(FAS::IO::read_flow_field(
      data_file("vtk_unstructured_4.2_ascii.vtk"), field,
      FAS::parameters::error_message(&error, FAS::parameters::array_name(std::string("U")))));
  EXPECT_NE(error.find("'U'"), std::string::npos) << error;
  EXPECT_NE(error.find("vtk_unstructured_4.2_ascii.vtk"), std::string::npos) << error;

  ASSERT_NE(field.get_if<Sampled::Regular_grid>(), nullptr);
  EXPECT_EQ(*field(probe), before);
}

// An empty file is called empty by every reader, and every reader gives its message without
// naming the default named parameters first (the overloads taking the error pointer third).
TEST(ReadFlowField, EmptyFileIsCalledEmptyByEveryReader)
{
  const std::string empty = scratch("empty.vtk");
  write_bytes(empty, "");
  auto expect_empty = [&empty](bool read, const std::string& error, const std::string& reader) {
    EXPECT_FALSE(read) << reader;
    EXPECT_EQ(error, reader + ": " + empty + ": the file is empty (0 bytes)");
  };
  std::string error;
  Sampled sampled(linear_grid());
  expect_empty(FAS::IO::read_flow_field(empty, sampled, FAS::parameters::error_message(&error)), error,
               "read_flow_field");
  EXPECT_NE(sampled.get_if<Sampled::Regular_grid>(), nullptr) << "the field is kept";
  Sampled::Regular_grid regular;
  expect_empty(FAS::IO::read_VTK_flow_field(empty, regular, FAS::parameters::error_message(&error)), error,
               "read_VTK_flow_field");
  Sampled::Rectilinear_grid rectilinear;
  expect_empty(FAS::IO::read_VTK_flow_field(empty, rectilinear, FAS::parameters::error_message(&error)),
               error, "read_VTK_flow_field");
  Sampled::Unstructured_grid cells;
  expect_empty(FAS::IO::read_VTK_flow_field(empty, cells, FAS::parameters::error_message(&error)), error,
               "read_VTK_flow_field");
  expect_empty(FAS::IO::read_AmiraMesh_flow_field(empty, regular, FAS::parameters::error_message(&error)),
               error, "read_AmiraMesh_flow_field");
  expect_empty(FAS::IO::read_NRRD_flow_field(empty, regular, FAS::parameters::error_message(&error)), error,
               "read_NRRD_flow_field");
  FAS::Session session;
  expect_empty(FAS::IO::read_session(empty, session, &error), error, "read_session");
}

// A directory opens as a stream that reads nothing: every reader calls it a directory, not an
// empty file, and the field is kept.
TEST(ReadFlowField, DirectoryIsCalledADirectoryByEveryReader)
{
  const std::string folder = scratch("a_folder.vtk");
  std::filesystem::create_directories(folder);
  auto expect_directory = [&folder](bool read, const std::string& error, const std::string& reader) {
    EXPECT_FALSE(read) << reader;
    EXPECT_EQ(error, reader + ": " + folder + ": is a directory, not a file");
  };
  std::string error;
  Sampled sampled(linear_grid());
  expect_directory(FAS::IO::read_flow_field(folder, sampled, FAS::parameters::error_message(&error)), error,
                   "read_flow_field");
  EXPECT_NE(sampled.get_if<Sampled::Regular_grid>(), nullptr) << "the field is kept";
  Sampled::Regular_grid regular;
  expect_directory(FAS::IO::read_VTK_flow_field(folder, regular, FAS::parameters::error_message(&error)),
                   error, "read_VTK_flow_field");
  Sampled::Unstructured_grid cells;
  expect_directory(FAS::IO::read_VTK_flow_field(folder, cells, FAS::parameters::error_message(&error)), error,
                   "read_VTK_flow_field");
  expect_directory(
      FAS::IO::read_AmiraMesh_flow_field(folder, regular, FAS::parameters::error_message(&error)), error,
      "read_AmiraMesh_flow_field");
  expect_directory(FAS::IO::read_NRRD_flow_field(folder, regular, FAS::parameters::error_message(&error)),
                   error, "read_NRRD_flow_field");
  std::filesystem::remove(folder);
}

TEST(ReadFlowField, RealDataInBothForms)
{
  const std::string cells = shared_data_file("CAVITY_cells.vtk"), grid = shared_data_file("CAVITY_grid.vtk");
  if (cells.empty() || grid.empty())
    GTEST_SKIP() << "../shared/data/CAVITY_{cells,grid}.vtk not found: the real-data check is not run";
  Sampled from_cells, from_grid;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_flow_field(cells, from_cells, FAS::parameters::error_message(&error))) << error;
  ASSERT_TRUE(FAS::IO::read_flow_field(grid, from_grid, FAS::parameters::error_message(&error))) << error;
  EXPECT_NE(from_cells.get_if<Sampled::Unstructured_grid>(), nullptr);
  EXPECT_NE(from_grid.get_if<Sampled::Regular_grid>(), nullptr);
  // At the grid's nodes the two forms agree to the float rounding of the resampled grid (see
  // test_read_VTK_legacy_datasets.cpp for the whole comparison).
  const Sampled::Regular_grid& g = *from_grid.get_if<Sampled::Regular_grid>();
  for (std::size_t n : {std::size_t(8), std::size_t(32), std::size_t(56)}) {
    const Point p = g.node_point(n, n, n);
    const std::optional<Vector> a = from_cells(p), b = from_grid(p);
    ASSERT_TRUE(a && b) << p;
    EXPECT_LT(std::sqrt((*a - *b).squared_length()), 2e-7) << p;
  }
}

} // namespace

} // namespace test_read_flow_field
