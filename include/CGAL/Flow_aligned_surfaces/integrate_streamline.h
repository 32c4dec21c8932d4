// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stream lines and path lines: the curves x(τ) with
//
//   dx/dτ = σ v(x)              (stream line of a steady field v, a model of FlowField_3), or
//   dx/dτ = σ v(x, t0 + σ τ)    (path line of an unsteady field, UnsteadyFlowField_3),
//
// x(0) = seed, σ = +1 (forward) or -1 (backward), τ in [0, T] where T is the first of: the line
// leaves the domain, the speed vanishes (stagnation), the arc length s(τ) = ∫ |dx/dτ| dτ reaches
// max_length, τ reaches max_time, max_number_of_steps steps were taken.  Integrated by the
// adaptive Dormand-Prince 5(4) pair with dense output (internal/Dormand_prince_integrator.h);
// s(τ) is the 5-point Gauss-Legendre rule on the derivative of the dense output of each step.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTEGRATE_STREAMLINE_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTEGRATE_STREAMLINE_H

#include <CGAL/Flow_aligned_surfaces/internal/Dormand_prince_integrator.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/iterator.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesRef
/// The direction of integration from the seed of a stream line or path line.
enum class Integration_direction {
  FORWARD,  ///< along \f$ v \f$ (increasing time)
  BACKWARD, ///< along \f$ -v \f$ (decreasing time)
  BOTH      ///< backward and forward: the backward half reversed, then the forward half
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// Why the integration of one direction of a stream line or path line stopped.
enum class Streamline_termination {
  NOT_INTEGRATED,      ///< this direction was not requested
  SEED_OUTSIDE_DOMAIN, ///< the field is not defined at the seed (nothing is written)
  LEFT_DOMAIN,         ///< the line reached the boundary of the domain (located by bisection)
  STAGNATION,          ///< the speed fell to 1e-10 × the speed at the seed (or is 0 there)
  MAX_LENGTH,          ///< the arc length reached `max_length` (the last point lies on it)
  MAX_TIME,            ///< the integration time reached `max_time` (the last point lies on it)
  MAX_NUMBER_OF_STEPS, ///< `max_number_of_steps` steps were taken
  STEP_UNDERFLOW       ///< the step needed for the tolerance fell below 1e-14 (a singularity)
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// returns the name of `t` (`"LEFT_DOMAIN"`, ...), for messages.
inline const char* to_string(Streamline_termination t)
{
  switch (t) {
  case Streamline_termination::NOT_INTEGRATED:
    return "NOT_INTEGRATED";
  case Streamline_termination::SEED_OUTSIDE_DOMAIN:
    return "SEED_OUTSIDE_DOMAIN";
  case Streamline_termination::LEFT_DOMAIN:
    return "LEFT_DOMAIN";
  case Streamline_termination::STAGNATION:
    return "STAGNATION";
  case Streamline_termination::MAX_LENGTH:
    return "MAX_LENGTH";
  case Streamline_termination::MAX_TIME:
    return "MAX_TIME";
  case Streamline_termination::MAX_NUMBER_OF_STEPS:
    return "MAX_NUMBER_OF_STEPS";
  case Streamline_termination::STEP_UNDERFLOW:
    return "STEP_UNDERFLOW";
  }
  return "?";
}

/// \ingroup PkgFlowAlignedSurfacesRef
/// What the integration of one direction of a stream line or path line did.
struct Streamline_half_report {
  /// why it stopped
  Streamline_termination termination = Streamline_termination::NOT_INTEGRATED;
  /// the arc length of this half
  double length = 0;
  /// the integration time \f$ \tau = |t - t_0| \f$ of this half
  double integration_time = 0;
  /// the number of accepted integration steps
  std::size_t number_of_accepted_steps = 0;
  /// the number of rejected trial steps (error above the tolerance)
  std::size_t number_of_rejected_steps = 0;
  /// the number of field evaluations
  std::size_t number_of_field_evaluations = 0;
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// What `integrate_streamline()` and `integrate_pathline()` did, per direction.
struct Streamline_report {
  Streamline_half_report backward; ///< the backward half (`NOT_INTEGRATED` unless requested)
  Streamline_half_report forward;  ///< the forward half (`NOT_INTEGRATED` unless requested)
  /// the number of points written (0 if the seed is outside the domain)
  std::size_t number_of_points = 0;
  /// whether the seed is inside the domain
  bool seed_inside_domain() const
  {
    return backward.termination != Streamline_termination::SEED_OUTSIDE_DOMAIN &&
           forward.termination != Streamline_termination::SEED_OUTSIDE_DOMAIN;
  }
  /// the arc length of the whole line
  double length() const { return backward.length + forward.length; }
};

namespace internal {

struct Streamline_options {
  Integration_tolerances tolerances;
  double max_length = std::numeric_limits<double>::infinity();
  double max_time = std::numeric_limits<double>::infinity();
  std::size_t max_number_of_steps = 100000;
  Integration_direction direction = Integration_direction::FORWARD;
  double output_time_step = 0;   // 0: the steps
  double output_length_step = 0; // 0: the steps
};

inline void check_positive_finite(const std::string& caller, const char* name, double value)
{
  if (!(value > 0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << caller << ": " << name << " is " << value << "; expected a positive finite number";
    throw std::invalid_argument(msg.str());
  }
}

template <class NamedParameters>
Streamline_options read_streamline_options(const NamedParameters& np, const std::string& caller)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Streamline_options o;
  // Each given value is checked; absent ones keep the defaults (the limits: none).
  const auto read = [&](auto tag, const char* name, double& value) {
    if constexpr (!is_default_parameter<NamedParameters, decltype(tag)>::value) {
      value = choose_parameter(get_parameter(np, tag), value);
      check_positive_finite(caller, name, value);
    }
  };
  read(internal_np::relative_tolerance_t(), "relative_tolerance", o.tolerances.relative);
  read(internal_np::absolute_tolerance_t(), "absolute_tolerance", o.tolerances.absolute);
  read(internal_np::max_length_t(), "max_length", o.max_length);
  read(internal_np::max_time_t(), "max_time", o.max_time);
  read(internal_np::output_time_step_t(), "output_time_step", o.output_time_step);
  read(internal_np::output_length_step_t(), "output_length_step", o.output_length_step);
  o.max_number_of_steps =
      choose_parameter(get_parameter(np, internal_np::max_number_of_steps_t()), o.max_number_of_steps);
  if (o.max_number_of_steps == 0)
    throw std::invalid_argument(caller + ": max_number_of_steps is 0; expected at least 1");
  o.direction = choose_parameter(get_parameter(np, internal_np::integration_direction_t()), o.direction);
  if (o.direction != Integration_direction::FORWARD && o.direction != Integration_direction::BACKWARD &&
      o.direction != Integration_direction::BOTH)
    throw std::invalid_argument(caller + ": integration_direction is not FORWARD, BACKWARD or BOTH");
  if (o.output_time_step > 0 && o.output_length_step > 0)
    throw std::invalid_argument(caller + ": output_time_step and output_length_step are both given; "
                                         "expected at most one");
  return o;
}

// Arc length of the dense output of the last accepted step between τa and τb (5-point
// Gauss-Legendre on |dx/dτ|).
template <class Integrator>
double dense_arc_length(const Integrator& dp, double tau_a, double tau_b)
{
  static constexpr double nodes[5] = {0.5 - 0.5 * 0.906179845938663993, 0.5 - 0.5 * 0.538469310105683091, 0.5,
                                      0.5 + 0.5 * 0.538469310105683091, 0.5 + 0.5 * 0.906179845938663993};
  static constexpr double weights[5] = {0.5 * 0.236926885056189088, 0.5 * 0.478628670499366468,
                                        0.5 * 0.568888888888888889, 0.5 * 0.478628670499366468,
                                        0.5 * 0.236926885056189088};
  double s = 0;
  for (int i = 0; i < 5; ++i)
    s += weights[i] * dp.dense_derivative(tau_a + nodes[i] * (tau_b - tau_a)).norm();
  return s * (tau_b - tau_a);
}

// The τ in [τ_prev, τ] of the last step at which the arc length from τ_prev is `ds`
// (0 ≤ ds ≤ the step's length): bisection, 200 halvings at most.
template <class Integrator>
double parameter_at_arc_length(const Integrator& dp, double ds)
{
  double lo = dp.previous_parameter(), hi = dp.parameter();
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (!(lo < mid && mid < hi))
      break;
    (dense_arc_length(dp, dp.previous_parameter(), mid) < ds ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// One direction from the seed; `emit(x, τ)` receives the points after the seed and their
// integration times, in order.
template <class Field, class Emit>
Streamline_half_report integrate_half_line(const Field& f, const Eigen::Vector3d& seed, double t0,
                                           int direction, const Streamline_options& o, Emit emit)
{
  Streamline_half_report report;
  Dormand_prince_integrator<Field> dp(f, seed, t0, direction, o.tolerances);
  if (!dp.is_start_inside()) {
    report.termination = Streamline_termination::SEED_OUTSIDE_DOMAIN;
    return report;
  }
  double length = 0;           // arc length at dp.previous_parameter() during a step
  double last_emitted = 0;     // τ of the last point written (the seed: 0)
  std::size_t next_sample = 1; // the next multiple of the output step
  Streamline_termination termination = Streamline_termination::MAX_NUMBER_OF_STEPS;
  while (dp.number_of_accepted_steps() < o.max_number_of_steps) {
    const Step_result r = dp.step();
    if (r == Step_result::STAGNATION || r == Step_result::STEP_UNDERFLOW) {
      termination = r == Step_result::STAGNATION ? Streamline_termination::STAGNATION
                                                 : Streamline_termination::STEP_UNDERFLOW;
      break;
    }
    const double tau0 = dp.previous_parameter();
    const double step_length = dense_arc_length(dp, tau0, dp.parameter());
    // Where this step ends: at a limit inside it, else at its end.
    double tau_end = dp.parameter(), length_end = length + step_length;
    bool stop = r == Step_result::LEFT_DOMAIN;
    Streamline_termination reason = Streamline_termination::LEFT_DOMAIN;
    if (length_end >= o.max_length) {
      tau_end = parameter_at_arc_length(dp, o.max_length - length);
      length_end = o.max_length;
      stop = true;
      reason = Streamline_termination::MAX_LENGTH;
    }
    if (tau_end >= o.max_time) {
      tau_end = o.max_time;
      length_end = length + dense_arc_length(dp, tau0, tau_end);
      stop = true;
      reason = Streamline_termination::MAX_TIME;
    }
    // The samples inside (τ0, τ_end] (inside (τ0, τ_end) when the line ends there: its last
    // point is written below); sample k at τ = k Δτ or s = k Δs.
    const auto before_end = [stop](double value, double end) { return stop ? value < end : value <= end; };
    if (o.output_time_step > 0) {
      for (; before_end(next_sample * o.output_time_step, tau_end); ++next_sample) {
        last_emitted = next_sample * o.output_time_step;
        emit(dp.dense_output(last_emitted), last_emitted);
      }
    }
    else if (o.output_length_step > 0) {
      for (; before_end(next_sample * o.output_length_step, length_end); ++next_sample) {
        last_emitted = parameter_at_arc_length(dp, next_sample * o.output_length_step - length);
        emit(dp.dense_output(last_emitted), last_emitted);
      }
    }
    const bool every_step = !(o.output_time_step > 0) && !(o.output_length_step > 0);
    if ((every_step || stop) && tau_end > last_emitted) {
      last_emitted = tau_end;
      emit(tau_end == dp.parameter() ? dp.position() : dp.dense_output(tau_end), tau_end);
    }
    report.integration_time = tau_end;
    length = length_end;
    if (stop) {
      termination = reason;
      break;
    }
  }
  report.termination = termination;
  report.length = length;
  report.number_of_accepted_steps = dp.number_of_accepted_steps();
  report.number_of_rejected_steps = dp.number_of_rejected_steps();
  report.number_of_field_evaluations = dp.number_of_evaluations();
  return report;
}

// Both halves as requested, written to `out` as points of the kernel of `Point_3` (the seed once),
// and the time of each point to `out_times`: t0 - τ on the backward half, t0 + τ on the forward one.
template <class Point_3, class ConstructPoint, class Field, class OutputIterator, class TimeOutputIterator>
Streamline_report integrate_line(const Field& f, const Point_3& seed, double t0, OutputIterator& out,
                                 TimeOutputIterator out_times, const ConstructPoint& construct_point,
                                 const Streamline_options& o, const std::string& caller)
{
  const Eigen::Vector3d x0(CGAL::to_double(seed.x()), CGAL::to_double(seed.y()), CGAL::to_double(seed.z()));
  if (!x0.allFinite()) {
    std::ostringstream msg;
    msg.precision(17);
    msg << caller << ": the seed (" << x0[0] << ", " << x0[1] << ", " << x0[2] << ") is not finite";
    throw std::invalid_argument(msg.str());
  }
  Streamline_report report;
  std::vector<std::pair<Eigen::Vector3d, double>> backward, forward; // points and τ
  const auto collect = [](std::vector<std::pair<Eigen::Vector3d, double>>& points) {
    return [&points](const Eigen::Vector3d& x, double tau) { points.emplace_back(x, tau); };
  };
  if (o.direction != Integration_direction::FORWARD)
    report.backward = integrate_half_line(f, x0, t0, -1, o, collect(backward));
  if (o.direction != Integration_direction::BACKWARD)
    report.forward = integrate_half_line(f, x0, t0, 1, o, collect(forward));
  if (!report.seed_inside_domain()) {
    report.backward.termination = report.forward.termination = Streamline_termination::SEED_OUTSIDE_DOMAIN;
    return report;
  }
  const auto write = [&](const Eigen::Vector3d& x, double t) {
    *out++ = construct_point(x[0], x[1], x[2]);
    *out_times++ = t;
  };
  for (auto b = backward.rbegin(); b != backward.rend(); ++b)
    write(b->first, t0 - b->second);
  write(x0, t0);
  for (const auto& [x, tau] : forward)
    write(x, t0 + tau);
  report.number_of_points = backward.size() + 1 + forward.size();
  return report;
}

// The output iterator of the named parameter `time_output_iterator`, or one that drops the times.
template <class NamedParameters>
auto time_output_iterator(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::time_output_iterator_t()),
                                      CGAL::Emptyset_iterator());
}

template <class Vector_3>
Eigen::Vector3d to_eigen_vector(const Vector_3& v)
{
  return Eigen::Vector3d(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
}

// The kernel: `geom_traits` if given, else the kernel of `Point_3`.
template <class Point_3, class NamedParameters>
auto streamline_geom_traits(const NamedParameters& np)
{
  using Kernel = typename CGAL::Kernel_traits<Point_3>::Kernel;
  return parameters::choose_parameter<Kernel>(parameters::get_parameter(np, CGAL::internal_np::geom_traits));
}

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Integrates the stream line of `field` through `seed` and writes its points to
`out_points`: the curve \f$ x(\tau) \f$ with \f$ dx/d\tau = \pm v(x) \f$, \f$ x(0) = \f$ `seed`.

The integrator is the adaptive embedded Runge–Kutta pair of Dormand and Prince, 5(4), with
Hairer's step-size control and its 4th-order dense output: each step keeps the local error below
`absolute_tolerance + relative_tolerance |x|` (componentwise, in the root-mean-square norm).
Each direction stops at the first of:
- the boundary of the domain (the field returns `std::nullopt` or a non-finite vector): the step
  that leaves is shortened by bisection until its end is inside and within
  `absolute_tolerance + relative_tolerance |x|` of the exit; that end is the last point;
- stagnation: the speed falls to \f$ 10^{-10} \f$ times the speed at the seed (at once if the
  field is zero at the seed);
- `max_length` of arc length or `max_time` of integration time: the last point is the dense
  output exactly at that limit;
- `max_number_of_steps` accepted steps;
- a step below \f$ 10^{-14} \f$ needed for the tolerance (a singularity).

The points are the ends of the accepted steps (or samples of the dense output every
`output_time_step` or `output_length_step`, with the last point of each direction always
written).  With `Integration_direction::BOTH` the backward half comes first, reversed, so the
points follow the flow; the seed is written once.

\tparam FlowField a model of `FlowField_3`
\tparam Point_3 a point type of a CGAL kernel, the one `field` takes
\tparam OutputIterator an output iterator accepting `Point_3`
\tparam NamedParameters a sequence of named parameters

\param field the flow field
\param seed the seed point
\param out_points receives the points of the stream line in flow order
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{integration_direction}
    \cgalParamDescription{forward, backward or both}
    \cgalParamType{`Integration_direction`}
    \cgalParamDefault{`Integration_direction::FORWARD`}
  \cgalParamNEnd
  \cgalParamNBegin{relative_tolerance}
    \cgalParamDescription{the relative local error tolerance}
    \cgalParamType{`double`, positive and finite}
    \cgalParamDefault{`1e-8`}
  \cgalParamNEnd
  \cgalParamNBegin{absolute_tolerance}
    \cgalParamDescription{the absolute local error tolerance (a length)}
    \cgalParamType{`double`, positive and finite}
    \cgalParamDefault{`1e-10`}
  \cgalParamNEnd
  \cgalParamNBegin{max_length}
    \cgalParamDescription{the largest arc length of each direction}
    \cgalParamType{`double`, positive and finite}
    \cgalParamDefault{no limit}
  \cgalParamNEnd
  \cgalParamNBegin{max_time}
    \cgalParamDescription{the largest integration time \f$ \tau \f$ of each direction}
    \cgalParamType{`double`, positive and finite}
    \cgalParamDefault{no limit}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_steps}
    \cgalParamDescription{the largest number of accepted steps of each direction}
    \cgalParamType{`std::size_t`, at least 1}
    \cgalParamDefault{`100000`}
  \cgalParamNEnd
  \cgalParamNBegin{output_time_step}
    \cgalParamDescription{write the dense output every Δτ instead of the steps' ends}
    \cgalParamType{`double`, positive and finite}
    \cgalParamDefault{the steps' ends}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the kernel that constructs the points given to `field` and written}
    \cgalParamType{a model of `Kernel` whose `Point_3` is `Point_3`}
    \cgalParamDefault{the kernel of `Point_3`}
  \cgalParamNEnd
  \cgalParamNBegin{output_length_step}
    \cgalParamDescription{write the dense output every Δs of arc length instead of the steps' ends}
    \cgalParamType{`double`, positive and finite}
    \cgalParamDefault{the steps' ends}
  \cgalParamNEnd
  \cgalParamNBegin{time_output_iterator}
    \cgalParamDescription{receives the time of every point written, in the same order: the signed
      integration time \f$ \pm\tau \f$ (negative on the backward half, 0 at the seed); for
      `integrate_pathline()` the time \f$ t_0 \pm \tau \f$ of the path line's point}
    \cgalParamType{an output iterator accepting `double`}
    \cgalParamDefault{the times are not written}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the report: per direction why it stopped, its length, integration time and numbers of
steps; the number of points written.  If the seed is outside the domain nothing is written and
both directions report `Streamline_termination::SEED_OUTSIDE_DOMAIN`.
\throws std::invalid_argument naming the parameter if a tolerance, limit or output step is not
positive and finite, `max_number_of_steps` is 0, both output steps are given, or the seed is
not finite; nothing is written then.
\sa `integrate_pathline()`, `sample_seed_points()`
*/
template <class FlowField, class Point_3, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
Streamline_report integrate_streamline(const FlowField& field, const Point_3& seed, OutputIterator out_points,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "integrate_streamline";
  const internal::Streamline_options o = internal::read_streamline_options(np, caller);
  const auto construct_point = internal::streamline_geom_traits<Point_3>(np).construct_point_3_object();
  const auto f = [&](const Eigen::Vector3d& x, double) -> std::optional<Eigen::Vector3d> {
    const auto v = field(construct_point(x[0], x[1], x[2]));
    if (!v)
      return std::nullopt;
    return internal::to_eigen_vector(*v);
  };
  return internal::integrate_line(f, seed, 0., out_points, internal::time_output_iterator(np), construct_point,
                                  o, caller);
}

/*!
\ingroup PkgFlowAlignedSurfacesRef

\brief Integrates the path line of the unsteady `field` released at `seed` at time `t0` and
writes its points to `out_points`: the curve \f$ x(t) \f$ with \f$ dx/dt = v(x, t) \f$,
\f$ x(t_0) = \f$ `seed`, forward (\f$ t \ge t_0 \f$) and/or backward (\f$ t \le t_0 \f$) in time.

The method, limits, reasons and named parameters are those of `integrate_streamline()`, with
the integration time \f$ \tau = |t - t_0| \f$: `max_time` bounds \f$ |t - t_0| \f$, and a line
also stops (`LEFT_DOMAIN`) where the field's time range ends.  The point written at step end or
sample \f$ \tau \f$ belongs to time \f$ t_0 \pm \tau \f$ (exactly \f$ t_0 \pm k\,\Delta\tau \f$
with `output_time_step`).

\tparam UnsteadyFlowField a model of `UnsteadyFlowField_3` (such as `Unsteady_flow_field_3`)
\tparam Point_3 a point type of a CGAL kernel, the one `field` takes
\tparam OutputIterator an output iterator accepting `Point_3`
\tparam NamedParameters a sequence of named parameters

\param field the unsteady flow field
\param seed the seed point
\param t0 the release time
\param out_points receives the points of the path line in time order
\param np an optional sequence of named parameters: those of `integrate_streamline()`

\returns the report, as for `integrate_streamline()`.
\throws std::invalid_argument as `integrate_streamline()`, and if `t0` is not finite.
\sa `integrate_streamline()`, `Unsteady_flow_field_3`
*/
template <class UnsteadyFlowField, class Point_3, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
Streamline_report integrate_pathline(const UnsteadyFlowField& field, const Point_3& seed, double t0,
                                     OutputIterator out_points,
                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string caller = "integrate_pathline";
  internal::Streamline_options o = internal::read_streamline_options(np, caller);
  // No step past max_time: a line that ends where its time series ends would otherwise sample
  // the field after it, and stop short of it as a line leaving the time range.
  o.tolerances.max_parameter = o.max_time;
  if (!std::isfinite(t0)) {
    std::ostringstream msg;
    msg << caller << ": t0 is " << t0 << "; expected a finite time";
    throw std::invalid_argument(msg.str());
  }
  const auto construct_point = internal::streamline_geom_traits<Point_3>(np).construct_point_3_object();
  const auto f = [&](const Eigen::Vector3d& x, double t) -> std::optional<Eigen::Vector3d> {
    const auto v = field(construct_point(x[0], x[1], x[2]), t);
    if (!v)
      return std::nullopt;
    return internal::to_eigen_vector(*v);
  };
  return internal::integrate_line(f, seed, t0, out_points, internal::time_output_iterator(np), construct_point,
                                  o, caller);
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTEGRATE_STREAMLINE_H
