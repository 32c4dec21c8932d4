// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a velocity field on a uniform grid from a NRRD file (`.nrrd` with the data attached,
// or a `.nhdr` text header beside a raw data file): a 4-dimensional array of sizes
// 3 × nx × ny × nz (the vector axis first, then x fastest), whose sample (c, i, j, k) is the
// component c of the velocity at the node  origin + i·d_x + j·d_y + k·d_z,  where the origin
// is `space origin` and the axis-aligned steps d_a come from `space directions` or `spacings`.
// The functions users call; the parser (the header read first and every size checked against
// the bytes of the data before anything is allocated, then the values decoded) is in `IO/NRRD/`.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_NRRD_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_NRRD_H

#include <CGAL/Flow_aligned_surfaces/IO/NRRD/NRRD_grid.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/reader_support.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads a velocity field on a uniform grid from a NRRD file (`.nrrd`, or a `.nhdr` header
with its data in another file), the way to read raw float32 files.

The file starts with `NRRD0001` to `NRRD0005`; the header holds `type` (any numeric NRRD type:
`int8` … `uint64`, `float`, `double` and their synonyms), `dimension: 4` and
`sizes: 3 nx ny nz` (the vector axis first, then x fastest; at least 2 nodes along each axis;
`kinds`, if given, must be `vector` (or `3-vector`, ...) then `domain domain domain`),
`encoding` (`raw`, `ascii`/`text`, and `gzip` when zlib is available:
`CGAL_FLOW_ALIGNED_SURFACES_USE_ZLIB` defined and zlib linked; other compressed encodings get
an "unsupported" message),
`endian` (required for raw and gzip multi-byte types), `byte skip` (`-1` = the data are the end of the
file), `line skip`, `data file` (relative to the header's folder; one file only), and the
geometry: `spacings: nan hx hy hz` or `space directions: none (hx,0,0) (0,hy,0) (0,0,hz)`
(axis-aligned with positive steps only: a rotated, sheared, permuted or mirrored frame gets an
"unsupported" message; default spacing 1), and `space origin: (x,y,z)` (default 0).  Node
`(i, j, k)` is at `origin + (i·hx, j·hy, k·hz)`: NRRD's origin is the first sample whatever the
`centers`, so cell-centered samples are taken as the nodes of the grid.

A raw file of float32 values `vx vy vz` per node (x fastest), 64 × 32 × 16 nodes, little-endian,
is read through this header beside it (`field.nhdr`):
\code
NRRD0004
type: float
dimension: 4
sizes: 3 64 32 16
spacings: nan 0.1 0.1 0.2
space origin: (0,0,-1.5)
endian: little
encoding: raw
data file: field.raw
\endcode

A NRRD file holds one array and no mask: `mask_array_name` (non-empty) is an error;
`array_name`, if given, must match the `content` field when the file has one.

Bad input never crashes, hangs or allocates more than the file's size: a truncated file, sizes
that do not match the data, non-numeric tokens, unknown types, a NaN or infinite velocity make
the function return `false` with a message that names the file, the line and/or byte, and what
is wrong.

\tparam K a model of `Kernel`
\tparam NamedParameters a sequence of named parameters

\param filename the file to read
\param field the field to fill, for instance a default-constructed (empty) one: assigned on
       success, left untouched on failure
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{array_name}
    \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`), checked
      against the `content` field}
    \cgalParamType{`std::string`}
    \cgalParamDefault{the file's array}
  \cgalParamNEnd
  \cgalParamNBegin{mask_array_name}
    \cgalParamDescription{not supported: NRRD files have no mask; a non-empty name is an error}
    \cgalParamType{`std::string`}
    \cgalParamDefault{no mask}
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

\sa `read_VTK_flow_field()`, `read_AmiraMesh_flow_field()`, `Regular_grid_flow_field_3`
*/
template <class K, class NamedParameters = parameters::Default_named_parameters>
bool read_NRRD_flow_field(const std::string& filename, Regular_grid_flow_field_3<K>& field,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Array_names names = internal::array_names(np);
  return internal::read_into("read_NRRD_flow_field", filename, field, np,
                             [&] { return internal::read_NRRD_grid<K>(filename, names.array, names.mask); });
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_NRRD_H
