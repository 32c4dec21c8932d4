// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A flow field read from data, whatever its grid: one of the package's sampled fields
// (uniform grid, rectilinear grid, or unstructured cells), chosen at run time, itself a model of
// `FlowField_3`.  `IO::read_flow_field()` returns it for a file of any supported format.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_SAMPLED_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_SAMPLED_FLOW_FIELD_3_H

#include <CGAL/Flow_aligned_surfaces/Rectilinear_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>

#include <CGAL/Bbox_3.h>

#include <optional>
#include <utility>
#include <variant>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// A velocity field from data on any of the package's grids, chosen at run time: a
/// `Regular_grid_flow_field_3`, a `Rectilinear_grid_flow_field_3` or an
/// `Unstructured_flow_field_3`.  It is a model of `FlowField_3` that forwards every query to
/// the field it holds (one `std::visit`, no allocation), so programs that accept any data file
/// need one code path; programs that know their grid can ask for the field itself with
/// `get_if()` and skip the dispatch.
///
/// Copies share the arrays of the field they hold, so copying is cheap.
///
/// \tparam GeomTraits a model of `Kernel`
///
/// \cgalModels `FlowField_3`
///
/// \sa `IO::read_flow_field()`
template <typename GeomTraits>
class Sampled_flow_field_3 {
public:
  /// \name Types
  /// @{

  /// The geometric traits.
  typedef GeomTraits Geom_traits;
  /// The point type.
  typedef typename GeomTraits::Point_3 Point_3;
  /// The vector type.
  typedef typename GeomTraits::Vector_3 Vector_3;
  /// The field on a uniform grid.
  typedef Regular_grid_flow_field_3<GeomTraits> Regular_grid;
  /// The field on a rectilinear grid.
  typedef Rectilinear_grid_flow_field_3<GeomTraits> Rectilinear_grid;
  /// The field on cells (also curvilinear grids, as hexahedra).
  typedef Unstructured_flow_field_3<GeomTraits> Unstructured_grid;
  /// the field held, one of the three
  typedef std::variant<Regular_grid, Rectilinear_grid, Unstructured_grid> Variant;
  /// @}

  /// \name Creation
  /// @{

  /// holds an empty `Regular_grid` (`std::nullopt` everywhere), what
  /// `IO::read_flow_field()` fills.
  Sampled_flow_field_3() {}

  /// holds `field`, one of `Regular_grid`, `Rectilinear_grid`, `Unstructured_grid`.
  template <typename Field>
  Sampled_flow_field_3(Field field) : m_field(std::move(field))
  {
  }
  /// @}

  /// \name Evaluation
  /// @{

  /// the velocity at `p` of the field held, or `std::nullopt` outside its domain.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    return std::visit([&p](const auto& f) { return f(p); }, m_field);
  }
  /// @}

  /// \name Access
  /// @{

  /// the bounding box of the field's domain
  Bbox_3 bbox() const
  {
    return std::visit([](const auto& f) { return f.bbox(); }, m_field);
  }
  /// the field held, or null if it is not a `Field`
  template <typename Field>
  const Field* get_if() const
  {
    return std::get_if<Field>(&m_field);
  }
  /// the field held
  const Variant& variant() const { return m_field; }
  /// @}

private:
  Variant m_field;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_SAMPLED_FLOW_FIELD_3_H
