// What the plugin's filters share: the velocity field of a VTK data set as a FlowField_3, the
// conversions between CGAL meshes or polylines and vtkPolyData, and the outputs kept for a
// failed run.  Private to the plugin.
#ifndef FAS_PARAVIEW_SUPPORT_H
#define FAS_PARAVIEW_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/VTK_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/make_unstructured_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>

#include "fas_flow_input.h"
#include "vtk_polydata_of_mesh.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <sstream>
#include <variant>
#include <vector>

namespace fas_paraview {

namespace FAS = CGAL::Flow_aligned_surfaces;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyline = std::vector<Point>;

/// The velocity of a VTK data set as a `FlowField_3`: point data of an image is copied into a
/// `Regular_grid_flow_field_3` (the same trilinear samples, 57-107 times faster than a cell
/// locator), float point data of an unstructured grid of tetrahedra, hexahedra, wedges and
/// pyramids into an `Unstructured_flow_field_3` (2-6 times faster; benchmark/.../RESULTS.md,
/// "Sampling fields"), every other case samples the data set through `VTK_flow_field_3`.  Safe to
/// call concurrently.
class Velocity_field {
public:
  Velocity_field() = default;
  Velocity_field(FAS::Regular_grid_flow_field_3<Kernel> grid) : m_field(std::move(grid)) {}
  Velocity_field(FAS::Unstructured_flow_field_3<Kernel> cells) : m_field(std::move(cells)) {}
  Velocity_field(FAS::VTK_flow_field_3<Kernel> cells) : m_field(std::move(cells)) {}

  std::optional<Vector> operator()(const Point& p) const
  {
    return std::visit([&p](const auto& f) { return f(p); }, m_field);
  }

  /// Whether `p` is in the interior of one of the cells of an unstructured mesh
  /// (`Unstructured_flow_field_3::is_in_cell_interior()`): no other piece of the mesh holds it.
  /// False for the other fields.
  bool is_in_cell_interior(const Point& p) const
  {
    const auto* cells = std::get_if<FAS::Unstructured_flow_field_3<Kernel>>(&m_field);
    return cells != nullptr && cells->is_in_cell_interior(p);
  }

private:
  std::variant<FAS::Regular_grid_flow_field_3<Kernel>, FAS::Unstructured_flow_field_3<Kernel>,
               FAS::VTK_flow_field_3<Kernel>>
      m_field;
};

/// The message for a *Velocity* property that names an array `data_set` does not have, with the
/// arrays it has.  In pvpython this happens when a filter of two inputs is created with keyword
/// inputs only: paraview.simple first connects the active source to port 0, and the selector takes
/// its default from that source's arrays before the keywords change the inputs.
inline std::string missing_velocity_message(vtkDataSet* data_set, const std::string& array_name)
{
  std::string arrays;
  auto list = [&arrays](vtkFieldData* data, const char* where) {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
      vtkDataArray* array = data->GetArray(a);
      if (array == nullptr || array->GetNumberOfComponents() != 3 || array->GetName() == nullptr)
        continue;
      arrays += (arrays.empty() ? "'" : ", '") + std::string(array->GetName()) + "' (" + where + ")";
    }
  };
  list(data_set->GetPointData(), "point data");
  list(data_set->GetCellData(), "cell data");
  return "the property Velocity is '" + array_name + "', an array the input does not have; its " +
         "3-component arrays: " + (arrays.empty() ? std::string("none") : arrays) +
         " (in pvpython, give the flow data first, e.g. ParametrizeAndSeed(reader, Surface=surface):" +
         " created with keyword inputs only, a filter takes its Velocity from the active source)";
}

/// The velocity field of `data_set`'s array `selection` (the first 3-component array when its
/// name is empty; a cell array is sampled per cell, see `with_selected_association()`).  An image that is a piece of a larger one (`whole_extent`, from the pipeline;
/// null: the image is whole) samples bit for bit as the whole image would, so that its pieces on
/// several ranks give the serial samples.  \throws std::invalid_argument naming the data set and
/// the array.
inline Velocity_field make_velocity_field(vtkDataSet* data_set, const Velocity_selection& selection,
                                          const int* whole_extent = nullptr)
{
  if (data_set == nullptr)
    throw std::invalid_argument("the input is not a data set (vtkDataSet)");
  auto* image = vtkImageData::SafeDownCast(data_set);
  const std::string& array_name = selection.name;
  vtkDataArray* points_array = array_name.empty() || selection.on_cells()
                                   ? nullptr
                                   : data_set->GetPointData()->GetArray(array_name.c_str());
  if (image != nullptr && points_array != nullptr && points_array->GetNumberOfComponents() == 3) {
    int dims[3];
    image->GetDimensions(dims);
    const double* spacing = image->GetSpacing();
    const double* direction = image->GetDirectionMatrix()->GetData();
    const bool axis_aligned = direction[0] == 1 && direction[4] == 1 && direction[8] == 1;
    if (axis_aligned && dims[0] >= 2 && dims[1] >= 2 && dims[2] >= 2) {
      // Node (0, 0, 0) of the whole image, at its extent's first index; this piece is the block
      // of the whole image's nodes from its own extent's first index on.
      int extent[6];
      image->GetExtent(extent);
      const int* whole = whole_extent != nullptr ? whole_extent : extent;
      const double* image_origin = image->GetOrigin();
      double origin[3];
      FAS::Regular_grid_flow_field_3<Kernel>::Dimensions grid_dimensions, first, dimensions;
      for (int d = 0; d < 3; ++d) {
        origin[d] = image_origin[d] + whole[2 * d] * spacing[d];
        grid_dimensions[std::size_t(d)] = std::size_t(whole[2 * d + 1] - whole[2 * d] + 1);
        first[std::size_t(d)] = std::size_t(extent[2 * d] - whole[2 * d]);
        dimensions[std::size_t(d)] = std::size_t(dims[d]);
      }
      const vtkIdType n = points_array->GetNumberOfTuples();
      std::vector<float> values(std::size_t(3 * n));
      for (vtkIdType i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
          values[std::size_t(3 * i + c)] = float(points_array->GetComponent(i, c));
      std::vector<unsigned char> mask;
      if (vtkDataArray* inside = data_set->GetPointData()->GetArray("inside");
          inside != nullptr && inside->GetNumberOfComponents() == 1) {
        mask.resize(std::size_t(n));
        for (vtkIdType i = 0; i < n; ++i)
          mask[std::size_t(i)] = inside->GetComponent(i, 0) != 0. ? 1 : 0;
      }
      return Velocity_field(FAS::Regular_grid_flow_field_3<Kernel>::block(
          Point(origin[0], origin[1], origin[2]), Vector(spacing[0], spacing[1], spacing[2]),
          grid_dimensions, first, dimensions, std::move(values), std::move(mask)));
    }
  }
  if (array_name.empty()) {
    if (auto cells = FAS::make_unstructured_flow_field<Kernel>(data_set))
      return Velocity_field(std::move(*cells));
    return Velocity_field(FAS::VTK_flow_field_3<Kernel>(data_set));
  }
  if (data_set->GetPointData()->GetArray(array_name.c_str()) == nullptr &&
      data_set->GetCellData()->GetArray(array_name.c_str()) == nullptr)
    throw std::invalid_argument(missing_velocity_message(data_set, array_name));
  const vtkSmartPointer<vtkDataSet> sampled = with_selected_association(data_set, selection);
  if (auto cells = FAS::make_unstructured_flow_field<Kernel>(sampled, FAS::parameters::array_name(array_name)))
    return Velocity_field(std::move(*cells));
  return Velocity_field(FAS::VTK_flow_field_3<Kernel>(sampled, FAS::parameters::array_name(array_name)));
}

/// `tm` as polygonal data (points in vertex index order, one triangle per face), as the demo
/// writes and renders its surfaces.
inline vtkSmartPointer<vtkPolyData> to_polydata(const Mesh& tm)
{
  return fas_demo::vtk_polydata_of_mesh(tm, tm.points(), get(CGAL::vertex_index, tm), get(CGAL::face_index, tm));
}

/// The triangles of `polydata` as a mesh (vertex i = point i).  \throws std::invalid_argument
/// naming `what` if it has no triangle, a polygon that is not a triangle, or is not a manifold
/// surface.
inline Mesh mesh_from_polydata(vtkPolyData* polydata, const std::string& what)
{
  if (polydata == nullptr || polydata->GetNumberOfPolys() == 0)
    throw std::invalid_argument(what + " has no polygons; expected a triangulated surface");
  Mesh tm;
  for (vtkIdType i = 0; i < polydata->GetNumberOfPoints(); ++i) {
    double x[3];
    polydata->GetPoint(i, x);
    tm.add_vertex(Point(x[0], x[1], x[2]));
  }
  vtkCellArray* polys = polydata->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  polys->InitTraversal();
  while (polys->GetNextCell(ids)) {
    if (ids->GetNumberOfIds() != 3)
      throw std::invalid_argument(what + " has a polygon with " + std::to_string(ids->GetNumberOfIds()) +
                                  " points; triangulate it first (Filters > Triangulate)");
    const Mesh::Face_index f = tm.add_face(Mesh::Vertex_index(Mesh::size_type(ids->GetId(0))),
                                           Mesh::Vertex_index(Mesh::size_type(ids->GetId(1))),
                                           Mesh::Vertex_index(Mesh::size_type(ids->GetId(2))));
    if (f == Mesh::null_face())
      throw std::invalid_argument(what + " is not a manifold, consistently oriented triangle surface");
  }
  return tm;
}

/// The lines and polylines of `polydata`, each as a list of points.
inline std::vector<Polyline> polylines_from_polydata(vtkPolyData* polydata)
{
  std::vector<Polyline> polylines;
  if (polydata == nullptr)
    return polylines;
  vtkCellArray* lines = polydata->GetLines();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  lines->InitTraversal();
  while (lines->GetNextCell(ids)) {
    Polyline polyline;
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i) {
      double x[3];
      polydata->GetPoint(ids->GetId(i), x);
      polyline.emplace_back(x[0], x[1], x[2]);
    }
    if (polyline.size() >= 2)
      polylines.push_back(std::move(polyline));
  }
  return polylines;
}

/// A named array of `components` doubles per tuple.
inline vtkSmartPointer<vtkDoubleArray> make_array(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// Adds the one-value array `name` = `value` to `data`'s field data.
inline void add_field_value(vtkDataObject* data, const char* name, double value)
{
  auto array = make_array(name, 1, 1);
  array->SetValue(0, value);
  data->GetFieldData()->AddArray(array);
}

/// The velocities at `points`: in one batch when the field answers batches (its `sample()`, as
/// `Distributed_velocity_field`), else point by point.  Call with 0 as the last argument.
template <class Field>
auto velocities_at(const Field& field, const std::vector<Point>& points, int) -> decltype(field.sample(points))
{
  return field.sample(points);
}
template <class Field>
std::vector<std::optional<Vector>> velocities_at(const Field& field, const std::vector<Point>& points, long)
{
  std::vector<std::optional<Vector>> velocities;
  for (const Point& p : points)
    velocities.push_back(field(p));
  return velocities;
}

/// The velocity at every point of `polydata`, as the point array `velocity` (zero where the
/// field has no sample) and `velocity_sampled` (1 where it has one).
template <class Field>
void add_point_velocities(vtkPolyData* polydata, const Field& field)
{
  const vtkIdType n = polydata->GetNumberOfPoints();
  auto velocity = make_array("velocity", 3, n);
  auto sampled = make_array("velocity_sampled", 1, n);
  std::vector<Point> points;
  for (vtkIdType i = 0; i < n; ++i) {
    double x[3];
    polydata->GetPoint(i, x);
    points.emplace_back(x[0], x[1], x[2]);
  }
  const std::vector<std::optional<Vector>> velocities = velocities_at(field, points, 0);
  for (vtkIdType i = 0; i < n; ++i) {
    const std::optional<Vector>& v = velocities[std::size_t(i)];
    velocity->SetTuple3(i, v ? v->x() : 0., v ? v->y() : 0., v ? v->z() : 0.);
    sampled->SetValue(i, v ? 1. : 0.);
  }
  polydata->GetPointData()->AddArray(velocity);
  polydata->GetPointData()->SetActiveVectors("velocity");
  polydata->GetPointData()->AddArray(sampled);
}

/// After Abort: clears the request.  The outputs keep what the filter kept, as VTK 9.2's
/// executive stamps them up to date (a Modified() inside RequestData comes before that stamp): the
/// next change of a property, of the input or of the time step asked for computes them anew.
inline void abort_handled(vtkAlgorithm* filter)
{
  filter->SetAbortExecute(0);
}

inline void require_property(bool in_range, const char* label, double value, const char* range)
{
  if (in_range)
    return;
  std::ostringstream os;
  os << "the property " << label << " is " << value << "; it must be " << range;
  throw std::invalid_argument(os.str());
}

/// The paper's alignment parameters as the panels name them (Flow-Aligned Surface, Grow Boundary).
/// \throws std::invalid_argument naming the first one out of its range.
inline void require_alignment_properties(double eta, double theta_max, double epsilon, int iterations)
{
  const double pi = 3.141592653589793;
  require_property(eta > 0 && eta <= pi, "Max Rotation Angle", eta, "in (0, pi] radians (0.1 as in the paper)");
  require_property(theta_max > 0 && theta_max <= pi, "Max Dihedral Angle", theta_max,
                   "in (0, pi] radians (pi/2 as in the paper)");
  require_property(epsilon >= 0, "Convergence Angle", epsilon, ">= 0 radians (1e-6 as in the paper)");
  require_property(iterations >= 0 && iterations <= 100000, "Number Of Iterations", iterations, "from 0 to 100,000");
}

/// Bounds (xmin, xmax, ymin, ymax, zmin, zmax) in words, for messages ("x a..b, y c..d, z e..f").
inline std::string bounds_text(const double b[6])
{
  std::ostringstream os;
  os << "x " << b[0] << ".." << b[1] << ", y " << b[2] << ".." << b[3] << ", z " << b[4] << ".." << b[5];
  return os.str();
}

/// The arrays of an aligned surface `tm` shown as `polydata` (its points in vertex index order,
/// its triangles in face index order, as `to_polydata()` makes them): point data `velocity` and
/// `velocity_sampled`, cell data `normalized_flux` (|n.v|/|v| per face, -1 where the field has no
/// sample), field data `normalized_flux` (absent when no face has a sample) and
/// `sampled_area_fraction`.  Returns the surface's normalized flux.
template <class Field>
FAS::Normalized_flux add_alignment_arrays(vtkPolyData* polydata, Mesh& tm, const Field& field)
{
  add_point_velocities(polydata, field);
  auto face_flux = make_array("normalized_flux", 1, vtkIdType(tm.number_of_faces()));
  auto flux_map = tm.add_property_map<Mesh::Face_index, double>("f:fas_paraview_flux", -1.).first;
  FAS::compute_face_normalized_flux(tm, field, flux_map);
  // NaN where the face has no flow sample (the library's -1): ParaView shows it in the NaN
  // colour and leaves it out of the colour range.
  for (Mesh::Face_index f : tm.faces())
    face_flux->SetValue(vtkIdType(f.idx()),
                        flux_map[f] < 0 ? std::numeric_limits<double>::quiet_NaN() : flux_map[f]);
  tm.remove_property_map(flux_map);
  polydata->GetCellData()->AddArray(face_flux);
  polydata->GetCellData()->SetActiveScalars("normalized_flux");

  const FAS::Normalized_flux flux = FAS::normalized_flux(tm, field);
  if (flux.value)
    add_field_value(polydata, "normalized_flux", *flux.value);
  add_field_value(polydata, "sampled_area_fraction", flux.sampled_area_fraction);
  return flux;
}

/// The warning for an aligned surface of which more than 5% of the area has no flow sample, or
/// an empty string.
inline std::string unsampled_area_warning(const FAS::Normalized_flux& flux)
{
  if (flux.sampled_area_fraction >= 0.95)
    return std::string();
  std::ostringstream os;
  os << 100. * (1. - flux.sampled_area_fraction)
     << "% of the surface's area has no flow sample (it reaches out of the data): that part is not aligned; "
        "move the surface or make it smaller";
  return os.str();
}

/// The outputs of the last successful run, given again when a run fails.
class Kept_outputs {
public:
  /// Remembers the outputs of `outputVector` (after a successful run).
  void keep(vtkInformationVector* outputVector)
  {
    m_outputs.clear();
    for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port) {
      vtkDataObject* output = vtkDataObject::GetData(outputVector, port);
      vtkSmartPointer<vtkDataObject> copy;
      if (output != nullptr) {
        copy.TakeReference(output->NewInstance());
        copy->ShallowCopy(output);
      }
      m_outputs.push_back(copy);
    }
  }

  /// Gives the kept outputs again; returns whether there were any.
  bool restore(vtkInformationVector* outputVector) const
  {
    if (m_outputs.empty())
      return false;
    for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
      if (vtkDataObject* output = vtkDataObject::GetData(outputVector, port);
          output != nullptr && std::size_t(port) < m_outputs.size() && m_outputs[std::size_t(port)])
        output->ShallowCopy(m_outputs[std::size_t(port)]);
    return true;
  }

private:
  std::vector<vtkSmartPointer<vtkDataObject>> m_outputs;
};

} // namespace fas_paraview

#endif // FAS_PARAVIEW_SUPPORT_H
