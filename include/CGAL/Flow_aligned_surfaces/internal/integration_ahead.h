// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Integrating ahead.  A stream or path surface asks a field that answers batches for the samples
// of its particles a Runge-Kutta stage at a time (batched_sampling.h): a path from the seed takes
// a round per stage.  A field whose pieces live on several processes can do better when it is
// told, with the points of a round, where the waiting particles stand (`Integration_ahead`): the
// process that alone decides a path's samples integrates the particle on as far as it decides
// them (`integrate_ahead()`) and sends those samples back with the round's.  The task on the
// algorithm's process then finds them when it replays the path: the same integrator from the
// same state asks for the same points and gets the same values, so the results stay the same,
// bit for bit, in fewer rounds.  What the algorithm's own process alone decides, its tasks sample
// at once (`Answers_here`), without a round.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_INTEGRATION_AHEAD_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_INTEGRATION_AHEAD_H

#include <CGAL/Flow_aligned_surfaces/internal/Dormand_prince_integrator.h>
#include <CGAL/Flow_aligned_surfaces/internal/batched_sampling.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

/// What an integrating task sees of a sample: zero at a critical point (the integrator stagnates
/// there), nothing outside the domain or for a non-finite vector, else the velocity or (with
/// `normalize`) its direction.
inline std::optional<Eigen::Vector3d> integrand_value(const Flow_sample& s, bool normalize)
{
  if (s.kind == Sample_kind::OUTSIDE || s.kind == Sample_kind::INVALID)
    return std::nullopt;
  if (s.kind == Sample_kind::ZERO)
    return Eigen::Vector3d::Zero();
  return normalize ? s.direction : s.velocity;
}

/// The particles whose integration to a parameter waits for samples, with the settings they
/// share: each one either starts at a point or goes on from an integrator's state.
struct Integration_ahead {
  double t0 = 0;
  int direction = 1;
  bool normalize = false;
  double target = 0;    ///< the parameter τ the particles are integrated to
  double max_steps = 0; ///< accepted steps from the seed after which a particle is lost
  Integration_tolerances tolerances;
  /// one record per particle: a flag (0: starts at a point, 1: an integrator's state) and
  /// `state_size` values (the point, or the state)
  std::vector<double> particles;

  static constexpr std::size_t record_size = 1 + 44;

  std::size_t size() const { return particles.size() / record_size; }
  bool empty() const { return particles.empty(); }

  void add_start(const Eigen::Vector3d& x0)
  {
    double* r = new_record(0.);
    for (int i = 0; i < 3; ++i)
      r[i] = x0[i];
  }

  template <class Field>
  void add_state(const Dormand_prince_integrator<Field>& integrator)
  {
    static_assert(Dormand_prince_integrator<Field>::state_size + 1 == record_size);
    integrator.write_state(new_record(1.));
  }

  /// All of it as numbers, for sending.
  std::vector<double> to_numbers() const
  {
    std::vector<double> out = {t0,
                               double(direction),
                               normalize ? 1. : 0.,
                               target,
                               max_steps,
                               tolerances.relative,
                               tolerances.absolute,
                               tolerances.initial_step,
                               tolerances.max_step,
                               tolerances.max_parameter,
                               tolerances.min_step,
                               tolerances.boundary,
                               tolerances.stagnation_speed};
    out.insert(out.end(), particles.begin(), particles.end());
    return out;
  }

  /// What `to_numbers()` wrote.  \throws std::invalid_argument when `numbers` cannot be that.
  static Integration_ahead from_numbers(const std::vector<double>& numbers)
  {
    if (numbers.size() < settings_size || (numbers.size() - settings_size) % record_size != 0)
      throw std::invalid_argument("integration ahead: " + std::to_string(numbers.size()) +
                                  " numbers are no settings and particle records");
    Integration_ahead a;
    const double* v = numbers.data();
    a.t0 = v[0];
    a.direction = v[1] < 0 ? -1 : 1;
    a.normalize = v[2] != 0;
    a.target = v[3];
    a.max_steps = v[4];
    Integration_tolerances& t = a.tolerances;
    std::size_t k = 5;
    for (double* x : {&t.relative, &t.absolute, &t.initial_step, &t.max_step, &t.max_parameter, &t.min_step,
                      &t.boundary, &t.stagnation_speed})
      *x = v[k++];
    a.particles.assign(numbers.begin() + settings_size, numbers.end());
    return a;
  }

private:
  static constexpr std::size_t settings_size = 13;

  double* new_record(double kind)
  {
    particles.resize(particles.size() + record_size, 0.);
    double* r = particles.data() + particles.size() - record_size;
    r[0] = kind;
    return r + 1;
  }
};

/// A sample that `integrate_ahead()` took: the point, the time and the field's answer.
template <class Answer>
struct Sample_ahead {
  Eigen::Vector3d x;
  double t;
  Answer answer;
};

/// The type of `FlowField`'s answer at a point (and a time, for an unsteady field).
template <class FlowField, class Point_3, bool unsteady>
struct Field_answer {
  using type = std::decay_t<decltype(std::declval<const FlowField&>()(std::declval<const Point_3&>()))>;
};
template <class FlowField, class Point_3>
struct Field_answer<FlowField, Point_3, true> {
  using type = std::decay_t<decltype(std::declval<const FlowField&>()(std::declval<const Point_3&>(), 0.))>;
};

/// Whether `FlowField` integrates ahead: its batch operation takes the waiting particles too,
/// `field.sample(points, ahead, along)` (`field.sample(points, times, ahead, along)` for an
/// unsteady field), and fills `along` (a `std::vector<Sample_ahead<Answer>>`) with the samples
/// taken along their paths.
template <class FlowField, class Point_3, class Answer, bool unsteady, class = void>
struct Integrates_ahead : std::false_type {
};
template <class FlowField, class Point_3, class Answer>
struct Integrates_ahead<
    FlowField, Point_3, Answer, false,
    std::void_t<decltype(std::declval<const FlowField&>().sample(
        std::declval<const std::vector<Point_3>&>(), std::declval<const Integration_ahead&>(),
        std::declval<std::vector<Sample_ahead<Answer>>&>()))>> : std::true_type {
};
template <class FlowField, class Point_3, class Answer>
struct Integrates_ahead<
    FlowField, Point_3, Answer, true,
    std::void_t<decltype(std::declval<const FlowField&>().sample(
        std::declval<const std::vector<Point_3>&>(), std::declval<const std::vector<double>&>(),
        std::declval<const Integration_ahead&>(), std::declval<std::vector<Sample_ahead<Answer>>&>()))>>
    : std::true_type {
};

/// Whether a field that integrates ahead also answers where this process alone decides a sample,
/// without an exchange: `field.sample_here(p)` (`field.sample_here(p, t)` for an unsteady
/// field) is the sample its batch operation would answer at p, or nothing when other processes
/// have a say.
template <class FlowField, class Point_3, class Answer, bool unsteady, class = void>
struct Answers_here : std::false_type {
};
template <class FlowField, class Point_3, class Answer>
struct Answers_here<FlowField, Point_3, Answer, false,
                    std::enable_if_t<std::is_same_v<decltype(std::declval<const FlowField&>().sample_here(
                                                        std::declval<const Point_3&>())),
                                                    std::optional<Answer>>>> : std::true_type {
};
template <class FlowField, class Point_3, class Answer>
struct Answers_here<FlowField, Point_3, Answer, true,
                    std::enable_if_t<std::is_same_v<decltype(std::declval<const FlowField&>().sample_here(
                                                        std::declval<const Point_3&>(), 0.)),
                                                    std::optional<Answer>>>> : std::true_type {
};

/// Integrates the particles of `ahead` on, each until its next sample is not decided here
/// (`decides(x)` false), it reaches the target or leaves the domain, and calls
/// `record(Sample_ahead<Answer>)` for every sample taken, also the one at the particle's end (at
/// the target, or where it left).  `answer(x, t)` is the field's answer at (x, t): what its
/// batch operation answers there.  The records are the samples that the integrating tasks ask
/// for when they replay these paths (integrate_stream_surface.h: `advance()`).
template <class Answer, class Sampler, class Decides, class Record>
void integrate_ahead(const Integration_ahead& ahead, const Sampler& answer, const Decides& decides,
                     const Record& record)
{
  struct Field {
    const Integration_ahead* ahead;
    const Sampler* answer;
    const Decides* decides;
    const Record* record;
    std::optional<Eigen::Vector3d> operator()(const Eigen::Vector3d& x, double t) const
    {
      if (!(*decides)(x))
        throw Sample_not_ready();
      Answer a = (*answer)(x, t);
      Flow_sample s = unclassified_sample(a);
      classify_sample(s);
      (*record)(Sample_ahead<Answer>{x, t, std::move(a)});
      return integrand_value(s, ahead->normalize);
    }
  };
  using Integrator = Dormand_prince_integrator<Field>;
  const Field field{&ahead, &answer, &decides, &record};
  for (std::size_t i = 0; i < ahead.size(); ++i) {
    const double* r = ahead.particles.data() + i * Integration_ahead::record_size;
    try {
      Integrator it = r[0] == 0 ? Integrator(field, Eigen::Vector3d(r[1], r[2], r[3]), ahead.t0,
                                             ahead.direction, ahead.tolerances)
                                : Integrator(field, r + 1);
      if (!it.is_start_inside())
        continue;
      Step_result result = Step_result::ACCEPTED;
      while (result == Step_result::ACCEPTED && it.parameter() < ahead.target &&
             double(it.number_of_accepted_steps()) < ahead.max_steps)
        result = it.step();
      if (result == Step_result::LEFT_DOMAIN)
        field(it.position(), ahead.t0 + ahead.direction * it.parameter());
      else if (result == Step_result::ACCEPTED && it.parameter() >= ahead.target)
        field(it.dense_output(ahead.target), ahead.t0 + ahead.direction * ahead.target);
    } catch (const Sample_not_ready&) {
    }
  }
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_INTEGRATION_AHEAD_H
