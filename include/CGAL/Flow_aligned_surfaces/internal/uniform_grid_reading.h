// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The second pass that the uniform-grid readers (AmiraMesh, NRRD) share: an array located by
// the first pass (binary numbers of one type and byte order, or ASCII tokens, starting at a
// known byte) is decoded into the velocities v(i, j, k) ∈ R³ (32-bit floats) and the node mask
// m(i, j, k) ∈ {0, 1} of a `Regular_grid_flow_field_3`, every value checked (a non-finite or
// out-of-float-range velocity at a fluid node, a NaN mask value and a non-numeric token fail
// with the node and the byte).  Also the public functions' common frame: the named array
// parameters and the translation of the internal `Read_error` into `false` + message.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_UNIFORM_GRID_READING_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_UNIFORM_GRID_READING_H

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/internal/reserve_huge_pages.h>
#include <CGAL/Flow_aligned_surfaces/internal/text_cursor.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

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

/// Decodes `velocity` (3 components per node) and `mask` (1 per node, or null) and builds the
/// field; fails through `cursor` on a bad value.
template <class K>
Regular_grid_flow_field_3<K> make_grid_field(const Text_cursor& cursor, const std::array<std::size_t, 3>& n,
                                             const std::array<double, 3>& origin,
                                             const std::array<double, 3>& spacing, const Grid_array& velocity,
                                             const Grid_array* mask)
{
  const std::size_t nodes = n[0] * n[1] * n[2];
  std::vector<unsigned char> flags;
  if (mask != nullptr) {
    reserve_huge_pages(flags, nodes);
    flags.resize(nodes);
    decode_grid_array(cursor, *mask, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
      if (std::isnan(v))
        cursor.fail_at(offset, line, "the mask '" + mask->name + "' is NaN at node " + std::to_string(i));
      flags[i] = v != 0. ? 1 : 0;
    });
  }
  std::vector<float> values;
  reserve_huge_pages(values, 3 * nodes);
  values.resize(3 * nodes);
  decode_grid_array(cursor, velocity, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    // The common case first, without looking at the node or its mask (false for NaN and infinities).
    if (std::fabs(v) <= static_cast<double>((std::numeric_limits<float>::max)())) {
      values[i] = static_cast<float>(v);
      return;
    }
    const std::size_t node = i / 3;
    if (!flags.empty() && flags[node] == 0) {
      // The constructor replaces a solid node's non-finite values by zeros.
      values[i] = std::numeric_limits<float>::quiet_NaN();
      return;
    }
    std::ostringstream msg;
    msg << "the velocity '" << velocity.name << "' at node " << node << " = (" << node % n[0] << ", "
        << (node / n[0]) % n[1] << ", " << node / (n[0] * n[1]) << "), component " << i % 3 << ", is " << v
        << (std::isfinite(v) ? ", which does not fit in a 32-bit float" : "; expected a finite number")
        << (flags.empty() ? "" : " at a fluid node");
    cursor.fail_at(offset, line, msg.str());
  });
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  try {
    return Regular_grid_flow_field_3<K>(Point_3(origin[0], origin[1], origin[2]),
                                        Vector_3(spacing[0], spacing[1], spacing[2]), n, std::move(values),
                                        std::move(flags));
  } catch (const std::invalid_argument& e) {
    cursor.fail_file(e.what());
  }
}

/// The value of the string parameter `Tag` of `np`, or nothing if `np` does not set it.
template <class Tag, class NamedParameters>
std::optional<std::string> string_parameter(const NamedParameters& np)
{
  if constexpr (parameters::is_default_parameter<NamedParameters, Tag>::value)
    return std::nullopt;
  else
    return std::string(parameters::get_parameter(np, Tag()));
}

/// Runs `read()` (which returns the field or throws `Read_error`) into `field`; on failure
/// leaves `field` untouched, writes the reason to `*error` (if not null) and returns `false`.
template <class Field, class Read>
bool read_into(const std::string& reader, const std::string& filename, std::optional<Field>& field,
               std::string* error, const Read& read)
{
  try {
    field.emplace(read());
    return true;
  } catch (const Read_error& e) {
    if (error)
      *error = e.what();
  } catch (const std::bad_alloc&) {
    if (error)
      *error = reader + ": " + filename + ": not enough memory for the field";
  }
  return false;
}

/// The `Field&` overload of a reader from its `std::optional<Field>&` one, called as
/// `read(result)`: `field` is assigned only on success.
template <class Field, class Read_optional>
bool read_and_assign(Field& field, const Read_optional& read)
{
  std::optional<Field> result;
  if (!read(result))
    return false;
  field = std::move(*result);
  return true;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_UNIFORM_GRID_READING_H
