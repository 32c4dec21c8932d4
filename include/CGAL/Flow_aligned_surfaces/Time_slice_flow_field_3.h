// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An unsteady flow v(p, t) seen at one time t that the caller may change: a model of
// `FlowField_3`, so that every algorithm of the package for steady flows works on an instant of
// an unsteady one, and an object that holds a reference to its field (the deformation) follows
// the flow through time when the time is changed.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_TIME_SLICE_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_TIME_SLICE_FLOW_FIELD_3_H

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// An unsteady flow at one time, a model of `FlowField_3`: `slice(p)` returns `field(p, time())`.
///
/// The time can be changed with `set_time()`.  An algorithm that keeps a reference to its field,
/// such as `Flow_aligned_deformation`, then samples the flow at the new time: this is how a
/// surface follows an unsteady flow.  After `set_time(t)`, further iterations (`run()`, `step()`)
/// re-align the surface from where it is — the surface aligned at the previous time, a warm
/// start — with the factorization the deformation already has (it depends on the reference patch
/// only, not on the field), so a small change of the flow costs a few iterations and no
/// factorization.  See the example `follow_unsteady_flow.cpp`.
///
/// Where the surface ends depends a little on where it starts: the iterations rotate the faces
/// towards the flow and keep the surface's position (the soft constraints pin its translation
/// only), so a surface re-aligned at \f$ t \f$ lies on the aligned surface of the flow at
/// \f$ t \f$ through its anchor, as one aligned at \f$ t \f$ from the initial patch does,
/// but its faces may sit elsewhere on it.  In the tests (a moving point source, orthogonal; a
/// swirl whose axis drifts, tangential) the warm-started and the cold surfaces lie on the same
/// sphere to 5e-4 and on the same cylinder to 2e-2, and their vertices slide apart by about 3%
/// of the distance the flow moved.  A surface that follows the flow from \f$ t_0 \f$ through
/// \f$ t_1 < \dots < t_k \f$ is reproduced exactly by replaying the same times in the same
/// order.
///
/// The unsteady field is held by value: models of `UnsteadyFlowField_3` are cheap to copy
/// (`Unsteady_flow_field_3` shares its steps between copies).
///
/// \tparam UnsteadyFlowField a model of `UnsteadyFlowField_3`
///
/// \cgalModels `FlowField_3`
///
/// \sa `Unsteady_flow_field_3`, `Flow_aligned_deformation`, `integrate_pathline()`
template <typename UnsteadyFlowField>
class Time_slice_flow_field_3 {
public:
  /// \name Types
  /// @{

  /// the type of the unsteady field
  typedef UnsteadyFlowField Unsteady_flow_field;
  /// @}

  /// \name Creation
  /// @{

  /// the flow `field` at time `t`.
  /// \throws std::invalid_argument if `t` is not finite
  Time_slice_flow_field_3(const UnsteadyFlowField& field, double t) : m_field(field), m_time(checked(t)) {}
  /// @}

  /// \name Time
  /// @{

  /// the time at which the flow is sampled
  double time() const { return m_time; }

  /// samples the flow at time `t` from now on.
  /// \throws std::invalid_argument if `t` is not finite (the time is then unchanged)
  void set_time(double t) { m_time = checked(t); }
  /// @}

  /// \name Evaluation
  /// @{

  /// returns `field(p, time())`: the velocity at `p`, or `std::nullopt` where the unsteady field
  /// has none at that time (outside its domain or its time interval).
  template <typename Point_3>
  auto operator()(const Point_3& p) const -> decltype(std::declval<const UnsteadyFlowField&>()(p, 0.))
  {
    return m_field(p, m_time);
  }
  /// @}

  /// \name Access
  /// @{

  /// the unsteady field
  const UnsteadyFlowField& unsteady_field() const { return m_field; }
  /// @}

private:
  static double checked(double t)
  {
    if (!std::isfinite(t)) {
      std::ostringstream msg;
      msg << "Time_slice_flow_field_3: the time is " << t << "; expected a finite number";
      throw std::invalid_argument(msg.str());
    }
    return t;
  }

  UnsteadyFlowField m_field;
  double m_time;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_TIME_SLICE_FLOW_FIELD_3_H
