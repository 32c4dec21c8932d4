// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decoding of binary numbers as data files store them: a type (8 to 64 bits, integer or IEEE
// float) and a byte order, independent of the host's.  Readers choose the decoding once per
// array, then call `decode_binary_number()` per value.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BINARY_NUMBERS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BINARY_NUMBERS_H

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

enum class Byte_order { BIG_ENDIAN_ORDER, LITTLE_ENDIAN_ORDER };

enum class Binary_type { FLOAT32, FLOAT64, UINT8, INT8, UINT16, INT16, UINT32, INT32, UINT64, INT64 };

/// Bytes per value.
inline std::size_t binary_type_size(Binary_type type)
{
  switch (type) {
  case Binary_type::UINT8:
  case Binary_type::INT8:
    return 1;
  case Binary_type::UINT16:
  case Binary_type::INT16:
    return 2;
  case Binary_type::FLOAT32:
  case Binary_type::UINT32:
  case Binary_type::INT32:
    return 4;
  default:
    return 8;
  }
}

/// The value stored at `p` (which needs no alignment), as a double.
inline double decode_binary_number(Binary_type type, Byte_order order, const unsigned char* p)
{
  // Assembled byte by byte, most significant first, so the host's order never matters.
  auto bits = [p, order](int n) {
    std::uint64_t u = 0;
    if (order == Byte_order::BIG_ENDIAN_ORDER)
      for (int i = 0; i < n; ++i)
        u = (u << 8) | p[i];
    else
      for (int i = n - 1; i >= 0; --i)
        u = (u << 8) | p[i];
    return u;
  };
  switch (type) {
  case Binary_type::FLOAT32: {
    const std::uint32_t u = static_cast<std::uint32_t>(bits(4));
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
  case Binary_type::FLOAT64: {
    const std::uint64_t u = bits(8);
    double d;
    std::memcpy(&d, &u, 8);
    return d;
  }
  case Binary_type::UINT8:
    return p[0];
  case Binary_type::INT8:
    return static_cast<signed char>(p[0]);
  case Binary_type::UINT16:
    return static_cast<double>(bits(2));
  case Binary_type::INT16:
    return static_cast<std::int16_t>(bits(2));
  case Binary_type::UINT32:
    return static_cast<double>(bits(4));
  case Binary_type::INT32:
    return static_cast<std::int32_t>(bits(4));
  case Binary_type::UINT64:
    return static_cast<double>(bits(8));
  case Binary_type::INT64:
    break;
  }
  return static_cast<double>(static_cast<std::int64_t>(bits(8)));
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BINARY_NUMBERS_H
