// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decompression of an LZ4 block (the raw block format that VTK's vtkLZ4DataCompressor writes,
// one block per call).  Needs liblz4: available when `CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4` is
// defined and the program links liblz4 (the CMake target of the package does both when it
// finds the library); without it the readers say that this build cannot read LZ4 data.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_LZ4_BYTES_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_LZ4_BYTES_H

#include <cstddef>
#include <string>
#include <string_view>

#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4)
#include <lz4.h>
#include <climits>
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Whether `lz4_bytes()` can decompress (the package was built with liblz4).
inline constexpr bool have_lz4()
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4)
  return true;
#else
  return false;
#endif
}

/// Decompresses the LZ4 block `in` into `out`, which must then hold exactly `expected` bytes.
/// Returns an empty string on success, else what is wrong.
inline std::string lz4_bytes(std::string_view in, std::size_t expected, std::string& out)
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4)
  out.clear();
  // A sequence of LZ4 expands at most 255:1 (a length byte of 255 per 255 bytes of a match);
  // a larger claim is a lying header, refused before the output is allocated.
  if (expected / 255 > in.size() + 16)
    return "the " + std::to_string(in.size()) + " compressed bytes cannot expand to the " +
           std::to_string(expected) + " bytes the sizes give";
  if (in.size() > INT_MAX || expected > INT_MAX)
    return "an LZ4 block of more than 2 GB";
  out.resize(expected);
  const int n = LZ4_decompress_safe(in.data(), out.data(), static_cast<int>(in.size()), static_cast<int>(expected));
  if (n < 0)
    return "the LZ4 data are invalid";
  if (static_cast<std::size_t>(n) != expected)
    return "the LZ4 data expand to " + std::to_string(n) + " bytes but the sizes give " + std::to_string(expected);
  return std::string();
#else
  (void)in;
  (void)expected;
  (void)out;
  return "this build has no LZ4 decompression (build with liblz4: Debian liblz4-dev)";
#endif
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_LZ4_BYTES_H
