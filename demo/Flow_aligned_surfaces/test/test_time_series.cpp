// The main job on a time series (time_series.h, the path surfaces of distinct_stream_surfaces.h,
// the path lines of stream_lines_with_arrays.h, growing_path_surfaces.h) against answers known
// without the code, in the flow v(x, t) = (1, 2t, 0), uniform in space and linear in time (so
// that the grid's trilinear and the series' linear interpolation are exact), written as a .pvd of
// three steps at t = 0, 0.5, 1:
// - a particle released at p at time t0 is at p + (tau, (t0 + tau)^2 - t0^2, 0) at t0 + tau:
//   every vertex of a path surface (and every point of a path line) lies there, from its seed
//   curve (the vertices of time t0);
// - the mean of the steps is (1, 1, 0);
// - steps on cells (.vtu) are read as cells;
// - the path surfaces as they grow: the part swept by a time holds the faces of vertices no
//   later than it, and the collection lists the data's times after the release, then the end.

#include "test_files.h"

#include "distinct_stream_surfaces.h"
#include "growing_path_surfaces.h"
#include "stream_lines_with_arrays.h"
#include "time_series.h"

#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

using namespace fas_demo;
using Polyline = std::vector<Point>;

constexpr double release = 0.25, duration = 0.7;

// Where the particle released at `seed` at time `t0` is at `t0 + tau`.
Point exact_path(const Point& seed, double t0, double tau)
{
  return seed + Vector(tau, (t0 + tau) * (t0 + tau) - t0 * t0, 0);
}

// The flow (1, 2t, 0) at time `t` on a grid over [0, 4] x [-1, 3] x [-1, 1].
FAS::Regular_grid_flow_field_3<Kernel> step_at(double t)
{
  const std::array<std::size_t, 3> n{{9, 9, 5}};
  std::vector<float> values;
  for (std::size_t i = 0; i < n[0] * n[1] * n[2]; ++i)
    values.insert(values.end(), {1.0f, float(2 * t), 0.0f});
  return FAS::Regular_grid_flow_field_3<Kernel>(Point(0, -1, -1), 0.5, 0.5, 0.5, n, values);
}

// A .pvd of the steps at t = 0, 0.5, 1, in a folder of its own; returns its path.
std::string write_series(const std::string& name)
{
  const std::filesystem::path folder = temporary_file("time_series_", name);
  std::filesystem::create_directories(folder);
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int k = 0; k < 3; ++k) {
    const std::string file = "step_" + std::to_string(k) + ".vti";
    std::string error;
    EXPECT_TRUE(FAS::IO::write_VTI_flow_field((folder / file).string(), step_at(0.5 * k),
                                              FAS::parameters::error_message(&error)))
        << error;
    pvd += "<DataSet timestep=\"" + std::to_string(0.5 * k) + "\" file=\"" + file + "\"/>\n";
  }
  write_bytes((folder / "series.pvd").string(), pvd + "</Collection>\n</VTKFile>\n");
  return (folder / "series.pvd").string();
}

// The distance of `p` to the polyline `curve`.
double distance_to(const Polyline& curve, const Point& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < curve.size(); ++i)
    best = std::min(best, std::sqrt(CGAL::squared_distance(p, Kernel::Segment_3(curve[i], curve[i + 1]))));
  return best;
}

TEST(TimeSeries, PathSurfacesAndLinesFollowTheExactPathLines)
{
  const std::optional<Time_series> series = read_time_series(write_series("exact"), "");
  ASSERT_TRUE(series);
  EXPECT_EQ(series->times, (std::vector<double>{0, 0.5, 1}));
  const Polyline seed{Point(0.5, 0, -0.4), Point(0.6, 0.1, 0), Point(0.5, 0.2, 0.4)};
  const auto surfaces = integrate_distinct_path_surfaces<Mesh>(
      series->flow, std::vector<Polyline>{seed, seed}, 0.05, release, duration);
  EXPECT_EQ(surfaces.number_of_surfaces(), 1u) << "the same seed curve twice is one surface";
  const Mesh& tm = surfaces.mesh;
  ASSERT_GT(tm.number_of_faces(), 50u);
  const auto t = tm.property_map<Mesh::Vertex_index, double>("v:t").first;
  const auto time = tm.property_map<Mesh::Vertex_index, double>("v:time").first;
  double largest_error = 0, last = 0;
  for (Mesh::Vertex_index v : tm.vertices()) {
    EXPECT_DOUBLE_EQ(time[v], release + t[v]);
    // Back along its exact path line to the release, the vertex is on the seed curve.
    const Point p = tm.point(v);
    const Point start = exact_path(p, release + t[v], -t[v]);
    largest_error = std::max(largest_error, distance_to(seed, start));
    last = std::max(last, t[v]);
  }
  EXPECT_LT(largest_error, 1e-6);
  EXPECT_NEAR(last, duration, 1e-12);

  const std::vector<Point> points{Point(0.5, 0, 0), Point(1, 0.5, 0.2)};
  const Stream_lines<Point> lines = integrate_path_lines(series->flow, points, release, duration);
  ASSERT_EQ(lines.lines.size(), 2u);
  std::size_t k = 0;
  for (std::size_t i = 0; i < lines.lines.size(); ++i)
    for (const Point& p : lines.lines[i]) {
      const double tau = lines.integration_time[k];
      EXPECT_LT(std::sqrt(CGAL::squared_distance(p, exact_path(points[i], release, tau))), 1e-6);
      EXPECT_NEAR(lines.velocity[3 * k + 1], 2 * (release + tau), 1e-6) << "v_y at the point's time";
      ++k;
    }
  EXPECT_EQ(lines.integration_time.front(), 0);
}

TEST(TimeSeries, MeanIsTheMeanOfTheSteps)
{
  const std::optional<Time_series> series = read_time_series(write_series("mean"), "");
  ASSERT_TRUE(series);
  const std::optional<Vector> mean = series->mean(Point(1, 1, 0));
  ASSERT_TRUE(mean);
  EXPECT_NEAR(mean->x(), 1, 1e-12);
  EXPECT_NEAR(mean->y(), 1, 1e-12);
  EXPECT_FALSE(series->mean(Point(10, 0, 0))) << "outside the grid";
  const std::optional<Vector> at = series->at(0.75)(Point(1, 1, 0));
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->y(), 1.5, 1e-12);
}

TEST(TimeSeries, StepsOnCellsAreReadAsCells)
{
  // One hexahedron [0, 1]^3 at t = 0 and t = 2 with the flow (1, t, 0).
  const std::filesystem::path folder = temporary_file("time_series_", "cells");
  std::filesystem::create_directories(folder);
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int k = 0; k < 2; ++k) {
    std::string velocity;
    for (int i = 0; i < 8; ++i)
      velocity += "1 " + std::to_string(2 * k) + " 0 ";
    write_bytes(
        (folder / ("step_" + std::to_string(k) + ".vtu")).string(),
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>\n"
        "<Piece NumberOfPoints=\"8\" NumberOfCells=\"1\">\n"
        "<PointData><DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" "
        "format=\"ascii\">" +
            velocity +
            "</DataArray></PointData>\n"
            "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
            "0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1</DataArray></Points>\n"
            "<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4 5 6 7"
            "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">8</DataArray>"
            "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">12</DataArray></Cells>\n"
            "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    pvd +=
        "<DataSet timestep=\"" + std::to_string(2 * k) + "\" file=\"step_" + std::to_string(k) + ".vtu\"/>\n";
  }
  write_bytes((folder / "series.pvd").string(), pvd + "</Collection>\n</VTKFile>\n");
  const std::optional<Time_series> series = read_time_series((folder / "series.pvd").string(), "");
  ASSERT_TRUE(series);
  const std::optional<Vector> v = series->flow(Point(0.5, 0.5, 0.5), 0.5);
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->y(), 0.5, 1e-12);
}

TEST(TimeSeries, GrowingPathSurfacesListTheDataTimes)
{
  const std::optional<Time_series> series = read_time_series(write_series("growing"), "");
  ASSERT_TRUE(series);
  const Polyline seed{Point(0.5, 0, -0.4), Point(0.5, 0, 0.4)};
  const auto surfaces = integrate_distinct_path_surfaces<Mesh>(series->flow, std::vector<Polyline>{seed},
                                                               0.05, release, duration);
  const Mesh& tm = surfaces.mesh;
  const auto time = tm.property_map<Mesh::Vertex_index, double>("v:time").first;
  std::vector<double> vertex_time;
  for (Mesh::Vertex_index v : tm.vertices())
    vertex_time.push_back(time[v]);
  const std::vector<FAS::IO::Data_array> point_data{{"time", 1, vertex_time}};
  const std::vector<FAS::IO::Data_array> cell_data{{"face", 1, std::vector<double>(tm.number_of_faces(), 7)}};

  std::size_t before = 0;
  for (double t : {0.5, 0.8, release + duration}) {
    const Surface_part part = part_swept_by(tm, vertex_time, t, point_data, cell_data);
    EXPECT_GT(part.mesh.number_of_faces(), before) << t;
    before = part.mesh.number_of_faces();
    ASSERT_EQ(part.point_data[0].values.size(), part.mesh.number_of_vertices());
    ASSERT_EQ(part.cell_data[0].values.size(), part.mesh.number_of_faces());
    for (double vt : part.point_data[0].values)
      EXPECT_LE(vt, t);
    for (Mesh::Vertex_index v : part.mesh.vertices()) // each vertex where the exact path line is at its time
      EXPECT_LT(distance_to(seed, exact_path(part.mesh.point(v), part.point_data[0].values[v.idx()],
                                             release - part.point_data[0].values[v.idx()])),
                1e-6);
  }
  EXPECT_EQ(before, tm.number_of_faces()) << "at the end, the whole surface";

  const std::filesystem::path out = temporary_file("time_series_", "growing_out");
  std::filesystem::create_directories(out);
  std::string error;
  ASSERT_TRUE(write_growing_path_surfaces(out, "run", tm, vertex_time, point_data, cell_data, series->times,
                                          release, release + duration, error))
      << error;
  const std::string pvd = read_bytes((out / "run_path_surfaces.pvd").string());
  const std::regex entry(
      "timestep=\"([^\"]+)\" group=\"\" part=\"0\" file=\"(run_path_surfaces/run_[0-9]+\\.vtp)\"");
  std::vector<double> listed;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry); it != std::sregex_iterator(); ++it) {
    listed.push_back(std::stod((*it)[1]));
    EXPECT_TRUE(std::filesystem::exists(out / std::string((*it)[2])));
  }
  EXPECT_EQ(listed, (std::vector<double>{0.5, release + duration}));
}

} // namespace
