// The velocity of an input distributed over MPI ranks, as a FlowField_3 for an algorithm that runs
// on rank 0 only (pvbatch --mpi, pvserver with several processes).  Private to the plugin.
//
// Rank 0 holds the surface; it samples the field in collective exchanges: it broadcasts points,
// every rank samples its own piece with the serial filter's sampler (make_velocity_field: the
// same trilinear or cell interpolation, masks and "outside" as on one process), and a
// sum-reduction brings rank 0 each point's sample (the mean where pieces share the point, as on
// the shared faces of image pieces) or "no sample" where no piece holds it: the semantics of
// ResampleWithDataset.  Where rank 0 knows the points beforehand (an iteration's face
// centroids, the vertices of a surface to parametrize) they go in one exchange (`probe()`); the
// library's algorithms that sample in batches (the concept's `sample()`: the measures, the
// parametrizations, the stages of a stream or path surface's time line; the default patch's
// lattice) get one exchange per batch; a point none of these announced (a boundary edge to grow)
// is exchanged alone when the algorithm asks for it.  The points that rank 0's own piece alone
// decides (no other piece's bounds hold them) stay out of the exchange: rank 0 samples them while
// the others answer, and a batch of only such points costs no exchange.  The other ranks answer
// until rank 0 says it has finished (`serve()`), so they take part in exactly as many exchanges
// as rank 0 needs; a rank that fails sends its reason instead of hanging the others.
//
// A stream or path surface's rounds also tell where their waiting particles stand
// (integration_ahead.h): the ranks other than 0 integrate them on while they alone decide their
// samples (no other piece's bounds hold the point) and send rank 0, with the round's samples,
// the states the particles reached, from which its tasks go on; rank 0 samples at once what its
// own piece alone decides (`sample_here()`).  So a path costs a round where it crosses from piece
// to piece, not one per Runge-Kutta stage, and each stretch of it is integrated once.
//
// A temporal input is sampled at a time: each rank interpolates its piece's steps around it
// linearly in time (Unsteady_flow_field_3), and rank 0 sends the time with every exchange.
//
// With one process (or no controller) nothing is exchanged: the field is the input's own.
#ifndef FAS_DISTRIBUTED_FIELD_H
#define FAS_DISTRIBUTED_FIELD_H

#include "fas_field_cache.h"
#include "fas_paraview_support.h"
#include "fas_temporal_input.h"

#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/integration_ahead.h>

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>
#include <vtkMultiProcessStream.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fas_paraview {

/// What rank 0 learns about the pieces of the input at the start of an update.
struct Distributed_input {
  int ranks = 1;               ///< processes of the controller
  int ranks_with_cells = 0;    ///< ranks whose piece has at least one cell
  bool changed = false;        ///< some rank's piece or array changed since the last update
  std::array<double, 6> bounds{ { 1, -1, 1, -1, 1, -1 } }; ///< of the pieces with cells
  std::string errors;          ///< "rank r: reason" for each rank that cannot sample its piece
  std::string note;            ///< what this rank left out of a composite input, or empty

  /// \throws std::invalid_argument when a piece cannot be sampled or no rank holds cells.
  void require_samples() const
  {
    if (!errors.empty())
      throw std::invalid_argument(ranks > 1 ? "cannot sample the input's pieces (" + errors + ")" : errors);
    if (ranks_with_cells == 0)
      throw std::invalid_argument("the input has no cells on any of the " + std::to_string(ranks) + " ranks");
  }
};

/// A rank's piece of the flow at a time: its steps (one for a steady input) interpolated linearly
/// in time.
using Piece_field = FAS::Time_slice_flow_field_3<FAS::Unsteady_flow_field_3<Velocity_field>>;

/// The time at which the ranks sample integrating ahead: NaN for each sample's own time.
constexpr double unsteady_time = std::numeric_limits<double>::quiet_NaN();

/// What a batch asks of the ranks besides its points: the particles to integrate ahead, the time
/// at which a steady field samples them (or `unsteady_time`) and where their states and samples
/// go.
struct Ahead_request {
  const FAS::internal::Integration_ahead* ahead = nullptr;
  double time = unsteady_time;
  FAS::internal::Integrated_ahead<std::optional<Vector>>* along = nullptr;
};

/// A `FlowField_3` over a data set whose pieces live on the ranks of the global controller.  On
/// one process it is the input's own field.  On several, only rank 0 samples it: at the points
/// given to `probe()` beforehand (looked up by the exact point), a batch (`sample()`) in one
/// exchange, and any other point in an exchange of its own.  Copies share their state.
class Distributed_velocity_field {
public:
  using Sample = std::optional<Vector>;
  using Integration_ahead = FAS::internal::Integration_ahead;
  using Integrated_ahead = FAS::internal::Integrated_ahead<Sample>;

  Distributed_velocity_field() : m_state(std::make_shared<State>()) {}

  /// Samples this rank's piece of the flow at `time` from `steps` (each a data set, or the 3D
  /// blocks of a composite data set: `flow_data_set()`; none when the piece has no cells) with
  /// the array `selection` (empty name: the active vectors); a step's field is built anew only
  /// when its data or the selection changed.  Not collective: RequestInformation calls it for
  /// the panel's default patch.  Never throws: a piece that cannot be sampled is reported by the
  /// next update.
  void sample_piece(const std::vector<Flow_step>& steps, double time, const Velocity_selection& selection)
  {
    State& s = *m_state;
    s.time = time;
    if (s.have_field && same_steps(steps, selection))
    {
      if (s.local)
        s.local->set_time(time);
      return;
    }
    std::vector<Sampled_step> sampled;
    s.local.reset();
    s.local_error.clear();
    try
    {
      for (const Flow_step& step : steps)
        sampled.push_back(sample_step(step, selection));
      s.local = piece_field(steps, sampled, time);
    }
    catch (const std::exception& e)
    {
      s.local_error = e.what();
    }
    s.flow = sampled.empty() ? Flow_data_set() : sampled.front().flow;
    s.sampled = std::move(sampled);
    s.selection = selection;
    s.have_field = s.local_error.empty();
    s.sampled_since_update = true;
  }

  /// The piece of a steady input (`input_information`'s data set) at time 0.
  void sample_piece(vtkInformation* input_information, const Velocity_selection& selection)
  {
    Flow_step step;
    step.data = input_information != nullptr ? vtkDataObject::GetData(input_information) : nullptr;
    using Pipeline = vtkStreamingDemandDrivenPipeline;
    if (input_information != nullptr && input_information->Has(Pipeline::WHOLE_EXTENT()))
    {
      step.whole_extent.emplace();
      input_information->Get(Pipeline::WHOLE_EXTENT(), step.whole_extent->data());
    }
    sample_piece({ step }, 0., selection);
  }

  /// This rank's field of its piece (`sample_piece()`): null when the piece has no cells or
  /// cannot be sampled.
  const Piece_field* piece_field() const { return m_state->local ? &*m_state->local : nullptr; }
  /// What `piece_field()` samples (its first step).
  const Flow_data_set& piece() const { return m_state->flow; }

  /// Called by every rank at the start of every update, collective when distributed: samples
  /// this rank's piece at `time` (`sample_piece()`) and gathers on rank 0 the state of every
  /// rank's piece.  The calling thread is the one that may exchange.  Never throws: a piece that
  /// cannot be sampled is reported in `errors`.
  Distributed_input update(const std::vector<Flow_step>& steps, double time, const Velocity_selection& selection)
  {
    State& s = *m_state;
    sample_piece(steps, time, selection);
    const bool changed = std::exchange(s.sampled_since_update, false);
    std::array<double, 6> local_bounds{ { 1, -1, 1, -1, 1, -1 } };
    if (s.flow.data_set != nullptr && s.flow.data_set->GetNumberOfCells() > 0)
      s.flow.data_set->GetBounds(local_bounds.data());
    Distributed_input pieces = start(global_controller(), local_bounds, changed);
    pieces.note = s.flow.note;
    return pieces;
  }

  /// Rank 0 (or the only process): samples the flow at time `t` from now on (within the times
  /// of the steps of the update).  The samples probed for another time are dropped.
  /// The time at which rank 0 samples.
  double time() const { return m_state->time; }

  void set_time(double t)
  {
    State& s = *m_state;
    if (s.time == t)
      return;
    s.time = t;
    s.samples.clear();
    if (s.local)
      s.local->set_time(t);
  }

  /// Whether the samples come from other ranks (more than one process).
  bool distributed() const { return m_state->controller != nullptr; }
  /// Whether this process runs the algorithm (rank 0, or the only process).
  bool is_root() const { return !distributed() || m_state->controller->GetLocalProcessId() == 0; }

  /// Rank 0: samples the distributed field at `points` in one exchange (collective: the other
  /// ranks are in `serve()`); afterwards `operator()` answers at these points without an
  /// exchange (until the next `probe()`).  Nothing on one process.
  void probe(const std::vector<Point>& points) const
  {
    State& s = *m_state;
    if (!distributed())
      return;
    std::vector<Sample> samples = exchange(points, std::vector<double>(points.size(), s.time));
    s.samples.clear();
    s.samples.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      s.samples[key(points[i])] = samples[i];
  }

private:
  // Rank 0: the samples at (points[i], times[i]).  Those its own piece alone decides are sampled
  // here; the others come from every rank in one exchange (collective: the other ranks are in
  // `serve()`), in which the ranks also integrate on the particles of `request`, while rank 0
  // samples its own and runs `meanwhile`.  No exchange when rank 0 alone decides every point and
  // there are no particles.  Throws std::runtime_error when a rank failed to sample its piece.
  std::vector<Sample> exchange(const std::vector<Point>& points, const std::vector<double>& times,
    const Ahead_request& request = {}, const std::function<void()>& meanwhile = {}) const
  {
    State& s = *m_state;
    if (s.working_meanwhile)
      throw std::logic_error("the field was asked for an exchange while the ranks integrate ahead");
    s.here.clear();
    s.asked.clear();
    for (std::size_t i = 0; i < points.size(); ++i)
      (decided_here(points[i]) ? s.here : s.asked).push_back(i);
    std::vector<Sample> samples(points.size());
    const auto sample_here_and_work = [&] {
      s.supplying_ranks = sample_decided_here(points, times, s.here, samples) ? 1 : 0;
      if (meanwhile)
        meanwhile();
    };
    s.failed_ranks = 0;
    const bool ahead = request.ahead != nullptr && !request.ahead->empty();
    if (s.asked.empty() && !ahead)
    {
      sample_here_and_work();
      return samples;
    }
    fill_round(points, times, request);
    send(PROBE, s.round);
    work_meanwhile(s.round, sample_here_and_work);
    take_replies(reply(s.round, request.along), samples);
    return samples;
  }

  // Rank 0: puts in its round (whose buffers are kept) the points `asked` at their times and the
  // particles of `request`.
  void fill_round(const std::vector<Point>& points, const std::vector<double>& times, const Ahead_request& request) const
  {
    State& s = *m_state;
    auto& round = s.round;
    round.coordinates.resize(4 * s.asked.size());
    for (std::size_t k = 0; k < s.asked.size(); ++k)
    {
      for (int d = 0; d < 3; ++d)
        round.coordinates[4 * k + std::size_t(d)] = points[s.asked[k]][d];
      round.coordinates[4 * k + 3] = times[s.asked[k]];
    }
    round.ahead.clear();
    if (request.ahead != nullptr && !request.ahead->empty())
      round.ahead = request.ahead->to_numbers();
    round.ahead_time = request.time;
  }

  // Rank 0: puts the samples of the points `asked` from the sum of the ranks' replies into
  // `samples` and counts the ranks that supplied one.  Throws std::runtime_error when a rank
  // failed to sample its piece.
  void take_replies(const std::vector<double>& total, std::vector<Sample>& samples) const
  {
    State& s = *m_state;
    ++s.exchanges;
    const std::size_t n = s.asked.size();
    for (std::size_t k = 0; k < n; ++k)
      samples[s.asked[k]] = combined(&total[4 * k]);
    s.failed_ranks = int(total[4 * n]);
    const bool supplied_here = s.supplying_ranks > 0;
    for (int r = 0; r < s.controller->GetNumberOfProcesses(); ++r)
      s.supplying_ranks += total[4 * n + 1 + std::size_t(r)] > 0 && !(r == 0 && supplied_here) ? 1 : 0;
    if (s.failed_ranks > 0)
      throw std::runtime_error(std::to_string(s.failed_ranks) + " rank(s) failed to sample their piece of the input");
  }

  // Rank 0: whether its own piece alone decides the sample at `p` (and can sample it).
  bool decided_here(const Point& p) const
  {
    return m_state->local_error.empty() && decides_here(Eigen::Vector3d(p.x(), p.y(), p.z()));
  }

  // Rank 0: the sample at `p` and time `t`, which its own piece alone decides, as an exchange
  // would give it.
  Sample decided_sample(const Point& p, double t) const
  {
    const State& s = *m_state;
    return as_exchanged(s.local ? s.local->unsteady_field()(p, t) : Sample());
  }

  // Rank 0: puts in `samples` those at the points `here` (which its own piece alone decides);
  // returns whether one of them is a sample.
  bool sample_decided_here(const std::vector<Point>& points, const std::vector<double>& times,
    const std::vector<std::size_t>& here, std::vector<Sample>& samples) const
  {
    bool supplied = false;
    for (std::size_t i : here)
      if ((samples[i] = decided_sample(points[i], times[i])))
        supplied = true;
    return supplied;
  }

  // Rank 0: the indices of the particles of `ahead` that stand where its piece does not alone
  // decide: another rank may take their first step.
  std::vector<std::size_t> particles_elsewhere(const Integration_ahead& ahead) const
  {
    std::vector<std::size_t> elsewhere;
    for (std::size_t i = 0; i < ahead.size(); ++i)
      if (!decides_here(ahead.position(i)))
        elsewhere.push_back(i);
    return elsewhere;
  }

public:

  /// Rank 0: tells the other ranks that no more probes come (ends their `serve()`).
  void finish() const
  {
    if (!distributed())
      return;
    send(FINISH, Round());
  }

  /// Ranks other than 0: answer rank 0's probes until it calls `finish()`.  Never throws.
  void serve() const
  {
    if (!distributed())
      return;
    Round round; // its buffers serve every exchange
    while (receive(round) == PROBE)
      reply(round, nullptr);
  }

  /// The velocity at `p`: the input's own field on one process; on rank 0 of several, the sample
  /// probed at exactly `p`, or else one exchanged for `p` alone.  \throws std::logic_error when
  /// such an exchange is asked for by another thread than the one that called `update()` (the
  /// algorithms' parallel loops sample probed points only).
  Sample operator()(const Point& p) const
  {
    State& s = *m_state;
    if (!distributed())
      return s.local ? (*s.local)(p) : Sample();
    const auto found = s.samples.find(key(p));
    if (found != s.samples.end())
      return found->second;
    if (std::this_thread::get_id() != s.owner)
      throw std::logic_error("the field was asked in a parallel loop for a point that was not probed from the ranks");
    return exchange({ p }, { s.time }).front();
  }

  /// The velocities at `points` (the batch operation of `FlowField_3`): on rank 0 of several,
  /// those not probed before in one exchange.
  std::vector<Sample> sample(const std::vector<Point>& points) const
  {
    return batch(points, std::vector<double>(points.size(), m_state->time), true);
  }

  /// The velocities at `points[i]` at `times[i]` (the batch operation of
  /// `UnsteadyFlowField_3`), in one exchange on rank 0 of several.
  std::vector<Sample> sample(const std::vector<Point>& points, const std::vector<double>& times) const
  {
    return batch(points, times, false);
  }

  /// The sample at `p` when this process alone decides it (the input's own field on one process;
  /// on rank 0 of several, a point no other rank's piece may hold), as an exchange would give it;
  /// nothing when other ranks have a say.
  std::optional<Sample> sample_here(const Point& p) const { return sample_here(p, m_state->time); }

  /// The same at time `t`.
  std::optional<Sample> sample_here(const Point& p, double t) const
  {
    const State& s = *m_state;
    if (!distributed())
      return s.local ? s.local->unsteady_field()(p, t) : Sample();
    if (!decided_here(p))
      return std::nullopt;
    return decided_sample(p, t);
  }

  /// `sample(points)`, integrating the particles `ahead` on where a rank alone decides their
  /// samples; where they got to is put in `along` (integration_ahead.h).
  std::vector<Sample> sample(const std::vector<Point>& points, const Integration_ahead& ahead,
    Integrated_ahead& along) const
  {
    const double t = m_state->time;
    return batch(points, std::vector<double>(points.size(), t), true, Ahead_request{ &ahead, t, &along });
  }

  /// Has the ranks other than 0 integrate the particles `ahead` on where they alone decide their
  /// samples (at the time `time`, or each sample's own: `unsteady_time`) while rank 0 runs `work()`,
  /// which must not exchange; then puts where they got to in `along` (integration_ahead.h).  The
  /// particles that stand where rank 0 alone decides stay with its tasks (no other rank could take
  /// their first step); when that is all of them, and on one process, only `work()`.
  void integrate_ahead_meanwhile(const Integration_ahead& ahead, Integrated_ahead& along,
    const std::function<void()>& work, double time) const
  {
    if (!distributed())
      return work();
    if (std::this_thread::get_id() != m_state->owner)
      throw std::logic_error("the field was asked to integrate ahead in a parallel loop");
    const std::vector<std::size_t> kept = particles_elsewhere(ahead);
    if (kept.empty())
      return work();
    const Integration_ahead sent = ahead.only(kept);
    Integrated_ahead got;
    exchange({}, {}, Ahead_request{ &sent, time, &got }, work);
    for (FAS::internal::State_ahead& reached : got.states)
    {
      reached.particle = kept.at(reached.particle);
      along.states.push_back(reached);
    }
    along.samples.insert(along.samples.end(), got.samples.begin(), got.samples.end());
  }

  /// The same at the time at which rank 0 samples.
  void integrate_ahead_meanwhile(const Integration_ahead& ahead, Integrated_ahead& along,
    const std::function<void()>& work) const
  {
    integrate_ahead_meanwhile(ahead, along, work, m_state->time);
  }

  /// `sample(points, times)`, integrating the particles `ahead` on in the same way.
  std::vector<Sample> sample(const std::vector<Point>& points, const std::vector<double>& times,
    const Integration_ahead& ahead, Integrated_ahead& along) const
  {
    return batch(points, times, false, Ahead_request{ &ahead, unsteady_time, &along });
  }

  /// The velocity at `p` at time `t` (within the times of the steps of the update), for an
  /// algorithm that samples the flow at times of its own (a path surface): the input's own field
  /// on one process; on rank 0 of several, a sample exchanged for `p` and `t` alone (the
  /// thread that called `update()` only).
  Sample at(const Point& p, double t) const
  {
    State& s = *m_state;
    if (!distributed())
      return s.local ? s.local->unsteady_field()(p, t) : Sample();
    if (std::this_thread::get_id() != s.owner)
      throw std::logic_error("the field was asked for a time in a parallel loop");
    return exchange({ p }, { t }).front();
  }

  /// Ranks whose piece supplied at least one sample in the last exchange.
  int number_of_supplying_ranks() const { return m_state->supplying_ranks; }
  /// Exchanges since the start of the update (batches and single points).
  std::size_t number_of_exchanges() const { return m_state->exchanges; }
  /// The velocity fields this rank built (not found in the `Field_cache`) since the last call.
  std::size_t take_fields_built() { return std::exchange(m_state->fields_built, 0); }

private:
  // The samples at (points[i], times[i]); with `probed`, those probed before at the current time
  // are taken from the probes.  On rank 0 of several the others come in one exchange.
  std::vector<Sample> batch(const std::vector<Point>& points, const std::vector<double>& times, bool probed,
    const Ahead_request& request = {}) const
  {
    State& s = *m_state;
    std::vector<Sample> samples(points.size());
    if (!distributed())
    {
      if (s.local)
        for (std::size_t i = 0; i < points.size(); ++i)
          samples[i] = s.local->unsteady_field()(points[i], times[i]);
      return samples;
    }
    if (points.empty())
      return samples;
    if (!probed || s.samples.empty())
    {
      if (std::this_thread::get_id() != s.owner)
        throw std::logic_error("the field was asked for a batch in a parallel loop");
      return exchange(points, times, request);
    }
    std::vector<std::size_t> asked;
    std::vector<Point> asked_points;
    std::vector<double> asked_times;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      if (probed)
        if (const auto found = s.samples.find(key(points[i])); found != s.samples.end())
        {
          samples[i] = found->second;
          continue;
        }
      asked.push_back(i);
      asked_points.push_back(points[i]);
      asked_times.push_back(times[i]);
    }
    if (asked.empty())
      return samples;
    if (std::this_thread::get_id() != s.owner)
      throw std::logic_error("the field was asked for a batch in a parallel loop");
    const std::vector<Sample> answers = exchange(asked_points, asked_times, request);
    for (std::size_t k = 0; k < asked.size(); ++k)
      samples[asked[k]] = answers[k];
    return samples;
  }

  // The global controller when there are several processes; null for one.
  static vtkMultiProcessController* global_controller()
  {
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    return controller != nullptr && controller->GetNumberOfProcesses() > 1 ? controller : nullptr;
  }

  // Gathers on rank 0 the state of every rank's piece (collective; `controller` null: one process).
  Distributed_input start(vtkMultiProcessController* controller, const std::array<double, 6>& local_bounds,
    bool changed)
  {
    State& s = *m_state;
    s.controller = controller;
    s.owner = std::this_thread::get_id();
    s.samples.clear();
    s.supplying_ranks = 0;
    s.exchanges = 0;
    const std::string& error = s.local_error;
    Distributed_input input;
    if (s.controller == nullptr)
    {
      input.ranks_with_cells = s.local ? 1 : 0;
      input.changed = changed;
      input.bounds = local_bounds;
      input.errors = error;
      return input;
    }
    vtkMultiProcessStream mine;
    mine << int(s.local ? 1 : 0) << int(changed ? 1 : 0) << error;
    for (double b : local_bounds)
      mine << b;
    std::vector<vtkMultiProcessStream> all;
    s.controller->Gather(mine, all, 0);
    share_piece_bounds(bounds_of_steps());
    input.ranks = s.controller->GetNumberOfProcesses();
    for (std::size_t r = 0; r < all.size(); ++r)
    {
      int has_cells = 0, piece_changed = 0;
      std::string piece_error;
      std::array<double, 6> b;
      all[r] >> has_cells >> piece_changed >> piece_error;
      for (double& x : b)
        all[r] >> x;
      input.ranks_with_cells += has_cells;
      input.changed = input.changed || piece_changed != 0;
      if (!piece_error.empty())
        input.errors += (input.errors.empty() ? "" : "; ") + ("rank " + std::to_string(r) + ": " + piece_error);
      if (has_cells)
        grow_bounds(input.bounds, b);
    }
    return input;
  }


  // The bounds of this rank's piece over all the steps it samples (they may be cut differently
  // at each step); empty (1, -1, ...) without cells.
  std::array<double, 6> bounds_of_steps() const
  {
    std::array<double, 6> bounds{ { 1, -1, 1, -1, 1, -1 } };
    for (const Sampled_step& step : m_state->sampled)
    {
      vtkDataSet* data = step.flow.data_set;
      if (data == nullptr || data->GetNumberOfCells() == 0)
        continue;
      std::array<double, 6> b;
      data->GetBounds(b.data());
      grow_bounds(bounds, b);
    }
    return bounds;
  }

  // Grows `bounds` (empty: 1, -1, ...) to hold the bounds `b`.
  static void grow_bounds(std::array<double, 6>& bounds, const std::array<double, 6>& b)
  {
    const bool empty = bounds[0] > bounds[1];
    for (int d = 0; d < 3; ++d)
    {
      bounds[2 * d] = empty ? b[2 * d] : std::min(bounds[2 * d], b[2 * d]);
      bounds[2 * d + 1] = empty ? b[2 * d + 1] : std::max(bounds[2 * d + 1], b[2 * d + 1]);
    }
  }

  // Every rank learns the bounds of every other rank's piece with cells (collective), for
  // `decides_here()`, widened by 1e-6 of the largest extent of them all (beyond the locators'
  // tolerances).
  void share_piece_bounds(const std::array<double, 6>& local_bounds)
  {
    State& s = *m_state;
    const int ranks = s.controller->GetNumberOfProcesses();
    std::vector<double> all(6 * std::size_t(ranks));
    s.controller->AllGather(local_bounds.data(), all.data(), 6);
    std::vector<std::array<double, 6>> pieces;
    pieces.resize(std::size_t(ranks));
    std::array<double, 6> whole{ { 1, -1, 1, -1, 1, -1 } };
    for (std::size_t r = 0; r < pieces.size(); ++r)
    {
      std::copy_n(all.begin() + std::ptrdiff_t(6 * r), 6, pieces[r].begin());
      if (pieces[r][0] <= pieces[r][1])
        grow_bounds(whole, pieces[r]);
    }
    double margin = 0;
    for (int d = 0; d < 3 && whole[0] <= whole[1]; ++d)
      margin = std::max(margin, 1e-6 * (whole[2 * d + 1] - whole[2 * d]));
    s.other_pieces.clear();
    for (std::size_t r = 0; r < pieces.size(); ++r)
    {
      if (int(r) == s.controller->GetLocalProcessId() || pieces[r][0] > pieces[r][1])
        continue;
      for (int d = 0; d < 3; ++d)
      {
        pieces[r][2 * d] -= margin;
        pieces[r][2 * d + 1] += margin;
      }
      s.other_pieces.push_back(pieces[r]);
    }
  }

  enum Command
  {
    FINISH = 0,
    PROBE = 1
  };

  // What rank 0 asks of every rank in an exchange.
  struct Round {
    std::vector<double> coordinates;   // (x, y, z, t) per point to sample
    std::vector<double> ahead;         // the particles to integrate ahead (Integration_ahead's numbers)
    double ahead_time = unsteady_time; // at which a steady field samples them
  };

  // The first broadcast of an exchange: the command, the number of points, the number of values
  // of the particles to integrate ahead, the time of their samples, and, when they fit, the points
  // followed by the particles, so that a small exchange costs one broadcast; else they follow in a
  // second one.  Its size keeps it below MPI's usual eager limit (4 KiB), which sends it at once.
  static constexpr std::size_t header_size = 4;
  using Message = std::array<double, 480>;

  // Rank 0: broadcasts `command` and `round`.
  void send(Command command, const Round& round) const
  {
    Message first{};
    first[0] = command;
    first[1] = double(round.coordinates.size() / 4);
    first[2] = double(round.ahead.size());
    first[3] = round.ahead_time;
    std::vector<double>& values = m_state->values;
    values.assign(round.coordinates.begin(), round.coordinates.end());
    values.insert(values.end(), round.ahead.begin(), round.ahead.end());
    const bool inline_values = values.size() <= first.size() - header_size;
    if (inline_values)
      std::copy(values.begin(), values.end(), first.begin() + header_size);
    m_state->controller->Broadcast(first.data(), vtkIdType(first.size()), 0);
    if (!inline_values)
      m_state->controller->Broadcast(values.data(), vtkIdType(values.size()), 0);
  }

  // Other ranks: receives what `send()` broadcasts into `round`; returns the command.
  Command receive(Round& round) const
  {
    Message first{};
    m_state->controller->Broadcast(first.data(), vtkIdType(first.size()), 0);
    if (first[0] != PROBE)
      return FINISH;
    const std::size_t n = 4 * std::size_t(first[1]);
    std::vector<double>& values = m_state->values;
    values.resize(n + std::size_t(first[2]));
    if (values.size() <= first.size() - header_size)
      std::copy_n(first.begin() + header_size, values.size(), values.begin());
    else
      m_state->controller->Broadcast(values.data(), vtkIdType(values.size()), 0);
    round.coordinates.assign(values.begin(), values.begin() + std::ptrdiff_t(n));
    round.ahead.assign(values.begin() + std::ptrdiff_t(n), values.end());
    round.ahead_time = first[3];
    return PROBE;
  }

  // Every rank's answer to `round` (collective): on rank 0 the sum of the ranks' replies
  // (`sample_local()`), and there where the particles integrated ahead got to in `along`
  // (`integrate_here()`).  The sum lives until the next exchange.
  const std::vector<double>& reply(const Round& round, Integrated_ahead* along) const
  {
    State& s = *m_state;
    const std::size_t ranks = std::size_t(s.controller->GetNumberOfProcesses());
    const int rank = s.controller->GetLocalProcessId();
    sample_local(round.coordinates, int(ranks), rank, s.mine);
    const std::vector<double> ahead = round.ahead.empty() ? std::vector<double>() : integrate_here(round);
    s.mine[s.mine.size() - ranks + std::size_t(rank)] = double(ahead.size());
    s.total.resize(s.mine.size());
    s.controller->Reduce(s.mine.data(), s.total.data(), vtkIdType(s.mine.size()), vtkCommunicator::SUM_OP, 0);
    if (round.ahead.empty())
      return s.total;
    std::vector<vtkIdType> lengths(ranks), offsets(ranks);
    for (std::size_t r = 0; r < ranks; ++r)
    {
      lengths[r] = vtkIdType(s.total[s.total.size() - ranks + r]);
      offsets[r] = r == 0 ? 0 : offsets[r - 1] + lengths[r - 1];
    }
    std::vector<double> all(std::size_t(offsets.back() + lengths.back()));
    s.controller->GatherV(ahead.data(), all.data(), vtkIdType(ahead.size()), lengths.data(), offsets.data(), 0);
    if (along != nullptr)
      for (std::size_t r = 0; r < ranks; ++r)
        read_integrated(all.data() + offsets[r], std::size_t(lengths[r]), *along);
    return s.total;
  }

  // Rank 0: runs `work()` between sending `round` and replying to it, while the other ranks
  // sample its points and integrate its particles ahead; replies whatever way `work()` ends, so
  // that every rank takes part in the same collectives.
  void work_meanwhile(const Round& round, const std::function<void()>& work) const
  {
    State& s = *m_state;
    s.working_meanwhile = true;
    try
    {
      work();
    }
    catch (...)
    {
      s.working_meanwhile = false;
      reply(round, nullptr);
      throw;
    }
    s.working_meanwhile = false;
  }

  // The values of a state (the particle's index and its integrator's state, as many as a
  // particle's record) and of a sample in what `integrate_here()` sends.
  static constexpr std::size_t state_values = Integration_ahead::record_size;
  static constexpr std::size_t sample_values = 8;

  // Adds to `along` what one rank's `integrate_here()` sent (`n` values at `v`).
  static void read_integrated(const double* v, std::size_t n, Integrated_ahead& along)
  {
    if (n == 0)
      return;
    const std::size_t states = std::size_t(v[0]), samples = std::size_t(v[1]);
    if (n != 2 + states * state_values + samples * sample_values)
      throw std::runtime_error("a rank sent " + std::to_string(n) + " values for " + std::to_string(states) +
                               " states and " + std::to_string(samples) + " samples integrated ahead");
    const double* r = v + 2;
    for (std::size_t i = 0; i < states; ++i, r += state_values)
    {
      FAS::internal::State_ahead reached;
      reached.particle = std::size_t(r[0]);
      std::copy_n(r + 1, reached.state.size(), reached.state.begin());
      along.states.push_back(reached);
    }
    for (std::size_t i = 0; i < samples; ++i, r += sample_values)
    {
      const Sample sample = r[7] > 0 ? Sample(Vector(r[4], r[5], r[6])) : Sample();
      along.samples.push_back({ Eigen::Vector3d(r[0], r[1], r[2]), r[3], as_exchanged(sample) });
    }
  }

  // Rank 0's sample from the sum of the ranks' replies at a point (`sample_local()`): the mean of
  // the pieces that hold it, or none.
  static Sample combined(const double* total)
  {
    if (!(total[3] > 0))
      return Sample();
    return Vector(total[0] / total[3], total[1] / total[3], total[2] / total[3]);
  }

  // A sample of this rank's piece that no other piece may hold as rank 0 gets it from an
  // exchange: the sum of it and the other ranks' zeros, divided by the one piece that has it.
  static Sample as_exchanged(const Sample& v)
  {
    if (!v)
      return Sample();
    const double total[4] = { 0. + v->x(), 0. + v->y(), 0. + v->z(), 1. };
    return combined(total);
  }

  // A rank other than 0: where the particles of `round` got to, integrated on while this rank
  // alone decides their samples: the number of states and of samples, then per state the
  // particle's index and its integrator's state, per sample (x, y, z, t, vx, vy, vz, 1 or 0 for
  // no sample).  Rank 0 answers those of its own piece when its tasks ask (`sample_here()`).  A
  // rank that fails to integrate sends nothing.
  std::vector<double> integrate_here(const Round& round) const
  {
    const State& s = *m_state;
    std::vector<double> sent;
    if (!s.local || !s.local_error.empty() || is_root())
      return sent;
    try
    {
      const auto& unsteady = s.local->unsteady_field();
      const double time = round.ahead_time;
      Integrated_ahead along;
      FAS::internal::integrate_ahead<Sample>(
        Integration_ahead::from_numbers(round.ahead),
        [&](const Eigen::Vector3d& x, double t) {
          return unsteady(Point(x[0], x[1], x[2]), std::isnan(time) ? t : time);
        },
        [&](const Eigen::Vector3d& x) { return decides_here(x); }, along);
      if (along.states.empty() && along.samples.empty())
        return sent;
      sent.reserve(2 + along.states.size() * state_values + along.samples.size() * sample_values);
      sent.push_back(double(along.states.size()));
      sent.push_back(double(along.samples.size()));
      for (const FAS::internal::State_ahead& reached : along.states)
      {
        sent.push_back(double(reached.particle));
        sent.insert(sent.end(), reached.state.begin(), reached.state.end());
      }
      for (const FAS::internal::Sample_ahead<Sample>& a : along.samples)
      {
        const Sample& v = a.answer;
        const double values[sample_values] = { a.x[0], a.x[1], a.x[2], a.t, v ? v->x() : 0., v ? v->y() : 0.,
          v ? v->z() : 0., v ? 1. : 0. };
        sent.insert(sent.end(), values, values + sample_values);
      }
    }
    catch (...)
    {
      sent.clear();
    }
    return sent;
  }

  // Whether this rank's piece alone decides the exchange's sample at `x`: no other rank's piece
  // with cells has bounds (widened beyond the locators' tolerances) that hold it.
  bool decides_here(const Eigen::Vector3d& x) const
  {
    for (const std::array<double, 6>& b : m_state->other_pieces)
      if (x[0] >= b[0] && x[0] <= b[1] && x[1] >= b[2] && x[1] <= b[3] && x[2] >= b[4] && x[2] <= b[5])
        return false;
    return true;
  }

  // The exact bits of the coordinates: the points are looked up as the library computes them.
  using Key = std::array<std::uint64_t, 3>;
  struct Key_hash {
    std::size_t operator()(const Key& k) const
    {
      return std::size_t(k[0] * 0x9E3779B97F4A7C15ull ^ (k[1] + 0x632BE59BD9B4E019ull) * 31 ^ k[2]);
    }
  };
  static Key key(const Point& p)
  {
    Key k;
    for (int d = 0; d < 3; ++d)
    {
      const double x = p[d];
      std::memcpy(&k[std::size_t(d)], &x, sizeof x);
    }
    return k;
  }

  // This rank's reply to the points (x, y, z, t), in `reply`: per point (vx, vy, vz, 1) where its
  // piece has a sample there and then, zeros elsewhere; then 1 if sampling failed here; then per
  // rank the number of samples it supplied; then per rank the number of values it integrated
  // ahead (0: `reply()` sets this rank's).
  void sample_local(const std::vector<double>& coordinates, int ranks, int rank, std::vector<double>& reply) const
  {
    const State& s = *m_state;
    const std::size_t n = coordinates.size() / 4;
    reply.assign(4 * n + 1 + 2 * std::size_t(ranks), 0.);
    if (!s.local_error.empty())
    {
      reply[4 * n] = 1;
      return;
    }
    if (!s.local)
      return;
    try
    {
      const auto& unsteady = s.local->unsteady_field();
      const double* x = coordinates.data();
      double supplied = 0;
      for (std::size_t i = 0; i < n; ++i)
      {
        const Sample v = unsteady(Point(x[4 * i], x[4 * i + 1], x[4 * i + 2]), x[4 * i + 3]);
        if (!v)
          continue;
        reply[4 * i] = v->x();
        reply[4 * i + 1] = v->y();
        reply[4 * i + 2] = v->z();
        reply[4 * i + 3] = 1;
        ++supplied;
      }
      reply[4 * n + 1 + std::size_t(rank)] = supplied;
    }
    catch (...)
    {
      std::fill(reply.begin(), reply.end(), 0.);
      reply[4 * n] = 1;
    }
  }

  // A step of this rank's piece and its field, with what it was built from.
  struct Sampled_step {
    vtkSmartPointer<vtkDataObject> data;
    vtkMTimeType data_time = 0;
    Flow_data_set flow;
    std::shared_ptr<const Velocity_field> field; // null: no cells here
  };

  bool same_steps(const std::vector<Flow_step>& steps, const Velocity_selection& selection) const
  {
    const State& s = *m_state;
    if (selection != s.selection || steps.size() != s.sampled.size())
      return false;
    for (std::size_t i = 0; i < steps.size(); ++i)
      if (steps[i].data != s.sampled[i].data ||
          (steps[i].data != nullptr && steps[i].data->GetMTime() != s.sampled[i].data_time))
        return false;
    return true;
  }

  // `step`'s field: the one built before when its data and the selection are the same.
  Sampled_step sample_step(const Flow_step& step, const Velocity_selection& selection) const
  {
    const State& s = *m_state;
    const vtkMTimeType data_time = step.data != nullptr ? step.data->GetMTime() : 0;
    if (selection == s.selection)
      for (const Sampled_step& old : s.sampled)
        if (old.data == step.data && old.data_time == data_time)
          return old;
    Sampled_step sampled{ step.data, data_time, flow_data_set(step.data), nullptr };
    const bool several = global_controller() != nullptr;
    if (sampled.flow.data_set == nullptr && vtkCompositeDataSet::SafeDownCast(step.data) != nullptr)
    {
      if (!several)
        throw std::invalid_argument("the Input (" + std::string(step.data->GetClassName()) +
                                    ") has no block with 3D cells: there is no volume to sample the flow in" +
                                    (sampled.flow.note.empty() ? std::string() : " (" + sampled.flow.note + ")"));
    }
    else if (!several || (sampled.flow.data_set != nullptr && sampled.flow.data_set->GetNumberOfCells() > 0))
    {
      bool built = false;
      sampled.field = Field_cache::field(sampled.flow.data_set, selection,
                                         step.whole_extent ? step.whole_extent->data() : nullptr, built);
      m_state->fields_built += built ? 1 : 0;
    }
    return sampled;
  }

  // The piece's steps interpolated in time, at `time`; none when the piece has no cells.
  static std::optional<Piece_field> piece_field(const std::vector<Flow_step>& steps,
                                                const std::vector<Sampled_step>& sampled, double time)
  {
    std::vector<double> times;
    std::vector<Velocity_field> fields;
    for (std::size_t i = 0; i < sampled.size(); ++i)
      if (sampled[i].field)
      {
        times.push_back(steps[i].time);
        fields.push_back(*sampled[i].field);
      }
    if (fields.empty())
      return std::nullopt;
    if (fields.size() != sampled.size())
      throw std::invalid_argument("the piece has cells at some time steps and none at others");
    return Piece_field(FAS::Unsteady_flow_field_3<Velocity_field>(std::move(times), std::move(fields)), time);
  }

  struct State {
    vtkMultiProcessController* controller = nullptr; // null: one process
    std::optional<Piece_field> local;                // this rank's piece; none: no cells
    std::string local_error;
    std::unordered_map<Key, Sample, Key_hash> samples;
    int failed_ranks = 0, supplying_ranks = 0;
    std::size_t exchanges = 0;
    std::vector<std::array<double, 6>> other_pieces; // the widened bounds of the other ranks' pieces with cells
    std::vector<double> values;                      // the points and particles of a round, as sent
    std::vector<double> mine, total;                 // this rank's reply and the sum of all (`reply()`)
    Round round;                                     // rank 0's, whose buffers serve every exchange
    std::vector<std::size_t> here, asked;            // the points of an exchange sampled here and asked
    std::thread::id owner;                           // the thread that may exchange
    bool working_meanwhile = false;                  // rank 0 works while the ranks integrate
    double time = 0;                                 // at which rank 0 samples
    std::vector<Sampled_step> sampled;               // the steps `local` interpolates
    Velocity_selection selection;
    Flow_data_set flow;                              // of the first step
    bool have_field = false;
    bool sampled_since_update = false;               // `local` sampled anew since the last update
    std::size_t fields_built = 0;                    // by `sample_step()` since `take_fields_built()`
  };
  std::shared_ptr<State> m_state;
};

} // namespace fas_paraview

#endif // FAS_DISTRIBUTED_FIELD_H
