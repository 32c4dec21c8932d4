// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// R(a, angle): the rotation about the unit axis a by angle (right-handed, Rodrigues),
// and the angle gamma(p, q) between two vectors.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_ROTATIONS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_ROTATIONS_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// R(axis, angle) for a unit `axis`, given c = cos(angle) and s = sin(angle).
inline Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& axis, double c, double s)
{
  const double t = 1 - c;
  const double x = axis.x(), y = axis.y(), z = axis.z();
  Eigen::Matrix3d r;
  r << t * x * x + c, t * x * y - s * z, t * x * z + s * y, //
      t * x * y + s * z, t * y * y + c, t * y * z - s * x,  //
      t * x * z - s * y, t * y * z + s * x, t * z * z + c;
  return r;
}

/// R(axis, angle) for a unit `axis`.
inline Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& axis, double angle)
{
  return rotation_matrix(axis, std::cos(angle), std::sin(angle));
}

/// gamma(p, q) in [0, pi]; atan2 keeps full precision near 0 and pi, where acos does not.
inline double angle_between(const Eigen::Vector3d& p, const Eigen::Vector3d& q)
{
  return std::atan2(p.cross(q).norm(), p.dot(q));
}

/// A unit vector orthogonal to the unit vector `n`.
inline Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d helper = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(helper).normalized();
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_ROTATIONS_H
