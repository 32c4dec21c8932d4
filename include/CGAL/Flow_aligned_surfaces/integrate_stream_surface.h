// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stream surfaces and path surfaces by an advancing front (Hultquist 1992, with the refinements
// of Garth et al. 2004/2008): the surface x(u, τ) with
//
//   ∂x/∂τ (u, τ) = σ v(x(u, τ), t0 + σ τ),   x(u, 0) = c(u),   u in [0, L], τ ≥ 0, σ = ±1,
//
// where c is the seed polyline parametrized by arc length u, is sampled on the time lines
// τ_k = k Δ (k = 0, 1, ...) at particles u_0 < u_1 < ... whose neighbours stay between h/2 and
// 2h apart: a particle re-integrated from c((u_i + u_{i+1}) / 2) is inserted where neighbours
// diverge, one is removed where they converge, and the front tears where it cannot be refined
// (a particle leaves the domain or stagnates, neighbours separate at a critical point or an
// obstacle).  The strip between two time lines is triangulated by the shorter-diagonal rule; a
// time line whose strip would be thin (a sheared front, turned towards the flow) is left out.
// With arc-length time lines v is replaced by v / |v| (steady fields), so τ is the arc length.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTEGRATE_STREAM_SURFACE_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTEGRATE_STREAM_SURFACE_H

#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/internal/Dormand_prince_integrator.h>
#include <CGAL/Flow_aligned_surfaces/internal/Field_in_turns.h>
#include <CGAL/Flow_aligned_surfaces/internal/Taking_turns.h>
#include <CGAL/Flow_aligned_surfaces/internal/batched_sampling.h>
#include <CGAL/Flow_aligned_surfaces/internal/flow_sample.h>
#include <CGAL/Flow_aligned_surfaces/internal/integration_ahead.h>
#include <CGAL/Flow_aligned_surfaces/internal/progress_callback.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesRef
/// Why `integrate_stream_surface()` stopped.
enum class Stream_surface_termination {
  MAX_INTEGRATION_TIME,     ///< the last time line is at `max_time`
  MAX_LENGTH,               ///< the last time line is at `max_length` (arc-length time lines)
  MAX_NUMBER_OF_TIME_LINES, ///< `max_number_of_time_lines` time lines were computed, before `max_time`
                            ///< (`max_length`); the message says how far the last one got
  NO_PARTICLE_LEFT,         ///< every front piece left the domain, stagnated or was torn to single particles
  MAX_NUMBER_OF_VERTICES,   ///< the surface reached `max_number_of_vertices`
  SEED_OUTSIDE_DOMAIN,      ///< no point of the seed is inside the field's domain: empty result
  SEED_AT_REST,             ///< the field is zero at every point of the seed inside the domain: empty result
  STOPPED                   ///< the `callback` named parameter returned `false` after the last time line
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// returns the name of `t` (`"MAX_LENGTH"`, ...), for messages.
inline const char* to_string(Stream_surface_termination t)
{
  switch (t) {
  case Stream_surface_termination::MAX_INTEGRATION_TIME:
    return "MAX_INTEGRATION_TIME";
  case Stream_surface_termination::MAX_LENGTH:
    return "MAX_LENGTH";
  case Stream_surface_termination::MAX_NUMBER_OF_TIME_LINES:
    return "MAX_NUMBER_OF_TIME_LINES";
  case Stream_surface_termination::NO_PARTICLE_LEFT:
    return "NO_PARTICLE_LEFT";
  case Stream_surface_termination::MAX_NUMBER_OF_VERTICES:
    return "MAX_NUMBER_OF_VERTICES";
  case Stream_surface_termination::SEED_OUTSIDE_DOMAIN:
    return "SEED_OUTSIDE_DOMAIN";
  case Stream_surface_termination::SEED_AT_REST:
    return "SEED_AT_REST";
  case Stream_surface_termination::STOPPED:
    return "STOPPED";
  }
  return "?";
}

/// \ingroup PkgFlowAlignedSurfacesRef
/// How far one direction of `integrate_stream_surface()` got and why it stopped.
struct Stream_surface_half_report {
  /// the number of time lines computed after the seed curve
  std::size_t number_of_time_lines = 0;
  /// the time-line parameter \f$ \tau \ge 0 \f$ of the last time line
  double final_parameter = 0;
  /// why the integration stopped
  Stream_surface_termination termination = Stream_surface_termination::NO_PARTICLE_LEFT;
  /// the reason in words, naming the limit and its value
  std::string message;
};

/// \ingroup PkgFlowAlignedSurfacesRef
/// What `integrate_stream_surface()` did.  With `Integration_direction::BOTH` the counts are
/// those of the whole surface, `number_of_time_lines`, `final_parameter`, `termination` and
/// `message` those of the forward half, and `backward` says how far the backward half got.
struct Stream_surface_report {
  /// the number of time lines computed after the seed curve
  std::size_t number_of_time_lines = 0;
  /// particles inserted (re-integrated from the seed) where neighbours diverged
  std::size_t number_of_inserted_particles = 0;
  /// particles removed where neighbours converged
  std::size_t number_of_removed_particles = 0;
  /// places where the front was torn into pieces (not counting particles that left the domain
  /// at the end of a piece)
  std::size_t number_of_tears = 0;
  /// particles that left the domain, stagnated or could not be integrated
  std::size_t number_of_lost_particles = 0;
  /// triangles that `CGAL::Euler::add_face()` refused because they would make the mesh
  /// non-manifold (the strips are built so that this does not happen: 0 in every test)
  std::size_t number_of_refused_faces = 0;
  std::size_t number_of_vertices = 0; ///< vertices added to the output mesh
  std::size_t number_of_faces = 0;    ///< triangles added to the output mesh
  /// the time-line parameter τ of the last time line
  double final_parameter = 0;
  /// the seed polyline's length L (the range of the seed parameter is [0, L])
  double seed_length = 0;
  /// the front spacing h actually used
  double front_spacing = 0;
  /// the time-line step Δ actually used
  double time_line_step = 0;
  /// why the integration stopped
  Stream_surface_termination termination = Stream_surface_termination::NO_PARTICLE_LEFT;
  /// the reason in words, naming the limit and its value
  std::string message;
  /// with `Integration_direction::BOTH`: the backward half's time lines, last parameter and
  /// termination; empty otherwise
  std::optional<Stream_surface_half_report> backward;
  /// the batches of samples asked of a field that answers batches (its `sample()`): one per
  /// stage of the Runge-Kutta steps of a whole time line, and per level of insertions; 0 for a
  /// field without `sample()`
  std::size_t number_of_sample_batches = 0;
  /// whether the `callback` named parameter stopped the integration (the termination of the half
  /// it stopped is then `STOPPED`; with `BOTH`, a stop in the backward half leaves out the
  /// forward half)
  bool stopped = false;
};

namespace internal {

// The field seen by the integrator: std::optional<Eigen::Vector3d>(x, t); zero at critical
// points (the integrator stagnates there), std::nullopt outside the domain or for NaN vectors.
// A field that answers batches (`sample()`) is seen through `replay`: the samples the front's
// particles asked for in earlier rounds (batched_sampling.h); where it has none yet, the task
// waits (`waiting()`) and the integrator stops its step.
template <class FlowField, class Point_3>
struct Front_field {
  using Value = std::optional<Eigen::Vector3d>;
  const FlowField* field;
  bool normalize;
  Replay_samples<Value>* replay = nullptr;

  static constexpr bool is_unsteady = std::is_invocable_v<const FlowField&, const Point_3&, double>;
  static constexpr bool is_batched = is_unsteady ? has_unsteady_batch_sampling_v<FlowField, Point_3>
                                                 : has_batch_sampling_v<FlowField, Point_3>;
  using Answer = typename Field_answer<FlowField, Point_3, is_unsteady>::type;
  static constexpr bool integrates_ahead = Integrates_ahead<FlowField, Point_3, Answer, is_unsteady>::value;
  static constexpr bool answers_here = Answers_here<FlowField, Point_3, Answer, is_unsteady>::value;
  static constexpr bool integrates_ahead_meanwhile =
      integrates_ahead && Integrates_ahead_meanwhile<FlowField, Answer>::value;
  static constexpr bool tells_where_it_decides =
      integrates_ahead_meanwhile && Decides_here<FlowField, Point_3>::value;
  static constexpr bool tells_while_others_integrate =
      integrates_ahead_meanwhile && Tells_while_others_integrate<FlowField>::value;

  Value operator()(const Eigen::Vector3d& x, double t) const
  {
    if (replay != nullptr) {
      if constexpr (answers_here)
        if (std::optional<Answer> here = sample_here(x, t))
          return value(classified(*here));
      if (const Value* known = replay->ask(x, t))
        return *known;
      return std::nullopt;
    }
    Flow_sample s;
    if constexpr (is_unsteady)
      s = sample_flow([&](const Point_3& q) { return (*field)(q, t); }, point(x));
    else
      s = sample_flow(*field, point(x));
    return value(s);
  }

  /// Whether the running task waits for a sample asked for in this round.
  bool waiting() const { return replay != nullptr && replay->waiting(); }

  /// While the other processes integrate ahead meanwhile: whether they still do (false when the
  /// field does not tell).
  bool others_still_integrating() const
  {
    if constexpr (tells_while_others_integrate)
      return field->others_still_integrating();
    else
      return false;
  }

  /// Whether this process alone decides the samples at x (false when the field does not tell).
  bool decided_here(const Eigen::Vector3d& x) const
  {
    if constexpr (tells_where_it_decides)
      return field->decides_here(point(x));
    else
      return false;
  }

  /// The values at the points (x, t) in one batch of the field.
  std::vector<Value> operator()(const std::vector<std::pair<Eigen::Vector3d, double>>& points) const
  {
    return (*this)(
        points, Integration_ahead(), [](const Eigen::Vector3d&, double, const Value&) {},
        [](std::size_t, const double*) {});
  }

  /// The same; a field that integrates ahead (integration_ahead.h) is also told of the particles
  /// `ahead`: `go_on(k, state)` is called with the state that the k-th of them reached, and
  /// `add(x, t, value)` for each sample taken after those states.
  template <class Add, class Go_on>
  std::vector<Value> operator()(const std::vector<std::pair<Eigen::Vector3d, double>>& points,
                                const Integration_ahead& ahead, const Add& add, const Go_on& go_on) const
  {
    std::vector<Point_3> ps;
    std::vector<double> times;
    for (const auto& [x, t] : points) {
      ps.push_back(point(x));
      times.push_back(t);
    }
    std::vector<Flow_sample> samples;
    if constexpr (integrates_ahead) {
      Integrated_ahead<Answer> along;
      if constexpr (is_unsteady)
        samples = classified(field->sample(ps, times, ahead, along), ps.size());
      else
        samples = classified(field->sample(ps, ahead, along), ps.size());
      take_up(ahead, along, add, go_on);
    }
    else if constexpr (is_unsteady)
      samples = sample_flow_at(*field, ps, times);
    else
      samples = sample_flow_at(*field, ps);
    std::vector<Value> values;
    for (const Flow_sample& s : samples)
      values.push_back(value(s));
    return values;
  }

  /// Has the field integrate the particles `ahead` while `work()` runs, then calls `go_on` and
  /// `add` as the batch operation above does.  Returns whether it took a particle on.
  template <class Work, class Add, class Go_on>
  bool integrate_ahead_meanwhile(const Integration_ahead& ahead, const Work& work, const Add& add,
                                 const Go_on& go_on) const
  {
    Integrated_ahead<Answer> along;
    field->integrate_ahead_meanwhile(ahead, along, work);
    take_up(ahead, along, add, go_on);
    return !along.states.empty() || !along.samples.empty();
  }

private:
  template <class Add, class Go_on>
  void take_up(const Integration_ahead& ahead, const Integrated_ahead<Answer>& along, const Add& add,
               const Go_on& go_on) const
  {
    for (const State_ahead& reached : along.states) {
      if (reached.particle >= ahead.size())
        throw std::logic_error("a flow field integrated ahead particle " + std::to_string(reached.particle) +
                               " of " + std::to_string(ahead.size()));
      go_on(reached.particle, reached.state.data());
    }
    for (const Sample_ahead<Answer>& a : along.samples)
      add(a.x, a.t, value(classified(a.answer)));
  }

  static Point_3 point(const Eigen::Vector3d& x)
  {
    using FT = typename CGAL::Kernel_traits<Point_3>::Kernel::FT;
    return Point_3{FT(x[0]), FT(x[1]), FT(x[2])};
  }

  Value value(const Flow_sample& s) const { return integrand_value(s, normalize); }

  // The sample at (x, t) of a field that integrates ahead, when this process alone decides it.
  std::optional<Answer> sample_here(const Eigen::Vector3d& x, double t) const
  {
    if constexpr (is_unsteady)
      return field->sample_here(point(x), t);
    else
      return field->sample_here(point(x));
  }

  static Flow_sample classified(const Answer& answer)
  {
    Flow_sample s = unclassified_sample(answer);
    classify_sample(s);
    return s;
  }
  static std::vector<Flow_sample> classified(const std::vector<Answer>& answers, std::size_t asked)
  {
    check_batch_size(answers, asked);
    std::vector<Flow_sample> samples;
    for (const Answer& a : answers)
      samples.push_back(classified(a));
    return samples;
  }
};

// The seed polyline with its arc-length parametrization c(u).
class Seed_curve {
public:
  template <class PointRange>
  explicit Seed_curve(const PointRange& polyline)
  {
    std::size_t i = 0;
    for (const auto& p : polyline) {
      const Eigen::Vector3d x(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      if (!x.allFinite())
        fail("point " + std::to_string(i) + " is " + printable(x) + "; expected finite coordinates");
      if (!m_points.empty() && x == m_points.back())
        fail("points " + std::to_string(i - 1) + " and " + std::to_string(i) + " are both " + printable(x) +
             "; expected distinct consecutive points");
      m_arc.push_back(m_points.empty() ? 0. : m_arc.back() + (x - m_points.back()).norm());
      m_points.push_back(x);
      ++i;
    }
    if (m_points.size() < 2)
      fail("has " + std::to_string(m_points.size()) + " point(s); expected at least 2");
  }

  double length() const { return m_arc.back(); }
  std::size_t number_of_segments() const { return m_points.size() - 1; }

  Eigen::Vector3d operator()(double u) const
  {
    const std::size_t j = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(m_arc.begin(), m_arc.end(), u) - m_arc.begin()), 1,
        m_points.size() - 1);
    const double s = std::clamp((u - m_arc[j - 1]) / (m_arc[j] - m_arc[j - 1]), 0., 1.);
    return (1. - s) * m_points[j - 1] + s * m_points[j];
  }

private:
  static std::string printable(const Eigen::Vector3d& x)
  {
    std::ostringstream os;
    os.precision(17);
    os << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
    return os.str();
  }
  [[noreturn]] static void fail(const std::string& what)
  {
    throw std::invalid_argument("integrate_stream_surface: seed_polyline " + what);
  }

  std::vector<Eigen::Vector3d> m_points;
  std::vector<double> m_arc;
};

inline double checked_positive(double value, const char* name)
{
  check_positive_finite("integrate_stream_surface", name, value);
  return value;
}

// The backward half of a BOTH surface integrated in turns with the forward half
// (`integrate_halves_in_turns()`): its turns, its report once it has ended, and whether its
// callback said stop (the forward half then lets it end at once).
struct Backward_half_in_turns {
  // `run(turns, stopping)` integrates the backward half and returns its report.
  template <class Run>
  explicit Backward_half_in_turns(Run run)
      : turns([this, run](Taking_turns& own) { report = run(own, stopping); })
  {
  }

  Stream_surface_report report;
  bool stopping = false; // set on the caller's thread, which runs the callback
  Taking_turns turns;    // last: its thread may start once the members above are made
};

// The settings of one half of a stream surface.
struct Front_settings {
  double spacing, step, max_parameter, t0, tear_cosine, min_gap;
  std::size_t max_time_lines, max_vertices, max_steps;
  int direction;
  Integration_tolerances tolerances;
  // The backward half is written with its triangles reversed, so that every surface is oriented
  // by ∂x/∂u × v, and, within a BOTH surface, with negative τ.
  bool reverse_triangles = false;
  double written_tau_sign = 1;
  // Time lines whose strip would be thin are left out of the mesh (with the default
  // time-line step only: a given step is the time-line spacing the caller asked for).
  bool skip_thin_strips = false;
  // Called after each time line with the fraction done, mapped to [progress_begin, progress_end]
  // (the halves of a BOTH surface share [0, 1]).
  Progress_callback callback = Progress_callback();
  double progress_begin = 0, progress_end = 1;
  // The forward half of a BOTH surface whose field has the other processes integrate while this
  // one works: its backward half, integrated in turns with it (`integrate_halves_in_turns()`).
  Backward_half_in_turns* backward_in_turns = nullptr;
};

// The settings of the backward half (of a BOTH surface: written with negative τ, the first half
// of the progress).
inline Front_settings backward_half(Front_settings settings, bool both)
{
  settings.direction = -1;
  settings.reverse_triangles = true;
  settings.written_tau_sign = both ? -1 : 1;
  if (both)
    settings.progress_end = 0.5;
  return settings;
}

// The settings of the forward half of a BOTH surface (the second half of the progress).
inline Front_settings forward_half_of_both(Front_settings settings)
{
  settings.direction = 1;
  settings.reverse_triangles = false;
  settings.written_tau_sign = 1;
  settings.progress_begin = 0.5;
  settings.progress_end = 1;
  return settings;
}

// Whether the backward half's end leaves out the forward half: a stop, or a seed outside the
// domain or at rest (the same seed forward).
inline bool ends_both_halves(const Stream_surface_report& backward)
{
  return backward.stopped || backward.termination == Stream_surface_termination::SEED_OUTSIDE_DOMAIN ||
         backward.termination == Stream_surface_termination::SEED_AT_REST;
}

// The backward half's report as the report of a BOTH surface that ends with it.
inline Stream_surface_report with_backward_half(Stream_surface_report report)
{
  report.backward = Stream_surface_half_report{report.number_of_time_lines, report.final_parameter,
                                               report.termination, report.message};
  return report;
}

// The advancing front.  Nodes are the samples of the time lines; a node becomes a vertex of the
// output mesh only when a triangle uses it, so particles lost at once leave no isolated vertex.
template <class FlowField, class Point_3, class TriangleMesh, class VPM, class UMap, class TMap>
class Stream_surface_front {
  using Field = Front_field<FlowField, Point_3>;
  using Integrator = Dormand_prince_integrator<Field>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Mesh_point = typename boost::property_traits<VPM>::value_type;
  using Mesh_FT = typename CGAL::Kernel_traits<Mesh_point>::Kernel::FT;

public:
  using Settings = Front_settings;

  // How a forward half integrated in turns with its backward half ended: as it would after the
  // backward half (`DONE`); left out, because the backward half stopped or its seed is outside or
  // at rest (`DISCARDED`); or to be integrated again after it, because it may have passed its
  // vertex limit while the backward half's vertices were not known yet (`RERUN`).
  enum class Outcome { DONE, DISCARDED, RERUN };

  // The vertices of the seed samples, shared by the two halves of a BOTH surface: the first
  // half writes those it creates, the second reuses them.
  using Seed_vertices = std::vector<std::optional<vertex_descriptor>>;

  Stream_surface_front(const FlowField& field, bool normalize, const Seed_curve& seed,
                       const Settings& settings, TriangleMesh& tm, VPM vpm, UMap u_map, TMap t_map,
                       Seed_vertices& seed_vertices)
      : m_field{&field, normalize}, m_seed(seed), m_s(settings), m_tm(tm), m_vpm(vpm), m_u_map(u_map),
        m_t_map(t_map), m_seed_vertices(seed_vertices),
        m_backward_pending(settings.backward_in_turns != nullptr)
  {
    if constexpr (Field::is_batched)
      m_field.replay = &m_replay;
  }
  // The integrators' field points to `m_replay`.
  Stream_surface_front(const Stream_surface_front&) = delete;
  Stream_surface_front& operator=(const Stream_surface_front&) = delete;

  Stream_surface_report run(Stream_surface_report report)
  {
    m_report = std::move(report);
    m_report.number_of_time_lines = 0;
    m_report.final_parameter = 0;
    m_report.termination = Stream_surface_termination::NO_PARTICLE_LEFT;
    seed_front();
    advance_front();
    if (m_backward_pending)
      take_in_backward_half(true);
    if (m_outcome != Outcome::DONE)
      return m_report;
    write_triangles();
    for (const auto& [sample, node] : m_seed_nodes)
      if (m_nodes[node].vertex)
        m_seed_vertices[sample] = m_nodes[node].vertex;
    return m_report;
  }

  Outcome outcome() const { return m_outcome; }

private:
  // The time lines, until a limit is reached or no particle is left.
  void advance_front()
  {
    if (m_pieces.empty())
      return;
    // The limits are tested after each time line too, so that the callback hears of the last one.
    bool last = limit_reached(1);
    for (std::size_t k = 1; !last; ++k) {
      m_previous_parameter = m_parameter;
      // The last time line is at the limit; one that would end less than Δ/2 before it is moved
      // there (not a strip of slivers behind it).
      m_parameter = double(k) * m_s.step;
      if (m_parameter >= m_s.max_parameter || m_s.max_parameter - m_parameter < 0.5 * m_s.step)
        m_parameter = m_s.max_parameter;
      m_last_line = m_parameter >= m_s.max_parameter || k >= m_s.max_time_lines;
      // Every particle of the front first, together (one batch of samples per round of steps).
      std::vector<Particle*> particles;
      for (std::vector<Particle>& piece : m_pieces)
        for (Particle& p : piece)
          particles.push_back(&p);
      const std::vector<char> reached = advance_all(particles);
      std::vector<std::vector<Particle>> next;
      std::size_t first = 0;
      for (std::vector<Particle>& piece : m_pieces) {
        advance_piece(piece, reached.data() + first, next);
        first += piece.size();
      }
      m_pieces = std::move(next);
      if constexpr (!Field::integrates_ahead_meanwhile)
        write_triangles(); // else while the next batch's first round runs
      m_report.number_of_time_lines = k;
      m_report.final_parameter = m_parameter;
      if (m_backward_pending && !take_in_backward_half(false))
        return;
      last = limit_reached(k + 1);
      if (m_backward_pending)
        continue; // the backward half reports the progress until it has ended
      if (!report_progress(m_s.callback, progress(k, last)) && !last) {
        m_report.stopped = true;
        return finish(Stream_surface_termination::STOPPED,
                      "stopped by the callback after time line " + std::to_string(k) + " at " +
                          (m_field.normalize ? "length " : "time ") + printable(m_parameter));
      }
    }
  }

  // Whether time line k may not be computed; if so, the report says which limit.
  bool limit_reached(std::size_t k)
  {
    const char* limit = m_field.normalize ? "max_length" : "max_time";
    if (m_pieces.empty())
      finish(Stream_surface_termination::NO_PARTICLE_LEFT, "no particle left");
    // The limit in τ first: when it is reached on the last allowed time line, it is what stopped.
    else if (m_parameter >= m_s.max_parameter)
      finish(m_field.normalize ? Stream_surface_termination::MAX_LENGTH
                               : Stream_surface_termination::MAX_INTEGRATION_TIME,
             std::string(limit) + " " + printable(m_s.max_parameter) + " reached");
    else if (k > m_s.max_time_lines)
      finish(Stream_surface_termination::MAX_NUMBER_OF_TIME_LINES,
             "max_number_of_time_lines (" + std::to_string(m_s.max_time_lines) + ") reached at " +
                 (m_field.normalize ? "length " : "time ") + printable(m_parameter) +
                 (std::isfinite(m_s.max_parameter)
                      ? ", before " + std::string(limit) + " " + printable(m_s.max_parameter)
                      : ", no " + std::string(limit) + " given"));
    else if ((!m_backward_pending && m_report.number_of_vertices >= m_s.max_vertices) ||
             m_nodes.size() >= 2 * m_s.max_vertices)
      finish(Stream_surface_termination::MAX_NUMBER_OF_VERTICES,
             "max_number_of_vertices (" + std::to_string(m_s.max_vertices) + ") reached at " +
                 (m_field.normalize ? "length " : "time ") + printable(m_parameter));
    else
      return false;
    return true;
  }

  // The fraction of the integration done after time line k: how near the nearest limit is (1 on
  // the last time line, whatever ended it), mapped to this half's share.
  double progress(std::size_t k, bool last) const
  {
    double done = 1;
    if (!last) {
      done = double(m_report.number_of_vertices) / double(m_s.max_vertices);
      if (std::isfinite(m_s.max_parameter))
        done = (std::max)(done, m_parameter / m_s.max_parameter);
      if (m_s.max_time_lines != std::numeric_limits<std::size_t>::max())
        done = (std::max)(done, double(k) / double(m_s.max_time_lines));
    }
    return m_s.progress_begin + (m_s.progress_end - m_s.progress_begin) * (std::min)(done, 1.);
  }

  // While the other processes integrate this half's particles: the backward half integrated in
  // turns with it takes turns (each a time line, or fewer samples: Field_in_turns.h) as long as
  // they do (when the field tells; else one), the progress it reports served before the next.
  // It stops early where it waits for an exchange.
  void give_backward_half_turns()
  {
    Taking_turns& turns = m_s.backward_in_turns->turns;
    for (bool first = true; Field::tells_while_others_integrate ? m_field.others_still_integrating() : first;
         first = false) {
      if (turns.pending() == Taking_turns::Request::LOCAL)
        turns.serve();
      if (turns.finished() || turns.pending() != Taking_turns::Request::NONE)
        return;
      turns.give_turn();
    }
  }

  // Between this half's exchanges: serves the backward half's exchange or progress (with
  // `to_its_end`, or once its callback said stop, all it asks for until it ends); once it has
  // ended, takes it in: its counts are added to this half's, the seed nodes become its seed
  // vertices, and this half's triangles are written after its own.  False when this half ends
  // here (`outcome()`).
  bool take_in_backward_half(bool to_its_end)
  {
    Taking_turns& turns = m_s.backward_in_turns->turns;
    if (to_its_end || m_s.backward_in_turns->stopping)
      turns.finish();
    else if (turns.pending() != Taking_turns::Request::NONE)
      turns.serve();
    if (!turns.finished())
      return true;
    turns.rethrow_failure();
    m_backward_pending = false;
    const Stream_surface_report& backward = m_s.backward_in_turns->report;
    if (ends_both_halves(backward)) {
      m_outcome = Outcome::DISCARDED;
      return false;
    }
    for (const auto& [sample, node] : m_seed_nodes)
      if (m_seed_vertices[sample]) {
        Node& seed_node = m_nodes[node];
        seed_node.vertex = m_seed_vertices[sample];
        if (std::exchange(seed_node.in_mesh, true))
          --m_report.number_of_vertices;
      }
    add_counts(backward, m_report);
    // The vertex limit was left out while the backward half's vertices were not known: as the
    // counts only grow, no time line passed it unless the whole count does now.
    if (m_report.number_of_vertices >= m_s.max_vertices) {
      m_outcome = Outcome::RERUN;
      return false;
    }
    return true;
  }

  static void add_counts(const Stream_surface_report& from, Stream_surface_report& to)
  {
    to.number_of_inserted_particles += from.number_of_inserted_particles;
    to.number_of_removed_particles += from.number_of_removed_particles;
    to.number_of_tears += from.number_of_tears;
    to.number_of_lost_particles += from.number_of_lost_particles;
    to.number_of_refused_faces += from.number_of_refused_faces;
    to.number_of_vertices += from.number_of_vertices;
    to.number_of_faces += from.number_of_faces;
    to.number_of_sample_batches += from.number_of_sample_batches;
  }

  static constexpr std::size_t no_node = std::numeric_limits<std::size_t>::max();

  // Where a particle is after `integrate_to_line()`.
  enum class Reach { LINE, EXIT, LOST };

  struct Particle {
    Particle(double u, Integrator integrator) : u(u), integrator(std::move(integrator)) {}
    double u;
    Integrator integrator;
    bool at_boundary = false; // it left the domain at x, before the current time line
    // The particle's node on the last time line put into the mesh (`no_node` for a particle
    // inserted after it).
    std::size_t node = no_node;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    double tau = 0; // of x: the current time line's, or where the particle left the domain
    // The node where the neighbour of this end particle of its piece left the domain: the
    // strips close the gap up to it while the particle stays within 2h of it.
    std::optional<std::size_t> boundary_neighbour;
    Eigen::Vector3d direction = Eigen::Vector3d::Zero(); // of the flow at x
  };
  struct Node {
    Eigen::Vector3d x;
    double u, tau;
    std::optional<vertex_descriptor> vertex;
    bool in_mesh = false; // a corner of a triangle (written or still to write), or a seed vertex
  };

  void finish(Stream_surface_termination why, std::string message)
  {
    m_report.termination = why;
    m_report.message = std::move(message);
  }

  static std::string printable(double x)
  {
    std::ostringstream os;
    os.precision(6);
    os << x;
    return os.str();
  }

  std::size_t add_node(const Particle& p)
  {
    m_nodes.push_back(Node{p.x, p.u, p.tau, std::nullopt});
    return m_nodes.size() - 1;
  }

  vertex_descriptor vertex(std::size_t n)
  {
    Node& node = m_nodes[n];
    if (!node.vertex) {
      const vertex_descriptor v = add_vertex(m_tm);
      put(m_vpm, v, Mesh_point(Mesh_FT(node.x[0]), Mesh_FT(node.x[1]), Mesh_FT(node.x[2])));
      put(m_u_map, v, node.u);
      put(m_t_map, v, node.tau == 0 ? 0. : m_s.written_tau_sign * node.tau);
      node.vertex = v;
    }
    return *node.vertex;
  }

  // Adds the triangle of nodes a, b, c to those `write_triangles()` puts into the mesh; its new
  // corners count as vertices at once (the limits and the progress see them).
  void add_triangle(std::size_t a, std::size_t b, std::size_t c)
  {
    if (m_s.reverse_triangles)
      std::swap(b, c);
    for (std::size_t n : {a, b, c})
      if (!std::exchange(m_nodes[n].in_mesh, true))
        ++m_report.number_of_vertices;
    m_triangles_to_write.push_back({a, b, c});
  }

  // Puts the triangles added since the last call into the mesh, their vertices made in the order
  // of their corners.  With a field that integrates ahead meanwhile, this runs while the other
  // processes integrate the next batch of tasks: it needs no sample, and it is 12 to 16 % of
  // rank 0's work on the tutorial's surface of the image on 2 ranks.
  void write_triangles()
  {
    if (m_backward_pending)
      return; // after the backward half's
    for (const std::array<std::size_t, 3>& t : m_triangles_to_write) {
      const std::array<vertex_descriptor, 3> v = {vertex(t[0]), vertex(t[1]), vertex(t[2])};
      if (CGAL::Euler::add_face(v, m_tm) == boost::graph_traits<TriangleMesh>::null_face())
        ++m_report.number_of_refused_faces;
      else
        ++m_report.number_of_faces;
    }
    m_triangles_to_write.clear();
  }

  // A particle released from the seed at c(u), advanced to the current time line; nothing if it
  // does not get there.
  // The particles at `us` released from the seed and advanced to the current time line
  // (`advance()`); none where that fails.
  std::vector<std::optional<Particle>> release(const std::vector<double>& us)
  {
    std::vector<std::optional<Particle>> released(us.size());
    std::vector<std::optional<Reach>> reach(us.size());
    std::vector<char> ok(us.size(), 0);
    run_tasks(
        us.size(),
        [&](std::size_t i) {
          if (!released[i] && !make_particle(released[i], us[i]))
            return;
          if (released[i]->integrator.is_start_inside())
            ok[i] = advance(*released[i], reach[i]);
        },
        [&](std::size_t i, Integration_ahead& ahead) { add_ahead(released[i], us[i], reach[i], ahead); },
        [&](std::size_t i, const double* state) { go_on(released[i], us[i], state); });
    for (std::size_t i = 0; i < us.size(); ++i)
      if (!ok[i])
        released[i].reset();
    return released;
  }

  // Advances the particles `ps` (`advance()`), together: whether each reached the time line.
  std::vector<char> advance_all(const std::vector<Particle*>& ps)
  {
    std::vector<std::optional<Reach>> reach(ps.size());
    std::vector<char> ok(ps.size(), 0);
    run_tasks(
        ps.size(), [&](std::size_t i) { ok[i] = advance(*ps[i], reach[i]); },
        [&](std::size_t i, Integration_ahead& ahead) {
          if (!reach[i] && !ps[i]->at_boundary)
            add_integrator(ps[i]->integrator, ahead);
        },
        [&](std::size_t i, const double* state) { ps[i]->integrator = Integrator(m_field, state); });
    return ok;
  }

  // Makes the particle released at c(u) into `p`; false when its task waits for the sample there.
  bool make_particle(std::optional<Particle>& p, double u) const
  {
    Integrator it(m_field, m_seed(u), m_s.t0, m_s.direction, m_s.tolerances);
    if (m_field.waiting())
      return false;
    p.emplace(u, std::move(it));
    return true;
  }

  // A released particle (at `u` on the seed, not made yet when `p` is empty) goes on from the
  // `state` that a field integrating ahead took it to.
  void go_on(std::optional<Particle>& p, double u, const double* state) const
  {
    Integrator it(m_field, state);
    if (p)
      p->integrator = std::move(it);
    else
      p.emplace(u, std::move(it));
  }

  // Adds a released particle (at `u` on the seed, not made yet when `p` is empty) to `ahead`
  // while it has not reached the time line.
  void add_ahead(const std::optional<Particle>& p, double u, const std::optional<Reach>& reach,
                 Integration_ahead& ahead) const
  {
    if (reach)
      return;
    if (p)
      add_integrator(p->integrator, ahead);
    else if (const Eigen::Vector3d x0 = m_seed(u); !stays_here(x0))
      ahead.add_start(x0);
  }

  // Adds a particle's integrator to `ahead`: its state; or, when its last step passed the current
  // time line, the one sample that `advance()` still takes, at its point on the line.
  void add_integrator(const Integrator& it, Integration_ahead& ahead) const
  {
    if (it.parameter() >= m_parameter) {
      const Eigen::Vector3d x = it.dense_output(m_parameter);
      if (!stays_here(x))
        ahead.add_last_sample(x, m_s.t0 + m_s.direction * m_parameter);
    }
    else if (!stays_here(it.position()))
      ahead.add_state(it);
  }

  // Whether a particle at x is left out of the particles integrated ahead: in the first round
  // of a batch of tasks, where this process alone decides (the field would leave it out).
  bool stays_here(const Eigen::Vector3d& x) const { return m_first_round && m_field.decided_here(x); }

  // Runs `task(i)` for i in [0, n).  With a field that answers batches, the tasks run in rounds,
  // one batch of samples per round (batched_sampling.h); a task must then commit its progress
  // only where it can be resumed: `reach` and the integrators' whole steps.  A field that
  // integrates ahead is told with each batch where the waiting tasks' particles stand
  // (`add_ahead(i, ahead)`); task i goes on from the state its particle reached there
  // (`go_on(i, state)`), and the samples taken after it are replayed.  A field that integrates
  // ahead meanwhile is told of every task's particle while the first round runs, but of those
  // that stand where this process alone decides (`stays_here()`); the triangles waiting to be
  // written are written in that round too.
  template <class Task, class Add_ahead, class Go_on>
  void run_tasks(std::size_t n, const Task& task, const Add_ahead& add_ahead, const Go_on& go_on)
  {
    if constexpr (!Field::is_batched) {
      for (std::size_t i = 0; i < n; ++i)
        task(i);
    }
    else {
      auto particles_of = [&](const std::vector<std::size_t>& tasks,
                              bool first_round) -> const Integration_ahead& {
        m_first_round = first_round;
        set_integration_ahead(m_ahead);
        m_task_of_particle.clear();
        for (std::size_t i : tasks) {
          add_ahead(i, m_ahead);
          m_task_of_particle.resize(m_ahead.size(), i);
        }
        m_first_round = false;
        return m_ahead;
      };
      auto add = [this](const Eigen::Vector3d& x, double t, std::optional<Eigen::Vector3d> v) {
        m_replay.add(x, t, std::move(v));
      };
      auto go_on_task = [&](std::size_t k, const double* state) { go_on(m_task_of_particle[k], state); };
      auto answer = [&](const auto& points, const std::vector<std::size_t>& waiting) {
        auto field = m_field;
        field.replay = nullptr;
        if constexpr (Field::integrates_ahead)
          return field(points, particles_of(waiting, false), add, go_on_task);
        else
          return field(points);
      };
      auto first = [&](const auto& round) {
        if constexpr (Field::integrates_ahead_meanwhile) {
          std::vector<std::size_t> all(n);
          for (std::size_t i = 0; i < n; ++i)
            all[i] = i;
          return m_field.integrate_ahead_meanwhile(
              particles_of(all, true),
              [&] {
                round();
                write_triangles();
                if (m_backward_pending && !m_ahead.empty())
                  give_backward_half_turns();
              },
              add, go_on_task);
        }
        else {
          round();
          return false;
        }
      };
      m_report.number_of_sample_batches += run_in_rounds(n, m_replay, task, answer, first);
      m_replay.clear();
    }
  }

  // Makes `ahead` the settings of the particles integrated ahead to the current time line, with
  // no particle yet (its records keep their memory from one batch of tasks to the next).
  void set_integration_ahead(Integration_ahead& ahead) const
  {
    ahead.particles.clear();
    ahead.t0 = m_s.t0;
    ahead.direction = m_s.direction;
    ahead.normalize = m_field.normalize;
    ahead.target = m_parameter;
    ahead.max_steps = double(m_s.max_steps);
    ahead.tolerances = m_s.tolerances;
  }

  // Advances `p` to the current time line, or to where it leaves the domain before it (then
  // `at_boundary`, at the last point inside that the integrator located by bisection), and
  // samples the flow's direction there.  False if it left before, stagnates, or has taken
  // max_number_of_steps steps since the seed (so every loop has a bound); also if it leaves
  // within 1e-3 Δ after the previous time line, whose node is then its last (a later one would
  // only make slivers).  `reach` keeps where the integration got to (see `run_tasks()`).
  bool advance(Particle& p, std::optional<Reach>& reach)
  {
    if (p.at_boundary)
      return false;
    if (!reach)
      reach = integrate_to_line(p.integrator);
    if (!reach) // waits for a sample
      return false;
    if (*reach == Reach::LOST)
      return false;
    const Integrator& it = p.integrator;
    const bool exit = *reach == Reach::EXIT;
    const double tau = exit ? it.parameter() : m_parameter;
    const Eigen::Vector3d x = exit ? it.position() : it.dense_output(m_parameter);
    const std::optional<Eigen::Vector3d> v = m_field(x, m_s.t0 + m_s.direction * tau);
    if (m_field.waiting())
      return false;
    p.at_boundary = exit;
    p.tau = tau;
    p.x = x;
    if (!v)
      return false;
    const double speed = v->norm();
    p.direction = speed > 0 ? Eigen::Vector3d(*v / speed) : Eigen::Vector3d::Zero();
    return speed > 0;
  }

  // Integrates to the current time line, a whole step at a time (resumable after each); nothing
  // when the task waits for a sample.
  std::optional<Reach> integrate_to_line(Integrator& it)
  {
    while (it.parameter() < m_parameter) {
      if (it.number_of_accepted_steps() >= m_s.max_steps)
        return Reach::LOST;
      const Step_result r = it.resumable_step(); // a suspended step is made again
      if (r == Step_result::SUSPENDED)
        return std::nullopt;
      if (r == Step_result::LEFT_DOMAIN)
        return it.parameter() <= m_previous_parameter + 1e-3 * m_s.step ? Reach::LOST : Reach::EXIT;
      if (r != Step_result::ACCEPTED)
        return Reach::LOST;
    }
    return Reach::LINE;
  }

  void seed_front()
  {
    // Resample the seed at spacing at most h; runs of seed points inside the domain and not at
    // rest make the first front pieces.
    const std::size_t n = static_cast<std::size_t>(
        std::min(std::ceil(m_seed.length() / m_s.spacing), double(m_s.max_vertices)));
    m_seed_vertices.resize(n + 1); // the same samples in both halves
    std::vector<double> us(n + 1);
    for (std::size_t i = 0; i <= n; ++i)
      us[i] = i == n ? m_seed.length() : m_seed.length() * double(i) / double(n);
    std::vector<std::optional<Particle>> particles(n + 1);
    std::vector<char> inside(n + 1, 0), moving(n + 1, 0);
    std::vector<std::optional<Reach>> reach(n + 1);
    run_tasks(
        n + 1,
        [&](std::size_t i) {
          if (!particles[i] && !make_particle(particles[i], us[i]))
            return;
          inside[i] = particles[i]->integrator.is_start_inside();
          if (inside[i])
            moving[i] = advance(*particles[i], reach[i]); // τ = 0: the flow direction at the seed point
        },
        [&](std::size_t i, Integration_ahead& ahead) { add_ahead(particles[i], us[i], reach[i], ahead); },
        [&](std::size_t i, const double* state) { go_on(particles[i], us[i], state); });
    std::vector<Particle> piece;
    for (std::size_t i = 0; i <= n; ++i) {
      if (moving[i]) {
        Particle& p = *particles[i];
        p.node = add_node(p);
        if (!m_backward_pending) { // else when the backward half is taken in
          m_nodes[p.node].vertex = m_seed_vertices[i];
          m_nodes[p.node].in_mesh = m_seed_vertices[i].has_value();
        }
        m_seed_nodes.emplace_back(i, p.node);
        piece.push_back(std::move(p));
      }
      else if (!piece.empty()) {
        m_pieces.push_back(std::move(piece));
        piece.clear();
      }
    }
    if (!piece.empty())
      m_pieces.push_back(std::move(piece));
    const std::size_t number_inside = std::size_t(std::count(inside.begin(), inside.end(), 1));
    const std::size_t number_moving = std::size_t(std::count(moving.begin(), moving.end(), 1));
    m_report.number_of_lost_particles += (n + 1) - number_moving;
    if (number_inside == 0) {
      m_pieces.clear();
      finish(Stream_surface_termination::SEED_OUTSIDE_DOMAIN,
             "every point of the seed is outside the domain");
    }
    else if (number_moving == 0) {
      m_pieces.clear();
      finish(Stream_surface_termination::SEED_AT_REST,
             "the field is zero at every point of the seed inside the domain");
    }
  }

  double cosine(const Particle& a, const Particle& b) const { return a.direction.dot(b.direction); }

  // What happens between two neighbours of a run.
  enum class Gap { OPEN, CLOSED, TORN };

  // Whether neighbours a and b are close enough and move alike (CLOSED), need a re-integrated
  // particle between them (OPEN), or cannot get one (TORN).
  Gap gap(const Particle& a, const Particle& b) const
  {
    const double d = (b.x - a.x).norm();
    const bool wide = d > 2 * m_s.spacing;
    const bool turning = cosine(a, b) < m_s.tear_cosine;
    if (!wide && !turning)
      return Gap::CLOSED;
    const bool refinable =
        b.u - a.u > m_s.min_gap && (wide || d > m_s.spacing) && m_nodes.size() < 2 * m_s.max_vertices;
    return refinable ? Gap::OPEN : Gap::TORN;
  }

  // The run's particles as front pieces: between neighbours that diverge, particles are
  // inserted (re-integrated from the seed half-way in u) while the gap is too wide or the flow
  // turns too much between them; the front is torn where that is not possible.  Level by level,
  // the insertions of a level integrated together; each gap's outcome depends on its two ends
  // only.  The levels are bounded by log2(2h / min_gap).
  std::vector<std::vector<Particle>> connect(std::vector<Particle>&& run)
  {
    std::vector<Particle> line = std::move(run);
    std::vector<Gap> gaps; // gaps[i]: between line[i] and line[i + 1]
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
      gaps.push_back(gap(line[i], line[i + 1]));
    for (;;) {
      std::vector<double> us;
      for (std::size_t i = 0; i < gaps.size(); ++i)
        if (gaps[i] == Gap::OPEN)
          us.push_back(0.5 * (line[i].u + line[i + 1].u));
      if (us.empty())
        break;
      std::vector<std::optional<Particle>> inserted = release(us);
      std::vector<Particle> finer;
      std::vector<Gap> finer_gaps;
      for (std::size_t i = 0, k = 0; i < line.size(); ++i) {
        finer.push_back(std::move(line[i]));
        if (i + 1 == line.size())
          break;
        if (gaps[i] != Gap::OPEN || !inserted[k]) {
          if (gaps[i] == Gap::OPEN) {
            ++m_report.number_of_lost_particles;
            ++k;
          }
          finer_gaps.push_back(gaps[i] == Gap::CLOSED ? Gap::CLOSED : Gap::TORN);
          continue;
        }
        ++m_report.number_of_inserted_particles;
        finer.push_back(std::move(*inserted[k++]));
        finer_gaps.push_back(gap(finer[finer.size() - 2], finer.back()));
        finer_gaps.push_back(gap(finer.back(), line[i + 1]));
      }
      line = std::move(finer);
      gaps = std::move(finer_gaps);
    }
    std::vector<std::vector<Particle>> pieces(1);
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (i > 0 && gaps[i - 1] == Gap::TORN) {
        ++m_report.number_of_tears;
        pieces.emplace_back();
      }
      pieces.back().push_back(std::move(line[i]));
    }
    return pieces;
  }

  // Removes particles closer than h/2 to their predecessor (an interior one of the two).
  void remove_converging(std::vector<Particle>& run)
  {
    for (std::size_t i = 0; i + 1 < run.size();) {
      if ((run[i + 1].x - run[i].x).norm() >= 0.5 * m_s.spacing) {
        ++i;
        continue;
      }
      const std::size_t victim = (i + 2 < run.size() || i == 0) ? i + 1 : i;
      run.erase(run.begin() + std::ptrdiff_t(victim));
      ++m_report.number_of_removed_particles;
      if (victim == i && i > 0)
        --i;
    }
  }

  // The strip between the old time line `old_chain` and the new one `new_chain` (nodes in order
  // of u), by the shorter-diagonal rule.
  void zip(const std::vector<std::size_t>& o, const std::vector<std::size_t>& n)
  {
    if (o.empty() || n.empty() || o.size() + n.size() < 3)
      return;
    std::size_t i = 0, j = 0;
    while (i + 1 < o.size() || j + 1 < n.size()) {
      const bool along_old = j + 1 == n.size() ||
                             (i + 1 < o.size() && (m_nodes[o[i + 1]].x - m_nodes[n[j]].x).squaredNorm() <=
                                                      (m_nodes[o[i]].x - m_nodes[n[j + 1]].x).squaredNorm());
      if (along_old) {
        add_triangle(o[i], o[i + 1], n[j]);
        ++i;
      }
      else {
        add_triangle(o[i], n[j + 1], n[j]);
        ++j;
      }
    }
  }

  // The piece's strip to the new time line, which its particles reached where `reached` says.
  void advance_piece(std::vector<Particle>& piece, const char* reached,
                     std::vector<std::vector<Particle>>& next)
  {
    std::vector<std::pair<double, std::size_t>> old_line; // (u, node) of the last meshed time line
    for (const Particle& p : piece)
      if (p.node != no_node)
        old_line.emplace_back(p.u, p.node);
    const std::array<std::size_t, 3> changes_before = {
        m_report.number_of_lost_particles, m_report.number_of_removed_particles, m_report.number_of_tears};

    // Runs of particles that reach the new time line.
    std::vector<std::vector<Particle>> runs(1);
    for (std::size_t i = 0; i < piece.size(); ++i) {
      if (reached[i])
        runs.back().push_back(std::move(piece[i]));
      else {
        ++m_report.number_of_lost_particles;
        if (!runs.back().empty())
          runs.emplace_back();
      }
    }
    for (std::vector<Particle>& run : runs) {
      if (run.empty())
        continue;
      remove_converging(run);
      std::vector<std::vector<Particle>> pieces = connect(std::move(run));
      // A piece that only moved (and gained inserted particles) since its last meshed time line
      // waits for the next one while the strip would be thin: sheared fronts turn towards the
      // flow, and their strips, h wide, get ever flatter.
      if (m_s.skip_thin_strips && runs.size() == 1 && pieces.size() == 1 && !m_last_line &&
          changes_before == std::array<std::size_t, 3>{m_report.number_of_lost_particles,
                                                       m_report.number_of_removed_particles,
                                                       m_report.number_of_tears} &&
          is_thin_strip(pieces.front())) {
        next.push_back(std::move(pieces.front()));
        continue;
      }
      for (std::vector<Particle>& new_piece : pieces) {
        std::vector<std::size_t> old_chain, new_chain;
        for (Particle& p : new_piece) {
          p.node = add_node(p);
          new_chain.push_back(p.node);
        }
        const double first = new_piece.front().u, last = new_piece.back().u;
        for (const auto& [u, node] : old_line)
          if (u >= first && u <= last)
            old_chain.push_back(node);
        // After a tear, a piece can span a single node of the old time line: its fan would touch
        // the strip below in that vertex only (a pinched, non-manifold vertex), so it gets a
        // copy of the node of its own.
        if (old_chain.size() == 1 && new_chain.size() >= 2 && m_nodes[old_chain.front()].in_mesh) {
          const Node copy{m_nodes[old_chain.front()].x, m_nodes[old_chain.front()].u,
                          m_nodes[old_chain.front()].tau, std::nullopt};
          m_nodes.push_back(copy);
          old_chain.front() = m_nodes.size() - 1;
        }
        zip(old_chain, new_chain);
        close_towards_boundary_neighbours(new_piece, old_chain);
        continue_without_boundary_particles(std::move(new_piece), next);
      }
    }
  }

  // Whether the strip from the piece's last meshed time line to its particles would be thinner
  // than h/2 somewhere and nowhere as wide as h: the width at a particle is its displacement
  // since its meshed node across the front (orthogonal to the front's local tangent), at the
  // ends its whole displacement (a border edge: longer ones make slivers in the corner where a
  // turned front meets its border stream line).  Only a piece whose particles all stay inside,
  // with none at an exit, qualifies.
  bool is_thin_strip(const std::vector<Particle>& piece) const
  {
    if (piece.size() < 2)
      return false;
    double smallest = std::numeric_limits<double>::infinity(), largest = 0;
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const Particle& p = piece[i];
      if (p.at_boundary || p.boundary_neighbour)
        return false;
      if (p.node == no_node)
        continue;
      const Eigen::Vector3d tangent =
          (piece[std::min(i + 1, piece.size() - 1)].x - piece[i == 0 ? 0 : i - 1].x).normalized();
      const Eigen::Vector3d d = p.x - m_nodes[p.node].x;
      const double width = (d - d.dot(tangent) * tangent).norm();
      smallest = std::min(smallest, width);
      largest = std::max(largest, i == 0 || i + 1 == piece.size() ? d.norm() : width);
    }
    return smallest < 0.5 * m_s.spacing && largest < m_s.spacing;
  }

  // The triangle from an end particle's old node to its new one and the node where its
  // neighbour left the domain: a fan around that node, over the time lines until the particle
  // leaves too or is more than 2h away, fills the notch between the two exits.
  void close_towards_boundary_neighbours(std::vector<Particle>& piece,
                                         const std::vector<std::size_t>& old_chain)
  {
    for (std::size_t end = 0; end < std::min<std::size_t>(piece.size(), 2); ++end) {
      Particle* p = end == 0 ? &piece.front() : &piece.back();
      if (!p->boundary_neighbour || old_chain.empty())
        continue;
      const std::size_t exit = *std::exchange(p->boundary_neighbour, std::nullopt);
      const bool before = m_nodes[exit].u < p->u; // the neighbour's seed parameter is the smaller one
      const std::size_t old = before ? old_chain.front() : old_chain.back();
      if (m_nodes[old].u != p->u)
        continue;
      if (before)
        add_triangle(exit, old, p->node);
      else
        add_triangle(old, exit, p->node);
      if (!p->at_boundary && (p->x - m_nodes[exit].x).norm() <= 2 * m_s.spacing)
        p->boundary_neighbour = exit;
    }
  }

  // The runs of particles of `piece` that did not leave the domain go on; their ends next to a
  // particle that left remember where it left.  A run needs two particles, or one that fans out
  // from such an exit.
  void continue_without_boundary_particles(std::vector<Particle>&& piece,
                                           std::vector<std::vector<Particle>>& next)
  {
    const auto goes_on = [](const std::vector<Particle>& run) {
      return run.size() >= 2 || (run.size() == 1 && run.front().boundary_neighbour);
    };
    std::vector<Particle> run;
    std::optional<std::size_t> exit_before; // where the particle before the run left the domain
    for (Particle& p : piece) {
      if (!p.at_boundary) {
        if (run.empty() && exit_before)
          p.boundary_neighbour = exit_before;
        run.push_back(std::move(p));
        continue;
      }
      ++m_report.number_of_lost_particles;
      if (!run.empty())
        run.back().boundary_neighbour = p.node;
      if (goes_on(run))
        next.push_back(std::move(run));
      run.clear();
      exit_before = p.node;
    }
    if (goes_on(run))
      next.push_back(std::move(run));
  }

  Field m_field;
  Replay_samples<typename Field::Value> m_replay; // with a field that answers batches
  // With a field that integrates ahead: the waiting tasks' particles, and the task of each.
  Integration_ahead m_ahead;
  std::vector<std::size_t> m_task_of_particle;
  bool m_first_round = false; // while the first round's particles are written
  const Seed_curve& m_seed;
  Settings m_s;
  TriangleMesh& m_tm;
  VPM m_vpm;
  UMap m_u_map;
  TMap m_t_map;
  Seed_vertices& m_seed_vertices;
  std::vector<std::pair<std::size_t, std::size_t>> m_seed_nodes; // (seed sample, node)
  Stream_surface_report m_report;
  std::vector<Node> m_nodes;
  std::vector<std::array<std::size_t, 3>> m_triangles_to_write; // nodes, in the mesh's order
  std::vector<std::vector<Particle>> m_pieces;
  double m_parameter = 0, m_previous_parameter = 0; // of the current and the previous time line
  bool m_last_line = false;
  bool m_backward_pending; // the backward half integrated in turns with this one is not taken in yet
  Outcome m_outcome = Outcome::DONE;
};

// A writable property map that drops what it is given (the default of the u and t maps).
struct Ignored_vertex_double_map {
  template <class Key>
  friend void put(const Ignored_vertex_double_map&, const Key&, double)
  {
  }
};

// The stream lines' own options (tolerances, max_time / max_length, steps, direction), with
// tolerances tighter than a stream line's defaults: the vertices then follow the sampled field as
// closely as its interpolation allows (1e-8 drifted up to 1.6 × that floor on a trilinear grid).
template <class NamedParameters>
Streamline_options read_stream_surface_line_options(const NamedParameters& np)
{
  Streamline_options lines = read_streamline_options(np, "integrate_stream_surface");
  if constexpr (parameters::is_default_parameter<NamedParameters, internal_np::relative_tolerance_t>::value)
    lines.tolerances.relative = 1e-10;
  if constexpr (parameters::is_default_parameter<NamedParameters, internal_np::absolute_tolerance_t>::value)
    lines.tolerances.absolute = 1e-12;
  return lines;
}

// h over the median speed at the seed points: time lines about h apart (h where the field is
// zero or undefined at every sample).
template <class Field>
double median_speed_time_line_step(const Field& f, const Seed_curve& seed, double spacing, double t0)
{
  std::vector<double> speeds;
  const std::size_t n = std::min<std::size_t>(64, seed.number_of_segments());
  std::vector<std::pair<Eigen::Vector3d, double>> points;
  for (std::size_t i = 0; i <= n; ++i)
    points.emplace_back(seed(seed.length() * double(i) / double(n)), t0);
  for (const std::optional<Eigen::Vector3d>& v : f(points)) // one batch
    if (v && v->norm() > 0)
      speeds.push_back(v->norm());
  std::nth_element(speeds.begin(), speeds.begin() + std::ptrdiff_t(speeds.size() / 2), speeds.end());
  return speeds.empty() ? spacing : spacing / speeds[speeds.size() / 2];
}

// The front's settings from the named parameters, each checked, for the front spacing h and the
// stream lines' options `lines`.
template <class Settings, class Point_3, class FlowField, class NamedParameters>
Settings read_stream_surface_settings(const FlowField& field, const Seed_curve& seed, bool arc_length,
                                      double spacing, const Streamline_options& lines,
                                      const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double max_parameter = arc_length ? lines.max_length : lines.max_time;
  const double t0 = choose_parameter(get_parameter(np, internal_np::start_time_t()), 0.);
  if (!std::isfinite(t0))
    checked_positive(t0, "start_time");
  const double tear_angle = choose_parameter(get_parameter(np, internal_np::tear_angle_t()), CGAL_PI / 4);
  checked_positive(tear_angle, "tear_angle");
  const std::size_t max_vertices = std::size_t(
      checked_positive(double(choose_parameter(get_parameter(np, internal_np::max_number_of_vertices_t()),
                                               std::size_t(1000000))),
                       "max_number_of_vertices"));
  // Without a limit in τ at most 100 time lines by default; with one, only the limit (and
  // max_number_of_vertices) unless max_number_of_time_lines is given.
  const std::size_t max_time_lines = choose_parameter(
      get_parameter(np, internal_np::max_number_of_time_lines_t()),
      std::isfinite(max_parameter) ? std::numeric_limits<std::size_t>::max() : std::size_t(100));
  if (max_time_lines == 0)
    throw std::invalid_argument(
        "integrate_stream_surface: max_number_of_time_lines is 0; expected at least 1");

  constexpr bool default_step =
      parameters::is_default_parameter<NamedParameters, internal_np::time_line_step_t>::value;
  double step;
  if constexpr (!default_step)
    step = checked_positive(get_parameter(np, internal_np::time_line_step_t()), "time_line_step");
  else if (arc_length)
    step = spacing;
  else
    step = median_speed_time_line_step(Front_field<FlowField, Point_3>{&field, false}, seed, spacing, t0);

  Settings settings{spacing,
                    step,
                    max_parameter,
                    t0,
                    std::cos(std::min(tear_angle, CGAL_PI)),
                    1e-9 * seed.length(),
                    max_time_lines,
                    max_vertices,
                    lines.max_number_of_steps,
                    lines.direction == Integration_direction::BACKWARD ? -1 : 1,
                    lines.tolerances};
  settings.skip_thin_strips = default_step;
  // No particle steps past the surface's end: a path surface that ends where its unsteady field
  // ends (the last step of a time series) would otherwise lose the particles whose steps sample
  // the field after it.
  settings.tolerances.max_parameter = max_parameter;
  settings.callback = progress_callback(np);
  return settings;
}

// The two halves of a BOTH surface in a field whose other processes integrate while this one
// works (a distributed field): the backward half is integrated in turns with the forward half,
// on a thread of its own while the other processes integrate the forward half's particles
// (Taking_turns.h), instead of before the forward half while they wait.  The surface and the
// report are those of the halves one after the other, bit for bit; but the callback hears of
// the forward half's time lines only from the end of the backward half on.
template <class Front, class Backward_front, class FlowField, class TriangleMesh, class VPM, class UMap,
          class TMap>
Stream_surface_report integrate_halves_in_turns(const FlowField& field, bool arc_length,
                                                const Seed_curve& seed, const Front_settings& settings,
                                                const Stream_surface_report& start, TriangleMesh& tm, VPM vpm,
                                                UMap u_map, TMap t_map)
{
  typename Front::Seed_vertices seed_vertices;
  Backward_half_in_turns backward([&](Taking_turns& own, bool& stopping) {
    Front_settings half = backward_half(settings, true);
    // Each time line of the backward half ends a turn: its progress is reported on the caller's
    // thread.
    half.callback = [&own, &stopping, callback = settings.callback](double done) {
      return own.ask(Taking_turns::Request::LOCAL, [&] {
        stopping = !report_progress(callback, done);
        return !stopping;
      });
    };
    const Field_in_turns<FlowField> in_turns{&field, &own};
    return Backward_front(in_turns, arc_length, seed, half, tm, vpm, u_map, t_map, seed_vertices).run(start);
  });
  Front_settings forward = forward_half_of_both(settings);
  forward.backward_in_turns = &backward;
  Front front(field, arc_length, seed, forward, tm, vpm, u_map, t_map, seed_vertices);
  Stream_surface_report report = front.run(start);
  switch (front.outcome()) {
  case Front::Outcome::DISCARDED:
    return with_backward_half(backward.report);
  case Front::Outcome::RERUN:
    forward.backward_in_turns = nullptr;
    return Front(field, arc_length, seed, forward, tm, vpm, u_map, t_map, seed_vertices)
        .run(with_backward_half(backward.report));
  default:
    report.backward = with_backward_half(backward.report).backward;
    return report;
  }
}

} // namespace internal

/*!
\ingroup PkgFlowAlignedSurfacesRef
\brief integrates the stream surface (steady field) or path surface (unsteady field) seeded by a
polyline with an advancing front, and adds it to `tm_out` as a triangle mesh.

The surface \f$ x(u, \tau) \f$ solves
\f$ \partial_\tau x = \sigma v(x, t_0 + \sigma \tau) \f$ with \f$ x(u, 0) = c(u) \f$, the seed
polyline parametrized by its arc length \f$ u \in [0, L] \f$, \f$ \sigma = -1 \f$ with
`integration_direction(Integration_direction::BACKWARD)`.  With `Integration_direction::BOTH` the
backward and the forward half are one surface, joined at the seed curve (its vertices shared):
the union of the `FORWARD` and `BACKWARD` surfaces.  Every surface is oriented by
\f$ \partial x / \partial u \times v \f$.  The front, a polyline of particles resampled from the seed at
spacing at most \f$ h \f$, advances in lock-step of \f$ \tau \f$ by the time-line step
\f$ \Delta \f$; each particle is integrated by the embedded Runge–Kutta pair of Dormand and
Prince, 5(4) (`relative_tolerance`, `absolute_tolerance`, as `integrate_streamline()`), and
evaluated on the time line by dense output.  Between consecutive time lines:
- where two neighbours are farther than \f$ 2h \f$ apart, or farther than \f$ h \f$ with flow
  directions more than `tear_angle` apart, a particle integrated anew from
  \f$ c((u_i + u_{i+1})/2) \f$ (not interpolated on the front) is inserted, recursively;
- where two neighbours are closer than \f$ h/2 \f$, one is removed (not the end of a piece);
- the front tears (its pieces continue independently) where a particle leaves the domain,
  stagnates or has taken `max_number_of_steps` steps, where a particle re-integrated for an insertion does, and where the refinement
  would need seed parameters closer than \f$ 10^{-9} L \f$ (neighbours separating at an
  obstacle or a critical point), or two neighbours closer than \f$ h \f$ have flow directions
  more than `tear_angle` apart;
- a particle that leaves the domain before the time line ends where it leaves (the last point
  inside, located by bisection within the integrator's boundary tolerance, as in
  `integrate_streamline()`) and takes part in the strip there: the surface reaches the boundary;
  the strips of its neighbour fan out from that exit until the neighbour leaves too or is more
  than \f$ 2h \f$ away, so that no notch is left between two exits;
- the strip is triangulated by the shorter-diagonal rule (Hultquist);
- with the default `time_line_step`, a piece of the front that only moved since its last time
  line in the mesh (no particle lost, removed or torn off) skips the new time line while the
  strip would be thinner than \f$ h/2 \f$ somewhere and nowhere \f$ h \f$ wide (at its ends:
  long): sheared fronts turn towards the flow, and their strips would get
  ever flatter.  The last time line is never less than \f$ \Delta/2 \f$ after the one before.

Integration stops at `max_time` (`max_length` with arc-length time lines), after `max_number_of_time_lines`, at
`max_number_of_vertices`, when no piece of the front is left, or when the `callback` asks to; the report's `termination` and
`message` say which limit, with its value and how far the front got.  A closed seed (first
point = last point) gives a surface with a seam.

Every vertex carries the seed parameter \f$ u \f$ of its particle (`seed_parameter_map`) and the
time-line parameter \f$ \tau \f$ (`integration_time_map`): the time-line / stream-line
parametrization of the paper's Figure 3 — the curves of constant \f$ \tau \f$ are the time lines,
those of constant \f$ u \f$ are stream lines (path lines).  All vertices of a time line have the
same \f$ \tau = k \Delta \f$ exactly (the last one: the limit); a vertex where a particle left the domain has the
\f$ \tau \f$ at which it left, between two time lines.  With `BOTH`, the backward half's vertices
get \f$ -\tau \f$.

Vertices and faces are added to `tm_out`; what it held before is kept.

A field that answers batches (the optional `sample()` of the concepts) is sampled a time line
at a time: the particles' Runge-Kutta stages, one batch each, and the particles re-integrated from
the seed, level by level, one batch per stage of their paths; the surface is the same, bit for
bit.  The report counts the batches.

\tparam FlowField a model of `FlowField_3` (a stream surface) or of `UnsteadyFlowField_3` (a path
        surface: it is called with `(p, t)`)
\tparam PointRange a range of points of a CGAL kernel (`FlowField`'s point type)
\tparam TriangleMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of named parameters

\param field the flow field
\param seed_polyline the seed curve, at least two points, finite, no two consecutive points equal
\param tm_out receives the surface
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{front_spacing}
    \cgalParamDescription{`FAS::parameters::front_spacing()`: \f$ h \f$}
    \cgalParamType{`double`}
    \cgalParamDefault{the mean segment length of `seed_polyline`}
  \cgalParamNEnd
  \cgalParamNBegin{time_line_step}
    \cgalParamDescription{`FAS::parameters::time_line_step()`: \f$ \Delta \f$}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$ h \f$ over the median speed at the seed points (with arc-length time lines: \f$ h \f$)}
  \cgalParamNEnd
  \cgalParamNBegin{max_time}
    \cgalParamDescription{`FAS::parameters::max_time()`: the largest \f$ \tau \f$ (time time lines)}
    \cgalParamType{`double`}
    \cgalParamDefault{no limit}
  \cgalParamNEnd
  \cgalParamNBegin{max_length}
    \cgalParamDescription{`FAS::parameters::max_length()`: the largest \f$ \tau \f$ with arc-length time
      lines (ignored otherwise)}
    \cgalParamType{`double`}
    \cgalParamDefault{no limit}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_time_lines}
    \cgalParamDescription{`FAS::parameters::max_number_of_time_lines()`, at least 1}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{no limit when `max_time` (`max_length` with arc-length time lines) is given,
      else `100`}
  \cgalParamNEnd
  \cgalParamNBegin{arc_length_time_lines}
    \cgalParamDescription{`FAS::parameters::arc_length_time_lines()`: whether \f$ \tau \f$ is the arc
      length (the field is normalized); steady fields only}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{integration_direction}
    \cgalParamDescription{`FAS::parameters::integration_direction()`: `FORWARD`, `BACKWARD`
      (\f$ \sigma = -1 \f$) or `BOTH` (one surface, joined at the seed)}
    \cgalParamType{`Integration_direction`}
    \cgalParamDefault{`Integration_direction::FORWARD`}
  \cgalParamNEnd
  \cgalParamNBegin{relative_tolerance, absolute_tolerance, max_number_of_steps}
    \cgalParamDescription{the integrator's, per particle, as in `integrate_streamline()`; the
      tolerances' defaults are tighter than a stream line's, so that on a sampled field the
      vertices drift no more than the interpolation itself allows}
    \cgalParamDefault{`1e-10`, `1e-12`, `100000`}
  \cgalParamNEnd
  \cgalParamNBegin{start_time}
    \cgalParamDescription{`FAS::parameters::start_time()`: \f$ t_0 \f$ (unsteady fields)}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{tear_angle}
    \cgalParamDescription{`FAS::parameters::tear_angle()`: radians}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$ \pi/4 \f$}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_vertices}
    \cgalParamDescription{`FAS::parameters::max_number_of_vertices()`}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`1000000`}
  \cgalParamNEnd
  \cgalParamNBegin{seed_parameter_map}
    \cgalParamDescription{`FAS::parameters::seed_parameter_map()`: receives \f$ u \f$ of every new vertex}
    \cgalParamType{a model of `WritablePropertyMap` from `vertex_descriptor` to `double`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{integration_time_map}
    \cgalParamDescription{`FAS::parameters::integration_time_map()`: receives \f$ \tau \f$ of every new vertex}
    \cgalParamType{a model of `WritablePropertyMap` from `vertex_descriptor` to `double`}
    \cgalParamDefault{not written}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{CGAL's progress callback (`CGAL::parameters::callback()`), called after
      each time line with the fraction done: the largest of \f$ \tau \f$ over its limit, the time
      lines over `max_number_of_time_lines` and the vertices over `max_number_of_vertices` (with
      `BOTH`, the backward half maps to \f$ [0, 1/2] \f$ and the forward half to
      \f$ [1/2, 1] \f$), and `1` after the last time line, whatever ended the integration.  If it
      returns `false` before the last time line, the integration stops there: `tm_out` holds the
      surface up to that time line (with `BOTH`, after a stop in the backward half, no forward
      half), the termination is `STOPPED` and the report's `stopped` is set (see \ref fas_progress).
      With `BOTH` and a field whose other processes integrate the particles while this one works
      (the ParaView plugin's field of data spread over MPI ranks), the backward half is integrated
      in turns with the forward half, while the other processes integrate the forward half's
      particles: the surface and the report are the same, but the callback hears of the forward
      half's time lines only from the end of the backward half on.}
    \cgalParamType{a callable convertible to `std::function<bool(double)>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the points of the vertices of `tm_out`}
    \cgalParamType{a model of `WritablePropertyMap`}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm_out)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the report: time lines, inserted and removed particles, tears, the termination reason
  (with `BOTH`: the counts of the whole surface, the forward half's time lines and reason, and
  `backward` for the backward half's).
  A seed entirely outside the domain, or at rest, gives an empty result
  (`SEED_OUTSIDE_DOMAIN`, `SEED_AT_REST`) and leaves `tm_out` untouched.

\throws std::invalid_argument naming the input if `seed_polyline` has fewer than two points, a
  non-finite point or two equal consecutive points, if a parameter is not positive, or if
  `arc_length_time_lines(true)` is given with an unsteady field, or `max_number_of_time_lines` is 0.

\sa `extract_iso_contours()` for seed curves, `normalized_flux()` to check the result
*/
template <class FlowField, class PointRange, class TriangleMesh,
          class NamedParameters = parameters::Default_named_parameters>
Stream_surface_report integrate_stream_surface(const FlowField& field, const PointRange& seed_polyline,
                                               TriangleMesh& tm_out,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Point_3 = typename std::iterator_traits<decltype(std::begin(seed_polyline))>::value_type;
  using Field = internal::Front_field<FlowField, Point_3>;

  const internal::Seed_curve seed(seed_polyline);
  const bool arc_length = choose_parameter(get_parameter(np, internal_np::arc_length_time_lines_t()), false);
  if (arc_length && Field::is_unsteady)
    throw std::invalid_argument("integrate_stream_surface: arc_length_time_lines(true) needs a steady field; "
                                "the field is unsteady (called with a point and a time)");
  const double spacing =
      internal::checked_positive(choose_parameter(get_parameter(np, internal_np::front_spacing_t()),
                                                  seed.length() / double(seed.number_of_segments())),
                                 "front_spacing");
  const internal::Streamline_options lines = internal::read_stream_surface_line_options(np);

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tm_out));
  const auto u_map = choose_parameter(get_parameter(np, internal_np::seed_parameter_map_t()),
                                      internal::Ignored_vertex_double_map());
  const auto t_map = choose_parameter(get_parameter(np, internal_np::integration_time_map_t()),
                                      internal::Ignored_vertex_double_map());
  using Front = internal::Stream_surface_front<FlowField, Point_3, TriangleMesh, std::decay_t<decltype(vpm)>,
                                               std::decay_t<decltype(u_map)>, std::decay_t<decltype(t_map)>>;
  typename Front::Settings settings =
      internal::read_stream_surface_settings<typename Front::Settings, Point_3>(field, seed, arc_length,
                                                                                spacing, lines, np);

  Stream_surface_report report;
  report.seed_length = seed.length();
  report.front_spacing = spacing;
  report.time_line_step = settings.step;
  if constexpr (Field::integrates_ahead_meanwhile)
    if (lines.direction == Integration_direction::BOTH) {
      using Backward_front =
          internal::Stream_surface_front<internal::Field_in_turns<FlowField>, Point_3, TriangleMesh,
                                         std::decay_t<decltype(vpm)>, std::decay_t<decltype(u_map)>,
                                         std::decay_t<decltype(t_map)>>;
      return internal::integrate_halves_in_turns<Front, Backward_front>(field, arc_length, seed, settings,
                                                                        report, tm_out, vpm, u_map, t_map);
    }
  typename Front::Seed_vertices seed_vertices;
  if (lines.direction == Integration_direction::FORWARD)
    return Front(field, arc_length, seed, settings, tm_out, vpm, u_map, t_map, seed_vertices).run(report);
  const bool both = lines.direction == Integration_direction::BOTH;
  report = Front(field, arc_length, seed, internal::backward_half(settings, both), tm_out, vpm, u_map, t_map,
                 seed_vertices)
               .run(report);
  if (!both)
    return report;
  report = internal::with_backward_half(report);
  if (internal::ends_both_halves(report))
    return report;
  // The forward half reuses the backward half's seed vertices and adds its counts to the
  // backward half's.
  return Front(field, arc_length, seed, internal::forward_half_of_both(settings), tm_out, vpm, u_map, t_map,
               seed_vertices)
      .run(report);
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTEGRATE_STREAM_SURFACE_H
