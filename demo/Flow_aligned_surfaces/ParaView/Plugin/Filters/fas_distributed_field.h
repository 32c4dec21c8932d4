// The velocity of an input distributed over MPI ranks, as a FlowField_3 for an algorithm that runs
// on rank 0 only (pvbatch --mpi, pvserver with several processes).  Private to the plugin.
//
// Rank 0 holds the surface; before the library samples the field (an iteration, a measure), rank
// 0 probes the points it will ask for in one collective exchange: it broadcasts the points, every
// rank samples its own piece with the serial filter's sampler (make_velocity_field: the same
// trilinear or cell interpolation, masks and "outside" as on one process), and a sum-reduction
// brings rank 0 each point's sample (the mean where pieces share the point, as on the shared
// faces of image pieces) or "no sample" where no piece holds it: the semantics of
// ResampleWithDataset.  The other ranks answer probes until rank 0 says it has finished, so they
// take part in exactly as many exchanges as rank 0 needs; a rank that fails sends its reason
// instead of hanging the others.
//
// With one process (or no controller) nothing is exchanged: the field is the input's own.
#ifndef FAS_DISTRIBUTED_FIELD_H
#define FAS_DISTRIBUTED_FIELD_H

#include "fas_paraview_support.h"

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>
#include <vtkMultiProcessStream.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace fas_paraview {

/// What rank 0 learns about the pieces of the input at the start of an update.
struct Distributed_input {
  int ranks = 1;               ///< processes of the controller
  int ranks_with_cells = 0;    ///< ranks whose piece has at least one cell
  bool changed = false;        ///< some rank's piece or array changed since the last update
  std::array<double, 6> bounds{ { 1, -1, 1, -1, 1, -1 } }; ///< of the pieces with cells
  std::string errors;          ///< "rank r: reason" for each rank that cannot sample its piece
};

/// A `FlowField_3` over a data set whose pieces live on the ranks of a controller.  On one process
/// it is the input's own field.  On several, only rank 0 samples it, at points given to
/// `probe()` (collective) beforehand; `operator()` looks the samples up by the exact point.
/// Copies share their samples.
class Distributed_velocity_field {
public:
  using Sample = std::optional<Vector>;

  Distributed_velocity_field() : m_state(std::make_shared<State>()) {}

  /// Sets this rank's piece of the input when it changed: its field, or nothing when the piece
  /// has no cells; `error` says why it cannot be sampled (then `local` is empty).
  void set_piece(std::optional<Velocity_field> local, const std::string& error)
  {
    m_state->local = std::move(local);
    m_state->local_error = error;
  }

  /// Called by every rank at the start of every update, collective when distributed: gathers
  /// on rank 0 the state of every rank's piece (`changed`: since the last update).
  Distributed_input start(vtkMultiProcessController* controller, const std::array<double, 6>& local_bounds,
    bool changed)
  {
    State& s = *m_state;
    s.controller = controller != nullptr && controller->GetNumberOfProcesses() > 1 ? controller : nullptr;
    s.samples.clear();
    s.supplying_ranks = 0;
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
      {
        if (input.ranks_with_cells == 1)
          input.bounds = b;
        for (int d = 0; d < 3; ++d)
        {
          input.bounds[2 * d] = std::min(input.bounds[2 * d], b[2 * d]);
          input.bounds[2 * d + 1] = std::max(input.bounds[2 * d + 1], b[2 * d + 1]);
        }
      }
    }
    return input;
  }

  /// Whether the samples come from other ranks (more than one process).
  bool distributed() const { return m_state->controller != nullptr; }
  /// Whether this process runs the algorithm (rank 0, or the only process).
  bool is_root() const { return !distributed() || m_state->controller->GetLocalProcessId() == 0; }

  /// Rank 0: samples the distributed field at `points` (collective: the other ranks are in
  /// `serve()`); afterwards `operator()` answers at exactly these points.  Nothing on one process.
  void probe(const std::vector<Point>& points)
  {
    State& s = *m_state;
    if (!distributed())
      return;
    const int ranks = s.controller->GetNumberOfProcesses();
    int header[2] = { PROBE, int(points.size()) };
    s.controller->Broadcast(header, 2, 0);
    std::vector<double> coordinates(3 * points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      for (int d = 0; d < 3; ++d)
        coordinates[3 * i + std::size_t(d)] = points[i][d];
    s.controller->Broadcast(coordinates.data(), vtkIdType(coordinates.size()), 0);
    const std::vector<double> mine = sample_local(coordinates, ranks, 0);
    std::vector<double> total(mine.size());
    s.controller->Reduce(mine.data(), total.data(), vtkIdType(mine.size()), vtkCommunicator::SUM_OP, 0);

    const std::size_t n = points.size();
    s.samples.clear();
    s.samples.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double* t = &total[4 * i];
      Sample sample;
      if (t[3] > 0)
        sample = Vector(t[0] / t[3], t[1] / t[3], t[2] / t[3]);
      s.samples[key(points[i])] = sample;
    }
    s.failed_ranks = int(total[4 * n]);
    s.supplying_ranks = 0;
    for (int r = 0; r < ranks; ++r)
      s.supplying_ranks += total[4 * n + 1 + std::size_t(r)] > 0 ? 1 : 0;
    if (s.failed_ranks > 0)
      throw std::runtime_error(std::to_string(s.failed_ranks) + " rank(s) failed to sample their piece of the input");
  }

  /// Rank 0: calls `evaluate()` once to learn the points it samples (it must sample the same
  /// points when called again and have no other effect), then probes them.  Nothing on one process.
  template <class Evaluate>
  void probe_points_of(const Evaluate& evaluate)
  {
    State& s = *m_state;
    if (!distributed())
      return;
    s.recorded.clear();
    s.recording = true;
    try
    {
      evaluate();
    }
    catch (...)
    {
      s.recording = false;
      throw;
    }
    s.recording = false;
    probe(s.recorded);
  }

  /// Rank 0: tells the other ranks that no more probes come (ends their `serve()`).
  void finish()
  {
    if (!distributed())
      return;
    int header[2] = { FINISH, 0 };
    m_state->controller->Broadcast(header, 2, 0);
  }

  /// Ranks other than 0: answer rank 0's probes until it calls `finish()`.  Never throws.
  void serve()
  {
    State& s = *m_state;
    if (!distributed())
      return;
    const int ranks = s.controller->GetNumberOfProcesses();
    const int rank = s.controller->GetLocalProcessId();
    for (;;)
    {
      int header[2] = { FINISH, 0 };
      s.controller->Broadcast(header, 2, 0);
      if (header[0] != PROBE)
        return;
      std::vector<double> coordinates(3 * std::size_t(header[1]));
      s.controller->Broadcast(coordinates.data(), vtkIdType(coordinates.size()), 0);
      const std::vector<double> mine = sample_local(coordinates, ranks, rank);
      std::vector<double> total(mine.size());
      s.controller->Reduce(mine.data(), total.data(), vtkIdType(mine.size()), vtkCommunicator::SUM_OP, 0);
    }
  }

  /// The velocity at `p`: the input's own field on one process; on rank 0 of several, the sample
  /// probed at exactly `p`.  \throws std::logic_error for a point that was not probed.
  Sample operator()(const Point& p) const
  {
    const State& s = *m_state;
    if (!distributed())
      return s.local ? (*s.local)(p) : Sample();
    if (s.recording)
    {
      std::lock_guard<std::mutex> lock(s.record_mutex);
      s.recorded.push_back(p);
      return Sample();
    }
    const auto found = s.samples.find(key(p));
    if (found == s.samples.end())
      throw std::logic_error("the field was asked for a point that was not probed from the ranks");
    return found->second;
  }

  /// Ranks whose piece supplied at least one sample in the last exchange.
  int number_of_supplying_ranks() const { return m_state->supplying_ranks; }

private:
  enum Command
  {
    FINISH = 0,
    PROBE = 1
  };

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

  // This rank's reply: per point (vx, vy, vz, 1) where its piece has a sample, zeros elsewhere;
  // then 1 if sampling failed here, then per rank the number of samples it supplied.
  std::vector<double> sample_local(const std::vector<double>& coordinates, int ranks, int rank) const
  {
    const State& s = *m_state;
    const std::size_t n = coordinates.size() / 3;
    std::vector<double> reply(4 * n + 1 + std::size_t(ranks), 0.);
    if (!s.local_error.empty())
    {
      reply[4 * n] = 1;
      return reply;
    }
    if (!s.local)
      return reply;
    try
    {
      double supplied = 0;
      for (std::size_t i = 0; i < n; ++i)
      {
        const Sample v =
          (*s.local)(Point(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]));
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
    return reply;
  }

  struct State {
    vtkMultiProcessController* controller = nullptr; // null: one process
    std::optional<Velocity_field> local;             // this rank's piece; none: no cells
    std::string local_error;
    std::unordered_map<Key, Sample, Key_hash> samples;
    bool recording = false;
    mutable std::mutex record_mutex;
    mutable std::vector<Point> recorded;
    int failed_ranks = 0, supplying_ranks = 0;
  };
  std::shared_ptr<State> m_state;
};

} // namespace fas_paraview

#endif // FAS_DISTRIBUTED_FIELD_H
