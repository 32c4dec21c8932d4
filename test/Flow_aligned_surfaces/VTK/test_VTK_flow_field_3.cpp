// VTK_flow_field_3, the FlowField_3 over any vtkDataSet: against the package's own fields on the
// same samples (trilinear on a vtkImageData = Regular_grid_flow_field_3; the package's readers
// of ../shared/data), against closed forms (a linear field on tetrahedra is reproduced exactly,
// cell data is the cell's value), its mask and its outside, its messages for bad input, and one
// deformation on it that equals the one on Regular_grid_flow_field_3, serially and in parallel.
// make_unstructured_flow_field(), the same grids as Unstructured_flow_field_3: the package's
// reader of the same file as the peer, the closed form, and the grids it leaves to VTK.

#include "expect_invalid_argument.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/VTK_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/make_unstructured_flow_field.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <mutex>
#include <set>
#include <thread>
#include <optional>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_VTK_flow_field_3 {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Grid = FAS::Regular_grid_flow_field_3<K>;
using Field = FAS::VTK_flow_field_3<K>;
using Mesh = CGAL::Surface_mesh<Point>;

// The same node values (and mask, as the array "inside") as a vtkImageData.
vtkSmartPointer<vtkImageData> to_image(const Grid& grid)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  const Grid::Dimensions& n = grid.dimensions();
  image->SetDimensions(int(n[0]), int(n[1]), int(n[2]));
  image->SetOrigin(grid.origin().x(), grid.origin().y(), grid.origin().z());
  image->SetSpacing(grid.spacing().x(), grid.spacing().y(), grid.spacing().z());
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(vtkIdType(grid.values().size() / 3));
  for (std::size_t i = 0; i < grid.values().size(); ++i)
    velocity->SetValue(vtkIdType(i), grid.values()[i]);
  image->GetPointData()->AddArray(velocity);
  if (grid.has_mask()) {
    vtkNew<vtkUnsignedCharArray> inside;
    inside->SetName("inside");
    inside->SetNumberOfTuples(vtkIdType(grid.mask().size()));
    for (std::size_t i = 0; i < grid.mask().size(); ++i)
      inside->SetValue(vtkIdType(i), grid.mask()[i]);
    image->GetPointData()->AddArray(inside);
  }
  return image;
}

Point random_point(CGAL::Random& random, const CGAL::Bbox_3& box)
{
  return Point(random.get_double(box.xmin(), box.xmax()), random.get_double(box.ymin(), box.ymax()),
               random.get_double(box.zmin(), box.zmax()));
}

double distance(const Vector& a, const Vector& b) { return std::sqrt((a - b).squared_length()); }

// A point source sampled on a grid around it: the node at the source has no sample, so the grid
// has a mask.
Grid point_source_grid(const std::array<std::size_t, 3>& n)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  return FAS::sample_on_grid(source, Point(-1, -1, -1), Vector(2. / double(n[0] - 1), 2. / double(n[1] - 1), 3.5 / double(n[2] - 1)), n);
}

TEST(VTKFlowField3, ImageDataIsTrilinearLikeRegularGrid)
{
  // The ABC flow has no mask: every sample inside the box exists.
  const FAS::ABC_flow<K> abc;
  const Grid grid = FAS::sample_on_grid(abc, Point(0.1, -0.2, 0.3), Vector(0.3, 0.25, 0.2), {{9, 11, 13}});
  ASSERT_FALSE(grid.has_mask());
  const Field field(to_image(grid));
  EXPECT_FALSE(field.velocity_on_cells());
  EXPECT_EQ(field.mask_array(), nullptr);
  CGAL::Random random(7);
  for (int i = 0; i < 2000; ++i) {
    const Point p = random_point(random, grid.bbox());
    const std::optional<Vector> expected = grid(p), got = field(p);
    ASSERT_TRUE(expected && got) << p;
    EXPECT_LE(distance(*expected, *got), 1e-12) << p;
  }
  // The nodes themselves, corners of the box among them, give the node values.
  for (std::size_t k : {std::size_t(0), std::size_t(12)})
    for (std::size_t j : {std::size_t(0), std::size_t(5), std::size_t(10)})
      for (std::size_t i : {std::size_t(0), std::size_t(8)}) {
        const std::optional<Vector> got = field(grid.node_point(i, j, k));
        ASSERT_TRUE(got) << i << " " << j << " " << k;
        EXPECT_LE(distance(*got, grid.node_value(i, j, k)), 1e-12);
      }
}

TEST(VTKFlowField3, MaskAndOutsideGiveNoSample)
{
  const Grid grid = point_source_grid({{11, 11, 15}});
  ASSERT_TRUE(grid.has_mask());
  const Field field(to_image(grid));
  ASSERT_NE(field.mask_array(), nullptr); // "inside", by default
  CGAL::Random random(11);
  int masked = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point p = random_point(random, grid.bbox());
    const std::optional<Vector> expected = grid(p), got = field(p);
    ASSERT_EQ(bool(expected), bool(got)) << p;
    if (!expected) {
      ++masked;
      continue;
    }
    EXPECT_LE(distance(*expected, *got), 1e-12 * (1 + std::sqrt(expected->squared_length()))) << p;
  }
  // The 8 cells around the source are masked: 8 / (10 · 10 · 14) of the volume.
  EXPECT_NEAR(masked / 20000., 8. / 1400., 0.003);
  // Right at the source, and outside the box (NaN too): no sample.
  EXPECT_FALSE(field(Point(0, 0, 0)));
  EXPECT_FALSE(field(Point(0, 0, 2.6)));
  EXPECT_FALSE(field(Point(-1.001, 0, 0)));
  EXPECT_FALSE(field(Point(std::numeric_limits<double>::quiet_NaN(), 0, 0)));
  // Without a mask (an empty name), the masked cells interpolate the zeros stored there.
  const Field unmasked(to_image(grid), FAS::parameters::mask_array_name(""));
  EXPECT_EQ(unmasked.mask_array(), nullptr);
  EXPECT_TRUE(unmasked(Point(0.01, 0.02, 0.03)));
  EXPECT_FALSE(field(Point(0.01, 0.02, 0.03)));
}

// A cube [0, 1]^3 of 3 x 3 x 3 hexahedra, each split into 6 tetrahedra around its diagonal
// (Kuhn's subdivision: the tetrahedra of neighbouring hexahedra share faces), mapped by an affine
// map so that no face is axis-aligned.
vtkSmartPointer<vtkUnstructuredGrid> tetrahedra(Point (*map)(double, double, double))
{
  const int n = 3;
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const Point p = map(double(i) / n, double(j) / n, double(k) / n);
        points->InsertNextPoint(p.x(), p.y(), p.z());
      }
  mesh->SetPoints(points);
  auto id = [n](int i, int j, int k) { return vtkIdType(i + (n + 1) * (j + (n + 1) * k)); };
  // The 6 paths from corner (0,0,0) to (1,1,1) along the axes, one tetrahedron each.
  const int order[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& o : order) {
          int c[3] = {i, j, k};
          vtkIdType tet[4];
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[o[s]];
            tet[s + 1] = id(c[0], c[1], c[2]);
          }
          mesh->InsertNextCell(VTK_TETRA, 4, tet);
        }
  return mesh;
}

Point sheared(double u, double v, double w) { return Point(1 + 2 * u + 0.3 * v, -0.5 + 1.5 * v + 0.2 * w, 0.25 + w + 0.1 * u); }

Vector linear_velocity(const Point& p)
{
  return Vector(0.5 + 2 * p.x() - p.y() + 0.25 * p.z(), -1 + 0.5 * p.x() + 3 * p.z(), 2 - p.x() + p.y() - 0.75 * p.z());
}

// The tetrahedra of the sheared cube with linear_velocity() at their points, as the point array "U".
vtkSmartPointer<vtkUnstructuredGrid> linear_field_on_tetrahedra()
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = tetrahedra(&sheared);
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("U");
  velocity->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double x[3];
    mesh->GetPoint(i, x);
    const Vector v = linear_velocity(Point(x[0], x[1], x[2]));
    velocity->InsertNextTuple3(v.x(), v.y(), v.z());
  }
  mesh->GetPointData()->AddArray(velocity);
  return mesh;
}

TEST(VTKFlowField3, LinearFieldOnTetrahedraIsExact)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = linear_field_on_tetrahedra();
  const Field field(mesh.Get(), FAS::parameters::array_name("U"));
  CGAL::Random random(3);
  for (int i = 0; i < 3000; ++i) {
    // Anywhere inside: a random point of the unit cube, mapped.
    const Point p = sheared(random.get_double(), random.get_double(), random.get_double());
    const std::optional<Vector> got = field(p);
    ASSERT_TRUE(got) << p;
    EXPECT_LE(distance(*got, linear_velocity(p)), 1e-12) << p;
  }
  // Outside the sheared cube but inside its bounding box: no sample.
  EXPECT_FALSE(field(sheared(-0.05, 0.5, 0.5)));
  EXPECT_FALSE(field(sheared(0.5, 1.05, 0.5)));
  EXPECT_FALSE(field(sheared(0.5, 0.5, -0.05)));

  // A point mask that is 0 at one point: the cells around it give no sample near it, the others
  // still do.
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("fluid");
  mask->SetNumberOfTuples(mesh->GetNumberOfPoints());
  mask->Fill(1);
  mask->SetValue(0, 0); // the corner sheared(0, 0, 0)
  mesh->GetPointData()->AddArray(mask);
  const Field masked(mesh.Get(), FAS::parameters::array_name("U", FAS::parameters::mask_array_name("fluid")));
  EXPECT_FALSE(masked(sheared(0.05, 0.05, 0.05)));
  EXPECT_TRUE(masked(sheared(0.95, 0.95, 0.95)));
  EXPECT_TRUE(field(sheared(0.05, 0.05, 0.05)));
}

// Sampled from several threads at once (as use_parallelism(true) does), the field answers as it
// does on one thread: each thread has its own cell and weights for VTK's FindCell().
TEST(VTKFlowField3, ConcurrentSamplesEqualSerialOnes)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = linear_field_on_tetrahedra();
  const Field field(mesh.Get());
  CGAL::Random random(13);
  std::vector<Point> points;
  const CGAL::Bbox_3 box = field.bbox();
  for (int i = 0; i < 200000; ++i)
    points.push_back(random_point(random, box)); // inside and outside the sheared cube
  std::vector<std::optional<Vector>> serial(points.size()), concurrent(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    serial[i] = field(points[i]);
  std::set<std::thread::id> threads;
  std::mutex mutex;
  tbb::task_arena arena(4);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256), [&](const auto& range) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        threads.insert(std::this_thread::get_id());
      }
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        concurrent[i] = field(points[i]);
    });
  });
  EXPECT_GE(threads.size(), 2u);
  std::size_t inside = 0, differ = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    inside += serial[i] ? 1 : 0;
    differ += serial[i] != concurrent[i] ? 1 : 0;
  }
  EXPECT_GT(inside, points.size() / 4);
  EXPECT_EQ(differ, 0u);
}

TEST(VTKFlowField3, CellDataGivesTheCellValue)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(5, 4, 3);
  image->SetOrigin(-1, 0, 2);
  image->SetSpacing(0.5, 1, 2);
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("cell_velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> solid;
  solid->SetName("open");
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        velocity->InsertNextTuple3(i, 10 * j, 100 * k + 1);
        solid->InsertNextValue(i == 3 && j == 2 ? 0 : 1);
      }
  image->GetCellData()->AddArray(velocity);
  image->GetCellData()->AddArray(solid);
  const Field field(image.Get()); // the only 3-component array, a cell array; no "inside"
  EXPECT_TRUE(field.velocity_on_cells());
  const Field masked(image.Get(), FAS::parameters::mask_array_name("open"));
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        // Anywhere strictly inside cell (i, j, k): its value.
        const Point p(-1 + 0.5 * (i + 0.3), j + 0.8, 2 + 2 * (k + 0.45));
        const std::optional<Vector> got = field(p);
        ASSERT_TRUE(got) << p;
        EXPECT_EQ(*got, Vector(i, 10 * j, 100 * k + 1));
        EXPECT_EQ(bool(masked(p)), !(i == 3 && j == 2)) << p;
      }
}

TEST(VTKFlowField3, BadInputIsRefusedWithTheArrayAndTheDataSetNamed)
{
  expect_invalid_argument([] { Field field(nullptr); }, {"VTK_flow_field_3", "null"});
  expect_invalid_argument([] { Field field(vtkSmartPointer<vtkImageData>::New().Get()); },
                          {"vtkImageData", "0 cells", "has no cells"});

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(3, 3, 3);
  vtkNew<vtkFloatArray> pressure;
  pressure->SetName("p");
  pressure->SetNumberOfTuples(27);
  pressure->Fill(0);
  image->GetPointData()->AddArray(pressure);
  expect_invalid_argument([&] { Field field(image.Get()); },
                          {"vtkImageData", "27 points, 8 cells", "no 3-component point or cell array",
                           "its arrays: 'p' (point data, 1 components)"});
  expect_invalid_argument([&] { Field field(image.Get(), FAS::parameters::array_name("U")); },
                          {"no array named 'U'", "vtkImageData"});
  expect_invalid_argument([&] { Field field(image.Get(), FAS::parameters::array_name("p")); },
                          {"'p'", "vtkImageData", "1 components; expected 3"});

  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("U");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(27);
  velocity->Fill(1);
  image->GetPointData()->AddArray(velocity);
  expect_invalid_argument([&] { Field field(image.Get(), FAS::parameters::mask_array_name("solid")); },
                          {"no mask array named 'solid'", "'p' (point data)"});
  expect_invalid_argument([&] { Field field(image.Get(), FAS::parameters::mask_array_name("U")); },
                          {"mask array 'U'", "3 components; expected 1"});
  vtkNew<vtkFloatArray> short_array;
  short_array->SetName("V");
  short_array->SetNumberOfComponents(3);
  short_array->SetNumberOfTuples(5);
  short_array->Fill(1);
  image->GetCellData()->AddArray(short_array);
  expect_invalid_argument([&] { Field field(image.Get(), FAS::parameters::array_name("V")); },
                          {"'V'", "5 tuples; expected 8 (one per cell)"});
  // And the good array is accepted.
  const Field field(image.Get(), FAS::parameters::array_name("U"));
  EXPECT_EQ(field(Point(1, 1, 1)), std::optional<Vector>(Vector(1, 1, 1)));
}

// The deformation of a disk over a point source, on the VTK image and on the grid of the same
// samples: the same surface; and on the VTK image in parallel, the same as serially.
TEST(VTKFlowField3, DeformationOnImageEqualsRegularGridAndIsTheSameInParallel)
{
  const Grid grid = point_source_grid({{21, 21, 29}});
  const Field field(to_image(grid));
  auto deform = [](const auto& f, bool parallel) {
    Mesh tm;
    FAS::make_disk_patch(tm, Point(0.1, 0.2, 1.5), Vector(0.2, 0.1, 1.0), 0.5, 1000);
    FAS::Flow_aligned_deformation<Mesh, std::decay_t<decltype(f)>> deformation(
        tm, f, FAS::Alignment::ORTHOGONAL, FAS::parameters::use_parallelism(parallel).number_of_iterations(20));
    deformation.run();
    return tm;
  };
  const Mesh on_grid = deform(grid, false), on_image = deform(field, false), parallel = deform(field, true);
  ASSERT_EQ(on_grid.number_of_vertices(), on_image.number_of_vertices());
  ASSERT_EQ(on_grid.number_of_vertices(), parallel.number_of_vertices());
  double moved = 0, to_grid = 0, to_serial = 0;
  Mesh start;
  FAS::make_disk_patch(start, Point(0.1, 0.2, 1.5), Vector(0.2, 0.1, 1.0), 0.5, 1000);
  for (auto v : on_grid.vertices()) {
    moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(on_grid.point(v), start.point(v))));
    to_grid = (std::max)(to_grid, std::sqrt(CGAL::squared_distance(on_grid.point(v), on_image.point(v))));
    to_serial = (std::max)(to_serial, std::sqrt(CGAL::squared_distance(parallel.point(v), on_image.point(v))));
  }
  EXPECT_GT(moved, 0.01); // the surface did bend
  EXPECT_LE(to_grid, 1e-9);
  EXPECT_LE(to_serial, 1e-9);
}

// ../shared/data read by VTK's reader into VTK_flow_field_3, and by the package's readers into
// Regular_grid_flow_field_3 (the grid, with its "inside" mask) and Unstructured_flow_field_3 (the
// native cells): the same samples.
TEST(VTKFlowField3, SharedCylinderDataReadByVTKAgreesWithThePackagesReaders)
{
  const std::string folder = FAS_SHARED_DATA_DIR;
  const std::string grid_file = folder + "/CYLINDER_grid.vtk", cells_file = folder + "/CYLINDER_cells.vtk";
  if (!std::ifstream(grid_file).good() || !std::ifstream(cells_file).good())
    GTEST_SKIP() << "CYLINDER_grid.vtk or CYLINDER_cells.vtk not found in FAS_SHARED_DATA_DIR (" << folder << ")";
  auto read = [](const std::string& file) {
    vtkNew<vtkDataSetReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    return vtkSmartPointer<vtkDataSet>(reader->GetOutput());
  };

  Grid grid;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(grid_file, grid, FAS::parameters::error_message(&error))) << error;
  const Field on_grid(read(grid_file).Get(), FAS::parameters::array_name("velocity"));
  ASSERT_NE(on_grid.mask_array(), nullptr);
  FAS::Unstructured_flow_field_3<K> cells;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(cells_file, cells, FAS::parameters::error_message(&error)))
      << error;
  const Field on_cells(read(cells_file).Get());

  CGAL::Random random(5);
  int both_grid = 0, both_cells = 0, disagree_cells = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Point p = random_point(random, grid.bbox());
    const std::optional<Vector> a = grid(p), b = on_grid(p);
    ASSERT_EQ(bool(a), bool(b)) << p;
    if (a) {
      ++both_grid;
      EXPECT_LE(distance(*a, *b), 1e-12 * (1 + std::sqrt(a->squared_length()))) << p;
    }
    const std::optional<Vector> c = cells(p), d = on_cells(p);
    if (bool(c) != bool(d))
      ++disagree_cells; // within VTK's parametric tolerance of the cylinder's wall
    else if (c) {
      ++both_cells;
      // VTK inverts a hexahedron's map to a parametric tolerance of 1e-3 between Newton steps.
      EXPECT_LE(distance(*c, *d), 1e-6 * (1 + std::sqrt(c->squared_length()))) << p;
    }
  }
  EXPECT_GT(both_grid, n / 2);
  EXPECT_GT(both_cells, n / 2);
  EXPECT_LE(disagree_cells, n / 100);
}

// The velocity array "U" of `mesh` as float values: the precision make_unstructured_flow_field()
// keeps without loss.
void velocity_as_float(vtkUnstructuredGrid* mesh)
{
  vtkDataArray* doubles = mesh->GetPointData()->GetArray("U");
  vtkNew<vtkFloatArray> floats;
  floats->SetName("U");
  floats->DeepCopy(doubles);
  mesh->GetPointData()->RemoveArray("U");
  mesh->GetPointData()->AddArray(floats);
}

// The grid in memory gives the field the package's reader makes of the same file, sample for
// sample (the same float arrays, the same cells); and VTK_flow_field_3's samples up to VTK's
// tolerance.
TEST(MakeUnstructuredFlowField, SharedCylinderCellsGiveTheReadersField)
{
  const std::string file = std::string(FAS_SHARED_DATA_DIR) + "/CYLINDER_cells.vtk";
  if (!std::ifstream(file).good())
    GTEST_SKIP() << "CYLINDER_cells.vtk not found in FAS_SHARED_DATA_DIR (" << FAS_SHARED_DATA_DIR << ")";
  vtkNew<vtkDataSetReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  const std::optional<FAS::Unstructured_flow_field_3<K>> converted =
      FAS::make_unstructured_flow_field<K>(reader->GetOutput());
  ASSERT_TRUE(converted);
  FAS::Unstructured_flow_field_3<K> read;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, read, FAS::parameters::error_message(&error))) << error;
  EXPECT_EQ(converted->number_of_cells(), read.number_of_cells());
  EXPECT_EQ(converted->number_of_points(), read.number_of_points());
  const Field through_VTK(reader->GetOutput());
  CGAL::Random random(11);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Point p = random_point(random, read.bbox());
    const std::optional<Vector> a = (*converted)(p), b = read(p);
    ASSERT_EQ(bool(a), bool(b)) << p;
    if (!a)
      continue;
    ++inside;
    EXPECT_EQ(*a, *b) << p;
    if (const std::optional<Vector> c = through_VTK(p))
      EXPECT_LE(distance(*a, *c), 1e-6 * (1 + std::sqrt(a->squared_length()))) << p;
  }
  EXPECT_GT(inside, 1000);
}

TEST(MakeUnstructuredFlowField, LinearFieldOnTetrahedraIsExact)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = linear_field_on_tetrahedra();
  velocity_as_float(mesh);
  const std::optional<FAS::Unstructured_flow_field_3<K>> field =
      FAS::make_unstructured_flow_field<K>(mesh.Get(), FAS::parameters::array_name("U"));
  ASSERT_TRUE(field);
  EXPECT_EQ(field->number_of_cells(), std::size_t(mesh->GetNumberOfCells()));
  CGAL::Random random(3);
  for (int i = 0; i < 1000; ++i) {
    const Point p = sheared(random.get_double(), random.get_double(), random.get_double());
    const std::optional<Vector> got = (*field)(p);
    ASSERT_TRUE(got) << p;
    // The point values are rounded to float: a linear field up to that rounding.
    EXPECT_LE(distance(*got, linear_velocity(p)), 1e-5) << p;
  }
  EXPECT_FALSE((*field)(sheared(-0.05, 0.5, 0.5)));
}

// The voxels of an image with its point mask "inside" (what RedistributeDataSet makes of an
// image): the package's reader of the same file into Regular_grid_flow_field_3 is the peer, the
// same trilinear samples and the same solid.
TEST(MakeUnstructuredFlowField, MaskedVoxelsSampleAsTheRegularGrid)
{
  const std::string file = std::string(FAS_SHARED_DATA_DIR) + "/CYLINDER_grid.vtk";
  if (!std::ifstream(file).good())
    GTEST_SKIP() << "CYLINDER_grid.vtk not found in FAS_SHARED_DATA_DIR (" << FAS_SHARED_DATA_DIR << ")";
  vtkNew<vtkDataSetReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataSet* image = reader->GetOutput();
  auto voxels = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble(); // the image's nodes as they are, not rounded to float
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
    points->InsertNextPoint(image->GetPoint(i));
  voxels->SetPoints(points);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < image->GetNumberOfCells(); ++c) {
    image->GetCellPoints(c, ids);
    voxels->InsertNextCell(image->GetCellType(c), ids);
  }
  voxels->GetPointData()->ShallowCopy(image->GetPointData());
  ASSERT_EQ(voxels->GetCellType(0), VTK_VOXEL);
  const std::optional<FAS::Unstructured_flow_field_3<K>> field = FAS::make_unstructured_flow_field<K>(voxels.Get());
  ASSERT_TRUE(field);
  EXPECT_LT(field->number_of_cells(), std::size_t(image->GetNumberOfCells())) << "the solid cells left out";

  Grid grid;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_VTK_flow_field(file, grid, FAS::parameters::error_message(&error))) << error;
  ASSERT_TRUE(grid.has_mask());
  CGAL::Random random(17);
  int fluid = 0, solid = 0;
  for (int i = 0; i < 3000; ++i) {
    const Point p = random_point(random, grid.bbox());
    const std::optional<Vector> a = (*field)(p), b = grid(p);
    ASSERT_EQ(bool(a), bool(b)) << p;
    (a ? fluid : solid) += 1;
    if (a)
      EXPECT_LE(distance(*a, *b), 1e-9 * (1 + std::sqrt(b->squared_length()))) << p;
  }
  EXPECT_GT(fluid, 1000);
  EXPECT_GT(solid, 10);
}

// What Unstructured_flow_field_3 cannot hold without a change of its samples stays with VTK.
TEST(MakeUnstructuredFlowField, GridsItCannotHoldAreLeftToVTK)
{
  auto make = [](vtkDataSet* data_set) { return FAS::make_unstructured_flow_field<K>(data_set); };
  vtkSmartPointer<vtkUnstructuredGrid> doubles = linear_field_on_tetrahedra();
  EXPECT_FALSE(make(doubles.Get())) << "a double velocity array would be rounded";
  EXPECT_FALSE(make(nullptr));
  EXPECT_FALSE(make(vtkSmartPointer<vtkUnstructuredGrid>::New().Get())) << "no cell";
  EXPECT_FALSE(make(to_image(point_source_grid({4, 4, 4})).Get())) << "not an unstructured grid";

  vtkSmartPointer<vtkUnstructuredGrid> floats = linear_field_on_tetrahedra();
  velocity_as_float(floats);
  ASSERT_TRUE(make(floats.Get()));
  EXPECT_FALSE(FAS::make_unstructured_flow_field<K>(floats.Get(), FAS::parameters::array_name("V")))
      << "no such array";

  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("inside");
  mask->SetNumberOfTuples(floats->GetNumberOfPoints());
  mask->Fill(0);
  floats->GetPointData()->AddArray(mask);
  EXPECT_FALSE(make(floats.Get())) << "every cell solid";
  EXPECT_TRUE(FAS::make_unstructured_flow_field<K>(floats.Get(), FAS::parameters::mask_array_name("")))
      << "a mask not asked for";
  floats->GetPointData()->RemoveArray("inside");

  vtkNew<vtkFloatArray> on_cells;
  on_cells->SetName("W");
  on_cells->SetNumberOfComponents(3);
  on_cells->SetNumberOfTuples(floats->GetNumberOfCells());
  on_cells->Fill(1);
  floats->GetCellData()->AddArray(on_cells);
  EXPECT_FALSE(FAS::make_unstructured_flow_field<K>(floats.Get(), FAS::parameters::array_name("W")))
      << "cell data";

  const vtkIdType quad[4] = {0, 1, 5, 4};
  floats->InsertNextCell(VTK_QUAD, 4, quad);
  EXPECT_FALSE(make(floats.Get())) << "a cell that is not a tetrahedron, hexahedron, wedge or pyramid";
}

} // namespace

} // namespace test_VTK_flow_field_3
