// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parser of legacy VTK files (`.vtk`, ASCII or BINARY): the file's structure in two passes
// over its bytes.  The first (`parse()`) checks the header, the geometry and the sections and
// records where each array starts, skipping the data; the second decodes only the arrays
// needed, each value checked.  Every count is checked against the bytes left before anything
// is allocated, so a lying header cannot make the reader allocate more than the file's size.
// Failures are thrown as `Read_error` with the line and byte offset.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_LEGACY_VTK_LEGACY_PARSER_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_LEGACY_VTK_LEGACY_PARSER_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/checked_float_decoding.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reserve_huge_pages.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
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

class VTK_legacy_parser {
public:
  VTK_legacy_parser(const std::string& filename, File_contents contents)
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
    header(accepted, target);
    bool have_dimensions = false;
    std::string key = geometry(have_dimensions);
    if (dataset == "UNSTRUCTURED_GRID")
      check_unstructured_geometry();
    else
      check_structured_geometry(have_dimensions);
    for (; !key.empty(); key = upper(m_in.token()))
      attribute(key);
  }

  // The first line, the title, the format and the dataset type, checked against `accepted`.
  void header(std::initializer_list<const char*> accepted, const char* target)
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
  }

  // The geometry keywords of `dataset`, up to the first attribute section: returns its keyword
  // (POINT_DATA or CELL_DATA), or "" at the end of the file.
  std::string geometry(bool& have_dimensions)
  {
    const bool structured_points = dataset == "STRUCTURED_POINTS",
               rectilinear = dataset == "RECTILINEAR_GRID", curvilinear = dataset == "STRUCTURED_GRID",
               unstructured = dataset == "UNSTRUCTURED_GRID";
    for (;;) {
      const std::string key = upper(m_in.token());
      if (key.empty() || key == "POINT_DATA" || key == "CELL_DATA")
        return key;
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
      else if (key == "CELLS" && unstructured)
        cells_keyword();
      else if (key == "CELL_TYPES" && unstructured) {
        const std::size_t n = integer("CELL_TYPES");
        if (have_cells && n != cells)
          fail("CELL_TYPES " + std::to_string(n) + " does not match the " + std::to_string(cells) +
               " cells of CELLS");
        cell_types = geometry_array(key, "int", 1, n);
      }
      else if (key == "FIELD")
        field(false);
      else
        fail("unexpected keyword '" + printable(key) + "' in the " + dataset + " geometry; expected " +
             (structured_points ? "DIMENSIONS, ORIGIN, SPACING, ASPECT_RATIO"
              : rectilinear     ? "DIMENSIONS, X_COORDINATES, Y_COORDINATES, Z_COORDINATES"
              : curvilinear     ? "DIMENSIONS, POINTS"
                                : "POINTS, CELLS, CELL_TYPES") +
             ", FIELD, POINT_DATA or CELL_DATA");
    }
  }

  // `CELLS n size` of an UNSTRUCTURED_GRID, in either form.
  void cells_keyword()
  {
    const std::size_t n = integer("CELLS"), size = integer("the CELLS size");
    if (upper(m_in.peek_token()) == "OFFSETS") {
      // VTK >= 9 (file version 5.1): n offsets (cells + 1) and `size` point indices.
      if (n == 0)
        fail("CELLS 0 " + std::to_string(size) + ": the OFFSETS form needs the number of cells + 1 offsets");
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
      cell_list = geometry_array("CELLS", "int", 1, size);
      cells = n;
    }
    have_cells = true;
  }

  // One keyword of the attribute sections: a section (POINT_DATA n, CELL_DATA n) or an array
  // in the current one, whose position is recorded and whose values are skipped.
  void attribute(const std::string& key)
  {
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
    else if (!m_in_section)
      fail("unexpected keyword '" + key + "' before POINT_DATA or CELL_DATA");
    else if (key == "SCALARS")
      scalars();
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
        fail("TEXTURE_COORDINATES '" + name + "' has dimension " + std::to_string(dim) + "; expected 1 to 3");
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
    else if (key == "FIELD")
      field(m_in_point_data);
    else
      fail("unknown keyword '" + key +
           "'; expected POINT_DATA, CELL_DATA, SCALARS, VECTORS, NORMALS, TENSORS, TEXTURE_COORDINATES, "
           "COLOR_SCALARS, LOOKUP_TABLE or FIELD");
  }

  // `SCALARS name type [components]`, optionally followed by `LOOKUP_TABLE name`.
  void scalars()
  {
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
    return "node " + grid_node_string(dimensions, node);
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
        decode_binary_numbers(type, Byte_order::BIG_ENDIAN_ORDER, data + pos, m, block);
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
    Binary_type type;
    std::size_t size, begin;
    static constexpr Byte_order order = Byte_order::BIG_ENDIAN_ORDER;
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

  File_contents m_contents;
  Text_cursor m_in; // reads m_contents.view()
  std::size_t m_section_tuples = 0;
  bool m_in_point_data = false, m_in_section = false;
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_LEGACY_VTK_LEGACY_PARSER_H
