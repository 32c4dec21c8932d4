// The files a user opens, read back by other readers: the PNG by libpng's own reader (texel
// values round(255 c), top row first), the OBJ by parsing its v/vt/f lines and its MTL, the VTP
// by VTK's vtkXMLPolyDataReader, which must find the texture coordinates as TCoords.

#include "png_test_reader.h"
#include "test_files.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_PNG.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_textured_OBJ.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#ifdef FAS_HAVE_VTK
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#endif

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_flow_texture_IO {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using UV = std::array<double, 2>;

// A 3 x 2 patch with uv = (x, 2 y + 0.5) and a NaN at vertex 0.
Mesh::Property_map<Vertex, UV> textured_patch(Mesh& tm)
{
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 3.0, 2.0, 60);
  auto uv = tm.add_property_map<Vertex, UV>("v:uv").first;
  for (Vertex v : tm.vertices())
    uv[v] = {tm.point(v).x(), 2 * tm.point(v).y() + 0.5};
  uv[Vertex(0)][0] = std::nan("");
  return uv;
}

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_PNG
TEST(FlowTextureIO, PNGHoldsTheRoundedTexelsTopRowFirst)
{
  FAS::Texture_image image = FAS::make_noise_texture(20, 6, 3, 1);
  image(0, 0, 0) = 2.0f;          // clamped to 255
  image(1, 0, 1) = -1.0f;         // clamped to 0
  image(2, 0, 2) = std::nanf(""); // 0
  const std::string file = temporary_file("flow_texture_io_", "noise.png");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_PNG(file, image, &error)) << error;
  const Png_picture picture = read_png(file);
  const auto& bytes = picture.rgb;
  ASSERT_EQ(picture.width, 20u);
  ASSERT_EQ(picture.height, 6u);
  for (std::size_t row = 0; row < 6; ++row)
    for (std::size_t x = 0; x < 20; ++x)
      for (std::size_t c = 0; c < 3; ++c) {
        const float value = image(x, 5 - row, c); // the file's first row is the image's top (y = 5)
        const int expected = std::isnan(value) ? 0 : int(std::lround(255 * std::clamp(value, 0.0f, 1.0f)));
        ASSERT_EQ(int(bytes[3 * (row * 20 + x) + c]), expected) << x << ' ' << row << ' ' << c;
      }
  EXPECT_EQ(bytes[3 * (5 * 20 + 0) + 0], 255);
  EXPECT_EQ(bytes[3 * (5 * 20 + 1) + 1], 0);
  EXPECT_EQ(bytes[3 * (5 * 20 + 2) + 2], 0);
}
#endif

TEST(FlowTextureIO, PNGOfAnInconsistentImageIsRefusedAndNothingIsLost)
{
  const std::string file = temporary_file("flow_texture_io_", "kept.png");
  write_bytes(file, "keep me");
  FAS::Texture_image bad;
  bad.width = 4;
  bad.height = 4;
  bad.pixels.resize(5);
  std::string error;
  EXPECT_FALSE(FAS::IO::write_PNG(file, bad, &error));
  EXPECT_NE(error.find("kept.png"), std::string::npos) << error;
  EXPECT_NE(error.find("4 x 4"), std::string::npos) << error;
  EXPECT_EQ(read_bytes(file), "keep me");
}

TEST(FlowTextureIO, OBJHasOneTextureCoordinatePerVertexAndItsMaterial)
{
  Mesh tm;
  const auto uv = textured_patch(tm);
  const std::string obj = temporary_file("flow_texture_io_", "patch.obj");
  std::string error;
  const bool written = FAS::IO::write_textured_OBJ(obj, tm, uv, FAS::make_arrow_texture(32, 32, 2, 2),
                                                   CGAL::parameters::default_values(), &error);
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_PNG
  ASSERT_TRUE(written) << error;
#else
  EXPECT_FALSE(written);
  EXPECT_NE(error.find("libpng"), std::string::npos) << error;
#endif
  std::ifstream is(obj);
  std::string line, mtllib, usemtl;
  std::vector<std::array<double, 3>> points;
  std::vector<UV> texture_coordinates;
  std::size_t faces = 0;
  while (std::getline(is, line)) {
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "v") {
      std::array<double, 3> p;
      ls >> p[0] >> p[1] >> p[2];
      points.push_back(p);
    }
    else if (key == "vt") {
      UV t;
      ls >> t[0] >> t[1];
      texture_coordinates.push_back(t);
    }
    else if (key == "f") {
      std::string corner;
      while (ls >> corner) {
        const auto slash = corner.find('/');
        ASSERT_NE(slash, std::string::npos) << line;
        EXPECT_EQ(corner.substr(0, slash), corner.substr(slash + 1))
            << "vertex and vt indices agree: " << line;
      }
      ++faces;
    }
    else if (key == "mtllib")
      ls >> mtllib;
    else if (key == "usemtl")
      ls >> usemtl;
  }
  EXPECT_EQ(faces, tm.number_of_faces());
  ASSERT_EQ(points.size(), tm.number_of_vertices());
  ASSERT_EQ(texture_coordinates.size(), tm.number_of_vertices());
  for (Vertex v : tm.vertices()) {
    EXPECT_EQ(points[v][0], tm.point(v).x());
    if (v == Vertex(0)) {
      EXPECT_EQ(texture_coordinates[v], (UV{0, 0})) << "a NaN coordinate is written as 0 0";
      continue;
    }
    EXPECT_EQ(texture_coordinates[v][0], tm.point(v).x());
    EXPECT_EQ(texture_coordinates[v][1], 2 * tm.point(v).y() + 0.5);
  }
  EXPECT_EQ(mtllib, "flow_texture_io_patch.mtl");
  const std::string mtl = read_bytes(temporary_file("flow_texture_io_", "patch.mtl"));
  EXPECT_NE(mtl.find("newmtl " + usemtl), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("map_Kd flow_texture_io_patch.png"), std::string::npos) << mtl;
}

#ifdef FAS_HAVE_VTK
TEST(FlowTextureIO, VTKFindsTheTextureCoordinatesAndTheMaskInTheVTP)
{
  Mesh tm;
  const auto uv = textured_patch(tm);
  std::vector<double> tcoords, mask;
  for (Vertex v : tm.vertices())
    tcoords.insert(tcoords.end(), {uv[v][0], uv[v][1]});
  for (auto f : tm.faces())
    mask.push_back(double(f) / double(tm.number_of_faces()));
  FAS::IO::Data_array texture{"texture_coordinates", 2, tcoords};
  texture.texture_coordinates = true;
  const std::string file = temporary_file("flow_texture_io_", "patch.vtp");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTP(file, tm,
                                 {{"r", 1, std::vector<double>(tm.number_of_vertices(), 1.0)}, texture},
                                 {{"texture_mask", 1, mask}}, CGAL::parameters::default_values(), &error))
      << error;
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* polydata = reader->GetOutput();
  ASSERT_EQ(polydata->GetNumberOfPoints(), vtkIdType(tm.number_of_vertices()));
  vtkDataArray* t = polydata->GetPointData()->GetTCoords();
  ASSERT_NE(t, nullptr) << "no TCoords";
  EXPECT_STREQ(t->GetName(), "texture_coordinates");
  ASSERT_EQ(t->GetNumberOfComponents(), 2);
  EXPECT_TRUE(std::isnan(t->GetComponent(0, 0)));
  for (Vertex v : tm.vertices())
    if (v != Vertex(0)) {
      EXPECT_EQ(t->GetComponent(vtkIdType(v), 0), uv[v][0]);
      EXPECT_EQ(t->GetComponent(vtkIdType(v), 1), uv[v][1]);
    }
  vtkDataArray* m = polydata->GetCellData()->GetArray("texture_mask");
  ASSERT_NE(m, nullptr);
  for (auto f : tm.faces())
    EXPECT_EQ(m->GetComponent(vtkIdType(f), 0), mask[f]);
}
#endif

} // namespace

} // namespace test_flow_texture_IO
