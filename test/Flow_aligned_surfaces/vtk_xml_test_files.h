// VTK XML files written by the tests themselves, in every encoding VTK writes, so that the
// package's reader is checked against values known independently of any VTK: `ascii`, inline
// `binary` (base64) and `appended` (raw or base64) data, UInt32 or UInt64 headers, either byte
// order, uncompressed or compressed in blocks with zlib, LZ4 or LZMA, as laid out by VTK 9's
// vtkXMLWriter: uncompressed binary data are one stream [byte count][data]; compressed ones a
// header [number of blocks, block size, last block size, compressed sizes] and the blocks, the
// header base64-encoded apart from the blocks.

#ifndef FAS_TEST_VTK_XML_TEST_FILES_H
#define FAS_TEST_VTK_XML_TEST_FILES_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
#include <zlib.h>
#endif
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4)
#include <lz4.h>
#endif
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA)
#include <lzma.h>
#endif

namespace vtk_xml_test {

enum class Mode { ASCII, BINARY, APPENDED_RAW, APPENDED_BASE64 };
enum class Codec { NONE, ZLIB, LZ4, LZMA };

inline const char* mode_name(Mode m)
{
  const char* names[] = {"ascii", "binary", "appended raw", "appended base64"};
  return names[int(m)];
}

inline const char* codec_name(Codec c)
{
  const char* names[] = {"none", "vtkZLibDataCompressor", "vtkLZ4DataCompressor", "vtkLZMADataCompressor"};
  return names[int(c)];
}

inline bool codec_available([[maybe_unused]] Codec c)
{
#if !defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
  if (c == Codec::ZLIB)
    return false;
#endif
#if !defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4)
  if (c == Codec::LZ4)
    return false;
#endif
#if !defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA)
  if (c == Codec::LZMA)
    return false;
#endif
  return true;
}

/// How the binary data of a file are written.
struct Encoding {
  Mode mode = Mode::APPENDED_RAW;
  bool wide_header = false; ///< UInt64 header words
  bool big_endian = false;
  Codec codec = Codec::NONE;
  std::size_t block_size = 64; ///< small, so that arrays span several blocks and a partial last one

  std::string describe() const
  {
    return std::string(mode_name(mode)) + (wide_header ? ", UInt64" : ", UInt32") +
           (big_endian ? ", BigEndian" : ", LittleEndian") + ", compressor " + codec_name(codec);
  }
};

/// An array of values of one VTK type.
struct Array {
  std::string name, type; ///< VTK type name: Int8 ... UInt64, Float32, Float64
  int components = 1;
  std::vector<double> values;
};

inline std::size_t type_size(const std::string& t)
{
  if (t == "Int8" || t == "UInt8")
    return 1;
  if (t == "Int16" || t == "UInt16")
    return 2;
  if (t == "Int32" || t == "UInt32" || t == "Float32")
    return 4;
  return 8;
}

/// `v` as `type`, in the given byte order.
inline std::string encode_value(const std::string& type, double v, bool big_endian)
{
  unsigned char b[8];
  const std::size_t n = type_size(type);
  if (type == "Float32") {
    const float f = static_cast<float>(v);
    std::memcpy(b, &f, 4);
  }
  else if (type == "Float64") {
    std::memcpy(b, &v, 8);
  }
  else {
    const std::uint64_t u = type[0] == 'U' ? static_cast<std::uint64_t>(v)
                                           : static_cast<std::uint64_t>(static_cast<std::int64_t>(v));
    for (std::size_t i = 0; i < 8; ++i)
      b[i] = static_cast<unsigned char>(u >> (8 * i)); // little endian
  }
  std::string r(reinterpret_cast<const char*>(b), n);
  if (big_endian) // the host of the tests is little endian (x86-64, arm64)
    r.assign(r.rbegin(), r.rend());
  return r;
}

inline std::string encode_word(std::uint64_t w, const Encoding& e)
{
  return encode_value(e.wide_header ? "UInt64" : "UInt32", double(w), e.big_endian);
}

inline std::string base64(const std::string& bytes)
{
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string r;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size())
      v |= unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size())
      v |= unsigned(static_cast<unsigned char>(bytes[i + 2]));
    const std::size_t left = bytes.size() - i;
    r += alphabet[(v >> 18) & 63u];
    r += alphabet[(v >> 12) & 63u];
    r += left > 1 ? alphabet[(v >> 6) & 63u] : '=';
    r += left > 2 ? alphabet[v & 63u] : '=';
  }
  return r;
}

inline std::string compress(Codec c, const std::string& in)
{
  std::string out;
  switch (c) {
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB)
  case Codec::ZLIB: {
    uLongf n = compressBound(uLong(in.size()));
    out.resize(n);
    if (compress2(reinterpret_cast<Bytef*>(&out[0]), &n, reinterpret_cast<const Bytef*>(in.data()), uLong(in.size()),
                  5) != Z_OK)
      throw std::runtime_error("zlib compress2 failed");
    out.resize(n);
    return out;
  }
#endif
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZ4)
  case Codec::LZ4: {
    out.resize(std::size_t(LZ4_compressBound(int(in.size()))));
    const int n = LZ4_compress_default(in.data(), &out[0], int(in.size()), int(out.size()));
    if (n <= 0)
      throw std::runtime_error("LZ4_compress_default failed");
    out.resize(std::size_t(n));
    return out;
  }
#endif
#if defined(CGAL_FLOW_ALIGNED_SURFACES_USE_LZMA)
  case Codec::LZMA: {
    out.resize(lzma_stream_buffer_bound(in.size()));
    std::size_t n = 0;
    // Preset 0 (a 256 KiB dictionary): the reader decodes any preset, and each block is
    // compressed on its own, which at VTK's preset 5 allocates about 94 MB per block (minutes
    // for this file's tests under AddressSanitizer).
    if (lzma_easy_buffer_encode(0, LZMA_CHECK_CRC32, nullptr, reinterpret_cast<const std::uint8_t*>(in.data()),
                                in.size(), reinterpret_cast<std::uint8_t*>(&out[0]), &n, out.size()) != LZMA_OK)
      throw std::runtime_error("lzma_easy_buffer_encode failed");
    out.resize(n);
    return out;
  }
#endif
  default:
    throw std::runtime_error(std::string("no compressor ") + codec_name(c) + " in this build");
  }
}

/// The binary block of an array as VTK writes it: (header, data), to be base64-encoded apart
/// when compressed, together when not.
inline std::pair<std::string, std::string> binary_block(const Array& a, const Encoding& e)
{
  std::string data;
  for (double v : a.values)
    data += encode_value(a.type, v, e.big_endian);
  if (e.codec == Codec::NONE)
    return {encode_word(data.size(), e), data};
  const std::size_t blocks = (data.size() + e.block_size - 1) / e.block_size;
  const std::size_t last = data.size() % e.block_size;
  std::string header = encode_word(blocks, e) + encode_word(e.block_size, e) + encode_word(last, e);
  std::string compressed;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::string c = compress(e.codec, data.substr(b * e.block_size, e.block_size));
    header += encode_word(c.size(), e);
    compressed += c;
  }
  return {header, compressed};
}

inline std::string encoded_block(const Array& a, const Encoding& e)
{
  const std::pair<std::string, std::string> b = binary_block(a, e);
  if (e.mode == Mode::APPENDED_RAW)
    return b.first + b.second;
  return e.codec == Codec::NONE ? base64(b.first + b.second) : base64(b.first) + base64(b.second);
}

inline std::string number_text(double v)
{
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

/// Writes the XML of a whole file: `elements(array)` gives the DataArray elements in order,
/// the appended data are collected.
class Writer {
public:
  explicit Writer(Encoding e) : m_encoding(e) {}

  std::string data_array(const Array& a, const std::string& extra = "")
  {
    std::string r = "<DataArray type=\"" + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
                    std::to_string(a.components) + "\"" + extra;
    switch (m_encoding.mode) {
    case Mode::ASCII: {
      r += " format=\"ascii\">\n";
      for (std::size_t i = 0; i < a.values.size(); ++i)
        r += number_text(a.values[i]) + ((i + 1) % 6 == 0 ? "\n" : " ");
      return r + "\n</DataArray>\n";
    }
    case Mode::BINARY:
      return r + " format=\"binary\">\n" + encoded_block(a, m_encoding) + "\n</DataArray>\n";
    default:
      r += " format=\"appended\" offset=\"" + std::to_string(m_appended.size()) + "\"/>\n";
      m_appended += encoded_block(a, m_encoding);
      return r;
    }
  }

  /// The file: the VTKFile element around `body`, with the appended data if any.
  std::string file(const std::string& type, const std::string& body) const
  {
    std::string r = "<?xml version=\"1.0\"?>\n<!-- written by the package's tests -->\n<VTKFile type=\"" + type +
                    "\" version=\"1.0\" byte_order=\"" + (m_encoding.big_endian ? "BigEndian" : "LittleEndian") +
                    "\" header_type=\"" + (m_encoding.wide_header ? "UInt64" : "UInt32") + "\"";
    if (m_encoding.codec != Codec::NONE)
      r += std::string(" compressor=\"") + codec_name(m_encoding.codec) + "\"";
    r += ">\n" + body;
    if (m_encoding.mode == Mode::APPENDED_RAW || m_encoding.mode == Mode::APPENDED_BASE64)
      r += std::string("  <AppendedData encoding=\"") + (m_encoding.mode == Mode::APPENDED_RAW ? "raw" : "base64") +
           "\">\n   _" + m_appended + "\n  </AppendedData>\n";
    return r + "</VTKFile>\n";
  }

private:
  Encoding m_encoding;
  std::string m_appended;
};

} // namespace vtk_xml_test

#endif // FAS_TEST_VTK_XML_TEST_FILES_H
