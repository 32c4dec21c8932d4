// The time steps of a flow filter's input (port 0), and the pipeline passes that bring the ones
// an update needs.  Private to the plugin.
//
// An update at time T of a temporal input (a .pvd, an OpenFOAM case with several times) samples
// the flow between the two steps around T, interpolated linearly in time (as the library's
// Unsteady_flow_field_3 does); the Flow-Aligned Surface also needs the steps its surface followed
// the flow through.  The pipeline hands a filter one step per execution, so the filter asks for
// the steps one after the other, as VTK's temporal filters do (vtkTemporalStatistics, the
// particle tracers): RequestUpdateExtent sets the input's UPDATE_TIME_STEP to the next step it
// lacks, and RequestData keeps that step and sets CONTINUE_EXECUTING until the last one has come;
// then the filter runs on them all.  A step held from an earlier update is not asked for again;
// the filter holds the steps of its last update only, and drops them when the pipeline above it
// or its own properties change (RequestInformation).
#ifndef FAS_TEMPORAL_INPUT_H
#define FAS_TEMPORAL_INPUT_H

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>
#include <vtkExecutive.h>
#include <vtkInformationExecutivePortKey.h>
#include <vtkInformation.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <vector>

namespace fas_paraview {

/// The input of a flow filter at one of its time steps (a steady input: its only "step", time 0).
struct Flow_step {
  double time = 0;
  vtkSmartPointer<vtkDataObject> data;
  std::optional<std::array<int, 6>> whole_extent; ///< of an image input, for its pieces' blocks
};

/// A flow filter's view of the time steps of its input port 0 (see the top of this file).
class Temporal_flow_input {
public:
  /// RequestInformation: the input's time steps (none: a steady input).  Drops the steps held.
  void read_time_steps(vtkInformation* input_information)
  {
    m_times.clear();
    m_held.clear();
    m_needed.clear();
    m_missing.clear();
    m_in_loop = false;
    using Pipeline = vtkStreamingDemandDrivenPipeline;
    if (input_information == nullptr || !input_information->Has(Pipeline::TIME_STEPS()))
      return;
    const double* steps = input_information->Get(Pipeline::TIME_STEPS());
    m_times.assign(steps, steps + input_information->Length(Pipeline::TIME_STEPS()));
  }

  /// Whether the input has time steps (more than one: a single step is a steady flow).
  bool temporal() const { return m_times.size() > 1; }
  /// The input's time steps, in increasing order.
  const std::vector<double>& times() const { return m_times; }

  /// The time the update of `output_information` asks for, within the data's time range (a
  /// time before the first step or after the last one samples that step, as ParaView's readers
  /// give it); the first step's time when none is asked for.  Temporal inputs only.
  double requested_time(vtkInformation* output_information) const
  {
    using Pipeline = vtkStreamingDemandDrivenPipeline;
    double t = m_times.front();
    if (output_information != nullptr && output_information->Has(Pipeline::UPDATE_TIME_STEP()))
      t = output_information->Get(Pipeline::UPDATE_TIME_STEP());
    return std::clamp(t, m_times.front(), m_times.back());
  }

  /// The index of the last step at or before `t` (0 before the first step).
  std::size_t step_at_or_before(double t) const
  {
    const auto after = std::upper_bound(m_times.begin(), m_times.end(), t);
    return after == m_times.begin() ? 0 : std::size_t(after - m_times.begin()) - 1;
  }

  /// The indices of the steps that the flow at `t` is interpolated from: one when `t` is a
  /// step's time, else the two around it.
  std::vector<std::size_t> steps_around(double t) const
  {
    const std::size_t i = step_at_or_before(t);
    if (m_times[i] == t || i + 1 == m_times.size())
      return { i };
    return { i, i + 1 };
  }

  /// The indices of the steps from the last one at or before `from` to the first one at or
  /// after `to` (`from` <= `to`): the steps that the flow over [from, to] is interpolated from.
  std::vector<std::size_t> steps_between(double from, double to) const
  {
    std::vector<std::size_t> steps;
    const std::size_t last = steps_around(to).back();
    for (std::size_t i = step_at_or_before(from); i <= last; ++i)
      steps.push_back(i);
    return steps;
  }

  /// RequestUpdateExtent: `needed` are the indices of the steps the update needs (nothing for a
  /// steady input); asks the input for the next one not held yet.  The first pass of an update
  /// (or a pass whose `needed` changed) starts the passes anew.
  void request_next(vtkInformation* input_information, const std::vector<std::size_t>& needed)
  {
    if (!temporal())
      return;
    if (!m_in_loop || needed != m_needed)
    {
      m_needed = needed;
      m_missing.clear();
      for (std::size_t i : needed)
        if (m_held.count(i) == 0)
          m_missing.push_back(i);
      m_pass = 0;
      m_in_loop = true;
    }
    // Nothing missing: the step the input gave last, which it does not compute again.
    if (m_pass < m_missing.size())
      m_last_asked = m_times[m_missing[m_pass]];
    if (m_last_asked)
      input_information->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), *m_last_asked);
  }

  /// RequestData: keeps the step this pass brought.  Returns false while steps are missing (the
  /// pipeline then runs the filter again: CONTINUE_EXECUTING is set), true when all are here.
  bool collect(vtkInformation* request, vtkInformation* input_information)
  {
    vtkDataObject* input = vtkDataObject::GetData(input_information);
    if (!temporal())
    {
      m_steady = Flow_step{ 0., input, whole_extent(input_information) };
      return true;
    }
    if (m_pass == 0)
      m_redistributed = redistributed(input_information);
    if (m_pass < m_missing.size() && input != nullptr)
    {
      vtkSmartPointer<vtkDataObject> copy;
      copy.TakeReference(input->NewInstance());
      copy->ShallowCopy(input);
      m_held[m_missing[m_pass]] = Flow_step{ m_times[m_missing[m_pass]], copy, whole_extent(input_information) };
    }
    ++m_pass;
    if (m_pass < m_missing.size())
    {
      request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
      return false;
    }
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    m_in_loop = false;
    for (auto held = m_held.begin(); held != m_held.end();)
      held = std::find(m_needed.begin(), m_needed.end(), held->first) == m_needed.end() ? m_held.erase(held)
                                                                                      : std::next(held);
    return true;
  }

  /// After `collect()` returned true: how many steps this update brought from a Redistribute
  /// DataSet, which keeps only the last step it made (0 from any other input).
  std::size_t steps_redistributed() const { return m_redistributed ? m_missing.size() : 0; }

  /// After `collect()` returned true: the steps of `indices` (held), in time order; for a steady
  /// input, the input itself.
  std::vector<Flow_step> steps(const std::vector<std::size_t>& indices) const
  {
    if (!temporal())
      return { m_steady };
    std::vector<Flow_step> steps;
    for (std::size_t i : indices)
      if (const auto held = m_held.find(i); held != m_held.end())
        steps.push_back(held->second);
    return steps;
  }

private:
  // Whether the input comes from ParaView's Redistribute DataSet (through the post filter that
  // ParaView puts after every filter's output, `vtkPVPostFilter`).
  static bool redistributed(vtkInformation* input_information)
  {
    vtkExecutive* producer = nullptr;
    int port = 0;
    if (input_information != nullptr)
      vtkExecutive::PRODUCER()->Get(input_information, producer, port);
    vtkAlgorithm* algorithm = producer != nullptr ? producer->GetAlgorithm() : nullptr;
    while (algorithm != nullptr && algorithm->IsA("vtkPVPostFilter") && algorithm->GetNumberOfInputPorts() > 0 &&
      algorithm->GetNumberOfInputConnections(0) > 0)
      algorithm = algorithm->GetInputAlgorithm(0, 0);
    return algorithm != nullptr && algorithm->IsA("vtkRedistributeDataSetFilter");
  }

  static std::optional<std::array<int, 6>> whole_extent(vtkInformation* input_information)
  {
    using Pipeline = vtkStreamingDemandDrivenPipeline;
    if (input_information == nullptr || !input_information->Has(Pipeline::WHOLE_EXTENT()))
      return std::nullopt;
    std::array<int, 6> extent;
    input_information->Get(Pipeline::WHOLE_EXTENT(), extent.data());
    return extent;
  }

  std::vector<double> m_times;
  std::map<std::size_t, Flow_step> m_held; // by step index
  std::vector<std::size_t> m_needed, m_missing;
  std::size_t m_pass = 0;
  bool m_in_loop = false, m_redistributed = false;
  std::optional<double> m_last_asked;
  Flow_step m_steady;
};

} // namespace fas_paraview

#endif // FAS_TEMPORAL_INPUT_H
