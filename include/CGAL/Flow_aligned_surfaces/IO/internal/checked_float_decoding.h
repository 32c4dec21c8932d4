// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decoding of a run of binary numbers x_0 … x_{n-1} (one type, one byte order) into 32-bit
// floats, fused with the readers' range check: out[i] = float(x_i) whenever x_i is finite with
// |x_i| <= FLT_MAX (a "good" value); each bad value goes to the caller's check, in file order.
// The blocks are independent, so with TBB (`CGAL_LINKED_WITH_TBB`) they are decoded in parallel.
// Also the mask flags m_i = [x_i != 0], with a NaN reported likewise.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_CHECKED_FLOAT_DECODING_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_CHECKED_FLOAT_DECODING_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// The values per block of `decode_checked_floats()` (256 KiB of floats: a task of ~0.1 ms).
constexpr std::size_t checked_block_size = std::size_t(1) << 16;

/// Decodes `out[i]` for `i` in `[begin, end)`; returns whether one of them is bad (then `out[i]`
/// holds an unspecified value for it).
inline bool decode_checked_float_range(Binary_type type, Byte_order order, const unsigned char* p,
                                       std::size_t begin, std::size_t end, float* out)
{
  unsigned bad = 0;
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && defined(__ORDER_BIG_ENDIAN__)
  if (type == Binary_type::FLOAT32) {
    // A float is bad exactly when its exponent bits are all ones (infinity or NaN); the
    // branch-free loop on the bits vectorizes.
    const bool swap =
        (order == Byte_order::LITTLE_ENDIAN_ORDER) != (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__);
    std::uint32_t* o = reinterpret_cast<std::uint32_t*>(out);
    std::size_t i = begin;
#if defined(__SSE2__)
    // Four values at a time (compilers vectorize a byte swap only from SSSE3 on, which a header
    // cannot assume): the bytes swapped as 16-bit halves, then within them; bit 31 of
    // (u & exponent) + 2^23 is set exactly when the exponent bits are all ones.
    if (swap) {
      const __m128i exponent = _mm_set1_epi32(0x7f800000), one = _mm_set1_epi32(0x00800000);
      __m128i acc = _mm_setzero_si128();
      for (; i + 4 <= end; i += 4) {
        __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 4 * i));
        v = _mm_shufflehi_epi16(_mm_shufflelo_epi16(v, 0xb1), 0xb1);
        v = _mm_or_si128(_mm_slli_epi16(v, 8), _mm_srli_epi16(v, 8));
        acc = _mm_or_si128(acc, _mm_add_epi32(_mm_and_si128(v, exponent), one));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(o + i), v);
      }
      bad |= unsigned(_mm_movemask_ps(_mm_castsi128_ps(acc)));
    }
#endif
    if (swap)
      for (; i < end; ++i) {
        std::uint32_t u;
        std::memcpy(&u, p + 4 * i, 4);
        u = byte_swap(u);
        bad |= unsigned((u & 0x7f800000u) == 0x7f800000u);
        o[i] = u;
      }
    else
      for (; i < end; ++i) {
        std::uint32_t u;
        std::memcpy(&u, p + 4 * i, 4);
        bad |= unsigned((u & 0x7f800000u) == 0x7f800000u);
        o[i] = u;
      }
    return bad != 0;
  }
#endif
  // The other types through doubles, in blocks that stay in the L1 cache.
  const std::size_t size = binary_type_size(type);
  constexpr std::size_t chunk = 1024;
  double d[chunk];
  constexpr double largest = static_cast<double>((std::numeric_limits<float>::max)());
  for (std::size_t i0 = begin; i0 < end; i0 += chunk) {
    const std::size_t m = end - i0 < chunk ? end - i0 : chunk;
    decode_binary_numbers(type, order, p + size * i0, m, d);
    for (std::size_t j = 0; j < m; ++j) {
      const bool good = std::fabs(d[j]) <= largest; // false for NaN too
      bad |= unsigned(!good);
      out[i0 + j] = good ? static_cast<float>(d[j]) : std::numeric_limits<float>::quiet_NaN();
    }
  }
  return bad != 0;
}

/// Decodes the `count` values stored from `p` into `out` (room for `count` floats) as described
/// at the top, in parallel with TBB; then, in file order, sets `out[i] = check(i, x_i)` for each
/// bad value x_i (`check` returns the float to store, or throws: so the first bad value that
/// `check` refuses is the one reported, as in a serial decoding).  Returns the indices of the
/// blocks `[b·checked_block_size, (b+1)·checked_block_size)` that held a bad value, increasing
/// (usually none).
template <class Check>
std::vector<std::size_t> decode_checked_floats(Binary_type type, Byte_order order, const unsigned char* p,
                                               std::size_t count, float* out, const Check& check)
{
  const std::size_t blocks = (count + checked_block_size - 1) / checked_block_size;
  std::vector<unsigned char> bad(blocks, 0);
  auto decode_blocks = [&](std::size_t b0, std::size_t b1) {
    for (std::size_t b = b0; b < b1; ++b) {
      const std::size_t end = (b + 1) * checked_block_size;
      bad[b] =
          decode_checked_float_range(type, order, p, b * checked_block_size, end < count ? end : count, out);
    }
  };
#ifdef CGAL_LINKED_WITH_TBB
  if (blocks > 1)
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks),
                      [&](const tbb::blocked_range<std::size_t>& r) { decode_blocks(r.begin(), r.end()); });
  else
#endif
    decode_blocks(0, blocks);
  std::vector<std::size_t> r;
  const std::size_t size = binary_type_size(type);
  for (std::size_t b = 0; b < blocks; ++b) {
    if (!bad[b])
      continue;
    r.push_back(b);
    const std::size_t end = (std::min)((b + 1) * checked_block_size, count);
    for (std::size_t i = b * checked_block_size; i < end; ++i)
      if (!std::isfinite(out[i])) // a good value is a finite float
        out[i] = check(i, decode_binary_number(type, order, p + i * size));
  }
  return r;
}

/// Decodes the `count` mask values stored from `p` into the fluid flags `out[i] = [x_i != 0]`;
/// returns whether one of them is NaN (then `out` is unspecified, for the caller to check the
/// values one at a time).  8-bit integers, the usual mask, take a vectorized loop.
inline bool decode_checked_flags(Binary_type type, Byte_order order, const unsigned char* p,
                                 std::size_t count, unsigned char* out)
{
  if (type == Binary_type::UINT8 || type == Binary_type::INT8) {
    for (std::size_t i = 0; i < count; ++i)
      out[i] = p[i] != 0;
    return false;
  }
  const std::size_t size = binary_type_size(type);
  constexpr std::size_t chunk = 1024;
  double d[chunk];
  bool nan = false;
  for (std::size_t i0 = 0; i0 < count; i0 += chunk) {
    const std::size_t m = count - i0 < chunk ? count - i0 : chunk;
    decode_binary_numbers(type, order, p + size * i0, m, d);
    for (std::size_t j = 0; j < m; ++j) {
      nan |= std::isnan(d[j]);
      out[i0 + j] = d[j] != 0.;
    }
  }
  return nan;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_CHECKED_FLOAT_DECODING_H
