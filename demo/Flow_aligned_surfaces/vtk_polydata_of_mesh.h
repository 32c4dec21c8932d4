// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A polygon mesh as VTK polydata (its points and polygons, numbered by the vertex and face index
// maps), shared by the demo's renderer (render_surface_PNG.h), its VTP writer
// (write_polydata_VTP.h) and the ParaView plugin's filters.  Needs VTK's CommonCore and
// CommonDataModel.

#ifndef FAS_DEMO_VTK_POLYDATA_OF_MESH_H
#define FAS_DEMO_VTK_POLYDATA_OF_MESH_H

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace fas_demo {

/// `tm` (a model of `FaceListGraph`) as polydata: point i is the vertex of index i in `vim`
/// (positions from `vpm`), polygon j the face of index j in `fim`.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
vtkSmartPointer<vtkPolyData> vtk_polydata_of_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim,
                                                  FaceIndexMap fim)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(num_vertices(tm)));
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    points->SetPoint(vtkIdType(get(vim, v)), CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                     CGAL::to_double(p.z()));
  }
  std::vector<std::vector<vtkIdType>> face_vertices(num_faces(tm));
  for (auto f : faces(tm))
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      face_vertices[get(fim, f)].push_back(vtkIdType(get(vim, v)));
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& fv : face_vertices)
    polys->InsertNextCell(vtkIdType(fv.size()), fv.data());
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetPolys(polys);
  return polydata;
}

} // namespace fas_demo

#endif // FAS_DEMO_VTK_POLYDATA_OF_MESH_H
