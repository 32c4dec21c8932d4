// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's `callback` named parameter, as the long-running functions read and call it: a
// `std::function<bool(double)>` that receives the fraction of the work done, in [0, 1], after
// each unit of work, and returns `false` to request a stop (the convention of CGAL's point set
// processing and shape detection).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_PROGRESS_CALLBACK_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_PROGRESS_CALLBACK_H

#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <algorithm>
#include <functional>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

using Progress_callback = std::function<bool(double)>;

// The callback of `np`, empty when none was given (then reporting costs one test per unit).
template <class NamedParameters>
Progress_callback progress_callback(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::callback),
                                      Progress_callback());
}

// Reports `fraction` (clamped to [0, 1], so that rounding in the caller's arithmetic never
// shows a caller 1.0000000000000002); returns whether the work may go on.
inline bool report_progress(const Progress_callback& callback, double fraction)
{
  return !callback || callback(std::clamp(fraction, 0., 1.));
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_PROGRESS_CALLBACK_H
