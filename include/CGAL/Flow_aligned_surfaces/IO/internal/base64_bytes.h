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

/// The value of a base64 digit, -1 for '=', -2 for any other character.
inline int base64_digit(unsigned char c)
{
  if (c >= 'A' && c <= 'Z')
    return c - 'A';
  if (c >= 'a' && c <= 'z')
    return c - 'a' + 26;
  if (c >= '0' && c <= '9')
    return c - '0' + 52;
  if (c == '+')
    return 62;
  if (c == '/')
    return 63;
  return c == '=' ? -1 : -2;
}

/// Decodes `text` into `out` (replaced).  Returns -1 on success, else the offset in `text` of
/// the first character that is not base64 or ends a group too early (the caller names it).
inline std::ptrdiff_t decode_base64(std::string_view text, std::string& out)
{
  out.clear();
  out.reserve(text.size() / 4 * 3);
  int group[4];
  std::size_t filled = 0, group_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
      continue;
    const int d = base64_digit(c);
    if (d == -2 || (d == -1 && filled < 2))
      return static_cast<std::ptrdiff_t>(i);
    if (filled == 0)
      group_start = i;
    group[filled++] = d;
    if (filled < 4)
      continue;
    filled = 0;
    if (group[2] == -1 && group[3] != -1)
      return static_cast<std::ptrdiff_t>(group_start);
    const unsigned bits = (unsigned(group[0]) << 18) | (unsigned(group[1]) << 12) |
                          (group[2] < 0 ? 0u : unsigned(group[2]) << 6) | (group[3] < 0 ? 0u : unsigned(group[3]));
    out += static_cast<char>(bits >> 16);
    if (group[2] >= 0)
      out += static_cast<char>((bits >> 8) & 0xffu);
    if (group[3] >= 0)
      out += static_cast<char>(bits & 0xffu);
  }
  return filled == 0 ? -1 : static_cast<std::ptrdiff_t>(group_start);
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_BYTES_H
