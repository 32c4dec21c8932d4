// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A VTK XML data set file opened without VTK: its bytes, its XML, the kind of data set
// (`<VTKFile type="ImageData|RectilinearGrid|StructuredGrid|UnstructuredGrid">`), its
// `<Piece>` (one; an unstructured grid may have several, visited in turn) with the number of
// points and cells (from the piece's Extent for the structured kinds), and its arrays, decoded
// on demand.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_DATA_SET_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_DATA_SET_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/VTK_XML_data_arrays.h>
#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/XML_document.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Opening the file first gives a plain message for a missing, unreadable or empty file.
inline void check_readable(const std::string& reader, const std::string& file)
{
  auto fail = [&](const std::string& what) { throw Read_error(reader + ": " + file + ": " + what); };
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    fail("is a directory, not a file");
  std::ifstream is(file, std::ios::binary);
  if (!is)
    fail(std::filesystem::exists(file, ec) ? "cannot open the file for reading (permissions?)" : "no such file");
  if (is.peek() == std::ifstream::traits_type::eof())
    fail("the file is empty (0 bytes)");
}

/// The whitespace-separated numbers of attribute `name` of `e`: exactly `count` finite ones.
inline std::vector<double> VTK_XML_numbers(const XML_document& doc, const XML_element& e, const char* name,
                                           std::size_t count)
{
  const std::string* s = e.attribute(name);
  std::vector<double> r;
  Text_cursor t(std::string(), doc.file(), s ? std::string_view(*s) : std::string_view());
  for (std::string_view token = t.token(); !token.empty(); token = t.token()) {
    double v = 0;
    if (!Text_cursor::parse_number(token, v) || !std::isfinite(v) || r.size() == count)
      doc.fail_element(e, std::string(name) + "=\"" + printable(*s) + "\"; expected " + std::to_string(count) +
                              " finite numbers");
    r.push_back(v);
  }
  if (r.size() != count)
    doc.fail_element(e, std::string(name) + "=\"" + printable(s ? *s : std::string()) + "\"; expected " +
                            std::to_string(count) + " finite numbers");
  return r;
}

/// What the file is, for messages when it is not what the caller wants.
inline std::string VTK_XML_kind(const std::string& type)
{
  if (type == "ImageData")
    return "a VTK XML ImageData file (.vti)";
  if (type == "RectilinearGrid")
    return "a VTK XML RectilinearGrid file (.vtr)";
  if (type == "StructuredGrid")
    return "a VTK XML StructuredGrid file (.vts)";
  if (type == "UnstructuredGrid")
    return "a VTK XML UnstructuredGrid file (.vtu)";
  return "a VTK XML file of type \"" + printable(type) + "\"";
}

class VTK_XML_data_set {
public:
  /// Reads and parses the file; fails unless it is one of the `accepted` kinds, which the
  /// message names as `wanted`.
  VTK_XML_data_set(const std::string& reader, const std::string& file, const std::vector<std::string>& accepted,
                   const std::string& wanted)
      : contents((check_readable(reader, file), File_contents(file, reader))),
        doc(reader, file, contents.view()), cursor(reader, file, contents.view()), decoder(doc)
  {
    const XML_element& root = doc.root();
    const std::string* t = root.attribute("type");
    if (root.name != "VTKFile" || t == nullptr)
      doc.fail_element(root, "the root element is not <VTKFile type=...>: not a VTK XML file");
    type = *t;
    if (std::find(accepted.begin(), accepted.end(), type) == accepted.end())
      doc.fail_file("this is " + VTK_XML_kind(type) + "; " + wanted);
    data_set = doc.child(root, type);
    if (data_set == nullptr)
      doc.fail_element(root, "there is no <" + type + "> element");
    find_pieces();
    if (type == "UnstructuredGrid") {
      bool any_points = false;
      for (std::size_t i = pieces.size(); i-- > 0;) {
        select_piece(i);
        any_points |= points != 0;
      }
      if (!any_points)
        doc.fail_element(*piece, pieces.size() == 1 ? "the piece has no points" : "no piece has points");
    }
    else {
      read_extent();
    }
  }

  /// Makes piece `i` (of an unstructured grid) the current one.
  void select_piece(std::size_t i)
  {
    piece = pieces[i];
    points = VTK_XML_count(doc, *piece, "NumberOfPoints", 0);
    cells = VTK_XML_count(doc, *piece, "NumberOfCells", 0);
  }

  File_contents contents;
  XML_document doc;
  Text_cursor cursor; ///< names the file in the messages of the value decoders
  VTK_XML_array_decoder decoder;
  std::string type;
  const XML_element* data_set = nullptr;
  std::vector<const XML_element*> pieces; ///< several only in an unstructured grid
  const XML_element* piece = nullptr;      ///< the current piece
  std::size_t points = 0, cells = 0;
  std::array<std::size_t, 3> dimensions{{0, 0, 0}}; ///< points along each axis (structured kinds)
  std::array<double, 3> first_index{{0, 0, 0}};      ///< the piece's first point index (i, j, k)

  /// The DataArray children of `e` (null: none).
  std::vector<VTK_XML_array> arrays(const XML_element* e) const
  {
    std::vector<VTK_XML_array> r;
    if (e != nullptr)
      for (std::size_t c : e->children)
        if (doc.elements[c].name == "DataArray")
          r.push_back(read_VTK_XML_array(doc, doc.elements[c]));
    return r;
  }

  /// The child `name` of the piece, which must be there.
  const XML_element& piece_child(const std::string& name) const
  {
    const XML_element* e = doc.child(*piece, name);
    if (e == nullptr)
      doc.fail_element(*piece, "the piece has no <" + name + "> element");
    return *e;
  }

private:
  // The pieces; several only in an unstructured grid, whose pieces the reader concatenates.
  void find_pieces()
  {
    for (std::size_t c : data_set->children)
      if (doc.elements[c].name == "Piece")
        pieces.push_back(&doc.elements[c]);
    if (pieces.empty())
      doc.fail_element(*data_set, "there is no <Piece> element");
    piece = pieces.front();
    if (pieces.size() > 1 && type != "UnstructuredGrid")
      doc.fail_element(*data_set, "the data set has " + std::to_string(pieces.size()) +
                                      " pieces; only structured files of one piece are read (merge them, for "
                                      "instance with ParaView's Merge Blocks, and save again)");
  }

  void read_extent()
  {
    const std::vector<double> e = VTK_XML_numbers(doc, *piece, "Extent", 6);
    const XML_element& d = *data_set;
    const std::vector<double> whole = d.attribute("WholeExtent") ? VTK_XML_numbers(doc, d, "WholeExtent", 6) : e;
    auto text = [](const std::vector<double>& x) {
      std::string r;
      for (std::size_t i = 0; i < x.size(); ++i)
        r += (i ? " " : "") + number_string(x[i]); // any finite number, whatever its size
      return r;
    };
    double n = 1;
    for (int a = 0; a < 3; ++a) {
      const double lo = e[2 * a], hi = e[2 * a + 1];
      if (lo != std::floor(lo) || hi != std::floor(hi) || std::fabs(lo) > 2e9 || std::fabs(hi) > 2e9 || hi < lo)
        doc.fail_element(*piece, "the Extent \"" + printable(*piece->attribute("Extent")) +
                                     "\" is not 3 ranges of integers, low <= high");
      if (lo < whole[2 * a] || hi > whole[2 * a + 1])
        doc.fail_element(*piece, "the piece's Extent \"" + text(e) + "\" reaches outside the WholeExtent \"" +
                                     text(whole) + "\" of the data set");
      dimensions[a] = static_cast<std::size_t>(hi - lo + 1);
      first_index[a] = lo;
      n *= hi - lo + 1;
    }
    // A count beyond any memory is refused here, before products of it can overflow; the
    // arrays are checked against their bytes when they are read.
    if (n > 1e15)
      doc.fail_element(*piece, "the Extent \"" + text(e) + "\" gives " + std::to_string(n) +
                                   " points, more than any file holds (corrupt file)");
    points = static_cast<std::size_t>(n);
    cells = (dimensions[0] - 1) * (dimensions[1] - 1) * (dimensions[2] - 1);
  }
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_VTK_XML_DATA_SET_H
