// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An unsteady flow for the main job: a time series of velocity fields (a ParaView collection,
// .pvd, of VTK XML files, or a folder of VTK XML files whose names end in their times), behind one type as the demo's steady flows are, with its times, the
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

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
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

namespace detail {

// A VTK XML file of a folder series: PREFIX<time>.EXT.
struct Series_file {
  std::string path, prefix, extension;
  double time;
};

// The VTK XML files of `folder` whose names end in a number (before the extension), sorted by
// it; `error` says why not when there are none or they are of several kinds.
inline std::vector<Series_file> series_files(const std::string& folder, std::string& error)
{
  static const std::regex name(
      "(.*?)([-+]?(?:[0-9]+\\.?[0-9]*|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\\.(vti|vtr|vts|vtu)");
  std::vector<Series_file> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(file, m, name))
      files.push_back({entry.path().string(), m[1], m[3], std::stod(m[2])});
  }
  if (files.empty()) {
    error =
        "--field: " + folder +
        " is a folder without VTK XML files whose names end in their time (NAME_<time>.vti, .vtr, .vts or "
        ".vtu); give such a folder, a time series (.pvd) or a velocity file (legacy VTK .vtk, VTK XML "
        ".vti/.vtr/.vts/.vtu, AmiraMesh .am or NRRD .nrrd/.nhdr)";
    return {};
  }
  std::sort(files.begin(), files.end(), [](const Series_file& a, const Series_file& b) {
    return a.time < b.time || (a.time == b.time && a.path < b.path);
  });
  for (const Series_file& f : files)
    if (f.prefix != files.front().prefix || f.extension != files.front().extension) {
      error = "--field: the folder " + folder + " holds files of two series, " + files.front().prefix +
              "<time>." + files.front().extension + " and " + f.prefix + "<time>." + f.extension +
              "; give a folder of one";
      return {};
    }
  return files;
}

// The series of `files` read as `Field`s.
template <class Field>
std::optional<Time_series> read_series_files(const std::vector<Series_file>& files, const std::string& array,
                                             std::string& error)
{
  std::vector<double> times;
  std::vector<Field> steps;
  for (const Series_file& f : files) {
    steps.emplace_back();
    if (!read_with_demo_options(
            [&](const auto& np) { return FAS::IO::read_VTK_XML_flow_field(f.path, steps.back(), np); }, array,
            error))
      return std::nullopt;
    times.push_back(f.time);
  }
  try {
    return make_time_series(FAS::Unsteady_flow_field_3<Field>(std::move(times), std::move(steps)));
  } catch (const std::invalid_argument& e) { // two files of one time
    error = "--field: the files of the folder " +
            std::filesystem::path(files.front().path).parent_path().string() +
            " do not have distinct times: " + e.what();
    return std::nullopt;
  }
}

} // namespace detail

/// The time series of the VTK XML files of `folder` whose names end in their time
/// (NAME_<time>.vti, .vtr, .vts or .vtu, one name and kind), as ParaView groups a file series:
/// ImageData steps on uniform grids, the others on cells; prints the reason and returns nothing
/// when it cannot be read.
inline std::optional<Time_series> read_time_series_folder(const std::string& folder, const std::string& array)
{
  std::string error;
  const std::vector<detail::Series_file> files = detail::series_files(folder, error);
  std::optional<Time_series> series;
  if (!files.empty())
    series = files.front().extension == "vti"
                 ? detail::read_series_files<FAS::Regular_grid_flow_field_3<Kernel>>(files, array, error)
                 : detail::read_series_files<FAS::Unstructured_flow_field_3<Kernel>>(files, array, error);
  if (!series)
    std::cerr << "error: " << error << "\n";
  return series;
}

} // namespace fas_demo

#endif // FAS_DEMO_TIME_SERIES_H
