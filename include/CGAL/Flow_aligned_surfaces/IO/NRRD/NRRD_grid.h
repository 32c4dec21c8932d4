// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The velocity field of a parsed NRRD header: its data found (attached after the header, or in
// the data file beside it), skipped as 'line skip' and 'byte skip' say, their size checked
// against the bytes left, then decoded (and inflated if gzip) into a regular grid.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_NRRD_NRRD_GRID_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_NRRD_NRRD_GRID_H

#include <CGAL/Flow_aligned_surfaces/IO/NRRD/NRRD_header.h>
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

// The folder of `filename` with its trailing '/', or "" if it has none.
inline std::string NRRD_folder(const std::string& filename)
{
  const std::size_t slash = filename.find_last_of('/');
  return slash == std::string::npos ? std::string() : filename.substr(0, slash + 1);
}

template <class K>
Regular_grid_flow_field_3<K> read_NRRD_grid(const std::string& filename,
                                            const std::optional<std::string>& array_name,
                                            const std::optional<std::string>& mask_name)
{
  const File_contents file(filename, "read_NRRD_flow_field");
  const std::string_view contents = file.view();
  NRRD_header header(filename, contents);
  header.parse();
  if (mask_name && !mask_name->empty())
    header.in.fail_file("NRRD files hold one array, so there is no mask '" + *mask_name +
                        "' to read (do not give mask_array_name)");
  if (array_name && !header.content.empty() && header.content != *array_name)
    header.in.fail_file("the array is named '" + printable(header.content) + "' (its content field), not '" +
                        *array_name + "'");

  // The data: attached after the header, or in the data file (relative to the header's folder).
  std::optional<File_contents> detached;
  std::string data_name = filename;
  std::size_t pos = header.data_start, line = header.data_line;
  if (!header.data_file.empty()) {
    data_name = header.data_file[0] == '/' ? header.data_file : NRRD_folder(filename) + header.data_file;
    detached.emplace(data_name, "read_NRRD_flow_field: " + filename + ": data file");
    pos = 0;
    line = 1;
  }
  else if (header.data_start >= contents.size())
    header.in.fail_file("the file ends after the header: no data attached (and no 'data file' field)");
  const std::string_view bytes = detached ? detached->view() : contents;
  // Messages about the data name both files.
  Text_cursor data("read_NRRD_flow_field",
                   header.data_file.empty() ? filename : filename + ": data file " + data_name, bytes);
  data.pos = pos;
  data.line = line;
  for (std::size_t l = 0; l < header.line_skip; ++l) {
    if (data.at_end())
      data.fail("the data end after " + std::to_string(l) + " of the " + std::to_string(header.line_skip) +
                " lines of 'line skip'");
    data.read_line();
  }

  Grid_array velocity;
  velocity.name = header.content.empty() ? std::string("velocity") : header.content;
  velocity.type = header.type;
  velocity.components = 3;
  velocity.tuples = header.nodes;
  velocity.ascii = header.encoding == "ascii";
  velocity.order = header.order.value_or(Byte_order::LITTLE_ENDIAN_ORDER);
  velocity.bytes = bytes;
  const std::size_t count = 3 * header.nodes, size = binary_type_size(header.type);
  const std::string what = "the " + std::to_string(count) + " " + header.type_name + " values (sizes: 3 " +
                           header.dimensions_string() + ")";
  std::string inflated;
  if (header.encoding == "gzip") {
    // 'byte skip' counts decompressed bytes.
    const std::size_t skip = static_cast<std::size_t>(header.byte_skip);
    const std::string why = inflate_bytes(bytes.substr(data.pos), count * size + skip, inflated);
    if (!why.empty())
      data.fail("the gzip data of " + what + ": " + why);
    velocity.bytes = inflated;
    velocity.begin = skip;
    velocity.file_offset = data.pos;
    return make_grid_field<K>(data, header.dimensions, header.origin, header.spacing, velocity, nullptr);
  }
  if (velocity.ascii) {
    if (static_cast<std::size_t>(header.byte_skip) > data.left())
      data.fail("'byte skip: " + std::to_string(header.byte_skip) + "' skips past the end of the data");
    data.pos += static_cast<std::size_t>(header.byte_skip);
    if (count > (data.left() + 1) / 2)
      data.fail(what + " need at least " + std::to_string(2 * count - 1) + " bytes of text but only " +
                std::to_string(data.left()) + " are left (truncated file or wrong sizes)");
    velocity.line = data.line;
  }
  else {
    if (count > bytes.size() / size)
      data.fail(what + " need " + std::to_string(count) + " x " + std::to_string(size) +
                " bytes but the data have " + std::to_string(bytes.size()) +
                " (truncated file or wrong sizes)");
    if (header.byte_skip == -1)
      data.pos = bytes.size() - count * size; // the data are the end of the file
    else if (static_cast<std::size_t>(header.byte_skip) > data.left())
      data.fail("'byte skip: " + std::to_string(header.byte_skip) + "' skips past the end of the data");
    else
      data.pos += static_cast<std::size_t>(header.byte_skip);
    if (count * size > data.left())
      data.fail(what + " need " + std::to_string(count * size) + " bytes but only " +
                std::to_string(data.left()) + " are left (truncated file or wrong sizes)");
    data.line = 0;
  }
  velocity.begin = data.pos;
  return make_grid_field<K>(data, header.dimensions, header.origin, header.spacing, velocity, nullptr);
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_NRRD_NRRD_GRID_H
