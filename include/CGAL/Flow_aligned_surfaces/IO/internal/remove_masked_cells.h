// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A node mask applied to cells: of the cells c_0 ... c_{m-1} given as VTK arrays (cell c's
// point indices are connectivity[offsets[c] .. offsets[c+1]), its VTK type types[c]), keeps
// exactly those whose points are all fluid (fluid[p] != 0), in their order.  This is the grid
// fields' rule for cells: the interior of a cell touching a solid node is outside.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_REMOVE_MASKED_CELLS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_REMOVE_MASKED_CELLS_H

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Removes from the cell arrays every cell that touches a point `p` with `fluid[p] == 0`, and
/// returns the number of cells left.  Point indices out of `[0, fluid.size())` do not remove a
/// cell: they are left for the field's constructor to report.
template <class Index>
std::size_t remove_masked_cells(const std::vector<unsigned char>& fluid, std::vector<Index>& connectivity,
                                std::vector<Index>& offsets, std::vector<unsigned char>& types)
{
  std::vector<Index> kept_connectivity, kept_offsets(1, 0);
  std::vector<unsigned char> kept_types;
  for (std::size_t cell = 0; cell < types.size(); ++cell) {
    const Index* b = connectivity.data() + offsets[cell];
    const Index* e = connectivity.data() + offsets[cell + 1];
    if (std::any_of(b, e, [&](Index p) {
          return p >= 0 && static_cast<std::size_t>(p) < fluid.size() &&
                 fluid[static_cast<std::size_t>(p)] == 0;
        }))
      continue;
    kept_connectivity.insert(kept_connectivity.end(), b, e);
    kept_offsets.push_back(static_cast<Index>(kept_connectivity.size()));
    kept_types.push_back(types[cell]);
  }
  connectivity = std::move(kept_connectivity);
  offsets = std::move(kept_offsets);
  types = std::move(kept_types);
  return types.size();
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_REMOVE_MASKED_CELLS_H
