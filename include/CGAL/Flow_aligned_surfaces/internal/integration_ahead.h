// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Integrating ahead.  A stream or path surface asks a field that answers batches for the samples
// of its particles a Runge-Kutta stage at a time (batched_sampling.h): a path from the seed takes
// a round per stage.  A field whose pieces live on several processes can do better when it is
// told, with the points of a round, where the waiting particles stand (`Integration_ahead`): the
// process that alone decides a path's samples integrates the particle on as far as it decides
// them (`integrate_ahead()`) and sends back, with the round's samples, the state of the
// particle's integrator after its last whole step there and the samples it took after that
// state.  The task on the algorithm's process goes on from that state: the same integrator in the
// same state asks for the same points and gets the same values, so the results stay the same,
// bit for bit, and each stretch of a path is integrated once, on the process that holds it.
// What the algorithm's own process alone decides, its tasks sample at once (`Answers_here`),
// without a round; the other processes may integrate the particles of a batch of tasks while it
// does (`Integrates_ahead_meanwhile`), told only of those that stand where it does not alone
// decide (`Decides_here`).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_INTEGRATION_AHEAD_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_INTEGRATION_AHEAD_H

#include <CGAL/Flow_aligned_surfaces/internal/Dormand_prince_integrator.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>

#include <Eigen/Core>

#include <array>
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
  /// How a particle's record begins: it starts at a point; it goes on from an integrator's
  /// state; or its last step passed the target, and all it still takes is the sample at (x, t)
  /// there, which needs no integrator.
  enum Record_kind { START = 0, STATE = 1, LAST_SAMPLE = 2 };

  /// one record per particle: its kind and `state_size` values (the point; the state; the point
  /// and the time)
  std::vector<double> particles;

  static constexpr std::size_t record_size = 1 + 44;

  std::size_t size() const { return particles.size() / record_size; }
  bool empty() const { return particles.empty(); }

  /// Where particle `i` stands: its start point, or its integrator's position.
  Eigen::Vector3d position(std::size_t i) const
  {
    const double* r = particles.data() + i * record_size;
    if (r[0] != STATE)
      return Eigen::Vector3d(r[1], r[2], r[3]);
    return Dormand_prince_integrator<No_field>::position_in_state(r + 1);
  }

  /// The same settings with the particles `kept` (indices, in their order).
  Integration_ahead only(const std::vector<std::size_t>& kept) const
  {
    Integration_ahead a = *this;
    a.particles.clear();
    for (std::size_t i : kept)
      a.particles.insert(a.particles.end(), particles.begin() + std::ptrdiff_t(i * record_size),
                         particles.begin() + std::ptrdiff_t((i + 1) * record_size));
    return a;
  }

  void add_start(const Eigen::Vector3d& x0)
  {
    double* r = new_record(START);
    for (int i = 0; i < 3; ++i)
      r[i] = x0[i];
  }

  template <class Field>
  void add_state(const Dormand_prince_integrator<Field>& integrator)
  {
    static_assert(Dormand_prince_integrator<Field>::state_size + 1 == record_size);
    integrator.write_state(new_record(STATE));
  }

  /// A particle past the target, whose task takes only the sample at `x` and time `t`.
  void add_last_sample(const Eigen::Vector3d& x, double t)
  {
    double* r = new_record(LAST_SAMPLE);
    for (int i = 0; i < 3; ++i)
      r[i] = x[i];
    r[3] = t;
  }

  /// The kind of particle `i`'s record.
  Record_kind kind(std::size_t i) const { return Record_kind(int(particles[i * record_size])); }

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
    for (std::size_t i = 0; i < a.size(); ++i)
      if (const double k = a.particles[i * record_size]; k != START && k != STATE && k != LAST_SAMPLE)
        throw std::invalid_argument("integration ahead: particle " + std::to_string(i) +
                                    " has no record kind (" + std::to_string(k) + ")");
    return a;
  }

private:
  static constexpr std::size_t settings_size = 13;

  // The field of an integrator whose state is read.
  struct No_field {
    std::optional<Eigen::Vector3d> operator()(const Eigen::Vector3d&, double) const { return std::nullopt; }
  };

  double* new_record(Record_kind kind)
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

/// Where `integrate_ahead()` took a particle: its index in the `Integration_ahead`, and the
/// state of its integrator after its last whole step (`Dormand_prince_integrator::write_state()`).
struct State_ahead {
  std::size_t particle;
  std::array<double, Integration_ahead::record_size - 1> state;
};

/// What `integrate_ahead()` gives back: the states the particles reached, and the samples taken
/// after them (of a particle that took no whole step, all its samples), which the tasks ask for
/// when they go on from those states.
template <class Answer>
struct Integrated_ahead {
  std::vector<State_ahead> states;
  std::vector<Sample_ahead<Answer>> samples;
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
/// unsteady field), and fills `along` (an `Integrated_ahead<Answer>`) with where they got to.
template <class FlowField, class Point_3, class Answer, bool unsteady, class = void>
struct Integrates_ahead : std::false_type {
};
template <class FlowField, class Point_3, class Answer>
struct Integrates_ahead<
    FlowField, Point_3, Answer, false,
    std::void_t<decltype(std::declval<const FlowField&>().sample(std::declval<const std::vector<Point_3>&>(),
                                                                 std::declval<const Integration_ahead&>(),
                                                                 std::declval<Integrated_ahead<Answer>&>()))>>
    : std::true_type {
};
template <class FlowField, class Point_3, class Answer>
struct Integrates_ahead<
    FlowField, Point_3, Answer, true,
    std::void_t<decltype(std::declval<const FlowField&>().sample(
        std::declval<const std::vector<Point_3>&>(), std::declval<const std::vector<double>&>(),
        std::declval<const Integration_ahead&>(), std::declval<Integrated_ahead<Answer>&>()))>>
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

/// Whether a field that integrates ahead can also have the other processes integrate while this
/// one works: `field.integrate_ahead_meanwhile(ahead, along, work)` tells them of the particles
/// `ahead`, calls `work()` (which must not sample the field but where this process alone decides:
/// `Answers_here`) and then fills `along` as the batch operation does.
template <class FlowField, class Answer, class = void>
struct Integrates_ahead_meanwhile : std::false_type {
};
template <class FlowField, class Answer>
struct Integrates_ahead_meanwhile<
    FlowField, Answer,
    std::void_t<decltype(std::declval<const FlowField&>().integrate_ahead_meanwhile(
        std::declval<const Integration_ahead&>(), std::declval<Integrated_ahead<Answer>&>(),
        std::declval<void (*)()>()))>> : std::true_type {
};

/// Whether a field that integrates ahead meanwhile also tells, while `work()` runs, whether the
/// other processes still integrate (`field.others_still_integrating()`): this process may then
/// take on more work without making them wait.
template <class FlowField, class = void>
struct Tells_while_others_integrate : std::false_type {
};
template <class FlowField>
struct Tells_while_others_integrate<
    FlowField, std::enable_if_t<std::is_same_v<
                   decltype(std::declval<const FlowField&>().others_still_integrating()), bool>>>
    : std::true_type {
};

/// Whether a field that integrates ahead meanwhile also tells where this process alone decides
/// the samples, `field.decides_here(p)`: a particle that stands there is left out of the first
/// round's particles (no other process could take its first step) before its state is written.
template <class FlowField, class Point_3, class = void>
struct Decides_here : std::false_type {
};
template <class FlowField, class Point_3>
struct Decides_here<
    FlowField, Point_3,
    std::enable_if_t<std::is_same_v<
        decltype(std::declval<const FlowField&>().decides_here(std::declval<const Point_3&>())), bool>>>
    : std::true_type {
};

// Integrates the particle `i` of `ahead` (integrator `it`, sampling `field`) on as
// `integrate_ahead()` does; returns its state after its last whole step, if it took one, and
// keeps in `taken` the samples after it.
template <class Integrator, class Field, class Taken>
std::optional<State_ahead> integrate_particle_ahead(Integrator& it, const Field& field, std::size_t i,
                                                    const Integration_ahead& ahead, Taken& taken)
{
  std::optional<State_ahead> reached;
  Step_result result = Step_result::ACCEPTED;
  while (result == Step_result::ACCEPTED && it.parameter() < ahead.target &&
         double(it.number_of_accepted_steps()) < ahead.max_steps) {
    result = it.step();
    if (result == Step_result::ACCEPTED) {
      reached = State_ahead{i, {}};
      it.write_state(reached->state.data());
      taken.clear();
    }
  }
  if (result == Step_result::LEFT_DOMAIN)
    field(it.position(), ahead.t0 + ahead.direction * it.parameter());
  else if (result == Step_result::ACCEPTED && it.parameter() >= ahead.target)
    field(it.dense_output(ahead.target), ahead.t0 + ahead.direction * ahead.target);
  return reached;
}

/// Integrates the particles of `ahead` on, each until its next sample is not decided here
/// (`decides(x)` false), it reaches the target or leaves the domain, also sampling the field at
/// the particle's end (at the target, or where it left), and adds to `along` where each one got
/// to; a particle already past the target (`LAST_SAMPLE`) only takes that sample.  `answer(x, t)`
/// is the field's answer at (x, t): what its batch operation answers there.  The integrating
/// tasks go on from those states and ask for those samples (integrate_stream_surface.h:
/// `advance()`).
template <class Answer, class Sampler, class Decides>
void integrate_ahead(const Integration_ahead& ahead, const Sampler& answer, const Decides& decides,
                     Integrated_ahead<Answer>& along)
{
  std::vector<Sample_ahead<Answer>> taken; // by the current particle since its last whole step
  bool stopped = false;                    // at a sample not decided here
  struct Field {
    const Integration_ahead* ahead;
    const Sampler* answer;
    const Decides* decides;
    std::vector<Sample_ahead<Answer>>* taken;
    bool* stopped;
    bool waiting() const { return *stopped; }
    std::optional<Eigen::Vector3d> operator()(const Eigen::Vector3d& x, double t) const
    {
      if (*stopped || !(*decides)(x)) {
        *stopped = true;
        return std::nullopt;
      }
      Answer a = (*answer)(x, t);
      Flow_sample s = unclassified_sample(a);
      classify_sample(s);
      taken->push_back(Sample_ahead<Answer>{x, t, std::move(a)});
      return integrand_value(s, ahead->normalize);
    }
  };
  using Integrator = Dormand_prince_integrator<Field>;
  const Field field{&ahead, &answer, &decides, &taken, &stopped};
  for (std::size_t i = 0; i < ahead.size(); ++i) {
    const double* r = ahead.particles.data() + i * Integration_ahead::record_size;
    taken.clear();
    stopped = false;
    if (ahead.kind(i) == Integration_ahead::LAST_SAMPLE) {
      field(Eigen::Vector3d(r[1], r[2], r[3]), r[4]);
    }
    else {
      Integrator it = ahead.kind(i) == Integration_ahead::START
                          ? Integrator(field, Eigen::Vector3d(r[1], r[2], r[3]), ahead.t0, ahead.direction,
                                       ahead.tolerances)
                          : Integrator(field, r + 1);
      if (it.is_start_inside())
        if (std::optional<State_ahead> reached = integrate_particle_ahead(it, field, i, ahead, taken))
          along.states.push_back(*reached);
    }
    along.samples.insert(along.samples.end(), taken.begin(), taken.end());
  }
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_INTEGRATION_AHEAD_H
