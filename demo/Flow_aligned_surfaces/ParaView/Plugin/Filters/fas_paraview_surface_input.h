// What the filters that work on a given surface share (Parametrize and Seed, Flow Texture):
// input port 0 the data set with the velocity, input port 1 a triangulated surface; the surface
// as a mesh whose vertex i is the surface's point i; vertex values as point arrays.  Private to
// the plugin.
#ifndef FAS_PARAVIEW_SURFACE_INPUT_H
#define FAS_PARAVIEW_SURFACE_INPUT_H

#include "fas_paraview_support.h"

#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkInformationVector.h>

#include <string>
#include <vector>

namespace fas_paraview {

/// Port 0: the flow (any data set, or a composite one); port 1: polygonal data (the surface).
inline int fill_surface_filter_input_port(int port, vtkInformation* info)
{
  if (port == 0)
    accept_flow_inputs(info);
  else
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

/// The surface of input port 1 as a mesh whose vertex i is the surface's point i.
/// \throws std::invalid_argument naming the input and the fault (not polygonal data, no
/// triangles, a point of no triangle).
inline Mesh surface_mesh(vtkPolyData* surface)
{
  if (surface == nullptr)
    throw std::invalid_argument("the Surface input (port 1) is not polygonal data");
  Mesh tm = mesh_from_polydata(surface, "the Surface input (port 1)");
  // Point i is vertex i of the mesh, so a point of no triangle cannot be dropped silently.
  for (Mesh::Vertex_index v : tm.vertices())
    if (tm.is_isolated(v))
      throw std::invalid_argument("the Surface input (port 1): point " + std::to_string(v.idx()) +
                                  " belongs to no triangle; remove such points first (Filters > Clean)");
  return tm;
}

/// Adds the values of a vertex property map of `tm` (vertex i = point i) to `polydata`'s point
/// data as the array `name` of `components` components (`value(v)` gives a double or an array).
template <class Values>
void add_vertex_array(vtkPolyData* polydata, const Mesh& tm, const char* name, int components,
                      const Values& value)
{
  auto array = make_array(name, components, vtkIdType(tm.number_of_vertices()));
  for (Mesh::Vertex_index v : tm.vertices()) {
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(value(v))>>)
      array->SetValue(vtkIdType(v.idx()), value(v));
    else
      for (int c = 0; c < components; ++c)
        array->SetComponent(vtkIdType(v.idx()), c, value(v)[std::size_t(c)]);
  }
  polydata->GetPointData()->AddArray(array);
}

} // namespace fas_paraview

#endif // FAS_PARAVIEW_SURFACE_INPUT_H
