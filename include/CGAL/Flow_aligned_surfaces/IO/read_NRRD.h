// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a velocity field on a uniform grid from a NRRD file (`.nrrd` with the data attached,
// or a `.nhdr` text header beside a raw data file): a 4-dimensional array of sizes
// 3 × nx × ny × nz (the vector axis first, then x fastest), whose sample (c, i, j, k) is the
// component c of the velocity at the node  origin + i·d_x + j·d_y + k·d_z,  where the origin
// is `space origin` and the axis-aligned steps d_a come from `space directions` or `spacings`.
// The header is read first and every size checked against the bytes of the data before
// anything is allocated; then the values are decoded.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_NRRD_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_NRRD_H

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/inflate_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/uniform_grid_reading.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

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
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \cond SKIP_IN_MANUAL
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

  void parse()
  {
    const std::string_view magic = in.read_line();
    if (magic.size() != 8 || magic.substr(0, 7) != "NRRD000" || magic[7] < '1' || magic[7] > '5')
      in.fail_at(0, 1,
                 "not a NRRD file: the first line is '" + printable(magic) +
                     "'; expected NRRD0001 to NRRD0005");
    bool have_type = false, have_dimension = false, have_sizes = false;
    std::size_t sizes_line = 0;
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
      const std::string field(l.substr(0, colon));
      Text_cursor value("read_NRRD_flow_field", in.file(), l.substr(colon + 2));
      // Messages about a value name the line and the byte of the value.
      auto fail = [&](const std::string& what) { in.fail_at(start + colon + 2, line, field + ": " + what); };
      const std::string_view rest = l.substr(colon + 2);
      if (field == "type") {
        type_name = trim(rest);
        if (!binary_type(type_name, type))
          fail("unknown or unsupported type '" + printable(type_name) +
               "'; expected one of the numeric types (int8 ... uint64, float, double and their synonyms)");
        have_type = true;
      }
      else if (field == "dimension") {
        const std::size_t d = integer(value, fail, "the dimension");
        if (d != 4)
          fail("the dimension is " + std::to_string(d) +
               "; a velocity field is 4-dimensional: sizes 3 nx ny nz (the vector axis first)");
        have_dimension = true;
      }
      else if (field == "sizes") {
        if (!have_dimension)
          fail("'sizes' comes before 'dimension'");
        const std::size_t c = integer(value, fail, "the size of axis 0");
        if (c != 3)
          fail("the first axis has " + std::to_string(c) +
               " samples; expected 3, the velocity components (sizes: 3 nx ny nz)");
        for (int a = 0; a < 3; ++a)
          dimensions[a] = integer(value, fail, "the size of axis " + std::to_string(a + 1));
        end_of_value(value, fail, "4 sizes");
        have_sizes = true;
        sizes_line = line;
      }
      else if (field == "spacings") {
        value.token(); // the vector axis: nan
        for (int a = 0; a < 3; ++a) {
          spacing[a] = real(value, fail, "the spacing of axis " + std::to_string(a + 1));
          if (!(spacing[a] > 0.))
            fail("the spacing of axis " + std::to_string(a + 1) + " is " + std::to_string(spacing[a]) +
                 "; expected a positive number");
        }
        end_of_value(value, fail, "4 spacings");
      }
      else if (field == "space directions") {
        const std::string_view first = value.token();
        if (first != "none")
          fail("the first direction is '" + printable(first) + "'; expected 'none' for the vector axis");
        for (int a = 0; a < 3; ++a) {
          const std::array<double, 3> d =
              vector(value, fail, "the direction of axis " + std::to_string(a + 1));
          for (int b = 0; b < 3; ++b)
            if ((b == a) != (d[b] != 0.) || d[a] < 0.)
              fail("the direction of axis " + std::to_string(a + 1) + " is (" + std::to_string(d[0]) + "," +
                   std::to_string(d[1]) + "," + std::to_string(d[2]) +
                   "): rotated, sheared, permuted or mirrored frames are not supported; expected the axes "
                   "(hx,0,0) (0,hy,0) (0,0,hz) with positive steps");
          spacing[a] = d[a];
        }
        end_of_value(value, fail, "4 directions");
      }
      else if (field == "space origin") {
        origin = vector(value, fail, "the space origin");
        end_of_value(value, fail, "one vector");
      }
      else if (field == "space dimension") {
        if (integer(value, fail, "the space dimension") != 3)
          fail("only 3-dimensional spaces are supported");
      }
      else if (field == "kinds") {
        const std::string first = Text_cursor::lower(value.token());
        if (first == "domain" || first == "space" || first == "time")
          fail("the first axis is a '" + first +
               "' axis; the vector axis must come first (kinds: vector domain domain domain)");
        for (int a = 0; a < 3; ++a) {
          const std::string k = Text_cursor::lower(value.token());
          if (k != "domain" && k != "space" && k != "???" && k != "none")
            fail("axis " + std::to_string(a + 1) + " is of kind '" + printable(k) +
                 "'; expected domain (the vector axis first, then x, y, z)");
        }
      }
      else if (field == "endian") {
        const std::string e = trim(rest);
        if (e == "little")
          order = Byte_order::LITTLE_ENDIAN_ORDER;
        else if (e == "big")
          order = Byte_order::BIG_ENDIAN_ORDER;
        else
          fail("unknown endian '" + printable(e) + "'; expected little or big");
      }
      else if (field == "encoding") {
        encoding = Text_cursor::lower(trim(rest));
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
      else if (field == "byte skip") {
        const std::string s = trim(rest);
        const auto r = std::from_chars(s.data(), s.data() + s.size(), byte_skip);
        if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || byte_skip < -1)
          fail("'" + printable(s) + "' is not a byte count (or -1)");
      }
      else if (field == "line skip") {
        line_skip = integer(value, fail, "the number of lines to skip");
      }
      else if (field == "data file" || field == "datafile") {
        data_file = trim(rest);
        if (data_file.rfind("LIST", 0) == 0 || data_file.find('%') != std::string::npos ||
            data_file.find(' ') != std::string::npos)
          fail("'" + printable(data_file) +
               "': data split over several files are not supported; expected one file name");
      }
      else if (field == "content") {
        content = trim(rest);
      }
      // Every other field (space, centers, labels, units, axis mins, ...) says nothing about
      // where the nodes are once the origin and the steps are known.
    }
    data_start = in.pos;
    data_line = in.line;
    if (!have_type)
      in.fail_file("the header has no 'type' field");
    if (!have_dimension || !have_sizes)
      in.fail_file("the header has no 'dimension: 4' and 'sizes: 3 nx ny nz' fields");
    for (int a = 0; a < 3; ++a)
      if (dimensions[a] < 2)
        in.fail_at(0, sizes_line,
                   "sizes 3 " + dimensions_string() +
                       ": a grid needs at least 2 nodes along each axis (empty, 1D and 2D grids are not "
                       "supported)");
    nodes = 1;
    for (int a = 0; a < 3; ++a) {
      if (nodes > (std::numeric_limits<std::size_t>::max)() / 64 / dimensions[a])
        in.fail_at(0, sizes_line, "sizes 3 " + dimensions_string() + " has too many nodes");
      nodes *= dimensions[a];
    }
    if (encoding != "ascii" && !order && binary_type_size(type) > 1)
      in.fail_file("the header has no 'endian' field (little or big), needed for " + encoding + " " +
                   type_name + " data");
    if (byte_skip == -1 && encoding != "raw")
      in.fail_file("'byte skip: -1' is only allowed with raw encoding");
  }

  std::size_t nodes = 0;

  std::string dimensions_string() const
  {
    return std::to_string(dimensions[0]) + " " + std::to_string(dimensions[1]) + " " +
           std::to_string(dimensions[2]);
  }

private:
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
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a NRRD file (`.nrrd`, or a `.nhdr` header
with its data in another file), the way to read raw float32 files.

The file starts with `NRRD0001` to `NRRD0005`; the header holds `type` (any numeric NRRD type:
`int8` … `uint64`, `float`, `double` and their synonyms), `dimension: 4` and
`sizes: 3 nx ny nz` (the vector axis first, then x fastest; at least 2 nodes along each axis;
`kinds`, if given, must be `vector` (or `3-vector`, ...) then `domain domain domain`),
`encoding` (`raw`, `ascii`/`text`, and `gzip` when zlib is available:
`CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB` defined and zlib linked; other compressed encodings get
an "unsupported" message),
`endian` (required for raw and gzip multi-byte types), `byte skip` (`-1` = the data are the end of the
file), `line skip`, `data file` (relative to the header's folder; one file only), and the
geometry: `spacings: nan hx hy hz` or `space directions: none (hx,0,0) (0,hy,0) (0,0,hz)`
(axis-aligned with positive steps only: a rotated, sheared, permuted or mirrored frame gets an
"unsupported" message; default spacing 1), and `space origin: (x,y,z)` (default 0).  Node
`(i, j, k)` is at `origin + (i·hx, j·hy, k·hz)`: NRRD's origin is the first sample whatever the
`centers`, so cell-centered samples are taken as the nodes of the grid.

A raw file of float32 values `vx vy vz` per node (x fastest), 64 × 32 × 16 nodes, little-endian,
is read through this header beside it (`field.nhdr`):
\code
NRRD0004
type: float
dimension: 4
sizes: 3 64 32 16
spacings: nan 0.1 0.1 0.2
space origin: (0,0,-1.5)
endian: little
encoding: raw
data file: field.raw
\endcode

A NRRD file holds one array and no mask: `mask_array_name` (non-empty) is an error;
`array_name`, if given, must match the `content` field when the file has one.

Bad input never crashes, hangs or allocates more than the file's size: a truncated file, sizes
that do not match the data, non-numeric tokens, unknown types, a NaN or infinite velocity make
the function return `false` with a message that names the file, the line and/or byte, and what
is wrong.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters among the ones listed below
\param error if not null, receives the reason of a failure

\cgalNamedParamsBegin
  \cgalParamNBegin{array_name}
    \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`), checked
      against the `content` field}
    \cgalParamType{`std::string`}
    \cgalParamDefault{the file's array}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{not supported: NRRD files have no mask; a non-empty name is an error}
    \cgalParamType{`std::string`}
    \cgalParamDefault{no mask}
  \cgalParamNEnd
  \cgalParamNBegin{use_parallelism}
    \cgalParamDescription{decode binary arrays on the threads of the caller's TBB arena
      (`FAS::parameters::use_parallelism()`); without it the reader starts no thread}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `read_VTK_flow_field()`, `read_AmiraMesh_flow_field()`, `Regular_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_NRRD_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                          const NamedParameters& np = CGAL::parameters::default_values(),
                          std::string* error = nullptr)
{
  const internal::Array_names names = internal::array_names(np);
  return internal::read_into("read_NRRD_flow_field", filename, field, error, internal::reads_in_parallel(np),
                             [&] { return internal::read_NRRD_grid<K>(filename, names.array, names.mask); });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief As the overload above with the default named parameters: the reason of a failure is in
`error` without naming `CGAL::parameters::default_values()` first, as in
`read_NRRD_flow_field(filename, field, &error)`.
*/
template <class K>
bool read_NRRD_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field, std::string* error)
{
  return read_NRRD_flow_field(filename, field, CGAL::parameters::default_values(), error);
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_NRRD_H
