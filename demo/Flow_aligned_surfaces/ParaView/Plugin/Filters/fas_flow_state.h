// What the plugin's filters share (vtkFlowAlignedFilter::FlowState): the flow of input 0 sampled
// on every rank, its time steps, the outputs of the last successful update, and what an update
// gathers.  Private to the plugin.
#ifndef FAS_FLOW_STATE_H
#define FAS_FLOW_STATE_H

#include "vtkFlowAlignedFilter.h"

#include "fas_distributed_field.h"
#include "fas_distributed_update.h"
#include "fas_paraview_support.h"
#include "fas_temporal_input.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstddef>
#include <vector>

struct vtkFlowAlignedFilter::FlowState {
  fas_paraview::Distributed_velocity_field field; // the flow of input 0 (several ranks: every rank's piece)
  fas_paraview::Temporal_flow_input steps;        // the time steps of input 0
  fas_paraview::Kept_outputs kept;                // the outputs of the last successful update
  std::vector<std::size_t> needed;                // the steps an update samples (SelectSteps)
  fas_paraview::Distributed_input pieces;         // of this update (rank 0)
  vtkSmartPointer<vtkPolyData> gathered;          // input 1 of this update on rank 0, or null
  bool said_one_rank = false;                     // the note on an input on one rank of several
  bool said_cache = false;                        // the note on a Temporal Cache
};

#endif // FAS_FLOW_STATE_H
