// Tests of internal/read_file.h's File_contents (the file's bytes, mapped or copied) and of
// internal/reserve_huge_pages.h: the bytes seen are exactly those written into hand-made files,
// and a file that cannot be read gives the message naming it.

#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reserve_huge_pages.h>

#include "test_files.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_file {

namespace FI = CGAL::Flow_aligned_surfaces::IO::internal;

namespace {

// Every byte value, a NUL inside, and a size that is not a multiple of a page (4096 + 4097).
std::string hand_made_bytes()
{
  std::string b = "# vtk DataFile Version 3.0\n";
  for (int i = 0; i < 256; ++i)
    b += static_cast<char>(i);
  b += std::string(4096 + 4097 - b.size(), 'x');
  b.back() = '\n';
  return b;
}

} // namespace

TEST(File_contents, sees_exactly_the_bytes_of_the_file)
{
  const std::string file = temporary_file("read_file_", "bytes.bin"), bytes = hand_made_bytes();
  write_bytes(file, bytes);
  const FI::File_contents c(file, "test_reader");
  ASSERT_EQ(c.view().size(), std::size_t(8193));
  EXPECT_TRUE(c.view() == bytes);
#if defined(__linux__) && !defined(CGAL_FLOW_ALIGNED_SURFACES_NO_MMAP)
  EXPECT_TRUE(c.is_mapped()); // a regular, non-empty file on Linux is mapped, not copied
#endif
}

TEST(File_contents, moved_contents_keep_their_bytes)
{
  const std::string file = temporary_file("read_file_", "moved.bin"), bytes = hand_made_bytes();
  write_bytes(file, bytes);
  FI::File_contents a(file, "test_reader");
  FI::File_contents b(std::move(a));
  EXPECT_TRUE(b.view() == bytes);
  const std::string small_file = temporary_file("read_file_", "small.bin");
  write_bytes(small_file, "abc");
  FI::File_contents s(small_file, "test_reader");
  s = std::move(b); // releases "abc", takes the big file
  EXPECT_TRUE(s.view() == bytes);
}

TEST(File_contents, empty_file_is_named_as_empty)
{
  const std::string file = temporary_file("read_file_", "empty.bin");
  write_bytes(file, "");
  try {
    FI::File_contents c(file, "test_reader");
    FAIL() << "no exception";
  } catch (const FI::Read_error& e) {
    EXPECT_EQ(std::string(e.what()), "test_reader: " + file + ": the file is empty (0 bytes)");
  }
}

TEST(File_contents, missing_file_is_named_in_the_message)
{
  const std::string file = temporary_file("read_file_", "does_not_exist.bin");
  try {
    FI::File_contents c(file, "test_reader");
    FAIL() << "no exception";
  } catch (const FI::Read_error& e) {
    EXPECT_EQ(std::string(e.what()), "test_reader: " + file + ": cannot open the file for reading");
  }
}

TEST(reserve_huge_pages, reserves_and_keeps_the_elements)
{
  std::vector<float> v = {1.f, 2.f, 3.f};
  const std::size_t n = std::size_t(3) << 20; // 12 MiB of floats: spans several huge pages
  FI::reserve_huge_pages(v, n);
  EXPECT_GE(v.capacity(), n);
  EXPECT_EQ(v, (std::vector<float>{1.f, 2.f, 3.f}));
  v.resize(n, 7.f);
  EXPECT_EQ(v[2], 3.f);
  EXPECT_EQ(v[n - 1], 7.f);
}

} // namespace test_read_file
