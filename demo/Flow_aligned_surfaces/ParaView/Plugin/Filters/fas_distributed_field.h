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
//
// This file holds the field the algorithms see and the order of an exchange; this rank's piece
// (its fields, its answers, its integration ahead) is fas_piece_field.h, the collective
// operations and what they carry are fas_rank_exchange.h.
#ifndef FAS_DISTRIBUTED_FIELD_H
#define FAS_DISTRIBUTED_FIELD_H

#include "fas_paraview_support.h"
#include "fas_piece_field.h"
#include "fas_rank_exchange.h"
#include "fas_temporal_input.h"

#include <CGAL/Flow_aligned_surfaces/internal/integration_ahead.h>

#include <vtkMultiProcessController.h>
#include <vtkMultiProcessStream.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
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
  /// when its data or the selection changed (`Rank_piece::sample()`).  Not collective:
  /// RequestInformation calls it for the panel's default patch.  Never throws: a piece that
  /// cannot be sampled is reported by the next update.
  void sample_piece(const std::vector<Flow_step>& steps, double time, const Velocity_selection& selection)
  {
    State& s = *m_state;
    s.time = time;
    s.piece.sample(steps, time, selection, global_controller() != nullptr);
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
  const Piece_field* piece_field() const { return m_state->piece.field(); }
  /// What `piece_field()` samples (its first step).
  const Flow_data_set& piece() const { return m_state->piece.flow(); }

  /// Called by every rank at the start of every update, collective when distributed: samples
  /// this rank's piece at `time` (`sample_piece()`) and gathers on rank 0 the state of every
  /// rank's piece.  The calling thread is the one that may exchange.  Never throws: a piece that
  /// cannot be sampled is reported in `errors`.
  Distributed_input update(const std::vector<Flow_step>& steps, double time, const Velocity_selection& selection)
  {
    State& s = *m_state;
    sample_piece(steps, time, selection);
    const bool changed = s.piece.take_sampled_anew();
    const Flow_data_set& flow = s.piece.flow();
    std::array<double, 6> local_bounds{ { 1, -1, 1, -1, 1, -1 } };
    if (flow.data_set != nullptr && flow.data_set->GetNumberOfCells() > 0)
      flow.data_set->GetBounds(local_bounds.data());
    Distributed_input pieces = start(global_controller(), local_bounds, changed);
    pieces.note = flow.note;
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
    s.piece.set_time(t);
  }

  /// Whether the samples come from other ranks (more than one process).
  bool distributed() const { return m_state->wire.controller() != nullptr; }
  /// Whether this process runs the algorithm (rank 0, or the only process).
  bool is_root() const { return !distributed() || m_state->wire.controller()->GetLocalProcessId() == 0; }

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
    Exchange_buffers& b = Exchange_buffers::of_this_process();
    b.here.clear();
    b.asked.clear();
    for (std::size_t i = 0; i < points.size(); ++i)
      (decided_here(points[i]) ? b.here : b.asked).push_back(i);
    std::vector<Sample> samples(points.size());
    const auto sample_here_and_work = [&] {
      s.supplying_ranks = sample_decided_here(points, times, b.here, samples) ? 1 : 0;
      if (meanwhile)
        meanwhile();
    };
    s.failed_ranks = 0;
    const bool ahead = request.ahead != nullptr && !request.ahead->empty();
    if (b.asked.empty() && !ahead)
    {
      sample_here_and_work();
      return samples;
    }
    fill_round(points, times, request);
    s.wire.send(Rank_exchange::PROBE, b.round);
    work_meanwhile(b.round, sample_here_and_work);
    take_replies(s.wire.reply(b.round, s.piece, request.along), samples);
    return samples;
  }

  // Rank 0: puts in its round (whose buffers are kept) the points `asked` at their times and the
  // particles of `request`.
  void fill_round(const std::vector<Point>& points, const std::vector<double>& times, const Ahead_request& request) const
  {
    Exchange_buffers& b = Exchange_buffers::of_this_process();
    Round& round = b.round;
    round.coordinates.resize(4 * b.asked.size());
    for (std::size_t k = 0; k < b.asked.size(); ++k)
    {
      for (int d = 0; d < 3; ++d)
        round.coordinates[4 * k + std::size_t(d)] = points[b.asked[k]][d];
      round.coordinates[4 * k + 3] = times[b.asked[k]];
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
    const std::vector<std::size_t>& asked = Exchange_buffers::of_this_process().asked;
    const std::size_t n = asked.size();
    for (std::size_t k = 0; k < n; ++k)
      samples[asked[k]] = Rank_exchange::combined(&total[4 * k]);
    s.failed_ranks = int(total[4 * n]);
    const bool supplied_here = s.supplying_ranks > 0;
    for (int r = 0; r < s.wire.controller()->GetNumberOfProcesses(); ++r)
      s.supplying_ranks += total[4 * n + 1 + std::size_t(r)] > 0 && !(r == 0 && supplied_here) ? 1 : 0;
    if (s.failed_ranks > 0)
      throw std::runtime_error(std::to_string(s.failed_ranks) + " rank(s) failed to sample their piece of the input");
  }

  // Rank 0: whether its own piece alone decides the sample at `p` (and can sample it).
  bool decided_here(const Point& p) const
  {
    const Rank_piece& piece = m_state->piece;
    return piece.error().empty() && piece.decides(Eigen::Vector3d(p.x(), p.y(), p.z()));
  }

  // Rank 0: the sample at `p` and time `t`, which its own piece alone decides, as an exchange
  // would give it.
  Sample decided_sample(const Point& p, double t) const
  {
    const Piece_field* field = m_state->piece.field();
    return Rank_exchange::as_exchanged(field != nullptr ? field->unsteady_field()(p, t) : Sample());
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
      if (!m_state->piece.decides(ahead.position(i)))
        elsewhere.push_back(i);
    return elsewhere;
  }

public:

  /// Rank 0: tells the other ranks that no more probes come (ends their `serve()`).
  void finish() const
  {
    if (!distributed())
      return;
    m_state->wire.send(Rank_exchange::FINISH, Round());
  }

  /// Ranks other than 0: answer rank 0's probes until it calls `finish()`.  Never throws.
  void serve() const
  {
    if (!distributed())
      return;
    State& s = *m_state;
    Round& round = Exchange_buffers::of_this_process().round;
    while (s.wire.receive(round) == Rank_exchange::PROBE)
      s.wire.reply(round, s.piece, nullptr);
  }

  /// The velocity at `p`: the input's own field on one process; on rank 0 of several, the sample
  /// probed at exactly `p`, or else one exchanged for `p` alone.  \throws std::logic_error when
  /// such an exchange is asked for by another thread than the one that called `update()` (the
  /// algorithms' parallel loops sample probed points only).
  Sample operator()(const Point& p) const
  {
    State& s = *m_state;
    if (!distributed())
      return s.piece.field() != nullptr ? (*s.piece.field())(p) : Sample();
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
      return s.piece.field() != nullptr ? s.piece.field()->unsteady_field()(p, t) : Sample();
    if (!decided_here(p))
      return std::nullopt;
    return decided_sample(p, t);
  }

  /// Whether this process alone decides the samples at `p` (every point on one process; on rank
  /// 0 of several, a point no other rank's piece may hold): the library leaves the particles that
  /// stand there out of those it has the ranks integrate ahead meanwhile.
  bool decides_here(const Point& p) const { return !distributed() || decided_here(p); }

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
    // The library leaves out the particles rank 0 alone decides (`decides_here()`): all are kept
    // unless rank 0's piece failed.
    std::optional<Integration_ahead> subset;
    if (kept.size() != ahead.size())
      subset = ahead.only(kept);
    Integrated_ahead got;
    exchange({}, {}, Ahead_request{ subset ? &*subset : &ahead, time, &got }, work);
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

  /// Rank 0, while it works during `integrate_ahead_meanwhile()`: whether a rank still integrates
  /// the particles (the library gives rank 0 more work meanwhile while they do).
  bool others_still_integrating() const
  {
    const State& s = *m_state;
    return s.working_meanwhile && s.wire.others_integrating();
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
      return s.piece.field() != nullptr ? s.piece.field()->unsteady_field()(p, t) : Sample();
    if (std::this_thread::get_id() != s.owner)
      throw std::logic_error("the field was asked for a time in a parallel loop");
    return exchange({ p }, { t }).front();
  }

  /// Ranks whose piece supplied at least one sample in the last exchange.
  int number_of_supplying_ranks() const { return m_state->supplying_ranks; }
  /// Exchanges since the start of the update (batches and single points).
  std::size_t number_of_exchanges() const { return m_state->exchanges; }
  /// The velocity fields this rank built (not found in the `Field_cache`) since the last call.
  std::size_t take_fields_built() { return m_state->piece.take_fields_built(); }

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
      if (const Piece_field* field = s.piece.field())
        for (std::size_t i = 0; i < points.size(); ++i)
          samples[i] = field->unsteady_field()(points[i], times[i]);
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
    s.wire.set_controller(controller);
    s.owner = std::this_thread::get_id();
    s.samples.clear();
    s.supplying_ranks = 0;
    s.exchanges = 0;
    const std::string& error = s.piece.error();
    const bool has_cells = s.piece.field() != nullptr;
    Distributed_input input;
    if (controller == nullptr)
    {
      input.ranks_with_cells = has_cells ? 1 : 0;
      input.changed = changed;
      input.bounds = local_bounds;
      input.errors = error;
      return input;
    }
    vtkMultiProcessStream mine;
    mine << int(has_cells ? 1 : 0) << int(changed ? 1 : 0) << error;
    for (double b : local_bounds)
      mine << b;
    std::vector<vtkMultiProcessStream> all;
    controller->Gather(mine, all, 0);
    s.piece.learn_other_pieces(controller);
    input.ranks = controller->GetNumberOfProcesses();
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
      s.wire.reply(round, s.piece, nullptr);
      throw;
    }
    s.working_meanwhile = false;
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

  struct State {
    Rank_piece piece;                                // this rank's piece of the flow
    Rank_exchange wire;                              // its controller is null on one process
    std::unordered_map<Key, Sample, Key_hash> samples;
    int failed_ranks = 0, supplying_ranks = 0;
    std::size_t exchanges = 0;
    std::thread::id owner;                           // the thread that may exchange
    bool working_meanwhile = false;                  // rank 0 works while the ranks integrate
    double time = 0;                                 // at which rank 0 samples
  };
  std::shared_ptr<State> m_state;
};

} // namespace fas_paraview

#endif // FAS_DISTRIBUTED_FIELD_H
