// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decompression of an xz stream (the format that VTK's vtkLZMADataCompressor writes, one stream
// per block).  Needs liblzma: available when `CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA` is defined
// and the program links liblzma (the CMake target of the package does both when it finds the
// library); without it the readers say that this build cannot read LZMA data.  The output
// grows with the data really decompressed and stops at the size the header claims, so a lying
// header cannot make it allocate more than the data give.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_LZMA_BYTES_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_LZMA_BYTES_H

#include <cstddef>
#include <string>
#include <string_view>

#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA)
#include <lzma.h>
#include <algorithm>
#include <cstdint>
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Whether `lzma_bytes()` can decompress (the package was built with liblzma).
inline constexpr bool have_lzma()
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA)
  return true;
#else
  return false;
#endif
}

/// Decompresses the xz stream `in` into `out`, which must then hold exactly `expected` bytes.
/// Returns an empty string on success, else what is wrong.
inline std::string lzma_bytes(std::string_view in, std::size_t expected, std::string& out)
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA)
  out.clear();
  lzma_stream z = LZMA_STREAM_INIT;
  // 256 MiB of dictionary at most: VTK's presets use at most 64 MiB.
  if (lzma_stream_decoder(&z, std::uint64_t(1) << 28, 0) != LZMA_OK)
    return "liblzma cannot start the decompression";
  z.next_in = reinterpret_cast<const std::uint8_t*>(in.data());
  z.avail_in = in.size();
  lzma_ret status = LZMA_OK;
  while (status == LZMA_OK) {
    const std::size_t before = out.size();
    // One byte more than expected is asked for, so that a stream giving more is seen.
    const std::size_t chunk = std::min<std::size_t>(expected + 1 - before, std::size_t(1) << 20);
    out.resize(before + chunk);
    z.next_out = reinterpret_cast<std::uint8_t*>(&out[before]);
    z.avail_out = chunk;
    status = lzma_code(&z, LZMA_FINISH);
    out.resize(before + chunk - z.avail_out);
    if (out.size() > expected)
      break;
  }
  lzma_end(&z);
  if (out.size() > expected)
    return "the LZMA data expand to more than the " + std::to_string(expected) + " bytes the sizes give";
  if (status != LZMA_STREAM_END)
    return "the LZMA data are invalid or truncated (liblzma error " + std::to_string(int(status)) + ") after " +
           std::to_string(out.size()) + " bytes";
  if (out.size() != expected)
    return "the LZMA data expand to " + std::to_string(out.size()) + " bytes but the sizes give " +
           std::to_string(expected);
  return std::string();
#else
  (void)in;
  (void)expected;
  (void)out;
  return "this build has no LZMA decompression (build with liblzma: Debian liblzma-dev)";
#endif
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_LZMA_BYTES_H
