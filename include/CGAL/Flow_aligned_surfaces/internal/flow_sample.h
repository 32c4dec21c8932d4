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

/// The field's value `value` (std::nullopt outside the domain), as a sample whose direction is
/// not computed yet (see `classify_sample()`).
template <class OptionalVector>
Flow_sample unclassified_sample(const OptionalVector& value)
{
  Flow_sample sample;
  if (value) {
    sample.kind = Sample_kind::VALID;
    sample.velocity =
        Eigen::Vector3d(CGAL::to_double(value->x()), CGAL::to_double(value->y()), CGAL::to_double(value->z()));
  }
  return sample;
}

/// Classifies a sample made by `unclassified_sample()` and computes its direction.  Apart so that
/// a caller with many samples can run this over all of them after the field's queries: the
/// square roots and divisions of many samples then overlap in the processor.
inline void classify_sample(Flow_sample& sample)
{
  if (sample.kind != Sample_kind::VALID)
    return;
  if (!sample.velocity.allFinite()) {
    sample.kind = Sample_kind::INVALID;
    return;
  }
  const double squared_norm = sample.velocity.squaredNorm();
  if (squared_norm > 1e-200 && squared_norm < 1e200) {
    sample.direction = sample.velocity * (1 / std::sqrt(squared_norm));
    return;
  }
  // Far from 1 the squared norm may under- or overflow: scale by the largest component first.
  const double largest = sample.velocity.cwiseAbs().maxCoeff();
  // Below the smallest normal double, a direction computed from the vector is rounding noise.
  if (largest < std::numeric_limits<double>::min())
    sample.kind = Sample_kind::ZERO;
  else
    sample.direction = (sample.velocity / largest).normalized();
}

/// Samples `field` at `p` (a point of the field's kernel).
template <class FlowField, class Point_3>
Flow_sample sample_flow(const FlowField& field, const Point_3& p)
{
  Flow_sample sample = unclassified_sample(field(p));
  classify_sample(sample);
  return sample;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_FLOW_SAMPLE_H
