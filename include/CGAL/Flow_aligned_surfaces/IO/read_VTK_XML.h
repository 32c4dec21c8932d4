// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads velocity fields from VTK XML files, without the VTK library: an ImageData file (.vti, a
// uniform grid of nx × ny × nz points) into a `Regular_grid_flow_field_3`, a RectilinearGrid
// file (.vtr) into a `Rectilinear_grid_flow_field_3`, and an UnstructuredGrid (.vtu),
// StructuredGrid (.vts), RectilinearGrid or ImageData file into an `Unstructured_flow_field_3`
// (a structured grid as its (nx-1)(ny-1)(nz-1) hexahedra); and a ParaView data collection (.pvd:
// steps t_0 ... t_n, one file each) into an `Unsteady_flow_field_3`.  The velocity is a
// 3-component point array, the optional mask a 1-component point array (nonzero = fluid).  The
// functions users call; the XML parser, the decoders of every encoding VTK writes and the
// fields built from them are in `IO/VTK_XML/`.
//
// Compressed arrays need zlib, liblz4 or liblzma (vtkZLibDataCompressor, vtkLZ4DataCompressor,
// vtkLZMADataCompressor), which the CMake target CGAL::Flow_aligned_surfaces links when found.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/PVD_steps.h>
#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/VTK_XML_fields.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

namespace internal {

// The public readers' common part: the named parameters, and the errors made `false` + message
// with `field` untouched.
template <class Field, class NamedParameters, class Read>
bool read_VTK_XML(const char* reader, const std::string& filename, Field& field, const NamedParameters& np,
                  const Read& read)
{
  const Array_names names = array_names(np);
  return read_into(reader, filename, field, np, [&] { return read(names.array_name(), names.mask_name()); });
}

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a VTK XML ImageData file (`.vti`).

The file is parsed by the package itself (no VTK library is needed).  The image must have one
piece, at least 2 points along each axis and no rotation (a `Direction` matrix other than the
identity is refused); its first point is the grid's origin, whatever the extent.  The velocity
is a 3-component point data array of any numeric type (stored as 32-bit floats), the node mask a
1-component point data array, nonzero = fluid.  Every encoding VTK writes is read: `ascii`,
inline `binary` (base64) and `appended` (raw or base64) data, 32- or 64-bit headers, either
byte order, uncompressed or compressed with zlib, LZ4 or LZMA (each when the package was built
with the library: the CMake target `CGAL::Flow_aligned_surfaces` links the ones it finds;
without one, such a file is refused with a message saying so).

Bad input never crashes, prints or allocates more than the file can hold: a missing or
unreadable file, malformed XML, a file of another kind, several pieces, sizes or compression
headers that the bytes do not hold (truncated files, lying headers), bad base64 or compressed
data, missing arrays (the message lists the arrays present), wrong numbers of components, a
rotated or flat image, or a NaN or infinite velocity at a fluid point (the message gives the
point's index) make the function return `false` with a message that names the file, the byte
(and line) where it applies and what is wrong.  Non-finite values at solid points are accepted
and stored as zero.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters among the ones listed below

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
  \cgalParamNBegin{use_parallelism}
    \cgalParamDescription{decode binary arrays on the threads of the caller's TBB arena
      (`FAS::parameters::use_parallelism()`); without it the reader starts no thread}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{error_message}
    \cgalParamDescription{where the reason of a failure goes (`FAS::parameters::error_message()`):
      a message naming the reader, the file, the line and/or byte, and what is wrong}
    \cgalParamType{`std::string*`}
    \cgalParamDefault{`nullptr`: no message}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message` when it is given.

\sa `write_VTI_flow_field()`, `read_VTK_flow_field()`, `read_PVD_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_XML("read_VTK_XML_flow_field", filename, field, np,
                                [&](const std::string* a, const std::string* m) {
                                  return internal::read_VTK_XML_grid<K>(filename, a, m);
                                });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a rectilinear grid from a VTK XML RectilinearGrid file (`.vtr`)
or ImageData file (`.vti`).

The grid's nodes are the `Coordinates` of the file (x, y and z, each increasing), or those of
the image.  Everything else (one piece, arrays, encodings, named parameters, bad input) is as
for the overload reading a `Regular_grid_flow_field_3`.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill: assigned on success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name`,
       `use_parallelism` and `error_message`, as for the overload reading a `Regular_grid_flow_field_3`

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message` when it is given.

\sa `Rectilinear_grid_flow_field_3`, `read_VTK_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, Rectilinear_grid_flow_field_3<K>& field,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_XML("read_VTK_XML_flow_field", filename, field, np,
                                [&](const std::string* a, const std::string* m) {
                                  return internal::read_VTK_XML_rectilinear<K>(filename, a, m);
                                });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on cells from a VTK XML UnstructuredGrid (`.vtu`), StructuredGrid
(`.vts`), RectilinearGrid (`.vtr`) or ImageData (`.vti`) file.

The kind of file is told by its contents, not its name.  An unstructured grid may hold
tetrahedra, hexahedra, wedges and pyramids (VTK cell types 10, 12, 13, 14) and voxels (type 11,
read as the same hexahedra, points 0 1 3 2 4 5 7 6); any other type is refused with the cell's
index and type, and so is a cell whose offsets give it the wrong number of points or a point
index outside the points.  A structured grid, rectilinear grid or image (without rotation)
becomes its hexahedra, point `(i, j, k)` being point `i + nx (j + ny k)`.  The velocity and the
mask are chosen as for the overload reading a `Regular_grid_flow_field_3`; with a mask, every
cell touching a solid point (mask value 0) is left out of the field.  Bad input is reported as
there, and also a grid without cells or without any cell whose points are all fluid.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name`, `use_parallelism` and
       `error_message`, as for the overload reading a `Regular_grid_flow_field_3`

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message` when it is given.

\sa `Unstructured_flow_field_3`, `read_PVD_flow_field()`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_XML_flow_field(const std::string& filename, Unstructured_flow_field_3<K>& field,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_XML("read_VTK_XML_flow_field", filename, field, np,
                                [&](const std::string* a, const std::string* m) {
                                  return internal::read_VTK_XML_cells<K>(filename, a, m);
                                });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a time series of flow fields from a ParaView data collection (`.pvd`).

The collection is parsed by the package itself: its `DataSet` elements each give a `timestep`
and a `file`, relative to the folder of the `.pvd` file unless absolute.  Every step is read
with `read_VTK_XML_flow_field()` into a `Field` (with the same named parameters) and the steps
are sorted by time.  A collection that cannot be parsed, has no step, a step without a time or
file, two steps with the same time, or a step that cannot be read makes the function return
`false` with a message naming the `.pvd` file, the step (its index after sorting, its time and
its file) and the reason given by the step's reader.

\tparam Field `Regular_grid_flow_field_3<K>`, `Rectilinear_grid_flow_field_3<K>` or
        `Unstructured_flow_field_3<K>`
\tparam NamedParameters a sequence of named parameters

\param filename the `.pvd` file to read
\param field the series to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name`, `use_parallelism` and
       `error_message`, as for `read_VTK_XML_flow_field()`

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message` when it is given.

\sa `Unsteady_flow_field_3`, `read_VTK_XML_flow_field()`
*/
template <class Field, class NamedParameters = parameters::Default_named_parameters>
bool read_PVD_flow_field(const std::string& filename, Unsteady_flow_field_3<Field>& field,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_XML(
      "read_PVD_flow_field", filename, field, np, [&](const std::string* a, const std::string* m) {
        const std::vector<internal::PVD_step> steps =
            internal::read_PVD_steps("read_PVD_flow_field", filename);
        std::vector<double> times;
        std::vector<Field> fields;
        times.reserve(steps.size());
        fields.reserve(steps.size());
        for (std::size_t i = 0; i < steps.size(); ++i) {
          try {
            fields.push_back(internal::VTK_XML_field_reader<Field>::read(steps[i].file, a, m));
          } catch (const internal::Read_error& e) {
            throw internal::Read_error("read_PVD_flow_field: " + filename + ": step " + std::to_string(i) +
                                       " (timestep " + internal::number_string(steps[i].time) + ", file " +
                                       steps[i].file + "): " + e.what());
          }
          times.push_back(steps[i].time);
        }
        return Unsteady_flow_field_3<Field>(std::move(times), std::move(fields));
      });
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H
