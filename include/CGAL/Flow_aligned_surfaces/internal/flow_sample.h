// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One sample of a FlowField_3, classified: inside with a usable vector, outside the
// domain (std::nullopt), invalid (NaN or infinite components, treated as outside),
// or zero (a critical point, where no direction exists).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FLOW_SAMPLE_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FLOW_SAMPLE_H

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

enum class Sample_kind { VALID, OUTSIDE, INVALID, ZERO };

struct Flow_sample {
  Sample_kind kind = Sample_kind::OUTSIDE;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero(); // unit, when VALID
};

/// Samples `field` at `p` (a point of the field's kernel).
template <class FlowField, class Point_3>
Flow_sample sample_flow(const FlowField& field, const Point_3& p)
{
  Flow_sample sample;
  const auto value = field(p);
  if (!value)
    return sample;
  sample.velocity =
      Eigen::Vector3d(CGAL::to_double(value->x()), CGAL::to_double(value->y()), CGAL::to_double(value->z()));
  if (!sample.velocity.allFinite()) {
    sample.kind = Sample_kind::INVALID;
    return sample;
  }
  const double squared_norm = sample.velocity.squaredNorm();
  if (squared_norm > 1e-200 && squared_norm < 1e200) {
    sample.kind = Sample_kind::VALID;
    sample.direction = sample.velocity * (1 / std::sqrt(squared_norm));
    return sample;
  }
  // Far from 1 the squared norm may under- or overflow: scale by the largest component first.
  const double largest = sample.velocity.cwiseAbs().maxCoeff();
  // Below the smallest normal double, a direction computed from the vector is rounding noise.
  if (largest < std::numeric_limits<double>::min())
    sample.kind = Sample_kind::ZERO;
  else {
    sample.kind = Sample_kind::VALID;
    sample.direction = (sample.velocity / largest).normalized();
  }
  return sample;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FLOW_SAMPLE_H
