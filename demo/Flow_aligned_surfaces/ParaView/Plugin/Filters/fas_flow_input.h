// The flow as ParaView gives it to the filters: the velocity array chosen in the panel with its
// association (point or cell data), on a data set or on a composite data set (an OpenFOAM case:
// the internal mesh and its boundary patches, a .vtm), which is one flow made of the 3D cells of
// all its blocks.  Private to the plugin.
#ifndef FAS_FLOW_INPUT_H
#define FAS_FLOW_INPUT_H

#include <vtkAlgorithm.h>
#include <vtkAppendFilter.h>
#include <vtkCellTypes.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>

#include <string>

namespace fas_paraview {

/// The velocity array of the panel's *Velocity* selector.
struct Velocity_selection {
  std::string name; ///< empty: the first 3-component array
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS;

  bool on_cells() const { return association == vtkDataObject::FIELD_ASSOCIATION_CELLS; }
  bool operator==(const Velocity_selection& o) const { return name == o.name && association == o.association; }
  bool operator!=(const Velocity_selection& o) const { return !(*this == o); }
};

/// The array chosen for input array 0 of `filter` (ParaView's *Velocity* property).
inline Velocity_selection selected_velocity(vtkAlgorithm* filter)
{
  Velocity_selection selection;
  vtkInformation* info = filter->GetInputArrayInformation(0);
  if (info == nullptr)
    return selection;
  if (info->Has(vtkDataObject::FIELD_NAME()))
    selection.name = info->Get(vtkDataObject::FIELD_NAME());
  if (info->Has(vtkDataObject::FIELD_ASSOCIATION()))
    selection.association = info->Get(vtkDataObject::FIELD_ASSOCIATION());
  return selection;
}

/// The flow's input port: a data set, or a composite data set (one flow, see `flow_data_set()`),
/// so that the pipeline hands the whole composite to the filter once instead of running the
/// filter on every block.
inline void accept_flow_inputs(vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
}

/// Whether `data_set` has a cell of dimension 3 (a volume that can contain a point).
inline bool has_volume_cells(vtkDataSet* data_set)
{
  if (auto* image = vtkImageData::SafeDownCast(data_set))
    return image->GetDataDimension() == 3;
  if (auto* grid = vtkRectilinearGrid::SafeDownCast(data_set))
    return grid->GetDataDimension() == 3;
  if (auto* grid = vtkStructuredGrid::SafeDownCast(data_set))
    return grid->GetDataDimension() == 3;
  for (vtkIdType c = 0; c < data_set->GetNumberOfCells(); ++c)
    if (vtkCellTypes::GetDimension(static_cast<unsigned char>(data_set->GetCellType(c))) == 3)
      return true;
  return false;
}

/// The data set the flow is sampled on, and what was left out of a composite input.
struct Flow_data_set {
  vtkSmartPointer<vtkDataSet> data_set; ///< null: no data set, or no block with a volume cell
  std::string note;                     ///< e.g. "3 blocks without 3D cells left out", or empty
};

/// `input` itself when it is a data set; for a composite data set, the blocks with 3D cells
/// appended into one unstructured grid (the arrays they all have), the blocks without (the
/// boundary patches of an OpenFOAM case) left out and counted in `note`.
inline Flow_data_set flow_data_set(vtkDataObject* input)
{
  Flow_data_set flow;
  if (auto* data_set = vtkDataSet::SafeDownCast(input)) {
    flow.data_set = data_set;
    return flow;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (composite == nullptr)
    return flow;
  vtkNew<vtkAppendFilter> append;
  append->SetOutputPointsPrecision(vtkAlgorithm::DEFAULT_PRECISION);
  int volumes = 0, left_out = 0;
  vtkSmartPointer<vtkCompositeDataIterator> block;
  block.TakeReference(composite->NewIterator());
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem()) {
    auto* piece = vtkDataSet::SafeDownCast(block->GetCurrentDataObject());
    if (piece == nullptr || piece->GetNumberOfCells() == 0)
      continue;
    if (has_volume_cells(piece)) {
      append->AddInputData(piece);
      ++volumes;
    }
    else
      ++left_out;
  }
  if (left_out > 0)
    flow.note = std::to_string(left_out) + (left_out == 1 ? " block" : " blocks") +
                " without 3D cells (boundary patches) left out of the flow";
  if (volumes == 0)
    return flow;
  if (volumes == 1)
    flow.data_set = vtkDataSet::SafeDownCast(append->GetInputDataObject(0, 0));
  else {
    append->Update();
    flow.data_set = append->GetOutput();
  }
  return flow;
}

/// `data_set` as the field should see it for `selection`: with a cell array chosen, a shallow
/// copy without the point array of the same name (an OpenFOAM case has `U` as both), so that the
/// cell values are sampled, piecewise constant per cell.
inline vtkSmartPointer<vtkDataSet> with_selected_association(vtkDataSet* data_set,
                                                            const Velocity_selection& selection)
{
  if (!selection.on_cells() || selection.name.empty() ||
      data_set->GetPointData()->GetArray(selection.name.c_str()) == nullptr)
    return data_set;
  vtkSmartPointer<vtkDataSet> copy;
  copy.TakeReference(data_set->NewInstance());
  copy->ShallowCopy(data_set);
  copy->GetPointData()->RemoveArray(selection.name.c_str());
  return copy;
}

} // namespace fas_paraview

#endif // FAS_FLOW_INPUT_H
