// What the tests of the uniform-grid readers share: files written byte by byte, numbers
// appended in either byte order, a sentinel field that a failed read must leave as it was, and
// the check of a failure (false, a message naming the file and every given part, field kept).

#ifndef FAS_TEST_GRID_READER_TEST_HELPERS_H
#define FAS_TEST_GRID_READER_TEST_HELPERS_H

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

namespace fas_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Grid_kernel;
typedef CGAL::Flow_aligned_surfaces::Regular_grid_flow_field_3<Grid_kernel> Grid;

inline void write_bytes(const std::string& filename, const std::string& bytes)
{
  std::ofstream os(filename, std::ios::binary | std::ios::trunc);
  os.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(bool(os)) << filename;
}

/// Appends the bytes of `v` (an arithmetic value) in the given byte order.
template <class T>
void append_binary(std::string& s, T v, bool big_endian)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  const unsigned one = 1;
  const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    s += static_cast<char>(b[host_little == big_endian ? sizeof(T) - 1 - i : i]);
}

/// A grid unlike the ones read, to detect that a failed read changed nothing.
inline Grid sentinel_grid()
{
  return Grid(Grid::Point_3(7, 7, 7), Grid::Vector_3(1, 1, 1), Grid::Dimensions{{2, 2, 2}},
              std::vector<float>(24, 3.f));
}

inline void expect_untouched(const Grid& g)
{
  const Grid s = sentinel_grid();
  EXPECT_EQ(g.dimensions(), s.dimensions());
  EXPECT_EQ(g.origin(), s.origin());
  EXPECT_EQ(g.spacing(), s.spacing());
  EXPECT_EQ(g.values(), s.values());
  EXPECT_FALSE(g.has_mask());
}

/// Writes `contents` to `file`, reads it with `read(file, grid, error)` into a sentinel grid and
/// expects `false`, a message naming the file and holding every one of `parts`, and the grid
/// untouched.
template <class Read>
void expect_read_failure(const std::string& file, const std::string& contents,
                         std::initializer_list<std::string> parts, const Read& read)
{
  write_bytes(file, contents);
  Grid g = sentinel_grid();
  std::string error;
  EXPECT_FALSE(read(file, g, &error)) << file;
  EXPECT_NE(error.find(file), std::string::npos) << "the message does not name the file: " << error;
  for (const std::string& part : parts)
    EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' is not in the message: " << error;
  expect_untouched(g);
}

} // namespace fas_test

#endif // FAS_TEST_GRID_READER_TEST_HELPERS_H
