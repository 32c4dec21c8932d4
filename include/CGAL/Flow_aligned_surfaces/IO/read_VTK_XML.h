// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads velocity fields from VTK XML files through the VTK library (9.x): an ImageData file
// (.vti, a uniform grid of nx × ny × nz points) into a `Regular_grid_flow_field_3`, and an
// UnstructuredGrid (.vtu), StructuredGrid (.vts) or ImageData file into an
// `Unstructured_flow_field_3` (a curvilinear or uniform grid as its (nx-1)(ny-1)(nz-1)
// hexahedra); and a ParaView data collection (.pvd: steps t_0 ... t_n, one file each) into an
// `Unsteady_flow_field_3`.  The velocity is a 3-component point array, the optional mask a
// 1-component point array (nonzero = fluid).  VTK's own error messages are captured by
// observers on the reader, its XML parser and its pipeline, never printed, and returned in the
// error message.
//
// Needs VTK: link the target CGAL::Flow_aligned_surfaces_VTK.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H

#include <string>

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/binary_numbers.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/node_value_checks.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/remove_masked_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/structured_grid_cells.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/voxels_as_hexahedra.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

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
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \cond SKIP_IN_MANUAL
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
    long long position = 0;
    bool base64 = true;
    if (std::string(format) == "appended") {
      const char* offset = e->GetAttribute("offset");
      if (appended == nullptr || offset == nullptr)
        continue; // VTK reports what is missing
      position =
          static_cast<long long>(parser->GetAppendedDataPosition()) + std::strtoll(offset, nullptr, 10);
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
      c.fail("byte " + std::to_string(e->GetXMLByteIndex()) + ": the compressed DataArray '" +
             (e->GetAttribute("Name") ? e->GetAttribute("Name") : "") + "' has no complete compression header in its " +
             (inline_array ? "inline" : "appended") + " data (corrupt file)");
    }
    const double blocks = number(head, 0), block_size = number(head, 1), last_size = number(head, 2);
    const std::string where = "byte " + std::to_string(e->GetXMLByteIndex()) +
                              ": the compressed DataArray '" +
                              (e->GetAttribute("Name") ? e->GetAttribute("Name") : "") + "' announces ";
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

// The velocity and mask of the point data, chosen as documented, as floats and fluid flags.
// `where(i)` names point i in messages.
template <class Where>
void read_VTK_point_arrays(const VTK_XML_context& c, vtkDataSet* ds, const std::string* array_name,
                           const std::string* mask_name, const Where& where, std::vector<float>& values,
                           std::vector<unsigned char>& flags)
{
  vtkPointData* pd = ds->GetPointData();
  const std::size_t n = static_cast<std::size_t>(ds->GetNumberOfPoints());
  const std::string present = " (the point data arrays are: " + describe_VTK_arrays(pd) + ")";
  vtkDataArray* velocity = nullptr;
  if (array_name != nullptr) {
    vtkAbstractArray* a = pd->GetAbstractArray(array_name->c_str());
    if (a == nullptr)
      c.fail("there is no point data array named '" + *array_name + "'" + present);
    velocity = vtkDataArray::SafeDownCast(a);
    if (velocity == nullptr)
      c.fail("the point data array '" + *array_name + "' holds " + a->GetDataTypeAsString() +
             ", not numbers; a velocity needs 3 numbers per point");
  }
  else {
    velocity = pd->GetVectors();
    for (int i = 0;
         i < pd->GetNumberOfArrays() && (velocity == nullptr || velocity->GetNumberOfComponents() != 3); ++i)
      velocity = pd->GetArray(i);
    if (velocity == nullptr || velocity->GetNumberOfComponents() != 3)
      c.fail("there is no 3-component point data array to read as the velocity" + present);
  }
  const std::string velocity_name = velocity->GetName() ? velocity->GetName() : "";
  if (velocity->GetNumberOfComponents() != 3)
    c.fail("the point data array '" + velocity_name + "' has " +
           std::to_string(velocity->GetNumberOfComponents()) +
           " components; a velocity needs 3 numbers per point");

  vtkDataArray* mask = nullptr;
  const std::string mask_array = mask_name ? *mask_name : std::string("inside");
  if (!mask_array.empty()) {
    vtkAbstractArray* a = pd->GetAbstractArray(mask_array.c_str());
    if (a == nullptr && mask_name != nullptr)
      c.fail("there is no point data array named '" + mask_array + "' for the mask" + present);
    if (a != nullptr) {
      mask = vtkDataArray::SafeDownCast(a);
      if (mask == nullptr || mask->GetNumberOfComponents() != 1)
        c.fail("the mask array '" + mask_array + "' has " + std::to_string(a->GetNumberOfComponents()) +
               " components of type " + a->GetDataTypeAsString() + "; a mask needs 1 number per point");
    }
  }
  for (vtkDataArray* a : {velocity, mask})
    if (a != nullptr && static_cast<std::size_t>(a->GetNumberOfTuples()) != n)
      c.fail(std::string(a == mask ? "the mask array '" : "the velocity array '") +
             (a->GetName() ? a->GetName() : "") + "' has " + std::to_string(a->GetNumberOfTuples()) +
             " tuples but the data set has " + std::to_string(n) + " points");

  std::vector<unsigned char> f;
  if (mask != nullptr) {
    f.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      f[i] = Flow_aligned_surfaces::IO::internal::checked_mask_flag(
          mask->GetComponent(static_cast<vtkIdType>(i), 0), mask_array, [&] { return "point " + where(i); },
          [&](const std::string& what) { c.fail(what); });
  }
  std::vector<float> v(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    double x[3];
    velocity->GetTuple(static_cast<vtkIdType>(i), x);
    for (int d = 0; d < 3; ++d) {
      const float s = Flow_aligned_surfaces::IO::internal::checked_velocity_component(
          x[d], std::size_t(d), [&] { return f.empty() || f[i] != 0; }, !f.empty(), velocity_name, "point",
          [&] { return "point " + where(i); }, [&](const std::string& what) { c.fail(what); });
      // Solid points' values are never interpolated; the fields' constructors want them finite.
      v[3 * i + d] = std::isnan(s) ? 0.f : s;
    }
  }
  values = std::move(v);
  flags = std::move(f);
}

// The image's dimensions, checked to be a 3D grid without rotation.
inline std::array<std::size_t, 3> checked_image_dimensions(const VTK_XML_context& c, vtkImageData* image)
{
  int d[3];
  image->GetDimensions(d);
  std::array<std::size_t, 3> n;
  for (int a = 0; a < 3; ++a) {
    if (d[a] < 2)
      c.fail("the image has " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
             std::to_string(d[2]) +
             " points; a grid needs at least 2 points along each axis (2D and 1D images are not supported)");
    n[a] = static_cast<std::size_t>(d[a]);
  }
  if (vtkMatrix3x3* m = image->GetDirectionMatrix()) {
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col)
        if (m->GetElement(r, col) != (r == col ? 1. : 0.)) {
          std::ostringstream msg;
          msg << "the image has the Direction matrix (";
          for (int k = 0; k < 9; ++k)
            msg << (k ? " " : "") << m->GetElement(k / 3, k % 3);
          msg << "), which is not the identity: rotated images are not supported";
          c.fail(msg.str());
        }
  }
  return n;
}

template <class K>
Regular_grid_flow_field_3<K> read_VTK_XML_grid(const VTK_XML_context& c, const std::string* array_name,
                                               const std::string* mask_name)
{
  check_readable(c);
  if (!VTK_can_read<vtkXMLImageDataReader>(c.file))
    c.fail("this is " + VTK_XML_kind(c.file) +
           "; a Regular_grid_flow_field_3 is read from a VTK XML ImageData file (.vti)");
  vtkSmartPointer<vtkDataSet> ds = run_VTK_reader<vtkXMLImageDataReader>(c);
  vtkImageData* image = vtkImageData::SafeDownCast(ds);
  const std::array<std::size_t, 3> n = checked_image_dimensions(c, image);
  std::vector<float> values;
  std::vector<unsigned char> flags;
  read_VTK_point_arrays(
      c, ds, array_name, mask_name,
      [&n](std::size_t i) { return Flow_aligned_surfaces::IO::internal::grid_node_string(n, i); }, values, flags);
  // The grid's origin is the image's first point, which the extent may move off VTK's origin.
  double first[3], spacing[3];
  image->GetPoint(0, first);
  image->GetSpacing(spacing);
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  return Flow_aligned_surfaces::IO::internal::construct_field<Regular_grid_flow_field_3<K>>(
      [&](const std::string& what) { c.fail(what); }, Point_3(first[0], first[1], first[2]),
      Vector_3(spacing[0], spacing[1], spacing[2]), n, std::move(values), std::move(flags));
}

// The cells of the data set as VTK arrays, with the velocity and the mask; cells touching a
// solid point are dropped.
// The coordinates of the np points of ds, x, y, z per point, as Real.
template <class Real>
std::vector<Real> VTK_point_coordinates(vtkDataSet* ds, std::size_t np)
{
  std::vector<Real> r(3 * np);
  double x[3];
  for (std::size_t i = 0; i < np; ++i) {
    ds->GetPoint(static_cast<vtkIdType>(i), x);
    for (int a = 0; a < 3; ++a)
      r[3 * i + a] = static_cast<Real>(x[a]);
  }
  return r;
}

template <class K>
Unstructured_flow_field_3<K> read_VTK_XML_cells(const VTK_XML_context& c, const std::string* array_name,
                                                const std::string* mask_name)
{
  // vtkIdType here; the field's constructor narrows to its 32-bit Index (and says so if it cannot).
  typedef std::int64_t Index;
  check_readable(c);
  vtkSmartPointer<vtkDataSet> ds;
  std::optional<std::array<std::size_t, 3>> structured;
  if (VTK_can_read<vtkXMLUnstructuredGridReader>(c.file)) {
    ds = run_VTK_reader<vtkXMLUnstructuredGridReader>(c);
  }
  else if (VTK_can_read<vtkXMLStructuredGridReader>(c.file)) {
    ds = run_VTK_reader<vtkXMLStructuredGridReader>(c);
    int d[3];
    vtkStructuredGrid::SafeDownCast(ds)->GetDimensions(d);
    for (int a = 0; a < 3; ++a)
      if (d[a] < 2)
        c.fail("the structured grid has " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
               std::to_string(d[2]) + " points; it needs at least 2 points along each axis");
    structured = {{std::size_t(d[0]), std::size_t(d[1]), std::size_t(d[2])}};
  }
  else if (VTK_can_read<vtkXMLImageDataReader>(c.file)) {
    ds = run_VTK_reader<vtkXMLImageDataReader>(c);
    structured = checked_image_dimensions(c, vtkImageData::SafeDownCast(ds));
  }
  else {
    c.fail("this is " + VTK_XML_kind(c.file) +
           "; an Unstructured_flow_field_3 is read from a VTK XML UnstructuredGrid (.vtu), StructuredGrid "
           "(.vts) or ImageData (.vti) file");
  }

  const std::size_t np = static_cast<std::size_t>(ds->GetNumberOfPoints());
  std::vector<float> values;
  std::vector<unsigned char> flags;
  if (structured)
    read_VTK_point_arrays(
        c, ds, array_name, mask_name,
        [&](std::size_t i) { return Flow_aligned_surfaces::IO::internal::grid_node_string(*structured, i); },
        values, flags);
  else
    read_VTK_point_arrays(
        c, ds, array_name, mask_name, [](std::size_t i) { return std::to_string(i); }, values, flags);

  std::vector<Index> connectivity, offsets;
  std::vector<unsigned char> types;
  if (structured) {
    Flow_aligned_surfaces::IO::internal::Structured_grid_cells cells =
        Flow_aligned_surfaces::IO::internal::structured_grid_cells(*structured);
    connectivity = std::move(cells.connectivity);
    offsets = std::move(cells.offsets);
    types = std::move(cells.cell_types);
  }
  else {
    vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(ds);
    const vtkIdType nc = grid->GetNumberOfCells();
    if (nc == 0)
      c.fail("the unstructured grid has no cells");
    offsets.reserve(static_cast<std::size_t>(nc) + 1);
    types.reserve(static_cast<std::size_t>(nc));
    offsets.push_back(0);
    for (vtkIdType cell = 0; cell < nc; ++cell) {
      const int type = grid->GetCellType(cell);
      if (type != VTK_TETRA && type != VTK_VOXEL && type != VTK_HEXAHEDRON && type != VTK_WEDGE &&
          type != VTK_PYRAMID) {
        const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
        c.fail("cell " + std::to_string(cell) + " has the VTK cell type " + std::to_string(type) + " (" +
               (name ? name : "unknown") +
               "); supported are 10 (tetrahedron), 11 (voxel), 12 (hexahedron), 13 (wedge) and 14 (pyramid)");
      }
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      grid->GetCellPoints(cell, n, ids);
      connectivity.insert(connectivity.end(), ids, ids + n);
      offsets.push_back(static_cast<Index>(connectivity.size()));
      types.push_back(static_cast<unsigned char>(type));
    }
    Flow_aligned_surfaces::IO::internal::voxels_as_hexahedra(types, offsets, connectivity);
  }

  const std::size_t cells = types.size();
  if (!flags.empty() &&
      Flow_aligned_surfaces::IO::internal::remove_masked_cells(flags, connectivity, offsets, types) == 0)
    c.fail("every one of the " + std::to_string(cells) +
           " cells touches a solid point of the mask (no fluid cell is left)");
  const auto refused = [&](const std::string& what) { c.fail(what); };
  // The points in the file's precision (float points stay float in the field).
  vtkPointSet* point_set = vtkPointSet::SafeDownCast(ds);
  if (point_set != nullptr && point_set->GetPoints() != nullptr &&
      point_set->GetPoints()->GetDataType() == VTK_FLOAT)
    return Flow_aligned_surfaces::IO::internal::construct_field<Unstructured_flow_field_3<K>>(
        refused, VTK_point_coordinates<float>(ds, np), std::move(connectivity), std::move(offsets),
        std::move(types), std::move(values));
  return Flow_aligned_surfaces::IO::internal::construct_field<Unstructured_flow_field_3<K>>(
      refused, VTK_point_coordinates<double>(ds, np), std::move(connectivity), std::move(offsets),
      std::move(types), std::move(values));
}

template <class Field>
struct VTK_XML_field_reader;

template <class K>
struct VTK_XML_field_reader<Regular_grid_flow_field_3<K>> {
  static Regular_grid_flow_field_3<K> read(const VTK_XML_context& c, const std::string* a,
                                           const std::string* m)
  {
    return read_VTK_XML_grid<K>(c, a, m);
  }
};

template <class K>
struct VTK_XML_field_reader<Unstructured_flow_field_3<K>> {
  static Unstructured_flow_field_3<K> read(const VTK_XML_context& c, const std::string* a,
                                           const std::string* m)
  {
    return read_VTK_XML_cells<K>(c, a, m);
  }
};

// The steps of a .pvd file: (time, file, byte offset of the DataSet element), in file order.
struct PVD_step {
  double time;
  std::string file;
  long long byte;
};

inline std::vector<PVD_step> read_PVD_steps(const VTK_XML_context& c)
{
  check_readable(c);
  vtkSmartPointer<vtkXMLDataParser> parser = vtkSmartPointer<vtkXMLDataParser>::New();
  const vtkSmartPointer<VTK_error_observer> messages = vtkSmartPointer<VTK_error_observer>::New();
  messages->watch(parser);
  parser->SetFileName(c.file.c_str());
  const int parsed = parser->Parse();
  if (!parsed || messages->has_errors() || parser->GetRootElement() == nullptr)
    c.fail("VTK cannot parse it as XML: " +
           (messages->has_errors() ? messages->errors() : std::string("no root element")));
  vtkXMLDataElement* root = parser->GetRootElement();
  const char* type = root->GetAttribute("type");
  if (std::string(root->GetName() ? root->GetName() : "") != "VTKFile" || type == nullptr ||
      std::string(type) != "Collection")
    c.fail(std::string("the root element is <") + (root->GetName() ? root->GetName() : "") + " type=\"" +
           (type ? type : "") + "\">; a ParaView data collection has <VTKFile type=\"Collection\">");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (collection == nullptr)
    c.fail("the VTKFile element has no <Collection> element");
  const std::filesystem::path folder = std::filesystem::path(c.file).parent_path();
  std::vector<PVD_step> steps;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    if (std::string(e->GetName() ? e->GetName() : "") != "DataSet")
      continue;
    const std::string where = "byte " + std::to_string(e->GetXMLByteIndex()) + ": DataSet element " +
                              std::to_string(steps.size()) + ": ";
    const char* timestep = e->GetAttribute("timestep");
    const char* file = e->GetAttribute("file");
    if (timestep == nullptr)
      c.fail(where + "no timestep attribute");
    if (file == nullptr || *file == '\0')
      c.fail(where + "no file attribute");
    char* end = nullptr;
    const double t = std::strtod(timestep, &end);
    if (end == timestep || *end != '\0' || !std::isfinite(t))
      c.fail(where + "the timestep '" + Flow_aligned_surfaces::IO::internal::printable(timestep) +
             "' is not a finite number");
    std::filesystem::path path(file);
    if (path.is_relative())
      path = folder / path;
    steps.push_back(PVD_step{t, path.string(), static_cast<long long>(e->GetXMLByteIndex())});
  }
  if (steps.empty())
    c.fail("the Collection holds no DataSet element");
  return steps;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a VTK XML ImageData file (`.vti`) into an
optional, for callers that have no field yet; same as the overload below otherwise.
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, std::optional<Regular_grid_flow_field_3<K>>& field,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             std::string* error = nullptr)
{
  const Flow_aligned_surfaces::IO::internal::Array_names names = Flow_aligned_surfaces::IO::internal::array_names(np);
  const internal::VTK_XML_context c{"read_VTK_XML_flow_field", filename};
  return Flow_aligned_surfaces::IO::internal::read_into(c.reader, filename, field, error, [&] {
    return internal::read_VTK_XML_grid<K>(c, names.array_name(), names.mask_name());
  });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a VTK XML ImageData file (`.vti`) with
VTK's `vtkXMLImageDataReader`.

The image must have at least 2 points along each axis and no rotation (a `Direction` matrix
other than the identity is refused); its first point is the grid's origin, whatever the
extent.  The velocity is a 3-component point data array of any numeric type (stored as 32-bit
floats), the node mask a 1-component point data array, nonzero = fluid.  Any encoding VTK
reads is accepted (ASCII, base64, raw appended, compressed).

Bad input never crashes or prints: a missing or unreadable file, a file VTK cannot read (its
messages are captured and returned), a file of another kind, missing arrays (the message lists
the arrays present), wrong numbers of components, a rotated or flat image, or a NaN or infinite
velocity at a fluid point (the message gives the point's index) make the function return
`false` with a message that names the file and what is wrong.  Non-finite values at solid
points are accepted and stored as zero.

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
    \cgalParamDefault{the active vectors of the point data if they have 3 components, else its first
      3-component array}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{the name of the node mask array (`FAS::parameters::mask_array_name()`);
      an error if given and absent; the empty string reads no mask}
    \cgalParamType{`std::string`}
    \cgalParamDefault{`"inside"` if the file has it, else no mask}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `write_VTI_flow_field()`, `read_VTK_flow_field()`, `read_PVD_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             std::string* error = nullptr)
{
  return Flow_aligned_surfaces::IO::internal::read_and_assign<Regular_grid_flow_field_3<K>>(
      field, [&](auto& result) { return read_VTK_XML_flow_field(filename, result, np, error); });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on cells from a VTK XML file into an optional, for callers that
have no field yet; same as the overload below otherwise.
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, std::optional<Unstructured_flow_field_3<K>>& field,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             std::string* error = nullptr)
{
  const Flow_aligned_surfaces::IO::internal::Array_names names = Flow_aligned_surfaces::IO::internal::array_names(np);
  const internal::VTK_XML_context c{"read_VTK_XML_flow_field", filename};
  return Flow_aligned_surfaces::IO::internal::read_into(c.reader, filename, field, error, [&] {
    return internal::read_VTK_XML_cells<K>(c, names.array_name(), names.mask_name());
  });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on cells from a VTK XML UnstructuredGrid (`.vtu`), StructuredGrid
(`.vts`) or ImageData (`.vti`) file with VTK's readers.

The kind of file is told by its contents, not its name.  An unstructured grid may hold
tetrahedra, hexahedra, wedges and pyramids (VTK cell types 10, 12, 13, 14) and voxels (type 11,
read as the same hexahedra, points 0 1 3 2 4 5 7 6); any other type is refused with the cell's
index and type.  A structured grid or an image (without rotation)
becomes its hexahedra, point `(i, j, k)` being point `i + nx (j + ny k)`.  The velocity and the
mask are chosen as for the overload reading a `Regular_grid_flow_field_3`; with a mask, every
cell touching a solid point (mask value 0) is left out of the field.  Bad input is reported as
there, and also a grid without cells or without any cell whose points are all fluid.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field receives the field on success; left untouched on failure
\param np an optional sequence of named parameters: `array_name` and `mask_array_name`, as for
       the overload reading a `Regular_grid_flow_field_3`
\param error if not null, receives the reason of a failure

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `Unstructured_flow_field_3`, `read_PVD_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, Unstructured_flow_field_3<K>& field,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             std::string* error = nullptr)
{
  return Flow_aligned_surfaces::IO::internal::read_and_assign<Unstructured_flow_field_3<K>>(
      field, [&](auto& result) { return read_VTK_XML_flow_field(filename, result, np, error); });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a time series from a ParaView data collection (`.pvd`) into an optional, for
callers that have no field yet; same as the overload below otherwise.
*/
template <class Field, class NamedParameters = parameters::Default_named_parameters>
bool read_PVD_flow_field(const std::string& filename, std::optional<Unsteady_flow_field_3<Field>>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  const Flow_aligned_surfaces::IO::internal::Array_names names = Flow_aligned_surfaces::IO::internal::array_names(np);
  const internal::VTK_XML_context c{"read_PVD_flow_field", filename};
  return Flow_aligned_surfaces::IO::internal::read_into(c.reader, filename, field, error, [&] {
    std::vector<internal::PVD_step> steps = internal::read_PVD_steps(c);
    std::stable_sort(
        steps.begin(), steps.end(),
        [](const internal::PVD_step& a, const internal::PVD_step& b) { return a.time < b.time; });
    for (std::size_t i = 1; i < steps.size(); ++i)
      if (steps[i - 1].time == steps[i].time) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "the DataSet elements at bytes " << steps[i - 1].byte << " (file " << steps[i - 1].file
            << ") and " << steps[i].byte << " (file " << steps[i].file << ") have the same timestep "
            << steps[i].time << "; expected distinct times (several parts per step are not supported)";
        c.fail(msg.str());
      }
    std::vector<double> times;
    std::vector<Field> fields;
    times.reserve(steps.size());
    fields.reserve(steps.size());
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const internal::VTK_XML_context step{"read_VTK_XML_flow_field", steps[i].file};
      try {
        fields.push_back(
            internal::VTK_XML_field_reader<Field>::read(step, names.array_name(), names.mask_name()));
      } catch (const internal::VTK_XML_error& e) {
        std::ostringstream msg;
        msg.precision(17);
        msg << "step " << i << " (timestep " << steps[i].time << ", file " << steps[i].file
            << "): " << e.what();
        c.fail(msg.str());
      }
      times.push_back(steps[i].time);
    }
    return Unsteady_flow_field_3<Field>(std::move(times), std::move(fields));
  });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a time series of flow fields from a ParaView data collection (`.pvd`).

The collection is parsed with VTK's `vtkXMLDataParser`: its `DataSet` elements each give a
`timestep` and a `file`, relative to the folder of the `.pvd` file unless absolute.  Every step
is read with `read_VTK_XML_flow_field()` into a `Field` (with the same named parameters) and
the steps are sorted by time.  A collection that cannot be parsed, has no step, a step without
a time or file, two steps with the same time, or a step that cannot be read makes the function
return `false` with a message naming the `.pvd` file, the step (its index after sorting, its
time and its file) and the reason given by the step's reader.

\tparam Field `Regular_grid_flow_field_3<K>` or `Unstructured_flow_field_3<K>`
\tparam NamedParameters a sequence of named parameters

\param filename the `.pvd` file to read
\param field receives the time series on success; left untouched on failure
\param np an optional sequence of named parameters: `array_name` and `mask_array_name`, as for
       `read_VTK_XML_flow_field()`
\param error if not null, receives the reason of a failure

\returns `true` on success; `false` with the reason in `error` (when not null) otherwise.

\sa `Unsteady_flow_field_3`, `read_VTK_XML_flow_field()`
*/
template <class Field, class NamedParameters = parameters::Default_named_parameters>
bool read_PVD_flow_field(const std::string& filename, Unsteady_flow_field_3<Field>& field,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         std::string* error = nullptr)
{
  return Flow_aligned_surfaces::IO::internal::read_and_assign<Unsteady_flow_field_3<Field>>(
      field, [&](auto& result) { return read_PVD_flow_field(filename, result, np, error); });
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H
