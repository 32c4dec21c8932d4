// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a velocity field from a legacy VTK file (`.vtk`, ASCII or BINARY) with DATASET
// STRUCTURED_POINTS, RECTILINEAR_GRID, STRUCTURED_GRID or UNSTRUCTURED_GRID: the nodes (a uniform
// grid origin + (i hx, j hy, k hz), per-axis coordinates (X_i, Y_j, Z_k), or listed points), the
// cells of an unstructured grid (point indices and VTK types), a 3-component point data array
// (the velocity, 3 numbers per node) and optionally a 1-component array (the node mask, one
// number per node).  The functions users call; the parser (two passes over the file's bytes,
// no count trusted before it is checked against them) is in `IO/VTK_legacy/`.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_legacy/VTK_legacy_fields.h>
#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a legacy VTK file.

The file must be a legacy VTK file (`# vtk DataFile Version x.x`), ASCII or BINARY (big-endian,
as VTK writes it), with `DATASET STRUCTURED_POINTS` (`DIMENSIONS`, `ORIGIN`, `SPACING`, or its
older synonym `ASPECT_RATIO`; at least 2 nodes along each axis).  The other dataset types are
refused with a message naming the field type that reads them (`Rectilinear_grid_flow_field_3`
for `RECTILINEAR_GRID`, `Unstructured_flow_field_3` for all).  The velocity is a
3-component `POINT_DATA` array: `VECTORS`, `NORMALS`, a 3-component `SCALARS` or a
3-component `FIELD` array, of any numeric type (stored as 32-bit floats).  The node mask is a
1-component `POINT_DATA` array of any numeric type, nonzero = fluid.  Every other array and
every `CELL_DATA` section is skipped, and so are the `METADATA` blocks that VTK 9 writes.

Bad input never crashes, hangs or allocates more than the file's size: a truncated file,
counts that do not match `DIMENSIONS`, unknown or unsupported dataset types, non-numeric tokens,
missing arrays, a mask that is not one number per node, an empty grid, or a NaN or infinite
velocity at a fluid node make the function return `false` with a message that names the file,
the line and/or byte offset, and what is wrong (the node index for bad values; the arrays
present for a missing one).  Non-finite values at solid nodes are accepted and stored as zero,
as in `Regular_grid_flow_field_3`.

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
    \cgalParamDefault{the first `VECTORS` array of the point data, else its first 3-component array}
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

\sa `write_VTK_flow_field()`, `Regular_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_legacy(filename, field, np, &internal::read_VTK_legacy_grid<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a rectilinear grid from a legacy VTK file.

As the `Regular_grid_flow_field_3` overload, for `DATASET RECTILINEAR_GRID` (`DIMENSIONS`, then
`X_COORDINATES nx type`, `Y_COORDINATES ny type`, `Z_COORDINATES nz type`, each count equal to
the matching dimension and the coordinates strictly increasing) and for `DATASET
STRUCTURED_POINTS` (its nodes `origin + i·spacing` along each axis).  The velocity and mask
arrays, the named parameters and the messages are those of that overload; a coordinate that is
not finite or not increasing is named with its axis and index.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name`, `use_parallelism`
          and `error_message`, as in the `Regular_grid_flow_field_3` overload

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message` when it is given.

\sa `Rectilinear_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, Rectilinear_grid_flow_field_3<K>& field,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_legacy(filename, field, np, &internal::read_VTK_legacy_rectilinear<K>);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on the cells of any legacy VTK dataset with volume cells.

- `DATASET UNSTRUCTURED_GRID`: `POINTS n type`, then `CELLS` in either form: the legacy one
  (file versions up to 5.0: `CELLS n size`, then per cell its number of points and their
  indices) or the one of file version 5.1 (`CELLS n+1 size`, `OFFSETS type` with `n + 1`
  values, `CONNECTIVITY type` with `size` values), and `CELL_TYPES n`.  The cell types must
  be 10 (tetrahedron), 12 (hexahedron), 13 (wedge) or 14 (pyramid), with VTK's point orders
  (see `Unstructured_flow_field_3`), or 11 (voxel: read as the same hexahedron, its points
  0 1 3 2 4 5 7 6).
- `DATASET STRUCTURED_GRID` (`DIMENSIONS`, `POINTS`), `RECTILINEAR_GRID` and
  `STRUCTURED_POINTS`: their grid cells become hexahedra, cell `(i, j, k)` with the points
  `(i, j, k)`, `(i+1, j, k)`, `(i+1, j+1, k)`, `(i, j+1, k)` and the same at `k + 1`, whose
  isoparametric interpolation is the trilinear one of the grid.

The velocity and mask arrays, the named parameters, and the messages for bad input are those
of the `Regular_grid_flow_field_3` overload; besides, a cell of another type gives a message
naming the cell's index and its type, a point index out of range names the cell and the
value, and counts that do not match (`CELLS` and `CELL_TYPES`, the number of values a cell
list holds, `POINTS` and `DIMENSIONS`) give both numbers.  A **node mask removes every cell
that touches a solid point**: the same rule as the grid fields: the interior of a cell
touching a solid node is outside, and the faces that a kept cell shares with a removed one are
inside (they belong to the kept cell).  Solid points may have non-finite values (stored as
zero); every other point must have a finite velocity.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters: `array_name`, `mask_array_name`, `use_parallelism`
          and `error_message`, as in the `Regular_grid_flow_field_3` overload

\returns `true` on success; `false` otherwise, with the reason in the string of `error_message` when it is given.

\sa `Unstructured_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_VTK_flow_field(const std::string& filename, Unstructured_flow_field_3<K>& field,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::read_VTK_legacy(filename, field, np, &internal::read_VTK_legacy_cells<K>);
}

} // namespace IO

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_VTK_LEGACY_H
