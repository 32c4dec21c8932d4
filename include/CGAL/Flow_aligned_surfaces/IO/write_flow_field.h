// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes a `Regular_grid_flow_field_3` as a legacy VTK file (`DATASET STRUCTURED_POINTS`,
// `VECTORS velocity float`, and the node mask as `SCALARS inside unsigned_char`), BINARY
// (big-endian) or ASCII, which ParaView, VisIt and `read_VTK_flow_field()` open.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_FLOW_FIELD_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_FLOW_FIELD_H

#include <string>

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/write_file_atomically.h>
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
\param error if not null, receives the reason of a failure

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
\cgalNamedParamsEnd

\returns `true` on success; `false` if an array name is empty or holds white space or the file
could not be written, with the reason in `error` when it is not null.

\sa `read_VTK_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool write_VTK_flow_field(const std::string& filename, const Regular_grid_flow_field_3<K>& field,
                          const NamedParameters& np = CGAL::parameters::default_values(),
                          std::string* error = nullptr)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool binary = choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), true);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 9);
  const std::string velocity_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::array_name_t()), std::string("velocity"));
  const std::string mask_name = choose_parameter(
      get_parameter(np, Flow_aligned_surfaces::internal_np::mask_array_name_t()), std::string("inside"));

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
      Flow_aligned_surfaces::internal::write_file_atomically(filename, reason, [&](std::ostream& os) {
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
          // Big-endian whatever the host, in blocks to keep the number of stream calls small.
          std::vector<unsigned char> block;
          block.reserve(4 * 4096);
          for (std::size_t i = 0; i < values.size(); ++i) {
            std::uint32_t u;
            std::memcpy(&u, &values[i], 4);
            for (int b = 3; b >= 0; --b)
              block.push_back(static_cast<unsigned char>(u >> (8 * b)));
            if (block.size() == block.capacity() || i + 1 == values.size()) {
              os.write(reinterpret_cast<const char*>(block.data()),
                       static_cast<std::streamsize>(block.size()));
              block.clear();
            }
          }
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
            std::vector<unsigned char> flags(mask.size());
            for (std::size_t v = 0; v < mask.size(); ++v)
              flags[v] = mask[v] != 0 ? 1 : 0;
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

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_FLOW_FIELD_H
