// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK's XML readers (VTK 9.x) run safely: the file's structure, the counts its header announces
// and the headers of its compressed arrays checked against the file's size before VTK reads
// (VTK trusts them, and fuzzing found lies that make it allocate gigabytes or write outside
// its arrays), and VTK's error messages captured by observers on the reader, its XML parser
// and its pipeline, never printed, and thrown as `Read_error`.
//
// Needs VTK: link the target CGAL::Flow_aligned_surfaces_VTK.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_READER_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_READER_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>

#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

typedef Flow_aligned_surfaces::IO::internal::Read_error VTK_XML_error;

// Collects the errors that VTK objects report, which VTK would otherwise print (to its log and
// output window): every object it watches reports to it instead, warnings are dropped.
class VTK_error_observer : public vtkCommand {
public:
  static VTK_error_observer* New() { return new VTK_error_observer; }

  void watch(vtkObject* object)
  {
    if (object == nullptr)
      return;
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }

  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ErrorEvent)
      m_errors.push_back(cleaned(static_cast<const char*>(data)));
  }

  bool has_errors() const { return !m_errors.empty(); }

  // VTK's errors, without the pipeline's restatement of them ("Algorithm ... returned failure
  // for request: <a dump of the request>") unless it is all there is.
  std::string errors() const
  {
    std::string r;
    for (const std::string& e : m_errors) {
      if (e.find("returned failure for request") != std::string::npos && m_errors.size() > 1)
        continue;
      if (r.find(e) != std::string::npos)
        continue;
      r += (r.empty() ? "" : "; ") + e;
      if (r.size() > 1000) {
        r += "; ...";
        break;
      }
    }
    return r;
  }

private:
  // "ERROR: In /path/vtkXMLReader.cxx, line 521\nvtkXMLImageDataReader (0x55d0): words\n\n"
  // becomes "vtkXMLImageDataReader: words".
  static std::string cleaned(const char* text)
  {
    std::string s = text ? text : "";
    if (s.rfind("ERROR: In ", 0) == 0) {
      const std::size_t eol = s.find('\n');
      s = eol == std::string::npos ? std::string() : s.substr(eol + 1);
    }
    const std::size_t open = s.find(" (0x");
    const std::size_t close = s.find("): ");
    if (open != std::string::npos && close != std::string::npos && open < close &&
        s.find_first_of(" \n") == open)
      s = s.substr(0, open) + ": " + s.substr(close + 3);
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r'))
      s.pop_back();
    for (char& c : s)
      if (c == '\n')
        c = ' ';
    return s;
  }

  std::vector<std::string> m_errors;
};

// An observer watching a VTK XML reader, its XML parser and its pipeline.
template <class Reader>
vtkSmartPointer<VTK_error_observer> watch_VTK_reader(Reader* reader)
{
  vtkSmartPointer<VTK_error_observer> observer = vtkSmartPointer<VTK_error_observer>::New();
  observer->watch(reader);
  observer->watch(reader->GetExecutive());
  reader->SetReaderErrorObserver(observer);
  reader->SetParserErrorObserver(observer);
  return observer;
}

// The reader's name and the file, at the head of every message.
struct VTK_XML_context {
  std::string reader, file;
  [[noreturn]] void fail(const std::string& what) const
  {
    throw VTK_XML_error(reader + ": " + file + ": " + what);
  }
};

// Opening the file ourselves first gives a plain message for a missing or unreadable file
// rather than VTK's.
inline void check_readable(const VTK_XML_context& c)
{
  std::error_code ec;
  if (std::filesystem::is_directory(c.file, ec))
    c.fail("is a directory, not a file");
  std::ifstream is(c.file, std::ios::binary);
  if (!is)
    c.fail(std::filesystem::exists(c.file, ec) ? "cannot open the file for reading (permissions?)"
                                               : "no such file");
  if (is.peek() == std::ifstream::traits_type::eof())
    c.fail("the file is empty (0 bytes)");
}

template <class Reader>
bool VTK_can_read(const std::string& filename)
{
  vtkSmartPointer<Reader> reader = vtkSmartPointer<Reader>::New();
  const vtkSmartPointer<VTK_error_observer> observer = watch_VTK_reader(reader.Get());
  return reader->CanReadFile(filename.c_str()) != 0;
}

// What the file is, for the message when it is not what the caller wants.
inline std::string VTK_XML_kind(const std::string& filename)
{
  if (VTK_can_read<vtkXMLImageDataReader>(filename))
    return "a VTK XML ImageData file (.vti)";
  if (VTK_can_read<vtkXMLUnstructuredGridReader>(filename))
    return "a VTK XML UnstructuredGrid file (.vtu)";
  if (VTK_can_read<vtkXMLStructuredGridReader>(filename))
    return "a VTK XML StructuredGrid file (.vts)";
  return "not a VTK XML ImageData, UnstructuredGrid or StructuredGrid file";
}

// The numbers of points and cells that the header of the file announces, after
// UpdateInformation().
inline std::array<double, 2> announced_size(vtkXMLUnstructuredDataReader* reader)
{
  reader->SetupUpdateExtent(0, 1, 0);
  return {{double(reader->GetNumberOfPoints()), double(reader->GetNumberOfCells())}};
}

inline std::array<double, 2> announced_size(vtkXMLStructuredDataReader* reader)
{
  int e[6] = {0, -1, 0, -1, 0, -1};
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
  double points = 1., cells = 1.;
  for (int a = 0; a < 3; ++a) {
    points *= std::max(0., double(e[2 * a + 1]) - double(e[2 * a]) + 1.);
    cells *= std::max(0., double(e[2 * a + 1]) - double(e[2 * a]));
  }
  return {{points, cells}};
}

// VTK allocates its arrays from the header's counts before it reads the data.  Each point needs
// at least a velocity (12 bytes as floats) and each cell 4 point indices (16 bytes); compressed
// they can shrink by zlib's 1032:1 at most, so a header announcing more than 2000 times the
// file's size is a lie, refused before VTK allocates.
template <class Reader>
void check_announced_size(const VTK_XML_context& c, Reader* reader)
{
  std::error_code ec;
  const double bytes = static_cast<double>(std::filesystem::file_size(c.file, ec));
  const std::array<double, 2> n = announced_size(reader);
  const double needed = 12. * n[0] + 16. * n[1];
  if (!ec && needed > 2000. * bytes + 1e6) {
    std::ostringstream msg;
    msg << "the header announces " << n[0] << " points and " << n[1] << " cells, which need at least "
        << needed << " bytes, far more than the " << bytes
        << " bytes of the file can hold even compressed (truncated file "
        << "or wrong header?)";
    c.fail(msg.str());
  }
}

// VTK's readers trust the structure that the header describes.  Two lies make VTK 9.1 write
// outside its arrays (found by fuzzing: a piece extent reaching outside the whole extent,
// together with a points array of 8 components, crashes vtkXMLStructuredDataReader::
// ReadSubExtent), so the header's elements are checked before VTK reads any data: every piece
// of a structured data set (ImageData, StructuredGrid) lies inside its whole extent, and every
// points array holds 3 components.  And VTK loops over the components of every array (for
// their names): a NumberOfComponents of 10^100 (read as 2^31 - 1) takes minutes, so an array
// needs a positive number of components that the file can hold (as check_announced_size()).
inline void check_VTK_XML_structure(const VTK_XML_context& c, vtkXMLDataParser* parser)
{
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  if (root == nullptr)
    return;
  auto where = [](vtkXMLDataElement* e) {
    return "byte " + std::to_string(e->GetXMLByteIndex()) + ": <" + (e->GetName() ? e->GetName() : "") + "> ";
  };
  std::error_code ec;
  const double bytes = static_cast<double>(std::filesystem::file_size(c.file, ec));
  std::vector<vtkXMLDataElement*> todo{root};
  while (!todo.empty() && !ec) {
    vtkXMLDataElement* e = todo.back();
    todo.pop_back();
    for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
      todo.push_back(e->GetNestedElement(i));
    const char* components = e->GetAttribute("NumberOfComponents");
    if (components == nullptr)
      continue;
    char* end = nullptr;
    const double n = std::strtod(components, &end);
    if (end == components || !(n >= 1.) || n != std::floor(n) || n > 2000. * bytes + 1e6)
      c.fail(where(e) + "NumberOfComponents=\"" + Flow_aligned_surfaces::IO::internal::printable(components) +
             "\" is not a positive integer that the file can hold");
  }
  auto extent_text = [](const int* e) {
    std::string r;
    for (int i = 0; i < 6; ++i)
      r += (i ? " " : "") + std::to_string(e[i]);
    return r;
  };
  for (int d = 0; d < root->GetNumberOfNestedElements(); ++d) {
    vtkXMLDataElement* data = root->GetNestedElement(d);
    int whole[6];
    const bool structured = data->GetVectorAttribute("WholeExtent", 6, whole) == 6;
    for (int p = 0; p < data->GetNumberOfNestedElements(); ++p) {
      vtkXMLDataElement* piece = data->GetNestedElement(p);
      if (std::string(piece->GetName() ? piece->GetName() : "") != "Piece")
        continue;
      int extent[6];
      if (structured && piece->GetVectorAttribute("Extent", 6, extent) == 6)
        for (int a = 0; a < 3; ++a)
          if (extent[2 * a] < whole[2 * a] || extent[2 * a + 1] > whole[2 * a + 1])
            c.fail(where(piece) + "the piece's Extent \"" + extent_text(extent) +
                   "\" reaches outside the WholeExtent \"" + extent_text(whole) + "\" of the data set");
      vtkXMLDataElement* points = piece->FindNestedElementWithName("Points");
      for (int i = 0; points != nullptr && i < points->GetNumberOfNestedElements(); ++i) {
        vtkXMLDataElement* array = points->GetNestedElement(i);
        int components = 1;
        array->GetScalarAttribute("NumberOfComponents", components);
        if (components != 3)
          c.fail(where(array) + "the points array has " + std::to_string(components) +
                 " components; points need 3 coordinates");
      }
    }
  }
}

// `n` bytes of an array's data at byte `position` of the file, raw or decoded from base64
// (whitespace skipped if `skip_whitespace`: VTK skips it in inline data, not in appended data,
// which it decodes 4 characters at a time); fewer if the file ends or the encoding stops first
// (at padding or any other character).
inline std::string read_VTK_XML_bytes(std::istream& in, long long position, bool base64, std::size_t n,
                                      bool skip_whitespace)
{
  std::string r;
  in.clear();
  in.seekg(position);
  if (!base64) {
    r.resize(n);
    in.read(&r[0], static_cast<std::streamsize>(n));
    r.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
    return r;
  }
  unsigned bits = 0;
  int count = 0;
  for (char ch; r.size() < n && in.get(ch);) {
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* digit = ch != '\0' ? std::strchr(alphabet, ch) : nullptr;
    if (skip_whitespace && (ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t'))
      continue;
    if (digit == nullptr)
      break;
    bits = (bits << 6) | static_cast<unsigned>(digit - alphabet);
    count += 6;
    if (count >= 8) {
      count -= 8;
      r += static_cast<char>((bits >> count) & 0xffu);
    }
  }
  return r;
}

// Where VTK looks for the inline data of the element whose start tag begins at byte `start`:
// after the tag's closing '>' (even for an empty element `<.../>`), or nothing if the tag does
// not end.
inline std::optional<long long> VTK_XML_inline_data_position(std::istream& in, long long start)
{
  in.clear();
  in.seekg(start);
  for (char ch; in.get(ch);)
    if (ch == '>')
      return static_cast<long long>(in.tellg());
  return std::nullopt;
}

// The header of a compressed array (number of blocks, block size, last block size, compressed
// size of each block) is trusted by VTK 9.1, which allocates from it (found by fuzzing: a
// 13-point file announcing 2 GB blocks, or 10^9 blocks).  Checked here against the file's size
// for the appended arrays (raw or base64) and the inline binary ones (base64, after the end of
// the DataArray's start tag) of a compressed file; VTK reads every format but `ascii` and
// `appended` as inline binary.
inline void check_VTK_XML_compression_headers(const VTK_XML_context& c, vtkXMLDataParser* parser)
{
  using Flow_aligned_surfaces::IO::internal::Binary_type;
  using Flow_aligned_surfaces::IO::internal::Byte_order;
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  if (root == nullptr || root->GetAttribute("compressor") == nullptr)
    return;
  std::error_code ec;
  const double file_bytes = static_cast<double>(std::filesystem::file_size(c.file, ec));
  std::ifstream in(c.file, std::ios::binary);
  if (ec || !in)
    return; // VTK reports it
  const char* header_type = root->GetAttribute("header_type");
  const bool wide = header_type != nullptr && std::string(header_type) == "UInt64";
  const std::size_t word = wide ? 8 : 4;
  const char* byte_order = root->GetAttribute("byte_order");
  const Byte_order order = byte_order != nullptr && std::string(byte_order) == "BigEndian"
                               ? Byte_order::BIG_ENDIAN_ORDER
                               : Byte_order::LITTLE_ENDIAN_ORDER;
  auto number = [&](const std::string& bytes, std::size_t i) {
    return Flow_aligned_surfaces::IO::internal::decode_binary_number(
        wide ? Binary_type::UINT64 : Binary_type::UINT32, order,
        reinterpret_cast<const unsigned char*>(bytes.data()) + i * word);
  };
  vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
  const char* appended_encoding = appended ? appended->GetAttribute("encoding") : nullptr;
  const bool appended_base64 = appended_encoding == nullptr || std::string(appended_encoding) != "raw";
  std::vector<vtkXMLDataElement*> todo{root}; // in file order, so that the first bad array is named
  while (!todo.empty()) {
    vtkXMLDataElement* e = todo.back();
    todo.pop_back();
    for (int i = e->GetNumberOfNestedElements(); i-- > 0;)
      todo.push_back(e->GetNestedElement(i));
    const char* format = e->GetAttribute("format");
    if (std::string(e->GetName() ? e->GetName() : "") != "DataArray" || format == nullptr)
      continue;
    if (std::string(format) == "ascii")
      continue;
    const std::string array = "byte " + std::to_string(e->GetXMLByteIndex()) +
                              ": the compressed DataArray '" +
                              (e->GetAttribute("Name") ? e->GetAttribute("Name") : "") + "'";
    long long position = 0;
    bool base64 = true;
    if (std::string(format) == "appended") {
      const char* offset = e->GetAttribute("offset");
      if (appended == nullptr || offset == nullptr)
        continue; // VTK reports what is missing
      // An offset outside the file holds no header; one beyond long long (found by fuzzing: 61
      // digits) saturates strtoll, and the sum would overflow.
      const long long start = static_cast<long long>(parser->GetAppendedDataPosition());
      errno = 0;
      const long long shift = std::strtoll(offset, nullptr, 10);
      const double where_in_file = double(start) + double(shift);
      if (errno == ERANGE || where_in_file < 0. || where_in_file > file_bytes) {
        const std::string shown = std::string(offset).substr(0, 40);
        c.fail(array + " has the offset \"" + shown + (shown.size() < std::strlen(offset) ? "...\"" : "\"") +
               ", outside the " + std::to_string(static_cast<long long>(file_bytes)) +
               " bytes of the file (corrupt file)");
      }
      position = start + shift;
      base64 = appended_base64;
    }
    else {
      const std::optional<long long> inline_data = VTK_XML_inline_data_position(in, e->GetXMLByteIndex());
      if (!inline_data)
        continue; // VTK reports the unfinished tag
      position = *inline_data;
    }
    const bool inline_array = std::string(format) != "appended";
    const std::string head = read_VTK_XML_bytes(in, position, base64, 3 * word, inline_array);
    if (head.size() < 3 * word) {
      // Inline, VTK would decode a header from what follows; appended, it allocates from the
      // words of a short read (found by fuzzing: padding inside the header, 3e9 blocks).
      c.fail(array + " has no complete compression header in its " + (inline_array ? "inline" : "appended") +
             " data (corrupt file)");
    }
    const double blocks = number(head, 0), block_size = number(head, 1), last_size = number(head, 2);
    const std::string where = array + " announces ";
    std::ostringstream msg;
    if (blocks * double(word) > file_bytes) {
      msg << where << blocks << " blocks, whose sizes alone need more than the " << file_bytes
          << " bytes of the file (corrupt or lying header)";
      c.fail(msg.str());
    }
    const double uncompressed =
        blocks == 0. ? 0. : block_size * (blocks - 1.) + (last_size ? last_size : block_size);
    if (std::max(block_size, uncompressed) > 2000. * file_bytes + 1e6) {
      msg << where << blocks << " blocks of " << block_size << " bytes (the last " << last_size
          << "), far more than the " << file_bytes << " bytes of the file can hold even compressed "
          << "(corrupt or lying header)";
      c.fail(msg.str());
    }
    const std::string sizes =
        read_VTK_XML_bytes(in, position, base64, (3 + static_cast<std::size_t>(blocks)) * word, inline_array);
    double compressed = 0.;
    for (std::size_t b = 3; b * word + word <= sizes.size(); ++b)
      compressed += number(sizes, b);
    if (compressed > file_bytes) {
      msg << where << "blocks of " << compressed << " compressed bytes in all, more than the " << file_bytes
          << " bytes of the file (corrupt or lying header)";
      c.fail(msg.str());
    }
  }
}

// Runs a VTK reader on the file; its errors become ours.
template <class Reader>
vtkSmartPointer<vtkDataSet> run_VTK_reader(const VTK_XML_context& c)
{
  vtkSmartPointer<Reader> reader = vtkSmartPointer<Reader>::New();
  const vtkSmartPointer<VTK_error_observer> messages = watch_VTK_reader(reader.Get());
  reader->SetFileName(c.file.c_str());
  // The header first, so that a lying one cannot make VTK allocate far more than the file holds.
  reader->UpdateInformation();
  if (messages->has_errors())
    c.fail("VTK cannot read it: " + messages->errors());
  check_VTK_XML_structure(c, reader->GetXMLParser());
  check_VTK_XML_compression_headers(c, reader->GetXMLParser());
  check_announced_size(c, reader.Get());
  reader->Update();
  vtkSmartPointer<vtkDataSet> output = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (messages->has_errors())
    c.fail("VTK cannot read it: " + messages->errors());
  if (output == nullptr || output->GetNumberOfPoints() == 0)
    c.fail("VTK read no points from it (an empty data set or an empty piece)");
  return output;
}

inline std::string describe_VTK_arrays(vtkPointData* pd)
{
  std::string r;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = pd->GetAbstractArray(i);
    if (a == nullptr)
      continue;
    const int n = a->GetNumberOfComponents();
    r += (r.empty() ? "'" : ", '") + std::string(a->GetName() ? a->GetName() : "") + "' (" +
         a->GetDataTypeAsString() + ", " + std::to_string(n) + " component" + (n == 1 ? "" : "s") + ")";
  }
  return r.empty() ? std::string("none") : r;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_READER_H
