// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How a uniform grid field interpolates between its nodes.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_GRID_INTERPOLATION_H
#define CGAL_FLOW_ALIGNED_SURFACES_GRID_INTERPOLATION_H

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// How `Regular_grid_flow_field_3` interpolates the velocities stored at its nodes.
enum class Grid_interpolation {
  /// trilinear in each cell from its 8 nodes: continuous, exact for trilinear fields, second
  /// order (error O(h²)); what VTK's probes and most visualization tools do
  TRILINEAR,
  /// tensor-product Catmull–Rom splines (Keys' cubic convolution) from the 4 × 4 × 4 nodes around
  /// the cell: continuously differentiable, exact for fields quadratic in each coordinate, third
  /// order (error O(h³)); at the box's faces the missing nodes are extrapolated quadratically.
  /// Cells with a solid node among the 64 are interpolated trilinearly.
  TRICUBIC
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_GRID_INTERPOLATION_H
