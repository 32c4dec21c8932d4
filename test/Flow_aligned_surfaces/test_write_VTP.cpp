// The VTP writer: what it writes reads back as the same mesh and arrays, and a
// failed write leaves the existing file as it was.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_write_VTP {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace FAS = CGAL::Flow_aligned_surfaces;

std::string read_file(const std::filesystem::path& path)
{
  std::ifstream is(path);
  std::stringstream ss;
  ss << is.rdbuf();
  return ss.str();
}

// The numbers inside the DataArray element whose opening tag matches `tag`.
std::vector<double> data_array(const std::string& xml, const std::string& tag)
{
  const std::size_t start = xml.find(tag);
  EXPECT_NE(start, std::string::npos) << tag;
  const std::size_t open = xml.find('>', start) + 1, close = xml.find("</DataArray>", open);
  std::istringstream is(xml.substr(open, close - open));
  std::vector<double> values;
  std::string token;
  while (is >> token)
    values.push_back(token == "NaN" ? std::nan("") : std::stod(token));
  return values;
}

std::filesystem::path scratch(const std::string& name)
{
  const auto dir = std::filesystem::path(::testing::TempDir()) / "fas_test_write_VTP";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(WriteVTP, MeshAndArraysReadBack)
{
  Mesh tm;
  FAS::make_disk_patch(tm, K::Point_3(1, 2, 3), K::Vector_3(0, 1, 1), 0.5, 40);
  std::vector<double> height, ids;
  for (auto v : tm.vertices())
    height.push_back(tm.point(v).z());
  for (auto f : tm.faces())
    ids.push_back(double(f.idx()));
  ids[3] = std::nan("");
  const auto path = scratch("disk.vtp");
  std::string error;
  ASSERT_TRUE(FAS::IO::write_VTP(path.string(), tm, {{"height", 1, height}}, {{"id", 1, ids}},
                                 FAS::parameters::error_message(&error)))
      << error;
  const std::string xml = read_file(path);
  EXPECT_NE(xml.find("NumberOfPoints=\"" + std::to_string(tm.number_of_vertices()) + "\""),
            std::string::npos);
  EXPECT_NE(xml.find("NumberOfPolys=\"" + std::to_string(tm.number_of_faces()) + "\""), std::string::npos);

  const auto points = data_array(xml, "<DataArray type=\"Float64\" NumberOfComponents=\"3\"");
  ASSERT_EQ(points.size(), 3 * tm.number_of_vertices());
  for (auto v : tm.vertices()) {
    EXPECT_EQ(points[3 * v.idx()], tm.point(v).x());
    EXPECT_EQ(points[3 * v.idx() + 2], tm.point(v).z());
  }
  const auto connectivity = data_array(xml, "Name=\"connectivity\"");
  const auto offsets = data_array(xml, "Name=\"offsets\"");
  ASSERT_EQ(offsets.size(), tm.number_of_faces());
  ASSERT_EQ(connectivity.size(), 3 * tm.number_of_faces());
  for (auto f : tm.faces()) {
    EXPECT_EQ(offsets[f.idx()], 3.0 * (f.idx() + 1));
    std::size_t k = 3 * f.idx();
    for (auto v : vertices_around_face(tm.halfedge(f), tm))
      EXPECT_EQ(connectivity[k++], double(v.idx()));
  }
  EXPECT_EQ(data_array(xml, "Name=\"height\""), height);
  const auto read_ids = data_array(xml, "Name=\"id\"");
  EXPECT_TRUE(std::isnan(read_ids[3]));
  EXPECT_EQ(read_ids[5], 5.0);
}

TEST(WriteVTP, FailureLeavesExistingFileAndNamesTheProblem)
{
  Mesh tm;
  FAS::make_planar_patch(tm, K::Point_3(0, 0, 0), K::Vector_3(0, 0, 1), 1, 1, 20);
  const auto path = scratch("keep.vtp");
  {
    std::ofstream(path) << "precious";
  }
  std::string error;
  EXPECT_FALSE(FAS::IO::write_VTP(path.string(), tm, {{"short", 1, {1.0, 2.0}}}, {},
                                  FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("short"), std::string::npos) << error;
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
  EXPECT_EQ(read_file(path), "precious");

  const auto unwritable = scratch("no_such_folder") / "x.vtp";
  EXPECT_FALSE(FAS::IO::write_VTP(unwritable.string(), tm, {}, {}, FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("cannot open"), std::string::npos) << error;
}

} // namespace

} // namespace test_write_VTP
