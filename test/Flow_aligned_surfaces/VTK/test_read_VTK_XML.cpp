// The VTK XML readers and the .vti writer, with VTK as the peer: .vtu files of tetrahedra,
// hexahedra, wedges and pyramids and curvilinear .vts files written by VTK's own writers with
// a field linear in space (whose values at the points are exact in float) read back to that
// field exactly at random points; .vti files written by write_VTI_flow_field() are read by
// VTK's vtkXMLImageDataReader with the same values, origin, spacing and extent; a .pvd of 3 steps
// of a field linear in space and time gives that field exactly at intermediate times; and every
// kind of bad input gives `false` with a message naming the file and the fault, prints nothing,
// and leaves the output untouched.

#include <gtest/gtest.h>

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "../test_files.h"

#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#ifdef FAS_HAVE_VTK_IO_LEGACY
#include <vtkStructuredPoints.h>
#include <vtkStructuredPointsReader.h>
#include <vtkUnstructuredGridReader.h>
#endif

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_VTK_XML {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;
using Grid = FAS::Regular_grid_flow_field_3<K>;
using Cells = FAS::Unstructured_flow_field_3<K>;

std::string temporary(const std::string& name)
{
  return temporary_file("fas_read_VTK_XML_", name);
}

// v(p, t) = A p + t b + c with integer coefficients: exact in float at half-integer points and
// times, so a reader that interpolates correctly gives it to double rounding.
Vector exact(const Point& p, double t = 0.)
{
  return Vector(2. * p.x() - p.y() + 3. * p.z() + 4. * t + 1., p.x() + 5. * p.y() - 2. * t - 3.,
                -p.x() + 2. * p.z() + t + 7.);
}

void expect_near(const Vector& a, const Vector& b, double tolerance, const std::string& where)
{
  EXPECT_NEAR(a.x(), b.x(), tolerance) << where;
  EXPECT_NEAR(a.y(), b.y(), tolerance) << where;
  EXPECT_NEAR(a.z(), b.z(), tolerance) << where;
}

// The point data array "velocity" holding exact() at the points of `ds`, as VTK's double array.
void add_velocity(vtkDataSet* ds, double t = 0., const char* name = "velocity", bool active = true)
{
  vtkNew<vtkDoubleArray> v;
  v->SetName(name);
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(ds->GetNumberOfPoints());
  for (vtkIdType i = 0; i < ds->GetNumberOfPoints(); ++i) {
    double x[3];
    ds->GetPoint(i, x);
    const Vector e = exact(Point(x[0], x[1], x[2]), t);
    const double tuple[3] = {e.x(), e.y(), e.z()};
    v->SetTuple(i, tuple);
  }
  if (active)
    ds->GetPointData()->SetVectors(v);
  else
    ds->GetPointData()->AddArray(v);
}

void add_scalars(vtkDataSet* ds, const char* name, int components, double value)
{
  vtkNew<vtkFloatArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(ds->GetNumberOfPoints());
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
    a->SetValue(i, static_cast<float>(value));
  ds->GetPointData()->AddArray(a);
}

// A mesh of one cell of each kind, touching along faces (some conforming, some not):
// a unit hexahedron, a wedge beside it, a pyramid on top of it, a tetrahedron on top of the
// wedge and one against the hexahedron's x = 0 face.
struct Mixed_mesh {
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  std::vector<std::vector<vtkIdType>> cells;
};

Mixed_mesh mixed_mesh()
{
  const double p[][3] = {{0, 0, 0},      {1, 0, 0},      {1, 1, 0}, {0, 1, 0}, {0, 0, 1},
                         {1, 0, 1},      {1, 1, 1},      {0, 1, 1}, {2, 0, 0}, {2, 0, 1},
                         {0.5, 0.5, 2.}, {1.5, 0.5, 2.}, {-1, 0, 0}};
  Mixed_mesh m;
  m.grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (const auto& x : p)
    points->InsertNextPoint(x);
  m.grid->SetPoints(points);
  const std::vector<std::pair<int, std::vector<vtkIdType>>> cells = {
      {VTK_HEXAHEDRON, {0, 1, 2, 3, 4, 5, 6, 7}},
      {VTK_WEDGE, {1, 8, 2, 5, 9, 6}},
      {VTK_PYRAMID, {4, 5, 6, 7, 10}},
      {VTK_TETRA, {5, 9, 6, 11}},
      {VTK_TETRA, {0, 3, 4, 12}}};
  m.grid->Allocate(static_cast<vtkIdType>(cells.size()));
  for (const auto& c : cells) {
    m.grid->InsertNextCell(c.first, static_cast<vtkIdType>(c.second.size()), c.second.data());
    m.cells.push_back(c.second);
  }
  add_velocity(m.grid);
  return m;
}

// `mode`: "appended" (VTK's default, compressed), "ascii", or "binary" (inline, compressed).
template <class Writer>
void write_with_VTK(vtkDataObject* data, const std::string& filename, const std::string& mode = "appended")
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(filename.c_str());
  if (mode == "ascii")
    writer->SetDataModeToAscii();
  else if (mode == "binary")
    writer->SetDataModeToBinary();
  ASSERT_EQ(writer->Write(), 1) << filename;
}

// A random point in the convex hull of the given points of `ds`: inside a convex cell.
Point random_point_in(vtkDataSet* ds, const std::vector<vtkIdType>& ids, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0.05, 1.);
  std::vector<double> w(ids.size());
  double sum = 0;
  for (double& x : w)
    sum += (x = u(rng));
  double r[3] = {0, 0, 0};
  for (std::size_t i = 0; i < ids.size(); ++i) {
    double x[3];
    ds->GetPoint(ids[i], x);
    for (int a = 0; a < 3; ++a)
      r[a] += w[i] / sum * x[a];
  }
  return Point(r[0], r[1], r[2]);
}

TEST(ReadVTKXML, UnstructuredGridOfEveryCellKindGivesTheLinearFieldExactly)
{
  const Mixed_mesh m = mixed_mesh();
  for (const std::string mode : {"appended", "ascii", "binary"}) {
    const std::string file = temporary("mixed_" + mode + ".vtu");
    write_with_VTK<vtkXMLUnstructuredGridWriter>(m.grid, file, mode);
    if (mode == "binary") { // inline base64 with compression headers, checked before VTK reads
      ASSERT_NE(read_bytes(file).find("format=\"binary\""), std::string::npos);
    }
    Cells field(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 2, 3}, {0, 4}, {10},
                std::vector<float>(12, 0.f));
    std::string error;
    ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, CGAL::parameters::default_values(), &error))
        << error;
    EXPECT_EQ(field.number_of_points(), 13u);
    ASSERT_EQ(field.number_of_cells(), 5u);
    EXPECT_EQ(field.cell_types(), (std::vector<unsigned char>{12, 13, 14, 10, 10}));
    std::mt19937 rng(11);
    for (std::size_t c = 0; c < m.cells.size(); ++c)
      for (int q = 0; q < 40; ++q) {
        const Point p = random_point_in(m.grid, m.cells[c], rng);
        const std::optional<Vector> v = field(p);
        ASSERT_TRUE(v.has_value()) << "cell " << c << " at " << p;
        expect_near(*v, exact(p), 1e-9, "cell " + std::to_string(c));
      }
    EXPECT_FALSE(field(Point(3, 3, 3)));
  }
}

TEST(ReadVTKXML, VoxelsAreReadAsHexahedra)
{
  // The unit hexahedron of the mixed mesh as a VTK_VOXEL (points in x, y, z order), as
  // vtkThreshold makes of image cells, beside a tetrahedron: the voxel is read as the
  // hexahedron 0 ... 7 (type 12) and gives the linear field exactly.
  const Mixed_mesh m = mixed_mesh();
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(m.grid->GetPoints());
  grid->GetPointData()->ShallowCopy(m.grid->GetPointData());
  const vtkIdType voxel[8] = {0, 1, 3, 2, 4, 5, 7, 6}, tetrahedron[4] = {0, 3, 4, 12};
  grid->Allocate(2);
  grid->InsertNextCell(VTK_VOXEL, 8, voxel);
  grid->InsertNextCell(VTK_TETRA, 4, tetrahedron);
  const std::string file = temporary("voxel.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(grid, file);
  Cells field(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 2, 3}, {0, 4}, {10},
              std::vector<float>(12, 0.f));
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_EQ(field.cell_types(), (std::vector<unsigned char>{12, 10}));
  EXPECT_EQ(field.connectivity(), (std::vector<Cells::Index>{0, 1, 2, 3, 4, 5, 6, 7, 0, 3, 4, 12}));
  std::mt19937 rng(12);
  for (const std::vector<vtkIdType>& cell : {m.cells[0], m.cells[4]})
    for (int q = 0; q < 40; ++q) {
      const Point p = random_point_in(grid, cell, rng);
      const std::optional<Vector> v = field(p);
      ASSERT_TRUE(v.has_value()) << p;
      expect_near(*v, exact(p), 1e-9, "voxel mesh");
    }
}

TEST(ReadVTKXML, UnstructuredMaskRemovesTheCellsTouchingSolidPoints)
{
  Mixed_mesh m = mixed_mesh();
  vtkNew<vtkUnsignedCharArray> inside;
  inside->SetName("inside");
  inside->SetNumberOfTuples(13);
  inside->Fill(1);
  inside->SetValue(12, 0); // only the last tetrahedron touches point 12
  m.grid->GetPointData()->AddArray(inside);
  const std::string file = temporary("masked.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(m.grid, file);
  Cells field;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, CGAL::parameters::default_values(), &error))
      << error;
  ASSERT_EQ(field.number_of_cells(), 4u);
  std::mt19937 rng(5);
  EXPECT_FALSE(field(random_point_in(m.grid, {0, 3, 4, 12}, rng)).has_value());
  const Point p = random_point_in(m.grid, m.cells[1], rng);
  expect_near(*field(p), exact(p), 1e-9, "wedge");

  // No mask when asked for none.
  ASSERT_TRUE(
      FAS::IO::read_VTK_XML_flow_field(file, field, FAS::parameters::mask_array_name(std::string()), &error))
      << error;
  EXPECT_EQ(field.number_of_cells(), 5u);
}

TEST(ReadVTKXML, CurvilinearStructuredGridGivesTheLinearFieldExactly)
{
  // x = i + j/2, y = j, z = k + i/4: a sheared grid of parallelepipeds, 4 x 3 x 5 points.
  const int n[3] = {4, 3, 5};
  auto position = [](double i, double j, double k) { return Point(i + 0.5 * j, j, k + 0.25 * i); };
  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(n[0], n[1], n[2]);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Point p = position(i, j, k);
        points->InsertNextPoint(p.x(), p.y(), p.z());
      }
  grid->SetPoints(points);
  add_velocity(grid);
  const std::string file = temporary("sheared.vts");
  write_with_VTK<vtkXMLStructuredGridWriter>(grid, file);

  Cells field;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_EQ(field.number_of_points(), 60u);
  EXPECT_EQ(field.number_of_cells(), 3u * 2u * 4u);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0., 1.);
  for (int q = 0; q < 200; ++q) {
    const Point p = position(3 * u(rng), 2 * u(rng), 4 * u(rng));
    const std::optional<Vector> v = field(p);
    ASSERT_TRUE(v.has_value()) << p;
    expect_near(*v, exact(p), 1e-9, "sheared grid");
  }
}

// A 5 x 4 x 3 grid of irregular values with two solid nodes, a non-trivial origin and spacing.
Grid sample_grid()
{
  std::vector<float> values(3 * 60);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = static_cast<float>(std::sin(0.37 * double(i)) * std::pow(10., double(i % 7) - 3.));
  std::vector<unsigned char> mask(60, 1);
  mask[7] = mask[33] = 0;
  return Grid(Point(0.1, -2.5, 1e-3), Vector(0.1, 1. / 3., 0.7), {{5, 4, 3}}, std::move(values),
              std::move(mask));
}

TEST(ReadVTKXML, VTIWriterIsReadByVTKWithTheSameValuesAndGeometry)
{
  const Grid grid = sample_grid();
  const std::string file = temporary("written.vti");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(file, grid, FAS::parameters::array_name("u v"), &error)) << error;
  EXPECT_FALSE(std::filesystem::exists(file + ".partial"));

  // The peer: VTK's own reader.
  vtkNew<vtkXMLImageDataReader> reader;
  ASSERT_EQ(reader->CanReadFile(file.c_str()), 1);
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int extent[6];
  image->GetExtent(extent);
  EXPECT_EQ(std::vector<int>(extent, extent + 6), (std::vector<int>{0, 4, 0, 3, 0, 2}));
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  EXPECT_EQ(origin[0], 0.1);
  EXPECT_EQ(origin[1], -2.5);
  EXPECT_EQ(origin[2], 1e-3);
  EXPECT_EQ(spacing[0], 0.1);
  EXPECT_EQ(spacing[1], 1. / 3.);
  EXPECT_EQ(spacing[2], 0.7);
  vtkDataArray* velocity = image->GetPointData()->GetVectors();
  ASSERT_NE(velocity, nullptr);
  EXPECT_STREQ(velocity->GetName(), "u v");
  EXPECT_EQ(velocity->GetDataType(), VTK_FLOAT);
  ASSERT_EQ(velocity->GetNumberOfTuples(), 60);
  for (vtkIdType i = 0; i < 180; ++i)
    ASSERT_EQ(velocity->GetComponent(i / 3, int(i % 3)), double(grid.values()[std::size_t(i)])) << i;
  vtkDataArray* inside = image->GetPointData()->GetArray("inside");
  ASSERT_NE(inside, nullptr);
  EXPECT_EQ(inside->GetDataType(), VTK_UNSIGNED_CHAR);
  for (vtkIdType i = 0; i < 60; ++i)
    EXPECT_EQ(inside->GetComponent(i, 0), (i == 7 || i == 33) ? 0. : 1.) << i;

  // Through our reader: the same grid.
  Grid back;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, back, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_EQ(back.dimensions(), grid.dimensions());
  EXPECT_EQ(back.origin(), grid.origin());
  EXPECT_EQ(back.spacing(), grid.spacing());
  EXPECT_EQ(back.values(), grid.values());
  EXPECT_EQ(back.mask(), grid.mask());

  // And as hexahedra: the same values wherever both are defined, and defined at the same places
  // inside the cells (the ones touching a solid node are out of both).
  Cells cells;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, cells, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_LT(cells.number_of_cells(), 4u * 3u * 2u);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> x(0.1, 0.5), y(-2.5, -1.5), z(1e-3, 1.401);
  int defined = 0;
  for (int q = 0; q < 300; ++q) {
    const Point p(x(rng), y(rng), z(rng));
    const std::optional<Vector> a = grid(p), b = cells(p);
    ASSERT_EQ(a.has_value(), b.has_value()) << p;
    if (a) {
      ++defined;
      expect_near(*a, *b, 1e-9, "grid vs cells");
    }
  }
  EXPECT_GT(defined, 50);

  // Without a mask, no mask array.
  const Grid plain(Point(0, 0, 0), Vector(1, 1, 1), {{2, 2, 2}}, std::vector<float>(24, 1.5f));
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(temporary("plain.vti"), plain));
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(temporary("plain.vti"), back));
  EXPECT_FALSE(back.has_mask());
  EXPECT_EQ(back.values(), plain.values());
}

TEST(ReadVTKXML, VTIWriterFailuresAreReportedAndKeepTheExistingFile)
{
  const Grid grid = sample_grid();
  const std::string file = temporary("kept.vti");
  write_bytes(file, "what the user had");
  std::string error;
  EXPECT_FALSE(FAS::IO::write_VTI_flow_field(file, grid, FAS::parameters::array_name(""), &error));
  EXPECT_NE(error.find("write_VTI_flow_field: " + file + ": an array name is empty"), std::string::npos)
      << error;
  EXPECT_FALSE(FAS::IO::write_VTI_flow_field(file, grid, FAS::parameters::array_name("inside"), &error));
  EXPECT_NE(error.find("both named 'inside'"), std::string::npos) << error;
  EXPECT_EQ(read_bytes(file), "what the user had");
  const std::string nowhere = temporary("no_such_folder/field.vti");
  EXPECT_FALSE(FAS::IO::write_VTI_flow_field(nowhere, grid, CGAL::parameters::default_values(), &error));
  EXPECT_NE(error.find("write_VTI_flow_field: " + nowhere + ": cannot open"), std::string::npos) << error;
}

TEST(ReadVTKXML, ImageWrittenByVTKWithAShiftedExtentGivesTheLinearField)
{
  // Extent starting at (2, 1, 3): the first point is origin + (2, 1, 3) * spacing.
  vtkNew<vtkImageData> image;
  image->SetExtent(2, 6, 1, 3, 3, 5);
  image->SetOrigin(1, 2, 3);
  image->SetSpacing(0.5, 1, 0.25);
  add_velocity(image, 0., "first", false);
  add_velocity(image, 0., "second", true);
  add_scalars(image, "pressure", 1, 2.);
  const std::string file = temporary("shifted.vti");
  write_with_VTK<vtkXMLImageDataWriter>(image, file);
  Grid grid;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, grid, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_EQ(grid.origin(), Point(2, 3, 3.75));
  EXPECT_EQ(grid.dimensions(), (Grid::Dimensions{{5, 3, 3}}));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0., 1.);
  for (int q = 0; q < 100; ++q) {
    const Point p(2 + 2 * u(rng), 3 + 2 * u(rng), 3.75 + 0.5 * u(rng));
    expect_near(*grid(p), exact(p), 1e-9, "shifted image");
  }
  // The active vectors were chosen ("second"); "first" by name gives the same values.
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, grid, FAS::parameters::array_name("first"), &error))
      << error;
  expect_near(*grid(Point(3, 4, 4)), exact(Point(3, 4, 4)), 1e-9, "by name");
}

// A 2 x 2 x 2 ImageData file written by hand, ASCII, with the given attributes and arrays.
std::string hand_written_vti(const std::string& arrays, const std::string& image_attributes = "",
                             const std::string& extent = "0 1 0 1 0 1")
{
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "<ImageData WholeExtent=\"" +
         extent + "\" Origin=\"0 0 0\" Spacing=\"1 1 1\" " + image_attributes + ">\n<Piece Extent=\"" +
         extent + "\">\n<PointData>\n" + arrays +
         "</PointData>\n<CellData>\n</CellData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
}

std::string ascii_array(const std::string& type, const std::string& name, int components,
                        const std::string& values)
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
  const bool ok = FAS::IO::read_VTK_XML_flow_field(file, empty, np, &error);
  const std::string printed =
      ::testing::internal::GetCapturedStderr() + ::testing::internal::GetCapturedStdout();
  EXPECT_FALSE(ok) << file;
  EXPECT_EQ(empty.bbox(), CGAL::Bbox_3()); // untouched: empty
  EXPECT_EQ(printed, "") << "VTK printed while reading " << file;
  EXPECT_NE(error.find("read_VTK_XML_flow_field: " + file + ": "), std::string::npos) << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "message \"" << error << "\" lacks \"" << part << "\"";
  if constexpr (std::is_same<Field, Grid>::value) {
    Grid g = sentinel_grid();
    EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(file, g, np));
    expect_sentinel(g);
  }
}

TEST(ReadVTKXML, BadFilesGiveClearMessagesAndChangeNothing)
{
  const std::string velocity = ascii_array("Float32", "velocity", 3, repeated("1 2 3", 8));
  expect_read_fails<Grid>(temporary("does_not_exist.vti"), {"no such file"});
  expect_read_fails<Cells>(temporary("does_not_exist.vtu"), {"no such file"});
  expect_read_fails<Grid>(::testing::TempDir(), {"is a directory"});

  const std::string garbage = temporary("garbage.vti");
  write_bytes(garbage, "this is not XML at all\n");
  expect_read_fails<Grid>(garbage, {"not a VTK XML ImageData, UnstructuredGrid or StructuredGrid file"});
  expect_read_fails<Cells>(garbage, {"not a VTK XML"});

  // Another kind of data set than asked for.
  const std::string vtu = temporary("kind.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(mixed_mesh().grid, vtu);
  expect_read_fails<Grid>(vtu, {"this is a VTK XML UnstructuredGrid file (.vtu)", "ImageData"});

  // XML that VTK cannot parse: its words, captured.
  const std::string broken = temporary("broken.vti");
  write_bytes(broken, hand_written_vti(velocity).substr(0, 300) + "<<<");
  expect_read_fails<Grid>(broken, {"VTK cannot read it: ", "vtkXML"});

  // A truncated binary file (written by our writer, then cut in its appended data).
  const std::string truncated = temporary("truncated.vti");
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(truncated, sample_grid()));
  const std::string whole = read_bytes(truncated);
  write_bytes(truncated, whole.substr(0, whole.size() - 400));
  expect_read_fails<Grid>(truncated, {"VTK cannot read it: "});
  expect_read_fails<Cells>(truncated, {"VTK cannot read it: "});

  // A lying header: 10^12 points announced in a file of a few hundred bytes.
  const std::string lying = temporary("lying.vti");
  write_bytes(lying, hand_written_vti(velocity, "", "0 9999 0 9999 0 9999"));
  expect_read_fails<Grid>(lying, {"the header announces 1e+12 points", "truncated file or wrong header"});
  const std::string lying_vtu = temporary("lying.vtu");
  write_bytes(
      lying_vtu,
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n"
      "<UnstructuredGrid><Piece NumberOfPoints=\"100000000000\" NumberOfCells=\"1\">\n"
      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0"
      "</DataArray></Points>\n<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0"
      "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">1</DataArray>"
      "<DataArray type=\"UInt8\" Name=\"types\" "
      "format=\"ascii\">1</DataArray></Cells>\n</Piece></UnstructuredGrid></VTKFile>\n");
  expect_read_fails<Cells>(lying_vtu, {"the header announces 1e+11 points and 1 cells"});

  // Arrays: missing (the message lists the present ones), wrong components, wrong types.
  const std::string arrays = temporary("arrays.vti");
  write_bytes(arrays, hand_written_vti(ascii_array("Float32", "two", 2, repeated("1 2", 8)) +
                                       ascii_array("Float64", "pressure", 1, repeated("1", 8))));
  expect_read_fails<Grid>(arrays, {"no 3-component point data array", "'two' (float, 2 components)",
                                   "'pressure' (double, 1 component)"});
  expect_read_fails<Grid>(arrays, {"no point data array named 'velocity'", "'two'"},
                          FAS::parameters::array_name("velocity"));
  expect_read_fails<Cells>(arrays, {"'two' has 2 components", "3 numbers per point"},
                           FAS::parameters::array_name("two"));

  const std::string masks = temporary("masks.vti");
  write_bytes(masks, hand_written_vti(velocity + ascii_array("Float32", "inside", 3, repeated("1 1 1", 8))));
  expect_read_fails<Grid>(masks, {"the mask array 'inside' has 3 components", "1 number per point"});
  expect_read_fails<Grid>(masks, {"no point data array named 'solid' for the mask", "'velocity'"},
                          FAS::parameters::mask_array_name("solid"));

  // Non-finite velocities (written by VTK, binary): at a fluid point an error with its index;
  // at a solid one accepted.
  auto image_with_nan = [](const std::string& name, bool masked) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(2, 2, 2);
    add_velocity(image);
    image->GetPointData()->GetVectors()->SetComponent(5, 1, std::nan(""));
    if (masked) {
      vtkNew<vtkUnsignedCharArray> inside;
      inside->SetName("inside");
      inside->SetNumberOfTuples(8);
      inside->Fill(1);
      inside->SetValue(5, 0);
      image->GetPointData()->AddArray(inside);
    }
    const std::string file = temporary(name);
    write_with_VTK<vtkXMLImageDataWriter>(image, file);
    return file;
  };
  const std::string nan = image_with_nan("nan.vti", false);
  expect_read_fails<Grid>(nan, {"at point 5 = (1, 0, 1), component 1", "nan", "finite"});
  expect_read_fails<Cells>(nan, {"at point 5 = (1, 0, 1), component 1"});
  const std::string nan_solid = image_with_nan("nan_solid.vti", true);
  Grid grid;
  std::string error;
  EXPECT_TRUE(FAS::IO::read_VTK_XML_flow_field(nan_solid, grid, CGAL::parameters::default_values(), &error))
      << error;
  Cells cells;
  EXPECT_FALSE(
      FAS::IO::read_VTK_XML_flow_field(nan_solid, cells, CGAL::parameters::default_values(), &error));
  EXPECT_NE(error.find("no fluid cell"), std::string::npos) << error;

  // Geometry: a rotated image, a flat image.
  const std::string rotated = temporary("rotated.vti");
  write_bytes(rotated, hand_written_vti(velocity, "Direction=\"0 -1 0 1 0 0 0 0 1\""));
  expect_read_fails<Grid>(rotated,
                          {"Direction matrix (0 -1 0 1 0 0 0 0 1)", "not the identity", "not supported"});
  expect_read_fails<Cells>(rotated, {"not the identity"});
  const std::string flat = temporary("flat.vti");
  write_bytes(
      flat, hand_written_vti(ascii_array("Float32", "velocity", 3, repeated("1 2 3", 4)), "", "0 1 0 1 0 0"));
  expect_read_fails<Grid>(flat, {"2 x 2 x 1 points", "at least 2 points along each axis"});
}

// Headers whose structure VTK 9.1 trusts (found by fuzzing: a .vts whose piece reached outside
// the whole extent, with 8-component points, crashed VTK; an array of 10^100 components kept
// it busy for minutes): refused before VTK reads any data.
// An empty file is called empty, and the message is reachable without naming the default named
// parameters (the overloads taking the error pointer third).
TEST(ReadVTKXML, EmptyFileIsCalledEmpty)
{
  const std::string empty = temporary("empty.vti");
  write_bytes(empty, "");
  std::string error;
  Grid grid;
  EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(empty, grid, &error));
  EXPECT_EQ(error, "read_VTK_XML_flow_field: " + empty + ": the file is empty (0 bytes)");
  Cells cells;
  EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(empty, cells, &error));
  EXPECT_EQ(error, "read_VTK_XML_flow_field: " + empty + ": the file is empty (0 bytes)");
  FAS::Unsteady_flow_field_3<Grid> series;
  EXPECT_FALSE(FAS::IO::read_PVD_flow_field(empty, series, &error));
  EXPECT_EQ(error, "read_PVD_flow_field: " + empty + ": the file is empty (0 bytes)");
}

TEST(ReadVTKXML, PiecesOutsideTheWholeExtentAndImpossibleComponentCountsAreRefused)
{
  auto vts = [](const std::string& whole, int point_components) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"StructuredGrid\" version=\"1.0\">\n"
           "<StructuredGrid WholeExtent=\"" +
           whole + "\">\n<Piece Extent=\"0 1 0 1 0 1\">\n<PointData>\n" +
           ascii_array("Float32", "velocity", 3, repeated("1 2 3", 8)) + "</PointData>\n<Points>\n" +
           ascii_array("Float32", "Points", point_components,
                       repeated("0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1", 1)) +
           "</Points>\n</Piece>\n</StructuredGrid>\n</VTKFile>\n";
  };
  const std::string outside = temporary("outside.vts");
  write_bytes(outside, vts("1 1 0 1 0 1", 3));
  expect_read_fails<Cells>(outside, {"<Piece> the piece's Extent \"0 1 0 1 0 1\" reaches outside the "
                                     "WholeExtent \"1 1 0 1 0 1\"",
                                     "byte "});
  const std::string points = temporary("points.vts");
  write_bytes(points, vts("0 1 0 1 0 1", 8));
  expect_read_fails<Cells>(points, {"<DataArray> the points array has 8 components; points need 3"});
  std::string huge = vts("0 1 0 1 0 1", 3);
  huge.replace(huge.find("NumberOfComponents=\"3\""), 22,
               "NumberOfComponents=\"1" + std::string(100, '0') + "\"");
  write_bytes(points, huge);
  expect_read_fails<Cells>(points,
                           {"NumberOfComponents=\"1000", "is not a positive integer that the file can hold"});
  // The same grid with 3 components is read: the checks refuse only what they say.
  const std::string good = temporary("good.vts");
  write_bytes(good, vts("0 1 0 1 0 1", 3));
  Cells field;
  std::string error;
  EXPECT_TRUE(FAS::IO::read_VTK_XML_flow_field(good, field, CGAL::parameters::default_values(), &error))
      << error;
}

// The header of a compressed array, which VTK 9.1 allocates from (fuzzing found 13-point files
// announcing a 2 GB block or 2.7e9 blocks): checked against the file's size before VTK reads.
TEST(ReadVTKXML, LyingCompressionHeadersAreRefused)
{
  const std::string file = temporary("compressed.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(mixed_mesh().grid, file); // zlib, base64 appended
  const std::string good = read_bytes(file);
  ASSERT_NE(good.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  ASSERT_NE(good.find("header_type=\"UInt32\""), std::string::npos);
  const std::size_t data = good.find('_', good.find("<AppendedData encoding=\"base64\">")) + 1;
  ASSERT_NE(data, std::string::npos + 1);
  // The first array's header: 4 little-endian 32-bit words (1 block, its size, the last
  // block's size, its compressed size), 24 base64 characters.
  auto header = [](std::uint32_t blocks, std::uint32_t size, std::uint32_t last, std::uint32_t compressed) {
    const std::uint32_t w[4] = {blocks, size, last, compressed};
    unsigned char b[18] = {};
    for (int i = 0; i < 16; ++i)
      b[i] = static_cast<unsigned char>(w[i / 4] >> (8 * (i % 4)));
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string r;
    for (int i = 0; i < 18; i += 3) {
      const unsigned v = (unsigned(b[i]) << 16) | (unsigned(b[i + 1]) << 8) | b[i + 2];
      for (int k = 3; k >= 0; --k)
        r += alphabet[(v >> (6 * k)) & 63u];
    }
    return r.substr(0, 22) + "==";
  };
  ASSERT_EQ(good.substr(data, 4), header(1, 0, 0, 0).substr(0, 4)); // 1 block, as written by VTK
  const std::string lying = temporary("lying_blocks.vtu");
  write_bytes(lying, good.substr(0, data) + header(1, 32768, 2000000000u, 310) + good.substr(data + 24));
  expect_read_fails<Cells>(lying, {"the compressed DataArray 'velocity' announces 1 blocks", "lying header"});
  write_bytes(lying, good.substr(0, data) + header(3000000000u, 32768, 312, 310) + good.substr(data + 24));
  expect_read_fails<Cells>(lying, {"announces 3e+09 blocks, whose sizes alone need more than the"});
}

// Found by the fuzzer: a 2 KB compressed .vts whose velocity array has format="appende0d", which
// VTK 9.1 reads as inline binary: the element is empty, so VTK decodes a compression header
// from the text after it and allocates 3.4 GB.  Inline headers are checked like appended ones.
TEST(ReadVTKXML, LyingInlineCompressionHeadersAreRefused)
{
  expect_read_fails<Cells>(
      std::string(FAS_TEST_DATA_DIR) + "/vts_inline_lying_compression_header.vts",
      {"the compressed DataArray 'velocity' has no complete compression header", "corrupt file"});
}

// Found by the fuzzer: a 2 KB compressed .vtu whose appended base64 data has "ImageData" pasted
// into one array, so that the next array's compression header ends in padding after 6 bytes.
// VTK 9.1 stops decoding there but allocates from the words it got (3e9 blocks, 12 GB).
TEST(ReadVTKXML, ShortAppendedCompressionHeadersAreRefused)
{
  expect_read_fails<Cells>(
      std::string(FAS_TEST_DATA_DIR) + "/vtu_appended_padding_in_compression_header.vtu",
      {"the compressed DataArray 'offsets' has no complete compression header in its appended data",
       "corrupt file"});
}

// Found by the fuzzer (fuzz/corpus/VTK_XML/vts_appended_offset_beyond_long_long.vts, which VTK
// 9.1 parses and ParaView's VTK 9.2 refuses for its byte_order): an appended offset of 61 digits
// saturated strtoll, and adding it to the appended data's position overflowed.  An offset outside
// the file is refused with its value, whatever its size.
TEST(ReadVTKXML, AppendedOffsetsOutsideTheFileAreRefused)
{
  const std::string file = temporary("compressed_offsets.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(mixed_mesh().grid, file); // zlib, base64 appended
  const std::string good = read_bytes(file);
  const std::size_t first = good.find("offset=\"0\"");
  ASSERT_NE(first, std::string::npos);
  const std::string beyond = temporary("offset_beyond_the_file.vtu");
  for (const std::string& offset : {std::string("99999999"), "4" + std::string(59, '2') + "40"}) {
    write_bytes(beyond, good.substr(0, first) + "offset=\"" + offset + "\"" + good.substr(first + 10));
    const std::string size = std::to_string(good.size() + offset.size() - 1);
    // At most 40 digits are shown.
    const std::string shown = offset.size() > 40 ? offset.substr(0, 40) + "..." : offset;
    expect_read_fails<Cells>(beyond, {"the compressed DataArray 'velocity' has the offset \"" + shown +
                                      "\", outside the " + size + " bytes of the file (corrupt file)"});
  }
}

TEST(ReadVTKXML, UnsupportedCellsAreNamed)
{
  Mixed_mesh m = mixed_mesh();
  const vtkIdType triangle[3] = {0, 1, 2};
  m.grid->InsertNextCell(VTK_TRIANGLE, 3, triangle);
  const std::string file = temporary("triangle.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(m.grid, file);
  expect_read_fails<Cells>(file, {"cell 5 has the VTK cell type 5 (vtkTriangle)", "supported are 10"});
}

TEST(ReadVTKXML, VoxelWithoutEightPointsIsRefused)
{
  // The last cell a voxel of 5 points (a malformed file): refused with its count, nothing read
  // past it while the voxels are reordered.
  Mixed_mesh m = mixed_mesh();
  const vtkIdType short_voxel[5] = {0, 1, 3, 2, 4};
  m.grid->InsertNextCell(VTK_VOXEL, 5, short_voxel);
  const std::string file = temporary("short_voxel.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(m.grid, file);
  expect_read_fails<Cells>(file, {"cell 5 (a hexahedron)", "5 points; expected 8"});
}

// A .pvd of the given (time, file) pairs.
std::string pvd(const std::vector<std::pair<std::string, std::string>>& steps)
{
  std::string r = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& s : steps)
    r += "    <DataSet timestep=\"" + s.first + "\" group=\"\" part=\"0\" file=\"" + s.second + "\"/>\n";
  return r + "  </Collection>\n</VTKFile>\n";
}

TEST(ReadVTKXML, TimeSeriesOfThreeStepsIsExactAtIntermediateTimes)
{
  const std::filesystem::path folder = temporary("series");
  std::filesystem::create_directories(folder / "steps");
  const std::vector<double> times = {0., 0.5, 2.};
  // Written out of order in the .pvd, with paths relative to its folder.
  for (double t : times) {
    vtkNew<vtkImageData> image;
    image->SetExtent(0, 4, 0, 2, 0, 3);
    image->SetOrigin(-1, 0, 0.5);
    image->SetSpacing(0.5, 1, 0.5);
    add_velocity(image, t);
    write_with_VTK<vtkXMLImageDataWriter>(
        image, (folder / "steps" / ("grid_" + std::to_string(t) + ".vti")).string());
    Mixed_mesh m = mixed_mesh();
    m.grid->GetPointData()->Initialize();
    add_velocity(m.grid, t);
    write_with_VTK<vtkXMLUnstructuredGridWriter>(
        m.grid, (folder / "steps" / ("cells_" + std::to_string(t) + ".vtu")).string());
  }
  auto series = [&](const std::string& prefix, const std::string& extension) {
    std::vector<std::pair<std::string, std::string>> steps;
    for (int i : {2, 0, 1})
      steps.emplace_back(i == 1 ? "5e-1" : std::to_string(times[std::size_t(i)]),
                         "steps/" + prefix + std::to_string(times[std::size_t(i)]) + extension);
    return pvd(steps);
  };
  const std::string grid_pvd = (folder / "grids.pvd").string(), cell_pvd = (folder / "cells.pvd").string();
  write_bytes(grid_pvd, series("grid_", ".vti"));
  write_bytes(cell_pvd, series("cells_", ".vtu"));

  FAS::Unsteady_flow_field_3<Grid> grids;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_PVD_flow_field(grid_pvd, grids, CGAL::parameters::default_values(), &error))
      << error;
  ASSERT_EQ(grids.number_of_steps(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(grids.time(i), times[i]);
  FAS::Unsteady_flow_field_3<Cells> cells = FAS::Unsteady_flow_field_3<Cells>(
      {0.}, {Cells(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 2, 3}, {0, 4}, {10},
                   std::vector<float>(12, 0.f))});
  ASSERT_TRUE(FAS::IO::read_PVD_flow_field(cell_pvd, cells, CGAL::parameters::default_values(), &error))
      << error;
  ASSERT_EQ(cells.number_of_steps(), 3u);
  EXPECT_EQ(cells.step(1).number_of_cells(), 5u);

  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0., 1.), time(0., 2.);
  const Mixed_mesh m = mixed_mesh();
  for (int q = 0; q < 200; ++q) {
    const double t = time(rng);
    const Point p(-1 + 2 * u(rng), 2 * u(rng), 0.5 + 1.5 * u(rng));
    expect_near(*grids(p, t), exact(p, t), 1e-9, "grid series at t = " + std::to_string(t));
    const Point c = random_point_in(m.grid, m.cells[std::size_t(q) % 5], rng);
    expect_near(*cells(c, t), exact(c, t), 1e-9, "cell series at t = " + std::to_string(t));
  }
  EXPECT_FALSE(grids(Point(0, 1, 1), 2.5));
}

// read_PVD_flow_field fails with all `parts` and leaves the output as it was (empty or not).
void expect_PVD_fails(const std::string& file, const std::vector<std::string>& parts)
{
  std::string error;
  FAS::Unsteady_flow_field_3<Grid> series;
  ::testing::internal::CaptureStderr();
  const bool ok = FAS::IO::read_PVD_flow_field(file, series, CGAL::parameters::default_values(), &error);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "VTK printed while reading " << file;
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

TEST(ReadVTKXML, BadCollectionsGiveClearMessagesAndChangeNothing)
{
  const std::filesystem::path folder = temporary("bad_series");
  std::filesystem::create_directories(folder);
  const std::string step = (folder / "step.vti").string();
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(step, sample_grid()));
  auto file = [&](const std::string& name, const std::string& contents) {
    const std::string f = (folder / name).string();
    write_bytes(f, contents);
    return f;
  };
  expect_PVD_fails((folder / "none.pvd").string(), {"no such file"});
  expect_PVD_fails(file("broken.pvd", "<VTKFile type=\"Collection\"><Collection><DataSet"),
                   {"cannot parse it as XML"});
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
  const std::string vtu = (folder / "cells.vtu").string();
  write_with_VTK<vtkXMLUnstructuredGridWriter>(mixed_mesh().grid, vtu);
  expect_PVD_fails(file("kind.pvd", pvd({{"0", "step.vti"}, {"2", "cells.vtu"}})),
                   {"step 1 (timestep 2", "UnstructuredGrid"});
}

// The real CFD data of ../shared/data, converted to VTK XML by VTK itself (its legacy readers,
// its XML writers, zlib-compressed): the figures that CYLINDER_stats.json states, and the native
// cells agree with the grid at its nodes, which CYLINDER.md says were sampled from these cells
// by vtkProbeFilter (trilinear interpolation in the native hexahedra).
TEST(ReadVTKXML, RealCylinderDataConvertedByVTKGivesTheStatedFigures)
{
#ifndef FAS_HAVE_VTK_IO_LEGACY
  GTEST_SKIP() << "VTK's IOLegacy module was not found; it converts the legacy files of ../shared/data";
#else
  const std::string folder = FAS_SHARED_DATA_DIR;
  const std::string grid_file = folder + "/CYLINDER_grid.vtk", cells_file = folder + "/CYLINDER_cells.vtk";
  if (!std::ifstream(grid_file).good() || !std::ifstream(cells_file).good())
    GTEST_SKIP() << "CYLINDER_grid.vtk or CYLINDER_cells.vtk not found in FAS_SHARED_DATA_DIR (" << folder
                 << ")";

  vtkNew<vtkStructuredPointsReader> grid_reader;
  grid_reader->SetFileName(grid_file.c_str());
  grid_reader->Update();
  const std::string vti = temporary("CYLINDER_grid.vti");
  write_with_VTK<vtkXMLImageDataWriter>(grid_reader->GetOutput(), vti);
  vtkNew<vtkUnstructuredGridReader> cells_reader;
  cells_reader->SetFileName(cells_file.c_str());
  cells_reader->Update();
  const std::string vtu = temporary("CYLINDER_cells.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(cells_reader->GetOutput(), vtu);

  Grid grid;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(vti, grid, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_EQ(grid.dimensions(), (Grid::Dimensions{{251, 42, 42}}));
  EXPECT_EQ(grid.origin(), Point(0, 0, 0));
  EXPECT_NEAR(grid.spacing().x(), 0.01, 1e-15);
  ASSERT_TRUE(grid.has_mask());
  std::size_t fluid = 0;
  double max_speed = 0;
  for (std::size_t v = 0; v < grid.number_of_nodes(); ++v) {
    fluid += grid.mask()[v] != 0;
    const float* c = grid.values().data() + 3 * v;
    max_speed =
        (std::max)(max_speed, std::sqrt(double(c[0]) * c[0] + double(c[1]) * c[1] + double(c[2]) * c[2]));
  }
  EXPECT_EQ(fluid, 439782u);
  EXPECT_NEAR(max_speed, 0.5093556873570264, 1e-6);

  Cells cells;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(vtu, cells, CGAL::parameters::default_values(), &error))
      << error;
  EXPECT_EQ(cells.number_of_points(), 197505u);
  EXPECT_EQ(cells.number_of_cells(), 185344u);

  // Every 5th fluid node: the native cells give the node's value, to the rounding of the
  // 32-bit floats in which both forms are stored (|v| <= 0.51, so an ulp is 6e-8).
  std::size_t compared = 0, undefined = 0;
  double max_difference = 0;
  const auto& n = grid.dimensions();
  for (std::size_t v = 0; v < grid.number_of_nodes(); v += 5) {
    if (grid.mask()[v] == 0)
      continue;
    const std::size_t i = v % n[0], j = (v / n[0]) % n[1], k = v / (n[0] * n[1]);
    const std::optional<Vector> c = cells(grid.node_point(i, j, k));
    if (!c) {
      ++undefined; // the planes y = 0.41 and z = 0.41 lie a float's rounding outside the mesh
      continue;
    }
    ++compared;
    const Vector d = *c - grid.node_value(i, j, k);
    max_difference = (std::max)(max_difference, std::sqrt(d.squared_length()));
  }
  EXPECT_GT(compared, 80000u);
  EXPECT_LT(undefined, compared / 10);
  EXPECT_LT(max_difference, 1e-6) << compared << " nodes compared, " << undefined << " outside the cells";
  std::cout << "CYLINDER: " << compared << " fluid nodes compared with the native cells, max |difference| "
            << max_difference << ", " << undefined << " nodes outside the cells\n";
#endif
}

} // namespace

} // namespace test_read_VTK_XML
