// The base of the plugin's filters: the flow of input 0 sampled on every rank, the algorithm on
// rank 0, and the protocol of an update between them, in one place.
#ifndef vtkFlowAlignedFilter_h
#define vtkFlowAlignedFilter_h

#include "FlowAlignedSurfacesFiltersModule.h"
#include <vtkPolyDataAlgorithm.h>

/// Input port 0 of every derived filter: the flow, any data set with a 3-component point or cell
/// array (`SetInputArrayToProcess(0, ...)`), steady or with time steps, on one process or spread
/// over the ranks of pvserver / pvbatch --mpi.  An optional input port 1 (a surface, seed curves)
/// is brought together on rank 0.
///
/// An update, on every rank: the time steps the filter needs come one pipeline pass after the
/// other (`SelectSteps()`); every rank samples its piece of the flow; the pieces of input 1 go
/// to rank 0.  Rank 0 (or the only process) runs the filter's algorithm (`Compute()`), taking its
/// samples from every rank's piece, while the other ranks answer its exchanges until it has
/// finished, whatever the way out, and output empty data (`FillOtherRankOutputs()`).  What
/// `Compute()` throws is reported as "<label>: <reason>" and the outputs of the last successful
/// update are restored.  An input whose cells are all on one rank of several (the legacy VTK
/// reader puts them on rank 0) works; the filter says once that redistributing the data would
/// spread the sampling.  A filter that follows several time steps of a Redistribute DataSet, which
/// keeps only its last one, says once that a Temporal Cache after it would keep them.
class FLOWALIGNEDSURFACESFILTERS_EXPORT vtkFlowAlignedFilter : public vtkPolyDataAlgorithm
{
public:
  vtkAbstractTypeMacro(vtkFlowAlignedFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkFlowAlignedFilter();
  ~vtkFlowAlignedFilter() override;

  /// Reads the time steps of input 0.
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Asks input 0 for the time steps of `SelectSteps()`, one pass after the other.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The protocol of an update (see above).
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The filter's name in its messages.
  virtual const char* GetLabel() = 0;
  /// Rank 0, or the only process: the filter's algorithm (what the ranks hold is in `Flow`).
  /// Returns whether the outputs are new, to be restored after a later failure (false: it kept
  /// the earlier ones, cancelled); throws `std::exception` saying what is wrong.
  virtual bool Compute(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) = 0;
  /// Sets `Flow`'s steps of input 0 that an update samples; by default those around the
  /// requested time (none for a steady input).
  virtual void SelectSteps(vtkInformationVector* outputVector);
  /// Ranks other than 0, after rank 0 has finished: their outputs (empty by default).
  virtual void FillOtherRankOutputs(vtkInformationVector* outputVector);
  /// Rank 0 after a failure; `kept`: whether the previous outputs were restored.
  virtual void AfterFailure(vtkInformationVector* outputVector, bool kept);
  /// Rank 0, when an abort (ParaView's Cancel) stopped `Compute()` before its parametrization
  /// was solved: restores the previous outputs, warns so, and returns false for `Compute()`.
  bool CancelledBeforeParametrization(vtkInformationVector* outputVector);

  /// What the derived filters share (fas_flow_state.h, private to the plugin): the flow of
  /// input 0 and its time steps, the outputs kept, the pieces of this update, input 1 gathered.
  struct FlowState;
  FlowState* Flow;

private:
  vtkFlowAlignedFilter(const vtkFlowAlignedFilter&) = delete;
  void operator=(const vtkFlowAlignedFilter&) = delete;
};

#endif
