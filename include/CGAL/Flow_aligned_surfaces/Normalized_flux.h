// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The value of the normalized flux f_n of a surface together with the share of its area that
// the flow was sampled on:
//
//   f_n = sum_{j sampled} A_j |n_j . v_j| / |v_j|  /  sum_{j sampled} A_j,
//   sampled_area_fraction = sum_{j sampled} A_j  /  sum_j A_j,
//
// with no f_n at all when no face is sampled (never 0, which would read as "tangential").

#ifndef CGAL_FLOW_ALIGNED_SURFACES_NORMALIZED_FLUX_H
#define CGAL_FLOW_ALIGNED_SURFACES_NORMALIZED_FLUX_H

#include <optional>
#include <ostream>

namespace CGAL {
namespace Flow_aligned_surfaces {

/*!
\ingroup PkgFlowAlignedSurfacesRef

The normalized flux \f$ f_n \f$ of a surface (see `normalized_flux()`), measured over the faces
where the flow has a usable sample, and the share of the surface's area those faces cover.

A face is <em>sampled</em> when the field's value at its centroid exists (the centroid is inside
the domain), is finite and is not zero.  Faces without a sample are left out of \f$ f_n \f$: the
fraction says how much of the surface the value speaks for.  When no face is sampled, for
instance when the surface has left the domain, there is no value: `value` is empty rather than
0, which would read as "perfectly tangential".

The type has no comparison operators on purpose: `report.normalized_flux.value.value()` (which
throws `std::bad_optional_access` when there is no value) or an explicit test of
`value.has_value()` says what happens without a value, where a comparison of an empty
`std::optional` with a number would silently be true or false.

\sa `normalized_flux()`, `Iteration_report`, `Alignment_report`
*/
struct Normalized_flux {
  /// \f$ f_n \in [0, 1] \f$ over the sampled faces (1: orthogonal, 0: tangential); empty when no
  /// face is sampled.
  std::optional<double> value;
  /// The area of the sampled faces divided by the area of the surface, in \f$ [0, 1] \f$; 0 for
  /// a surface without area.
  double sampled_area_fraction = 0;
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// Writes `f` for people: the value, followed by the sampled share of the area when it is not
/// all of it (`0.0123`, `0.0123 (on 97.5% of the area)`), or `none (no face sampled)`.
inline std::ostream& operator<<(std::ostream& os, const Normalized_flux& f)
{
  if (!f.value)
    return os << "none (no face sampled)";
  os << *f.value;
  if (f.sampled_area_fraction < 1)
    os << " (on " << 100 * f.sampled_area_fraction << "% of the area)";
  return os;
}

namespace internal {

/// Accumulates the area-weighted flux of the sampled faces and the area of all faces.
struct Normalized_flux_sum {
  double flux = 0, sampled_area = 0, total_area = 0;

  /// A face of area `area`, and its |n . v| / |v| when it is sampled.
  void add(double area, const std::optional<double>& face_flux)
  {
    total_area += area;
    if (face_flux) {
      flux += area * *face_flux;
      sampled_area += area;
    }
  }
  void join(const Normalized_flux_sum& other)
  {
    flux += other.flux;
    sampled_area += other.sampled_area;
    total_area += other.total_area;
  }
  Normalized_flux result() const
  {
    Normalized_flux f;
    if (sampled_area > 0)
      f.value = flux / sampled_area;
    if (total_area > 0)
      f.sampled_area_fraction = sampled_area / total_area;
    return f;
  }
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_NORMALIZED_FLUX_H
