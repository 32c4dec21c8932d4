// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A vtkUnstructuredGrid in memory as the package's own Unstructured_flow_field_3, whose walk and
// hierarchy answer a query faster than VTK's locator and cell functions (VTK_flow_field_3).
// Needs VTK (CommonCore, CommonDataModel): only users of CGAL::Flow_aligned_surfaces_VTK include
// it, never an algorithm header.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_MAKE_UNSTRUCTURED_FLOW_FIELD_H
#define CGAL_FLOW_ALIGNED_SURFACES_MAKE_UNSTRUCTURED_FLOW_FIELD_H

#include <CGAL/Named_function_parameters.h>

#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/internal/VTK_velocity_array.h>
#include <CGAL/Flow_aligned_surfaces/internal/array_names.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

namespace internal {

template <class Real>
std::vector<Real> components_of(vtkDataArray* array)
{
  const vtkIdType n = array->GetNumberOfTuples();
  const int c = array->GetNumberOfComponents();
  std::vector<Real> values(std::size_t(n) * std::size_t(c));
  for (vtkIdType t = 0; t < n; ++t)
    for (int k = 0; k < c; ++k)
      values[std::size_t(t) * std::size_t(c) + std::size_t(k)] = Real(array->GetComponent(t, k));
  return values;
}

// The cells of a vtkUnstructuredGrid as Unstructured_flow_field_3 takes them: voxels as the
// hexahedra they are, the cells a mask marks as solid left out.
template <class Index>
struct Kept_cells {
  std::vector<Index> connectivity, offsets{0};
  std::vector<unsigned char> types;

  // Appends cell `points` of VTK type `type`; false if Unstructured_flow_field_3 has no such
  // type or an index does not fit in `Index`.
  bool add(unsigned char type, vtkIdType size, const vtkIdType* points)
  {
    // A voxel's points go along x, then y, then z; a hexahedron's around each quadrilateral.
    static const int voxel_as_hexahedron[8] = {0, 1, 3, 2, 4, 5, 7, 6};
    const bool voxel = type == VTK_VOXEL;
    if (type != VTK_TETRA && type != VTK_HEXAHEDRON && type != VTK_WEDGE && type != VTK_PYRAMID && !voxel)
      return false;
    for (vtkIdType i = 0; i < size; ++i) {
      const vtkIdType id = points[voxel && size == 8 ? voxel_as_hexahedron[i] : i];
      if (id < 0 || id > vtkIdType(std::numeric_limits<Index>::max()))
        return false;
      connectivity.push_back(Index(id));
    }
    if (connectivity.size() > std::size_t(std::numeric_limits<Index>::max()))
      return false;
    offsets.push_back(Index(connectivity.size()));
    types.push_back(voxel ? (unsigned char)(VTK_HEXAHEDRON) : type);
    return true;
  }
};

// The mask of `grid` as the named parameters give it (the array "inside" by default, none for
// an empty name); null if there is none.
template <class NamedParameters>
vtkDataArray* mask_of(vtkUnstructuredGrid* grid, const NamedParameters& np, bool& on_cells)
{
  const Array_names names = array_names(np);
  const std::string name = names.mask_name() != nullptr ? *names.mask_name() : std::string("inside");
  on_cells = false;
  return name.empty() ? nullptr : point_or_cell_array(grid, name, on_cells);
}

} // namespace internal

/// \ingroup PkgFlowAlignedSurfacesFlows
/// returns the velocity of a `vtkUnstructuredGrid` in memory as an `Unstructured_flow_field_3`,
/// whose queries cost less than those of a `VTK_flow_field_3` over the same grid (on the solver
/// cells of the CYLINDER data, 2 to 6 times less: benchmark/Flow_aligned_surfaces/RESULTS.md,
/// "Sampling fields"), or `std::nullopt` where the grid is not one that field can hold; the
/// header needs VTK and the target `CGAL::Flow_aligned_surfaces_VTK`.
///
/// The arrays are copied: the coordinates in the precision of the grid's points (`float` or
/// `double`; another type as `double`), the cells' point indices as 32-bit indices (a voxel, VTK
/// type 11, as the hexahedron it is), the velocities as `float`.  The samples are those of
/// `VTK_flow_field_3` over the same grid up to the tolerance of VTK's inversion of a
/// hexahedron's map (about 1e-6 of the speed) and at points within VTK's parametric tolerance
/// outside a cell.  A mask (1 component, point or cell data, nonzero = fluid) leaves out the
/// cells where a cell mask is zero and the cells that have a point where a point mask is zero:
/// inside a cell this is the rule of `VTK_flow_field_3` (no sample where the interpolation
/// gives weight to a solid point); on the faces and edges of the cells left out that no kept
/// cell shares, `VTK_flow_field_3` samples where the solid points have no weight, this field
/// does not.
///
/// There is no field (`std::nullopt`) when `data_set` is not a `vtkUnstructuredGrid`, when it has
/// a cell that is not a tetrahedron, hexahedron, voxel, wedge or pyramid (VTK types 10, 11, 12,
/// 13, 14), when the velocity array is missing, cell data or not `VTK_FLOAT` (its values would
/// change), when the mask has not 1 component, when no cell is left, when an index does not fit
/// in 32 bits, or when a coordinate or velocity is not finite.  `VTK_flow_field_3` samples all
/// of these.
///
/// \tparam GeomTraits a model of `Kernel`
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param data_set the data set
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones
///        listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{array_name}
///     \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`),
///       a point array}
///     \cgalParamType{`std::string`}
///     \cgalParamDefault{the first 3-component array of the point data, else of the cell data}
///   \cgalParamNEnd
///   \cgalParamNBegin{mask_array_name}
///     \cgalParamDescription{the name of a 1-component mask array
///       (`FAS::parameters::mask_array_name()`), point or cell data, nonzero = fluid; an empty
///       name asks for no mask}
///     \cgalParamType{`std::string`}
///     \cgalParamDefault{`"inside"` if the data set has it, else no mask}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \sa `VTK_flow_field_3`
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
std::optional<Unstructured_flow_field_3<GeomTraits>>
make_unstructured_flow_field(vtkDataSet* data_set,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using Field = Unstructured_flow_field_3<GeomTraits>;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data_set);
  if (grid == nullptr || grid->GetNumberOfCells() == 0)
    return std::nullopt;
  const internal::Array_names names = internal::array_names(np);
  bool on_cells = false;
  vtkDataArray* velocity = names.array_name() != nullptr
                               ? grid->GetPointData()->GetArray(names.array_name()->c_str())
                               : internal::first_velocity_array(grid, on_cells);
  if (velocity == nullptr || on_cells || velocity->GetNumberOfComponents() != 3 ||
      velocity->GetDataType() != VTK_FLOAT || velocity->GetNumberOfTuples() != grid->GetNumberOfPoints())
    return std::nullopt;
  bool mask_on_cells = false;
  vtkDataArray* mask = internal::mask_of(grid, np, mask_on_cells);
  if (mask != nullptr &&
      (mask->GetNumberOfComponents() != 1 ||
       mask->GetNumberOfTuples() != (mask_on_cells ? grid->GetNumberOfCells() : grid->GetNumberOfPoints())))
    return std::nullopt;

  internal::Kept_cells<typename Field::Index> kept;
  vtkCellArray* cells = grid->GetCells();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    vtkIdType size = 0;
    const vtkIdType* points = nullptr;
    cells->GetCellAtId(c, size, points);
    bool solid = mask != nullptr && mask_on_cells && mask->GetComponent(c, 0) == 0.;
    for (vtkIdType i = 0; mask != nullptr && !mask_on_cells && i < size && !solid; ++i)
      solid = mask->GetComponent(points[i], 0) == 0.;
    if (!solid && !kept.add((unsigned char)(grid->GetCellType(c)), size, points))
      return std::nullopt;
  }
  if (kept.types.empty())
    return std::nullopt;
  std::vector<float> vectors = internal::components_of<float>(velocity);
  vtkDataArray* coordinates = grid->GetPoints()->GetData();
  try {
    if (coordinates->GetDataType() == VTK_FLOAT)
      return Field(internal::components_of<float>(coordinates), std::move(kept.connectivity),
                   std::move(kept.offsets), std::move(kept.types), std::move(vectors));
    return Field(internal::components_of<double>(coordinates), std::move(kept.connectivity),
                 std::move(kept.offsets), std::move(kept.types), std::move(vectors));
  } catch (const std::invalid_argument&) {
    return std::nullopt; // a coordinate or velocity that is not finite, or a malformed cell
  }
}

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_MAKE_UNSTRUCTURED_FLOW_FIELD_H
