// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The velocity field of a parsed AmiraMesh file: pass 2, the velocity and mask lattice fields
// chosen by name or by their number of components, expanded if compressed (HxByteRLE, HxZip),
// then decoded into a regular grid.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_AMIRAMESH_AMIRAMESH_GRID_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_AMIRAMESH_AMIRAMESH_GRID_H

#include <CGAL/Flow_aligned_surfaces/IO/AmiraMesh/AmiraMesh_parser.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/inflate_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/uniform_grid_reading.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

// Expands HxByteRLE data (a control byte c: c < 128 = the next byte c times; c ≥ 128 = the
// next c − 128 bytes as they are) into exactly `expected` bytes.
inline std::string expand_HxByteRLE(const Text_cursor& in, const AmiraMesh_data& d, std::size_t expected)
{
  // Each pair of input bytes gives at most 127 output bytes: a larger claim is a lying header.
  if (expected / 127 > d.compressed_size)
    in.fail_at(d.array.begin, 0,
               "the HxByteRLE data of '" + d.array.name + "' (" + std::to_string(d.compressed_size) +
                   " bytes) cannot expand to the " + std::to_string(expected) + " bytes the lattice needs");
  std::string out; // grows with the data really expanded, never to a claimed size
  const std::string_view b = in.bytes().substr(d.array.begin, d.compressed_size);
  std::size_t i = 0;
  while (out.size() < expected) {
    if (i >= b.size())
      in.fail_at(d.array.begin + i, 0,
                 "the HxByteRLE data of '" + d.array.name + "' end after " + std::to_string(out.size()) +
                     " of " + std::to_string(expected) + " bytes");
    const unsigned char c = static_cast<unsigned char>(b[i++]);
    const std::size_t n = c & 0x7f;
    const std::size_t available = (c & 0x80) ? b.size() - i : (i < b.size() ? n : 0);
    if (n == 0 || n > expected - out.size() || n > available)
      in.fail_at(d.array.begin + i - 1, 0,
                 "invalid HxByteRLE run of " + std::to_string(n) + " bytes in '" + d.array.name + "' after " +
                     std::to_string(out.size()) + " of " + std::to_string(expected) + " bytes");
    if (c & 0x80) {
      out.append(b.data() + i, n);
      i += n;
    }
    else
      out.append(n, b[i++]);
  }
  return out;
}

template <class K>
Regular_grid_flow_field_3<K> read_AmiraMesh_grid(const std::string& filename,
                                                 const std::optional<std::string>& array_name,
                                                 const std::optional<std::string>& mask_name)
{
  const File_contents contents(filename, "read_AmiraMesh_flow_field");
  AmiraMesh_parser parser(filename, contents.view());
  parser.parse();
  const Text_cursor& in = parser.in;

  const AmiraMesh_data* velocity = nullptr;
  const AmiraMesh_data* mask = nullptr;
  for (const AmiraMesh_data& d : parser.data) {
    if (d.location != "Lattice")
      continue;
    if (velocity == nullptr && (array_name ? d.array.name == *array_name : d.array.components == 3))
      velocity = &d;
    if (mask == nullptr && d.array.name == mask_name.value_or("inside"))
      mask = &d;
  }
  const std::string present = " (the lattice fields are: " + parser.describe_lattice_fields() + ")";
  if (velocity == nullptr)
    in.fail_file(array_name ? "there is no lattice field named '" + *array_name + "'" + present
                            : "there is no 3-component lattice field to read as the velocity" + present);
  if (velocity->array.components != 3)
    in.fail_file("the lattice field '" + velocity->array.name + "' has " +
                 std::to_string(velocity->array.components) +
                 " components; a velocity needs 3 numbers per node");
  if (mask_name && !mask_name->empty() && mask == nullptr)
    in.fail_file("there is no lattice field named '" + *mask_name + "' for the mask" + present);
  if (mask == velocity)
    mask = nullptr;
  if (mask != nullptr && mask->array.components != 1)
    in.fail_file("the mask field '" + mask->array.name + "' has " + std::to_string(mask->array.components) +
                 " components; a mask needs 1 number per node");

  // The chosen fields' data, expanded if compressed.
  std::string expanded[2];
  Grid_array arrays[2];
  const AmiraMesh_data* chosen[2] = {velocity, mask};
  for (int c = 0; c < 2; ++c) {
    const AmiraMesh_data* d = chosen[c];
    if (d == nullptr)
      continue;
    if (!d->found)
      in.fail_file("the data section @" + std::to_string(d->section) + " of '" + d->array.name +
                   "' is missing (the file ends before it)");
    arrays[c] = d->array;
    if (d->encoding.empty())
      continue;
    const std::size_t bytes = d->array.tuples * d->array.components * binary_type_size(d->array.type);
    if (d->encoding == "HxByteRLE")
      expanded[c] = expand_HxByteRLE(in, *d, bytes);
    else if (d->encoding == "HxZip" && have_inflate()) {
      const std::string why =
          inflate_bytes(in.bytes().substr(d->array.begin, d->compressed_size), bytes, expanded[c]);
      if (!why.empty())
        in.fail_at(d->array.begin, 0, "the HxZip data of '" + d->array.name + "': " + why);
    }
    else
      in.fail_at(d->array.begin, 0,
                 "the data of '" + d->array.name + "' are compressed with " + printable(d->encoding) +
                     ", which is not supported " +
                     (d->encoding == "HxZip"
                          ? "by this build (it needs zlib: define CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB "
                            "and link zlib)"
                          : "(HxByteRLE and HxZip are)") +
                     "; save the file uncompressed");
    arrays[c].bytes = expanded[c];
    arrays[c].begin = 0;
    arrays[c].file_offset = d->array.begin;
  }
  return make_grid_field<K>(in, parser.dimensions, parser.origin, parser.spacing, arrays[0],
                            mask ? &arrays[1] : nullptr);
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_AMIRAMESH_AMIRAMESH_GRID_H
