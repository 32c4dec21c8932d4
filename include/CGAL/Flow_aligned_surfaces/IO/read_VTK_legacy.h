// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a velocity field on a uniform grid from a legacy VTK file (`.vtk`, ASCII or BINARY,
// `DATASET STRUCTURED_POINTS`): nx × ny × nz nodes, a 3-component point data array (the
// velocity, 3·nx·ny·nz numbers) and optionally a 1-component array (the node mask, nx·ny·nz
// numbers).  The file is read in two passes over its bytes: the first checks the whole
// structure and records where each array starts, skipping the data; the second decodes only the
// two chosen arrays.  Every count is checked against the bytes left before anything is
// allocated, so a lying header cannot make the reader allocate more than the file's size.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H

#include <string>

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
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
  std::size_t begin = 0, line = 0; // byte offset and line of the first value
  bool point_data = true;
};

// Thrown inside the reader only; read_VTK_flow_field() turns it into `false` + message.
typedef Flow_aligned_surfaces::internal::Read_error VTK_legacy_error;
using Flow_aligned_surfaces::internal::printable;

class VTK_legacy_parser {
public:
  VTK_legacy_parser(const std::string& filename, std::string contents)
      : file_(filename), buf_(std::move(contents))
  {
  }

  std::array<std::size_t, 3> dimensions = {{0, 0, 0}};
  std::array<double, 3> origin = {{0., 0., 0.}}, spacing = {{1., 1., 1.}};
  std::size_t nodes = 0;
  std::vector<VTK_legacy_array> arrays;
  bool binary = false;

  [[noreturn]] void fail_at(std::size_t offset, std::size_t line, const std::string& what) const
  {
    std::ostringstream msg;
    msg << "read_VTK_flow_field: " << file_ << ": ";
    if (line != 0)
      msg << "line " << line << ", ";
    msg << "byte " << offset << ": " << what;
    throw VTK_legacy_error(msg.str());
  }
  [[noreturn]] void fail(const std::string& what) const { fail_at(pos_, line_, what); }
  [[noreturn]] void fail_file(const std::string& what) const
  {
    throw VTK_legacy_error("read_VTK_flow_field: " + file_ + ": " + what);
  }

  // Pass 1: the header, the geometry and the position of every array.
  void parse()
  {
    const std::string_view first = read_line();
    if (lower(first).rfind("# vtk datafile version", 0) != 0)
      fail_at(0, 1,
              "not a legacy VTK file: the first line is '" + printable(first) +
                  "'; expected '# vtk DataFile Version x.x'");
    read_line(); // the title, free text
    const std::string format = upper(token("the format (ASCII or BINARY)"));
    if (format == "BINARY")
      binary = true;
    else if (format != "ASCII")
      fail("unknown file format '" + format + "'; expected ASCII or BINARY");

    expect_keyword("DATASET");
    const std::string dataset = upper(token("the dataset type"));
    if (dataset == "RECTILINEAR_GRID" || dataset == "STRUCTURED_GRID" || dataset == "UNSTRUCTURED_GRID" ||
        dataset == "POLYDATA")
      fail("DATASET " + dataset + " is not supported by this reader yet; it reads STRUCTURED_POINTS");
    if (dataset != "STRUCTURED_POINTS")
      fail("unknown dataset type '" + dataset +
           "'; expected STRUCTURED_POINTS, STRUCTURED_GRID, RECTILINEAR_GRID, UNSTRUCTURED_GRID or POLYDATA");

    bool have_dimensions = false;
    std::string key;
    for (;;) {
      if (!next_token(key)) {
        key.clear();
        break;
      }
      key = upper(key);
      if (key == "DIMENSIONS") {
        for (int a = 0; a < 3; ++a)
          dimensions[a] = integer("DIMENSIONS");
        have_dimensions = true;
      }
      else if (key == "ORIGIN") {
        for (int a = 0; a < 3; ++a)
          origin[a] = real("ORIGIN");
      }
      else if (key == "SPACING" || key == "ASPECT_RATIO") {
        for (int a = 0; a < 3; ++a)
          spacing[a] = real(key.c_str());
      }
      else if (key == "FIELD") {
        field(false);
      }
      else if (key == "POINT_DATA" || key == "CELL_DATA") {
        break;
      }
      else {
        fail("unexpected keyword '" + key +
             "' in the STRUCTURED_POINTS geometry; expected DIMENSIONS, ORIGIN, SPACING, ASPECT_RATIO, "
             "FIELD, POINT_DATA or CELL_DATA");
      }
    }
    if (!have_dimensions)
      fail("the STRUCTURED_POINTS dataset has no DIMENSIONS");
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
    const std::size_t cells = (dimensions[0] - 1) * (dimensions[1] - 1) * (dimensions[2] - 1);

    // The attribute sections.
    while (!key.empty()) {
      const bool point_data = key == "POINT_DATA";
      if (point_data || key == "CELL_DATA") {
        const std::size_t n = integer(key.c_str());
        const std::size_t expected = point_data ? nodes : cells;
        if (n != expected)
          fail(key + " " + std::to_string(n) + " does not match DIMENSIONS " + dimensions_string() +
               ", which has " + std::to_string(expected) + (point_data ? " nodes" : " cells"));
        section_tuples_ = n;
        in_point_data_ = point_data;
        in_section_ = true;
      }
      else if (!in_section_) {
        fail("unexpected keyword '" + key + "' before POINT_DATA or CELL_DATA");
      }
      else if (key == "SCALARS") {
        const std::string name = token("the SCALARS name");
        const std::string type = data_type("SCALARS");
        std::size_t components = 1;
        std::string next;
        if (peek_token_on_line(next)) {
          components = integer("the SCALARS number of components");
          if (components < 1 || components > 4)
            fail("SCALARS '" + name + "' has " + std::to_string(components) + " components; expected 1 to 4");
        }
        if (peek_token(next) && upper(next) == "LOOKUP_TABLE") {
          next_token(next);
          token("the LOOKUP_TABLE name");
        }
        array("SCALARS", name, type, components, section_tuples_);
      }
      else if (key == "VECTORS" || key == "NORMALS") {
        const std::string name = token(key + " name");
        array(key, name, data_type(key.c_str()), 3, section_tuples_);
      }
      else if (key == "TENSORS" || key == "TENSORS6") {
        const std::string name = token(key + " name");
        array(key, name, data_type(key.c_str()), key == "TENSORS" ? 9 : 6, section_tuples_);
      }
      else if (key == "TEXTURE_COORDINATES") {
        const std::string name = token("the TEXTURE_COORDINATES name");
        const std::size_t dim = integer("the TEXTURE_COORDINATES dimension");
        if (dim < 1 || dim > 3)
          fail("TEXTURE_COORDINATES '" + name + "' has dimension " + std::to_string(dim) +
               "; expected 1 to 3");
        array(key, name, data_type(key.c_str()), dim, section_tuples_);
      }
      else if (key == "COLOR_SCALARS") {
        const std::string name = token("the COLOR_SCALARS name");
        const std::size_t n = integer("the COLOR_SCALARS number of values");
        if (n < 1 || n > 4)
          fail("COLOR_SCALARS '" + name + "' has " + std::to_string(n) + " values; expected 1 to 4");
        array(key, name, binary ? "unsigned_char" : "float", n, section_tuples_);
      }
      else if (key == "LOOKUP_TABLE") {
        const std::string name = token("the LOOKUP_TABLE name");
        const std::size_t n = integer("the LOOKUP_TABLE size");
        array(key, name, binary ? "unsigned_char" : "float", 4, n);
      }
      else if (key == "FIELD") {
        field(in_point_data_);
      }
      else {
        fail("unknown keyword '" + key +
             "'; expected POINT_DATA, CELL_DATA, SCALARS, VECTORS, NORMALS, TENSORS, TEXTURE_COORDINATES, "
             "COLOR_SCALARS, LOOKUP_TABLE or FIELD");
      }
      if (!next_token(key))
        key.clear();
      else
        key = upper(key);
    }
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
    pos_ = a.begin;
    line_ = a.line;
    if (binary) {
      // Decoded in blocks that stay in the L1 cache, so that the block decoding is a tight loop.
      const std::size_t size = type_size(a.type);
      const Binary_type type = binary_type(a.type);
      const unsigned char* data = reinterpret_cast<const unsigned char*>(buf_.data());
      constexpr std::size_t block_size = 1024;
      double block[block_size];
      for (std::size_t i0 = 0; i0 < count; i0 += block_size) {
        const std::size_t m = count - i0 < block_size ? count - i0 : block_size;
        // Big-endian, as VTK's legacy writer writes, whatever the host.
        Flow_aligned_surfaces::internal::decode_binary_numbers(
            type, Flow_aligned_surfaces::internal::Byte_order::BIG_ENDIAN_ORDER, data + pos_, m, block);
        for (std::size_t j = 0; j < m; ++j, pos_ += size)
          out(i0 + j, block[j], pos_, 0);
      }
    }
    else {
      std::string_view t;
      for (std::size_t i = 0; i < count; ++i) {
        next_view(t, a);
        out(i, ascii_value(t, a), pos_ - t.size(), line_);
      }
    }
  }

  std::string dimensions_string() const
  {
    return std::to_string(dimensions[0]) + " " + std::to_string(dimensions[1]) + " " +
           std::to_string(dimensions[2]);
  }

  static std::string upper(std::string_view s)
  {
    std::string r(s);
    for (char& c : r)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return r;
  }

  static std::string lower(std::string_view s)
  {
    std::string r(s);
    for (char& c : r)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
  }

private:
  static bool is_space(char c)
  {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
  }

  std::string_view read_line()
  {
    const std::size_t start = pos_;
    while (pos_ < buf_.size() && buf_[pos_] != '\n')
      ++pos_;
    std::string_view l(buf_.data() + start, pos_ - start);
    if (pos_ < buf_.size()) {
      ++pos_;
      ++line_;
    }
    if (!l.empty() && l.back() == '\r')
      l.remove_suffix(1);
    return l;
  }

  void skip_space()
  {
    while (pos_ < buf_.size() && is_space(buf_[pos_])) {
      if (buf_[pos_] == '\n')
        ++line_;
      ++pos_;
    }
  }

  bool next_view(std::string_view& t)
  {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < buf_.size() && !is_space(buf_[pos_]))
      ++pos_;
    t = std::string_view(buf_.data() + start, pos_ - start);
    return !t.empty();
  }

  void next_view(std::string_view& t, const VTK_legacy_array& a)
  {
    if (!next_view(t))
      fail("the file ends inside the values of " + a.kind + " '" + a.name + "'");
  }

  bool next_token(std::string& t)
  {
    std::string_view v;
    if (!next_view(v))
      return false;
    t.assign(v);
    return true;
  }

  bool peek_token(std::string& t)
  {
    const std::size_t p = pos_, l = line_;
    const bool r = next_token(t);
    pos_ = p;
    line_ = l;
    return r;
  }

  bool peek_token_on_line(std::string& t)
  {
    std::size_t p = pos_;
    while (p < buf_.size() && (buf_[p] == ' ' || buf_[p] == '\t' || buf_[p] == '\r'))
      ++p;
    if (p >= buf_.size() || buf_[p] == '\n')
      return false;
    return peek_token(t);
  }

  std::string token(const std::string& what)
  {
    std::string t;
    if (!next_token(t))
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
    const std::string t = token(std::string("a number of ") + what);
    std::size_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail("'" + printable(t) + "' is not a non-negative integer (" + what + ")");
    return v;
  }

  double real(const char* what)
  {
    const std::string t = token(std::string("a number of ") + what);
    double v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
      fail("'" + printable(t) + "' is not a finite number (" + what + ")");
    return v;
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
      const std::string name = token("a FIELD array name");
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

  // Records an array and skips its values, after checking that they fit in what is left.
  void array(const std::string& kind, const std::string& name, const std::string& type,
             std::size_t components, std::size_t tuples, bool candidate = true)
  {
    const std::size_t left = buf_.size() - pos_;
    if (components != 0 && tuples > left / components)
      fail(kind + " '" + name + "' needs " + std::to_string(tuples) + " x " + std::to_string(components) +
           " values but only " + std::to_string(left) + " bytes are left (truncated file or wrong count)");
    const std::size_t count = components * tuples;
    VTK_legacy_array a;
    a.name = name;
    a.kind = kind;
    a.type = type;
    a.components = components;
    a.tuples = tuples;
    a.point_data = in_point_data_ && candidate && kind != "LOOKUP_TABLE";
    if (binary) {
      // The values start right after the end of the header line.
      while (pos_ < buf_.size() && buf_[pos_] != '\n') {
        if (!is_space(buf_[pos_]))
          fail("unexpected text after the header of " + kind + " '" + name + "'");
        ++pos_;
      }
      if (pos_ < buf_.size()) {
        ++pos_;
        ++line_;
      }
      const std::size_t bytes = type == "bit" ? (count + 7) / 8 : count * type_size(type);
      const std::size_t remaining = buf_.size() - pos_;
      if (bytes > remaining)
        fail(kind + " '" + name + "' (" + type + ") needs " + std::to_string(bytes) +
             " bytes of binary data but only " + std::to_string(remaining) +
             " are left (truncated file or wrong count)");
      a.begin = pos_;
      a.line = 0;
      pos_ += bytes;
    }
    else {
      if (count > (left + 1) / 2)
        fail(kind + " '" + name + "' needs " + std::to_string(count) + " values but only " +
             std::to_string(left) + " bytes are left (truncated file or wrong count)");
      skip_space();
      a.begin = pos_;
      a.line = line_;
      std::string_view t;
      for (std::size_t i = 0; i < count; ++i) {
        next_view(t, a);
        if (a.type != "bit")
          ascii_value(t, a);
      }
    }
    arrays.push_back(std::move(a));
    skip_metadata();
  }

  // VTK ≥ 8 may follow an array with METADATA and INFORMATION lines, ended by an empty line.
  void skip_metadata()
  {
    std::string next;
    if (!peek_token(next) || upper(next) != "METADATA")
      return;
    next_token(next);
    read_line();
    while (pos_ < buf_.size()) {
      const std::string_view l = read_line();
      if (l.find_first_not_of(" \t\r") == std::string_view::npos)
        return;
    }
  }

  double ascii_value(std::string_view t, const VTK_legacy_array& a) const
  {
    double v = 0;
    const char* b = t.data();
    const char* e = b + t.size();
    if (b != e && *b == '+')
      ++b;
    auto r = std::from_chars(b, e, v);
    if (r.ec == std::errc::result_out_of_range)
      v = (b != e && *b == '-') ? -std::numeric_limits<double>::infinity()
                                : std::numeric_limits<double>::infinity();
    else if (r.ec != std::errc() || r.ptr != e)
      fail_at(pos_ - t.size(), line_,
              "'" + printable(t) + "' is not a number (in the values of " + a.kind + " '" + a.name + "')");
    return v;
  }

  // The binary decodings, chosen once per array rather than once per value.
  typedef Flow_aligned_surfaces::internal::Binary_type Binary_type;

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

  std::string file_;
  std::string buf_;
  std::size_t pos_ = 0, line_ = 1;
  std::size_t section_tuples_ = 0;
  bool in_point_data_ = false, in_section_ = false;
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

// Reads the file and builds the field; throws VTK_legacy_error with the message.
template <class K>
Regular_grid_flow_field_3<K> read_VTK_legacy_grid(const std::string& filename, const std::string* array_name,
                                                  const std::string* mask_name)
{
  std::string contents = Flow_aligned_surfaces::internal::read_file_contents(filename, "read_VTK_flow_field");
  VTK_legacy_parser parser(filename, std::move(contents));
  parser.parse();

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
                       "' has " + std::to_string(a->tuples) + " tuples but the grid (DIMENSIONS " +
                       parser.dimensions_string() + ") has " + std::to_string(parser.nodes) + " nodes");

  const std::size_t nodes = parser.nodes;
  std::vector<unsigned char> flags;
  if (mask != nullptr) {
    flags.resize(nodes);
    parser.decode(*mask, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
      if (std::isnan(v))
        parser.fail_at(offset, line, "the mask '" + mask->name + "' is NaN at node " + std::to_string(i));
      flags[i] = v != 0. ? 1 : 0;
    });
  }
  std::vector<float> values(3 * nodes);
  parser.decode(*velocity, [&](std::size_t i, double v, std::size_t offset, std::size_t line) {
    const std::size_t node = i / 3;
    const bool representable =
        std::isfinite(v) && std::fabs(v) <= static_cast<double>((std::numeric_limits<float>::max)());
    if (!flags.empty() && flags[node] == 0) {
      // The constructor replaces a solid node's non-finite values by zeros.
      values[i] = representable ? static_cast<float>(v) : std::numeric_limits<float>::quiet_NaN();
      return;
    }
    if (!representable) {
      const std::size_t nx = parser.dimensions[0], ny = parser.dimensions[1];
      std::ostringstream msg;
      msg << "the velocity '" << velocity->name << "' at node " << node << " = (" << node % nx << ", "
          << (node / nx) % ny << ", " << node / (nx * ny) << "), component " << i % 3 << ", is " << v
          << (std::isfinite(v) ? ", which does not fit in a 32-bit float" : "; expected a finite number")
          << (flags.empty() ? "" : " at a fluid node");
      parser.fail_at(offset, line, msg.str());
    }
    values[i] = static_cast<float>(v);
  });

  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  try {
    return Regular_grid_flow_field_3<K>(Point_3(parser.origin[0], parser.origin[1], parser.origin[2]),
                                        Vector_3(parser.spacing[0], parser.spacing[1], parser.spacing[2]),
                                        parser.dimensions, std::move(values), std::move(flags));
  } catch (const std::invalid_argument& e) {
    parser.fail_file(e.what());
  }
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
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::string array_name =
      choose_parameter(get_parameter(np, Flow_aligned_surfaces::internal_np::array_name_t()), std::string());
  const std::string mask_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::mask_array_name_t()), std::string());
  constexpr bool has_array_name =
      !parameters::is_default_parameter<NamedParameters,
                                        Flow_aligned_surfaces::internal_np::array_name_t>::value;
  constexpr bool has_mask_name =
      !parameters::is_default_parameter<NamedParameters,
                                        Flow_aligned_surfaces::internal_np::mask_array_name_t>::value;
  try {
    field.emplace(internal::read_VTK_legacy_grid<K>(filename, has_array_name ? &array_name : nullptr,
                                                    has_mask_name ? &mask_name : nullptr));
    return true;
  } catch (const internal::VTK_legacy_error& e) {
    if (error)
      *error = e.what();
  } catch (const std::bad_alloc&) {
    if (error)
      *error = "read_VTK_flow_field: " + filename + ": not enough memory for the field";
  }
  return false;
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a legacy VTK file.

The file must be a legacy VTK file (`# vtk DataFile Version x.x`), ASCII or BINARY (big-endian,
as VTK writes it), with `DATASET STRUCTURED_POINTS` (`DIMENSIONS`, `ORIGIN`, `SPACING`, or its
older synonym `ASPECT_RATIO`; at least 2 nodes along each axis).  The velocity is a
3-component `POINT_DATA` array: `VECTORS`, `NORMALS`, a 3-component `SCALARS` or a
3-component `FIELD` array, of any numeric type (stored as 32-bit floats).  The node mask is a
1-component `POINT_DATA` array of any numeric type, nonzero = fluid.  Every other array and
every `CELL_DATA` section is skipped.

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
  std::optional<Regular_grid_flow_field_3<K>> result;
  if (!read_VTK_flow_field(filename, result, np, error))
    return false;
  field = std::move(*result);
  return true;
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H
