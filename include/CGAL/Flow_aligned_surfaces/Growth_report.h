// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a growth at the boundary did (grow_boundary.h), reported by `grow_boundary()` and
// `Flow_aligned_deformation::grow()`.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_GROWTH_REPORT_H
#define CGAL_FLOW_ALIGNED_SURFACES_GROWTH_REPORT_H

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/*!
\ingroup PkgFlowAlignedSurfacesRef
What `grow_boundary()` and `Flow_aligned_deformation::grow()` did.
*/
struct Growth_report {
  std::size_t number_of_new_vertices = 0; ///< vertices added to the mesh
  std::size_t number_of_new_faces = 0;    ///< faces added to the mesh
  double grown_boundary_length = 0;       ///< length of the boundary part that was offset (before growing)
  double added_area = 0;                  ///< total area of the new faces
  double offset_ms = 0;                   ///< time spent selecting the boundary and building the raw strip
  double remesh_ms = 0;        ///< time spent tessellating the strip (split and isotropic remeshing)
  double reference_map_ms = 0; ///< time spent placing the new vertices in \f$ M_0 \f$ and appending them
  double factor_ms = 0;        ///< time spent rebuilding and refactoring the operators (the class only)
  double check_ms = 0; ///< time spent checking the grown surface (manifold, no face cutting through another)
  std::size_t number_of_grown_edges = 0; ///< boundary edges that were grown (the size of `grown_edges`)
  /// The boundary edges that were grown, each as the indices of its two vertices (source and
  /// target of its border halfedge): positions in the order of `vertices(tm)` before growing for
  /// `grow_boundary()`, indices into `Flow_aligned_deformation::vertices()` for `grow()`.
  std::vector<std::pair<std::size_t, std::size_t>> grown_edges;
  /// whether the `callback` named parameter returned `false` once the strip was built: nothing
  /// was then added to the mesh (the counts are 0, the times those of the work done)
  bool stopped = false;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_GROWTH_REPORT_H
