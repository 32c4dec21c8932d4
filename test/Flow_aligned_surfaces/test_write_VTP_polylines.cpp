// IO::write_VTP_polylines(): a wrong array size is refused, named, and leaves an existing file
// untouched; the digits follow `stream_precision` (the file read back by VTK:
// VTK/test_write_VTP_polylines_VTK.cpp).

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
  EXPECT_FALSE(FAS::IO::write_VTP_polylines(path.string(), lines, {{"t", 1, {0., 1.}}}, {},
                                            FAS::parameters::error_message(&error)));
  EXPECT_NE(error.find("write_VTP_polylines"), std::string::npos) << error;
  EXPECT_NE(error.find("kept.vtp"), std::string::npos) << error;
  EXPECT_NE(error.find("'t' has 2 values, expected 5"), std::string::npos) << error;
  std::ifstream is(path);
  std::stringstream ss;
  ss << is.rdbuf();
  EXPECT_EQ(ss.str(), "previous content");
}

std::string file_text(const std::filesystem::path& path)
{
  std::ifstream is(path);
  std::stringstream ss;
  ss << is.rdbuf();
  return ss.str();
}

TEST(write_VTP_polylines, stream_precision_sets_the_digits)
{
  const auto path = polylines_scratch("precision.vtp");
  std::string error;
  ASSERT_TRUE(
      FAS::IO::write_VTP_polylines(path.string(), lines, {}, {}, FAS::parameters::error_message(&error)))
      << error;
  EXPECT_NE(file_text(path).find("2 0.33333333333333331 -1\n"), std::string::npos) << "17 digits by default";
  ASSERT_TRUE(FAS::IO::write_VTP_polylines(
      path.string(), lines, {}, {},
      FAS::parameters::error_message(&error, CGAL::parameters::stream_precision(4))))
      << error;
  EXPECT_NE(file_text(path).find("2 0.3333 -1\n"), std::string::npos) << file_text(path);
}

// The writers' check, public for programs that write the same arrays by other means.
TEST(write_VTP_polylines, check_VTP_array_sizes_gives_the_writers_message)
{
  std::string reason;
  EXPECT_TRUE(FAS::IO::check_VTP_array_sizes({{"t", 1, {0., 1., 2., 3., 4.}}}, 5,
                                             {{"v", 3, {0., 1., 2., 3., 4., 5.}}}, 2, reason));
  EXPECT_FALSE(FAS::IO::check_VTP_array_sizes({}, 5, {{"v", 3, {0., 1., 2.}}}, 2, reason));
  EXPECT_EQ(reason, "array 'v' has 3 values, expected 6");
}

} // namespace

} // namespace test_write_VTP_polylines
