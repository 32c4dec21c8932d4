// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A model of `FlowField_3` sampled on a uniform grid: v(p) is the trilinear (or, on request,
// tricubic) interpolation of the velocities stored at the nx × ny × nz nodes
// origin + (i hx, j hy, k hz), and std::nullopt outside the closed box
// [origin, origin + ((nx-1) hx, (ny-1) hy, (nz-1) hz)] or where an optional node mask marks the
// cell as solid.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_REGULAR_GRID_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_REGULAR_GRID_FLOW_FIELD_3_H

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <CGAL/Flow_aligned_surfaces/Grid_interpolation.h>
#include <CGAL/Flow_aligned_surfaces/internal/tricubic_grid.h>
#include <CGAL/Flow_aligned_surfaces/internal/trilinear_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
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
/// A velocity field given at the nodes of a uniform grid and interpolated trilinearly (by
/// default) or tricubically, a model of `FlowField_3`.
///
/// The grid has `nx × ny × nz` nodes (at least 2 along each axis) at
/// `origin + (i·hx, j·hy, k·hz)`.  The velocities are stored as 32-bit floats, interleaved
/// `x, y, z` per node, nodes ordered with `i` fastest, then `j`, then `k` (the order of VTK
/// `STRUCTURED_POINTS` and of most CFD exports): node `(i, j, k)` starts at
/// `3 · (i + nx · (j + ny · k))`.
///
/// The field is defined on the closed box `[origin, origin + ((nx−1)·hx, (ny−1)·hy, (nz−1)·hz)]`
/// and returns `std::nullopt` elsewhere.  An optional node mask (nonzero = fluid, zero = solid)
/// restricts the domain further: a point is outside when its trilinear interpolation would
/// give a nonzero weight to a solid node.  So the interior of every cell touching a solid node is
/// outside, and every closed cell whose 8 nodes are fluid is inside, including the faces it
/// shares with solid cells.
///
/// `with_interpolation(Grid_interpolation::TRICUBIC)` returns the same field interpolated by
/// tensor-product Catmull–Rom splines over the 4 × 4 × 4 nodes around each cell: continuously
/// differentiable, exact for fields quadratic in each coordinate and third-order accurate, where
/// the trilinear blend is second-order and has derivatives that jump at every cell face.  How much
/// closer stream lines on it keep the first integrals of the sampled flow depends on the flow
/// (median drift over stream lines, benchmark/Flow_aligned_surfaces/RESULTS.md, "Stream lines and
/// stream surfaces"): on the ABC flow
/// over one period [0, 2π]³, 5, 15, 31 and 66 times closer at 16³, 32³, 64³ and 128³ nodes; 5 to
/// 8 times closer inside Hill's spherical vortex at 16³ to 32³ nodes (a quadratic field,
/// reproduced exactly away from the vortex's boundary); but no closer on the cellular flow
/// \f$ (\sin x \cos y, -\cos x \sin y) \f$, where the largest drift over the lines is even 2 to
/// 3 times larger.  On the smoother field the adaptive integrators take fewer steps (2.6 times
/// fewer on the ABC flow of the manual's benchmark).  The domain is the same; a cell with a solid node among the 64 of its
/// stencil is interpolated trilinearly, so next to solid nodes the field is continuous within a
/// cell but may jump by O(h²) across the faces between such cells and tricubic ones.
///
/// Copies share the node arrays (through `std::shared_ptr`), so copying a field is cheap and
/// the arrays are never duplicated.  A query performs no allocation and no virtual call.
///
/// \tparam GeomTraits a model of `Kernel`; the coordinates are converted to `double` with
///         `CGAL::to_double()` for the interpolation.
///
/// \cgalModels `FlowField_3`
///
/// \sa `sample_on_grid()`
template <typename GeomTraits>
class Regular_grid_flow_field_3 {
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
  /// @}

  /// \name Creation
  /// @{

  /// creates an empty field: no node, `std::nullopt` everywhere, `bbox()` the empty `Bbox_3()`.
  /// It is what a reader such as `IO::read_VTK_flow_field()` fills.
  Regular_grid_flow_field_3() : m_origin(ORIGIN), m_spacing(NULL_VECTOR), m_dimensions{{0, 0, 0}}
  {
    // The empty box +inf..-inf, which no point (not even a NaN) is in.
    for (int a = 0; a < 3; ++a) {
      m_lo[a] = m_grid_lo[a] = std::numeric_limits<double>::infinity();
      m_hi[a] = m_grid_hi[a] = -std::numeric_limits<double>::infinity();
      m_grid_last_cell[a] = m_first[a] = 0;
      m_h[a] = m_inv_h[a] = 0.;
    }
  }

  /// creates the field from its node values.
  ///
  /// \param origin the position of node `(0, 0, 0)`, the lower corner of the domain
  /// \param hx,hy,hz the distances between neighbouring nodes along each axis
  /// \param dimensions the numbers of nodes `{nx, ny, nz}` along each axis
  /// \param values the `3·nx·ny·nz` velocity components in the order described above; pass it
  ///        with `std::move()` to avoid a copy
  /// \param mask either empty (every node is fluid) or `nx·ny·nz` flags, nonzero = fluid, in
  ///        node order; pass it with `std::move()` to avoid a copy.  Values at solid nodes are
  ///        never interpolated; non-finite ones are accepted there and stored as zero.
  ///
  /// \throws std::invalid_argument naming the faulty argument, with the expected and actual
  ///         values, if a dimension is below 2, a spacing is not positive and finite, the
  ///         origin is not finite, `values` or a nonempty `mask` has the wrong size, or a fluid
  ///         node has a non-finite value.
  Regular_grid_flow_field_3(const Point_3& origin, const FT& hx, const FT& hy, const FT& hz,
                            const Dimensions& dimensions, std::vector<float> values,
                            std::vector<unsigned char> mask = std::vector<unsigned char>())
      : Regular_grid_flow_field_3(origin, Vector_3(hx, hy, hz), dimensions, std::move(values),
                                  std::move(mask))
  {
  }

  /// creates the field from its node values, with the spacings `(hx, hy, hz)` given as the
  /// components of `spacing`; see the constructor above.
  Regular_grid_flow_field_3(const Point_3& origin, const Vector_3& spacing, const Dimensions& dimensions,
                            std::vector<float> values,
                            std::vector<unsigned char> mask = std::vector<unsigned char>())
      : Regular_grid_flow_field_3(origin, spacing, dimensions, std::move(values), std::move(mask), false)
  {
  }

  /// creates the field of a block of a larger grid, for data split into pieces (the pieces of a
  /// VTK image spread over MPI ranks, for instance): the nodes `first_node + (i, j, k)`,
  /// `(i, j, k) < dimensions`, of the grid of `grid_dimensions` nodes whose node `(0, 0, 0)` is at
  /// `grid_origin`; `values` and `mask` hold the block's nodes, in the order of the constructor.
  ///
  /// Where the block has a sample it is, bit for bit, the sample of the whole grid's field (made
  /// by the constructor from all the nodes), trilinearly interpolated: the block locates points in
  /// the whole grid's cells, as that field does.  It has a sample at the points of the whole
  /// grid's domain that lie in one of its own closed cells, so blocks sharing a face both answer
  /// there, with the same value, and the blocks of a partition of the grid answer wherever the
  /// whole grid does.  Elsewhere it returns `std::nullopt`.  `origin()` and `bbox()` are those of
  /// the block; `node_point()` and `node_value()` take the block's node indices.  (Interpolated
  /// tricubically, the stencil of a cell next to an inner face of the block is cut there.)
  ///
  /// \throws std::invalid_argument as the constructor, or if the block does not fit in the grid
  ///         (`first_node[a] + dimensions[a] > grid_dimensions[a]` along an axis `a`).
  static Regular_grid_flow_field_3 block(const Point_3& grid_origin, const Vector_3& spacing,
                                         const Dimensions& grid_dimensions, const Dimensions& first_node,
                                         const Dimensions& dimensions, std::vector<float> values,
                                         std::vector<unsigned char> mask = std::vector<unsigned char>())
  {
    checked_number_of_nodes(grid_origin, spacing, grid_dimensions);
    for (int a = 0; a < 3; ++a) {
      if (first_node[a] > grid_dimensions[a] || dimensions[a] > grid_dimensions[a] - first_node[a]) {
        std::ostringstream msg;
        msg << "Regular_grid_flow_field_3::block: along axis " << a << " the block's nodes "
            << first_node[a] << ".." << first_node[a] + dimensions[a] - 1 << " do not fit in the grid's "
            << grid_dimensions[a] << " nodes";
        throw std::invalid_argument(msg.str());
      }
    }
    Regular_grid_flow_field_3 r(grid_origin, spacing, dimensions, std::move(values), std::move(mask), false);
    for (int a = 0; a < 3; ++a) {
      r.m_first[a] = first_node[a];
      r.m_grid_last_cell[a] = grid_dimensions[a] - 2;
      r.m_lo[a] = node_coordinate(r.m_grid_lo[a], r.m_h[a], first_node[a]);
      r.m_hi[a] = node_coordinate(r.m_grid_lo[a], r.m_h[a], first_node[a] + dimensions[a] - 1);
      r.m_grid_hi[a] = node_coordinate(r.m_grid_lo[a], r.m_h[a], grid_dimensions[a] - 1);
    }
    r.m_origin = Point_3(FT(r.m_lo[0]), FT(r.m_lo[1]), FT(r.m_lo[2]));
    return r;
  }

  /// \cond SKIP_IN_MANUAL
  // For the package's readers, which checked the values while decoding them (see
  // `internal::Node_values_checked`): the sizes and the geometry are still checked.
  Regular_grid_flow_field_3(internal::Node_values_checked, const Point_3& origin, const Vector_3& spacing,
                            const Dimensions& dimensions, std::vector<float> values,
                            std::vector<unsigned char> mask)
      : Regular_grid_flow_field_3(origin, spacing, dimensions, std::move(values), std::move(mask), true)
  {
  }
  /// \endcond

  /// @}

private:
  Regular_grid_flow_field_3(const Point_3& origin, const Vector_3& spacing, const Dimensions& dimensions,
                            std::vector<float> values, std::vector<unsigned char> mask, bool values_checked)
      : m_origin(origin), m_spacing(spacing), m_dimensions(dimensions)
  {
    const std::size_t nodes = checked_number_of_nodes(origin, spacing, dimensions);
    internal::check_grid_node_values("Regular_grid_flow_field_3", dimensions, nodes, values, mask,
                                     values_checked);

    m_values = std::make_shared<const std::vector<float>>(std::move(values));
    m_value_data = m_values->data();
    if (!mask.empty()) {
      m_mask = std::make_shared<const std::vector<unsigned char>>(std::move(mask));
      m_mask_data = m_mask->data();
    }

    const double o[3] = {CGAL::to_double(origin.x()), CGAL::to_double(origin.y()),
                         CGAL::to_double(origin.z())};
    const double h[3] = {CGAL::to_double(spacing.x()), CGAL::to_double(spacing.y()),
                         CGAL::to_double(spacing.z())};
    for (int a = 0; a < 3; ++a) {
      m_lo[a] = m_grid_lo[a] = o[a];
      m_h[a] = h[a];
      m_hi[a] = m_grid_hi[a] = node_coordinate(o[a], h[a], m_dimensions[a] - 1);
      m_inv_h[a] = 1. / h[a];
      m_first[a] = 0;
      m_grid_last_cell[a] = m_dimensions[a] - 2;
    }
    m_stride_y = m_dimensions[0];
    m_stride_z = m_dimensions[0] * m_dimensions[1];
  }

public:
  /// \name Evaluation
  /// @{

  /// returns the interpolated velocity at `p` (see `interpolation()`), or `std::nullopt` if `p`
  /// is outside the closed box or its trilinear stencil touches a solid node with a nonzero
  /// weight.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    // Written so that NaN coordinates fail too.  The box test is done in world coordinates so
    // that it agrees exactly with `bbox()` (of the whole grid, for a block).
    if (!(x[0] >= m_grid_lo[0] && x[0] <= m_grid_hi[0] && x[1] >= m_grid_lo[1] && x[1] <= m_grid_hi[1] &&
          x[2] >= m_grid_lo[2] && x[2] <= m_grid_hi[2]))
      return std::nullopt;

    std::size_t c[3];
    double f[3], g[3];
    for (int a = 0; a < 3; ++a) {
      const double t = (x[a] - m_grid_lo[a]) * m_inv_h[a]; // >= 0, so truncation is floor
      // The upper boundary belongs to the last cell; rounding in t can only overshoot by ulps,
      // which the clamp on f absorbs.
      const std::size_t cell = (std::min)(static_cast<std::size_t>(t), m_grid_last_cell[a]);
      f[a] = (std::min)(t - static_cast<double>(cell), 1.);
      // A block has the whole grid's cells first .. first + n - 2 (so `c`, which wraps around
      // below first, is at most n - 2), and the node after them: there (f = 0 in the next cell)
      // it blends its last cell with f = 1, the same value.
      c[a] = cell - m_first[a];
      if (c[a] >= m_dimensions[a] - 1) {
        if (c[a] != m_dimensions[a] - 1 || f[a] != 0.)
          return std::nullopt;
        c[a] = m_dimensions[a] - 2;
        f[a] = 1.;
      }
      g[a] = 1. - f[a];
    }
    if (m_interpolation == Grid_interpolation::TRICUBIC) {
      const internal::Cubic_axis_stencil stencil[3] = {
          internal::cubic_axis_stencil(c[0], f[0], m_dimensions[0]),
          internal::cubic_axis_stencil(c[1], f[1], m_dimensions[1]),
          internal::cubic_axis_stencil(c[2], f[2], m_dimensions[2])};
      double r[3];
      if (internal::masked_tricubic_blend(m_value_data, m_mask_data, m_stride_y, m_stride_z, stencil, r))
        return Vector_3(FT(r[0]), FT(r[1]), FT(r[2]));
    }
    return internal::masked_trilinear_vector<Vector_3, FT>(m_value_data, m_mask_data,
                                                           c[0] + m_stride_y * c[1] + m_stride_z * c[2],
                                                           m_stride_y, m_stride_z, f, g);
  }

  /// @}

  /// \name Interpolation
  /// @{

  /// the interpolation of the node values, `Grid_interpolation::TRILINEAR` unless this field
  /// was made by `with_interpolation()`
  Grid_interpolation interpolation() const { return m_interpolation; }

  /// returns this field with the interpolation `interpolation`: a copy sharing the node arrays
  Regular_grid_flow_field_3 with_interpolation(Grid_interpolation interpolation) const
  {
    Regular_grid_flow_field_3 r(*this);
    r.m_interpolation = interpolation;
    return r;
  }

  /// @}

  /// \name Access
  /// @{

  /// the numbers of nodes `{nx, ny, nz}`
  const Dimensions& dimensions() const { return m_dimensions; }
  /// the total number of nodes `nx·ny·nz`
  std::size_t number_of_nodes() const { return m_dimensions[0] * m_dimensions[1] * m_dimensions[2]; }
  /// the position of node `(0, 0, 0)`
  const Point_3& origin() const { return m_origin; }
  /// the node spacings `(hx, hy, hz)`
  const Vector_3& spacing() const { return m_spacing; }
  /// the closed box on which the field is defined (before the mask is applied)
  Bbox_3 bbox() const { return Bbox_3(m_lo[0], m_lo[1], m_lo[2], m_hi[0], m_hi[1], m_hi[2]); }

  /// the position of node `(i, j, k)`
  /// \pre `i < nx`, `j < ny`, `k < nz`
  Point_3 node_point(std::size_t i, std::size_t j, std::size_t k) const
  {
    CGAL_precondition(i < m_dimensions[0] && j < m_dimensions[1] && k < m_dimensions[2]);
    return Point_3(FT(node_coordinate(m_grid_lo[0], m_h[0], m_first[0] + i)),
                   FT(node_coordinate(m_grid_lo[1], m_h[1], m_first[1] + j)),
                   FT(node_coordinate(m_grid_lo[2], m_h[2], m_first[2] + k)));
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
  const std::vector<float>& values() const
  {
    static const std::vector<float> no_values;
    return m_values ? *m_values : no_values;
  }

  /// the `nx·ny·nz` mask flags, or an empty vector if the field has no mask
  const std::vector<unsigned char>& mask() const
  {
    static const std::vector<unsigned char> no_mask;
    return m_mask ? *m_mask : no_mask;
  }

  /// @}

  /// samples `field` (any model of `FlowField_3`) at the nodes of a grid.  Nodes where `field`
  /// returns `std::nullopt` or a non-finite vector get the value zero and become solid; the
  /// result has a mask only if there is such a node.
  ///
  /// \throws std::invalid_argument as the constructor for bad `spacing`, `origin` or
  ///         `dimensions` (before anything is allocated), or if a sampled value does not fit in
  ///         a 32-bit float.
  template <typename FlowField>
  static Regular_grid_flow_field_3 sample(const FlowField& field, const Point_3& origin,
                                          const Vector_3& spacing, const Dimensions& dimensions)
  {
    const std::size_t nodes = checked_number_of_nodes(origin, spacing, dimensions);
    const double o[3] = {CGAL::to_double(origin.x()), CGAL::to_double(origin.y()),
                         CGAL::to_double(origin.z())};
    const double h[3] = {CGAL::to_double(spacing.x()), CGAL::to_double(spacing.y()),
                         CGAL::to_double(spacing.z())};

    std::vector<float> values(3 * nodes, 0.f);
    std::vector<unsigned char> mask(nodes, 1);
    bool all_fluid = true;
    std::size_t v = 0;
    for (std::size_t k = 0; k < dimensions[2]; ++k)
      for (std::size_t j = 0; j < dimensions[1]; ++j)
        for (std::size_t i = 0; i < dimensions[0]; ++i, ++v) {
          // Same node positions as `node_point()`, so queries at nodes return these samples.
          const Point_3 p(FT(node_coordinate(o[0], h[0], i)), FT(node_coordinate(o[1], h[1], j)),
                          FT(node_coordinate(o[2], h[2], k)));
          const std::optional<Vector_3> s = field(p);
          const double w[3] = {s ? CGAL::to_double(s->x()) : 0., s ? CGAL::to_double(s->y()) : 0.,
                               s ? CGAL::to_double(s->z()) : 0.};
          if (!s || !std::isfinite(w[0]) || !std::isfinite(w[1]) || !std::isfinite(w[2])) {
            mask[v] = 0;
            all_fluid = false;
            continue;
          }
          for (int d = 0; d < 3; ++d) {
            const float fv = static_cast<float>(w[d]);
            if (!std::isfinite(fv)) {
              std::ostringstream msg;
              msg << "sample_on_grid: the field value " << w[d] << " at node (" << i << ", " << j << ", " << k
                  << ") does not fit in a 32-bit float";
              throw std::invalid_argument(msg.str());
            }
            values[3 * v + d] = fv;
          }
        }
    if (all_fluid)
      mask.clear();
    return Regular_grid_flow_field_3(origin, spacing, dimensions, std::move(values), std::move(mask));
  }

private:
  // The one formula for node positions, shared by the box, `node_point()` and `sample()` so
  // that they agree to the last bit.
  static double node_coordinate(double o, double h, std::size_t i) { return o + static_cast<double>(i) * h; }

  std::size_t node_index(std::size_t i, std::size_t j, std::size_t k) const
  {
    return i + m_stride_y * j + m_stride_z * k;
  }

  // Validates the geometry and returns nx·ny·nz, guaranteed to fit with the factor 3 of the
  // value array, so that callers can allocate from it.
  static std::size_t checked_number_of_nodes(const Point_3& origin, const Vector_3& spacing,
                                             const Dimensions& dimensions)
  {
    static const char* const axis[3] = {"x", "y", "z"};
    internal::check_grid_dimensions("Regular_grid_flow_field_3", dimensions);
    const double h[3] = {CGAL::to_double(spacing.x()), CGAL::to_double(spacing.y()),
                         CGAL::to_double(spacing.z())};
    for (int a = 0; a < 3; ++a) {
      if (!(std::isfinite(h[a]) && h[a] > 0.)) {
        std::ostringstream msg;
        msg << "Regular_grid_flow_field_3: spacing h" << axis[a] << " is " << h[a]
            << "; expected a positive finite number";
        throw std::invalid_argument(msg.str());
      }
    }
    const double o[3] = {CGAL::to_double(origin.x()), CGAL::to_double(origin.y()),
                         CGAL::to_double(origin.z())};
    for (int a = 0; a < 3; ++a) {
      const double far_corner = node_coordinate(o[a], h[a], dimensions[a] - 1);
      if (!std::isfinite(o[a]) || !std::isfinite(far_corner)) {
        std::ostringstream msg;
        msg << "Regular_grid_flow_field_3: origin." << axis[a] << " is " << o[a] << " and the far corner "
            << far_corner << "; expected finite coordinates";
        throw std::invalid_argument(msg.str());
      }
    }
    return internal::grid_node_count("Regular_grid_flow_field_3", dimensions);
  }

  // The kernel objects, as given, for the accessors.
  Point_3 m_origin;
  Vector_3 m_spacing;
  Dimensions m_dimensions;
  std::shared_ptr<const std::vector<float>> m_values;
  std::shared_ptr<const std::vector<unsigned char>> m_mask;
  // The hot path reads only these: doubles and raw pointers into the shared arrays (which the
  // shared pointers keep alive in every copy).
  double m_lo[3], m_hi[3], m_h[3], m_inv_h[3];
  // The whole grid of which this field is a block (itself unless made by `block()`): its box,
  // its last cell and the index of this field's node (0, 0, 0) in it.
  double m_grid_lo[3], m_grid_hi[3];
  std::size_t m_grid_last_cell[3], m_first[3];
  std::size_t m_stride_y = 0, m_stride_z = 0;
  Grid_interpolation m_interpolation = Grid_interpolation::TRILINEAR;
  const float* m_value_data = nullptr;
  const unsigned char* m_mask_data = nullptr;
};

/// \ingroup PkgFlowAlignedSurfacesFlows
/// samples a flow field on a uniform grid: shorthand for
/// `Regular_grid_flow_field_3<K>::sample(field, origin, spacing, dimensions)` with the kernel
/// `K` of `Point_3`.
///
/// \tparam FlowField a model of `FlowField_3` (a lambda `std::optional<Vector_3>(const Point_3&)`
///         will do)
/// \tparam Point_3 a point type of a CGAL kernel
///
/// \param field the field to sample; nodes where it returns `std::nullopt` (or a non-finite
///        vector) get zero and a solid mask flag
/// \param origin the position of node `(0, 0, 0)`
/// \param spacing the node spacings `(hx, hy, hz)`
/// \param dimensions the numbers of nodes `{nx, ny, nz}`, each at least 2
///
/// \throws std::invalid_argument for bad `spacing`, `origin` or `dimensions`, before anything is
///         allocated.
template <typename FlowField, typename Point_3>
Regular_grid_flow_field_3<typename Kernel_traits<Point_3>::Kernel>
sample_on_grid(const FlowField& field, const Point_3& origin,
               const typename Kernel_traits<Point_3>::Kernel::Vector_3& spacing,
               const std::array<std::size_t, 3>& dimensions)
{
  return Regular_grid_flow_field_3<typename Kernel_traits<Point_3>::Kernel>::sample(field, origin, spacing,
                                                                                    dimensions);
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_REGULAR_GRID_FLOW_FIELD_3_H
