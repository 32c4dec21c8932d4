// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow-field readers of the package, one header per file format, and `read_flow_field()`,
// which reads a file of any of these formats into a `Sampled_flow_field_3`: the format is told
// from the first bytes of the file (never from its name), and the field type from the dataset
// the file holds (a uniform grid, a rectilinear grid, or cells).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_FLOW_FIELD_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_FLOW_FIELD_H

#include <CGAL/Flow_aligned_surfaces/IO/read_AmiraMesh.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_NRRD.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/Sampled_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <cctype>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

enum class Flow_field_file_kind {
  LEGACY_UNIFORM_GRID,
  LEGACY_RECTILINEAR_GRID,
  LEGACY_CELLS, // STRUCTURED_GRID, UNSTRUCTURED_GRID and what the legacy reader then rejects
  XML_IMAGE_DATA,
  XML_RECTILINEAR_GRID,
  XML_CELLS, // UnstructuredGrid, StructuredGrid and what the XML reader then rejects
  AMIRA_MESH,
  NRRD_FILE,
  UNKNOWN
};

// The kind of file from its first bytes; an unreadable file is UNKNOWN (the reader then called
// says why it cannot open it).  `head` receives those bytes for the message about an unknown
// format.
inline Flow_field_file_kind flow_field_file_kind(const std::string& filename, std::string& head)
{
  std::ifstream is(filename, std::ios::binary);
  char bytes[4096];
  is.read(bytes, sizeof bytes);
  head.assign(bytes, static_cast<std::size_t>(is.gcount()));
  const std::string_view h(head);
  auto starts_with = [&h](std::string_view s) { return h.substr(0, s.size()) == s; };

  if (starts_with("# vtk DataFile") || starts_with("# vtk datafile")) {
    // The dataset type follows the DATASET keyword of line 4 (after the title and the format).
    std::string upper(head);
    for (char& c : upper)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const std::size_t d = upper.find("DATASET");
    const std::string_view rest =
        d == std::string::npos ? std::string_view() : std::string_view(upper).substr(d + 7);
    const std::size_t b = rest.find_first_not_of(" \t\r\n");
    const std::string_view type = b == std::string_view::npos ? std::string_view() : rest.substr(b);
    if (type.substr(0, 17) == "STRUCTURED_POINTS")
      return Flow_field_file_kind::LEGACY_UNIFORM_GRID;
    if (type.substr(0, 16) == "RECTILINEAR_GRID")
      return Flow_field_file_kind::LEGACY_RECTILINEAR_GRID;
    return Flow_field_file_kind::LEGACY_CELLS;
  }
  if (starts_with("# AmiraMesh") || starts_with("# Avizo"))
    return Flow_field_file_kind::AMIRA_MESH;
  if (starts_with("NRRD000"))
    return Flow_field_file_kind::NRRD_FILE;
  // XML: a '<' first (after white space and a byte-order mark), then the VTKFile element.
  const std::size_t first = h.find_first_not_of(" \t\r\n\xef\xbb\xbf");
  const std::size_t x = h.find("<VTKFile");
  if (first != std::string_view::npos && h[first] == '<' && x != std::string_view::npos) {
    const std::size_t t = h.find("type=\"", x);
    if (t != std::string_view::npos && h.substr(t + 6, 10) == "ImageData\"")
      return Flow_field_file_kind::XML_IMAGE_DATA;
    if (t != std::string_view::npos && h.substr(t + 6, 16) == "RectilinearGrid\"")
      return Flow_field_file_kind::XML_RECTILINEAR_GRID;
    return Flow_field_file_kind::XML_CELLS;
  }
  return Flow_field_file_kind::UNKNOWN;
}

// Reads a `Field` with `read(Field&)` and assigns it to `field` on success only.
template <class Field, class Sampled, class Read>
bool read_as(Sampled& field, const Read& read)
{
  Field f;
  if (!read(f))
    return false;
  field = std::move(f);
  return true;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field from a file of any supported format into a
`Sampled_flow_field_3`, for programs that take whatever file their user has.

The format is told from the first bytes of the file, not from its name:

| the file starts with | format | read by | the field holds |
|---|---|---|---|
| `# vtk DataFile`, `DATASET STRUCTURED_POINTS` | legacy VTK | `read_VTK_flow_field()` | a `Regular_grid_flow_field_3` |
| `# vtk DataFile`, `DATASET RECTILINEAR_GRID` | legacy VTK | `read_VTK_flow_field()` | a `Rectilinear_grid_flow_field_3` |
| `# vtk DataFile`, `DATASET STRUCTURED_GRID` or `UNSTRUCTURED_GRID` | legacy VTK | `read_VTK_flow_field()` | an `Unstructured_flow_field_3` |
| `<VTKFile type="ImageData"` | VTK XML (`.vti`) | `read_VTK_XML_flow_field()` | a `Regular_grid_flow_field_3` |
| `<VTKFile type="RectilinearGrid"` | VTK XML (`.vtr`) | `read_VTK_XML_flow_field()` | a `Rectilinear_grid_flow_field_3` |
| `<VTKFile type="UnstructuredGrid"` or `"StructuredGrid"` | VTK XML (`.vtu`, `.vts`) | `read_VTK_XML_flow_field()` | an `Unstructured_flow_field_3` |
| `# AmiraMesh` or `# Avizo` | AmiraMesh (`.am`) | `read_AmiraMesh_flow_field()` | a `Regular_grid_flow_field_3` |
| `NRRD000` | NRRD (`.nrrd`, `.nhdr` + raw data) | `read_NRRD_flow_field()` | a `Regular_grid_flow_field_3` |

Every format is read by the package itself (VTK XML files too: no VTK library is needed).  Time
series (`.pvd`) are read by `read_PVD_flow_field()`.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters, passed on to the reader of the format:
`array_name`, `mask_array_name`, `use_parallelism` and `error_message` (see `read_VTK_flow_field()`)

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message`
when it is given: the one of the reader of the format, or, for a file of no supported format, a
message naming the file and its first bytes.

\sa `Sampled_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_flow_field(const std::string& filename, Sampled_flow_field_3<K>& field,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef Sampled_flow_field_3<K> Sampled;
  typedef typename Sampled::Regular_grid Regular;
  typedef typename Sampled::Rectilinear_grid Rectilinear;
  typedef typename Sampled::Unstructured_grid Cells;
  std::string head;
  switch (internal::flow_field_file_kind(filename, head)) {
  case internal::Flow_field_file_kind::LEGACY_UNIFORM_GRID:
    return internal::read_as<Regular>(field,
                                      [&](Regular& f) { return read_VTK_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::LEGACY_RECTILINEAR_GRID:
    return internal::read_as<Rectilinear>(
        field, [&](Rectilinear& f) { return read_VTK_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::LEGACY_CELLS:
    return internal::read_as<Cells>(field, [&](Cells& f) { return read_VTK_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::AMIRA_MESH:
    return internal::read_as<Regular>(field,
                                      [&](Regular& f) { return read_AmiraMesh_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::NRRD_FILE:
    return internal::read_as<Regular>(field,
                                      [&](Regular& f) { return read_NRRD_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::XML_IMAGE_DATA:
    return internal::read_as<Regular>(field,
                                      [&](Regular& f) { return read_VTK_XML_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::XML_RECTILINEAR_GRID:
    return internal::read_as<Rectilinear>(
        field, [&](Rectilinear& f) { return read_VTK_XML_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::XML_CELLS:
    return internal::read_as<Cells>(field,
                                    [&](Cells& f) { return read_VTK_XML_flow_field(filename, f, np); });
  case internal::Flow_field_file_kind::UNKNOWN:
    break;
  }
  if (std::string* const error = internal::error_output(np)) {
    std::ifstream probe(filename, std::ios::binary);
    std::error_code ec;
    // A directory opens as a stream that reads nothing: it would be called empty.
    if (std::filesystem::is_directory(filename, ec))
      *error = "read_flow_field: " + filename + ": is a directory, not a file";
    else if (!probe)
      *error = "read_flow_field: " + filename + ": cannot open the file for reading";
    else if (head.empty())
      *error = "read_flow_field: " + filename + ": the file is empty (0 bytes)";
    else
      *error = "read_flow_field: " + filename + ": unknown file format (it starts with '" +
               internal::printable(head.substr(0, 24)) +
               "'); expected a legacy VTK file ('# vtk DataFile'), a VTK XML file ('<VTKFile'), an "
               "AmiraMesh file ('# AmiraMesh') or a NRRD file ('NRRD000x')";
  }
  return false;
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_FLOW_FIELD_H
