// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every flow-field reader needs before it parses: the error it throws internally (turned
// into `false` + message by its public function), the whole file as bytes, and tokens shown in
// messages without control characters.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_READ_FILE_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_READ_FILE_H

#include <cctype>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Thrown inside the readers only, with the complete message ("reader: file: where: what").
struct Read_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The contents of `filename`; throws `Read_error` naming `reader` and the file if it cannot be
/// read.  Reading the whole file at once is the fastest way on every system (one `read()`), and
/// lets the parsers check every count against the bytes that are really there.
inline std::string read_file_contents(const std::string& filename, const std::string& reader)
{
  std::ifstream is(filename, std::ios::binary);
  if (!is)
    throw Read_error(reader + ": " + filename + ": cannot open the file for reading");
  is.seekg(0, std::ios::end);
  const std::streamoff size = is.tellg();
  if (size < 0)
    throw Read_error(reader + ": " + filename + ": cannot determine the size of the file (not a regular file?)");
  std::string contents;
  contents.resize(static_cast<std::size_t>(size));
  is.seekg(0, std::ios::beg);
  is.read(&contents[0], size);
  if (!is)
    throw Read_error(reader + ": " + filename + ": reading the file failed");
  return contents;
}

/// A token shown in a message: at most 40 characters, non-printable bytes escaped as `\xNN`.
inline std::string printable(std::string_view s)
{
  std::string r;
  for (std::size_t i = 0; i < s.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isprint(c))
      r += static_cast<char>(c);
    else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      r += hex;
    }
  }
  if (s.size() > 40)
    r += "...";
  return r;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_READ_FILE_H
