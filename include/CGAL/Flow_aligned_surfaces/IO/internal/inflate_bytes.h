// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decompression of zlib or gzip streams (deflate, RFC 1950/1952) for the readers: AmiraMesh
// `HxZip` sections and NRRD `gzip` data.  Needs zlib: available when
// `CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB` is defined and the program links zlib (CMake:
// `find_package(ZLIB)`, `ZLIB::ZLIB`); without it the readers say that these encodings are not
// supported.  The output grows with the data really decompressed and stops at the size the
// header claims, so a lying header cannot make it allocate more than that the data give.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_INFLATE_BYTES_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_INFLATE_BYTES_H

#include <cstddef>
#include <string>
#include <string_view>

#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
#include <zlib.h>
#include <algorithm>
#include <climits>
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Whether `inflate_bytes()` can decompress (the package was built with zlib).
inline constexpr bool have_inflate()
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
  return true;
#else
  return false;
#endif
}

/// Decompresses the zlib or gzip stream `in` (the format is detected) into `out`, which must
/// then hold exactly `expected` bytes.  Returns an empty string on success, else what is wrong.
inline std::string inflate_bytes(std::string_view in, std::size_t expected, std::string& out)
{
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
  out.clear();
  // Deflate expands at most 1032:1; a larger claim is a lying header.
  if (expected / 1032 > in.size())
    return "the " + std::to_string(in.size()) + " compressed bytes cannot expand to the " +
           std::to_string(expected) + " bytes the sizes give";
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) // 15 + 32: a zlib or a gzip header
    return "zlib cannot start the decompression";
  std::size_t fed = 0;
  auto feed = [&] {
    if (z.avail_in == 0 && fed < in.size()) {
      const std::size_t more = std::min<std::size_t>(in.size() - fed, UINT_MAX);
      z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data() + fed));
      z.avail_in = static_cast<uInt>(more);
      fed += more;
    }
  };
  auto failure = [&](const std::string& why) {
    inflateEnd(&z);
    return why;
  };
  int status = Z_OK;
  while (out.size() < expected && status != Z_STREAM_END) {
    const std::size_t before = out.size();
    const std::size_t chunk = std::min<std::size_t>(expected - before, std::size_t(1) << 20);
    out.resize(before + chunk);
    z.next_out = reinterpret_cast<Bytef*>(&out[before]);
    z.avail_out = static_cast<uInt>(chunk);
    feed();
    status = inflate(&z, Z_NO_FLUSH);
    out.resize(before + chunk - z.avail_out);
    if (status == Z_BUF_ERROR && z.avail_in == 0 && fed >= in.size())
      return failure("the compressed data end after " + std::to_string(out.size()) + " of the " +
                     std::to_string(expected) + " bytes the sizes give");
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR)
      return failure("the compressed data are invalid (zlib: " + std::string(z.msg ? z.msg : "corrupt data") +
                     ") after " + std::to_string(out.size()) + " bytes");
  }
  // All the bytes the sizes give are there: the stream must not give one more.
  while (status != Z_STREAM_END) {
    char extra;
    z.next_out = reinterpret_cast<Bytef*>(&extra);
    z.avail_out = 1;
    feed();
    status = inflate(&z, Z_NO_FLUSH);
    if (z.avail_out == 0)
      return failure("the compressed data expand to more than the " + std::to_string(expected) +
                     " bytes the sizes give");
    if (status == Z_BUF_ERROR)
      break; // no end marker, but nothing more either
    if (status != Z_OK && status != Z_STREAM_END)
      return failure("the compressed data are invalid (zlib: " + std::string(z.msg ? z.msg : "corrupt data") +
                     ") after " + std::to_string(out.size()) + " bytes");
  }
  inflateEnd(&z);
  if (out.size() != expected)
    return "the compressed data expand to " + std::to_string(out.size()) + " bytes but the sizes give " +
           std::to_string(expected);
  return std::string();
#else
  (void)in;
  (void)expected;
  (void)out;
  return "decompression needs zlib (define CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB and link zlib)";
#endif
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_INFLATE_BYTES_H
