// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The header of a NRRD file (`.nrrd` or `.nhdr`): the magic line, then one field per line up to
// an empty line (or the end of a detached header).  Every field is checked as it is read; the
// sizes are checked against each other once the header is read, before anything is allocated.
// Failures are thrown as `Read_error` naming the line and the byte of the value.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_NRRD_NRRD_HEADER_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_NRRD_NRRD_HEADER_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/inflate_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

class NRRD_header {
public:
  NRRD_header(const std::string& filename, std::string_view contents)
      : in("read_NRRD_flow_field", filename, contents)
  {
  }

  Text_cursor in;
  std::array<std::size_t, 3> dimensions = {{0, 0, 0}};
  std::array<double, 3> origin = {{0., 0., 0.}}, spacing = {{1., 1., 1.}};
  Binary_type type = Binary_type::FLOAT32;
  std::string type_name, encoding = "raw", content, data_file;
  std::optional<Byte_order> order;
  long long byte_skip = 0;
  std::size_t line_skip = 0;
  std::size_t data_start = 0, data_line = 0; // attached data: where they start in the file
  std::size_t nodes = 0;

  void parse()
  {
    magic_line();
    while (!in.at_end()) {
      const std::size_t start = in.pos, line = in.line;
      const std::string_view l = in.read_line();
      if (l.empty())
        break; // the end of the header: attached data follow
      if (l[0] == '#')
        continue;
      if (l.find(":=") != std::string_view::npos && l.find(":=") < l.find(": "))
        continue; // a key/value pair
      const std::size_t colon = l.find(": ");
      if (colon == std::string_view::npos)
        in.fail_at(start, line,
                   "'" + printable(l) +
                       "' is neither a field 'name: value', a 'key:=value' pair nor a comment");
      Field f{std::string(l.substr(0, colon)), l.substr(colon + 2),
              Text_cursor("read_NRRD_flow_field", in.file(), l.substr(colon + 2)), start + colon + 2, line};
      if (!geometry_field(f))
        data_field(f);
      // Every other field (space, centers, labels, units, axis mins, ...) says nothing about
      // where the nodes are once the origin and the steps are known.
    }
    data_start = in.pos;
    data_line = in.line;
    check_header();
  }

  std::string dimensions_string() const
  {
    return std::to_string(dimensions[0]) + " " + std::to_string(dimensions[1]) + " " +
           std::to_string(dimensions[2]);
  }

private:
  // One header line `name: value`: `rest` is the value as written, `value` reads its tokens.
  struct Field {
    std::string name;
    std::string_view rest;
    Text_cursor value;
    std::size_t offset, line; // of the value
  };

  bool m_have_type = false, m_have_dimension = false, m_have_sizes = false;
  std::size_t m_sizes_line = 0;

  void magic_line()
  {
    const std::string_view magic = in.read_line();
    if (magic.size() != 8 || magic.substr(0, 7) != "NRRD000" || magic[7] < '1' || magic[7] > '5')
      in.fail_at(0, 1,
                 "not a NRRD file: the first line is '" + printable(magic) +
                     "'; expected NRRD0001 to NRRD0005");
  }

  // Messages about a value name the line and the byte of the value.
  auto failure(const Field& f) const
  {
    return [this, &f](const std::string& what) { in.fail_at(f.offset, f.line, f.name + ": " + what); };
  }

  // The fields that place the nodes; false for any other field.
  bool geometry_field(Field& f)
  {
    const auto fail = failure(f);
    Text_cursor& value = f.value;
    if (f.name == "dimension") {
      const std::size_t d = integer(value, fail, "the dimension");
      if (d != 4)
        fail("the dimension is " + std::to_string(d) +
             "; a velocity field is 4-dimensional: sizes 3 nx ny nz (the vector axis first)");
      m_have_dimension = true;
    }
    else if (f.name == "sizes") {
      if (!m_have_dimension)
        fail("'sizes' comes before 'dimension'");
      const std::size_t c = integer(value, fail, "the size of axis 0");
      if (c != 3)
        fail("the first axis has " + std::to_string(c) +
             " samples; expected 3, the velocity components (sizes: 3 nx ny nz)");
      for (int a = 0; a < 3; ++a)
        dimensions[a] = integer(value, fail, "the size of axis " + std::to_string(a + 1));
      end_of_value(value, fail, "4 sizes");
      m_have_sizes = true;
      m_sizes_line = f.line;
    }
    else if (f.name == "spacings") {
      value.token(); // the vector axis: nan
      for (int a = 0; a < 3; ++a) {
        spacing[a] = real(value, fail, "the spacing of axis " + std::to_string(a + 1));
        if (!(spacing[a] > 0.))
          fail("the spacing of axis " + std::to_string(a + 1) + " is " + std::to_string(spacing[a]) +
               "; expected a positive number");
      }
      end_of_value(value, fail, "4 spacings");
    }
    else if (f.name == "space directions")
      space_directions(f);
    else if (f.name == "space origin") {
      origin = vector(value, fail, "the space origin");
      end_of_value(value, fail, "one vector");
    }
    else if (f.name == "space dimension") {
      if (integer(value, fail, "the space dimension") != 3)
        fail("only 3-dimensional spaces are supported");
    }
    else if (f.name == "kinds")
      kinds(f);
    else
      return false;
    return true;
  }

  void space_directions(Field& f)
  {
    const auto fail = failure(f);
    const std::string_view first = f.value.token();
    if (first != "none")
      fail("the first direction is '" + printable(first) + "'; expected 'none' for the vector axis");
    for (int a = 0; a < 3; ++a) {
      const std::array<double, 3> d = vector(f.value, fail, "the direction of axis " + std::to_string(a + 1));
      for (int b = 0; b < 3; ++b)
        if ((b == a) != (d[b] != 0.) || d[a] < 0.)
          fail("the direction of axis " + std::to_string(a + 1) + " is (" + std::to_string(d[0]) + "," +
               std::to_string(d[1]) + "," + std::to_string(d[2]) +
               "): rotated, sheared, permuted or mirrored frames are not supported; expected the axes "
               "(hx,0,0) (0,hy,0) (0,0,hz) with positive steps");
      spacing[a] = d[a];
    }
    end_of_value(f.value, fail, "4 directions");
  }

  void kinds(Field& f)
  {
    const auto fail = failure(f);
    const std::string first = Text_cursor::lower(f.value.token());
    if (first == "domain" || first == "space" || first == "time")
      fail("the first axis is a '" + first +
           "' axis; the vector axis must come first (kinds: vector domain domain domain)");
    for (int a = 0; a < 3; ++a) {
      const std::string k = Text_cursor::lower(f.value.token());
      if (k != "domain" && k != "space" && k != "???" && k != "none")
        fail("axis " + std::to_string(a + 1) + " is of kind '" + printable(k) +
             "'; expected domain (the vector axis first, then x, y, z)");
    }
  }

  // The fields that say how the values are stored and where; every other field is skipped.
  void data_field(Field& f)
  {
    const auto fail = failure(f);
    if (f.name == "type") {
      type_name = trim(f.rest);
      if (!binary_type(type_name, type))
        fail("unknown or unsupported type '" + printable(type_name) +
             "'; expected one of the numeric types (int8 ... uint64, float, double and their synonyms)");
      m_have_type = true;
    }
    else if (f.name == "endian") {
      const std::string e = trim(f.rest);
      if (e == "little")
        order = Byte_order::LITTLE_ENDIAN_ORDER;
      else if (e == "big")
        order = Byte_order::BIG_ENDIAN_ORDER;
      else
        fail("unknown endian '" + printable(e) + "'; expected little or big");
    }
    else if (f.name == "encoding")
      encoding_field(f);
    else if (f.name == "byte skip") {
      const std::string s = trim(f.rest);
      const auto r = std::from_chars(s.data(), s.data() + s.size(), byte_skip);
      if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || byte_skip < -1)
        fail("'" + printable(s) + "' is not a byte count (or -1)");
    }
    else if (f.name == "line skip") {
      line_skip = integer(f.value, fail, "the number of lines to skip");
    }
    else if (f.name == "data file" || f.name == "datafile") {
      data_file = trim(f.rest);
      if (data_file.rfind("LIST", 0) == 0 || data_file.find('%') != std::string::npos ||
          data_file.find(' ') != std::string::npos)
        fail("'" + printable(data_file) +
             "': data split over several files are not supported; expected one file name");
    }
    else if (f.name == "content") {
      content = trim(f.rest);
    }
  }

  void encoding_field(const Field& f)
  {
    const auto fail = failure(f);
    encoding = Text_cursor::lower(trim(f.rest));
    if (encoding == "txt" || encoding == "text")
      encoding = "ascii";
    if (encoding == "gz")
      encoding = "gzip";
    if (encoding == "gzip" && !have_inflate())
      fail("encoding gzip is not supported by this build (it needs zlib: define "
           "CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB and link zlib); decompress the data first");
    if (encoding == "bzip2" || encoding == "bz2" || encoding == "hex")
      fail("encoding " + encoding +
           " is not supported; expected raw, ascii or gzip (decompress the data first)");
    if (encoding != "raw" && encoding != "ascii" && encoding != "gzip")
      fail("unknown encoding '" + printable(encoding) + "'; expected raw, ascii or gzip");
  }

  // The checks of the whole header once it is read; sets `nodes`.
  void check_header()
  {
    if (!m_have_type)
      in.fail_file("the header has no 'type' field");
    if (!m_have_dimension || !m_have_sizes)
      in.fail_file("the header has no 'dimension: 4' and 'sizes: 3 nx ny nz' fields");
    for (int a = 0; a < 3; ++a)
      if (dimensions[a] < 2)
        in.fail_at(0, m_sizes_line,
                   "sizes 3 " + dimensions_string() +
                       ": a grid needs at least 2 nodes along each axis (empty, 1D and 2D grids are not "
                       "supported)");
    nodes = 1;
    for (int a = 0; a < 3; ++a) {
      if (nodes > (std::numeric_limits<std::size_t>::max)() / 64 / dimensions[a])
        in.fail_at(0, m_sizes_line, "sizes 3 " + dimensions_string() + " has too many nodes");
      nodes *= dimensions[a];
    }
    if (encoding != "ascii" && !order && binary_type_size(type) > 1)
      in.fail_file("the header has no 'endian' field (little or big), needed for " + encoding + " " +
                   type_name + " data");
    if (byte_skip == -1 && encoding != "raw")
      in.fail_file("'byte skip: -1' is only allowed with raw encoding");
  }

  static std::string trim(std::string_view s)
  {
    while (!s.empty() && Text_cursor::is_space(s.front()))
      s.remove_prefix(1);
    while (!s.empty() && Text_cursor::is_space(s.back()))
      s.remove_suffix(1);
    return std::string(s);
  }

  template <class Fail>
  static std::size_t integer(Text_cursor& value, const Fail& fail, const std::string& what)
  {
    const std::string_view t = value.token();
    std::size_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail("'" + printable(t) + "' is not a non-negative integer (" + what + ")");
    return v;
  }

  template <class Fail>
  static double real(Text_cursor& value, const Fail& fail, const std::string& what)
  {
    const std::string_view t = value.token();
    double v = 0;
    if (!Text_cursor::parse_number(t, v) || !std::isfinite(v))
      fail("'" + printable(t) + "' is not a finite number (" + what + ")");
    return v;
  }

  // A vector `(x,y,z)`, spaces allowed inside.
  template <class Fail>
  static std::array<double, 3> vector(Text_cursor& value, const Fail& fail, const std::string& what)
  {
    value.skip_space();
    const std::string_view b = value.bytes();
    const std::size_t open = value.pos;
    const std::size_t close = b.find(')', open);
    if (open >= b.size() || b[open] != '(' || close == std::string_view::npos)
      fail("expected " + what + " as (x,y,z), found '" + printable(b.substr(std::min(open, b.size()))) + "'");
    std::array<double, 3> v = {{0, 0, 0}};
    std::string_view inside = b.substr(open + 1, close - open - 1);
    for (int c = 0; c < 3; ++c) {
      const std::size_t comma = inside.find(',');
      if ((c < 2) == (comma == std::string_view::npos))
        fail(what + " '" + printable(b.substr(open, close + 1 - open)) +
             "' does not have 3 components; only 3D spaces are supported");
      const std::string t = trim(inside.substr(0, comma));
      if (!Text_cursor::parse_number(t, v[c]) || !std::isfinite(v[c]))
        fail("'" + printable(t) + "' is not a finite number (in " + what + ")");
      inside = comma == std::string_view::npos ? std::string_view() : inside.substr(comma + 1);
    }
    value.pos = close + 1;
    return v;
  }

  template <class Fail>
  static void end_of_value(Text_cursor& value, const Fail& fail, const std::string& expected)
  {
    const std::string_view t = value.token();
    if (!t.empty())
      fail("unexpected '" + printable(t) + "' after " + expected);
  }

  static bool binary_type(const std::string& t, Binary_type& type)
  {
    static const std::pair<const char*, Binary_type> types[] = {
        {"signed char", Binary_type::INT8},
        {"int8", Binary_type::INT8},
        {"int8_t", Binary_type::INT8},
        {"uchar", Binary_type::UINT8},
        {"unsigned char", Binary_type::UINT8},
        {"uint8", Binary_type::UINT8},
        {"uint8_t", Binary_type::UINT8},
        {"short", Binary_type::INT16},
        {"short int", Binary_type::INT16},
        {"signed short", Binary_type::INT16},
        {"signed short int", Binary_type::INT16},
        {"int16", Binary_type::INT16},
        {"int16_t", Binary_type::INT16},
        {"ushort", Binary_type::UINT16},
        {"unsigned short", Binary_type::UINT16},
        {"unsigned short int", Binary_type::UINT16},
        {"uint16", Binary_type::UINT16},
        {"uint16_t", Binary_type::UINT16},
        {"int", Binary_type::INT32},
        {"signed int", Binary_type::INT32},
        {"int32", Binary_type::INT32},
        {"int32_t", Binary_type::INT32},
        {"uint", Binary_type::UINT32},
        {"unsigned int", Binary_type::UINT32},
        {"uint32", Binary_type::UINT32},
        {"uint32_t", Binary_type::UINT32},
        {"longlong", Binary_type::INT64},
        {"long long", Binary_type::INT64},
        {"long long int", Binary_type::INT64},
        {"signed long long", Binary_type::INT64},
        {"signed long long int", Binary_type::INT64},
        {"int64", Binary_type::INT64},
        {"int64_t", Binary_type::INT64},
        {"ulonglong", Binary_type::UINT64},
        {"unsigned long long", Binary_type::UINT64},
        {"unsigned long long int", Binary_type::UINT64},
        {"uint64", Binary_type::UINT64},
        {"uint64_t", Binary_type::UINT64},
        {"float", Binary_type::FLOAT32},
        {"double", Binary_type::FLOAT64}};
    for (const auto& p : types)
      if (t == p.first) {
        type = p.second;
        return true;
      }
    return false;
  }
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_NRRD_NRRD_HEADER_H
