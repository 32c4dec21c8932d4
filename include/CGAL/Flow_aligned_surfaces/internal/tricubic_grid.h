// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tricubic blend of the uniform grid field: tensor-product Catmull–Rom weights (Keys' cubic
// convolution with a = -1/2) along each axis,
//   w_-1 = (-s + 2s² - s³)/2,  w_0 = (2 - 5s² + 3s³)/2,  w_1 = (s + 4s² - 3s³)/2,  w_2 = (s³ - s²)/2,
// over the nodes c-1 .. c+2 of the cell c with fraction s.  Where c-1 or c+2 lies outside the grid
// it is replaced by the quadratic extrapolation of the three nodes inside (f_-1 = 3f_0 - 3f_1 + f_2),
// which keeps the third order and the exactness for quadratics up to the box; with two nodes
// along an axis, by the linear one (the blend is then linear along that axis).  The weights of an
// axis depend only on the coordinate along it, so neighbouring cells agree on their shared face
// (value and first derivatives: the derivative at a node is the central difference).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TRICUBIC_GRID_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TRICUBIC_GRID_H

#include <cstddef>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// The 4 nodes along one axis that the tricubic blend reads, and their weights; a slot that
/// the boundary folding emptied keeps a valid node with weight 0.
struct Cubic_axis_stencil {
  std::size_t node[4];
  double weight[4];
};

/// The stencil of cell `c` (0 <= c <= n - 2) at fraction `s` in [0, 1] on an axis of `n` >= 2 nodes.
inline Cubic_axis_stencil cubic_axis_stencil(std::size_t c, double s, std::size_t n)
{
  const double s2 = s * s, s3 = s2 * s;
  double w[4] = {0.5 * (-s + 2. * s2 - s3), 0.5 * (2. - 5. * s2 + 3. * s3), 0.5 * (s + 4. * s2 - 3. * s3),
                 0.5 * (s3 - s2)};
  Cubic_axis_stencil r;
  if (n == 2) { // f_-1 = 2 f_0 - f_1 and f_2 = 2 f_1 - f_0: the linear blend
    r.node[0] = 0; r.node[1] = 0; r.node[2] = 1; r.node[3] = 1;
    r.weight[0] = 0.; r.weight[3] = 0.;
    r.weight[1] = w[1] + 2. * w[0] - w[3];
    r.weight[2] = w[2] - w[0] + 2. * w[3];
    return r;
  }
  if (c == 0) { // f_-1 = 3 f_0 - 3 f_1 + f_2
    r.node[0] = 0; r.node[1] = 0; r.node[2] = 1; r.node[3] = 2;
    r.weight[0] = 0.;
    r.weight[1] = w[1] + 3. * w[0];
    r.weight[2] = w[2] - 3. * w[0];
    r.weight[3] = w[3] + w[0];
    return r;
  }
  if (c + 2 == n) { // f_n = 3 f_(n-1) - 3 f_(n-2) + f_(n-3)
    r.node[0] = c - 1; r.node[1] = c; r.node[2] = c + 1; r.node[3] = c + 1;
    r.weight[0] = w[0] + w[3];
    r.weight[1] = w[1] - 3. * w[3];
    r.weight[2] = w[2] + 3. * w[3];
    r.weight[3] = 0.;
    return r;
  }
  for (int q = 0; q < 4; ++q) {
    r.node[q] = c - 1 + static_cast<std::size_t>(q);
    r.weight[q] = w[q];
  }
  return r;
}

/// The tricubic blend of the node values `v` (3 floats per node) with the axis stencils `a`;
/// `m` is the mask or null.  Returns `false` if a node with a nonzero weight is solid (the caller
/// then falls back to the trilinear blend of the cell).
inline bool masked_tricubic_blend(const float* v, const unsigned char* m, std::size_t stride_y,
                                  std::size_t stride_z, const Cubic_axis_stencil a[3], double r[3])
{
  double sum[3] = {0., 0., 0.};
  for (int k = 0; k < 4; ++k) {
    const double wz = a[2].weight[k];
    if (wz == 0.)
      continue;
    for (int j = 0; j < 4; ++j) {
      const double wyz = a[1].weight[j] * wz;
      if (wyz == 0.)
        continue;
      const std::size_t row = stride_y * a[1].node[j] + stride_z * a[2].node[k];
      double line[3] = {0., 0., 0.};
      for (int i = 0; i < 4; ++i) {
        const double wx = a[0].weight[i];
        const std::size_t node = row + a[0].node[i];
        if (m != nullptr && wx != 0. && m[node] == 0)
          return false;
        const float* c = v + 3 * node;
        line[0] += wx * c[0];
        line[1] += wx * c[1];
        line[2] += wx * c[2];
      }
      sum[0] += wyz * line[0];
      sum[1] += wyz * line[1];
      sum[2] += wyz * line[2];
    }
  }
  r[0] = sum[0];
  r[1] = sum[1];
  r[2] = sum[2];
  return true;
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TRICUBIC_GRID_H
