// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The second pass that the uniform-grid readers (AmiraMesh, NRRD) share: an array located by
// the first pass (binary numbers of one type and byte order, or ASCII tokens, starting at a
// known byte) is decoded into the velocities v(i, j, k) ∈ R³ (32-bit floats) and the node mask
// m(i, j, k) ∈ {0, 1} of a `Regular_grid_flow_field_3`, every value checked (a non-finite or
// out-of-float-range velocity at a fluid node, a NaN mask value and a non-numeric token fail
// with the node and the byte).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_UNIFORM_GRID_READING_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_UNIFORM_GRID_READING_H

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/checked_float_decoding.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reserve_huge_pages.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// One array of node values as the first pass found it.
struct Grid_array {
  std::string name;
  Binary_type type = Binary_type::FLOAT32;
  std::size_t components = 0, tuples = 0;
  bool ascii = false;
  Byte_order order = Byte_order::LITTLE_ENDIAN_ORDER;
  std::string_view bytes; ///< the bytes holding the values: the file, or a decompressed copy
  std::size_t begin = 0;  ///< where the values start in `bytes`
  std::size_t line = 0;   ///< the line of `begin` (ASCII only)
  std::size_t file_offset = std::size_t(-1); ///< if not -1, `bytes` is decompressed data that starts here
                                             ///< in the file: messages name this byte
};

/// Calls `out(index, value, offset, line)` for each value of `a` in storage order; `cursor`
/// names the file in messages.  The first pass checked that binary values fit in `a.bytes`;
/// ASCII tokens are checked here.
template <class Out>
void decode_grid_array(const Text_cursor& cursor, const Grid_array& a, const Out& out)
{
  const std::size_t count = a.components * a.tuples;
  if (!a.ascii) {
    const std::size_t size = binary_type_size(a.type);
    const unsigned char* p = reinterpret_cast<const unsigned char*>(a.bytes.data()) + a.begin;
    for (std::size_t i = 0; i < count; ++i, p += size)
      out(i, decode_binary_number(a.type, a.order, p),
          a.file_offset != std::size_t(-1) ? a.file_offset : a.begin + i * size, 0);
    return;
  }
  Text_cursor values(std::string(), cursor.file(), a.bytes);
  values.pos = a.begin;
  values.line = a.line;
  for (std::size_t i = 0; i < count; ++i) {
    const std::string_view t = values.token();
    if (t.empty())
      cursor.fail_at(values.pos, values.line,
                     "the data end after " + std::to_string(i) + " of the " + std::to_string(count) +
                         " values of '" + a.name + "' (truncated file or wrong sizes)");
    double v = 0;
    if (!Text_cursor::parse_number(t, v))
      cursor.fail_at(values.pos - t.size(), values.line,
                     "'" + printable(t) + "' is not a number (value " + std::to_string(i) + " of the " +
                         std::to_string(count) + " values of '" + a.name + "')");
    out(i, v, values.pos - t.size(), values.line);
  }
}

/// The node values of a field: 3 velocity components per node, and the fluid flags (empty
/// without a mask).
struct Node_values {
  std::vector<float> values;
  std::vector<unsigned char> flags;
};

/// Decodes `velocity` (3 components per node) and `mask` (1 per node, or null), checked; fails
/// through `cursor` on a bad value, naming the node `kind + " " + node_name(i)` (the mask: by
/// its index).
template <class Node_name>
Node_values decode_node_values(const Text_cursor& cursor, std::size_t nodes, const Grid_array& velocity,
                               const Grid_array* mask, const char* kind, const Node_name& node_name)
{
  // Binary arrays are decoded as runs (the velocity in parallel blocks, see
  // checked_float_decoding.h); only their bad values take the value-by-value checks.
  auto data = [](const Grid_array& a) {
    return reinterpret_cast<const unsigned char*>(a.bytes.data()) + a.begin;
  };
  auto offset = [](const Grid_array& a, std::size_t i) {
    return a.file_offset != std::size_t(-1) ? a.file_offset : a.begin + i * binary_type_size(a.type);
  };
  Node_values r;
  std::vector<unsigned char>& flags = r.flags;
  if (mask != nullptr) {
    reserve_huge_pages(flags, nodes);
    flags.resize(nodes);
    if (mask->ascii || decode_checked_flags(mask->type, mask->order, data(*mask), nodes, flags.data()))
      decode_grid_array(cursor, *mask, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
        flags[i] = checked_mask_flag(
            v, mask->name, [&] { return std::string(kind) + " " + std::to_string(i); },
            [&](const std::string& what) { cursor.fail_at(offset, line, what); });
      });
  }
  std::vector<float>& values = r.values;
  reserve_huge_pages(values, 3 * nodes);
  values.resize(3 * nodes);
  // The fields' constructors replace a solid node's non-finite values by zeros.
  auto check = [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    return checked_velocity_component(
        v, i, [&] { return flags.empty() || flags[i / 3] != 0; }, !flags.empty(), velocity.name, kind,
        [&] { return std::string(kind) + " " + node_name(i / 3); },
        [&](const std::string& what) { cursor.fail_at(offset, line, what); });
  };
  if (velocity.ascii)
    decode_grid_array(cursor, velocity, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
      values[i] = check(i, v, offset, line);
    });
  else
    decode_checked_floats(velocity.type, velocity.order, data(velocity), 3 * nodes, values.data(),
                          [&](std::size_t i, double v) { return check(i, v, offset(velocity, i), 0); });
  return r;
}

/// Decodes `velocity` (3 components per node) and `mask` (1 per node, or null) and builds the
/// field; fails through `cursor` on a bad value.
template <class K>
Regular_grid_flow_field_3<K> make_grid_field(const Text_cursor& cursor, const std::array<std::size_t, 3>& n,
                                             const std::array<double, 3>& origin,
                                             const std::array<double, 3>& spacing, const Grid_array& velocity,
                                             const Grid_array* mask)
{
  Node_values d = decode_node_values(cursor, n[0] * n[1] * n[2], velocity, mask, "node",
                                     [&n](std::size_t i) { return grid_node_string(n, i); });
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  return construct_field<Regular_grid_flow_field_3<K>>(
      [&](const std::string& what) { cursor.fail_file(what); }, Point_3(origin[0], origin[1], origin[2]),
      Vector_3(spacing[0], spacing[1], spacing[2]), n, std::move(d.values), std::move(d.flags));
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_UNIFORM_GRID_READING_H
