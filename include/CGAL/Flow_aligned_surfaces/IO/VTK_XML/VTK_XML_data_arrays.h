// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of a VTK XML `<DataArray>` in every encoding VTK writes, without VTK: `ascii`
// (numbers in the element's text), `binary` (base64 text in the element) and `appended` (at an
// offset in the `<AppendedData>` element, raw or base64).  Binary data are a byte stream
// [header][data]: uncompressed, the header is one word giving the byte count; compressed
// (vtkZLibDataCompressor, vtkLZ4DataCompressor, vtkLZMADataCompressor) it is [number of blocks,
// block size, size of the last block (0: a full block), compressed size of each block] and the
// compressed blocks follow.  Words are UInt32 or UInt64 (`header_type`), in the file's
// `byte_order`.  Every size is checked against the bytes that are there before anything is
// allocated from it.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_DATA_ARRAYS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_DATA_ARRAYS_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/XML_document.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/base64_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/inflate_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/lz4_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/lzma_bytes.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/uniform_grid_reading.h>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

enum class VTK_XML_compressor { NONE, ZLIB, LZ4, LZMA };

/// How the binary data of a file are laid out: the attributes of its `<VTKFile>` element.
struct VTK_XML_format {
  std::size_t word = 4; ///< bytes per header word (UInt32 or UInt64)
  Byte_order order = Byte_order::LITTLE_ENDIAN_ORDER;
  VTK_XML_compressor compressor = VTK_XML_compressor::NONE;
};

inline VTK_XML_format read_VTK_XML_format(const XML_document& doc)
{
  const XML_element& root = doc.root();
  VTK_XML_format f;
  if (const std::string* h = root.attribute("header_type")) {
    if (*h != "UInt32" && *h != "UInt64")
      doc.fail_element(root, "header_type=\"" + printable(*h) + "\"; expected UInt32 or UInt64");
    f.word = *h == "UInt64" ? 8 : 4;
  }
  if (const std::string* o = root.attribute("byte_order")) {
    if (*o != "LittleEndian" && *o != "BigEndian")
      doc.fail_element(root, "byte_order=\"" + printable(*o) + "\"; expected LittleEndian or BigEndian");
    f.order = *o == "BigEndian" ? Byte_order::BIG_ENDIAN_ORDER : Byte_order::LITTLE_ENDIAN_ORDER;
  }
  if (const std::string* c = root.attribute("compressor")) {
    if (*c == "vtkZLibDataCompressor")
      f.compressor = VTK_XML_compressor::ZLIB;
    else if (*c == "vtkLZ4DataCompressor")
      f.compressor = VTK_XML_compressor::LZ4;
    else if (*c == "vtkLZMADataCompressor")
      f.compressor = VTK_XML_compressor::LZMA;
    else if (!c->empty())
      doc.fail_element(root, "compressor=\"" + printable(*c) +
                                 "\"; expected vtkZLibDataCompressor, vtkLZ4DataCompressor or vtkLZMADataCompressor");
  }
  return f;
}

/// The numeric type named by a DataArray's `type` attribute, false if it names none.
inline bool VTK_XML_binary_type(const std::string& name, Binary_type& type)
{
  static const std::pair<const char*, Binary_type> types[] = {
      {"Float32", Binary_type::FLOAT32}, {"Float64", Binary_type::FLOAT64}, {"Int8", Binary_type::INT8},
      {"UInt8", Binary_type::UINT8},     {"Int16", Binary_type::INT16},     {"UInt16", Binary_type::UINT16},
      {"Int32", Binary_type::INT32},     {"UInt32", Binary_type::UINT32},   {"Int64", Binary_type::INT64},
      {"UInt64", Binary_type::UINT64}};
  for (const auto& t : types)
    if (name == t.first) {
      type = t.second;
      return true;
    }
  return false;
}

/// A non-negative integer attribute of `e` (`fallback` if absent).
inline std::size_t VTK_XML_count(const XML_document& doc, const XML_element& e, const char* attribute,
                                 std::size_t fallback)
{
  const std::string* s = e.attribute(attribute);
  if (s == nullptr)
    return fallback;
  std::size_t v = 0;
  const char* end = s->data() + s->size();
  const auto r = std::from_chars(s->data(), end, v);
  if (r.ec != std::errc() || r.ptr != end)
    doc.fail_element(e, std::string(attribute) + "=\"" + printable(*s) + "\" is not a non-negative integer");
  return v;
}

/// A DataArray element and what its attributes say.
struct VTK_XML_array {
  const XML_element* element = nullptr;
  std::string name;
  std::string type_name;
  bool numeric = false;
  Binary_type type = Binary_type::FLOAT32;
  std::size_t components = 1;
};

inline VTK_XML_array read_VTK_XML_array(const XML_document& doc, const XML_element& e)
{
  VTK_XML_array a;
  a.element = &e;
  if (const std::string* n = e.attribute("Name"))
    a.name = *n;
  const std::string* t = e.attribute("type");
  if (t == nullptr)
    doc.fail_element(e, "the DataArray '" + printable(a.name) + "' has no type attribute");
  a.type_name = *t;
  a.numeric = VTK_XML_binary_type(*t, a.type);
  a.components = VTK_XML_count(doc, e, "NumberOfComponents", 1);
  if (a.components == 0)
    doc.fail_element(e, "the DataArray '" + printable(a.name) + "' has NumberOfComponents=\"0\"");
  return a;
}

/// The values of one array: a view of the file or of decompressed bytes that it owns.
struct VTK_XML_values {
  Grid_array array;
  std::unique_ptr<std::string> storage;
};

/// Decodes the DataArrays of one file; holds the sorted offsets of its appended arrays (an
/// array's appended data end where the next one begins).
class VTK_XML_array_decoder {
public:
  explicit VTK_XML_array_decoder(const XML_document& doc) : m_doc(doc), m_format(read_VTK_XML_format(doc))
  {
    for (const XML_element& e : doc.elements) {
      const std::string* format = e.attribute("format");
      if (e.name == "DataArray" && format != nullptr && *format == "appended")
        m_offsets.push_back(VTK_XML_count(doc, e, "offset", 0));
    }
    std::sort(m_offsets.begin(), m_offsets.end());
  }

  /// The `tuples` tuples of `a`, checked to be there.
  VTK_XML_values values(const VTK_XML_array& a, std::size_t tuples) const
  {
    const XML_element& e = *a.element;
    if (!a.numeric)
      fail(a, "has type \"" + printable(a.type_name) + "\", not a number type (Int8 ... UInt64, Float32, Float64)");
    const std::size_t count = tuples * a.components;
    if (a.components != 0 && count / a.components != tuples)
      fail(a, "has more values than memory can hold");
    const std::string* format = e.attribute("format");
    const std::string f = format ? *format : std::string("ascii");
    VTK_XML_values r;
    r.array.name = a.name;
    r.array.type = a.type;
    r.array.components = a.components;
    r.array.tuples = tuples;
    r.array.order = m_format.order;
    if (f == "ascii")
      return ascii_values(a, count, std::move(r));
    if (f != "binary" && f != "appended")
      fail(a, "has format=\"" + printable(f) + "\"; expected ascii, binary or appended");
    std::string_view stream;
    std::size_t data_byte = 0;
    if (f == "binary") {
      data_byte = e.text_end != 0 ? e.text_begin : e.byte; // an empty element: named by its tag
      r.storage = std::make_unique<std::string>();
      decoded_base64(a, m_doc.bytes().substr(e.text_begin, e.text_end - e.text_begin), e.text_begin, *r.storage);
      stream = *r.storage;
    }
    else {
      stream = appended_stream(a, data_byte, r.storage);
    }
    const std::size_t needed = count * binary_type_size(a.type);
    if (needed / binary_type_size(a.type) != count)
      fail(a, "has more values than memory can hold");
    std::unique_ptr<std::string> decompressed;
    const std::string_view data = m_format.compressor == VTK_XML_compressor::NONE
                                      ? uncompressed_data(a, stream, data_byte, needed)
                                      : compressed_data(a, stream, data_byte, needed, decompressed);
    if (decompressed)
      r.storage = std::move(decompressed);
    r.array.bytes = data;
    r.array.begin = 0;
    r.array.file_offset = data_byte;
    return r;
  }

  const VTK_XML_format& format() const { return m_format; }

  [[noreturn]] void fail(const VTK_XML_array& a, const std::string& what) const
  {
    m_doc.fail_at(a.element->byte, "the DataArray '" + printable(a.name) + "' " + what);
  }

private:
  VTK_XML_values ascii_values(const VTK_XML_array& a, std::size_t count, VTK_XML_values r) const
  {
    const XML_element& e = *a.element;
    // Each number takes a character and a separator: a count the text cannot hold is refused
    // before the caller allocates for it.
    const std::size_t length = e.text_end - e.text_begin;
    if (count > (length + 1) / 2)
      fail(a, "needs " + std::to_string(count) + " numbers but its text holds " + std::to_string(length) +
                  " bytes (truncated file or wrong sizes)");
    r.array.ascii = true;
    r.array.bytes = m_doc.bytes().substr(0, e.text_end);
    r.array.begin = e.text_begin;
    r.array.line = m_doc.line_of(e.text_begin);
    return r;
  }

  void decoded_base64(const VTK_XML_array& a, std::string_view text, std::size_t at, std::string& out) const
  {
    const std::ptrdiff_t bad = decode_base64(text, out);
    if (bad >= 0)
      m_doc.fail_at(at + static_cast<std::size_t>(bad),
                    "the base64 data of the DataArray '" + printable(a.name) + "' hold '" +
                        printable(text.substr(static_cast<std::size_t>(bad), 1)) + "', which is not base64 here");
  }

  // The raw or decoded appended bytes of `a`, from its offset to the next array's.
  std::string_view appended_stream(const VTK_XML_array& a, std::size_t& data_byte,
                                   std::unique_ptr<std::string>& storage) const
  {
    if (!m_doc.has_appended)
      fail(a, "has format=\"appended\" but the file has no <AppendedData> element");
    const std::size_t offset = VTK_XML_count(m_doc, *a.element, "offset", std::size_t(-1));
    const std::size_t size = m_doc.appended_end - m_doc.appended_begin;
    if (offset == std::size_t(-1))
      fail(a, "has format=\"appended\" but no offset attribute");
    if (offset >= size)
      fail(a, "has offset " + std::to_string(offset) + ", outside the " + std::to_string(size) +
                  " bytes of the appended data (truncated or corrupt file)");
    const auto next = std::upper_bound(m_offsets.begin(), m_offsets.end(), offset);
    const std::size_t end = next == m_offsets.end() ? size : std::min(*next, size);
    data_byte = m_doc.appended_begin + offset;
    const std::string_view bytes = m_doc.bytes().substr(data_byte, end - offset);
    const XML_element* appended = m_doc.child(m_doc.root(), "AppendedData");
    const std::string* encoding = appended ? appended->attribute("encoding") : nullptr;
    if (encoding != nullptr && *encoding == "raw")
      return bytes;
    if (encoding != nullptr && *encoding != "base64")
      m_doc.fail_element(*appended, "encoding=\"" + printable(*encoding) + "\"; expected raw or base64");
    storage = std::make_unique<std::string>();
    // The last array's text ends with the white space before </AppendedData>, which is skipped.
    decoded_base64(a, bytes, data_byte, *storage);
    return *storage;
  }

  // Header word i of `stream`, assembled as an integer (a double would round 2^64 - 1 up to
  // 2^64, which no integer holds); a word beyond size_t saturates.
  std::size_t word(std::string_view stream, std::size_t i) const
  {
    const unsigned char* p = reinterpret_cast<const unsigned char*>(stream.data()) + i * m_format.word;
    std::uint64_t u = 0;
    for (std::size_t b = 0; b < m_format.word; ++b)
      u = (u << 8) | p[m_format.order == Byte_order::BIG_ENDIAN_ORDER ? b : m_format.word - 1 - b];
    return u > std::uint64_t((std::numeric_limits<std::size_t>::max)()) ? (std::numeric_limits<std::size_t>::max)()
                                                                       : static_cast<std::size_t>(u);
  }

  std::string_view uncompressed_data(const VTK_XML_array& a, std::string_view stream, std::size_t at,
                                     std::size_t needed) const
  {
    const std::size_t w = m_format.word;
    if (stream.size() < w)
      m_doc.fail_at(at, "the data of the DataArray '" + printable(a.name) + "' end inside their " +
                            std::to_string(w) + "-byte header (truncated file?)");
    const std::size_t n = word(stream, 0);
    std::string what;
    if (n > stream.size() - w)
      what = "announce " + std::to_string(n) + " bytes but only " + std::to_string(stream.size() - w) +
             " follow (truncated file or lying header)";
    else if (n < needed)
      what = "hold " + std::to_string(n) + " bytes but the array needs " + std::to_string(needed) +
             " (wrong sizes or truncated data)";
    if (!what.empty())
      m_doc.fail_at(at, "the data of the DataArray '" + printable(a.name) + "' " + what);
    return stream.substr(w, needed);
  }

  std::string decompress(std::string_view in, std::size_t expected, std::string& out) const
  {
    switch (m_format.compressor) {
    case VTK_XML_compressor::ZLIB:
      return have_inflate() ? inflate_bytes(in, expected, out)
                            : "this build has no zlib decompression (build with zlib: Debian zlib1g-dev)";
    case VTK_XML_compressor::LZ4:
      return lz4_bytes(in, expected, out);
    default:
      return lzma_bytes(in, expected, out);
    }
  }

  // The first `needed` bytes of the compressed blocks of `stream`, decompressed into `out`.
  std::string_view compressed_data(const VTK_XML_array& a, std::string_view stream, std::size_t at,
                                   std::size_t needed, std::unique_ptr<std::string>& out) const
  {
    const std::size_t w = m_format.word;
    const std::string array = "the compressed DataArray '" + printable(a.name) + "' ";
    if (stream.size() < 3 * w)
      m_doc.fail_at(at, array + "has no complete compression header (truncated or corrupt file)");
    const std::size_t blocks = word(stream, 0), block_size = word(stream, 1), last_size = word(stream, 2);
    const std::size_t left = stream.size() - 3 * w;
    auto refuse = [&](const std::string& what) { m_doc.fail_at(at, array + what + " (corrupt or lying header)"); };
    if (blocks > left / w)
      refuse("announces " + std::to_string(blocks) + " blocks, whose sizes alone need more than the " +
             std::to_string(left) + " bytes that follow");
    if (blocks != 0 && block_size == 0)
      refuse("announces " + std::to_string(blocks) + " blocks of 0 bytes");
    if (last_size > block_size)
      refuse("announces a last block of " + std::to_string(last_size) + " bytes, more than the block size " +
             std::to_string(block_size));
    const double total = blocks == 0 ? 0. : double(block_size) * double(blocks - 1) + double(last_size ? last_size : block_size);
    if (total < double(needed))
      refuse("holds " + number_string(total) + " bytes in " + std::to_string(blocks) + " blocks but the array needs " +
             std::to_string(needed));
    std::vector<std::size_t> starts(blocks + 1, 3 * w + blocks * w);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t size = word(stream, 3 + b);
      if (size > stream.size() - starts[b])
        refuse("announces compressed blocks of more bytes than the " + std::to_string(stream.size() - starts[0]) +
               " that follow");
      starts[b + 1] = starts[b] + size;
    }
    out = std::make_unique<std::string>();
    std::string block;
    for (std::size_t b = 0; out->size() < needed; ++b) {
      const std::size_t expected = b + 1 == blocks && last_size != 0 ? last_size : block_size;
      const std::string why = decompress(stream.substr(starts[b], starts[b + 1] - starts[b]), expected, block);
      if (!why.empty())
        m_doc.fail_at(at, array + "block " + std::to_string(b) + " of " + std::to_string(blocks) + ": " + why);
      if (out->empty())
        out->reserve(std::min(needed, blocks * block.size()));
      out->append(block, 0, std::min(block.size(), needed - out->size()));
    }
    return *out;
  }

  const XML_document& m_doc;
  VTK_XML_format m_format;
  std::vector<std::size_t> m_offsets;
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_DATA_ARRAYS_H
