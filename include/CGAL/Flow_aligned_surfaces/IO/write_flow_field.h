// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes a `Regular_grid_flow_field_3` as a legacy VTK file (`DATASET STRUCTURED_POINTS`,
// `VECTORS velocity float`, and the node mask as `SCALARS inside unsigned_char`), BINARY
// (big-endian) or ASCII, or as a VTK XML ImageData file (`.vti`: the same arrays as Float32 and
// UInt8, little-endian binary inline in base64), which ParaView, VisIt,
// `read_VTK_flow_field()` and `read_VTK_XML_flow_field()` open.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_FLOW_FIELD_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_FLOW_FIELD_H

#include <string>

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/base64_streambuf.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/error_output.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/write_file_atomically.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Writes 32-bit floats in the given byte order whatever the host's, in blocks to keep the
// number of stream calls small.
inline void write_float32s(std::ostream& os, const std::vector<float>& values, bool big_endian)
{
  std::vector<unsigned char> block;
  block.reserve(4 * 4096);
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::uint32_t u;
    std::memcpy(&u, &values[i], 4);
    for (int b = 0; b < 4; ++b)
      block.push_back(static_cast<unsigned char>(u >> (8 * (big_endian ? 3 - b : b))));
    if (block.size() == block.capacity() || i + 1 == values.size()) {
      os.write(reinterpret_cast<const char*>(block.data()), static_cast<std::streamsize>(block.size()));
      block.clear();
    }
  }
}

// The inline content of a binary VTK XML DataArray without compression: its size in bytes
// (UInt64, little-endian) and its bytes, written by `write_bytes`, all in one base64 stream.
template <class Write_bytes>
void write_VTK_XML_inline_array(std::ostream& os, std::uint64_t bytes, const Write_bytes& write_bytes)
{
  Base64_streambuf base64(os);
  std::ostream encoded(&base64);
  unsigned char size[8];
  for (int i = 0; i < 8; ++i)
    size[i] = static_cast<unsigned char>(bytes >> (8 * i));
  encoded.write(reinterpret_cast<const char*>(size), 8);
  write_bytes(encoded);
  encoded.flush();
  base64.finish();
}

// The mask as bytes 1 (fluid) and 0 (solid).
inline std::vector<unsigned char> mask_flags(const std::vector<unsigned char>& mask)
{
  std::vector<unsigned char> flags(mask.size());
  for (std::size_t v = 0; v < mask.size(); ++v)
    flags[v] = mask[v] != 0 ? 1 : 0;
  return flags;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Writes a grid flow field to `filename` as a legacy VTK file.

The file holds `DATASET STRUCTURED_POINTS` with the field's `DIMENSIONS`, `ORIGIN` and
`SPACING` (17 significant digits, so they read back exactly), `POINT_DATA` with the velocity as
`VECTORS velocity float` and, if the field has a mask, the mask as
`SCALARS inside unsigned_char` (1 = fluid, 0 = solid).  Binary files are big-endian, as VTK
reads them.  The file is first written beside `filename` and renamed over it only when
complete, so an existing file is never left half-written.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the output file
\param field the field to write
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{use_binary_mode}
    \cgalParamDescription{`CGAL::parameters::use_binary_mode()`: whether the values are written
      in binary (`BINARY`) or as text (`ASCII`)}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{stream_precision}
    \cgalParamDescription{the number of significant digits of ASCII velocity values}
    \cgalParamType{int}
    \cgalParamDefault{`9`, which reads back every 32-bit float exactly}
  \cgalParamNEnd
  \cgalParamNBegin{array_name}
    \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`)}
    \cgalParamType{`std::string` without white space}
    \cgalParamDefault{`"velocity"`}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{the name of the mask array (`FAS::parameters::mask_array_name()`)}
    \cgalParamType{`std::string` without white space}
    \cgalParamDefault{`"inside"`}
  \cgalParamNEnd
  \cgalParamNBegin{error_message}
    \cgalParamDescription{where the reason of a failure goes (`FAS::parameters::error_message()`)}
    \cgalParamType{`std::string*`}
    \cgalParamDefault{`nullptr`: no message}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success; `false` if an array name is empty or holds white space or the file
could not be written, with the reason in the string of `error_message` when it is given.

\sa `read_VTK_flow_field()`, `write_VTI_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool write_VTK_flow_field(const std::string& filename, const Regular_grid_flow_field_3<K>& field,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool binary = choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), true);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 9);
  const std::string velocity_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::array_name_t()), std::string("velocity"));
  const std::string mask_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::mask_array_name_t()), std::string("inside"));

  std::string* const error = internal::error_output(np);
  auto fail = [&](const std::string& reason) {
    if (error)
      *error = "write_VTK_flow_field: " + filename + ": " + reason;
    return false;
  };
  for (const std::string* name : {&velocity_name, &mask_name})
    if (name->empty() || name->find_first_of(" \t\r\n") != std::string::npos)
      return fail("the array name '" + *name +
                  "' is empty or holds white space, which legacy VTK cannot store");

  const auto& n = field.dimensions();
  const std::vector<float>& values = field.values();
  const std::vector<unsigned char>& mask = field.mask();

  std::string reason;
  const bool written =
      internal::write_file_atomically(filename, reason, [&](std::ostream& os) {
        os.precision(17);
        os << "# vtk DataFile Version 3.0\n"
           << "flow field written by CGAL Flow_aligned_surfaces\n"
           << (binary ? "BINARY\n" : "ASCII\n") << "DATASET STRUCTURED_POINTS\n"
           << "DIMENSIONS " << n[0] << ' ' << n[1] << ' ' << n[2] << '\n'
           << "ORIGIN " << CGAL::to_double(field.origin().x()) << ' ' << CGAL::to_double(field.origin().y())
           << ' ' << CGAL::to_double(field.origin().z()) << '\n'
           << "SPACING " << CGAL::to_double(field.spacing().x()) << ' '
           << CGAL::to_double(field.spacing().y()) << ' ' << CGAL::to_double(field.spacing().z()) << '\n'
           << "POINT_DATA " << field.number_of_nodes() << '\n'
           << "VECTORS " << velocity_name << " float\n";
        if (binary) {
          internal::write_float32s(os, values, true);
          os << '\n';
        }
        else {
          os.precision(precision);
          for (std::size_t v = 0; v < values.size(); v += 3)
            os << values[v] << ' ' << values[v + 1] << ' ' << values[v + 2] << '\n';
        }
        if (!mask.empty()) {
          os << "SCALARS " << mask_name << " unsigned_char 1\nLOOKUP_TABLE default\n";
          if (binary) {
            const std::vector<unsigned char> flags = internal::mask_flags(mask);
            os.write(reinterpret_cast<const char*>(flags.data()), static_cast<std::streamsize>(flags.size()));
            os << '\n';
          }
          else {
            for (std::size_t v = 0; v < mask.size(); ++v)
              os << (mask[v] != 0 ? '1' : '0') << ((v + 1) % n[0] == 0 ? '\n' : ' ');
          }
        }
      });
  return written ? true : fail(reason);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Writes a grid flow field to `filename` as a VTK XML ImageData file (`.vti`).

The file holds an `ImageData` with `WholeExtent` `0 nx-1 0 ny-1 0 nz-1` and the field's
`Origin` and `Spacing` (17 significant digits, so they read back exactly), one `Piece` whose
point data holds the velocity as a 3-component `Float32` array (the active vectors) and, if
the field has a mask, the mask as a `UInt8` array (1 = fluid, 0 = solid).  The arrays are
stored inline in base64, little-endian (`format="binary"`, `header_type="UInt64"`: each array
is preceded by its size in bytes), without compression.  Every VTK reads this form, also
ParaView 5.11 on an up-to-date Debian bookworm, whose VTK cannot parse appended data with the
current expat (the manual's ParaView pages say more).  The file is first written beside `filename` and renamed over it
only when complete, so an existing file is never left half-written.  VTK is not needed.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the output file
\param field the field to write
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{array_name}
    \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`)}
    \cgalParamType{`std::string`, not empty}
    \cgalParamDefault{`"velocity"`}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{the name of the mask array (`FAS::parameters::mask_array_name()`)}
    \cgalParamType{`std::string`, not empty}
    \cgalParamDefault{`"inside"`}
  \cgalParamNEnd
  \cgalParamNBegin{error_message}
    \cgalParamDescription{where the reason of a failure goes (`FAS::parameters::error_message()`)}
    \cgalParamType{`std::string*`}
    \cgalParamDefault{`nullptr`: no message}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success; `false` if an array name is empty or the two names are equal, or the
file could not be written, with the reason in the string of `error_message` when it is given.

\sa `read_VTK_XML_flow_field()`, `write_VTK_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool write_VTI_flow_field(const std::string& filename, const Regular_grid_flow_field_3<K>& field,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::string velocity_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::array_name_t()), std::string("velocity"));
  const std::string mask_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::mask_array_name_t()), std::string("inside"));

  std::string* const error = internal::error_output(np);
  auto fail = [&](const std::string& reason) {
    if (error)
      *error = "write_VTI_flow_field: " + filename + ": " + reason;
    return false;
  };
  const std::vector<unsigned char>& mask = field.mask();
  if (velocity_name.empty() || mask_name.empty())
    return fail("an array name is empty; VTK selects arrays by name");
  if (!mask.empty() && velocity_name == mask_name)
    return fail("the velocity and the mask arrays are both named '" + velocity_name + "'");

  // Names are free text in XML attributes: escape the five special characters.
  auto escaped = [](const std::string& s) {
    std::string r;
    for (char c : s) {
      switch (c) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '>':
        r += "&gt;";
        break;
      case '"':
        r += "&quot;";
        break;
      case '\'':
        r += "&apos;";
        break;
      default:
        r += c;
      }
    }
    return r;
  };
  const auto& n = field.dimensions();
  const std::vector<float>& values = field.values();

  std::string reason;
  const bool written =
      internal::write_file_atomically(filename, reason, [&](std::ostream& os) {
        os.precision(17);
        const std::string extent = "0 " + std::to_string(n[0] - 1) + " 0 " + std::to_string(n[1] - 1) +
                                   " 0 " + std::to_string(n[2] - 1);
        os << "<?xml version=\"1.0\"?>\n"
           << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
              "header_type=\"UInt64\">\n"
           << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << CGAL::to_double(field.origin().x())
           << ' ' << CGAL::to_double(field.origin().y()) << ' ' << CGAL::to_double(field.origin().z())
           << "\" Spacing=\"" << CGAL::to_double(field.spacing().x()) << ' '
           << CGAL::to_double(field.spacing().y()) << ' ' << CGAL::to_double(field.spacing().z()) << "\">\n"
           << "    <Piece Extent=\"" << extent << "\">\n"
           << "      <PointData Vectors=\"" << escaped(velocity_name) << '"';
        if (!mask.empty())
          os << " Scalars=\"" << escaped(mask_name) << '"';
        os << ">\n"
           << "        <DataArray type=\"Float32\" Name=\"" << escaped(velocity_name)
           << "\" NumberOfComponents=\"3\" format=\"binary\">\n          ";
        internal::write_VTK_XML_inline_array(os, 4 * static_cast<std::uint64_t>(values.size()),
                                             [&](std::ostream& bytes) { internal::write_float32s(bytes, values, false); });
        os << "\n        </DataArray>\n";
        if (!mask.empty()) {
          const std::vector<unsigned char> flags = internal::mask_flags(mask);
          os << "        <DataArray type=\"UInt8\" Name=\"" << escaped(mask_name)
             << "\" NumberOfComponents=\"1\" format=\"binary\">\n          ";
          internal::write_VTK_XML_inline_array(os, flags.size(), [&](std::ostream& bytes) {
            bytes.write(reinterpret_cast<const char*>(flags.data()), static_cast<std::streamsize>(flags.size()));
          });
          os << "\n        </DataArray>\n";
        }
        os << "      </PointData>\n"
           << "      <CellData>\n      </CellData>\n"
           << "    </Piece>\n"
           << "  </ImageData>\n"
           << "</VTKFile>\n";
      });
  return written ? true : fail(reason);
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_FLOW_FIELD_H
