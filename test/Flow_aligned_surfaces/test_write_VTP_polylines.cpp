// IO::write_VTP_polylines(): a wrong array size is refused, named, and leaves an existing file
// untouched (the file read back by VTK: VTK/test_write_VTP_polylines_VTK.cpp).

#include "polylines_test_data.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_write_VTP_polylines {

namespace {

using namespace fas_test;

const std::vector<std::vector<Point_3>>& lines = test_polylines();

TEST(write_VTP_polylines, wrong_array_size_leaves_the_file)
{
  const auto path = polylines_scratch("kept.vtp");
  {
    std::ofstream os(path);
    os << "previous content";
  }
  std::string error;
  EXPECT_FALSE(FAS::IO::write_VTP_polylines(path.string(), lines, {{"t", 1, {0., 1.}}}, {}, &error));
  EXPECT_NE(error.find("write_VTP_polylines"), std::string::npos) << error;
  EXPECT_NE(error.find("kept.vtp"), std::string::npos) << error;
  EXPECT_NE(error.find("'t' has 2 values, expected 5"), std::string::npos) << error;
  std::ifstream is(path);
  std::stringstream ss;
  ss << is.rdbuf();
  EXPECT_EQ(ss.str(), "previous content");
}

} // namespace

} // namespace test_write_VTP_polylines
