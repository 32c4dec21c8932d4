// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An unsteady flow for the main job: a time series of velocity fields (a ParaView collection,
// .pvd, of VTK XML files), behind one type as the demo's steady flows are, with its times, the
// flow at one time, the flow a path surface saw (Path_surface_flow_field_3), and the mean of its
// steps, <v>: where the flow hardly changes in time (a confined wake), |v| looks the same at
// every time, and v - <v> is what shows the unsteadiness.

#ifndef FAS_DEMO_TIME_SERIES_H
#define FAS_DEMO_TIME_SERIES_H

#include "demo_support.h"

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_XML.h>
#include <CGAL/Flow_aligned_surfaces/Path_surface_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unstructured_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>

#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fas_demo {

// Every unsteady flow behind one type, so that the path surfaces are compiled once.
using Unsteady_flow = std::function<std::optional<Vector>(const Point&, double)>;

/// A time series of velocity fields (see the file's comment).
struct Time_series {
  Unsteady_flow flow;        ///< linear in time between the steps, as `Unsteady_flow_field_3`
  Flow mean;                 ///< the mean of the steps (nothing where a step has no flow)
  std::vector<double> times; ///< of the steps, increasing
  CGAL::Bbox_3 box;          ///< the first step's domain

  double start_time() const { return times.front(); }
  double end_time() const { return times.back(); }

  /// The flow at time `t`, a steady flow.
  Flow at(double t) const
  {
    return [flow = flow, t](const Point& p) { return flow(p, t); };
  }
};

/// The times of a run in an unsteady flow: the patches are aligned to the flow at `time`, and
/// what they seed is integrated over [`time`, `time` + `duration`].
struct Unsteady_run {
  Time_series series;
  double time = 0, duration = 0;
};

/// The flow that the path surface `tm` saw: at a point of it, the flow at the time at which the
/// surface passed there, interpolated from the vertex times `time` (Path_surface_flow_field_3).
/// `tm` must outlive the result.
template <class VertexTimeMap>
Flow path_surface_flow(const Unsteady_flow& flow, const Mesh& tm, VertexTimeMap time)
{
  const auto on_surface =
      std::make_shared<const FAS::Path_surface_flow_field_3<Unsteady_flow, Mesh, VertexTimeMap>>(flow, tm,
                                                                                                 time);
  return [on_surface](const Point& p) { return (*on_surface)(p); };
}

namespace detail {

template <class Field>
Time_series make_time_series(const FAS::Unsteady_flow_field_3<Field>& series)
{
  Time_series result;
  for (std::size_t i = 0; i < series.number_of_steps(); ++i)
    result.times.push_back(series.time(i));
  result.box = series.step(0).bbox();
  result.flow = [series](const Point& p, double t) { return series(p, t); };
  result.mean = [series](const Point& p) -> std::optional<Vector> {
    Vector sum = CGAL::NULL_VECTOR;
    for (std::size_t i = 0; i < series.number_of_steps(); ++i) {
      const std::optional<Vector> v = series.step(i)(p);
      if (!v)
        return std::nullopt;
      sum = sum + *v;
    }
    return sum / double(series.number_of_steps());
  };
  return result;
}

} // namespace detail

/// The time series of the collection `file` (.pvd), velocity array `array` (empty: the first
/// vector array): steps on uniform grids (.vti), or else on cells (the other VTK XML data
/// sets); prints the reason and returns nothing when it cannot be read.
inline std::optional<Time_series> read_time_series(const std::string& file, const std::string& array)
{
  std::string error;
  FAS::Unsteady_flow_field_3<FAS::Regular_grid_flow_field_3<Kernel>> grids;
  if (read_with_demo_options([&](const auto& np) { return FAS::IO::read_PVD_flow_field(file, grids, np); },
                             array, error))
    return detail::make_time_series(grids);
  // A step of another kind than ImageData is read as cells; any other failure is the answer.
  if (error.find("a Regular_grid_flow_field_3 is read from") != std::string::npos) {
    error.clear();
    FAS::Unsteady_flow_field_3<FAS::Unstructured_flow_field_3<Kernel>> cells;
    if (read_with_demo_options([&](const auto& np) { return FAS::IO::read_PVD_flow_field(file, cells, np); },
                               array, error))
      return detail::make_time_series(cells);
  }
  std::cerr << "error: " << error << "\n";
  return std::nullopt;
}

} // namespace fas_demo

#endif // FAS_DEMO_TIME_SERIES_H
