// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How VTK_flow_field_3 and make_unstructured_flow_field() find their arrays in a VTK data set:
// a named array in the point data, then in the cell data; the velocity when no name is given.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_VTK_VELOCITY_ARRAY_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_VTK_VELOCITY_ARRAY_H

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

#include <string>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

// The first 3-component array of the point data, else of the cell data (VTK_flow_field_3's
// default velocity); null if there is none.
inline vtkDataArray* first_velocity_array(vtkDataSet* data_set, bool& on_cells)
{
  vtkDataSetAttributes* const data[2] = {data_set->GetPointData(), data_set->GetCellData()};
  for (int d = 0; d < 2; ++d)
    for (int i = 0; i < data[d]->GetNumberOfArrays(); ++i)
      if (vtkDataArray* a = data[d]->GetArray(i); a != nullptr && a->GetNumberOfComponents() == 3) {
        on_cells = d == 1;
        return a;
      }
  return nullptr;
}

// The array named `name` in the point data of `data_set`, else in its cell data (`on_cells`);
// null if neither has it.
inline vtkDataArray* point_or_cell_array(vtkDataSet* data_set, const std::string& name, bool& on_cells)
{
  on_cells = false;
  if (vtkDataArray* a = data_set->GetPointData()->GetArray(name.c_str()))
    return a;
  on_cells = true;
  return data_set->GetCellData()->GetArray(name.c_str());
}

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_VTK_VELOCITY_ARRAY_H
