// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's Figure 4 (top): an aligned tangential patch grown across the flow before its seed
// curves are taken, so that an iso-contour of its tangential parametrization spans more of the
// flow ("growing a tangentially aligned surface in a direction orthogonal to the flow is
// advantageous for the seed curve extraction", Section 4).  The growth goes in `steps` steps of
// `distance / steps` each (Flow_aligned_deformation::grow with across_flow: both sides of the
// patch), the surface aligned again after each, as a user of the paper's tool grows it.

#ifndef FAS_DEMO_GROW_ACROSS_FLOW_H
#define FAS_DEMO_GROW_ACROSS_FLOW_H

#include <CGAL/Flow_aligned_surfaces/Alignment.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <cstddef>
#include <exception>
#include <string>

namespace fas_demo {

/// What `grow_across_flow()` did.
struct Growth_across_flow {
  std::size_t number_of_steps = 0;    ///< growth steps made
  std::size_t number_of_new_faces = 0; ///< faces added by them
  double added_area = 0;              ///< area added by them
  /// The iterations of the alignments after the steps, and the last one's flux and convergence.
  CGAL::Flow_aligned_surfaces::Alignment_report alignment;
  std::string stopped_because; ///< empty, or why a step could not be made (the rest are skipped)
};

/// Grows the tangential surface of `deformation` across the flow by `distance` in `steps` steps,
/// realigning after each (see the file's comment).
template <class Deformation>
Growth_across_flow grow_across_flow(Deformation& deformation, double distance, std::size_t steps)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
  Growth_across_flow result;
  for (std::size_t k = 0; k < steps; ++k) {
    try {
      const auto growth = deformation.grow(distance / double(steps), FAS::parameters::across_flow(true));
      result.number_of_new_faces += growth.number_of_new_faces;
      result.added_area += growth.added_area;
    } catch (const std::exception& e) { // no border edge across the flow, a fold, ...
      result.stopped_because = e.what();
      break;
    }
    ++result.number_of_steps;
    const FAS::Alignment_report r = deformation.run();
    result.alignment.number_of_iterations += r.number_of_iterations;
    result.alignment.converged = r.converged;
    result.alignment.normalized_flux = r.normalized_flux;
    result.alignment.max_rotation_angle = r.max_rotation_angle;
    result.alignment.factor_ms += r.factor_ms;
  }
  return result;
}

} // namespace fas_demo

#endif // FAS_DEMO_GROW_ACROSS_FLOW_H
