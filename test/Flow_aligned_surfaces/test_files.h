// Scratch files for the reader tests: a name in the test's temporary directory, and the bytes
// of a file written or read whole.

#ifndef FAS_TEST_TEST_FILES_H
#define FAS_TEST_TEST_FILES_H

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

/// `name` in the test's temporary directory, prefixed by `prefix` so that suites do not collide.
inline std::string temporary_file(const std::string& prefix, const std::string& name)
{
  return ::testing::TempDir() + prefix + name;
}

inline void write_bytes(const std::string& filename, const std::string& bytes)
{
  std::ofstream os(filename, std::ios::binary | std::ios::trunc);
  os.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(bool(os)) << filename;
}

inline std::string read_bytes(const std::string& filename)
{
  std::ifstream is(filename, std::ios::binary);
  std::ostringstream s;
  s << is.rdbuf();
  return s.str();
}

#endif // FAS_TEST_TEST_FILES_H
