// What every filter's update does over the ranks, around its algorithm on rank 0: the other
// ranks serve rank 0's exchanges until it finishes (`serve_rank_0()`, `Finish_probes`), a
// polygonal input is brought together on rank 0 (`gather_on_root()`), the steps of a temporal
// input are collected before the field is updated (`update_with_steps()`), the views through
// which the algorithms sample the distributed field, and the field data that say how the input
// was spread.  Private to the plugin.
#ifndef FAS_DISTRIBUTED_UPDATE_H
#define FAS_DISTRIBUTED_UPDATE_H

#include "fas_distributed_field.h"
#include "fas_paraview_support.h"
#include "fas_temporal_input.h"

#include <vtkAppendPolyData.h>
#include <vtkCleanPolyData.h>
#include <vtkMultiProcessController.h>
#include <vtkStripper.h>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace fas_paraview {

/// Ends the other ranks' `serve()` when rank 0 leaves an update, whatever the way out.
class Finish_probes {
public:
  explicit Finish_probes(const Distributed_velocity_field& field) : m_field(field) {}
  Finish_probes(const Finish_probes&) = delete;
  Finish_probes& operator=(const Finish_probes&) = delete;
  ~Finish_probes() { m_field.finish(); }

private:
  const Distributed_velocity_field& m_field;
};

/// Ranks other than 0: answers rank 0's probes until it has finished the update; the outputs of
/// this rank stay empty (the results live on rank 0).
inline void serve_rank_0(const Distributed_velocity_field& field, vtkInformationVector* outputVector)
{
  field.serve();
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
    if (vtkDataObject* output = vtkDataObject::GetData(outputVector, port))
      output->Initialize();
}

/// Rank 0 of several: how the input was spread and what sampling it cost, as field data of
/// `output` (number_of_ranks, number_of_ranks_with_cells, number_of_sampling_ranks: ranks that
/// supplied samples in the last exchange, number_of_exchanges).  Nothing on one process.
inline void add_distribution_values(vtkDataObject* output, const Distributed_input& pieces,
                                    const Distributed_velocity_field& field)
{
  if (!field.distributed())
    return;
  add_field_value(output, "number_of_ranks", double(pieces.ranks));
  add_field_value(output, "number_of_ranks_with_cells", double(pieces.ranks_with_cells));
  add_field_value(output, "number_of_sampling_ranks", double(field.number_of_supplying_ranks()));
  add_field_value(output, "number_of_exchanges", double(field.number_of_exchanges()));
}

/// Rank 0: `tm` as polygonal data with the arrays of `add_alignment_arrays()` (on several ranks
/// an exchange per array: the vertices' velocities, the faces' fluxes, the normalized flux), and
/// its normalized flux.
inline std::pair<vtkSmartPointer<vtkPolyData>, FAS::Normalized_flux> aligned_surface_output(
  Mesh& tm, const Distributed_velocity_field& field)
{
  vtkSmartPointer<vtkPolyData> polydata = to_polydata(tm);
  const FAS::Normalized_flux measured = add_alignment_arrays(polydata, tm, field);
  return std::make_pair(polydata, measured);
}

/// Every rank (collective when distributed): the pieces of a polygonal input brought together on
/// rank 0, where the algorithm runs: points that pieces share are merged, and line pieces are
/// joined into polylines where they meet.  A single non-empty piece is returned as it is (the
/// serial filter's point order).  On the other ranks, and on one process, `piece` itself (may be
/// null).
inline vtkSmartPointer<vtkPolyData> gather_on_root(vtkPolyData* piece)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  vtkSmartPointer<vtkPolyData> own = piece;
  if (controller == nullptr || controller->GetNumberOfProcesses() < 2)
    return own;
  auto sent = vtkSmartPointer<vtkPolyData>::New();
  if (piece != nullptr)
    sent->ShallowCopy(piece);
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(sent, pieces, 0);
  if (controller->GetLocalProcessId() != 0)
    return own;
  auto append = vtkSmartPointer<vtkAppendPolyData>::New();
  vtkSmartPointer<vtkPolyData> last;
  int non_empty = 0;
  bool polygons = false;
  for (const vtkSmartPointer<vtkDataObject>& object : pieces)
    if (vtkPolyData* p = vtkPolyData::SafeDownCast(object); p != nullptr && p->GetNumberOfPoints() > 0)
    {
      append->AddInputData(p);
      last = p;
      ++non_empty;
      polygons = polygons || p->GetNumberOfPolys() > 0 || p->GetNumberOfStrips() > 0;
    }
  if (non_empty == 0)
    return vtkSmartPointer<vtkPolyData>::New();
  if (non_empty == 1)
    return last;
  auto merge = vtkSmartPointer<vtkCleanPolyData>::New();
  merge->SetInputConnection(append->GetOutputPort());
  merge->PointMergingOn();
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(0.);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  vtkAlgorithm* last_stage = merge;
  auto join = vtkSmartPointer<vtkStripper>::New();
  if (!polygons)
  {
    join->SetInputConnection(merge->GetOutputPort());
    join->JoinContiguousSegmentsOn();
    last_stage = join;
  }
  last_stage->Update();
  vtkSmartPointer<vtkPolyData> whole = vtkPolyData::SafeDownCast(last_stage->GetOutputDataObject(0));
  return whole;
}

/// A `Distributed_velocity_field` point by point, without its batch operation: on one process,
/// where the library's rounds of batched sampling (a stream surface's Runge-Kutta stages) cost
/// more than the exchanges they save.
struct Pointwise_view {
  const Distributed_velocity_field& field;
  Distributed_velocity_field::Sample operator()(const Point& p) const { return field(p); }
};

/// The same as an unsteady field.
struct Pointwise_unsteady_view {
  const Distributed_velocity_field& field;
  Distributed_velocity_field::Sample operator()(const Point& p, double t) const { return field.at(p, t); }
};

/// The view of a `Distributed_velocity_field` as an unsteady field (`UnsteadyFlowField_3`):
/// `field.at(p, t)`, and batches of points and times in one exchange.
struct Unsteady_view {
  const Distributed_velocity_field& field;
  Distributed_velocity_field::Sample operator()(const Point& p, double t) const { return field.at(p, t); }
  std::vector<Distributed_velocity_field::Sample> sample(const std::vector<Point>& points,
                                                         const std::vector<double>& times) const
  {
    return field.sample(points, times);
  }
  std::optional<Distributed_velocity_field::Sample> sample_here(const Point& p, double t) const
  {
    return field.sample_here(p, t);
  }
  bool decides_here(const Point& p) const { return field.decides_here(p); }
  std::vector<Distributed_velocity_field::Sample> sample(const std::vector<Point>& points,
    const std::vector<double>& times, const Distributed_velocity_field::Integration_ahead& ahead,
    Distributed_velocity_field::Integrated_ahead& along) const
  {
    return field.sample(points, times, ahead, along);
  }
  void integrate_ahead_meanwhile(const Distributed_velocity_field::Integration_ahead& ahead,
    Distributed_velocity_field::Integrated_ahead& along, const std::function<void()>& work) const
  {
    field.integrate_ahead_meanwhile(ahead, along, work, unsteady_time);
  }
};

/// RequestData of a filter that samples the flow (every rank, collective when distributed): none
/// while the pipeline is still bringing the steps `needed` (the filter returns and is run again);
/// then `field.update()` with these steps, at the requested time.
inline std::optional<Distributed_input> update_with_steps(Temporal_flow_input& steps,
  Distributed_velocity_field& field, vtkInformation* request, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, const Velocity_selection& selection, const std::vector<std::size_t>& needed)
{
  if (!steps.collect(request, inputVector[0]->GetInformationObject(0)))
    return std::nullopt;
  if (!steps.temporal())
    return field.update(steps.steps({}), 0., selection);
  return field.update(steps.steps(needed), steps.requested_time(outputVector->GetInformationObject(0)), selection);
}

} // namespace fas_paraview

#endif // FAS_DISTRIBUTED_UPDATE_H
