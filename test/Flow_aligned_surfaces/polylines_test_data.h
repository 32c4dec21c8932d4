// The polylines that the tests of IO::write_VTP_polylines() write, and their scratch folder.

#ifndef FAS_TEST_POLYLINES_TEST_DATA_H
#define FAS_TEST_POLYLINES_TEST_DATA_H

#include "test_kernel.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace fas_test {

// Two polylines, 3 and 2 points, with a coordinate that no short decimal holds and a tiny one.
inline const std::vector<std::vector<Point_3>>& test_polylines()
{
  static const std::vector<std::vector<Point_3>> lines = {
      {Point_3(0, 0, 0), Point_3(1, 0.5, 0.25), Point_3(2, 1. / 3, -1)}, {Point_3(5, 6, 7), Point_3(-1e-300, 2, 3)}};
  return lines;
}

inline std::filesystem::path polylines_scratch(const std::string& name)
{
  const auto dir = std::filesystem::path(::testing::TempDir()) / "fas_test_write_VTP_polylines";
  std::filesystem::create_directories(dir);
  return dir / name;
}

} // namespace fas_test

#endif // FAS_TEST_POLYLINES_TEST_DATA_H
