// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surfaces that the seed curves of an aligned surface start, as the main job integrates
// them: stream surfaces in a steady flow (forward and backward, arc-length time lines), path
// surfaces in an unsteady one (released at the run's time, forward over its duration), one per
// distinct seed curve (distinct_stream_surfaces.h); with the flow each saw (the steady flow, or
// for path surfaces the flow at the time their particles passed, Path_surface_flow_field_3, so
// that their flux and their LIC-like texture are measured against their path lines) and their
// point data under the names of the plugin's Stream Surface From Curve.

#ifndef FAS_DEMO_SEEDED_SURFACES_H
#define FAS_DEMO_SEEDED_SURFACES_H

#include "demo_support.h"
#include "distinct_stream_surfaces.h"
#include "time_series.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_VTP.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fas_demo {

/// See the file's comment.  Neither copied nor moved: the path surfaces' flow refers to the mesh.
struct Seeded_surfaces {
  using Polyline = std::vector<Point>;

  /// The surfaces of `seed_curves` in `flow` (path surfaces when `unsteady` is given) with front
  /// spacing `spacing`; stream surfaces reach `max_length` each way.
  Seeded_surfaces(const Flow& flow, const std::optional<Unsteady_run>& unsteady,
                  const std::vector<Polyline>& seed_curves, double spacing, double max_length)
      : path_surfaces(bool(unsteady)),
        integrated(unsteady
                       ? integrate_distinct_path_surfaces<Mesh>(unsteady->series.flow, seed_curves, spacing,
                                                                unsteady->time, unsteady->duration)
                       : integrate_distinct_stream_surfaces<Mesh>(flow, seed_curves, spacing, max_length)),
        flow(flow)
  {
    if (!unsteady)
      return;
    const Mesh& tm = integrated.mesh;
    const auto time = tm.property_map<Mesh::Vertex_index, double>("v:time").first;
    for (Mesh::Vertex_index v : tm.vertices()) {
      const std::optional<Vector> saw = unsteady->series.flow(tm.point(v), time[v]),
                                  mean = unsteady->series.mean(tm.point(v));
      deviation.push_back(saw && mean ? std::sqrt((*saw - *mean).squared_length())
                                      : std::numeric_limits<double>::quiet_NaN());
    }
    if (tm.number_of_faces() > 0)
      this->flow = path_surface_flow(unsteady->series.flow, tm, time);
  }
  Seeded_surfaces(const Seeded_surfaces&) = delete;
  Seeded_surfaces& operator=(const Seeded_surfaces&) = delete;

  const Mesh& mesh() const { return integrated.mesh; }
  /// The files' and pictures' name for them.
  std::string kind() const { return path_surfaces ? "path_surfaces" : "stream_surfaces"; }

  /// The point data (the plugin's names): the velocity they saw, u, t and SeedIds; path surfaces
  /// also IntegrationTime (t, as ParaView's ParticlePath names it), their time and the deviation
  /// |v - <v>| of the flow they saw from the time mean.
  std::vector<FAS::IO::Data_array> point_data() const
  {
    const Mesh& tm = mesh();
    std::vector<FAS::IO::Data_array> arrays{{"velocity", 3, vertex_velocities(tm, flow)}};
    std::vector<std::pair<const char*, const char*>> maps{{"u", "v:u"}, {"t", "v:t"}, {"SeedIds", "v:seed"}};
    if (path_surfaces)
      maps.insert(maps.end(), {{"IntegrationTime", "v:t"}, {"time", "v:time"}});
    for (const auto& [name, map] : maps) {
      const auto values = tm.property_map<Mesh::Vertex_index, double>(map).first;
      arrays.push_back({name, 1, {}});
      for (Mesh::Vertex_index v : tm.vertices())
        arrays.back().values.push_back(values[v]);
    }
    if (path_surfaces)
      arrays.push_back({"velocity_deviation", 1, deviation});
    return arrays;
  }

  const bool path_surfaces;
  const Distinct_stream_surfaces<Mesh> integrated;
  Flow flow;                     ///< the flow they saw (see the file's comment)
  std::vector<double> deviation; ///< path surfaces: |v - <v>| per vertex (NaN where either is undefined)
};

} // namespace fas_demo

#endif // FAS_DEMO_SEEDED_SURFACES_H
