// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A model of `UnsteadyFlowField_3` given by steps v_0, ..., v_n (models of `FlowField_3`) at
// times t_0 < ... < t_n:  v(p, t) = (1 - s) v_i(p) + s v_{i+1}(p),  s = (t - t_i) / (t_{i+1} - t_i)
// for t in [t_i, t_{i+1}] (only v_i at t = t_i), and std::nullopt for t outside [t_0, t_n] or
// where a step with a nonzero weight is outside its domain.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_UNSTEADY_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_UNSTEADY_FLOW_FIELD_3_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// A time series of steady fields with linear interpolation in time, a model of
/// `UnsteadyFlowField_3`.
///
/// Step `i` is a field `v_i` (any model of `FlowField_3`: `Regular_grid_flow_field_3`,
/// `Unstructured_flow_field_3`, an analytic flow, a lambda) valid at time `t_i`, with
/// `t_0 < t_1 < ... < t_n`.  For `t` in `[t_i, t_{i+1}]` the velocity is
/// \f$ v(p, t) = (1 - s)\, v_i(p) + s\, v_{i+1}(p) \f$ with
/// \f$ s = (t - t_i) / (t_{i+1} - t_i) \f$: exact for fields linear in time.  At a step's own
/// time only that step is queried, so the steps' values are returned exactly and a step may be
/// defined where its neighbours are not.  `std::nullopt` is returned for `t` outside
/// `[t_0, t_n]` (or NaN), and where a step with a nonzero weight returns `std::nullopt`.
///
/// The steps are shared between copies (through a `std::shared_ptr`), so copying the field is
/// cheap.  A query costs a binary search over the times and one or two queries of the steps.
///
/// \tparam FlowField a model of `FlowField_3` whose call operator returns
///         `std::optional<Vector_3>` for a `Point_3` of a CGAL kernel
///
/// \cgalModels `UnsteadyFlowField_3`
///
/// \sa `IO::read_PVD_flow_field()`
template <typename FlowField>
class Unsteady_flow_field_3 {
public:
  /// \name Types
  /// @{

  /// the type of the steps
  typedef FlowField Flow_field;
  /// @}

  /// \name Creation
  /// @{

  /// creates an empty series: no step, `std::nullopt` at every time.  It is what
  /// `IO::read_PVD_flow_field()` fills.
  Unsteady_flow_field_3() : m_storage(std::make_shared<const Storage>()) {}

  /// creates the series from its times and steps (pass `steps` with `std::move()` to avoid a
  /// copy).
  ///
  /// \throws std::invalid_argument naming the faulty index and values if `times` and `steps`
  ///         differ in size, there is no step, a time is not finite, or the times are not
  ///         strictly increasing.
  Unsteady_flow_field_3(std::vector<double> times, std::vector<FlowField> steps)
  {
    std::ostringstream msg;
    msg.precision(17);
    msg << "Unsteady_flow_field_3: ";
    if (times.size() != steps.size()) {
      msg << "times.size() is " << times.size() << " but steps.size() is " << steps.size()
          << "; expected one time per step";
      throw std::invalid_argument(msg.str());
    }
    if (times.empty()) {
      msg << "no step; expected at least one";
      throw std::invalid_argument(msg.str());
    }
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (!std::isfinite(times[i])) {
        msg << "times[" << i << "] is " << times[i] << "; expected a finite number";
        throw std::invalid_argument(msg.str());
      }
      if (i > 0 && !(times[i - 1] < times[i])) {
        msg << "times[" << i - 1 << "] = " << times[i - 1] << " and times[" << i << "] = " << times[i]
            << "; expected strictly increasing times";
        throw std::invalid_argument(msg.str());
      }
    }
    auto s = std::make_shared<Storage>();
    s->times = std::move(times);
    s->steps = std::move(steps);
    m_storage = std::move(s);
  }

  /// @}

  /// \name Evaluation
  /// @{

  /// returns the velocity at `p` at time `t` interpolated linearly between the two steps
  /// around `t` (only the step at `t` if there is one), or `std::nullopt` if `t` is outside
  /// `[start_time(), end_time()]` or one of these steps with a nonzero weight returns
  /// `std::nullopt`.
  template <typename Point_3>
  auto operator()(const Point_3& p, double t) const -> decltype(std::declval<const FlowField&>()(p))
  {
    const std::vector<double>& times = m_storage->times;
    if (times.empty() || !(t >= times.front() && t <= times.back()))
      return std::nullopt;
    // The first step after t; t = times.back() is the last step's own time.
    const std::size_t j =
        static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    if (j == times.size() || times[j - 1] == t)
      return m_storage->steps[j - 1](p);
    const std::size_t i = j - 1;
    const double s = (t - times[i]) / (times[j] - times[i]);
    // s is in (0, 1) here, but may round to 0 or 1 for t within an ulp of a step's time.
    if (s <= 0.)
      return m_storage->steps[i](p);
    if (s >= 1.)
      return m_storage->steps[j](p);
    const auto a = m_storage->steps[i](p);
    if (!a)
      return std::nullopt;
    const auto b = m_storage->steps[j](p);
    if (!b)
      return std::nullopt;
    return (1. - s) * *a + s * *b;
  }

  /// @}

  /// \name Access
  /// @{

  /// the number of steps
  std::size_t number_of_steps() const { return m_storage->times.size(); }
  /// the time of step `i`
  /// \pre `i < number_of_steps()`
  double time(std::size_t i) const
  {
    CGAL_precondition(i < number_of_steps());
    return m_storage->times[i];
  }
  /// step `i`
  /// \pre `i < number_of_steps()`
  const FlowField& step(std::size_t i) const
  {
    CGAL_precondition(i < number_of_steps());
    return m_storage->steps[i];
  }
  /// the time of the first step
  /// \pre `number_of_steps() > 0`
  double start_time() const
  {
    CGAL_precondition(number_of_steps() > 0);
    return m_storage->times.front();
  }
  /// the time of the last step
  /// \pre `number_of_steps() > 0`
  double end_time() const
  {
    CGAL_precondition(number_of_steps() > 0);
    return m_storage->times.back();
  }

  /// @}

private:
  struct Storage {
    std::vector<double> times;
    std::vector<FlowField> steps;
  };
  std::shared_ptr<const Storage> m_storage;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_UNSTEADY_FLOW_FIELD_3_H
