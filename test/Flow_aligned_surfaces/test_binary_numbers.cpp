// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// internal/binary_numbers.h: decode_binary_number() and the run decoder decode_binary_numbers()
// on byte sequences written by hand from the IEEE 754 and two's complement encodings, in both
// byte orders, and the run decoder against the single-value one on every type.

#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_binary_numbers {

namespace {

namespace FI = CGAL::Flow_aligned_surfaces::IO::internal;
using FI::Binary_type;
using FI::Byte_order;

// Big-endian encodings and their values: float 1.5 = 0x3FC00000, float -2 = 0xC0000000,
// double 0.1 = 0x3FB999999999999A, int32 -2 = 0xFFFFFFFE, int64 -3 = 0xFF..FD.
struct Case {
  Binary_type type;
  std::vector<unsigned char> bytes; // big-endian, consecutive values
  std::vector<double> values;
};

std::vector<Case> cases()
{
  return {
      {Binary_type::FLOAT32, {0x3F, 0xC0, 0, 0, 0xC0, 0, 0, 0}, {1.5, -2.}},
      {Binary_type::FLOAT64, {0x3F, 0xB9, 0x99, 0x99, 0x99, 0x99, 0x99, 0x9A}, {0.1}},
      {Binary_type::INT32, {0xFF, 0xFF, 0xFF, 0xFE, 0, 0, 1, 0}, {-2., 256.}},
      {Binary_type::UINT32, {0xFF, 0xFF, 0xFF, 0xFE}, {4294967294.}},
      {Binary_type::INT64, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFD}, {-3.}},
      {Binary_type::UINT64, {0, 0, 0, 1, 0, 0, 0, 0}, {4294967296.}},
      {Binary_type::INT16, {0xFF, 0xFE, 0x01, 0x00}, {-2., 256.}},
      {Binary_type::UINT16, {0xFF, 0xFE}, {65534.}},
      {Binary_type::INT8, {0xFE, 0x05}, {-2., 5.}},
      {Binary_type::UINT8, {0xFE, 0x05}, {254., 5.}},
  };
}

// The same values with each value's bytes reversed.
std::vector<unsigned char> little_endian(const Case& c)
{
  std::vector<unsigned char> r = c.bytes;
  const std::size_t size = FI::binary_type_size(c.type);
  for (std::size_t i = 0; i < r.size(); i += size)
    std::reverse(r.begin() + i, r.begin() + i + size);
  return r;
}

TEST(BinaryNumbers, HandEncodedValuesInBothByteOrders)
{
  for (const Case& c : cases()) {
    const std::size_t size = FI::binary_type_size(c.type);
    ASSERT_EQ(c.bytes.size(), size * c.values.size());
    const std::vector<unsigned char> le = little_endian(c);
    std::vector<double> big(c.values.size()), little(c.values.size());
    FI::decode_binary_numbers(c.type, Byte_order::BIG_ENDIAN_ORDER, c.bytes.data(), c.values.size(),
                              big.data());
    FI::decode_binary_numbers(c.type, Byte_order::LITTLE_ENDIAN_ORDER, le.data(), c.values.size(),
                              little.data());
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      EXPECT_EQ(FI::decode_binary_number(c.type, Byte_order::BIG_ENDIAN_ORDER, c.bytes.data() + i * size),
                c.values[i]);
      EXPECT_EQ(FI::decode_binary_number(c.type, Byte_order::LITTLE_ENDIAN_ORDER, le.data() + i * size),
                c.values[i]);
      EXPECT_EQ(big[i], c.values[i]) << "type " << int(c.type) << " value " << i;
      EXPECT_EQ(little[i], c.values[i]) << "type " << int(c.type) << " value " << i;
    }
  }
}

TEST(BinaryNumbers, RunDecoderAgreesWithSingleValuesAtUnalignedPositions)
{
  // Pseudo-random bytes, decoded from an odd offset so that no value is aligned.
  std::vector<unsigned char> bytes(1 + 8 * 37);
  unsigned int h = 12345;
  for (unsigned char& b : bytes) {
    h = h * 1103515245u + 12345u;
    b = static_cast<unsigned char>(h >> 16);
  }
  for (const Case& c : cases())
    for (Byte_order order : {Byte_order::BIG_ENDIAN_ORDER, Byte_order::LITTLE_ENDIAN_ORDER}) {
      const std::size_t size = FI::binary_type_size(c.type), count = 37;
      std::vector<double> run(count);
      FI::decode_binary_numbers(c.type, order, bytes.data() + 1, count, run.data());
      for (std::size_t i = 0; i < count; ++i) {
        const double one = FI::decode_binary_number(c.type, order, bytes.data() + 1 + i * size);
        if (one != one) // NaN payloads: both NaN
          EXPECT_NE(run[i], run[i]);
        else
          EXPECT_EQ(run[i], one) << "type " << int(c.type) << " value " << i;
      }
    }
}

} // namespace

} // namespace test_binary_numbers
