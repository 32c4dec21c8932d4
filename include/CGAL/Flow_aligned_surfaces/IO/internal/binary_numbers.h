// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decoding of binary numbers as data files store them: a type (8 to 64 bits, integer or IEEE
// float) and a byte order, independent of the host's.  Readers choose the decoding once per
// array, then call `decode_binary_number()` per value, or `decode_binary_numbers()` for a run
// of consecutive values (the same results, several times faster for large arrays).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BINARY_NUMBERS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BINARY_NUMBERS_H

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
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

#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && defined(__ORDER_BIG_ENDIAN__)
inline std::uint8_t byte_swap(std::uint8_t u)
{
  return u;
}
inline std::uint32_t byte_swap(std::uint32_t u)
{
  return __builtin_bswap32(u);
}
inline std::uint64_t byte_swap(std::uint64_t u)
{
  return __builtin_bswap64(u);
}

// `count` words of type Word from p, byte-swapped if `swap`, converted by `convert` into out.
template <class Word, class Convert>
void decode_binary_words(const unsigned char* p, std::size_t count, bool swap, double* out, Convert convert)
{
  for (std::size_t i = 0; i < count; ++i) {
    Word u;
    std::memcpy(&u, p + sizeof(Word) * i, sizeof(Word));
    out[i] = convert(swap ? byte_swap(u) : u);
  }
}
#endif

/// Decodes the `count` values of type `type` stored consecutively from `p` (no alignment needed)
/// into `out`: `out[i]` is `decode_binary_number(type, order, p + i * binary_type_size(type))`.
/// 8-bit integers, and 32- and 64-bit floats and integers, are copied as words and byte-swapped
/// only when `order` differs from the host's (the whole run at once, which the compiler
/// vectorizes); the other types and hosts of unknown byte order go value by value.
inline void decode_binary_numbers(Binary_type type, Byte_order order, const unsigned char* p,
                                  std::size_t count, double* out)
{
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && defined(__ORDER_BIG_ENDIAN__)
  const Byte_order host = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? Byte_order::LITTLE_ENDIAN_ORDER
                                                                    : Byte_order::BIG_ENDIAN_ORDER;
  const bool swap = order != host;
  switch (type) {
  case Binary_type::FLOAT32:
    return decode_binary_words<std::uint32_t>(p, count, swap, out, [](std::uint32_t u) {
      float f;
      std::memcpy(&f, &u, 4);
      return double(f);
    });
  case Binary_type::FLOAT64:
    return decode_binary_words<std::uint64_t>(p, count, swap, out, [](std::uint64_t u) {
      double d;
      std::memcpy(&d, &u, 8);
      return d;
    });
  case Binary_type::INT32:
    return decode_binary_words<std::uint32_t>(p, count, swap, out,
                                              [](std::uint32_t u) { return double(std::int32_t(u)); });
  case Binary_type::INT64:
    return decode_binary_words<std::uint64_t>(p, count, swap, out,
                                              [](std::uint64_t u) { return double(std::int64_t(u)); });
  case Binary_type::UINT8: // masks: the per-value switch of decode_binary_number() costs 2 x
    return decode_binary_words<std::uint8_t>(p, count, false, out, [](std::uint8_t u) { return double(u); });
  case Binary_type::INT8:
    return decode_binary_words<std::uint8_t>(p, count, false, out,
                                             [](std::uint8_t u) { return double(std::int8_t(u)); });
  default:
    break;
  }
#endif
  const std::size_t size = binary_type_size(type);
  for (std::size_t i = 0; i < count; ++i)
    out[i] = decode_binary_number(type, order, p + i * size);
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BINARY_NUMBERS_H
