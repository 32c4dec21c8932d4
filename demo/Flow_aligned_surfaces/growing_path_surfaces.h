// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Path surfaces as they grow, for ParaView's time controls: at each time step of the data after
// the release and before the end of the integration (and at that end), the part of the surfaces that
// their particles had swept by then (the faces whose three vertices have times no later), with
// its point and cell data, as a collection NAME_path_surfaces.pvd whose time steps are the
// data's times (surface_collection.h).  Played with the data, the surface grows where the flow
// of the shown time carries it.

#ifndef FAS_DEMO_GROWING_PATH_SURFACES_H
#define FAS_DEMO_GROWING_PATH_SURFACES_H

#include "demo_support.h"
#include "surface_collection.h"
#include "write_polydata_VTP.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace fas_demo {

/// A part of a mesh with its data arrays (see `part_swept_by()`).
struct Surface_part {
  Mesh mesh;
  std::vector<FAS::IO::Data_array> point_data, cell_data;
};

/// The faces of `tm` whose vertices all have a `time` (by vertex index) of at most `t`, as a mesh
/// of their own, with `point_data` and `cell_data` (by vertex and face index) restricted to them.
inline Surface_part part_swept_by(const Mesh& tm, const std::vector<double>& time, double t,
                                  const std::vector<FAS::IO::Data_array>& point_data,
                                  const std::vector<FAS::IO::Data_array>& cell_data)
{
  Surface_part part;
  for (const auto& a : point_data)
    part.point_data.push_back({a.name, a.number_of_components, {}, a.texture_coordinates});
  for (const auto& a : cell_data)
    part.cell_data.push_back({a.name, a.number_of_components, {}, a.texture_coordinates});
  const auto copy_values = [](std::vector<FAS::IO::Data_array>& to,
                              const std::vector<FAS::IO::Data_array>& from, std::size_t index) {
    for (std::size_t a = 0; a < from.size(); ++a) {
      const std::size_t n = std::size_t(from[a].number_of_components);
      to[a].values.insert(to[a].values.end(), from[a].values.begin() + std::ptrdiff_t(n * index),
                          from[a].values.begin() + std::ptrdiff_t(n * (index + 1)));
    }
  };
  const Mesh::Vertex_index none;
  std::vector<Mesh::Vertex_index> in_part(tm.number_of_vertices(), none);
  for (Mesh::Face_index f : tm.faces()) {
    std::vector<Mesh::Vertex_index> corners;
    for (Mesh::Vertex_index v : vertices_around_face(tm.halfedge(f), tm))
      corners.push_back(v);
    if (std::any_of(corners.begin(), corners.end(), [&](Mesh::Vertex_index v) { return time[v.idx()] > t; }))
      continue;
    for (Mesh::Vertex_index& v : corners) {
      if (in_part[v.idx()] == none) {
        in_part[v.idx()] = part.mesh.add_vertex(tm.point(v));
        copy_values(part.point_data, point_data, v.idx());
      }
      v = in_part[v.idx()];
    }
    part.mesh.add_face(corners);
    copy_values(part.cell_data, cell_data, f.idx());
  }
  return part;
}

/// Writes the collection NAME_path_surfaces.pvd of the path surfaces `tm` (see the file's
/// comment): the parts swept by each of the data's `times` within ]`start`, `end`[ and by
/// `end`, with the arrays of `tm`; `vertex_time` is the time of each vertex.  Returns
/// false with the reason in `error` when a file cannot be written.
inline bool write_growing_path_surfaces(const std::filesystem::path& out, const std::string& name,
                                        const Mesh& tm, const std::vector<double>& vertex_time,
                                        const std::vector<FAS::IO::Data_array>& point_data,
                                        const std::vector<FAS::IO::Data_array>& cell_data,
                                        const std::vector<double>& times, double start, double end,
                                        std::string& error)
{
  std::vector<double> shown; // nothing is swept at the release yet
  for (double t : times)
    if (t > start && t < end)
      shown.push_back(t);
  shown.push_back(end);
  Surface_collection collection(out, name, "path_surfaces");
  for (double t : shown) {
    const Surface_part part = part_swept_by(tm, vertex_time, t, point_data, cell_data);
    const auto write = [&](const std::filesystem::path& path) {
      return write_mesh_VTP(path.string(), part.mesh, part.point_data, part.cell_data,
                            Active_scalars{"time", ""}, &error);
    };
    if (!collection.add(write, t))
      break;
  }
  if (collection.write_pvd())
    return true;
  if (error.empty())
    error = collection.error();
  return false;
}

} // namespace fas_demo

#endif // FAS_DEMO_GROWING_PATH_SURFACES_H
