// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decoding of base64 text (RFC 4648, the standard alphabet) for the VTK XML reader.  VTK
// encodes a header and the data after it as separate base64 runs, each padded with '=' to a
// multiple of 4 characters, so padding may end a group in the middle of the text: the bytes
// of all the runs are concatenated.  White space between groups is skipped.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_BYTES_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_BYTES_H

#include <cstddef>
#include <string>
#include <string_view>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// The value of each byte as a base64 digit: 0 to 63, or one of these.
enum : signed char { BASE64_PADDING = -1, BASE64_INVALID = -2, BASE64_SPACE = -3 };

struct Base64_table {
  signed char value[256];
  Base64_table()
  {
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (signed char& v : value)
      v = BASE64_INVALID;
    for (int d = 0; d < 64; ++d)
      value[static_cast<unsigned char>(digits[d])] = static_cast<signed char>(d);
    value[static_cast<unsigned char>('=')] = BASE64_PADDING;
    for (char c : {' ', '\n', '\r', '\t'})
      value[static_cast<unsigned char>(c)] = BASE64_SPACE;
  }
};

/// Decodes `text` into `out` (replaced).  Returns -1 on success, else the offset in `text` of
/// the first character that is not base64 or ends a group too early (the caller names it).
/// Groups of 4 digits without white space or padding, nearly all of a VTK file, take a fast
/// path; the others are gathered one character at a time.
inline std::ptrdiff_t decode_base64(std::string_view text, std::string& out)
{
  static const Base64_table table;
  const signed char* t = table.value;
  const unsigned char* p = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  out.resize(n / 4 * 3 + 3);
  char* o = &out[0];
  auto put = [&o](unsigned bits, int bytes) {
    *o++ = static_cast<char>(bits >> 16);
    if (bytes > 1)
      *o++ = static_cast<char>((bits >> 8) & 0xffu);
    if (bytes > 2)
      *o++ = static_cast<char>(bits & 0xffu);
  };
  std::size_t i = 0;
  while (i < n) {
    if (i + 4 <= n) {
      const int a = t[p[i]], b = t[p[i + 1]], c = t[p[i + 2]], d = t[p[i + 3]];
      if ((a | b | c | d) >= 0) {
        put((unsigned(a) << 18) | (unsigned(b) << 12) | (unsigned(c) << 6) | unsigned(d), 3);
        i += 4;
        continue;
      }
    }
    // One group the slow way: white space skipped, padding only at its end.
    int group[4];
    int filled = 0;
    std::size_t start = i;
    for (; i < n && filled < 4; ++i) {
      const int d = t[p[i]];
      if (d == BASE64_SPACE)
        continue;
      if (d == BASE64_INVALID || (d == BASE64_PADDING && filled < 2) ||
          (filled == 3 && d != BASE64_PADDING && group[2] == BASE64_PADDING))
        return static_cast<std::ptrdiff_t>(i);
      if (filled == 0)
        start = i;
      group[filled++] = d;
    }
    if (filled == 0)
      break; // white space at the end
    if (filled < 4)
      return static_cast<std::ptrdiff_t>(start);
    const int bytes = group[2] < 0 ? 1 : group[3] < 0 ? 2 : 3;
    put((unsigned(group[0]) << 18) | (unsigned(group[1]) << 12) | (group[2] < 0 ? 0u : unsigned(group[2]) << 6) |
            (group[3] < 0 ? 0u : unsigned(group[3])),
        bytes);
  }
  out.resize(static_cast<std::size_t>(o - out.data()));
  return -1;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_BYTES_H
