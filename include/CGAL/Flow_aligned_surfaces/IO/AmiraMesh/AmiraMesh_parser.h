// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parser of AmiraMesh files (`.am`): pass 1 over the file's bytes.  It reads the header
// (`define`, `Parameters`, the data declarations `Location { type[n] name } @N`), the uniform
// lattice it describes, then locates every `@N` data section, each size checked against the
// bytes left without allocating.  Failures are thrown as `Read_error` with the line and byte.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_AMIRAMESH_AMIRAMESH_PARSER_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_AMIRAMESH_AMIRAMESH_PARSER_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/uniform_grid_reading.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

// One data declaration `Location { type[components] name } @section(encoding,size)`.
struct AmiraMesh_data {
  Grid_array array;                          // located by the data section
  std::string location, type_name, encoding; // encoding: empty (raw), HxByteRLE, HxZip, ...
  std::size_t section = 0, compressed_size = 0;
  std::size_t declaration_offset = 0, declaration_line = 0;
  bool found = false; // whether its data section was met
};

class AmiraMesh_parser {
public:
  AmiraMesh_parser(const std::string& filename, std::string_view contents)
      : in("read_AmiraMesh_flow_field", filename, contents)
  {
  }

  Text_cursor in;
  std::array<std::size_t, 3> dimensions = {{0, 0, 0}};
  std::array<double, 3> origin = {{0., 0., 0.}}, spacing = {{1., 1., 1.}};
  std::size_t nodes = 0;
  std::vector<AmiraMesh_data> data;
  bool ascii = false;
  Byte_order order = Byte_order::BIG_ENDIAN_ORDER;

  // Pass 1.
  void parse()
  {
    first_line();
    header();
    geometry();
    sections();
  }

  std::string describe_lattice_fields() const
  {
    std::string r;
    for (const AmiraMesh_data& d : data) {
      if (d.location != "Lattice")
        continue;
      r += (r.empty() ? "'" : ", '") + d.array.name + "' (" + d.type_name + "[" +
           std::to_string(d.array.components) + "])";
    }
    return r.empty() ? std::string("none") : r;
  }

  std::string dimensions_string() const
  {
    return std::to_string(dimensions[0]) + " " + std::to_string(dimensions[1]) + " " +
           std::to_string(dimensions[2]);
  }

private:
  // A header token: a word, a quoted string (without its quotes), one of `{ } , =`, or a
  // section reference `@N(...)`.  Empty text and kind 0 at the end of the header.
  struct Token {
    std::string_view text;
    char kind = 0; // 'w' word, 's' string, '@' section, or the punctuation character itself
    std::size_t offset = 0, line = 0;
  };

  void first_line()
  {
    const std::string_view l = in.read_line();
    Text_cursor words("", "", l);
    const std::string_view hash = words.token(), name = words.token();
    bool known = hash == "#" && (name == "AmiraMesh" || name == "Avizo");
    std::string format;
    for (std::string_view w = words.token(); known && !w.empty(); w = words.token())
      if (w == "ASCII" || w == "BINARY" || w == "BINARY-LITTLE-ENDIAN" || w == "BINARY-BIG-ENDIAN")
        format = std::string(w);
    if (!known || format.empty())
      in.fail_at(0, 1,
                 "not an AmiraMesh file: the first line is '" + printable(l) +
                     "'; expected '# AmiraMesh BINARY-LITTLE-ENDIAN 2.1', '# AmiraMesh 3D BINARY 2.0', "
                     "'# AmiraMesh 3D ASCII 2.0' or the same with Avizo");
    ascii = format == "ASCII";
    order = format == "BINARY-LITTLE-ENDIAN" ? Byte_order::LITTLE_ENDIAN_ORDER : Byte_order::BIG_ENDIAN_ORDER;
  }

  static bool is_word_char(char c)
  {
    return !Text_cursor::is_space(c) && c != '{' && c != '}' && c != ',' && c != '"' && c != '#';
  }

  // The next header token; comments are skipped, and `# Data section follows` ends the header.
  Token next()
  {
    for (;;) {
      in.skip_space();
      Token t;
      t.offset = in.pos;
      t.line = in.line;
      if (in.at_end() || m_header_done)
        return t;
      const std::string_view b = in.bytes();
      const char c = b[in.pos];
      if (c == '#') {
        const std::string comment = Text_cursor::lower(in.read_line());
        if (comment.find("data section follows") != std::string::npos) {
          m_header_done = true;
          m_data_start = in.pos;
          m_data_line = in.line;
        }
        continue;
      }
      if (c == '{' || c == '}' || c == ',' || c == '=') {
        ++in.pos;
        t.kind = c;
        t.text = b.substr(t.offset, 1);
        return t;
      }
      if (c == '"') {
        ++in.pos;
        while (!in.at_end() && b[in.pos] != '"') {
          if (b[in.pos] == '\n')
            in.fail_at(t.offset, t.line, "a quoted string is not closed on its line");
          if (b[in.pos] == '\\' && in.pos + 1 < b.size())
            ++in.pos;
          ++in.pos;
        }
        if (in.at_end())
          in.fail_at(t.offset, t.line, "the file ends inside a quoted string");
        t.kind = 's';
        t.text = b.substr(t.offset + 1, in.pos - t.offset - 1);
        ++in.pos;
        return t;
      }
      if (c == '@') {
        // @N, possibly followed by (encoding,size)
        ++in.pos;
        while (!in.at_end() && b[in.pos] >= '0' && b[in.pos] <= '9')
          ++in.pos;
        if (!in.at_end() && b[in.pos] == '(') {
          while (!in.at_end() && b[in.pos] != ')' && b[in.pos] != '\n')
            ++in.pos;
          if (in.at_end() || b[in.pos] != ')')
            in.fail_at(t.offset, t.line,
                       "the section reference '" + printable(b.substr(t.offset, in.pos - t.offset)) +
                           "' has no closing ')'");
          ++in.pos;
        }
        t.kind = '@';
        t.text = b.substr(t.offset, in.pos - t.offset);
        return t;
      }
      while (!in.at_end() && is_word_char(b[in.pos]))
        ++in.pos;
      t.kind = 'w';
      t.text = b.substr(t.offset, in.pos - t.offset);
      return t;
    }
  }

  Token peek()
  {
    const std::size_t p = in.pos, l = in.line;
    const bool done = m_header_done;
    const std::size_t ds = m_data_start, dl = m_data_line;
    Token t = next();
    in.pos = p;
    in.line = l;
    m_header_done = done;
    m_data_start = ds;
    m_data_line = dl;
    return t;
  }

  [[noreturn]] void fail_at(const Token& t, const std::string& what) const
  {
    in.fail_at(t.offset, t.line, what);
  }

  static std::string shown(const Token& t)
  {
    return t.kind == 0 ? std::string("the end of the header") : "'" + printable(t.text) + "'";
  }

  Token expect(char kind, const std::string& what)
  {
    const Token t = next();
    if (t.kind != kind)
      fail_at(t, "found " + shown(t) + " where " + what + " was expected");
    return t;
  }

  std::size_t count(const Token& t, const std::string& what) const
  {
    std::size_t v = 0;
    const auto r = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (t.kind != 'w' || r.ec != std::errc() || r.ptr != t.text.data() + t.text.size())
      fail_at(t, shown(t) + " is not a non-negative integer (" + what + ")");
    return v;
  }

  double real(const Token& t, const std::string& what) const
  {
    double v = 0;
    if (t.kind != 'w' || !Text_cursor::parse_number(t.text, v) || !std::isfinite(v))
      fail_at(t, shown(t) + " is not a finite number (" + what + ")");
    return v;
  }

  // The header: `define`, `Parameters` and the data declarations, up to the data.
  void header()
  {
    for (;;) {
      const Token t = next();
      if (t.kind == 0)
        break;
      if (t.kind == '@') {
        // No `# Data section follows` line: the data start at the first section marker.
        m_header_done = true;
        m_data_start = t.offset;
        m_data_line = t.line;
        in.pos = t.offset;
        in.line = t.line;
        break;
      }
      if (t.kind != 'w')
        fail_at(t, "found " + shown(t) + " where 'define', 'Parameters' or a data declaration was expected");
      if (t.text == "define" || t.text == "nNodes" || t.text == "nTetrahedra" || t.text == "nTriangles") {
        define(t);
      }
      else if (t.text == "Parameters") {
        parameters_block();
      }
      else {
        const Token brace = next();
        if (brace.kind != '{')
          fail_at(t, "unexpected " + shown(t) +
                         " in the header; expected 'define', 'Parameters' or a data declaration "
                         "'Location { type name } @N'");
        declaration(t);
      }
    }
    if (!m_header_done)
      in.fail("the file has no data section (no '# Data section follows' line and no '@1' marker)");
  }

  // `define Name n1 n2 ...` (the numbers on the same line), or the older `nNodes n`.
  void define(const Token& keyword)
  {
    Token name = keyword;
    if (keyword.text == "define")
      name = expect('w', "the name of a define");
    std::vector<std::size_t> sizes;
    for (Token t = peek(); t.kind == 'w' && t.line == name.line; t = peek()) {
      next();
      sizes.push_back(count(t, "a size of '" + std::string(name.text) + "'"));
    }
    if (sizes.empty())
      fail_at(name, "the define '" + std::string(name.text) + "' has no size");
    std::size_t product = 1;
    for (std::size_t s : sizes) {
      if (s != 0 && product > (std::numeric_limits<std::size_t>::max)() / 64 / s)
        fail_at(name, "the define '" + std::string(name.text) + "' has too many elements");
      product *= s;
    }
    m_locations[std::string(name.text)] = product;
    if (name.text == "Lattice") {
      if (sizes.size() != 3)
        fail_at(name, "'define Lattice' has " + std::to_string(sizes.size()) +
                          " sizes; this reader reads 3D lattices (define Lattice nx ny nz)");
      for (int a = 0; a < 3; ++a)
        dimensions[a] = sizes[a];
      m_lattice = name;
      nodes = product;
    }
  }

  // `Parameters { ... }`: only BoundingBox and CoordType at the first level are read; nested
  // blocks and every other value are skipped.
  void parameters_block()
  {
    const Token open = expect('{', "'{' after Parameters");
    int depth = 1;
    bool entry_start = true;
    while (depth > 0) {
      const Token t = next();
      if (t.kind == 0)
        fail_at(open, "the Parameters block is not closed (no matching '}')");
      if (t.kind == '{')
        ++depth;
      else if (t.kind == '}')
        --depth;
      else if (depth == 1 && entry_start && t.kind == 'w' && t.text == "BoundingBox") {
        for (int i = 0; i < 6; ++i)
          m_bounding_box[i] = real(next(), "the BoundingBox xmin xmax ymin ymax zmin zmax");
        m_have_bounding_box = true;
        m_bounding_box_token = t;
      }
      else if (depth == 1 && entry_start && t.kind == 'w' && t.text == "CoordType") {
        const Token v = next();
        if (v.kind != 's' && v.kind != 'w')
          fail_at(v, "found " + shown(v) + " where the CoordType (a quoted string) was expected");
        m_coord_type = std::string(v.text);
        m_coord_type_token = v;
      }
      const Token after = peek();
      entry_start = t.kind == ',' || t.kind == '{' || t.kind == '}' || after.line != t.line;
    }
  }

  // `Location { type[n] name } @N` (the '{' already read), or with `= @N`.
  void declaration(const Token& location)
  {
    AmiraMesh_data d;
    d.location = std::string(location.text);
    d.declaration_offset = location.offset;
    d.declaration_line = location.line;
    const Token type = expect('w', "the data type of a '" + d.location + "' declaration");
    const Token name = expect('w', "the name of a '" + d.location + "' data field");
    expect('}', "'}' closing the declaration of '" + std::string(name.text) + "'");
    Token section = next();
    if (section.kind == '=')
      section = next();
    if (section.kind != '@')
      fail_at(section, "found " + shown(section) + " where the section reference '@N' of '" +
                           std::string(name.text) + "' was expected");
    d.array.name = std::string(name.text);

    // type[components]
    std::string_view tn = type.text;
    d.array.components = 1;
    const std::size_t bracket = tn.find('[');
    if (bracket != std::string_view::npos) {
      const std::string_view n = tn.substr(bracket + 1);
      std::size_t c = 0;
      const auto r = std::from_chars(n.data(), n.data() + n.size(), c);
      if (r.ec != std::errc() || r.ptr == n.data() + n.size() || *r.ptr != ']' ||
          r.ptr + 1 != n.data() + n.size() || c == 0 || c > 1024)
        fail_at(type, "the data type " + shown(type) + " has no valid '[components]' (1 to 1024)");
      d.array.components = c;
      tn = tn.substr(0, bracket);
    }
    d.type_name = std::string(tn);
    if (!binary_type(d.type_name, d.array.type))
      fail_at(type, "unknown data type '" + printable(tn) + "' of '" + d.array.name +
                        "'; expected byte, sbyte, short, ushort, int, uint, int64, uint64, float or double");

    // @N(encoding,size)
    std::string_view ref = section.text.substr(1);
    const std::size_t paren = ref.find('(');
    const std::string_view number = ref.substr(0, paren);
    const auto r = std::from_chars(number.data(), number.data() + number.size(), d.section);
    if (number.empty() || r.ec != std::errc() || r.ptr != number.data() + number.size())
      fail_at(section, "the section reference " + shown(section) + " has no section number");
    if (paren != std::string_view::npos) {
      const std::string_view inside = ref.substr(paren + 1, ref.size() - paren - 2);
      const std::size_t comma = inside.find(',');
      d.encoding = std::string(inside.substr(0, comma));
      const std::string_view size =
          comma == std::string_view::npos ? std::string_view() : inside.substr(comma + 1);
      const auto s = std::from_chars(size.data(), size.data() + size.size(), d.compressed_size);
      if (size.empty() || s.ec != std::errc() || s.ptr != size.data() + size.size())
        fail_at(section, "the section reference " + shown(section) +
                             " has no compressed size (expected '@N(" + d.encoding + ",size)')");
    }
    for (const AmiraMesh_data& other : data)
      if (other.section == d.section)
        fail_at(section, "section @" + std::to_string(d.section) + " is declared twice (for '" +
                             other.array.name + "' and '" + d.array.name + "')");
    d.array.ascii = ascii;
    d.array.order = order;
    d.array.bytes = in.bytes();
    data.push_back(std::move(d));
  }

  static bool binary_type(const std::string& t, Binary_type& type)
  {
    static const std::pair<const char*, Binary_type> types[] = {
        {"byte", Binary_type::UINT8},    {"ubyte", Binary_type::UINT8},   {"sbyte", Binary_type::INT8},
        {"short", Binary_type::INT16},   {"ushort", Binary_type::UINT16}, {"int", Binary_type::INT32},
        {"uint", Binary_type::UINT32},   {"int64", Binary_type::INT64},   {"uint64", Binary_type::UINT64},
        {"float", Binary_type::FLOAT32}, {"double", Binary_type::FLOAT64}};
    for (const auto& p : types)
      if (t == p.first) {
        type = p.second;
        return true;
      }
    return false;
  }

  // The lattice and its uniform coordinates.
  void geometry()
  {
    if (m_lattice.kind == 0)
      in.fail_file("the header has no 'define Lattice nx ny nz'; this reader reads uniform lattices");
    for (int a = 0; a < 3; ++a)
      if (dimensions[a] < 2)
        fail_at(m_lattice,
                "define Lattice " + dimensions_string() +
                    ": a grid needs at least 2 nodes along each axis (empty, 1D and 2D lattices are not "
                    "supported)");
    if (m_coord_type_token.kind != 0 && m_coord_type != "uniform")
      fail_at(m_coord_type_token, "CoordType \"" + printable(m_coord_type) +
                                      "\" is not supported; this reader reads uniform lattices "
                                      "(CoordType \"uniform\")");
    if (!m_have_bounding_box)
      in.fail_file("the Parameters have no BoundingBox xmin xmax ymin ymax zmin zmax; the node positions are "
                   "unknown");
    for (int a = 0; a < 3; ++a) {
      const double lo = m_bounding_box[2 * a], hi = m_bounding_box[2 * a + 1];
      origin[a] = lo;
      spacing[a] = (hi - lo) / static_cast<double>(dimensions[a] - 1);
      if (!(hi > lo) || !(spacing[a] > 0.) || !std::isfinite(spacing[a]))
        fail_at(m_bounding_box_token, "the BoundingBox gives [" + std::to_string(lo) + ", " +
                                          std::to_string(hi) + "] along axis " + std::to_string(a) +
                                          "; expected min < max (the first and the last node)");
    }
  }

  // Pass 1 over the data: every `@N` section in turn, its size checked against the bytes left.
  void sections()
  {
    in.pos = m_data_start;
    in.line = m_data_line;
    for (;;) {
      in.skip_space();
      if (in.at_end())
        break;
      // Lines mean nothing after binary data: no line is named then.
      const std::size_t marker = in.pos, marker_line = m_after_binary ? 0 : in.line;
      const std::string_view l = in.read_line();
      std::size_t n = 0;
      const auto r = l.empty() ? std::from_chars_result{l.data(), std::errc::invalid_argument}
                               : std::from_chars(l.data() + 1, l.data() + l.size(), n);
      const bool blank_after = r.ec == std::errc() &&
                               std::string_view(r.ptr, static_cast<std::size_t>(l.data() + l.size() - r.ptr))
                                       .find_first_not_of(" \t") == std::string_view::npos;
      if (l.empty() || l[0] != '@' || !blank_after)
        in.fail_at(marker, marker_line,
                   "found '" + printable(l) +
                       "' where a data section marker '@N' alone on its line was expected (wrong sizes in "
                       "the header?)");
      AmiraMesh_data* d = nullptr;
      for (AmiraMesh_data& candidate : data)
        if (candidate.section == n)
          d = &candidate;
      if (d == nullptr)
        in.fail_at(marker, marker_line,
                   "data section @" + std::to_string(n) + " has no declaration in the header");
      if (d->found)
        in.fail_at(marker, marker_line, "data section @" + std::to_string(n) + " appears twice");
      d->found = true;
      section(*d, marker, marker_line);
    }
  }

  void section(AmiraMesh_data& d, std::size_t marker, std::size_t marker_line)
  {
    const auto location = m_locations.find(d.location);
    if (location == m_locations.end())
      in.fail_at(d.declaration_offset, d.declaration_line,
                 "the data '" + d.array.name + "' is declared on '" + d.location + "', which has no define");
    d.array.tuples = location->second;
    if (d.array.tuples > (std::numeric_limits<std::size_t>::max)() / 64 / d.array.components)
      in.fail_at(d.declaration_offset, d.declaration_line,
                 "the data '" + d.array.name + "' have too many values (" + std::to_string(d.array.tuples) +
                     " x " + std::to_string(d.array.components) + ")");
    const std::size_t count = d.array.tuples * d.array.components; // < max / 64
    const std::size_t size = binary_type_size(d.array.type);
    const std::size_t left = in.left();
    const std::string what = "data section @" + std::to_string(d.section) + " ('" + d.array.name + "', " +
                             std::to_string(d.array.tuples) + " x " + d.type_name + "[" +
                             std::to_string(d.array.components) + "])";
    d.array.begin = in.pos;
    d.array.line = in.line;
    if (!d.encoding.empty()) {
      if (ascii)
        in.fail_at(marker, marker_line, what + " is compressed (" + d.encoding + ") in an ASCII file");
      if (d.compressed_size > left)
        in.fail_at(marker, marker_line,
                   what + " has " + std::to_string(d.compressed_size) + " compressed bytes but only " +
                       std::to_string(left) + " are left (truncated file or wrong size)");
      in.pos += d.compressed_size;
      m_after_binary = true;
      return;
    }
    if (ascii) {
      if (count > (left + 1) / 2)
        in.fail_at(marker, marker_line,
                   what + " needs " + std::to_string(count) + " values but only " + std::to_string(left) +
                       " bytes are left (truncated file or wrong sizes)");
      for (std::size_t i = 0; i < count; ++i) {
        const std::size_t before = in.pos;
        const std::string_view t = in.token();
        if (t.empty() || t[0] == '@') {
          if (!t.empty())
            in.pos = before;
          in.fail(what + " ends after " + std::to_string(i) + " of its " + std::to_string(count) +
                  " values (truncated file or wrong sizes)");
        }
      }
      return;
    }
    if (count > left / size)
      in.fail_at(marker, marker_line,
                 what + " needs " + std::to_string(count * size) + " bytes but only " + std::to_string(left) +
                     " are left (truncated file or wrong sizes)");
    in.pos += count * size;
    m_after_binary = true;
  }

  std::map<std::string, std::size_t> m_locations; // define name -> number of elements
  Token m_lattice, m_bounding_box_token, m_coord_type_token;
  std::array<double, 6> m_bounding_box = {{0, 0, 0, 0, 0, 0}};
  bool m_have_bounding_box = false;
  std::string m_coord_type;
  bool m_header_done = false, m_after_binary = false;
  std::size_t m_data_start = 0, m_data_line = 0;
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_AMIRAMESH_AMIRAMESH_PARSER_H
