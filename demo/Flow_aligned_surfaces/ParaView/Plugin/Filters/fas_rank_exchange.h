// The wire between rank 0 and the other ranks (fas_distributed_field.h): what rank 0 broadcasts
// in an exchange, how every rank answers it from its piece, and how the answers come back to
// rank 0.  Private to the plugin.
//
// An exchange is one broadcast (the points and the particles inline up to 3.8 KB, below MPI's
// usual eager limit; more in a second broadcast), one sum-reduction (per point the sum of the
// samples of the pieces that hold it and their number; a failure flag; per rank its number of
// samples and of values integrated ahead) and, when the round has particles, one gather of the
// states and samples that the ranks integrated ahead.  In a round with particles each rank also
// tells rank 0 that it has integrated them (a message of one number, before the reduction), so
// that rank 0 can go on working while they integrate (`others_integrating()`).
#ifndef FAS_RANK_EXCHANGE_H
#define FAS_RANK_EXCHANGE_H

#include "fas_piece_field.h"

#include <CGAL/Flow_aligned_surfaces/internal/integration_ahead.h>

#include <vtkCommunicator.h>
#include <vtkMPICommunicator.h>
#include <vtkMultiProcessController.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fas_paraview {

/// The time at which the ranks sample integrating ahead: NaN for each sample's own time.
constexpr double unsteady_time = std::numeric_limits<double>::quiet_NaN();

/// What rank 0 asks of every rank in an exchange.
struct Round {
  std::vector<double> coordinates;   ///< (x, y, z, t) per point to sample
  std::vector<double> ahead;         ///< the particles to integrate ahead (Integration_ahead's numbers)
  double ahead_time = unsteady_time; ///< at which a steady field samples them
};

/// The buffers of the exchanges on this process, kept from one exchange to the next and shared by
/// every field: a page fault costs microseconds on the virtual machines the benchmarks run on,
/// and a new filter's first exchange (the default patch's lattice of 64,000 points over the whole
/// data) took 0.051 s on 2 ranks with buffers of its own against 0.036 s with these (0.030 s on
/// one process).  One exchange runs at a time on a process: the pipeline updates one filter at a
/// time, a field exchanges only on the thread of its update, and never while rank 0 works
/// between the two halves of an exchange (`Distributed_velocity_field::work_meanwhile()`).
struct Exchange_buffers {
  Round round;                          ///< rank 0's points and particles; a rank's received round
  std::vector<std::size_t> here, asked; ///< rank 0: the points it samples itself and those it asks
  std::vector<double> values;           ///< the round as sent
  std::vector<double> mine, total;      ///< this rank's reply and, on rank 0, the sum of all

  static Exchange_buffers& of_this_process()
  {
    static Exchange_buffers buffers;
    return buffers;
  }
};

/// The collective operations of the exchanges over a controller's ranks.
class Rank_exchange {
public:
  using Sample = std::optional<Vector>;
  using Integrated_ahead = FAS::internal::Integrated_ahead<Sample>;
  enum Command
  {
    FINISH = 0,
    PROBE = 1
  };

  void set_controller(vtkMultiProcessController* controller) { m_controller = controller; }
  /// Null on one process.
  vtkMultiProcessController* controller() const { return m_controller; }

  /// Rank 0: broadcasts `command` and `round`.
  void send(Command command, const Round& round)
  {
    Message first{};
    first[0] = command;
    first[1] = double(round.coordinates.size() / 4);
    first[2] = double(round.ahead.size());
    first[3] = round.ahead_time;
    std::vector<double>& values = Exchange_buffers::of_this_process().values;
    values.assign(round.coordinates.begin(), round.coordinates.end());
    values.insert(values.end(), round.ahead.begin(), round.ahead.end());
    const bool inline_values = values.size() <= first.size() - header_size;
    if (inline_values)
      std::copy(values.begin(), values.end(), first.begin() + header_size);
    m_controller->Broadcast(first.data(), vtkIdType(first.size()), 0);
    if (!inline_values)
      m_controller->Broadcast(values.data(), vtkIdType(values.size()), 0);
  }

  /// Other ranks: receives what `send()` broadcasts into `round`; returns the command.
  Command receive(Round& round)
  {
    Message first{};
    m_controller->Broadcast(first.data(), vtkIdType(first.size()), 0);
    if (first[0] != PROBE)
      return FINISH;
    const std::size_t n = 4 * std::size_t(first[1]);
    std::vector<double>& values = Exchange_buffers::of_this_process().values;
    values.resize(n + std::size_t(first[2]));
    if (values.size() <= first.size() - header_size)
      std::copy_n(first.begin() + header_size, values.size(), values.begin());
    else
      m_controller->Broadcast(values.data(), vtkIdType(values.size()), 0);
    round.coordinates.assign(values.begin(), values.begin() + std::ptrdiff_t(n));
    round.ahead.assign(values.begin() + std::ptrdiff_t(n), values.end());
    round.ahead_time = first[3];
    return PROBE;
  }

  /// Every rank's answer to `round` from its `piece` (collective): on rank 0 the sum of the
  /// ranks' replies (`Rank_piece::answer()`), and there where the particles that the other ranks
  /// integrated ahead got to in `along`.  The sum lives until the next exchange (`Exchange_buffers`).
  const std::vector<double>& reply(const Round& round, const Rank_piece& piece, Integrated_ahead* along)
  {
    const std::size_t ranks = std::size_t(m_controller->GetNumberOfProcesses());
    const int rank = m_controller->GetLocalProcessId();
    std::vector<double>& mine = Exchange_buffers::of_this_process().mine;
    std::vector<double>& total = Exchange_buffers::of_this_process().total;
    piece.answer(round.coordinates, int(ranks), rank, mine);
    const std::vector<double> ahead =
      round.ahead.empty() || rank == 0 ? std::vector<double>() : integrated_here(round, piece);
    mine[mine.size() - ranks + std::size_t(rank)] = double(ahead.size());
    if (!round.ahead.empty())
      say_integrated(ranks, rank);
    total.resize(mine.size());
    m_controller->Reduce(mine.data(), total.data(), vtkIdType(mine.size()), vtkCommunicator::SUM_OP, 0);
    if (round.ahead.empty())
      return total;
    std::vector<vtkIdType> lengths(ranks), offsets(ranks);
    for (std::size_t r = 0; r < ranks; ++r)
    {
      lengths[r] = vtkIdType(total[total.size() - ranks + r]);
      offsets[r] = r == 0 ? 0 : offsets[r - 1] + lengths[r - 1];
    }
    std::vector<double> all(std::size_t(offsets.back() + lengths.back()));
    m_controller->GatherV(ahead.data(), all.data(), vtkIdType(ahead.size()), lengths.data(), offsets.data(), 0);
    if (along != nullptr)
      for (std::size_t r = 0; r < ranks; ++r)
        read_integrated(all.data() + offsets[r], std::size_t(lengths[r]), *along);
    return total;
  }

  /// Rank 0, between sending a round with particles and replying to it: whether a rank has not
  /// integrated them yet (false when the controller cannot tell without waiting).
  bool others_integrating() const
  {
    auto* mpi = vtkMPICommunicator::SafeDownCast(m_controller->GetCommunicator());
    if (mpi == nullptr)
      return false;
    for (int r = 1; r < m_controller->GetNumberOfProcesses(); ++r)
    {
      int flag = 0, source = 0;
      if (mpi->Iprobe(r, integrated_tag, &flag, &source) == 0)
        return false;
      if (flag == 0)
        return true;
    }
    return false;
  }

  /// Rank 0's sample from the sum of the ranks' replies at a point: the mean of the pieces that
  /// hold it, or none.
  static Sample combined(const double* total)
  {
    if (!(total[3] > 0))
      return Sample();
    return Vector(total[0] / total[3], total[1] / total[3], total[2] / total[3]);
  }

  /// A sample of this rank's piece that no other piece may hold as rank 0 gets it from an
  /// exchange: the sum of it and the other ranks' zeros, divided by the one piece that has it.
  static Sample as_exchanged(const Sample& v)
  {
    if (!v)
      return Sample();
    const double total[4] = { 0. + v->x(), 0. + v->y(), 0. + v->z(), 1. };
    return combined(total);
  }

private:
  // The first broadcast of an exchange: the command, the number of points, the number of values
  // of the particles to integrate ahead, the time of their samples, and, when they fit, the points
  // followed by the particles, so that a small exchange costs one broadcast; else they follow in a
  // second one.  Its size keeps it below MPI's usual eager limit (4 KiB), which sends it at once.
  static constexpr std::size_t header_size = 4;
  // The tag of the message by which a rank says it has integrated a round's particles.
  static constexpr int integrated_tag = 73021;

  // Ranks other than 0 tell rank 0 that they have integrated the round's particles; rank 0 takes
  // these messages before the reduction.
  void say_integrated(std::size_t ranks, int rank)
  {
    int done = 1;
    if (rank != 0)
      m_controller->Send(&done, 1, 0, integrated_tag);
    else
      for (int r = 1; r < int(ranks); ++r)
        m_controller->Receive(&done, 1, r, integrated_tag);
  }
  using Message = std::array<double, 480>;

  // The values of a state (the particle's index and its integrator's state, as many as a
  // particle's record) and of a sample in what `integrated_here()` sends.
  static constexpr std::size_t state_values = FAS::internal::Integration_ahead::record_size;
  static constexpr std::size_t sample_values = 8;

  // A rank other than 0: where the particles of `round` got to, integrated on while its piece
  // alone decides their samples: the number of states and of samples, then per state the
  // particle's index and its integrator's state, per sample (x, y, z, t, vx, vy, vz, 1 or 0 for
  // no sample).  Rank 0 answers those of its own piece when its tasks ask (`sample_here()`).  A
  // rank that fails to integrate sends nothing.
  static std::vector<double> integrated_here(const Round& round, const Rank_piece& piece)
  {
    std::vector<double> sent;
    try
    {
      Integrated_ahead along;
      piece.integrate_ahead(FAS::internal::Integration_ahead::from_numbers(round.ahead), round.ahead_time, along);
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

  // Adds to `along` what one rank's `integrated_here()` sent (`n` values at `v`).
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

  vtkMultiProcessController* m_controller = nullptr;
};

} // namespace fas_paraview

#endif // FAS_RANK_EXCHANGE_H
