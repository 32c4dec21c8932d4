// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads velocity fields from VTK XML files through the VTK library (9.x): an ImageData file
// (.vti, a uniform grid of nx × ny × nz points) into a `Regular_grid_flow_field_3`, and an
// UnstructuredGrid (.vtu), StructuredGrid (.vts) or ImageData file into an
// `Unstructured_flow_field_3` (a curvilinear or uniform grid as its (nx-1)(ny-1)(nz-1)
// hexahedra); and a ParaView data collection (.pvd: steps t_0 ... t_n, one file each) into an
// `Unsteady_flow_field_3`.  The velocity is a 3-component point array, the optional mask a
// 1-component point array (nonzero = fluid).  The functions users call; running VTK's readers
// safely (checks before VTK reads, its messages captured, never printed) and building the
// fields is in `IO/VTK_XML/`.
//
// Needs VTK: link the target CGAL::Flow_aligned_surfaces_VTK.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/VTK_XML_fields.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
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
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
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
  \cgalParamNBegin{use_parallelism}
    \cgalParamDescription{decode binary arrays on the threads of the caller's TBB arena
      (`FAS::parameters::use_parallelism()`); without it the reader starts no thread}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
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
  const Flow_aligned_surfaces::IO::internal::Array_names names = Flow_aligned_surfaces::IO::internal::array_names(np);
  const internal::VTK_XML_context c{"read_VTK_XML_flow_field", filename};
  return Flow_aligned_surfaces::IO::internal::read_into(c.reader, filename, field, error,
      Flow_aligned_surfaces::IO::internal::reads_in_parallel(np), [&] {
    return internal::read_VTK_XML_grid<K>(c, names.array_name(), names.mask_name());
  });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief As the overload above with the default named parameters: the reason of a failure is in
`error` without naming `CGAL::parameters::default_values()` first, as in
`read_VTK_XML_flow_field(filename, field, &error)`.
*/
template <class K>
bool read_VTK_XML_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field, std::string* error)
{
  return read_VTK_XML_flow_field(filename, field, CGAL::parameters::default_values(), error);
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
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name` and `use_parallelism`, as for
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
  const Flow_aligned_surfaces::IO::internal::Array_names names =
      Flow_aligned_surfaces::IO::internal::array_names(np);
  const internal::VTK_XML_context c{"read_VTK_XML_flow_field", filename};
  return Flow_aligned_surfaces::IO::internal::read_into(c.reader, filename, field, error,
      Flow_aligned_surfaces::IO::internal::reads_in_parallel(np), [&] {
    return internal::read_VTK_XML_cells<K>(c, names.array_name(), names.mask_name());
  });
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief As the overload above with the default named parameters: the reason of a failure is in
`error` without naming `CGAL::parameters::default_values()` first, as in
`read_VTK_XML_flow_field(filename, field, &error)`.
*/
template <class K>
bool read_VTK_XML_flow_field(const std::string& filename, Unstructured_flow_field_3<K>& field, std::string* error)
{
  return read_VTK_XML_flow_field(filename, field, CGAL::parameters::default_values(), error);
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
\param field the series to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name` and `use_parallelism`, as for
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
  const Flow_aligned_surfaces::IO::internal::Array_names names = Flow_aligned_surfaces::IO::internal::array_names(np);
  const internal::VTK_XML_context c{"read_PVD_flow_field", filename};
  return Flow_aligned_surfaces::IO::internal::read_into(c.reader, filename, field, error,
      Flow_aligned_surfaces::IO::internal::reads_in_parallel(np), [&] {
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

\brief As the overload above with the default named parameters: the reason of a failure is in
`error` without naming `CGAL::parameters::default_values()` first, as in
`read_PVD_flow_field(filename, field, &error)`.
*/
template <class Field>
bool read_PVD_flow_field(const std::string& filename, Unsteady_flow_field_3<Field>& field, std::string* error)
{
  return read_PVD_flow_field(filename, field, CGAL::parameters::default_values(), error);
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_XML_H
