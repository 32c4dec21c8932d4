// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The velocity array that VTK_flow_field_3 and make_unstructured_flow_field() take from a VTK
// data set when no name is given.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_VTK_VELOCITY_ARRAY_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_VTK_VELOCITY_ARRAY_H

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

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

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_VTK_VELOCITY_ARRAY_H
