#include "vtkFlowAlignedFilter.h"

#include "fas_flow_input.h"
#include "fas_flow_state.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkOutputWindow.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <exception>
#include <optional>
#include <string>

using namespace fas_paraview;

vtkFlowAlignedFilter::vtkFlowAlignedFilter()
  : Flow(new FlowState)
{
}

vtkFlowAlignedFilter::~vtkFlowAlignedFilter()
{
  delete this->Flow;
}

int vtkFlowAlignedFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Flow->steps.read_time_steps(inputVector[0]->GetInformationObject(0));
  // A steady flow: the output has the time steps of input 1 (a surface that plays Flow-Aligned
  // Surface's iterations), at which the pipeline asks that input.  ParaView's time keeper leaves
  // out the time steps of the inputs of a filter that has a TimestepValues property: without
  // them the iterations vanish from the time controls once a filter takes the surface.
  if (!this->Flow->steps.temporal() && this->GetNumberOfInputPorts() > 1 &&
      inputVector[1]->GetNumberOfInformationObjects() > 0)
  {
    using Pipeline = vtkStreamingDemandDrivenPipeline;
    vtkInformation* surface = inputVector[1]->GetInformationObject(0);
    for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
      for (vtkInformationDoubleVectorKey* key : { Pipeline::TIME_STEPS(), Pipeline::TIME_RANGE() })
        if (surface->Has(key))
          outputVector->GetInformationObject(port)->CopyEntry(surface, key);
  }
  return 1;
}

int vtkFlowAlignedFilter::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  FlowState& flow = *this->Flow;
  if (flow.steps.temporal())
  {
    this->SelectSteps(outputVector);
    flow.steps.request_next(inputVector[0]->GetInformationObject(0), flow.needed);
  }
  return 1;
}

void vtkFlowAlignedFilter::SelectSteps(vtkInformationVector* outputVector)
{
  FlowState& flow = *this->Flow;
  flow.needed.clear();
  if (flow.steps.temporal())
    flow.needed = flow.steps.steps_around(flow.steps.requested_time(outputVector->GetInformationObject(0)));
}

void vtkFlowAlignedFilter::FillOtherRankOutputs(vtkInformationVector*) {}

void vtkFlowAlignedFilter::AfterFailure(vtkInformationVector*, bool) {}

bool vtkFlowAlignedFilter::CancelledBeforeParametrization(vtkInformationVector* outputVector)
{
  const bool kept = this->Flow->kept.restore(outputVector);
  abort_handled(this);
  vtkWarningMacro(<< this->GetLabel() << ": cancelled before the parametrization was solved"
                  << (kept ? "; the previous output is kept" : ""));
  this->AfterFailure(outputVector, kept);
  return false;
}

int vtkFlowAlignedFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  FlowState& flow = *this->Flow;
  // Every rank: the flow of the steps the update needs (a temporal input: once they have come).
  this->SelectSteps(outputVector);
  const std::optional<Distributed_input> update = update_with_steps(
    flow.steps, flow.field, request, inputVector, outputVector, selected_velocity(this), flow.needed);
  if (!update)
    return 1; // the pipeline runs this filter again with the next time step
  flow.pieces = *update;
  // The velocity fields this update built here (0: the field of another filter of the same
  // input, or of an earlier update, was at hand: fas_field_cache.h).
  const double fields_built = double(flow.field.take_fields_built());
  // Every rank: input 1's pieces go to rank 0, and every rank samples its piece of the flow for
  // rank 0 (one process: the input's own field).
  flow.gathered = this->GetNumberOfInputPorts() > 1
    ? gather_on_root(vtkPolyData::GetData(inputVector[1], 0))
    : vtkSmartPointer<vtkPolyData>();
  if (!flow.field.is_root())
  {
    serve_rank_0(flow.field, outputVector);
    this->FillOtherRankOutputs(outputVector);
    return 1;
  }
  if (flow.pieces.ranks > 1 && flow.pieces.ranks_with_cells == 1 && !flow.said_one_rank)
  {
    flow.said_one_rank = true;
    vtkOutputWindowDisplayText((std::string(this->GetLabel()) + ": the input's cells are all on one of the " +
      std::to_string(flow.pieces.ranks) + " ranks, which samples the flow alone; redistributing the data "
      "(Redistribute DataSet) would spread the sampling over the ranks\n").c_str());
  }
  if (flow.steps.steps_redistributed() >= 2 && !flow.said_cache)
  {
    flow.said_cache = true;
    vtkOutputWindowDisplayText((std::string(this->GetLabel()) + ": the input is a Redistribute DataSet, which "
      "keeps only the last time step it made, so the " + std::to_string(flow.steps.steps_redistributed()) +
      " steps this update follows were redistributed for it; a Temporal Cache (Filters > Temporal) right "
      "after it would keep them for this filter's next updates and the next filters\n").c_str());
  }
  try
  {
    Finish_probes finish_probes(flow.field);
    if (this->Compute(request, inputVector, outputVector))
    {
      for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
        if (vtkDataObject* output = vtkDataObject::GetData(outputVector, port))
          add_field_value(output, "number_of_velocity_fields_built", fields_built);
      flow.kept.keep(outputVector);
    }
  }
  catch (const std::exception& e)
  {
    const bool kept = flow.kept.restore(outputVector);
    vtkErrorMacro(<< this->GetLabel() << ": " << e.what() << (kept ? "; the previous output is kept" : ""));
    this->AfterFailure(outputVector, kept);
  }
  return 1;
}

void vtkFlowAlignedFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
