// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK_VOXEL (type 11), the axis-aligned hexahedron of VTK's image cells (what vtkThreshold or
// vtkExtractCells make of a vtkImageData), numbers its eight points with x fastest, then y,
// then z.  VTK_HEXAHEDRON (type 12) goes around each face instead: voxel points 0 1 3 2 4 5 7 6
// are hexahedron points 0 1 2 3 4 5 6 7.  The VTK readers store a voxel as that hexahedron, so
// `Unstructured_flow_field_3` interpolates it trilinearly like any other hexahedron.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_VOXELS_AS_HEXAHEDRA_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_VOXELS_AS_HEXAHEDRA_H

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

constexpr unsigned char vtk_voxel_type = 11, vtk_hexahedron_type = 12;

/// Rewrites every cell of type 11 as a hexahedron (type 12) in place.  A voxel without 8
/// points (a malformed file) becomes a hexahedron with its points as they are, for
/// `Unstructured_flow_field_3`'s constructor to refuse with the cell's point count.
/// \pre `offsets` has one more entry than `cell_types`, nondecreasing, within `connectivity`.
template <class Index>
void voxels_as_hexahedra(std::vector<unsigned char>& cell_types, const std::vector<Index>& offsets,
                         std::vector<Index>& connectivity)
{
  for (std::size_t c = 0; c < cell_types.size(); ++c) {
    if (cell_types[c] != vtk_voxel_type)
      continue;
    cell_types[c] = vtk_hexahedron_type;
    if (offsets[c + 1] - offsets[c] != 8)
      continue;
    Index* p = connectivity.data() + offsets[c];
    std::swap(p[2], p[3]);
    std::swap(p[6], p[7]);
  }
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_VOXELS_AS_HEXAHEDRA_H
