// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The VTK cell types by number, as the legacy and XML readers name them in messages, with the
// number of points of the linear 3D cells that `Unstructured_flow_field_3` holds.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_VTK_CELL_TYPES_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_VTK_CELL_TYPES_H

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

// The VTK cell type names, for messages; the number of points of the supported ones (else 0).
inline const char* vtk_cell_type_name(double t, int* points = nullptr)
{
  static const struct {
    int type, points;
    const char* name;
  } table[] = {{1, 0, "VTK_VERTEX"},
               {2, 0, "VTK_POLY_VERTEX"},
               {3, 0, "VTK_LINE"},
               {4, 0, "VTK_POLY_LINE"},
               {5, 0, "VTK_TRIANGLE"},
               {6, 0, "VTK_TRIANGLE_STRIP"},
               {7, 0, "VTK_POLYGON"},
               {8, 0, "VTK_PIXEL"},
               {9, 0, "VTK_QUAD"},
               {10, 4, "VTK_TETRA"},
               {11, 8, "VTK_VOXEL"},
               {12, 8, "VTK_HEXAHEDRON"},
               {13, 6, "VTK_WEDGE"},
               {14, 5, "VTK_PYRAMID"},
               {15, 0, "VTK_PENTAGONAL_PRISM"},
               {16, 0, "VTK_HEXAGONAL_PRISM"},
               {21, 0, "VTK_QUADRATIC_EDGE"},
               {22, 0, "VTK_QUADRATIC_TRIANGLE"},
               {23, 0, "VTK_QUADRATIC_QUAD"},
               {24, 0, "VTK_QUADRATIC_TETRA"},
               {25, 0, "VTK_QUADRATIC_HEXAHEDRON"},
               {26, 0, "VTK_QUADRATIC_WEDGE"},
               {27, 0, "VTK_QUADRATIC_PYRAMID"},
               {42, 0, "VTK_POLYHEDRON"}};
  for (const auto& e : table)
    if (t == e.type) {
      if (points != nullptr)
        *points = e.points;
      return e.name;
    }
  if (points != nullptr)
    *points = 0;
  return "not a linear 3D cell type this reader knows";
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_VTK_CELL_TYPES_H
