// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The embedded Runge-Kutta pair of Dormand and Prince, 5(4), for
//
//   dx/dτ = σ f(x, t0 + σ τ),  x(0) = x0,  τ ≥ 0,  σ = ±1,
//
// with x in R^3: seven stages per step, the last one the first of the next step (FSAL); the
// local error of the 4th-order solution, measured in the norm
//   err = sqrt(1/3 Σ_i (e_i / (absolute + relative max(|x_i|, |x_new,i|)))^2),
// decides acceptance (err ≤ 1); the next step is h (1/err)^0.17 err_prev^0.04 (Hairer's PI
// control, clamped to [h/10, 5h] with safety 0.9); the starting step is Hairer's estimate
// (Hairer, Nørsett, Wanner, Solving ODE I, II.4 and the code DOPRI5).  Dense output is DOPRI5's
// 4th-order continuous extension x(τ_prev + θ h), θ in [0, 1], of the last accepted step.
//
// The field may leave its domain (returns std::nullopt): a step with a stage outside is
// shortened by bisection on its length until the end point is inside and within the boundary
// tolerance (along the path) of the first rejected length; that shortened step is accepted.
//
// A field whose samples come in rounds (batched_sampling.h) may have none yet at a point: it has
// `bool waiting() const`, true once it answered such a point; the step then stops there
// (`SUSPENDED`), and the integrator is to be dropped for a copy taken before the step.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_DORMAND_PRINCE_INTEGRATOR_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_DORMAND_PRINCE_INTEGRATOR_H

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// Tolerances and step limits of `Dormand_prince_integrator`.
struct Integration_tolerances {
  double relative = 1e-8;  ///< relative local error tolerance
  double absolute = 1e-10; ///< absolute local error tolerance (a length)
  double initial_step = 0; ///< first trial step in τ; 0: automatic (Hairer's starting step)
  double max_step = std::numeric_limits<double>::infinity(); ///< largest step in τ
  /// the τ no step goes beyond (the end of the integration): a step is shortened to end there,
  /// so that no stage samples the field after it (an unsteady field may end there)
  double max_parameter = std::numeric_limits<double>::infinity();
  double min_step = 1e-14; ///< smallest step in τ before `STEP_UNDERFLOW`
  /// the distance (along the path) within which the exit point is located when the line
  /// leaves the domain; 0: `absolute + relative |x|` at the current point
  double boundary = 0;
  /// the speed |f| at or below which the line stagnates; a negative value: `1e-10 |f(x0, t0)|`
  double stagnation_speed = -1;
};

/// What `Dormand_prince_integrator::step()` did.
enum class Step_result {
  ACCEPTED,      ///< one step within tolerance, inside the domain
  LEFT_DOMAIN,   ///< the last (shortened) step ends within the boundary tolerance of the exit
  SUSPENDED,     ///< the field has no sample yet at a point of the step; drop this integrator
  STAGNATION,    ///< the speed at the current point is at most the stagnation speed; no step
  STEP_UNDERFLOW ///< the step needed for the tolerance is below `min_step`; no step
};

// See the top of the file.  `Field`: std::optional<Eigen::Vector3d>(const Eigen::Vector3d& x,
// double t); std::nullopt (or a non-finite vector) means outside the domain.
template <class Field, class = void>
struct Field_may_wait : std::false_type {
};
template <class Field>
struct Field_may_wait<Field, std::void_t<decltype(std::declval<const Field&>().waiting())>> : std::true_type {
};

template <class Field>
class Dormand_prince_integrator {
public:
  Dormand_prince_integrator(const Field& f, const Eigen::Vector3d& x0, double t0, int direction,
                            Integration_tolerances tol = {})
      : m_f(f), m_t0(t0), m_sigma(direction < 0 ? -1. : 1.), m_tol(tol), m_x(x0), m_x_prev(x0)
  {
    m_start_inside = evaluate(m_x, 0., m_k1);
    if (!m_start_inside)
      return;
    m_stagnation_speed = m_tol.stagnation_speed >= 0 ? m_tol.stagnation_speed : 1e-10 * m_k1.norm();
    m_dense[0] = m_x;
  }

  /// The number of values `write_state()` writes.
  static constexpr std::size_t state_size = 44;

  /// The integrator that `write_state()` wrote into `state` (`state_size` values), sampling `f`:
  /// it steps exactly as the one that wrote it, for integrating on where another process holds
  /// the field.
  Dormand_prince_integrator(const Field& f, const double* state) : m_f(f)
  {
    for_each_state_value(*this, [&state](auto& v) { v = static_cast<std::decay_t<decltype(v)>>(*state++); });
  }

  /// The current point of the integrator that wrote `state`, without making it.
  static Eigen::Vector3d position_in_state(const double* state)
  {
    // for_each_state_value()'s order: t0, σ, the 8 tolerances, start_inside, the stagnation
    // speed, then x.
    constexpr std::size_t x = 12;
    return Eigen::Vector3d(state[x], state[x + 1], state[x + 2]);
  }

  /// Writes everything but the field into `state` (`state_size` values, the exact bits; the
  /// counters are below 2^53).
  void write_state(double* state) const
  {
    for_each_state_value(*this, [&state](const auto& v) { *state++ = static_cast<double>(v); });
  }

  /// whether f(x0, t0) exists; when not, `step()` must not be called.
  bool is_start_inside() const { return m_start_inside; }

  /// Whether the field waits for a sample that this integrator asked for (a field with
  /// `waiting()`; false for any other): it is then to be dropped.
  bool waiting() const
  {
    if constexpr (Field_may_wait<Field>::value)
      return m_f.waiting();
    else
      return false;
  }

  /// one accepted step; see `Step_result`.  Leaving the domain takes two calls: the first
  /// returns `ACCEPTED` with the step shortened to end within the boundary tolerance of the exit,
  /// the second confirms it from there with a step of twice the bracket and returns
  /// `LEFT_DOMAIN` (with a step of length 0, or of at most twice the bracket; `position()` is
  /// the last point inside), or `ACCEPTED` if that step is inside after all.
  Step_result step()
  {
    if (!m_start_inside || m_k1.norm() <= m_stagnation_speed)
      return Step_result::STAGNATION;
    if (m_h == 0)
      m_h = m_tol.initial_step > 0 ? m_tol.initial_step : starting_step();
    if (waiting())
      return Step_result::SUSPENDED;
    const bool confirming = m_confirming;
    m_confirming = false;

    // Bisection state once a trial left the domain: a step of length `inside` is an accepted
    // candidate (kept in `candidate`), a step of length `outside` has a stage outside.
    constexpr double none = std::numeric_limits<double>::infinity();
    double inside = 0, outside = none;
    Trial candidate;
    bool have_candidate = false;
    double speed = m_k1.norm();
    bool rejected = false;
    // Each rejection shrinks h by a factor of at least 0.9 / 5^-... (>= 1.1) and each bisection
    // halves the bracket, so going from any h to min_step takes far fewer trials than this.
    for (int trials = 0; trials < 4000; ++trials) {
      const bool bisecting = outside < none;
      if (bisecting) {
        const double boundary_tolerance =
            m_tol.boundary > 0 ? m_tol.boundary : m_tol.absolute + m_tol.relative * m_x.cwiseAbs().maxCoeff();
        if ((outside - inside) * speed <= boundary_tolerance || outside - inside <= m_tol.min_step ||
            m_tau + inside == m_tau + outside) {
          if (!have_candidate) { // a step within the tolerance leaves: the boundary is here
            accept_zero_step();
            return Step_result::LEFT_DOMAIN;
          }
          accept(candidate);
          if (confirming) // located with steps of at most twice the bracket: accurate stages
            return Step_result::LEFT_DOMAIN;
          // The bracket was found with the stages of a long step, whose points may leave the
          // domain before the path does (at a grazing exit); the next call confirms the exit
          // from the new point with a step of twice the bracket, or goes on if that is inside.
          m_h = std::max(2. * (outside - inside), 4. * m_tol.min_step);
          m_confirming = true;
          return Step_result::ACCEPTED;
        }
      }
      const double left = m_tol.max_parameter - m_tau;
      const double h = bisecting ? 0.5 * (inside + outside) : std::min({m_h, m_tol.max_step, left});
      if (!bisecting && (h < m_tol.min_step || m_tau + h == m_tau))
        return Step_result::STEP_UNDERFLOW;
      Trial trial;
      if (!attempt(h, trial, speed)) {
        if (waiting())
          return Step_result::SUSPENDED;
        outside = h;
        continue;
      }
      if (trial.error > 1.) {
        ++m_number_of_rejected;
        if (have_candidate) { // the boundary is farther than an accurate step: take the candidate
          m_h = candidate.h;
          accept(candidate);
          return Step_result::ACCEPTED;
        }
        // Accuracy, not the boundary, limits this step: back to ordinary step-size control.
        outside = none;
        m_h = h / std::min(1. / min_factor, std::pow(trial.error, exponent) / safety);
        rejected = true;
        continue;
      }
      if (!bisecting) {
        m_h = next_step(h, trial.error, rejected);
        accept(trial);
        return Step_result::ACCEPTED;
      }
      inside = h;
      candidate = trial;
      have_candidate = true;
    }
    if (have_candidate) {
      accept(candidate);
      return Step_result::LEFT_DOMAIN;
    }
    return Step_result::STEP_UNDERFLOW;
  }

  /// `step()`, except that a step the field suspends leaves the integrator as it was, so that
  /// the call can be made again once the field has the samples (a task run in rounds:
  /// batched_sampling.h).  Such a step changes only the step size, the exit's confirmation and
  /// the counters: the point and the dense output change only with an accepted step.
  Step_result resumable_step()
  {
    const double h = m_h;
    const bool confirming = m_confirming;
    const std::size_t rejected = m_number_of_rejected, evaluations = m_number_of_evaluations;
    const Step_result result = step();
    if (result == Step_result::SUSPENDED) {
      m_h = h;
      m_confirming = confirming;
      m_number_of_rejected = rejected;
      m_number_of_evaluations = evaluations;
    }
    return result;
  }

  /// the current point x(τ)
  const Eigen::Vector3d& position() const { return m_x; }
  /// τ ≥ 0
  double parameter() const { return m_tau; }
  /// t0 + σ τ
  double time() const { return m_t0 + m_sigma * m_tau; }
  /// f(x, t) at the current point, times σ: the derivative dx/dτ
  const Eigen::Vector3d& derivative() const { return m_k1; }
  /// the direction σ = ±1
  int direction() const { return m_sigma < 0 ? -1 : 1; }
  /// the point at the start of the last accepted step
  const Eigen::Vector3d& previous_position() const { return m_x_prev; }
  /// τ at the start of the last accepted step
  double previous_parameter() const { return m_tau_prev; }

  /// the 4th-order continuous extension of the last accepted step at `tau`, clamped to
  /// [previous_parameter(), parameter()].
  Eigen::Vector3d dense_output(double tau) const
  {
    const double h = m_tau - m_tau_prev;
    if (!(h > 0))
      return m_x;
    const double theta = std::clamp((tau - m_tau_prev) / h, 0., 1.);
    if (theta == 1.) // exactly the step's end, not the polynomial's rounding of it
      return m_x;
    const double theta1 = 1. - theta;
    return m_dense[0] +
           theta * (m_dense[1] + theta1 * (m_dense[2] + theta * (m_dense[3] + theta1 * m_dense[4])));
  }

  /// dx/dτ of the continuous extension at `tau` (clamped as in `dense_output()`): the
  /// derivative of a degree-4 polynomial, the tangent for arc lengths within the step.
  Eigen::Vector3d dense_derivative(double tau) const
  {
    const double h = m_tau - m_tau_prev;
    if (!(h > 0))
      return m_k1;
    const double theta = std::clamp((tau - m_tau_prev) / h, 0., 1.);
    const double theta1 = 1. - theta;
    // x = r0 + θ u,  u = r1 + (1 - θ) q,  q = r2 + θ (r3 + (1 - θ) r4)
    const Eigen::Vector3d q = m_dense[2] + theta * (m_dense[3] + theta1 * m_dense[4]);
    const Eigen::Vector3d dq = m_dense[3] + (theta1 - theta) * m_dense[4];
    const Eigen::Vector3d u = m_dense[1] + theta1 * q;
    const Eigen::Vector3d du = -q + theta1 * dq;
    return (u + theta * du) / h;
  }

  std::size_t number_of_accepted_steps() const { return m_number_of_accepted; }
  std::size_t number_of_rejected_steps() const { return m_number_of_rejected; }
  /// field evaluations so far
  std::size_t number_of_evaluations() const { return m_number_of_evaluations; }

private:
  struct Trial {
    double h = 0;
    double error = 0;
    Eigen::Vector3d x;
    std::array<Eigen::Vector3d, 7> k; // k[0] = f at the start, k[6] = f at the end (FSAL)
  };

  // Hairer's PI control (DOPRI5's defaults: β = 0.04, safety 0.9, factors in [0.2, 10]).
  static constexpr double beta = 0.04;
  static constexpr double exponent = 0.2 - 0.75 * beta;
  static constexpr double safety = 0.9;
  static constexpr double min_factor = 0.2;
  static constexpr double max_factor = 10.;

  // σ f(x, t0 + σ τ); false outside the domain (std::nullopt or non-finite).
  bool evaluate(const Eigen::Vector3d& x, double tau, Eigen::Vector3d& k)
  {
    ++m_number_of_evaluations;
    if (!x.allFinite())
      return false;
    const std::optional<Eigen::Vector3d> v = m_f(x, m_t0 + m_sigma * tau);
    if (!v || !v->allFinite())
      return false;
    k = m_sigma * *v;
    return true;
  }

  // The stages of a step of length h from the current point; false if one is outside.
  // `speed` grows to the largest stage speed seen (the bisection's distance estimate).
  bool attempt(double h, Trial& t, double& speed)
  {
    static constexpr double c[7] = {0., 1. / 5, 3. / 10, 4. / 5, 8. / 9, 1., 1.};
    static constexpr double a[6][6] = {{1. / 5},
                                       {3. / 40, 9. / 40},
                                       {44. / 45, -56. / 15, 32. / 9},
                                       {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729},
                                       {9017. / 3168, -355. / 33, 46732. / 5247, 49. / 176, -5103. / 18656},
                                       {35. / 384, 0., 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
    // b5 - b4: the difference of the 5th- and 4th-order weights.
    static constexpr double e[7] = {71. / 57600,      0.,        -71. / 16695, 71. / 1920,
                                    -17253. / 339200, 22. / 525, -1. / 40};
    t.h = h;
    t.k[0] = m_k1;
    for (int s = 1; s < 7; ++s) {
      Eigen::Vector3d y = m_x;
      for (int j = 0; j < s; ++j)
        y += (h * a[s - 1][j]) * t.k[j];
      if (!evaluate(y, m_tau + c[s] * h, t.k[s]))
        return false;
      speed = std::max(speed, t.k[s].norm());
      if (s == 6)
        t.x = y; // the 5th-order solution is the last stage's point (b = a[5])
    }
    Eigen::Vector3d err = Eigen::Vector3d::Zero();
    for (int s = 0; s < 7; ++s)
      err += (h * e[s]) * t.k[s];
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      const double scale = m_tol.absolute + m_tol.relative * std::max(std::abs(m_x[i]), std::abs(t.x[i]));
      sum += (err[i] / scale) * (err[i] / scale);
    }
    t.error = std::sqrt(sum / 3.);
    return std::isfinite(t.error);
  }

  double next_step(double h, double error, bool rejected)
  {
    const double fac11 = std::pow(error, exponent);
    double fac = fac11 / std::pow(m_error_prev, beta) / safety;
    fac = std::clamp(fac, 1. / max_factor, 1. / min_factor);
    m_error_prev = std::max(error, 1e-4);
    double h_new = h / fac;
    if (rejected)
      h_new = std::min(h_new, h);
    return h_new;
  }

  void accept(const Trial& t)
  {
    static constexpr double d[7] = {-12715105075. / 11282082432.,  0.,
                                    87487479700. / 32700410799.,   -10690763975. / 1880347072.,
                                    701980252875. / 199316789632., -1453857185. / 822651844.,
                                    69997945. / 29380423.};
    const Eigen::Vector3d dx = t.x - m_x;
    const Eigen::Vector3d b = t.h * t.k[0] - dx;
    m_dense[0] = m_x;
    m_dense[1] = dx;
    m_dense[2] = b;
    m_dense[3] = dx - t.h * t.k[6] - b;
    m_dense[4] = Eigen::Vector3d::Zero();
    for (int s = 0; s < 7; ++s)
      m_dense[4] += (t.h * d[s]) * t.k[s];
    m_x_prev = m_x;
    m_tau_prev = m_tau;
    m_x = t.x;
    m_tau =
        t.h == m_tol.max_parameter - m_tau ? m_tol.max_parameter : m_tau + t.h; // lands on the end exactly
    m_k1 = t.k[6];
    ++m_number_of_accepted;
  }

  void accept_zero_step()
  {
    m_x_prev = m_x;
    m_tau_prev = m_tau;
  }

  // Hairer's starting step (DOPRI5's HINIT) for order 5.
  double starting_step()
  {
    const Eigen::Vector3d scale = (m_tol.absolute + m_tol.relative * m_x.cwiseAbs().array()).matrix();
    const double dnf = m_k1.cwiseQuotient(scale).squaredNorm();
    const double dny = m_x.cwiseQuotient(scale).squaredNorm();
    double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : 0.01 * std::sqrt(dny / dnf);
    h = std::min(h, m_tol.max_step);
    Eigen::Vector3d k;
    // An explicit Euler step; halve it while it leaves the domain (bounded).
    bool in = false;
    for (int i = 0; i < 60 && !(in = evaluate(m_x + h * m_k1, m_tau + h, k)) && !waiting(); ++i)
      h *= 0.5;
    if (!in)
      return std::max(h, m_tol.min_step);
    const double der2 = (k - m_k1).cwiseQuotient(scale).norm() / h;
    const double der12 = std::max(der2, std::sqrt(dnf));
    const double h1 = der12 <= 1e-15 ? std::max(1e-6, 1e-3 * h) : std::pow(0.01 / der12, 0.2);
    return std::max(std::min({100. * h, h1, m_tol.max_step}), m_tol.min_step);
  }

  // Calls `fn` on every member but the field, in one order for writing and reading.
  template <class Self, class Fn>
  static void for_each_state_value(Self& self, const Fn& fn)
  {
    fn(self.m_t0);
    fn(self.m_sigma);
    for (auto* v : {&self.m_tol.relative, &self.m_tol.absolute, &self.m_tol.initial_step,
                    &self.m_tol.max_step, &self.m_tol.max_parameter, &self.m_tol.min_step,
                    &self.m_tol.boundary, &self.m_tol.stagnation_speed})
      fn(*v);
    fn(self.m_start_inside);
    fn(self.m_stagnation_speed);
    for (auto* x : {&self.m_x, &self.m_x_prev, &self.m_k1, &self.m_dense[0], &self.m_dense[1],
                    &self.m_dense[2], &self.m_dense[3], &self.m_dense[4]})
      for (int i = 0; i < 3; ++i)
        fn((*x)[i]);
    for (auto* v : {&self.m_tau, &self.m_tau_prev, &self.m_h, &self.m_error_prev})
      fn(*v);
    fn(self.m_confirming);
    for (auto* n : {&self.m_number_of_accepted, &self.m_number_of_rejected, &self.m_number_of_evaluations})
      fn(*n);
  }

  Field m_f;
  double m_t0;
  double m_sigma;
  Integration_tolerances m_tol;
  bool m_start_inside = false;
  double m_stagnation_speed = 0;
  Eigen::Vector3d m_x, m_x_prev;
  Eigen::Vector3d m_k1 = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 5> m_dense{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                         Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                         Eigen::Vector3d::Zero()};
  double m_tau = 0, m_tau_prev = 0;
  double m_h = 0;
  double m_error_prev = 1e-4;
  bool m_confirming = false; // the last step ended at a located exit, to be confirmed
  std::size_t m_number_of_accepted = 0, m_number_of_rejected = 0, m_number_of_evaluations = 0;
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_DORMAND_PRINCE_INTEGRATOR_H
