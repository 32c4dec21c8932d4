// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A model of `FlowField_3` over any vtkDataSet and one of its 3-component arrays: the cell that
// contains a point is found by a vtkStaticCellLocator, a point array is interpolated with that
// cell's interpolation functions (its weights), a cell array gives the cell's value; outside
// every cell, or where an optional mask array is 0, there is no sample (std::nullopt).
// Needs VTK (CommonCore, CommonDataModel): only users of CGAL::Flow_aligned_surfaces_VTK
// include it, never an algorithm header.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_VTK_FLOW_FIELD_3_H
#define CGAL_FLOW_ALIGNED_SURFACES_VTK_FLOW_FIELD_3_H

#include <CGAL/Bbox_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <CGAL/Flow_aligned_surfaces/internal/VTK_velocity_array.h>
#include <CGAL/Flow_aligned_surfaces/internal/array_names.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <vtkAbstractCellLocator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {

/// \ingroup PkgFlowAlignedSurfacesFlows
/// A velocity field given by a 3-component array of any VTK data set (`vtkImageData`,
/// `vtkRectilinearGrid`, `vtkStructuredGrid`, `vtkUnstructuredGrid`, ...), interpolated as VTK
/// interpolates it, a model of `FlowField_3`; the header needs VTK and the target
/// `CGAL::Flow_aligned_surfaces_VTK`.
///
/// The cell containing a point is found by a `vtkStaticCellLocator` built over the data set
/// (VTK's own test `vtkCell::EvaluatePosition()`, which counts points on a cell's faces as
/// inside, and for some cell types, tetrahedra among them, points up to a small parametric
/// tolerance outside too).  The value there is:
/// - for a *point* array, the array interpolated with the cell's interpolation functions (the
///   weights VTK computes for the point): trilinear in the voxels of a `vtkImageData`, which
///   gives what `Regular_grid_flow_field_3` gives on the same node values; linear in
///   tetrahedra, so a linear field given at the points of a tetrahedral mesh is reproduced
///   exactly; isoparametric in hexahedra, wedges, pyramids and higher-order cells;
/// - for a *cell* array, the value of the containing cell (constant per cell).
///
/// There is no sample (`std::nullopt`) where no cell contains the point, and where the mask says
/// so.  The cells that hold a volume are the 3D ones: a data set of surfaces or lines (a slice, a
/// `vtkPolyData`) is accepted but contains hardly any point, so it gives hardly any sample.  The mask is an optional 1-component array (point or cell data, any numeric type),
/// nonzero = fluid, zero = solid: a cell mask removes the cells where it is zero; with a point
/// mask, a point is outside when its interpolation gives a nonzero weight to a point where the
/// mask is zero (the rule of `Regular_grid_flow_field_3`'s node mask).  By default, the array
/// named `"inside"` is the mask if the data set has one (as the package's writers and its test
/// data name it), and there is no mask otherwise.
///
/// The data set, the locator and the arrays are held by `vtkSmartPointer`: copies share them,
/// so copying a field is cheap, and the field keeps the data set alive.  The data set must not
/// be modified while a field over it is in use (the locator would be stale).  `operator()` is
/// `const` and safe to call from several threads at once (`parameters::use_parallelism(true)`):
/// it uses the thread-safe `FindCell()` overload of `vtkStaticCellLocator` with a
/// `vtkGenericCell` and a weight buffer per thread (`thread_local`, allocated on a thread's first
/// query), and the constructor makes the data set's cell access thread-safe as VTK asks (a first
/// `GetCell()` from one thread).  Values are read in `double`; a non-finite value is returned as
/// it is (the algorithms treat it as no sample and count it).
///
/// A query costs what VTK's locator and cell functions cost: on the solver cells of the
/// CYLINDER data 2 to 6 times an `Unstructured_flow_field_3` query, on an image 57 to 107
/// times a `Regular_grid_flow_field_3` query on the same samples (which finds the voxel by
/// arithmetic; benchmark/Flow_aligned_surfaces/RESULTS.md, "Sampling fields").  For a `vtkImageData`, a
/// `Regular_grid_flow_field_3` of its array gives the same samples faster; for a
/// `vtkUnstructuredGrid` of the linear 3D cells, `make_unstructured_flow_field()` gives an
/// `Unstructured_flow_field_3`.
///
/// \tparam GeomTraits a model of `Kernel`; the coordinates are converted to `double` with
///         `CGAL::to_double()`.
///
/// \cgalModels `FlowField_3`
///
/// \sa `Regular_grid_flow_field_3`, `Unstructured_flow_field_3`, `make_unstructured_flow_field()`
template <typename GeomTraits>
class VTK_flow_field_3 {
public:
  /// \name Types
  /// @{

  /// The geometric traits.
  typedef GeomTraits Geom_traits;
  /// The number type.
  typedef typename GeomTraits::FT FT;
  /// The point type.
  typedef typename GeomTraits::Point_3 Point_3;
  /// The vector type.
  typedef typename GeomTraits::Vector_3 Vector_3;
  /// @}

  /// \name Creation
  /// @{

  /// creates the field over `data_set` and builds its cell locator.
  ///
  /// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
  ///
  /// \param data_set the data set, with at least one cell
  /// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the
  ///        ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{array_name}
  ///     \cgalParamDescription{the name of the velocity array (`FAS::parameters::array_name()`),
  ///       looked for in the point data, then in the cell data}
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
  /// \throws std::invalid_argument naming the data set (its VTK class and sizes) and the array,
  ///         if `data_set` is null or has no cell, if the velocity array is missing or does not
  ///         have 3 components, or if a mask was named that is missing or does not have 1
  ///         component.
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit VTK_flow_field_3(vtkDataSet* data_set,
                            const NamedParameters& np = CGAL::parameters::default_values())
  {
    if (data_set == nullptr)
      fail("the data set is null");
    m_data_set = data_set;
    if (data_set->GetNumberOfCells() == 0)
      fail(describe() + " has no cells; expected at least one cell to interpolate in");
    const internal::Array_names names = internal::array_names(np);
    find_velocity(names.array_name());
    find_mask(names.mask_name());

    // VTK: GetCell(id, vtkGenericCell*) is thread-safe once called from a single thread.
    vtkNew<vtkGenericCell> cell;
    data_set->GetCell(0, cell);
    double bounds[6];
    data_set->GetBounds(bounds);
    m_bbox = Bbox_3(bounds[0], bounds[2], bounds[4], bounds[1], bounds[3], bounds[5]);
    m_max_cell_size = static_cast<std::size_t>(data_set->GetMaxCellSize());

    m_locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    m_locator->SetDataSet(data_set);
    m_locator->BuildLocator();
  }

  /// @}

  /// \name Evaluation
  /// @{

  /// returns the velocity at `p`, or `std::nullopt` if no cell contains `p` or the mask marks
  /// it as solid.
  std::optional<Vector_3> operator()(const Point_3& p) const
  {
    double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    // Written so that NaN coordinates fail too (the locator would bin them).
    if (!(x[0] >= m_bbox.xmin() && x[0] <= m_bbox.xmax() && x[1] >= m_bbox.ymin() && x[1] <= m_bbox.ymax() &&
          x[2] >= m_bbox.zmin() && x[2] <= m_bbox.zmax()))
      return std::nullopt;
    Scratch& s = scratch(m_max_cell_size);
    double pcoords[3];
    // Through the base class: the overload without `subId` is declared there in VTK 9.1 and
    // 9.2 (ParaView 5.11's), where a subclass may hide it.
    vtkAbstractCellLocator* const locator = m_locator;
    const vtkIdType c = locator->FindCell(x, 0., s.cell, pcoords, s.weights.data());
    if (c < 0)
      return std::nullopt;
    double r[3] = {0., 0., 0.};
    if (m_mask != nullptr && m_mask_on_cells && m_mask->GetComponent(c, 0) == 0.)
      return std::nullopt;
    if (m_mask != nullptr && !m_mask_on_cells) {
      const vtkIdType n = s.cell->GetNumberOfPoints();
      for (vtkIdType i = 0; i < n; ++i)
        if (s.weights[std::size_t(i)] != 0. && m_mask->GetComponent(s.cell->GetPointId(i), 0) == 0.)
          return std::nullopt;
    }
    if (m_on_cells)
      m_velocity->GetTuple(c, r);
    else {
      const vtkIdType n = s.cell->GetNumberOfPoints();
      double v[3];
      for (vtkIdType i = 0; i < n; ++i) {
        const double w = s.weights[std::size_t(i)];
        m_velocity->GetTuple(s.cell->GetPointId(i), v);
        for (int d = 0; d < 3; ++d)
          r[d] += w * v[d];
      }
    }
    return Vector_3(FT(r[0]), FT(r[1]), FT(r[2]));
  }

  /// @}

  /// \name Access
  /// @{

  /// the data set
  vtkDataSet* data_set() const { return m_data_set; }
  /// the velocity array
  vtkDataArray* velocity_array() const { return m_velocity; }
  /// whether the velocity array is cell data (else it is point data)
  bool velocity_on_cells() const { return m_on_cells; }
  /// the mask array, or null if there is none
  vtkDataArray* mask_array() const { return m_mask; }
  /// the bounding box of the data set
  Bbox_3 bbox() const { return m_bbox; }

  /// @}

private:
  struct Scratch {
    vtkSmartPointer<vtkGenericCell> cell = vtkSmartPointer<vtkGenericCell>::New();
    std::vector<double> weights;
  };

  // The per-thread cell and weights that FindCell() fills; any field may use them, as each
  // query fills them before it reads them.
  static Scratch& scratch(std::size_t max_cell_size)
  {
    thread_local Scratch s;
    if (s.weights.size() < max_cell_size)
      s.weights.resize(max_cell_size);
    return s;
  }

  [[noreturn]] static void fail(const std::string& what)
  {
    throw std::invalid_argument("VTK_flow_field_3: " + what);
  }

  std::string describe() const
  {
    return "the data set (" + std::string(m_data_set->GetClassName()) + ", " +
           std::to_string(m_data_set->GetNumberOfPoints()) + " points, " +
           std::to_string(m_data_set->GetNumberOfCells()) + " cells)";
  }

  // The names of the arrays with `components` components (every array, with its number of
  // components, when `components` is 0), for the messages.
  std::string arrays_with(int components) const
  {
    std::string list;
    vtkDataSetAttributes* const data[2] = {m_data_set->GetPointData(), m_data_set->GetCellData()};
    for (int d = 0; d < 2; ++d)
      for (int i = 0; i < data[d]->GetNumberOfArrays(); ++i) {
        vtkDataArray* a = data[d]->GetArray(i);
        if (a == nullptr || (components != 0 && a->GetNumberOfComponents() != components))
          continue;
        list += std::string(list.empty() ? "" : ", ") + "'" + (a->GetName() ? a->GetName() : "") + "' (" +
                (d == 0 ? "point data" : "cell data") +
                (components == 0 ? ", " + std::to_string(a->GetNumberOfComponents()) + " components)" : ")");
      }
    return list.empty() ? std::string("none") : list;
  }

  void find_velocity(const std::string* name)
  {
    if (name != nullptr) {
      m_velocity = internal::point_or_cell_array(m_data_set, *name, m_on_cells);
      if (m_velocity == nullptr)
        fail(describe() + " has no array named '" + *name + "'; its 3-component arrays: " + arrays_with(3));
      if (m_velocity->GetNumberOfComponents() != 3)
        fail("the array '" + *name + "' of " + describe() + " has " +
             std::to_string(m_velocity->GetNumberOfComponents()) +
             " components; expected 3 (a velocity); its 3-component arrays: " + arrays_with(3));
      check_size(m_velocity, *name, m_on_cells);
      return;
    }
    m_velocity = internal::first_velocity_array(m_data_set, m_on_cells);
    if (m_velocity != nullptr) {
      check_size(m_velocity, m_velocity->GetName() ? m_velocity->GetName() : "", m_on_cells);
      return;
    }
    fail(describe() + " has no 3-component point or cell array; expected a velocity array; its arrays: " +
         arrays_with(0));
  }

  void find_mask(const std::string* name)
  {
    const bool named = name != nullptr;
    const std::string mask_name = named ? *name : std::string("inside");
    if (mask_name.empty())
      return; // no mask asked for
    m_mask = internal::point_or_cell_array(m_data_set, mask_name, m_mask_on_cells);
    if (m_mask == nullptr) {
      if (named)
        fail(describe() + " has no mask array named '" + mask_name + "'; its 1-component arrays: " +
             arrays_with(1));
      return;
    }
    if (m_mask->GetNumberOfComponents() != 1)
      fail("the mask array '" + mask_name + "' of " + describe() + " has " +
           std::to_string(m_mask->GetNumberOfComponents()) + " components; expected 1 (nonzero = fluid)");
    check_size(m_mask, mask_name, m_mask_on_cells);
  }

  // An attribute array need not have as many tuples as its data set has points or cells.
  void check_size(vtkDataArray* a, const std::string& name, bool on_cells) const
  {
    const vtkIdType expected = on_cells ? m_data_set->GetNumberOfCells() : m_data_set->GetNumberOfPoints();
    if (a->GetNumberOfTuples() != expected)
      fail("the array '" + name + "' of " + describe() + " has " + std::to_string(a->GetNumberOfTuples()) +
           " tuples; expected " + std::to_string(expected) + " (one per " + (on_cells ? "cell" : "point") + ")");
  }

  vtkSmartPointer<vtkDataSet> m_data_set;
  vtkSmartPointer<vtkStaticCellLocator> m_locator;
  vtkSmartPointer<vtkDataArray> m_velocity;
  vtkSmartPointer<vtkDataArray> m_mask;
  bool m_on_cells = false;
  bool m_mask_on_cells = false;
  std::size_t m_max_cell_size = 0;
  Bbox_3 m_bbox;
};

} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_VTK_FLOW_FIELD_3_H
