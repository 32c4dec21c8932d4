// The files a user opens, read back by other readers: the PNG by libpng's own reader (texel
// values round(255 c), top row first), the OBJ by parsing its v/vt/f lines and its MTL, the VTP
// by VTK's vtkXMLPolyDataReader in VTK/test_flow_texture_IO_VTK.cpp.

#include "png_test_reader.h"
#include "test_files.h"
#include "test_kernel.h"
#include "textured_patch.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_PNG.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_textured_OBJ.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_flow_texture_IO {

namespace {

using namespace fas_test;
using Mesh = Textured_mesh;
using Vertex = Mesh::Vertex_index;

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
                                                   FAS::parameters::error_message(&error));
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

// The MTL and the PNG beside the OBJ are files the caller did not name: a user's file of that name
// is kept and nothing is written; the files of an earlier call for the same OBJ are replaced.
TEST(FlowTextureIO, OBJKeepsAUsersFileBesideItAndReplacesItsOwn)
{
  Mesh tm;
  const auto uv = textured_patch(tm);
  const FAS::Texture_image texture = FAS::make_arrow_texture(16, 16, 2, 2);
  const std::string obj = temporary_file("flow_texture_io_", "keep.obj");
  const std::string mtl = temporary_file("flow_texture_io_", "keep.mtl");
  const std::string png = temporary_file("flow_texture_io_", "keep.png");
  std::filesystem::remove(obj);
  std::filesystem::remove(mtl);
  write_bytes(png, "the user's picture");
  std::string error;
  EXPECT_FALSE(FAS::IO::write_textured_OBJ(obj, tm, uv, texture, FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("flow_texture_io_keep.png exists"), std::string::npos) << error;
  EXPECT_NE(error.find("nothing was written"), std::string::npos) << error;
  EXPECT_EQ(read_bytes(png), "the user's picture");
  EXPECT_FALSE(std::filesystem::exists(obj));
  EXPECT_FALSE(std::filesystem::exists(mtl));

  // A material file that is not this OBJ's is kept too.
  std::filesystem::remove(png);
  write_bytes(mtl, "newmtl brick\n");
  EXPECT_FALSE(FAS::IO::write_textured_OBJ(obj, tm, uv, texture, FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("flow_texture_io_keep.mtl exists"), std::string::npos) << error;
  EXPECT_EQ(read_bytes(mtl), "newmtl brick\n");

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_PNG
  // Written once from scratch, then again over its own files.
  std::filesystem::remove(mtl);
  ASSERT_TRUE(FAS::IO::write_textured_OBJ(obj, tm, uv, texture, FAS::parameters::error_message(&error)))
      << error;
  const Png_picture first = read_png(png);
  ASSERT_TRUE(FAS::IO::write_textured_OBJ(obj, tm, uv, FAS::make_arrow_texture(8, 8, 2, 2),
                                          FAS::parameters::error_message(&error)))
      << error;
  EXPECT_EQ(first.width, 16u);
  EXPECT_EQ(read_png(png).width, 8u);
#endif
}

} // namespace

} // namespace test_flow_texture_IO
