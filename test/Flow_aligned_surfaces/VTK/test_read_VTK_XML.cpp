// The package's VTK XML reader (which runs no VTK) with VTK as the peer: files written by VTK's
// own writers in every data mode (ascii, inline binary, appended raw, appended base64), with every
// compressor (none, zlib, LZ4, LZMA), both byte orders and both header types, are read with the
// same values as VTK's readers give; where VTK's reader cannot read a file (ParaView 5.11's VTK 9.2
// fails on any appended data with the expat of an up-to-date Debian bookworm), the values are
// compared with the data set written, and the test says so.  Also: .vtu files of tetrahedra,
// hexahedra, wedges and pyramids and curvilinear .vts files with a field linear in space read
// back to that field exactly; .vti files written by write_VTI_flow_field() are read by VTK's
// vtkXMLImageDataReader with the same values; and the real time series of ../shared/data (34
// inline binary zlib .vti files) is read as VTK reads it.

#include <gtest/gtest.h>

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "../test_files.h"

#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
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
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLWriter.h>
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

// Reads `file` with VTK's reader `Reader`, its errors captured (never printed): the data set, or
// null with the errors in `errors`.
class Error_recorder : public vtkCommand {
public:
  static Error_recorder* New() { return new Error_recorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    errors += (errors.empty() ? "" : "; ") + std::string(data ? static_cast<const char*>(data) : "?");
  }
  std::string errors;
};

template <class Reader>
vtkSmartPointer<vtkDataSet> read_with_VTK(const std::string& file, std::string& errors)
{
  vtkNew<Reader> reader;
  vtkNew<Error_recorder> recorder;
  for (vtkObject* o : {static_cast<vtkObject*>(reader.Get()), static_cast<vtkObject*>(reader->GetExecutive())}) {
    o->AddObserver(vtkCommand::ErrorEvent, recorder);
    o->AddObserver(vtkCommand::WarningEvent, recorder);
  }
  reader->SetReaderErrorObserver(recorder);
  reader->SetParserErrorObserver(recorder);
  reader->SetFileName(file.c_str());
  reader->Update();
  errors = recorder->errors;
  if (!errors.empty())
    return nullptr;
  return vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
}

// How VTK's writer writes a file.
struct VTK_writer_mode {
  int data_mode;      // vtkXMLWriter::Ascii, Binary or Appended
  bool encode;        // appended data base64-encoded
  int compressor;     // vtkXMLWriter::NONE, ZLIB, LZ4, LZMA
  bool big_endian, wide_header;

  std::string describe() const
  {
    const char* modes[] = {"ascii", "binary", "appended"};
    const char* compressors[] = {"none", "zlib", "LZ4", "LZMA"};
    return std::string(modes[data_mode]) + (data_mode == vtkXMLWriter::Appended ? (encode ? " base64" : " raw") : "") +
           ", compressor " + compressors[compressor] + (big_endian ? ", BigEndian" : ", LittleEndian") +
           (wide_header ? ", UInt64" : ", UInt32");
  }
};

std::vector<VTK_writer_mode> every_VTK_writer_mode()
{
  std::vector<VTK_writer_mode> r;
  for (int data_mode : {vtkXMLWriter::Ascii, vtkXMLWriter::Binary, vtkXMLWriter::Appended})
    for (bool encode : {false, true})
      for (int compressor : {vtkXMLWriter::NONE, vtkXMLWriter::ZLIB, vtkXMLWriter::LZ4, vtkXMLWriter::LZMA})
        for (bool big : {false, true}) {
          if ((data_mode != vtkXMLWriter::Appended && encode) || (data_mode == vtkXMLWriter::Ascii && (compressor || big)))
            continue;
          r.push_back(VTK_writer_mode{data_mode, encode, compressor, big, big});
        }
  return r;
}

template <class Writer>
void write_with_VTK(vtkDataObject* data, const std::string& filename, const VTK_writer_mode& m)
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(filename.c_str());
  writer->SetDataMode(m.data_mode);
  writer->SetEncodeAppendedData(m.encode);
  writer->SetCompressorType(m.compressor);
  writer->SetBlockSize(256); // several blocks per array
  if (m.big_endian)
    writer->SetByteOrderToBigEndian();
  if (m.wide_header)
    writer->SetHeaderTypeToUInt64();
  ASSERT_EQ(writer->Write(), 1) << filename << ", " << m.describe();
}

// The velocity array of `ds` as the floats the package stores.
std::vector<float> VTK_velocity(vtkDataSet* ds)
{
  vtkDataArray* v = ds->GetPointData()->GetArray("velocity");
  std::vector<float> r;
  for (vtkIdType i = 0; v != nullptr && i < v->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      r.push_back(static_cast<float>(v->GetComponent(i, c)));
  return r;
}

std::vector<unsigned char> VTK_mask(vtkDataSet* ds)
{
  vtkDataArray* m = ds->GetPointData()->GetArray("inside");
  std::vector<unsigned char> r;
  for (vtkIdType i = 0; m != nullptr && i < m->GetNumberOfTuples(); ++i)
    r.push_back(m->GetComponent(i, 0) != 0.);
  return r;
}

std::vector<double> VTK_points(vtkDataSet* ds)
{
  std::vector<double> r;
  for (vtkIdType i = 0; i < ds->GetNumberOfPoints(); ++i) {
    double x[3];
    ds->GetPoint(i, x);
    r.insert(r.end(), x, x + 3);
  }
  return r;
}

// The package's field equals the data set `reference` (VTK's reading of the file, or what was
// written): the same grid and values, or the same points, values and number of cells.
void expect_same(const Grid& g, vtkDataSet* reference, const std::string& what)
{
  vtkImageData* image = vtkImageData::SafeDownCast(reference);
  ASSERT_NE(image, nullptr) << what;
  int d[3];
  image->GetDimensions(d);
  EXPECT_EQ(g.dimensions(), (Grid::Dimensions{{std::size_t(d[0]), std::size_t(d[1]), std::size_t(d[2])}})) << what;
  double first[3], spacing[3];
  image->GetPoint(0, first);
  image->GetSpacing(spacing);
  EXPECT_EQ(g.origin(), Point(first[0], first[1], first[2])) << what;
  EXPECT_EQ(g.spacing(), Vector(spacing[0], spacing[1], spacing[2])) << what;
  EXPECT_EQ(g.values(), VTK_velocity(reference)) << what;
  EXPECT_EQ(g.mask(), VTK_mask(reference)) << what;
}

void expect_same(const Cells& c, vtkDataSet* reference, const std::string& what)
{
  EXPECT_EQ(c.vectors(), VTK_velocity(reference)) << what;
  const std::vector<double> points = VTK_points(reference);
  ASSERT_EQ(c.points().size(), points.size()) << what;
  for (std::size_t i = 0; i < points.size(); ++i)
    ASSERT_EQ(c.points()[i], points[i]) << what << ", coordinate " << i;
  EXPECT_EQ(c.number_of_cells(), std::size_t(reference->GetNumberOfCells())) << what;
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
    ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, FAS::parameters::error_message(&error)))
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
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, FAS::parameters::error_message(&error))) << error;
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
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, FAS::parameters::error_message(&error))) << error;
  ASSERT_EQ(field.number_of_cells(), 4u);
  std::mt19937 rng(5);
  EXPECT_FALSE(field(random_point_in(m.grid, {0, 3, 4, 12}, rng)).has_value());
  const Point p = random_point_in(m.grid, m.cells[1], rng);
  expect_near(*field(p), exact(p), 1e-9, "wedge");

  // No mask when asked for none.
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(
      file, field, FAS::parameters::error_message(&error, FAS::parameters::mask_array_name(std::string()))))
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
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, field, FAS::parameters::error_message(&error))) << error;
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
  ASSERT_TRUE(FAS::IO::write_VTI_flow_field(
      file, grid, FAS::parameters::error_message(&error, FAS::parameters::array_name("u v"))))
      << error;
  EXPECT_FALSE(std::filesystem::exists(file + ".partial"));

  // The peer: VTK's own reader.  The data are inline, which every VTK reads, ParaView 5.11's on
  // an up-to-date bookworm too (it cannot parse appended data with the current expat).
  const std::string bytes = read_bytes(file);
  EXPECT_EQ(bytes.find("AppendedData"), std::string::npos);
  EXPECT_EQ(bytes.find("format=\"appended\""), std::string::npos);
  std::string vtk_errors;
  vtkSmartPointer<vtkDataSet> by_VTK = read_with_VTK<vtkXMLImageDataReader>(file, vtk_errors);
  ASSERT_NE(by_VTK, nullptr) << "VTK's reader cannot read the .vti written: " << vtk_errors;
  {
    vtkImageData* image = vtkImageData::SafeDownCast(by_VTK);
    ASSERT_NE(image, nullptr);
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
  }

  // Through our reader: the same grid.
  Grid back;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, back, FAS::parameters::error_message(&error))) << error;
  EXPECT_EQ(back.dimensions(), grid.dimensions());
  EXPECT_EQ(back.origin(), grid.origin());
  EXPECT_EQ(back.spacing(), grid.spacing());
  EXPECT_EQ(back.values(), grid.values());
  EXPECT_EQ(back.mask(), grid.mask());

  // And as hexahedra: the same values wherever both are defined, and defined at the same places
  // inside the cells (the ones touching a solid node are out of both).
  Cells cells;
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, cells, FAS::parameters::error_message(&error))) << error;
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
  EXPECT_FALSE(FAS::IO::write_VTI_flow_field(
      file, grid, FAS::parameters::error_message(&error, FAS::parameters::array_name(""))));
  EXPECT_NE(error.find("write_VTI_flow_field: " + file + ": an array name is empty"), std::string::npos)
      << error;
  EXPECT_FALSE(FAS::IO::write_VTI_flow_field(
      file, grid, FAS::parameters::error_message(&error, FAS::parameters::array_name("inside"))));
  EXPECT_NE(error.find("both named 'inside'"), std::string::npos) << error;
  EXPECT_EQ(read_bytes(file), "what the user had");
  const std::string nowhere = temporary("no_such_folder/field.vti");
  EXPECT_FALSE(FAS::IO::write_VTI_flow_field(nowhere, grid, FAS::parameters::error_message(&error)));
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
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, grid, FAS::parameters::error_message(&error))) << error;
  EXPECT_EQ(grid.origin(), Point(2, 3, 3.75));
  EXPECT_EQ(grid.dimensions(), (Grid::Dimensions{{5, 3, 3}}));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0., 1.);
  for (int q = 0; q < 100; ++q) {
    const Point p(2 + 2 * u(rng), 3 + 2 * u(rng), 3.75 + 0.5 * u(rng));
    expect_near(*grid(p), exact(p), 1e-9, "shifted image");
  }
  // The active vectors were chosen ("second"); "first" by name gives the same values.
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(
      file, grid, FAS::parameters::error_message(&error, FAS::parameters::array_name("first"))))
      << error;
  expect_near(*grid(Point(3, 4, 4)), exact(Point(3, 4, 4)), 1e-9, "by name");
}

// Writes `data` in every mode VTK's writer has; the package's reading of each file equals VTK's
// reading of it, or, where VTK's reader fails, the data set written.  Returns the number of files
// VTK could not read.
template <class Writer, class Reader, class Field>
std::size_t expect_read_like_VTK(vtkDataSet* data, const std::string& extension)
{
  std::size_t vtk_failed = 0, compared = 0;
  std::string first_error;
  const std::vector<VTK_writer_mode> modes = every_VTK_writer_mode();
  for (const VTK_writer_mode& m : modes) {
    const std::string file = temporary("mode." + extension), what = extension + ", " + m.describe();
    write_with_VTK<Writer>(data, file, m);
    Field field;
    std::string error;
    if (!FAS::IO::read_VTK_XML_flow_field(
            file, field,
            FAS::parameters::error_message(&error, FAS::parameters::mask_array_name(std::string())))) {
      ADD_FAILURE() << what << ": " << error;
      continue;
    }
    std::string vtk_errors;
    vtkSmartPointer<vtkDataSet> by_VTK = read_with_VTK<Reader>(file, vtk_errors);
    if (by_VTK == nullptr) {
      ++vtk_failed;
      if (first_error.empty())
        first_error = what + ": " + vtk_errors.substr(0, 300);
      expect_same(field, data, what + " (against the data written)");
    }
    else {
      expect_same(field, by_VTK, what + " (against VTK's reader)");
    }
    ++compared;
  }
  EXPECT_EQ(compared, modes.size());
  std::cout << extension << ": " << compared << " files in every mode of VTK's writer read by the package; "
            << compared - vtk_failed << " compared with VTK's reader, " << vtk_failed
            << " with the data written because VTK's reader failed on them"
            << (first_error.empty() ? std::string() : " (first: " + first_error + ")") << "\n";
  return vtk_failed;
}

TEST(ReadVTKXML, EveryModeOfVTKsWriterIsReadAsVTKReadsIt)
{
  EXPECT_EQ(every_VTK_writer_mode().size(), 1u + 8u + 16u); // ascii; binary; appended raw and base64
  vtkNew<vtkImageData> image;
  image->SetExtent(2, 9, 1, 6, 3, 8);
  image->SetOrigin(1, 2, 3);
  image->SetSpacing(0.5, 1, 0.25);
  add_velocity(image);
  vtkNew<vtkUnsignedCharArray> inside;
  inside->SetName("inside");
  inside->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < inside->GetNumberOfTuples(); ++i)
    inside->SetValue(i, i % 7 == 3 ? 0 : 1);
  image->GetPointData()->AddArray(inside);
  // The mask is read too (not as a mask: as an array next to the velocity).
  const std::size_t image_failures =
      expect_read_like_VTK<vtkXMLImageDataWriter, vtkXMLImageDataReader, Cells>(image, "vti");
  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(4, 3, 5);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        points->InsertNextPoint(i + 0.5 * j, j, k + 0.25 * i);
  grid->SetPoints(points);
  add_velocity(grid);
  expect_read_like_VTK<vtkXMLStructuredGridWriter, vtkXMLStructuredGridReader, Cells>(grid, "vts");
  expect_read_like_VTK<vtkXMLUnstructuredGridWriter, vtkXMLUnstructuredGridReader, Cells>(mixed_mesh().grid, "vtu");
  // Inline binary and ASCII files are read by every VTK: a failure there is not the known one.
  EXPECT_LE(image_failures, 16u) << "VTK's reader failed on files without appended data";
}

TEST(ReadVTKXML, ImagesInEveryModeAreReadAsVTKReadsThem)
{
  vtkNew<vtkImageData> image;
  image->SetExtent(0, 6, 0, 4, 0, 5);
  image->SetOrigin(-1, 0.5, 2);
  image->SetSpacing(0.25, 0.5, 1);
  add_velocity(image);
  vtkNew<vtkUnsignedCharArray> inside;
  inside->SetName("inside");
  inside->SetNumberOfTuples(image->GetNumberOfPoints());
  inside->Fill(1);
  inside->SetValue(11, 0);
  image->GetPointData()->AddArray(inside);
  std::size_t vtk_failed = 0, compared = 0;
  for (const VTK_writer_mode& m : every_VTK_writer_mode()) {
    const std::string file = temporary("grid_mode.vti"), what = m.describe();
    write_with_VTK<vtkXMLImageDataWriter>(image, file, m);
    Grid g;
    std::string error;
    ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(file, g, FAS::parameters::error_message(&error)))
        << what << ": " << error;
    std::string vtk_errors;
    vtkSmartPointer<vtkDataSet> by_VTK = read_with_VTK<vtkXMLImageDataReader>(file, vtk_errors);
    vtk_failed += by_VTK == nullptr;
    expect_same(g, by_VTK ? by_VTK.Get() : image.Get(), what);
    ++compared;
  }
  EXPECT_EQ(compared, 25u);
  std::cout << "vti as grids: " << compared << " files, " << compared - vtk_failed << " compared with VTK's reader, "
            << vtk_failed << " with the data written (VTK's reader failed)\n";
}

// The real CFD time series of ../shared/data: 34 steps of 151 x 25 x 25 points, inline binary
// zlib-compressed .vti files (which every VTK reads): the package's series holds, at every
// step, exactly what VTK's reader reads from the step's file.
TEST(ReadVTKXML, RealUnsteadyCylinderSeriesIsReadAsVTKReadsIt)
{
  const std::string pvd = std::string(FAS_SHARED_DATA_DIR) + "/CYLINDER_UNSTEADY_grid.pvd";
  if (!std::ifstream(pvd).good())
    GTEST_SKIP() << pvd << " not found";
  FAS::Unsteady_flow_field_3<Grid> series;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_PVD_flow_field(pvd, series, FAS::parameters::error_message(&error))) << error;
  ASSERT_EQ(series.number_of_steps(), 34u);
  EXPECT_EQ(series.time(0), 6.5);
  EXPECT_EQ(series.time(33), 6.833373);
  for (std::size_t i = 0; i < series.number_of_steps(); i += 11) {
    char name[64];
    std::snprintf(name, sizeof name, "/CYLINDER_UNSTEADY_grid/step_%04zu.vti", i);
    std::string vtk_errors;
    vtkSmartPointer<vtkDataSet> by_VTK =
        read_with_VTK<vtkXMLImageDataReader>(std::string(FAS_SHARED_DATA_DIR) + name, vtk_errors);
    ASSERT_NE(by_VTK, nullptr) << name << ": " << vtk_errors;
    expect_same(series.step(i), by_VTK, name);
    EXPECT_EQ(series.step(i).dimensions(), (Grid::Dimensions{{151, 25, 25}}));
  }
}

// The reader fails with all `parts` in the message and leaves the output untouched.
void expect_read_fails(const std::string& file, const std::vector<std::string>& parts)
{
  std::string error;
  Cells empty;
  EXPECT_FALSE(FAS::IO::read_VTK_XML_flow_field(file, empty, FAS::parameters::error_message(&error))) << file;
  EXPECT_EQ(empty.bbox(), CGAL::Bbox_3());
  EXPECT_NE(error.find("read_VTK_XML_flow_field: " + file + ": "), std::string::npos) << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "message \"" << error << "\" lacks \"" << part << "\"";
}

TEST(ReadVTKXML, UnsupportedCellsAreNamed)
{
  Mixed_mesh m = mixed_mesh();
  const vtkIdType triangle[3] = {0, 1, 2};
  m.grid->InsertNextCell(VTK_TRIANGLE, 3, triangle);
  const std::string file = temporary("triangle.vtu");
  write_with_VTK<vtkXMLUnstructuredGridWriter>(m.grid, file);
  expect_read_fails(file, {"gives cell 5 the VTK cell type 5 (VTK_TRIANGLE)", "supported are 10"});
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
  expect_read_fails(file, {"gives cell 5 (VTK_VOXEL) 5 points; expected 8"});
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
  ASSERT_TRUE(FAS::IO::read_PVD_flow_field(grid_pvd, grids, FAS::parameters::error_message(&error))) << error;
  ASSERT_EQ(grids.number_of_steps(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(grids.time(i), times[i]);
  FAS::Unsteady_flow_field_3<Cells> cells = FAS::Unsteady_flow_field_3<Cells>(
      {0.}, {Cells(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 2, 3}, {0, 4}, {10},
                   std::vector<float>(12, 0.f))});
  ASSERT_TRUE(FAS::IO::read_PVD_flow_field(cell_pvd, cells, FAS::parameters::error_message(&error))) << error;
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
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(vti, grid, FAS::parameters::error_message(&error))) << error;
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
  ASSERT_TRUE(FAS::IO::read_VTK_XML_flow_field(vtu, cells, FAS::parameters::error_message(&error))) << error;
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
