// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's VTP files (a surface mesh, or polylines, with point and cell arrays), written through
// VTK's vtkXMLPolyDataWriter, binary and zlib-compressed, with the array that ParaView colours by
// flagged as the active scalars.  The binary data are inline (base64 in each DataArray), not
// appended: ParaView 5.11's VTK cannot parse appended data with the expat of an up-to-date
// Debian bookworm, and every VTK reads inline data.  That needs VTK's XML
// I/O (the package's target CGAL::Flow_aligned_surfaces_VTK defines
// CGAL_FLOW_ALIGNED_SURFACES_USE_VTK); a demo program built without it writes the same arrays
// through the package's own writer, as ASCII, without the active-scalars flag.  Either way the
// file is written beside its name and renamed over it when complete.

#ifndef FAS_DEMO_WRITE_POLYDATA_VTP_H
#define FAS_DEMO_WRITE_POLYDATA_VTP_H

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>

#include <CGAL/boost/graph/iterator.h>

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkZLibDataCompressor.h>

#include "vtk_polydata_of_mesh.h"
#include "write_then_rename.h"
#endif

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace fas_demo {

/// Which arrays a VTP file flags as active: the names of a point array and of a cell array
/// (empty: none).  ParaView colours a new source by its active scalars.
struct Active_scalars {
  std::string point_array;
  std::string cell_array;
};

/// Whether this build writes VTP through VTK (binary, inline, compressed) rather than ASCII.
constexpr bool writes_binary_VTP()
{
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
  return true;
#else
  return false;
#endif
}

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
namespace detail {

inline void add_VTK_arrays(vtkDataSetAttributes* attributes,
                           const std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array>& arrays,
                           std::size_t number_of_tuples, const std::string& active)
{
  for (const auto& a : arrays) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(a.name.c_str());
    array->SetNumberOfComponents(a.number_of_components);
    array->SetNumberOfTuples(vtkIdType(number_of_tuples));
    for (std::size_t i = 0; i < a.values.size(); ++i)
      array->SetValue(vtkIdType(i), a.values[i]);
    attributes->AddArray(array);
    if (a.texture_coordinates)
      attributes->SetActiveTCoords(a.name.c_str());
  }
  if (!active.empty())
    attributes->SetActiveScalars(active.c_str());
}

// Writes `polydata` to `filename` (beside it first, then renamed over it).
inline bool write_VTK_polydata(const std::string& filename, vtkPolyData* polydata, std::string& reason)
{
  return write_then_rename(filename, reason, [&](const std::string& temporary) {
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetFileName(temporary.c_str());
    writer->SetInputData(polydata);
    writer->SetDataModeToBinary(); // inline: readable by ParaView 5.11 whatever the expat
    writer->SetCompressor(vtkSmartPointer<vtkZLibDataCompressor>::New());
    if (writer->Write() == 1)
      return true;
    reason = "VTK's XML writer could not write " + temporary;
    return false;
  });
}

} // namespace detail
#endif

/// Writes `tm` with `point_data` (one tuple per vertex, in the order of the vertex index map) and
/// `cell_data` (one per face) to `filename`; `error` receives the reason of a failure.
template <class TriangleMesh>
bool write_mesh_VTP(const std::string& filename, const TriangleMesh& tm,
                    const std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array>& point_data,
                    const std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array>& cell_data,
                    const Active_scalars& active, std::string* error)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
  std::string reason;
  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  bool ok = FAS::IO::check_VTP_array_sizes(point_data, nv, cell_data, nf, reason);
  if (ok) {
    const vtkSmartPointer<vtkPolyData> polydata = vtk_polydata_of_mesh(
        tm, get(CGAL::vertex_point, tm), get(CGAL::vertex_index, tm), get(CGAL::face_index, tm));
    detail::add_VTK_arrays(polydata->GetPointData(), point_data, nv, active.point_array);
    detail::add_VTK_arrays(polydata->GetCellData(), cell_data, nf, active.cell_array);
    ok = detail::write_VTK_polydata(filename, polydata, reason);
  }
  if (!ok && error)
    *error = "write_mesh_VTP: " + filename + ": " + reason;
  return ok;
#else
  (void)active;
  return FAS::IO::write_VTP(filename, tm, point_data, cell_data, FAS::parameters::error_message(error));
#endif
}

/// Writes `polylines` as one line cell each, with `point_data` (one tuple per point, polyline
/// after polyline) and `cell_data` (one per polyline) to `filename`.
template <class Polyline>
bool write_polylines_VTP(const std::string& filename, const std::vector<Polyline>& polylines,
                         const std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array>& point_data,
                         const std::vector<CGAL::Flow_aligned_surfaces::IO::Data_array>& cell_data,
                         const Active_scalars& active, std::string* error)
{
  namespace FAS = CGAL::Flow_aligned_surfaces;
#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_VTK
  std::string reason;
  std::size_t np = 0;
  for (const Polyline& line : polylines)
    np += line.size();
  bool ok = FAS::IO::check_VTP_array_sizes(point_data, np, cell_data, polylines.size(), reason);
  if (ok) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (const Polyline& line : polylines) {
      std::vector<vtkIdType> ids;
      for (const auto& p : line)
        ids.push_back(points->InsertNextPoint(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                              CGAL::to_double(p.z())));
      lines->InsertNextCell(vtkIdType(ids.size()), ids.data());
    }
    auto polydata = vtkSmartPointer<vtkPolyData>::New();
    polydata->SetPoints(points);
    polydata->SetLines(lines);
    detail::add_VTK_arrays(polydata->GetPointData(), point_data, np, active.point_array);
    detail::add_VTK_arrays(polydata->GetCellData(), cell_data, polylines.size(), active.cell_array);
    ok = detail::write_VTK_polydata(filename, polydata, reason);
  }
  if (!ok && error)
    *error = "write_polylines_VTP: " + filename + ": " + reason;
  return ok;
#else
  (void)active;
  return FAS::IO::write_VTP_polylines(filename, polylines, point_data, cell_data,
                                      FAS::parameters::error_message(error));
#endif
}

} // namespace fas_demo

#endif // FAS_DEMO_WRITE_POLYDATA_VTP_H
