// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a velocity field on a uniform grid from an AmiraMesh file (`.am`, written by Amira and
// Avizo, the format in which many public flow data sets are shared): a lattice of nx × ny × nz
// nodes whose bounding box [xmin, xmax] × [ymin, ymax] × [zmin, zmax] holds the first and the
// last node, so node (i, j, k) is at (xmin + i·hx, ymin + j·hy, zmin + k·hz) with
// hx = (xmax − xmin)/(nx − 1) (and so on); a 3-component lattice field (the velocity) and
// optionally a 1-component one (the node mask).  The functions users call; the parser (two
// passes over the file's bytes: the first reads the header and locates every data section,
// checking each size against the bytes left without allocating; the second decodes the two
// chosen fields) is in `IO/AmiraMesh/`.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_AMIRAMESH_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_AMIRAMESH_H

#include <CGAL/Flow_aligned_surfaces/IO/AmiraMesh/AmiraMesh_grid.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from an AmiraMesh file (`.am`, Amira and Avizo).

The first line is `# AmiraMesh BINARY-LITTLE-ENDIAN 2.1`, `# AmiraMesh 3D BINARY 2.0`
(big-endian), `# AmiraMesh 3D ASCII 2.0`, or the same with `Avizo` for `AmiraMesh`.  The header
must have `define Lattice nx ny nz` (at least 2 nodes along each axis) and a `Parameters`
block with `BoundingBox xmin xmax ymin ymax zmin zmax`, the positions of the first and the last
node: node `(i, j, k)` is at `(xmin + i·hx, ymin + j·hy, zmin + k·hz)` with
`hx = (xmax − xmin)/(nx − 1)` and so on.  `CoordType` must be `"uniform"` (or absent); every
other parameter, nested blocks included, is skipped.  The fields are declared as
`Lattice { float[3] Data } @1`, of type `byte`, `sbyte`, `short`, `ushort`, `int`, `uint`,
`int64`, `uint64`, `float` or `double` with 1 to 1024 components, and stored after the
`# Data section follows` line in `@N` sections (x fastest, components interleaved).  Sections
compressed with `HxByteRLE` are read, and those compressed with `HxZip` too when zlib is
available (`CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB` defined and zlib linked; else an
"unsupported" message).
Declarations on other locations than `Lattice` are skipped.

The velocity is the lattice field named by `array_name`, by default the first 3-component
one; the mask is the 1-component lattice field named by `mask_array_name` (nonzero = fluid).

Bad input never crashes, hangs or allocates more than the file's size: a truncated file, a
missing data section, sizes that do not match the bytes, non-numeric tokens, unknown types, a
NaN or infinite velocity at a fluid node make the function return `false` with a message that
names the file, the line and/or byte, and what is wrong.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{array_name}
    \cgalParamDescription{the name of the velocity field (`FAS::parameters::array_name()`)}
    \cgalParamType{`std::string`}
    \cgalParamDefault{the first 3-component lattice field}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{the name of the node mask field (`FAS::parameters::mask_array_name()`);
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

\sa `read_VTK_flow_field()`, `read_NRRD_flow_field()`, `Regular_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_AmiraMesh_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Array_names names = internal::array_names(np);
  return internal::read_into("read_AmiraMesh_flow_field", filename, field, np, [&] {
    return internal::read_AmiraMesh_grid<K>(filename, names.array, names.mask);
  });
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_AMIRAMESH_H
