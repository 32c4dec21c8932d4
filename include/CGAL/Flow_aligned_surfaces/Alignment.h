// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two kinds of flow alignment of Section 4 of the paper, and the reports of
// the alignment iteration.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_ALIGNMENT_H
#define CGAL_FLOW_ALIGNED_SURFACES_ALIGNMENT_H

#include <CGAL/Flow_aligned_surfaces/Normalized_flux.h>

#include <cstddef>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesRef
/// The target of the flow alignment.
enum class Alignment {
  TANGENTIAL, ///< minimize the flux: the surface becomes a stream surface (n·v = 0)
  ORTHOGONAL  ///< maximize the flux: the surface becomes orthogonal to the flow (n ∥ v)
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// What one iteration of `Flow_aligned_deformation` did.  The flux is that of the surface the
/// iteration started from (it is measured from the samples the iteration takes anyway), with the
/// share of the area where the flow was sampled; the faces without a sample are also counted by
/// kind.
struct Iteration_report {
  std::size_t iteration = 0;     ///< 1 for the first iteration since construction
  /// f_n of the surface before the iteration and its sampled area fraction (see `normalized_flux()`);
  /// no value when no face had a usable sample
  Normalized_flux normalized_flux;
  double max_rotation_angle = 0; ///< the largest alignment rotation requested, before clamping to η (radians)
  double max_vertex_step = 0;    ///< the largest vertex displacement, relative to the bounding-box diagonal
  std::size_t number_of_folds = 0;           ///< interior edges whose dihedral angle exceeded θmax
  std::size_t number_of_outside_samples = 0; ///< faces whose centroid is outside the domain (`T = I`)
  std::size_t number_of_invalid_samples =
      0; ///< faces where the field returned NaN or infinite values (treated as outside)
  std::size_t number_of_zero_samples = 0; ///< faces where the field vanishes (`T = I`)
  double gradient_transformation_ms = 0;  ///< GTRANSF: sampling, local transformations and right-hand side
  double solve_ms = 0;                    ///< SOLVE: the back-substitutions
  bool converged = false;                 ///< whether this iteration met a stopping rule
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// What a sequence of iterations (`Flow_aligned_deformation::run()`, `align_to_flow()`) achieved.
struct Alignment_report {
  std::size_t number_of_iterations = 0; ///< iterations performed
  bool converged = false;               ///< whether the last iteration met a stopping rule
  Normalized_flux normalized_flux;      ///< f_n of the final surface and its sampled area fraction
  double max_rotation_angle = 0;        ///< the largest rotation requested by the last iteration (radians)
  double factor_ms = 0;                 ///< FACTOR: time spent in factorizations (ms)
  /// whether the iterations ended because the `callback` named parameter returned `false` (the
  /// surface is then the one of the last iteration performed)
  bool stopped = false;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_ALIGNMENT_H
