// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A surface mesh with per-vertex and per-face data arrays, or polylines with per-point and
// per-line arrays, as a VTK XML PolyData file (.vtp, ASCII), which ParaView and VTK open.  CGAL's own write_VTP needs
// the VTK library and writes no data arrays; this writer needs neither.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_VTP_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_VTP_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/error_output.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/write_file_atomically.h>
#include <CGAL/Flow_aligned_surfaces/parameters.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \ingroup PkgFlowAlignedSurfacesIO
/// A named data array attached to the vertices or faces of a mesh: `values` holds
/// `number_of_components` values per vertex (or face), in the order of the vertex (face) index map.
struct Data_array {
  std::string name;             ///< the array's name, as ParaView shows it
  int number_of_components = 1; ///< 1 for scalars, 3 for vectors
  std::vector<double> values;   ///< `number_of_components` values per element
  /// Point data only: the array is the texture coordinates (2 components), flagged `TCoords`
  /// so that ParaView's "Texture" property and VTK's `GetTCoords()` use it.
  bool texture_coordinates = false;
};

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Checks that every array of `point_data` has `number_of_components` values per point and
every array of `cell_data` as many per cell, as `write_VTP()` and `write_VTP_polylines()` do
before they write: a program that writes the same arrays by other means (VTK's own writers)
refuses the same arrays with the same message.

\param point_data arrays with one tuple per point
\param number_of_points the number of points
\param cell_data arrays with one tuple per cell
\param number_of_cells the number of cells (faces or polylines)
\param reason receives, on failure, the first array of the wrong size, its size and the one
       expected

\returns `true` if every array has its size and at least one component.
*/
inline bool check_VTP_array_sizes(const std::vector<Data_array>& point_data, std::size_t number_of_points,
                                  const std::vector<Data_array>& cell_data, std::size_t number_of_cells,
                                  std::string& reason)
{
  for (const auto* arrays : {&point_data, &cell_data})
    for (const Data_array& a : *arrays) {
      const std::size_t expected =
          std::size_t(a.number_of_components) * (arrays == &point_data ? number_of_points : number_of_cells);
      if (a.number_of_components < 1 || a.values.size() != expected) {
        reason = "array '" + a.name + "' has " + std::to_string(a.values.size()) + " values, expected " +
                 std::to_string(expected);
        return false;
      }
    }
  return true;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// Non-finite values as VTK reads them.
inline void write_VTP_value(std::ostream& os, double x)
{
  if (std::isfinite(x))
    os << x;
  else
    os << (std::isnan(x) ? "NaN" : (x > 0 ? "Infinity" : "-Infinity"));
}

inline void write_VTP_data_arrays(std::ostream& os, const std::vector<Data_array>& arrays)
{
  for (const Data_array& a : arrays) {
    os << "        <DataArray type=\"Float64\" Name=\"" << a.name << "\" NumberOfComponents=\""
       << a.number_of_components << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < a.values.size(); ++i) {
      write_VTP_value(os, a.values[i]);
      os << ((i + 1) % std::size_t(a.number_of_components) == 0 ? '\n' : ' ');
    }
    os << "        </DataArray>\n";
  }
}

// The file's head up to the opening of the points' coordinates.
inline void write_VTP_head(std::ostream& os, std::size_t points, std::size_t lines, std::size_t polys)
{
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n"
     << "  <PolyData>\n"
     << "    <Piece NumberOfPoints=\"" << points << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << lines
     << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << polys << "\">\n"
     << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
        "format=\"ascii\">\n";
}

// The point and cell data and the file's tail.
inline void write_VTP_tail(std::ostream& os, const std::vector<Data_array>& point_data,
                           const std::vector<Data_array>& cell_data)
{
  os << "      <PointData";
  for (const Data_array& a : point_data)
    if (a.texture_coordinates) { // the array ParaView's "Texture" property maps
      os << " TCoords=\"" << a.name << "\"";
      break;
    }
  os << ">\n";
  write_VTP_data_arrays(os, point_data);
  os << "      </PointData>\n      <CellData>\n";
  write_VTP_data_arrays(os, cell_data);
  os << "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Writes `tm` with optional per-vertex and per-face arrays to `filename` as a VTK XML
PolyData file (ASCII `.vtp`).

The file is first written beside `filename` and renamed over it only when complete, so an
existing file is never left half-written.  Non-finite values are written as `NaN`, which
VTK reads as such.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam NamedParameters a sequence of named parameters

\param filename the output file
\param tm the mesh (any polygon mesh; faces keep their degree)
\param point_data arrays with one tuple per vertex, in the order of the vertex index map; the
       first one with `texture_coordinates` set is flagged as the texture coordinates
\param cell_data arrays with one tuple per face, in the order of the face index map
\param np optional named parameters: `vertex_point_map`, `vertex_index_map`, `face_index_map`
       as in `normalized_flux()`, `stream_precision` (the number of significant digits, default 17)
       and `error_message` (where the reason of a failure goes, `FAS::parameters::error_message()`;
       default: no message)

\returns `true` on success; `false` if an array has the wrong size or the file could not be
written, with the reason in the string of `error_message` when it is given.

\sa `check_VTP_array_sizes()`
*/
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
bool write_VTP(const std::string& filename, const TriangleMesh& tm,
               const std::vector<Data_array>& point_data = {}, const std::vector<Data_array>& cell_data = {},
               const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);

  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  std::string* const error = internal::error_output(np);
  auto fail = [&](const std::string& reason) {
    if (error)
      *error = "write_VTP: " + filename + ": " + reason;
    return false;
  };
  std::string reason;
  if (!check_VTP_array_sizes(point_data, nv, cell_data, nf, reason))
    return fail(reason);

  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> ordered_vertices(nv);
  for (auto v : vertices(tm))
    ordered_vertices[get(vim, v)] = v;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> ordered_faces(nf);
  for (auto f : faces(tm))
    ordered_faces[get(fim, f)] = f;

  const bool written = internal::write_file_atomically(filename, reason, [&](std::ostream& os) {
    os.precision(precision);
    internal::write_VTP_head(os, nv, 0, nf);
    for (auto v : ordered_vertices) {
      const auto& p = get(vpm, v);
      os << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z()) << '\n';
    }
    os << "        </DataArray>\n      </Points>\n      <Polys>\n"
       << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    std::vector<std::size_t> offsets;
    offsets.reserve(nf);
    std::size_t offset = 0;
    for (auto f : ordered_faces) {
      for (auto v : vertices_around_face(halfedge(f, tm), tm)) {
        os << get(vim, v) << ' ';
        ++offset;
      }
      os << '\n';
      offsets.push_back(offset);
    }
    os << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t o : offsets)
      os << o << '\n';
    os << "        </DataArray>\n      </Polys>\n";
    internal::write_VTP_tail(os, point_data, cell_data);
  });
  return written ? true : fail(reason);
}

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Writes polylines (stream lines, seed curves) with optional per-point and per-line arrays
to `filename` as a VTK XML PolyData file (ASCII `.vtp`) of `Lines` cells, one per polyline.

The points are numbered polyline after polyline, in order; `point_data` arrays follow that
order, `cell_data` arrays have one tuple per polyline.  Written atomically as `write_VTP()`.

\tparam Polyline a range of points of a CGAL kernel (`std::vector<Point_3>`)
\tparam NamedParameters a sequence of named parameters

\param filename the output file
\param polylines the polylines (an empty one gives a line without points)
\param point_data arrays with one tuple per point, in the order above
\param cell_data arrays with one tuple per polyline
\param np optional named parameters: `stream_precision` (the number of significant digits,
       default 17) and `error_message` (where the reason of a failure goes,
       `FAS::parameters::error_message()`; default: no message)

\returns `true` on success; `false` if an array has the wrong size or the file could not be
written, with the reason in the string of `error_message` when it is given.
\sa `write_VTP()`, `check_VTP_array_sizes()`, `integrate_streamline()`
*/
template <class Polyline, class NamedParameters = parameters::Default_named_parameters>
bool write_VTP_polylines(const std::string& filename, const std::vector<Polyline>& polylines,
                         const std::vector<Data_array>& point_data = {},
                         const std::vector<Data_array>& cell_data = {},
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), 17);
  std::size_t points = 0;
  for (const Polyline& line : polylines)
    points += std::size_t(std::distance(line.begin(), line.end()));
  std::string reason;
  const bool written =
      check_VTP_array_sizes(point_data, points, cell_data, polylines.size(), reason) &&
      internal::write_file_atomically(filename, reason, [&](std::ostream& os) {
        os.precision(precision);
        internal::write_VTP_head(os, points, polylines.size(), 0);
        for (const Polyline& line : polylines)
          for (const auto& p : line)
            os << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z())
               << '\n';
        os << "        </DataArray>\n      </Points>\n      <Lines>\n"
           << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < points; ++i)
          os << i << '\n';
        os << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
        std::size_t offset = 0;
        for (const Polyline& line : polylines) {
          offset += std::size_t(std::distance(line.begin(), line.end()));
          os << offset << '\n';
        }
        os << "        </DataArray>\n      </Lines>\n";
        internal::write_VTP_tail(os, point_data, cell_data);
      });
  std::string* const error = internal::error_output(np);
  if (!written && error)
    *error = "write_VTP_polylines: " + filename + ": " + reason;
  return written;
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_WRITE_VTP_H
