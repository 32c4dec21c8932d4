// This rank's piece of the flow (fas_distributed_field.h): the velocity fields of its steps,
// interpolated in time, what it answers to the points of an exchange, how far it integrates the
// particles of a stream or path surface, and where it alone decides a sample.  Private to the
// plugin.
#ifndef FAS_PIECE_FIELD_H
#define FAS_PIECE_FIELD_H

#include "fas_field_cache.h"
#include "fas_paraview_support.h"
#include "fas_temporal_input.h"

#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/integration_ahead.h>

#include <vtkCompositeDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fas_paraview {

/// A rank's piece of the flow at a time: its steps (one for a steady input) interpolated linearly
/// in time.
using Piece_field = FAS::Time_slice_flow_field_3<FAS::Unsteady_flow_field_3<Velocity_field>>;

/// Grows `bounds` (empty: 1, -1, ...) to hold the bounds `b`.
inline void grow_bounds(std::array<double, 6>& bounds, const std::array<double, 6>& b)
{
  const bool empty = bounds[0] > bounds[1];
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] = empty ? b[2 * d] : std::min(bounds[2 * d], b[2 * d]);
    bounds[2 * d + 1] = empty ? b[2 * d + 1] : std::max(bounds[2 * d + 1], b[2 * d + 1]);
  }
}

/// This rank's piece of a flow and its field.
class Rank_piece {
public:
  using Sample = std::optional<Vector>;

  /// Samples the piece at `time` from `steps` (each a data set, or the 3D blocks of a composite
  /// data set: `flow_data_set()`; none when the piece has no cells) with the array `selection`
  /// (empty name: the active vectors); a step's field is taken anew only when its data or the
  /// selection changed (from the `Field_cache` when another filter has it).  `several`: the
  /// piece is one of several ranks' (a composite without 3D cells is then an empty piece, not an
  /// error).  Never throws: a piece that cannot be sampled keeps its reason in `error()`.
  void sample(const std::vector<Flow_step>& steps, double time, const Velocity_selection& selection, bool several)
  {
    if (m_have_field && same_steps(steps, selection))
    {
      if (m_field)
        m_field->set_time(time);
      return;
    }
    std::vector<Sampled_step> sampled;
    m_field.reset();
    m_error.clear();
    try
    {
      for (const Flow_step& step : steps)
        sampled.push_back(sample_step(step, selection, several));
      m_field = interpolated(steps, sampled, time);
    }
    catch (const std::exception& e)
    {
      m_error = e.what();
    }
    m_flow = sampled.empty() ? Flow_data_set() : sampled.front().flow;
    m_sampled = std::move(sampled);
    m_selection = selection;
    m_have_field = m_error.empty();
    m_sampled_since_taken = true;
  }

  /// The field of the piece: null when the piece has no cells or cannot be sampled.
  const Piece_field* field() const { return m_field ? &*m_field : nullptr; }
  /// What `field()` samples (its first step).
  const Flow_data_set& flow() const { return m_flow; }
  /// Why the piece cannot be sampled, or empty.
  const std::string& error() const { return m_error; }
  /// Samples at time `t` from now on.
  void set_time(double t)
  {
    if (m_field)
      m_field->set_time(t);
  }
  /// Whether the piece was sampled anew since the last call.
  bool take_sampled_anew() { return std::exchange(m_sampled_since_taken, false); }
  /// The velocity fields built (not found in the `Field_cache`) since the last call.
  std::size_t take_fields_built() { return std::exchange(m_fields_built, 0); }

  /// The bounds of the piece over all the steps it samples (they may be cut differently at each
  /// step); empty (1, -1, ...) without cells.
  std::array<double, 6> bounds_of_steps() const
  {
    std::array<double, 6> bounds{ { 1, -1, 1, -1, 1, -1 } };
    for (const Sampled_step& step : m_sampled)
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

  /// Every rank learns the bounds of every other rank's piece with cells (collective), for
  /// `decides()`, widened by 1e-6 of the largest extent of them all (beyond the locators'
  /// tolerances).
  void learn_other_pieces(vtkMultiProcessController* controller)
  {
    const std::array<double, 6> local_bounds = bounds_of_steps();
    const int ranks = controller->GetNumberOfProcesses();
    std::vector<double> all(6 * std::size_t(ranks));
    controller->AllGather(local_bounds.data(), all.data(), 6);
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
    m_other_pieces.clear();
    for (std::size_t r = 0; r < pieces.size(); ++r)
    {
      if (int(r) == controller->GetLocalProcessId() || pieces[r][0] > pieces[r][1])
        continue;
      for (int d = 0; d < 3; ++d)
      {
        pieces[r][2 * d] -= margin;
        pieces[r][2 * d + 1] += margin;
      }
      m_other_pieces.push_back(pieces[r]);
    }
  }

  /// Whether this piece alone decides an exchange's sample at `x`: no other rank's piece with
  /// cells has bounds (widened beyond the locators' tolerances) that hold it, or, where the
  /// pieces' bounds overlap (the cells along a cut between pieces of an unstructured mesh), it
  /// lies in the interior of one of this piece's cells at every step, where no other piece's
  /// cells reach.
  bool decides(const Eigen::Vector3d& x) const
  {
    return !in_other_bounds(x) || in_own_cells_interior(x);
  }

  /// This rank's reply to the points (x, y, z, t), in `reply`: per point (vx, vy, vz, 1) where the
  /// piece has a sample there and then, zeros elsewhere; then 1 if sampling failed here; then per
  /// rank the number of samples it supplied; then per rank the number of values it integrated
  /// ahead (0: fas_rank_exchange.h sets this rank's).
  void answer(const std::vector<double>& coordinates, int ranks, int rank, std::vector<double>& reply) const
  {
    const std::size_t n = coordinates.size() / 4;
    reply.assign(4 * n + 1 + 2 * std::size_t(ranks), 0.);
    if (!m_error.empty())
    {
      reply[4 * n] = 1;
      return;
    }
    if (!m_field)
      return;
    try
    {
      const auto& unsteady = m_field->unsteady_field();
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

  /// Integrates the particles `ahead` on while this piece alone decides their samples (at
  /// `time`, or each sample's own when it is NaN), and puts where they got to in `along`
  /// (integration_ahead.h).  \throws what sampling or reading the particles throws.
  void integrate_ahead(const FAS::internal::Integration_ahead& ahead, double time,
    FAS::internal::Integrated_ahead<Sample>& along) const
  {
    if (!m_field || !m_error.empty())
      return;
    const auto& unsteady = m_field->unsteady_field();
    FAS::internal::integrate_ahead<Sample>(
      ahead,
      [&](const Eigen::Vector3d& x, double t) {
        return unsteady(Point(x[0], x[1], x[2]), std::isnan(time) ? t : time);
      },
      [&](const Eigen::Vector3d& x) { return decides(x); }, along);
  }

private:
  bool in_other_bounds(const Eigen::Vector3d& x) const
  {
    for (const std::array<double, 6>& b : m_other_pieces)
      if (x[0] >= b[0] && x[0] <= b[1] && x[1] >= b[2] && x[1] <= b[3] && x[2] >= b[4] && x[2] <= b[5])
        return true;
    return false;
  }

  bool in_own_cells_interior(const Eigen::Vector3d& x) const
  {
    if (!m_error.empty() || m_sampled.empty())
      return false;
    const Point p(x[0], x[1], x[2]);
    for (const Sampled_step& step : m_sampled)
      if (!step.field || !step.field->is_in_cell_interior(p))
        return false;
    return true;
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
    if (selection != m_selection || steps.size() != m_sampled.size())
      return false;
    for (std::size_t i = 0; i < steps.size(); ++i)
      if (steps[i].data != m_sampled[i].data ||
          (steps[i].data != nullptr && steps[i].data->GetMTime() != m_sampled[i].data_time))
        return false;
    return true;
  }

  // `step`'s field: the one built before when its data and the selection are the same.
  Sampled_step sample_step(const Flow_step& step, const Velocity_selection& selection, bool several)
  {
    const vtkMTimeType data_time = step.data != nullptr ? step.data->GetMTime() : 0;
    if (selection == m_selection)
      for (const Sampled_step& old : m_sampled)
        if (old.data == step.data && old.data_time == data_time)
          return old;
    Sampled_step sampled{ step.data, data_time, flow_data_set(step.data), nullptr };
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
      m_fields_built += built ? 1 : 0;
    }
    return sampled;
  }

  // The piece's steps interpolated in time, at `time`; none when the piece has no cells.
  static std::optional<Piece_field> interpolated(const std::vector<Flow_step>& steps,
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

  std::optional<Piece_field> m_field; // none: no cells
  std::string m_error;
  std::vector<Sampled_step> m_sampled; // the steps `m_field` interpolates
  Velocity_selection m_selection;
  Flow_data_set m_flow;                // of the first step
  bool m_have_field = false;
  bool m_sampled_since_taken = false;
  std::size_t m_fields_built = 0;
  std::vector<std::array<double, 6>> m_other_pieces; // the widened bounds of the other ranks' pieces with cells
};

} // namespace fas_paraview

#endif // FAS_PIECE_FIELD_H
