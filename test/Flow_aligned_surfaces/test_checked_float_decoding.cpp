// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// internal/checked_float_decoding.h: runs of binary numbers spanning several blocks (so that
// TBB decodes them in parallel when it is linked), assembled byte by byte here, decode to the
// floats they encode; exactly the blocks holding a bad value (NaN, infinity, a double beyond
// FLT_MAX) are reported and their bad values, and only those, go to the check in file order.
// Through the legacy VTK reader: a binary file of three blocks with bad values in two blocks
// names the first one at a fluid node, and stores a solid node's bad value as zeros.

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/checked_float_decoding.h>

#include "grid_reader_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_checked_float_decoding {

namespace {

using namespace fas_test;
namespace FASi = CGAL::Flow_aligned_surfaces::IO::internal;
const std::size_t B = FASi::checked_block_size;

// Value i of the test runs: quarters, exact in every type used.
double value(std::size_t i)
{
  return double(i % 1000) * 0.25 - 100.;
}

template <class T>
std::string encode(const std::vector<T>& v, bool big_endian)
{
  std::string s;
  for (T x : v)
    append_binary(s, x, big_endian);
  return s;
}

const unsigned char* bytes(const std::string& s)
{
  return reinterpret_cast<const unsigned char*>(s.data());
}

// Decodes and records the indices given to the check (which returns -1 for them).
template <class T>
std::pair<std::vector<std::size_t>, std::vector<std::size_t>>
decode(FASi::Binary_type type, const std::vector<T>& v, bool big_endian, std::vector<float>& out)
{
  const std::string s = encode(v, big_endian);
  out.assign(v.size(), 0.f);
  std::vector<std::size_t> checked;
  const std::vector<std::size_t> blocks = FASi::decode_checked_floats(
      type, big_endian ? FASi::Byte_order::BIG_ENDIAN_ORDER : FASi::Byte_order::LITTLE_ENDIAN_ORDER, bytes(s),
      v.size(), out.data(), [&](std::size_t i, double x) {
        EXPECT_FALSE(std::fabs(x) <= double((std::numeric_limits<float>::max)()))
            << "value " << i << " is good";
        checked.push_back(i);
        return -1.f;
      });
  return {blocks, checked};
}

TEST(CheckedFloatDecoding, Float32BigEndianOverSeveralBlocks)
{
  const std::size_t count = 3 * B + 7;
  std::vector<float> v(count);
  for (std::size_t i = 0; i < count; ++i)
    v[i] = float(value(i));
  const float inf = std::numeric_limits<float>::infinity();
  v[B + 3] = std::numeric_limits<float>::quiet_NaN();
  v[3 * B + 6] = -inf;                             // the last value, in the short last block
  v[B + 9] = inf;                                  // a second one in block 1
  v[2 * B] = (std::numeric_limits<float>::max)();  // good: the largest float
  v[5] = std::numeric_limits<float>::denorm_min(); // good
  std::vector<float> out;
  const auto r = decode(FASi::Binary_type::FLOAT32, v, true, out);
  EXPECT_EQ(r.first, (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(r.second, (std::vector<std::size_t>{B + 3, B + 9, 3 * B + 6}));
  for (std::size_t i = 0; i < count; ++i) {
    if (i == B + 3 || i == B + 9 || i == 3 * B + 6)
      EXPECT_EQ(out[i], -1.f) << i;
    else
      ASSERT_EQ(out[i], v[i]) << i;
  }
}

TEST(CheckedFloatDecoding, Float32LittleEndianWithoutBadValues)
{
  std::vector<float> v(2 * B + 1);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = float(value(7 * i));
  std::vector<float> out;
  const auto r = decode(FASi::Binary_type::FLOAT32, v, false, out);
  EXPECT_TRUE(r.first.empty());
  EXPECT_TRUE(r.second.empty());
  EXPECT_EQ(out, v);
}

TEST(CheckedFloatDecoding, DoublesAndIntegers)
{
  std::vector<double> d(B + 10);
  for (std::size_t i = 0; i < d.size(); ++i)
    d[i] = value(i);
  d[B + 2] = 1e300;  // finite, but not a float
  d[4] = -3.5e38;    // just beyond -FLT_MAX (3.4028235e38)
  d[B + 3] = 3.4e38; // within
  std::vector<float> out;
  auto r = decode(FASi::Binary_type::FLOAT64, d, true, out);
  EXPECT_EQ(r.first, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(r.second, (std::vector<std::size_t>{4, B + 2}));
  EXPECT_EQ(out[B + 3], 3.4e38f);
  EXPECT_EQ(out[B + 4], float(value(B + 4)));

  std::vector<std::int16_t> s(B + 5);
  for (std::size_t i = 0; i < s.size(); ++i)
    s[i] = std::int16_t(int(i % 60000) - 30000);
  r = decode(FASi::Binary_type::INT16, s, false, out);
  EXPECT_TRUE(r.first.empty());
  for (std::size_t i = 0; i < s.size(); ++i)
    ASSERT_EQ(out[i], float(s[i])) << i;
}

TEST(CheckedFloatDecoding, MaskFlags)
{
  const std::string u8("\0\1\7\0\377", 5);
  unsigned char f[5];
  EXPECT_FALSE(FASi::decode_checked_flags(FASi::Binary_type::UINT8, FASi::Byte_order::BIG_ENDIAN_ORDER,
                                          bytes(u8), 5, f));
  EXPECT_EQ(std::vector<unsigned char>(f, f + 5), (std::vector<unsigned char>{0, 1, 1, 0, 1}));
  std::vector<float> m = {0.f, 0.5f, -2.f, 0.f};
  EXPECT_FALSE(FASi::decode_checked_flags(FASi::Binary_type::FLOAT32, FASi::Byte_order::BIG_ENDIAN_ORDER,
                                          bytes(encode(m, true)), 4, f));
  EXPECT_EQ(std::vector<unsigned char>(f, f + 4), (std::vector<unsigned char>{0, 1, 1, 0}));
  m[2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(FASi::decode_checked_flags(FASi::Binary_type::FLOAT32, FASi::Byte_order::BIG_ENDIAN_ORDER,
                                         bytes(encode(m, true)), 4, f));
}

struct Read_legacy {
  template <class NP>
  bool operator()(const std::string& file, Grid& g, const NP& np, std::string* error) const
  {
    return FAS::IO::read_VTK_flow_field(file, g, FAS::parameters::error_message(error, np));
  }
};

TEST(CheckedFloatDecoding, BinaryLegacyFileOfSeveralBlocks)
{
  // 40^3 nodes: 192,000 velocity components, three blocks (and a bit) of 65,536.
  const Grid::Dimensions n{{40, 40, 40}};
  const std::size_t nodes = 40 * 40 * 40;
  const Grid_reader_checks<Read_legacy> checks("checked_float_decoding_");
  const std::string header =
      "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 40 40 "
      "40\nORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 64000\nVECTORS velocity float\n";
  auto v = [](std::size_t i, std::size_t j, std::size_t k) {
    return Vector_3(0.25 * double(i), -0.5 * double(j), double(k) + 0.75);
  };
  std::string values = node_values_binary<float>(n, v, true);
  // A NaN at node 10 (component 1: value 31, block 0) and +infinity at node 30000 (component
  // 2: value 90002, block 1); node 10 is solid in the mask, node 30000 fluid.
  const std::size_t first = 3 * 10 + 1, second = 3 * 30000 + 2;
  auto put = [&](std::size_t index, float x) {
    std::string b;
    append_binary(b, x, true);
    values.replace(4 * index, 4, b);
  };
  put(first, std::numeric_limits<float>::quiet_NaN());
  put(second, std::numeric_limits<float>::infinity());
  std::string mask(nodes, '\1');
  mask[10] = '\0';
  const std::string mask_section = "\nSCALARS inside unsigned_char\nLOOKUP_TABLE default\n" + mask;
  // Without the mask the NaN at node 10 is the first bad value at a fluid node.
  checks.expect_failure(
      "nan_first.vtk", header + values,
      {"byte " + std::to_string(header.size() + 4 * first), "node 10 = (10, 0, 0), component 1"});
  // With it, the infinity in the next block is.
  checks.expect_failure("inf_second.vtk", header + values + mask_section,
                        {"byte " + std::to_string(header.size() + 4 * second),
                         "node 30000 = (0, 30, 18), component 2", "at a fluid node"});
  // Node 30000 solid too: read, the solid node with a bad value stored as zeros, every other
  // value as written.
  mask[30000] = '\0';
  const Grid g = checks.read_ok("read.vtk", header + values +
                                                "\nSCALARS inside unsigned_char\nLOOKUP_TABLE "
                                                "default\n" +
                                                mask);
  ASSERT_EQ(g.values().size(), 3 * nodes);
  EXPECT_EQ(g.node_value(10, 0, 0), Vector_3(0, 0, 0));
  EXPECT_EQ(g.node_value(0, 30, 18), Vector_3(0, 0, 0));
  for (std::size_t node = 0; node < nodes; node += 997) {
    if (node == 10 || node == 30000)
      continue;
    const std::size_t i = node % 40, j = (node / 40) % 40, k = node / 1600;
    ASSERT_EQ(g.node_value(i, j, k), v(i, j, k)) << "node " << node;
    EXPECT_EQ(g.is_fluid(i, j, k), true);
  }
  EXPECT_FALSE(g.is_fluid(10, 0, 0));
}

} // namespace

} // namespace test_checked_float_decoding
