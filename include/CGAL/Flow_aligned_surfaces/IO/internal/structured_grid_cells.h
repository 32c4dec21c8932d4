// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells of a structured (curvilinear) grid of nx × ny × nz points, point (i, j, k) at index
// i + nx (j + ny k) as VTK orders them, written as the VTK_HEXAHEDRON cells of an unstructured
// grid: cell (i, j, k) is
//   (i,j,k) (i+1,j,k) (i+1,j+1,k) (i,j+1,k)  (i,j,k+1) (i+1,j,k+1) (i+1,j+1,k+1) (i,j+1,k+1),
// VTK's hexahedron order.  Readers of STRUCTURED_GRID and .vts files hand these arrays to
// `Unstructured_flow_field_3`, whose isoparametric hexahedra are exactly the trilinear cells of
// a curvilinear grid.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_STRUCTURED_GRID_CELLS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_STRUCTURED_GRID_CELLS_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

struct Structured_grid_cells {
  std::vector<std::int64_t> connectivity; // 8 point indices per cell
  std::vector<std::int64_t> offsets;      // number_of_cells + 1 entries, 0, 8, 16, ...
  std::vector<unsigned char> cell_types;  // 12 (VTK_HEXAHEDRON) per cell
};

/// The hexahedra of a grid with `dimensions` points along each axis, cells ordered with `i`
/// fastest.  \pre every dimension is at least 2 and the counts fit in memory (the callers have
/// checked the dimensions against the points they hold).
inline Structured_grid_cells structured_grid_cells(const std::array<std::size_t, 3>& dimensions)
{
  const std::size_t nx = dimensions[0], ny = dimensions[1], nz = dimensions[2];
  const std::size_t cells = (nx - 1) * (ny - 1) * (nz - 1);
  Structured_grid_cells r;
  r.connectivity.reserve(8 * cells);
  r.offsets.reserve(cells + 1);
  r.cell_types.assign(cells, 12);
  r.offsets.push_back(0);
  auto index = [nx, ny](std::size_t i, std::size_t j, std::size_t k) {
    return static_cast<std::int64_t>(i + nx * (j + ny * k));
  };
  for (std::size_t k = 0; k + 1 < nz; ++k)
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        for (std::size_t dk = 0; dk < 2; ++dk) {
          r.connectivity.push_back(index(i, j, k + dk));
          r.connectivity.push_back(index(i + 1, j, k + dk));
          r.connectivity.push_back(index(i + 1, j + 1, k + dk));
          r.connectivity.push_back(index(i, j + 1, k + dk));
        }
        r.offsets.push_back(static_cast<std::int64_t>(r.connectivity.size()));
      }
  return r;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_STRUCTURED_GRID_CELLS_H
