// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sampling a field in batches.  A field may answer many points in one call (the optional
// `sample()` of the concepts `FlowField_3` and `UnsteadyFlowField_3`): a field whose pieces live
// on the processes of a cluster answers a batch in one exchange.  The algorithms then ask for
// the points they know beforehand in one batch (`sample_flow_at()`), and run the work whose
// next point depends on the last sample (the stages of a Runge-Kutta step) as resumable tasks
// in rounds (`run_in_rounds()`): each round runs every task until it asks for a sample not known
// yet (`Replay_samples::ask()` answers nothing and the task returns, waiting), and one batch
// answers all of them.  A task commits its progress only at points where it can be taken up
// again, so it computes exactly what it computes with samples at hand: batched or not, the
// results are the same, bit for bit.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BATCHED_SAMPLING_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BATCHED_SAMPLING_H

#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

template <class FlowField, class Point_3, class = void>
struct Has_batch_sampling : std::false_type {
};
template <class FlowField, class Point_3>
struct Has_batch_sampling<FlowField, Point_3,
                          std::void_t<decltype(std::declval<const FlowField&>().sample(
                              std::declval<const std::vector<Point_3>&>()))>> : std::true_type {
};

template <class FlowField, class Point_3, class = void>
struct Has_unsteady_batch_sampling : std::false_type {
};
template <class FlowField, class Point_3>
struct Has_unsteady_batch_sampling<
    FlowField, Point_3,
    std::void_t<decltype(std::declval<const FlowField&>().sample(
        std::declval<const std::vector<Point_3>&>(), std::declval<const std::vector<double>&>()))>>
    : std::true_type {
};

/// Whether `FlowField` answers a batch of points in one call (`field.sample(points)`).
template <class FlowField, class Point_3>
constexpr bool has_batch_sampling_v = Has_batch_sampling<FlowField, Point_3>::value;
/// Whether the unsteady `FlowField` answers a batch in one call (`field.sample(points, times)`).
template <class FlowField, class Point_3>
constexpr bool has_unsteady_batch_sampling_v = Has_unsteady_batch_sampling<FlowField, Point_3>::value;

template <class Answers>
void check_batch_size(const Answers& answers, std::size_t asked)
{
  if (answers.size() != asked)
    throw std::logic_error("a flow field's sample() answered " + std::to_string(answers.size()) + " of " +
                           std::to_string(asked) + " points");
}

/// The classified samples of `field` at `points`: one call of `field.sample(points)` when the
/// field has it, else one query per point, in order.
template <class FlowField, class Point_3>
std::vector<Flow_sample> sample_flow_at(const FlowField& field, const std::vector<Point_3>& points)
{
  std::vector<Flow_sample> samples;
  samples.reserve(points.size());
  if constexpr (has_batch_sampling_v<FlowField, Point_3>) {
    const auto answers = field.sample(points);
    check_batch_size(answers, points.size());
    for (const auto& answer : answers)
      samples.push_back(unclassified_sample(answer));
  }
  else
    for (const Point_3& p : points)
      samples.push_back(unclassified_sample(field(p)));
  for (Flow_sample& s : samples)
    classify_sample(s);
  return samples;
}

/// The same for an unsteady field at `points[i]` and `times[i]`.
template <class FlowField, class Point_3>
std::vector<Flow_sample> sample_flow_at(const FlowField& field, const std::vector<Point_3>& points,
                                        const std::vector<double>& times)
{
  std::vector<Flow_sample> samples;
  samples.reserve(points.size());
  if constexpr (has_unsteady_batch_sampling_v<FlowField, Point_3>) {
    const auto answers = field.sample(points, times);
    check_batch_size(answers, points.size());
    for (const auto& answer : answers)
      samples.push_back(unclassified_sample(answer));
  }
  else
    for (std::size_t i = 0; i < points.size(); ++i)
      samples.push_back(unclassified_sample(field(points[i], times[i])));
  for (Flow_sample& s : samples)
    classify_sample(s);
  return samples;
}

/// The samples known so far at points (x, t), and the points asked for that are not.  `Value`
/// is what the tasks are answered (their field's view of a sample).
template <class Value>
class Replay_samples {
public:
  /// The sample at (x, t), or null when it is not known.
  const Value* known(const Eigen::Vector3d& x, double t) const
  {
    const auto found = m_known.find(key(x, t));
    return found != m_known.end() ? &found->second : nullptr;
  }

  /// The sample at (x, t) for the running task; when it is not known, records the point, marks
  /// the task as waiting (`waiting()`) and returns null: the task must then return without
  /// committing what it computed from the missing sample.
  const Value* ask(const Eigen::Vector3d& x, double t)
  {
    const Key k = key(x, t);
    const auto found = m_known.find(k);
    if (found != m_known.end())
      return &found->second;
    if (m_asked.emplace(k, m_missing.size()).second)
      m_missing.emplace_back(x, t);
    m_waiting = true;
    return nullptr;
  }

  /// Whether the running task asked for a sample not known yet.
  bool waiting() const { return m_waiting; }
  /// A task starts (or resumes): it waits for nothing yet.
  void start_task() { m_waiting = false; }

  /// The points asked for since the last call, each once, in the order first asked.
  std::vector<std::pair<Eigen::Vector3d, double>> take_missing()
  {
    m_asked.clear();
    return std::exchange(m_missing, {});
  }

  void add(const Eigen::Vector3d& x, double t, Value value) { m_known[key(x, t)] = std::move(value); }

  /// Forgets every sample (between independent batches of tasks, to bound the memory).
  void clear()
  {
    m_known.clear();
    m_asked.clear();
    m_missing.clear();
    m_waiting = false;
  }

private:
  // The exact bits: a task asks again for the very point it computed before.
  using Key = std::array<std::uint64_t, 4>;
  struct Key_hash {
    std::size_t operator()(const Key& k) const
    {
      std::uint64_t h = 0x9E3779B97F4A7C15ull;
      for (std::uint64_t w : k)
        h = (h ^ w) * 0x100000001B3ull + (h >> 29);
      return std::size_t(h);
    }
  };
  static Key key(const Eigen::Vector3d& x, double t)
  {
    Key k;
    const double values[4] = {x[0], x[1], x[2], t};
    std::memcpy(k.data(), values, sizeof values);
    return k;
  }

  std::unordered_map<Key, Value, Key_hash> m_known;
  std::unordered_map<Key, std::size_t, Key_hash> m_asked;
  std::vector<std::pair<Eigen::Vector3d, double>> m_missing;
  bool m_waiting = false;
};

/// Runs tasks 0 … n-1 to their end: `resume(i)` runs task i on from where it last committed its
/// progress, and either ends it or returns waiting for a sample (`samples.ask()`).  After each
/// round over the unfinished tasks, `answer(missing, waiting)` gives the values at the points they
/// asked for, in one batch, and they are added to `samples`; `waiting` are the tasks that wait
/// (an answer may add more samples along their way: integration_ahead.h).  The first round runs
/// within `first(round)`, which calls `round()` once and may have other processes work for the
/// tasks meanwhile; when it returns true, they took tasks on while the round ran, so the points
/// that round asked for may be behind them: the waiting tasks run a round again, from where the
/// others took them, before anything is asked.  Returns the number of batches.
template <class Value, class Resume, class Answer, class First>
std::size_t run_in_rounds(std::size_t n, Replay_samples<Value>& samples, const Resume& resume,
                          const Answer& answer, const First& first)
{
  std::vector<std::size_t> waiting(n);
  for (std::size_t i = 0; i < n; ++i)
    waiting[i] = i;
  std::vector<std::size_t> still;
  auto round = [&] {
    still.clear();
    for (std::size_t i : waiting) {
      samples.start_task();
      resume(i);
      if (samples.waiting())
        still.push_back(i);
    }
  };
  if (first(round) && !still.empty()) {
    samples.take_missing();
    waiting.swap(still);
    round();
  }
  std::size_t batches = 0;
  for (; !still.empty(); round()) {
    const std::vector<std::pair<Eigen::Vector3d, double>> missing = samples.take_missing();
    if (missing.empty())
      throw std::logic_error("run_in_rounds: a task waits for a sample it did not ask for");
    std::vector<Value> values = answer(missing, still);
    check_batch_size(values, missing.size());
    for (std::size_t k = 0; k < missing.size(); ++k)
      samples.add(missing[k].first, missing[k].second, std::move(values[k]));
    ++batches;
    waiting.swap(still);
  }
  return batches;
}

/// The same, the first round run like the others.
template <class Value, class Resume, class Answer>
std::size_t run_in_rounds(std::size_t n, Replay_samples<Value>& samples, const Resume& resume,
                          const Answer& answer)
{
  return run_in_rounds(n, samples, resume, answer, [](const auto& round) {
    round();
    return false;
  });
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_BATCHED_SAMPLING_H
