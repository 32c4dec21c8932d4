// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A model of `FlowField_3` sampled on a rectilinear grid: nodes at (X_i, Y_j, Z_k) with strictly
// increasing per-axis coordinates; v(p) is the trilinear interpolation in the cell
// [X_i, X_i+1] × [Y_j, Y_j+1] × [Z_k, Z_k+1] containing p, with the fractions
// f_x = (x − X_i) / (X_i+1 − X_i) (and likewise in y, z), and std::nullopt outside the closed box
// [X_0, X_nx−1] × [Y_0, Y_ny−1] × [Z_0, Z_nz−1] or where an optional node mask marks the
// interpolation stencil as solid.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_RECTILINEAR_GRID_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_RECTILINEAR_GRID_FLOW_FIELD_3_H

#include <CGAL/Bbox_3.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <CGAL/Flow_aligned_surfaces/internal/trilinear_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// A velocity field given at the nodes of a rectilinear grid (per-axis node coordinates, as
/// VTK's `RECTILINEAR_GRID` and the graded meshes of many CFD codes) and trilinearly
/// interpolated, a model of `FlowField_3`.
///
/// The grid has `nx × ny × nz` nodes (at least 2 along each axis) at `(X[i], Y[j], Z[k])`,
/// where `X`, `Y`, `Z` are strictly increasing.  The velocities are stored as 32-bit floats,
/// interleaved `x, y, z` per node, nodes ordered with `i` fastest, then `j`, then `k`: node
/// `(i, j, k)` starts at `3 · (i + nx · (j + ny · k))`, as in `Regular_grid_flow_field_3`.
///
/// In the cell `[X[i], X[i+1]] × [Y[j], Y[j+1]] × [Z[k], Z[k+1]]` the field is the trilinear
/// interpolation of the cell's 8 nodes with the fractions `(x − X[i]) / (X[i+1] − X[i])` (and
/// likewise along `y` and `z`); the cell is found by a binary search per axis.  The field is
/// defined on the closed box `[X[0], X[nx−1]] × [Y[0], Y[ny−1]] × [Z[0], Z[nz−1]]` and returns
/// `std::nullopt` elsewhere.  An optional node mask (nonzero = fluid, zero = solid) restricts
/// the domain with the rule of `Regular_grid_flow_field_3`: a point is outside when its
/// trilinear interpolation would give a nonzero weight to a solid node.
///
/// Copies share the arrays (through `std::shared_ptr`).  A query performs no allocation.
///
/// \tparam GeomTraits a model of `Kernel`; the coordinates are converted to `double` with
///         `CGAL::to_double()` for the interpolation.
///
/// \cgalModels `FlowField_3`
///
/// \sa `Regular_grid_flow_field_3`, `IO::read_VTK_flow_field()`
template <typename GeomTraits>
class Rectilinear_grid_flow_field_3 {
public:
  /// \name Types
  /// @{

  /// The geometric traits.
  typedef GeomTraits Geom_traits;
  /// The number type.
  typedef typename GeomTraits::FT FT;
  /// The point type.
  typedef typename GeomTraits::Point_3 Point_3;
  /// The vector type.
  typedef typename GeomTraits::Vector_3 Vector_3;
  /// the numbers of nodes `{nx, ny, nz}`
  typedef std::array<std::size_t, 3> Dimensions;
  /// the node coordinates along each axis, `{X, Y, Z}`
  typedef std::array<std::vector<double>, 3> Coordinates;
  /// @}

  /// \name Creation
  /// @{

  /// creates an empty field: no node, `std::nullopt` everywhere, `bbox()` the empty `Bbox_3()`.
  /// It is what a reader such as `IO::read_VTK_flow_field()` fills.
  Rectilinear_grid_flow_field_3() : m_storage(std::make_shared<const Storage>()) {}

  /// creates the field from its node coordinates and values.
  ///
  /// \param coordinates the node coordinates `{X, Y, Z}` along each axis, each strictly
  ///        increasing, finite, with at least 2 entries; pass it with `std::move()` to avoid a copy
  /// \param values the `3·nx·ny·nz` velocity components in the order described above; pass it
  ///        with `std::move()` to avoid a copy
  /// \param mask either empty (every node is fluid) or `nx·ny·nz` flags, nonzero = fluid, in
  ///        node order.  Values at solid nodes are never interpolated; non-finite ones are
  ///        accepted there and stored as zero.
  ///
  /// \throws std::invalid_argument naming the faulty argument, with the expected and actual
  ///         values, if an axis has fewer than 2 nodes, a coordinate is not finite or not
  ///         greater than the previous one (with the axis and the index), `values` or a
  ///         nonempty `mask` has the wrong size, or a fluid node has a non-finite value.
  Rectilinear_grid_flow_field_3(Coordinates coordinates, std::vector<float> values,
                                std::vector<unsigned char> mask = std::vector<unsigned char>())
      : Rectilinear_grid_flow_field_3(std::move(coordinates), std::move(values), std::move(mask), false)
  {
  }

  /// \cond SKIP_IN_MANUAL
  // For the package's readers, which checked the values while decoding them (see
  // `internal::Node_values_checked`): the sizes and the coordinates are still checked.
  Rectilinear_grid_flow_field_3(internal::Node_values_checked, Coordinates coordinates,
                                std::vector<float> values, std::vector<unsigned char> mask)
      : Rectilinear_grid_flow_field_3(std::move(coordinates), std::move(values), std::move(mask), true)
  {
  }
  /// \endcond

  /// @}

private:
  Rectilinear_grid_flow_field_3(Coordinates coordinates, std::vector<float> values,
                                std::vector<unsigned char> mask, bool values_checked)
  {
    static const char* const who = "Rectilinear_grid_flow_field_3";
    static const char* const axis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
      m_dimensions[a] = coordinates[a].size();
    internal::check_grid_dimensions(who, m_dimensions);
    for (int a = 0; a < 3; ++a) {
      const std::vector<double>& X = coordinates[a];
      for (std::size_t i = 0; i < X.size(); ++i) {
        if (!std::isfinite(X[i])) {
          std::ostringstream msg;
          msg << who << ": coordinates[" << a << "][" << i << "] (" << axis[a] << " of node " << i << ") is "
              << X[i] << "; expected finite numbers";
          throw std::invalid_argument(msg.str());
        }
        if (i > 0 && !(X[i] > X[i - 1])) {
          std::ostringstream msg;
          msg.precision(17);
          msg << who << ": coordinates[" << a << "][" << i << "] (" << axis[a] << " of node " << i << ") is "
              << X[i] << ", not greater than coordinates[" << a << "][" << i - 1 << "] = " << X[i - 1]
              << "; expected strictly increasing coordinates";
          throw std::invalid_argument(msg.str());
        }
      }
    }
    const std::size_t nodes = internal::grid_node_count(who, m_dimensions);
    internal::check_grid_node_values(who, m_dimensions, nodes, values, mask, values_checked);

    auto s = std::make_shared<Storage>();
    s->coordinates = std::move(coordinates);
    s->values = std::move(values);
    s->mask = std::move(mask);
    m_storage = std::move(s);
    for (int a = 0; a < 3; ++a) {
      m_coordinate_data[a] = m_storage->coordinates[a].data();
      m_lo[a] = m_storage->coordinates[a].front();
      m_hi[a] = m_storage->coordinates[a].back();
    }
    m_value_data = m_storage->values.data();
    m_mask_data = m_storage->mask.empty() ? nullptr : m_storage->mask.data();
    m_stride_y = m_dimensions[0];
    m_stride_z = m_dimensions[0] * m_dimensions[1];
  }

public:
  /// \name Evaluation
  /// @{

  /// returns the trilinearly interpolated velocity at `p`, or `std::nullopt` if `p` is outside
  /// the closed box or its interpolation stencil touches a solid node with a nonzero weight.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    // Written so that NaN coordinates fail too.
    for (int a = 0; a < 3; ++a)
      if (!(x[a] >= m_lo[a] && x[a] <= m_hi[a]))
        return std::nullopt;

    std::size_t c[3];
    double f[3], g[3];
    for (int a = 0; a < 3; ++a) {
      // The last node not above x[a], clamped so that the upper boundary belongs to the last cell.
      const double* X = m_coordinate_data[a];
      const std::size_t i = static_cast<std::size_t>(std::upper_bound(X, X + m_dimensions[a], x[a]) - X);
      c[a] = (std::min)(i - 1, m_dimensions[a] - 2);
      f[a] = (std::min)((x[a] - X[c[a]]) / (X[c[a] + 1] - X[c[a]]), 1.);
      g[a] = 1. - f[a];
    }
    return internal::masked_trilinear_vector<Vector_3, FT>(m_value_data, m_mask_data,
                                                           c[0] + m_stride_y * c[1] + m_stride_z * c[2],
                                                           m_stride_y, m_stride_z, f, g);
  }

  /// @}

  /// \name Access
  /// @{

  /// the numbers of nodes `{nx, ny, nz}`
  const Dimensions& dimensions() const { return m_dimensions; }
  /// the total number of nodes `nx·ny·nz`
  std::size_t number_of_nodes() const { return m_dimensions[0] * m_dimensions[1] * m_dimensions[2]; }
  /// the node coordinates along axis `axis` (0 = x, 1 = y, 2 = z)
  /// \pre `axis < 3`
  const std::vector<double>& coordinates(int axis) const
  {
    CGAL_precondition(axis >= 0 && axis < 3);
    return m_storage->coordinates[axis];
  }
  /// the closed box on which the field is defined (before the mask is applied)
  Bbox_3 bbox() const { return Bbox_3(m_lo[0], m_lo[1], m_lo[2], m_hi[0], m_hi[1], m_hi[2]); }

  /// the position `(X[i], Y[j], Z[k])` of node `(i, j, k)`
  /// \pre `i < nx`, `j < ny`, `k < nz`
  Point_3 node_point(std::size_t i, std::size_t j, std::size_t k) const
  {
    CGAL_precondition(i < m_dimensions[0] && j < m_dimensions[1] && k < m_dimensions[2]);
    return Point_3(FT(m_coordinate_data[0][i]), FT(m_coordinate_data[1][j]), FT(m_coordinate_data[2][k]));
  }

  /// the velocity stored at node `(i, j, k)` (zero at a solid node whose given value was not
  /// finite)
  /// \pre `i < nx`, `j < ny`, `k < nz`
  Vector_3 node_value(std::size_t i, std::size_t j, std::size_t k) const
  {
    CGAL_precondition(i < m_dimensions[0] && j < m_dimensions[1] && k < m_dimensions[2]);
    const float* c = m_value_data + 3 * node_index(i, j, k);
    return Vector_3(FT(c[0]), FT(c[1]), FT(c[2]));
  }

  /// whether the field has a node mask
  bool has_mask() const { return m_mask_data != nullptr; }

  /// whether node `(i, j, k)` is fluid (always `true` without a mask)
  /// \pre `i < nx`, `j < ny`, `k < nz`
  bool is_fluid(std::size_t i, std::size_t j, std::size_t k) const
  {
    CGAL_precondition(i < m_dimensions[0] && j < m_dimensions[1] && k < m_dimensions[2]);
    return m_mask_data == nullptr || m_mask_data[node_index(i, j, k)] != 0;
  }

  /// the `3·nx·ny·nz` stored velocity components, in node order
  const std::vector<float>& values() const { return m_storage->values; }

  /// the `nx·ny·nz` mask flags, or an empty vector if the field has no mask
  const std::vector<unsigned char>& mask() const { return m_storage->mask; }

  /// @}

private:
  std::size_t node_index(std::size_t i, std::size_t j, std::size_t k) const
  {
    return i + m_stride_y * j + m_stride_z * k;
  }

  struct Storage {
    Coordinates coordinates;
    std::vector<float> values;
    std::vector<unsigned char> mask;
  };

  std::shared_ptr<const Storage> m_storage;
  Dimensions m_dimensions = {{0, 0, 0}};
  // The hot path reads only these: the box (the first and last coordinates; empty, +inf..-inf,
  // without nodes) and raw pointers into the shared storage (which the shared pointer keeps
  // alive in every copy).
  double m_lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, m_hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  const double* m_coordinate_data[3] = {nullptr, nullptr, nullptr};
  const float* m_value_data = nullptr;
  const unsigned char* m_mask_data = nullptr;
  std::size_t m_stride_y = 0, m_stride_z = 0;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_RECTILINEAR_GRID_FLOW_FIELD_3_H
