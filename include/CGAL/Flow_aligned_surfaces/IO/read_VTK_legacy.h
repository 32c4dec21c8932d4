// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a velocity field from a legacy VTK file (`.vtk`, ASCII or BINARY) with DATASET
// STRUCTURED_POINTS, RECTILINEAR_GRID, STRUCTURED_GRID or UNSTRUCTURED_GRID: the nodes (a uniform
// grid origin + (i hx, j hy, k hz), per-axis coordinates (X_i, Y_j, Z_k), or listed points), the
// cells of an unstructured grid (point indices and VTK types), a 3-component point data array
// (the velocity, 3 numbers per node) and optionally a 1-component array (the node mask, one
// number per node).  The file is read in two passes over its bytes: the first checks the whole
// structure and records where each array starts, skipping the data; the second decodes only the
// arrays needed.  Every count is checked against the bytes left before anything is allocated,
// so a lying header cannot make the reader allocate more than the file's size.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H

#include <string>

#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/checked_float_decoding.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/remove_masked_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reserve_huge_pages.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/structured_grid_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/voxels_as_hexahedra.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

// One data array met in the file: where its values start and how to decode them.
struct VTK_legacy_array {
  std::string name;
  std::string kind; // SCALARS, VECTORS, NORMALS, FIELD, ...
  std::string type; // the VTK data type, lower case
  std::size_t components = 0, tuples = 0;
  std::size_t begin = 0, line = 0;         // byte offset and line of the first value
  std::size_t header = 0, header_line = 0; // byte offset and line of the header
  bool point_data = true;
};

// Thrown inside the reader only; read_VTK_flow_field() turns it into `false` + message.
typedef Flow_aligned_surfaces::IO::internal::Read_error VTK_legacy_error;
using Flow_aligned_surfaces::IO::internal::printable;

class VTK_legacy_parser {
public:
  VTK_legacy_parser(const std::string& filename, Flow_aligned_surfaces::IO::internal::File_contents contents)
      : m_contents(std::move(contents)), m_in("read_VTK_flow_field", filename, m_contents.view())
  {
  }
  VTK_legacy_parser(const VTK_legacy_parser&) = delete; // m_in views m_contents
  VTK_legacy_parser& operator=(const VTK_legacy_parser&) = delete;

  std::array<std::size_t, 3> dimensions = {{0, 0, 0}};
  std::array<double, 3> origin = {{0., 0., 0.}}, spacing = {{1., 1., 1.}};
  std::size_t nodes = 0, cells = 0;
  std::vector<VTK_legacy_array> arrays;
  bool binary = false;
  std::string dataset;
  // The geometry arrays: per-axis coordinates (RECTILINEAR_GRID), points (STRUCTURED_GRID and
  // UNSTRUCTURED_GRID), and the cells of an UNSTRUCTURED_GRID, either as one list (`cell_list`,
  // up to file version 5.0) or as offsets and connectivity (version 5.1).
  std::optional<VTK_legacy_array> coordinates[3], points, cell_list, offsets, connectivity, cell_types;
  bool have_cells = false;

  [[noreturn]] void fail_at(std::size_t offset, std::size_t line, const std::string& what) const
  {
    m_in.fail_at(offset, line, what);
  }
  [[noreturn]] void fail(const std::string& what) const { m_in.fail(what); }
  [[noreturn]] void fail_file(const std::string& what) const { m_in.fail_file(what); }
  // `fail_file` as a function object.
  auto file_failure() const
  {
    return [this](const std::string& what) { fail_file(what); };
  }

  // Pass 1: the header, the geometry and the position of every array.  `target` names the
  // field type being read, for the message when `dataset` is not one it reads.
  void parse(std::initializer_list<const char*> accepted, const char* target)
  {
    const std::string_view first = m_in.read_line();
    if (lower(first).rfind("# vtk datafile version", 0) != 0)
      fail_at(0, 1,
              "not a legacy VTK file: the first line is '" + printable(first) +
                  "'; expected '# vtk DataFile Version x.x'");
    m_in.read_line(); // the title, free text
    const std::string format = upper(token("the format (ASCII or BINARY)"));
    if (format == "BINARY")
      binary = true;
    else if (format != "ASCII")
      fail("unknown file format '" + format + "'; expected ASCII or BINARY");

    expect_keyword("DATASET");
    dataset = upper(token("the dataset type"));
    const char* readers = readers_of(dataset);
    if (readers == nullptr)
      fail(dataset == "POLYDATA"
               ? std::string("DATASET POLYDATA has no volume cells to interpolate in; expected "
                             "STRUCTURED_POINTS, RECTILINEAR_GRID, STRUCTURED_GRID or UNSTRUCTURED_GRID")
               : "unknown dataset type '" + printable(dataset) +
                     "'; expected STRUCTURED_POINTS, STRUCTURED_GRID, RECTILINEAR_GRID, UNSTRUCTURED_GRID or "
                     "POLYDATA");
    if (std::find_if(accepted.begin(), accepted.end(), [&](const char* d) { return dataset == d; }) ==
        accepted.end())
      fail("DATASET " + dataset + " cannot be read into a " + target + "; it is read by " + readers);
    const bool structured_points = dataset == "STRUCTURED_POINTS",
               rectilinear = dataset == "RECTILINEAR_GRID", curvilinear = dataset == "STRUCTURED_GRID",
               unstructured = dataset == "UNSTRUCTURED_GRID";

    bool have_dimensions = false;
    std::string key;
    for (;;) {
      key = upper(m_in.token());
      if (key.empty())
        break;
      const int axis = key == "X_COORDINATES"   ? 0
                       : key == "Y_COORDINATES" ? 1
                       : key == "Z_COORDINATES" ? 2
                                                : -1;
      if (key == "DIMENSIONS" && !unstructured) {
        for (int a = 0; a < 3; ++a)
          dimensions[a] = integer("DIMENSIONS");
        have_dimensions = true;
      }
      else if (key == "ORIGIN" && structured_points) {
        for (int a = 0; a < 3; ++a)
          origin[a] = real("ORIGIN");
      }
      else if ((key == "SPACING" || key == "ASPECT_RATIO") && structured_points) {
        for (int a = 0; a < 3; ++a)
          spacing[a] = real(key.c_str());
      }
      else if (axis >= 0 && rectilinear) {
        const std::size_t n = integer(key.c_str());
        coordinates[axis] = geometry_array(key, data_type(key.c_str()), 1, n);
      }
      else if (key == "POINTS" && (curvilinear || unstructured)) {
        const std::size_t n = integer("POINTS");
        points = geometry_array(key, data_type("POINTS"), 3, n);
      }
      else if (key == "CELLS" && unstructured) {
        const std::size_t n = integer("CELLS"), size = integer("the CELLS size");
        if (upper(m_in.peek_token()) == "OFFSETS") {
          // VTK >= 9 (file version 5.1): n offsets (cells + 1) and `size` point indices.
          if (n == 0)
            fail("CELLS 0 " + std::to_string(size) +
                 ": the OFFSETS form needs the number of cells + 1 offsets");
          m_in.token();
          offsets = geometry_array("OFFSETS", data_type("OFFSETS"), 1, n);
          expect_keyword("CONNECTIVITY");
          connectivity = geometry_array("CONNECTIVITY", data_type("CONNECTIVITY"), 1, size);
          cells = n - 1;
        }
        else {
          // Up to file version 5.0: per cell, its number of points and their indices.
          if (n > size)
            fail("CELLS " + std::to_string(n) + " " + std::to_string(size) + ": " + std::to_string(n) +
                 " cells cannot be listed in " + std::to_string(size) +
                 " values (each needs its number of points)");
          cell_list = geometry_array(key, "int", 1, size);
          cells = n;
        }
        have_cells = true;
      }
      else if (key == "CELL_TYPES" && unstructured) {
        const std::size_t n = integer("CELL_TYPES");
        if (have_cells && n != cells)
          fail("CELL_TYPES " + std::to_string(n) + " does not match the " + std::to_string(cells) +
               " cells of CELLS");
        cell_types = geometry_array(key, "int", 1, n);
      }
      else if (key == "FIELD") {
        field(false);
      }
      else if (key == "POINT_DATA" || key == "CELL_DATA") {
        break;
      }
      else {
        fail("unexpected keyword '" + printable(key) + "' in the " + dataset + " geometry; expected " +
             (structured_points ? "DIMENSIONS, ORIGIN, SPACING, ASPECT_RATIO"
              : rectilinear     ? "DIMENSIONS, X_COORDINATES, Y_COORDINATES, Z_COORDINATES"
              : curvilinear     ? "DIMENSIONS, POINTS"
                                : "POINTS, CELLS, CELL_TYPES") +
             ", FIELD, POINT_DATA or CELL_DATA");
      }
    }
    if (unstructured)
      check_unstructured_geometry();
    else
      check_structured_geometry(have_dimensions);

    // The attribute sections.
    while (!key.empty()) {
      const bool point_data = key == "POINT_DATA";
      if (point_data || key == "CELL_DATA") {
        const std::size_t n = integer(key.c_str());
        const std::size_t expected = point_data ? nodes : cells;
        if (n != expected)
          fail(key + " " + std::to_string(n) + " does not match " + size_source(point_data) + ", which has " +
               std::to_string(expected) + (point_data ? " nodes" : " cells"));
        m_section_tuples = n;
        m_in_point_data = point_data;
        m_in_section = true;
      }
      else if (!m_in_section) {
        fail("unexpected keyword '" + key + "' before POINT_DATA or CELL_DATA");
      }
      else if (key == "SCALARS") {
        const std::string name(token("the SCALARS name"));
        const std::string type = data_type("SCALARS");
        std::size_t components = 1;
        if (!m_in.rest_of_line_blank() && !m_in.peek_token().empty()) {
          components = integer("the SCALARS number of components");
          if (components < 1 || components > 4)
            fail("SCALARS '" + name + "' has " + std::to_string(components) + " components; expected 1 to 4");
        }
        if (upper(m_in.peek_token()) == "LOOKUP_TABLE") {
          m_in.token();
          token("the LOOKUP_TABLE name");
        }
        array("SCALARS", name, type, components, m_section_tuples);
      }
      else if (key == "VECTORS" || key == "NORMALS") {
        const std::string name(token(key + " name"));
        array(key, name, data_type(key.c_str()), 3, m_section_tuples);
      }
      else if (key == "TENSORS" || key == "TENSORS6") {
        const std::string name(token(key + " name"));
        array(key, name, data_type(key.c_str()), key == "TENSORS" ? 9 : 6, m_section_tuples);
      }
      else if (key == "TEXTURE_COORDINATES") {
        const std::string name(token("the TEXTURE_COORDINATES name"));
        const std::size_t dim = integer("the TEXTURE_COORDINATES dimension");
        if (dim < 1 || dim > 3)
          fail("TEXTURE_COORDINATES '" + name + "' has dimension " + std::to_string(dim) +
               "; expected 1 to 3");
        array(key, name, data_type(key.c_str()), dim, m_section_tuples);
      }
      else if (key == "COLOR_SCALARS") {
        const std::string name(token("the COLOR_SCALARS name"));
        const std::size_t n = integer("the COLOR_SCALARS number of values");
        if (n < 1 || n > 4)
          fail("COLOR_SCALARS '" + name + "' has " + std::to_string(n) + " values; expected 1 to 4");
        array(key, name, binary ? "unsigned_char" : "float", n, m_section_tuples);
      }
      else if (key == "LOOKUP_TABLE") {
        const std::string name(token("the LOOKUP_TABLE name"));
        const std::size_t n = integer("the LOOKUP_TABLE size");
        array(key, name, binary ? "unsigned_char" : "float", 4, n);
      }
      else if (key == "FIELD") {
        field(m_in_point_data);
      }
      else {
        fail("unknown keyword '" + key +
             "'; expected POINT_DATA, CELL_DATA, SCALARS, VECTORS, NORMALS, TENSORS, TEXTURE_COORDINATES, "
             "COLOR_SCALARS, LOOKUP_TABLE or FIELD");
      }
      key = upper(m_in.token());
    }
  }

  // The checks of a structured dataset's geometry once it is all read; sets `nodes` and `cells`.
  void check_structured_geometry(bool have_dimensions)
  {
    if (!have_dimensions)
      fail("the " + dataset + " dataset has no DIMENSIONS");
    for (int a = 0; a < 3; ++a)
      if (dimensions[a] == 0)
        fail("empty grid: DIMENSIONS " + dimensions_string() + " has no nodes");
    for (int a = 0; a < 3; ++a)
      if (dimensions[a] < 2)
        fail("DIMENSIONS " + dimensions_string() +
             ": a grid needs at least 2 nodes along each axis (2D and 1D grids are not supported)");
    for (int a = 0; a < 3; ++a)
      if (!(spacing[a] > 0.))
        fail("SPACING component " + std::to_string(a) + " is " + std::to_string(spacing[a]) +
             "; expected positive numbers");
    nodes = dimensions[0];
    for (int a = 1; a < 3; ++a) {
      // A grid whose float values cannot fit in the file is caught by the array sizes; this only
      // keeps the product from overflowing.
      if (nodes > (std::numeric_limits<std::size_t>::max)() / 16 / dimensions[a])
        fail("DIMENSIONS " + dimensions_string() + " has too many nodes");
      nodes *= dimensions[a];
    }
    cells = (dimensions[0] - 1) * (dimensions[1] - 1) * (dimensions[2] - 1);
    static const char* const names[3] = {"X_COORDINATES", "Y_COORDINATES", "Z_COORDINATES"};
    if (dataset == "RECTILINEAR_GRID") {
      for (int a = 0; a < 3; ++a) {
        if (!coordinates[a])
          fail("the RECTILINEAR_GRID dataset has no " + std::string(names[a]));
        if (coordinates[a]->tuples != dimensions[a])
          fail_at(coordinates[a]->header, coordinates[a]->header_line,
                  std::string(names[a]) + " " + std::to_string(coordinates[a]->tuples) +
                      " does not match DIMENSIONS " + dimensions_string() + ", which has " +
                      std::to_string(dimensions[a]) + " nodes along " + "xyz"[a]);
      }
    }
    if (dataset == "STRUCTURED_GRID") {
      if (!points)
        fail("the STRUCTURED_GRID dataset has no POINTS");
      if (points->tuples != nodes)
        fail_at(points->header, points->header_line,
                "POINTS " + std::to_string(points->tuples) + " does not match DIMENSIONS " +
                    dimensions_string() + ", which has " + std::to_string(nodes) + " nodes");
    }
  }

  void check_unstructured_geometry()
  {
    if (!points)
      fail("the UNSTRUCTURED_GRID dataset has no POINTS");
    if (!have_cells)
      fail("the UNSTRUCTURED_GRID dataset has no CELLS");
    if (!cell_types)
      fail("the UNSTRUCTURED_GRID dataset has no CELL_TYPES");
    if (cell_types->tuples != cells)
      fail_at(cell_types->header, cell_types->header_line,
              "CELL_TYPES " + std::to_string(cell_types->tuples) + " does not match the " +
                  std::to_string(cells) + " cells of CELLS");
    nodes = points->tuples;
    if (nodes == 0 || cells == 0)
      fail("empty grid: POINTS " + std::to_string(nodes) + " and " + std::to_string(cells) + " cells");
  }

  // What the number of nodes (or cells) comes from, for messages.
  std::string size_source(bool point_data = true) const
  {
    if (dataset != "UNSTRUCTURED_GRID")
      return "DIMENSIONS " + dimensions_string();
    return point_data ? "POINTS " + std::to_string(nodes) : "CELLS " + std::to_string(cells);
  }

  // The node in messages: its grid index, or the point index of an unstructured grid.
  std::string node_name(std::size_t node) const
  {
    if (dataset == "UNSTRUCTURED_GRID")
      return "point " + std::to_string(node);
    return "node " + Flow_aligned_surfaces::IO::internal::grid_node_string(dimensions, node);
  }

  // The field types that read a dataset type, or null for the types no field reads.
  static const char* readers_of(const std::string& dataset)
  {
    if (dataset == "STRUCTURED_POINTS")
      return "Regular_grid_flow_field_3, Rectilinear_grid_flow_field_3 and Unstructured_flow_field_3";
    if (dataset == "RECTILINEAR_GRID")
      return "Rectilinear_grid_flow_field_3 and Unstructured_flow_field_3";
    if (dataset == "STRUCTURED_GRID" || dataset == "UNSTRUCTURED_GRID")
      return "Unstructured_flow_field_3";
    return nullptr;
  }

  // An array in messages: "VECTORS 'velocity'", or "POINTS" for the unnamed geometry arrays.
  static std::string label(const std::string& kind, const std::string& name)
  {
    return name.empty() ? kind : kind + " '" + name + "'";
  }

  // Pass 2: decodes the array `a` (checked by pass 1) into doubles, calling `out(index, value,
  // offset, line)` for each value in file order.
  // `flatten` inlines `out` (a lambda too large for the inliner's own choice) into the loops:
  // -20 % CPU for a 100 MB binary file.
  template <class Out>
#if defined(__GNUC__)
  __attribute__((flatten))
#endif
  void
  decode(const VTK_legacy_array& a, const Out& out)
  {
    const std::size_t count = a.components * a.tuples;
    m_in.pos = a.begin;
    m_in.line = a.line;
    if (binary) {
      // Decoded in blocks that stay in the L1 cache, so that the block decoding is a tight loop.
      const std::size_t size = type_size(a.type);
      const Binary_type type = binary_type(a.type);
      const unsigned char* data = reinterpret_cast<const unsigned char*>(m_in.bytes().data());
      constexpr std::size_t block_size = 1024;
      double block[block_size];
      // A local offset, not the cursor's: `out` storing bytes (the mask) could alias `m_in.pos`,
      // which would then be stored and reloaded per value.
      std::size_t pos = m_in.pos;
      for (std::size_t i0 = 0; i0 < count; i0 += block_size) {
        const std::size_t m = count - i0 < block_size ? count - i0 : block_size;
        // Big-endian, as VTK's legacy writer writes, whatever the host.
        Flow_aligned_surfaces::IO::internal::decode_binary_numbers(
            type, Flow_aligned_surfaces::IO::internal::Byte_order::BIG_ENDIAN_ORDER, data + pos, m, block);
        for (std::size_t j = 0; j < m; ++j, pos += size)
          out(i0 + j, block[j], pos, 0);
      }
      m_in.pos = pos;
    }
    else {
      for (std::size_t i = 0; i < count; ++i) {
        const std::string_view t = value_token(a);
        out(i, ascii_value(t, a), m_in.pos - t.size(), m_in.line);
      }
    }
  }

  // The values of a binary array (checked by pass 1): decoded with `type`, big-endian (as
  // VTK's legacy writer writes, whatever the host), value i at data + i * size, which is byte
  // begin + i * size of the file.
  struct Binary_values {
    const unsigned char* data;
    Flow_aligned_surfaces::IO::internal::Binary_type type;
    std::size_t size, begin;
    static constexpr Flow_aligned_surfaces::IO::internal::Byte_order order =
        Flow_aligned_surfaces::IO::internal::Byte_order::BIG_ENDIAN_ORDER;
  };
  Binary_values binary_values(const VTK_legacy_array& a) const
  {
    return {reinterpret_cast<const unsigned char*>(m_in.bytes().data()) + a.begin, binary_type(a.type),
            type_size(a.type), a.begin};
  }

  std::string dimensions_string() const
  {
    return std::to_string(dimensions[0]) + " " + std::to_string(dimensions[1]) + " " +
           std::to_string(dimensions[2]);
  }

private:
  typedef Flow_aligned_surfaces::IO::internal::Text_cursor Text_cursor;
  static std::string upper(std::string_view s)
  {
    return Text_cursor::upper(s);
  }
  static std::string lower(std::string_view s)
  {
    return Text_cursor::lower(s);
  }

  // The next token of the values of `a`.
  std::string_view value_token(const VTK_legacy_array& a)
  {
    const std::string_view t = m_in.token();
    if (t.empty())
      fail("the file ends inside the values of " + label(a.kind, a.name));
    return t;
  }

  std::string_view token(const std::string& what)
  {
    const std::string_view t = m_in.token();
    if (t.empty())
      fail("the file ends where " + what + " was expected (truncated file?)");
    return t;
  }

  void expect_keyword(const char* keyword)
  {
    const std::string t = upper(token(std::string("the keyword ") + keyword));
    if (t != keyword)
      fail("found '" + printable(t) + "' where the keyword " + keyword + " was expected");
  }

  std::size_t integer(const char* what)
  {
    return m_in.count(token(std::string("a number of ") + what), what);
  }

  double real(const char* what)
  {
    return m_in.finite_number(token(std::string("a number of ") + what), what);
  }

  // Bytes per value in BINARY files (as VTK's legacy writer writes them), 0 if unknown.
  static std::size_t type_size(const std::string& type)
  {
    if (type == "bit")
      return 0; // packed, handled apart
    if (type == "unsigned_char" || type == "char")
      return 1;
    if (type == "unsigned_short" || type == "short")
      return 2;
    if (type == "unsigned_int" || type == "int" || type == "float" || type == "vtkidtype")
      return 4;
    if (type == "unsigned_long" || type == "long" || type == "double" || type == "vtktypeint64" ||
        type == "vtktypeuint64")
      return 8;
    return 0;
  }

  std::string data_type(const char* what)
  {
    const std::string t = lower(token(std::string("the data type of ") + what));
    if (t != "bit" && type_size(t) == 0)
      fail("unknown data type '" + printable(t) +
           "'; expected bit, unsigned_char, char, unsigned_short, short, unsigned_int, int, unsigned_long, "
           "long, "
           "float, double, vtktypeint64, vtktypeuint64 or vtkIdType");
    return t;
  }

  // FIELD name n, then n arrays `name components tuples type` and their values.  In POINT_DATA
  // the arrays are candidates for the velocity and the mask (their tuple count is checked when
  // one is chosen).
  void field(bool point_data)
  {
    token("the FIELD name");
    const std::size_t n = integer("FIELD arrays");
    for (std::size_t i = 0; i < n; ++i) {
      const std::string name(token("a FIELD array name"));
      if (upper(name) == "NULL_ARRAY")
        continue;
      const std::size_t components = integer("FIELD array components");
      const std::size_t tuples = integer("FIELD array tuples");
      const std::string type = data_type("a FIELD array");
      if (components == 0)
        fail("FIELD array '" + name + "' has 0 components");
      array("FIELD", name, type, components, tuples, point_data);
    }
  }

  // Records an array of the point or cell data and skips its values.
  void array(const std::string& kind, const std::string& name, const std::string& type,
             std::size_t components, std::size_t tuples, bool candidate = true)
  {
    arrays.push_back(skip_values(kind, name, type, components, tuples));
    arrays.back().point_data = m_in_point_data && candidate && kind != "LOOKUP_TABLE";
    skip_metadata();
  }

  // Records an array of the geometry (coordinates, points, cells) and skips its values.
  VTK_legacy_array geometry_array(const std::string& kind, const std::string& type, std::size_t components,
                                  std::size_t tuples)
  {
    if (type == "bit")
      fail(kind + " of type bit; expected numbers");
    VTK_legacy_array a = skip_values(kind, "", type, components, tuples);
    a.point_data = false;
    skip_metadata();
    return a;
  }

  // Checks that the values of an array fit in what is left, then skips them.
  VTK_legacy_array skip_values(const std::string& kind, const std::string& name, const std::string& type,
                               std::size_t components, std::size_t tuples)
  {
    const std::size_t left = m_in.left();
    if (components != 0 && tuples > left / components)
      fail(label(kind, name) + " needs " + std::to_string(tuples) + " x " + std::to_string(components) +
           " values but only " + std::to_string(left) + " bytes are left (truncated file or wrong count)");
    const std::size_t count = components * tuples;
    VTK_legacy_array a;
    a.name = name;
    a.kind = kind;
    a.type = type;
    a.components = components;
    a.tuples = tuples;
    a.header = m_in.pos;
    a.header_line = m_in.line;
    if (binary) {
      // The values start right after the end of the header line.
      const std::string_view b = m_in.bytes();
      while (m_in.pos < b.size() && b[m_in.pos] != '\n') {
        if (!Text_cursor::is_space(b[m_in.pos]))
          fail("unexpected text after the header of " + label(kind, name));
        ++m_in.pos;
      }
      m_in.read_line(); // the end of the header line
      const std::size_t bytes = type == "bit" ? (count + 7) / 8 : count * type_size(type);
      const std::size_t remaining = m_in.left();
      if (bytes > remaining)
        fail(label(kind, name) + " (" + type + ") needs " + std::to_string(bytes) +
             " bytes of binary data but only " + std::to_string(remaining) +
             " are left (truncated file or wrong count)");
      a.begin = m_in.pos;
      a.line = 0;
      m_in.pos += bytes;
    }
    else {
      if (count > (left + 1) / 2)
        fail(label(kind, name) + " needs " + std::to_string(count) + " values but only " +
             std::to_string(left) + " bytes are left (truncated file or wrong count)");
      m_in.skip_space();
      a.begin = m_in.pos;
      a.line = m_in.line;
      for (std::size_t i = 0; i < count; ++i) {
        const std::string_view t = value_token(a);
        if (a.type != "bit")
          ascii_value(t, a);
      }
    }
    return a;
  }

  // VTK ≥ 8 may follow an array with METADATA and INFORMATION lines, ended by an empty line.
  void skip_metadata()
  {
    if (upper(m_in.peek_token()) != "METADATA")
      return;
    m_in.token();
    m_in.read_line();
    while (!m_in.at_end()) {
      const std::string_view l = m_in.read_line();
      if (l.find_first_not_of(" \t\r") == std::string_view::npos)
        return;
    }
  }

  double ascii_value(std::string_view t, const VTK_legacy_array& a) const
  {
    double v = 0;
    if (!Text_cursor::parse_number(t, v))
      fail_at(m_in.pos - t.size(), m_in.line,
              "'" + printable(t) + "' is not a number (in the values of " + label(a.kind, a.name) + ")");
    return v;
  }

  // The binary decodings, chosen once per array rather than once per value.
  typedef Flow_aligned_surfaces::IO::internal::Binary_type Binary_type;

  static Binary_type binary_type(const std::string& type)
  {
    if (type == "float")
      return Binary_type::FLOAT32;
    if (type == "double")
      return Binary_type::FLOAT64;
    if (type == "unsigned_char")
      return Binary_type::UINT8;
    if (type == "char")
      return Binary_type::INT8;
    if (type == "unsigned_short")
      return Binary_type::UINT16;
    if (type == "short")
      return Binary_type::INT16;
    if (type == "unsigned_int")
      return Binary_type::UINT32;
    if (type == "int" || type == "vtkidtype")
      return Binary_type::INT32;
    if (type == "unsigned_long" || type == "vtktypeuint64")
      return Binary_type::UINT64;
    return Binary_type::INT64;
  }

  Flow_aligned_surfaces::IO::internal::File_contents m_contents;
  Text_cursor m_in; // reads m_contents.view()
  std::size_t m_section_tuples = 0;
  bool m_in_point_data = false, m_in_section = false;
};

inline std::string describe_arrays(const std::vector<VTK_legacy_array>& arrays)
{
  std::string r;
  for (const VTK_legacy_array& a : arrays) {
    if (!a.point_data)
      continue;
    if (!r.empty())
      r += ", ";
    r += "'" + a.name + "' (" + a.kind + " " + a.type + ", " + std::to_string(a.components) + " component" +
         (a.components == 1 ? "" : "s") + ")";
  }
  return r.empty() ? std::string("none") : r;
}

// The node arrays of a parsed file: the velocity (3 floats per node) and the mask (empty when
// there is none), decoded and checked.
struct VTK_legacy_node_data {
  std::vector<float> values;
  std::vector<unsigned char> flags;
  std::string mask_name;
};

// Chooses the velocity and mask arrays among the point data (by name, else the first VECTORS,
// else the first 3-component array; the mask named `inside` by default) and decodes them.
inline VTK_legacy_node_data read_node_data(VTK_legacy_parser& parser, const std::string* array_name,
                                           const std::string* mask_name)
{
  const VTK_legacy_array* velocity = nullptr;
  const VTK_legacy_array* mask = nullptr;
  for (const VTK_legacy_array& a : parser.arrays) {
    if (!a.point_data)
      continue;
    if (array_name != nullptr) {
      if (velocity == nullptr && a.name == *array_name)
        velocity = &a;
    }
    else if (a.components == 3 && a.type != "bit" &&
             (velocity == nullptr || (velocity->kind != "VECTORS" && a.kind == "VECTORS"))) {
      velocity = &a; // the first VECTORS array, else the first 3-component array
    }
    if (mask == nullptr && a.name == (mask_name ? *mask_name : std::string("inside")))
      mask = &a;
  }
  const std::string present = " (the point data arrays are: " + describe_arrays(parser.arrays) + ")";
  if (velocity == nullptr) {
    if (array_name != nullptr)
      parser.fail_file("there is no point data array named '" + *array_name + "'" + present);
    parser.fail_file("there is no 3-component point data array to read as the velocity" + present);
  }
  if (velocity->components != 3 || velocity->type == "bit")
    parser.fail_file("the point data array '" + velocity->name + "' has " +
                     std::to_string(velocity->components) + " components of type " + velocity->type +
                     "; a velocity needs 3 numbers per node");
  if (mask_name != nullptr && !mask_name->empty() && mask == nullptr)
    parser.fail_file("there is no point data array named '" + *mask_name + "' for the mask" + present);
  if (mask != nullptr && (mask->components != 1 || mask->type == "bit"))
    parser.fail_file("the mask array '" + mask->name + "' has " + std::to_string(mask->components) +
                     " components of type " + mask->type + "; a mask needs 1 number per node (" +
                     std::to_string(parser.nodes) + " values)");
  if (mask == velocity)
    mask = nullptr;
  for (const VTK_legacy_array* a : {velocity, mask})
    if (a != nullptr && a->tuples != parser.nodes)
      parser.fail_file(std::string(a == mask ? "the mask array '" : "the velocity array '") + a->name +
                       "' has " + std::to_string(a->tuples) + " tuples but the grid (" +
                       parser.size_source() + ") has " + std::to_string(parser.nodes) + " nodes");

  VTK_legacy_node_data d;
  const std::size_t nodes = parser.nodes;
  namespace FASi = Flow_aligned_surfaces::IO::internal;
  if (mask != nullptr) {
    d.mask_name = mask->name;
    FASi::reserve_huge_pages(d.flags, nodes);
    d.flags.resize(nodes);
    // By value: a byte store through d.flags[i], or through a captured reference, could alias
    // the pointer, which would then be reloaded per value.
    unsigned char* flags = d.flags.data();
    auto check = [&, flags](std::size_t i, double v, std::size_t offset, std::size_t line) {
      flags[i] = FASi::checked_mask_flag(
          v, mask->name, [&] { return "node " + std::to_string(i); },
          [&](const std::string& what) { parser.fail_at(offset, line, what); });
    };
    const auto b = parser.binary_values(*mask);
    // Binary: decoded as a run; only a NaN, which the run reports, goes through `check`.
    if (!parser.binary || FASi::decode_checked_flags(b.type, b.order, b.data, nodes, flags))
      parser.decode(*mask, check);
  }
  FASi::reserve_huge_pages(d.values, 3 * nodes);
  d.values.resize(3 * nodes);
  float* values = d.values.data();
  auto check = [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    values[i] = FASi::checked_velocity_component(
        v, i, [&] { return d.flags.empty() || d.flags[i / 3] != 0; }, !d.flags.empty(), velocity->name,
        "node", [&] { return parser.node_name(i / 3); },
        [&](const std::string& what) { parser.fail_at(offset, line, what); });
  };
  // A solid node's value is never interpolated: one with a non-finite component is stored as
  // zero, as the grid fields' constructors do (and the cells field, which refuses non-finite
  // values, gets the same).
  auto zero_bad_solid_nodes = [&](std::size_t first_node, std::size_t end_node) {
    for (std::size_t node = first_node; node < end_node && node < d.flags.size(); ++node) {
      float* c = values + 3 * node;
      if (d.flags[node] == 0 && !(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])))
        c[0] = c[1] = c[2] = 0.f;
    }
  };
  if (parser.binary) {
    // Decoded and range-checked straight into the result, in parallel blocks; the values of the
    // (rare) blocks holding a non-finite or too large value are then checked one by one in file
    // order, so the message names the first bad value at a fluid node, as in the ASCII case.
    const auto b = parser.binary_values(*velocity);
    for (std::size_t block : FASi::decode_checked_floats(b.type, b.order, b.data, 3 * nodes, values,
                                                         [&](std::size_t i, double v) {
                                                           check(i, v, b.begin + i * b.size, 0);
                                                           return values[i];
                                                         })) {
      const std::size_t begin = block * FASi::checked_block_size;
      zero_bad_solid_nodes(begin / 3, (begin + FASi::checked_block_size + 2) / 3);
    }
  }
  else {
    parser.decode(*velocity, check);
    zero_bad_solid_nodes(0, nodes);
  }
  return d;
}

// The values of a geometry array (coordinates or points) as doubles, each finite.
inline std::vector<double> decode_reals(VTK_legacy_parser& parser, const VTK_legacy_array& a)
{
  std::vector<double> r(a.components * a.tuples);
  parser.decode(a, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    if (!std::isfinite(v)) {
      std::ostringstream msg;
      msg << a.kind << ": ";
      if (a.components == 3)
        msg << "coordinate " << i % 3 << " of point " << i / 3;
      else
        msg << "value " << i;
      msg << " is " << v << "; expected a finite number";
      parser.fail_at(offset, line, msg.str());
    }
    r[i] = v;
  });
  return r;
}

// The node coordinates along each axis of a STRUCTURED_POINTS or RECTILINEAR_GRID dataset.
inline std::array<std::vector<double>, 3> grid_coordinates(VTK_legacy_parser& parser)
{
  std::array<std::vector<double>, 3> x;
  for (int a = 0; a < 3; ++a) {
    if (parser.dataset == "RECTILINEAR_GRID") {
      x[a] = decode_reals(parser, *parser.coordinates[a]);
      continue;
    }
    x[a].resize(parser.dimensions[a]);
    for (std::size_t i = 0; i < x[a].size(); ++i) // the formula of Regular_grid_flow_field_3
      x[a][i] = parser.origin[a] + static_cast<double>(i) * parser.spacing[a];
  }
  return x;
}

// The VTK cell type names, for messages; the number of points of the supported ones (else 0).
inline const char* vtk_cell_type_name(double t, int* points = nullptr)
{
  static const struct {
    int type, points;
    const char* name;
  } table[] = {{1, 0, "VTK_VERTEX"},
               {2, 0, "VTK_POLY_VERTEX"},
               {3, 0, "VTK_LINE"},
               {4, 0, "VTK_POLY_LINE"},
               {5, 0, "VTK_TRIANGLE"},
               {6, 0, "VTK_TRIANGLE_STRIP"},
               {7, 0, "VTK_POLYGON"},
               {8, 0, "VTK_PIXEL"},
               {9, 0, "VTK_QUAD"},
               {10, 4, "VTK_TETRA"},
               {11, 8, "VTK_VOXEL"},
               {12, 8, "VTK_HEXAHEDRON"},
               {13, 6, "VTK_WEDGE"},
               {14, 5, "VTK_PYRAMID"},
               {15, 0, "VTK_PENTAGONAL_PRISM"},
               {16, 0, "VTK_HEXAGONAL_PRISM"},
               {21, 0, "VTK_QUADRATIC_EDGE"},
               {22, 0, "VTK_QUADRATIC_TRIANGLE"},
               {23, 0, "VTK_QUADRATIC_QUAD"},
               {24, 0, "VTK_QUADRATIC_TETRA"},
               {25, 0, "VTK_QUADRATIC_HEXAHEDRON"},
               {26, 0, "VTK_QUADRATIC_WEDGE"},
               {27, 0, "VTK_QUADRATIC_PYRAMID"},
               {42, 0, "VTK_POLYHEDRON"}};
  for (const auto& e : table)
    if (t == e.type) {
      if (points != nullptr)
        *points = e.points;
      return e.name;
    }
  if (points != nullptr)
    *points = 0;
  return "not a linear 3D cell type this reader knows";
}

inline std::string number_string(double v)
{
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The cells of an UNSTRUCTURED_GRID (either form of CELLS) in the form of
// `Unstructured_flow_field_3`, with every type, point count and point index checked.
inline Flow_aligned_surfaces::IO::internal::Structured_grid_cells
read_unstructured_cells(VTK_legacy_parser& parser)
{
  Flow_aligned_surfaces::IO::internal::Structured_grid_cells r;
  const std::size_t nc = parser.cells, np = parser.nodes;
  std::vector<int> points_per_cell(nc);
  r.cell_types.resize(nc);
  parser.decode(*parser.cell_types, [&](std::size_t i, double t, std::size_t offset, std::size_t line) {
    int n = 0;
    const char* name = vtk_cell_type_name(t, &n);
    if (n == 0)
      parser.fail_at(
          offset, line,
          "cell " + std::to_string(i) + " has VTK type " + number_string(t) + " (" + name +
              "); supported: 10 (VTK_TETRA), 11 (VTK_VOXEL), 12 (VTK_HEXAHEDRON), 13 (VTK_WEDGE), "
              "14 (VTK_PYRAMID)");
    r.cell_types[i] = static_cast<unsigned char>(t);
    points_per_cell[i] = n;
  });
  auto point_index = [&](std::size_t cell, double v, std::size_t offset, std::size_t line) {
    if (!(v >= 0. && v < static_cast<double>(np) && v == std::floor(v)))
      parser.fail_at(offset, line,
                     "cell " + std::to_string(cell) + " has the point index " + number_string(v) +
                         "; expected an index in [0, " + std::to_string(np) + ") (POINTS " +
                         std::to_string(np) + ")");
    return static_cast<std::int64_t>(v);
  };
  auto cell_name = [&](std::size_t cell) {
    return "cell " + std::to_string(cell) + " (" + vtk_cell_type_name(r.cell_types[cell]) + ")";
  };

  if (parser.cell_list) {
    // Legacy form: per cell, its number of points, then their indices.
    const VTK_legacy_array& list = *parser.cell_list;
    const std::string cells_line = "CELLS " + std::to_string(nc) + " " + std::to_string(list.tuples);
    r.offsets.reserve(nc + 1);
    r.offsets.push_back(0);
    r.connectivity.reserve(list.tuples - nc); // nc <= list.tuples, checked by pass 1
    std::size_t cell = 0, left = 0;           // the current cell and its points still to read
    parser.decode(list, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
      if (left == 0) {
        if (cell == nc)
          parser.fail_at(offset, line,
                         cells_line + ": the " + std::to_string(nc) + " cells end after " +
                             std::to_string(i) + " values, not " + std::to_string(list.tuples));
        if (v != points_per_cell[cell])
          parser.fail_at(offset, line,
                         cell_name(cell) + " lists " + number_string(v) + " points; expected " +
                             std::to_string(points_per_cell[cell]));
        left = static_cast<std::size_t>(points_per_cell[cell]);
        return;
      }
      r.connectivity.push_back(point_index(cell, v, offset, line));
      if (--left == 0) {
        r.offsets.push_back(static_cast<std::int64_t>(r.connectivity.size()));
        ++cell;
      }
    });
    if (cell != nc)
      parser.fail_at(list.header, list.header_line,
                     cells_line + ": the values end inside cell " + std::to_string(cell) + " of " +
                         std::to_string(nc) + " (wrong count)");
    Flow_aligned_surfaces::IO::internal::voxels_as_hexahedra(r.cell_types, r.offsets, r.connectivity);
    return r;
  }

  // File version 5.1: OFFSETS (cells + 1 of them) and CONNECTIVITY.
  const VTK_legacy_array& offsets = *parser.offsets;
  const VTK_legacy_array& connectivity = *parser.connectivity;
  r.offsets.resize(nc + 1);
  parser.decode(offsets, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    if (i == 0 && v != 0.)
      parser.fail_at(offset, line, "OFFSETS[0] is " + number_string(v) + "; expected 0");
    if (i > 0) {
      const double previous = static_cast<double>(r.offsets[i - 1]);
      if (v - previous != points_per_cell[i - 1])
        parser.fail_at(offset, line,
                       cell_name(i - 1) + " has OFFSETS " + number_string(previous) + " and " +
                           number_string(v) + ", so " + number_string(v - previous) + " points; expected " +
                           std::to_string(points_per_cell[i - 1]));
    }
    if (i == nc && v != static_cast<double>(connectivity.tuples))
      parser.fail_at(offset, line,
                     "the last offset is " + number_string(v) + " but CONNECTIVITY has " +
                         std::to_string(connectivity.tuples) + " values; expected them equal");
    r.offsets[i] = static_cast<std::int64_t>(v);
  });
  r.connectivity.resize(connectivity.tuples);
  parser.decode(connectivity, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    const std::size_t cell = static_cast<std::size_t>(
        std::upper_bound(r.offsets.begin(), r.offsets.end(), static_cast<std::int64_t>(i)) -
        r.offsets.begin() - 1);
    r.connectivity[i] = point_index(cell, v, offset, line);
  });
  Flow_aligned_surfaces::IO::internal::voxels_as_hexahedra(r.cell_types, r.offsets, r.connectivity);
  return r;
}

// Reads the file and builds the field; throw VTK_legacy_error with the message.
template <class K>
Regular_grid_flow_field_3<K> read_VTK_legacy_grid(const std::string& filename, const std::string* array_name,
                                                  const std::string* mask_name)
{
  VTK_legacy_parser parser(filename,
                           Flow_aligned_surfaces::IO::internal::File_contents(filename, "read_VTK_flow_field"));
  parser.parse({"STRUCTURED_POINTS"}, "Regular_grid_flow_field_3");
  VTK_legacy_node_data d = read_node_data(parser, array_name, mask_name);
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  return Flow_aligned_surfaces::IO::internal::construct_field<Regular_grid_flow_field_3<K>>(
      parser.file_failure(), Flow_aligned_surfaces::internal::Node_values_checked(),
      Point_3(parser.origin[0], parser.origin[1], parser.origin[2]),
      Vector_3(parser.spacing[0], parser.spacing[1], parser.spacing[2]), parser.dimensions,
      std::move(d.values), std::move(d.flags));
}

template <class K>
Rectilinear_grid_flow_field_3<K> read_VTK_legacy_rectilinear(const std::string& filename,
                                                             const std::string* array_name,
                                                             const std::string* mask_name)
{
  VTK_legacy_parser parser(filename,
                           Flow_aligned_surfaces::IO::internal::File_contents(filename, "read_VTK_flow_field"));
  parser.parse({"STRUCTURED_POINTS", "RECTILINEAR_GRID"}, "Rectilinear_grid_flow_field_3");
  VTK_legacy_node_data d = read_node_data(parser, array_name, mask_name);
  std::array<std::vector<double>, 3> x = grid_coordinates(parser);
  return Flow_aligned_surfaces::IO::internal::construct_field<Rectilinear_grid_flow_field_3<K>>(
      parser.file_failure(), Flow_aligned_surfaces::internal::Node_values_checked(), std::move(x),
      std::move(d.values), std::move(d.flags));
}

template <class K>
Unstructured_flow_field_3<K> read_VTK_legacy_cells(const std::string& filename, const std::string* array_name,
                                                   const std::string* mask_name)
{
  VTK_legacy_parser parser(filename,
                           Flow_aligned_surfaces::IO::internal::File_contents(filename, "read_VTK_flow_field"));
  parser.parse({"UNSTRUCTURED_GRID", "STRUCTURED_GRID", "RECTILINEAR_GRID", "STRUCTURED_POINTS"},
               "Unstructured_flow_field_3");
  VTK_legacy_node_data d = read_node_data(parser, array_name, mask_name);
  std::vector<double> points;
  Flow_aligned_surfaces::IO::internal::Structured_grid_cells cells;
  if (parser.dataset == "UNSTRUCTURED_GRID") {
    points = decode_reals(parser, *parser.points);
    cells = read_unstructured_cells(parser);
  }
  else {
    if (parser.dataset == "STRUCTURED_GRID") {
      points = decode_reals(parser, *parser.points);
    }
    else {
      const std::array<std::vector<double>, 3> x = grid_coordinates(parser);
      points.reserve(3 * parser.nodes);
      for (double z : x[2])
        for (double y : x[1])
          for (double xi : x[0])
            points.insert(points.end(), {xi, y, z});
    }
    cells = Flow_aligned_surfaces::IO::internal::structured_grid_cells(parser.dimensions);
  }
  const std::size_t all_cells = cells.cell_types.size();
  if (!d.flags.empty() && Flow_aligned_surfaces::IO::internal::remove_masked_cells(
                              d.flags, cells.connectivity, cells.offsets, cells.cell_types) == 0)
    parser.fail_file("every one of the " + std::to_string(all_cells) +
                     " cells touches a solid node of the mask '" + d.mask_name + "'; no cell is left");
  // Float points stay float in the field (they were decoded as doubles, exactly).
  if ((parser.dataset == "UNSTRUCTURED_GRID" || parser.dataset == "STRUCTURED_GRID") && parser.points &&
      parser.points->type == "float")
    return Flow_aligned_surfaces::IO::internal::construct_field<Unstructured_flow_field_3<K>>(
        parser.file_failure(), std::vector<float>(points.begin(), points.end()),
        std::move(cells.connectivity), std::move(cells.offsets), std::move(cells.cell_types),
        std::move(d.values));
  return Flow_aligned_surfaces::IO::internal::construct_field<Unstructured_flow_field_3<K>>(
      parser.file_failure(), std::move(points), std::move(cells.connectivity), std::move(cells.offsets),
      std::move(cells.cell_types), std::move(d.values));
}

// The public functions' common part: the named parameters, and the errors made `false` + message.
template <class Field, class NamedParameters, class Read>
bool read_VTK_legacy(const std::string& filename, std::optional<Field>& field, const NamedParameters& np,
                     std::string* error, const Read& read)
{
  const Flow_aligned_surfaces::IO::internal::Array_names names = Flow_aligned_surfaces::IO::internal::array_names(np);
  return Flow_aligned_surfaces::IO::internal::read_into("read_VTK_flow_field", filename, field, error, [&] {
    return read(filename, names.array_name(), names.mask_name());
  });
}

// The same into an existing field, assigned only on success.
template <class Field, class NamedParameters, class Read>
bool read_VTK_legacy(const std::string& filename, Field& field, const NamedParameters& np, std::string* error,
                     const Read& read)
{
  return Flow_aligned_surfaces::IO::internal::read_and_assign<Field>(field, [&](std::optional<Field>& result) {
    return read_VTK_legacy(filename, result, np, error, read);
  });
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a legacy VTK file into an optional, for
callers that have no field yet; same as the overload below otherwise.

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np the named parameters of the overload below
\param error if not null, receives the reason of a failure
\returns `true` on success.
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, std::optional<Regular_grid_flow_field_3<K>>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return internal::read_VTK_legacy(filename, field, np, error, &internal::read_VTK_legacy_grid<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a legacy VTK file.

The file must be a legacy VTK file (`# vtk DataFile Version x.x`), ASCII or BINARY (big-endian,
as VTK writes it), with `DATASET STRUCTURED_POINTS` (`DIMENSIONS`, `ORIGIN`, `SPACING`, or its
older synonym `ASPECT_RATIO`; at least 2 nodes along each axis).  The other dataset types are
refused with a message naming the field type that reads them (`Rectilinear_grid_flow_field_3`
for `RECTILINEAR_GRID`, `Unstructured_flow_field_3` for all).  The velocity is a
3-component `POINT_DATA` array: `VECTORS`, `NORMALS`, a 3-component `SCALARS` or a
3-component `FIELD` array, of any numeric type (stored as 32-bit floats).  The node mask is a
1-component `POINT_DATA` array of any numeric type, nonzero = fluid.  Every other array and
every `CELL_DATA` section is skipped, and so are the `METADATA` blocks that VTK 9 writes.

Bad input never crashes, hangs or allocates more than the file's size: a truncated file,
counts that do not match `DIMENSIONS`, unknown or unsupported dataset types, non-numeric tokens,
missing arrays, a mask that is not one number per node, an empty grid, or a NaN or infinite
velocity at a fluid node make the function return `false` with a message that names the file,
the line and/or byte offset, and what is wrong (the node index for bad values; the arrays
present for a missing one).  Non-finite values at solid nodes are accepted and stored as zero,
as in `Regular_grid_flow_field_3`.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np an optional sequence of named parameters among the ones listed below
\param error if not null, receives the reason of a failure

\cgalNamedParamsBegin
  \cgalParamNBegin{array_name}
    \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`)}
    \cgalParamType{`std::string`}
    \cgalParamDefault{the first `VECTORS` array of the point data, else its first 3-component array}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{the name of the node mask array (`FAS::parameters::mask_array_name()`);
      an error if given and absent; the empty string reads no mask}
    \cgalParamType{`std::string`}
    \cgalParamDefault{`"inside"` if the file has it, else no mask}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `write_VTK_flow_field()`, `Regular_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return internal::read_VTK_legacy(filename, field, np, error, &internal::read_VTK_legacy_grid<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a rectilinear grid from a legacy VTK file into an optional;
same as the overload below otherwise.

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np the named parameters of the overload below
\param error if not null, receives the reason of a failure
\returns `true` on success.
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, std::optional<Rectilinear_grid_flow_field_3<K>>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return internal::read_VTK_legacy(filename, field, np, error, &internal::read_VTK_legacy_rectilinear<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a rectilinear grid from a legacy VTK file.

As the `Regular_grid_flow_field_3` overload, for `DATASET RECTILINEAR_GRID` (`DIMENSIONS`, then
`X_COORDINATES nx type`, `Y_COORDINATES ny type`, `Z_COORDINATES nz type`, each count equal to
the matching dimension and the coordinates strictly increasing) and for `DATASET
STRUCTURED_POINTS` (its nodes `origin + i·spacing` along each axis).  The velocity and mask
arrays, the named parameters and the messages are those of that overload; a coordinate that is
not finite or not increasing is named with its axis and index.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np an optional sequence of named parameters: `array_name` and `mask_array_name`, as
          in the `Regular_grid_flow_field_3` overload
\param error if not null, receives the reason of a failure

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `Rectilinear_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, Rectilinear_grid_flow_field_3<K>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return internal::read_VTK_legacy(filename, field, np, error, &internal::read_VTK_legacy_rectilinear<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on cells from a legacy VTK file into an optional; same as the
overload below otherwise.

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np the named parameters of the overload below
\param error if not null, receives the reason of a failure
\returns `true` on success.
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, std::optional<Unstructured_flow_field_3<K>>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return internal::read_VTK_legacy(filename, field, np, error, &internal::read_VTK_legacy_cells<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on the cells of any legacy VTK dataset with volume cells.

- `DATASET UNSTRUCTURED_GRID`: `POINTS n type`, then `CELLS` in either form: the legacy one
  (file versions up to 5.0: `CELLS n size`, then per cell its number of points and their
  indices) or the one of file version 5.1 (`CELLS n+1 size`, `OFFSETS type` with `n + 1`
  values, `CONNECTIVITY type` with `size` values), and `CELL_TYPES n`.  The cell types must
  be 10 (tetrahedron), 12 (hexahedron), 13 (wedge) or 14 (pyramid), with VTK's point orders
  (see `Unstructured_flow_field_3`), or 11 (voxel: read as the same hexahedron, its points
  0 1 3 2 4 5 7 6).
- `DATASET STRUCTURED_GRID` (`DIMENSIONS`, `POINTS`), `RECTILINEAR_GRID` and
  `STRUCTURED_POINTS`: their grid cells become hexahedra, cell `(i, j, k)` with the points
  `(i, j, k)`, `(i+1, j, k)`, `(i+1, j+1, k)`, `(i, j+1, k)` and the same at `k + 1`, whose
  isoparametric interpolation is the trilinear one of the grid.

The velocity and mask arrays, the named parameters, and the messages for bad input are those
of the `Regular_grid_flow_field_3` overload; besides, a cell of another type gives a message
naming the cell's index and its type, a point index out of range names the cell and the
value, and counts that do not match (`CELLS` and `CELL_TYPES`, the number of values a cell
list holds, `POINTS` and `DIMENSIONS`) give both numbers.  A **node mask removes every cell
that touches a solid point**: the same rule as the grid fields: the interior of a cell
touching a solid node is outside, and the faces that a kept cell shares with a removed one are
inside (they belong to the kept cell).  Solid points may have non-finite values (stored as
zero); every other point must have a finite velocity.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np an optional sequence of named parameters: `array_name` and `mask_array_name`, as
          in the `Regular_grid_flow_field_3` overload
\param error if not null, receives the reason of a failure

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `Unstructured_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, Unstructured_flow_field_3<K>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return internal::read_VTK_legacy(filename, field, np, error, &internal::read_VTK_legacy_cells<K>);
}

} // namespace IO

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H
