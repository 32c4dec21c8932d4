// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the grid fields (uniform and rectilinear) share: the checks of the node arrays (sizes,
// finite values at fluid nodes, zeros at solid ones) and the masked trilinear blend of the 8
// corners of a cell,  v = sum_q w_q v_q  with  w_q = prod_a (f_a if bit a of q else 1 - f_a),
// which is refused (outside) when a solid corner has a nonzero weight.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TRILINEAR_GRID_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TRILINEAR_GRID_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

typedef std::array<std::size_t, 3> Grid_dimensions;

inline std::string grid_dimensions_string(const Grid_dimensions& d)
{
  std::ostringstream s;
  s << d[0] << " x " << d[1] << " x " << d[2];
  return s.str();
}

/// Throws `std::invalid_argument` ("who: dimensions[a] (nx) is 1; ...") unless every dimension
/// is at least 2.
inline void check_grid_dimensions(const char* who, const Grid_dimensions& dimensions)
{
  static const char* const axis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (dimensions[a] < 2) {
      std::ostringstream msg;
      msg << who << ": dimensions[" << a << "] (n" << axis[a] << ") is " << dimensions[a]
          << "; expected at least 2 nodes along each axis";
      throw std::invalid_argument(msg.str());
    }
  }
}

/// nx·ny·nz, guaranteed to fit with the factor 3 of the value array so that callers can
/// allocate from it; throws `std::invalid_argument` otherwise.
inline std::size_t grid_node_count(const char* who, const Grid_dimensions& dimensions)
{
  const std::size_t max_nodes =
      (std::min)(std::vector<float>().max_size() / 3, std::vector<unsigned char>().max_size());
  std::size_t nodes = dimensions[0];
  for (int a = 1; a < 3; ++a) {
    if (nodes > max_nodes / dimensions[a]) {
      std::ostringstream msg;
      msg << who << ": dimensions " << grid_dimensions_string(dimensions)
          << " have more nodes than a std::vector can hold (at most " << max_nodes << ")";
      throw std::invalid_argument(msg.str());
    }
    nodes *= dimensions[a];
  }
  return nodes;
}

/// The tag of the grid fields' constructor for the package's readers, which have checked the
/// values as they decoded them (every value of a fluid node finite, a solid node with a
/// non-finite value stored as three zeros): the constructor then checks only the sizes and the
/// geometry, not each of the values again.
struct Node_values_checked {};

/// Checks the sizes of `values` (3 per node) and of a nonempty `mask` (1 per node), and, unless
/// `values_checked` (see `Node_values_checked`), that fluid nodes have finite values; replaces
/// the non-finite values of solid nodes by zeros (a solid node can get a zero weight in the
/// blend, and 0 · NaN would poison the result).
inline void check_grid_node_values(const char* who, const Grid_dimensions& n, std::size_t nodes,
                                   std::vector<float>& values, const std::vector<unsigned char>& mask,
                                   bool values_checked = false)
{
  // Compared before anything is read or allocated: the sizes come from the caller.
  if (values.size() / 3 != nodes || values.size() % 3 != 0) {
    std::ostringstream msg;
    msg << who << ": values.size() is " << values.size() << " but the dimensions "
        << grid_dimensions_string(n) << " need 3*nx*ny*nz = " << 3 * nodes;
    throw std::invalid_argument(msg.str());
  }
  if (!mask.empty() && mask.size() != nodes) {
    std::ostringstream msg;
    msg << who << ": mask.size() is " << mask.size() << " but the dimensions " << grid_dimensions_string(n)
        << " need nx*ny*nz = " << nodes << " (or an empty mask for no mask)";
    throw std::invalid_argument(msg.str());
  }
  if (values_checked)
    return;
  for (std::size_t v = 0; v < nodes; ++v) {
    float* c = values.data() + 3 * v;
    if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]))
      continue;
    if (!mask.empty() && mask[v] == 0) {
      c[0] = c[1] = c[2] = 0.f;
      continue;
    }
    const std::size_t i = v % n[0], j = (v / n[0]) % n[1], k = v / (n[0] * n[1]);
    std::ostringstream msg;
    msg << who << ": values of fluid node (" << i << ", " << j << ", " << k << ") (values[" << 3 * v << ".."
        << 3 * v + 2 << "]) are (" << c[0] << ", " << c[1] << ", " << c[2] << "); expected finite numbers";
    throw std::invalid_argument(msg.str());
  }
}

/// The trilinear blend in the cell whose node `(0, 0, 0)` is `base`, with the fractions `f`
/// (and `g = 1 - f`) along each axis, of the node values `v` (3 floats per node); `m` is the
/// mask or null.  Returns `false` (outside) if a solid corner has a nonzero weight: so the
/// interior of a cell touching a solid node is outside, and a closed fluid cell is inside,
/// including the faces it shares with solid cells.
inline bool masked_trilinear_blend(const float* v, const unsigned char* m, std::size_t base,
                                   std::size_t stride_y, std::size_t stride_z, const double f[3],
                                   const double g[3], double r[3])
{
  const std::size_t corner[8] = {base,
                                 base + 1,
                                 base + stride_y,
                                 base + stride_y + 1,
                                 base + stride_z,
                                 base + stride_z + 1,
                                 base + stride_z + stride_y,
                                 base + stride_z + stride_y + 1};
  if (m != nullptr) {
    for (int q = 0; q < 8; ++q) {
      if (m[corner[q]] == 0 && ((q & 1) ? f[0] : g[0]) != 0. && ((q & 2) ? f[1] : g[1]) != 0. &&
          ((q & 4) ? f[2] : g[2]) != 0.)
        return false;
    }
  }
  // The (1-f)·a + f·b form returns a node's value exactly when f is 0 or 1.
  for (int d = 0; d < 3; ++d) {
    const double x00 = g[0] * v[3 * corner[0] + d] + f[0] * v[3 * corner[1] + d];
    const double x10 = g[0] * v[3 * corner[2] + d] + f[0] * v[3 * corner[3] + d];
    const double x01 = g[0] * v[3 * corner[4] + d] + f[0] * v[3 * corner[5] + d];
    const double x11 = g[0] * v[3 * corner[6] + d] + f[0] * v[3 * corner[7] + d];
    r[d] = g[2] * (g[1] * x00 + f[1] * x10) + f[2] * (g[1] * x01 + f[1] * x11);
  }
  return true;
}

/// The same blend as a kernel vector, or `std::nullopt` where the mask refuses it.
template <class Vector_3, class FT>
std::optional<Vector_3> masked_trilinear_vector(const float* v, const unsigned char* m, std::size_t base,
                                                std::size_t stride_y, std::size_t stride_z, const double f[3],
                                                const double g[3])
{
  double r[3];
  if (!masked_trilinear_blend(v, m, base, stride_y, stride_z, f, g, r))
    return std::nullopt;
  return Vector_3(FT(r[0]), FT(r[1]), FT(r[2]));
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TRILINEAR_GRID_H
