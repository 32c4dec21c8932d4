// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// integrate_stream_surface() beside VTK 9.1's vtkStreamSurface (iterative seeding,
// RK45) in the same run, on the ABC flow with C = 0 sampled at 64^3 on [0, 2 pi]^3 (trilinear in
// both), the same seed curve and the same arc length.  The seed curve lies on the level set
// I = A cos z + B sin x = 0.5 of the first integral: x in [1, 2], y = 2 + 2 (x - 1),
// z = acos((0.5 - B sin x) / A).  VTK gets its points at the front spacing h, exactly on the
// level set (its new seeds are interpolated on the front); ours gets the same curve sampled 100
// times finer (its new particles are re-integrated from points of the polyline, whose chords
// are then within ~1e-7 of the level set).  Both advance in arc length (ours:
// arc_length_time_lines) for the same length.  Reported: median wall time of the runs,
// triangles, first-integral drift max |I - 0.5| / 0.5 over the vertices (and the RMS), and the
// normalized flux against the analytic field; and ours on the analytic field, for the drift of
// the integration alone.  x_max, the largest x of a vertex, shows how far each surface got.
//
// Ours also at tolerances 1e-12 (the floor: what the sampled field itself allows) and at the
// stream lines' defaults 1e-8 / 1e-10, with the ratio of each drift to the floor, the ratio of
// VTK's time to each, and the smallest triangle angle.
//
// vtkStreamSurface with iterative seeding was seen to run to the domain's boundary whatever its
// MaximumPropagation (the same surface for 2 and 6), so the default length, 6, takes ours there
// too: both surfaces then end where the flow leaves the grid (the same x_max).
//
//   bench_stream_surface [runs (default 5)] [h (default 0.05)] [length (default 6)]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Surface_mesh.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamSurface.h>
#include <vtkStreamTracer.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

namespace {

const double A = std::sqrt(3.), B = std::sqrt(2.), level = 0.5;

// The seed curve at x in [1, 2].
Point seed_point(double x)
{
  return Point(x, 2 + 2 * (x - 1), std::acos((level - B * std::sin(x)) / A));
}

std::vector<Point> seed_curve(std::size_t segments)
{
  std::vector<Point> seed;
  for (std::size_t i = 0; i <= segments; ++i)
    seed.push_back(seed_point(1 + double(i) / double(segments)));
  return seed;
}

double seed_length()
{
  const std::vector<Point> fine = seed_curve(100000);
  double length = 0;
  for (std::size_t i = 1; i < fine.size(); ++i)
    length += std::sqrt(CGAL::squared_distance(fine[i - 1], fine[i]));
  return length;
}

// A triangle soup, whatever produced it.
struct Soup {
  FAS::internal::Positions positions;
  std::vector<std::array<Eigen::Index, 3>> triangles;
};

struct Row {
  double ms, triangles, max_drift, rms_drift, flux, x_max, min_angle;
};

double smallest_angle(const Soup& soup)
{
  double smallest = 180;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d a = soup.positions.row(t[(k + 1) % 3]) - soup.positions.row(t[k]);
      const Eigen::RowVector3d b = soup.positions.row(t[(k + 2) % 3]) - soup.positions.row(t[k]);
      const double c = a.dot(b) / std::sqrt(a.squaredNorm() * b.squaredNorm());
      smallest = std::min(smallest, std::acos(std::clamp(c, -1., 1.)) * 180 / CGAL_PI);
    }
  return smallest;
}

Row measure(const Soup& soup, double ms)
{
  const FAS::ABC_flow<K> abc(A, B, 0.);
  double max_drift = 0, sum = 0;
  for (Eigen::Index i = 0; i < soup.positions.rows(); ++i) {
    const double d = std::abs(CGAL::to_double(abc.first_integral(
                                  Point(soup.positions(i, 0), soup.positions(i, 1), soup.positions(i, 2)))) -
                              level) /
                     level;
    max_drift = std::max(max_drift, d);
    sum += d * d;
  }
  return {ms,
          double(soup.triangles.size()),
          max_drift,
          std::sqrt(sum / std::max<double>(1, double(soup.positions.rows()))),
          FAS::internal::normalized_flux(soup.positions, soup.triangles, abc, K()).value.value(),
          soup.positions.rows() > 0 ? soup.positions.col(0).maxCoeff() : 0.,
          smallest_angle(soup)};
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class Run>
Row median_of_runs(int runs, const Run& run)
{
  std::vector<double> ms;
  Soup soup;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    soup = run();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return measure(soup, median(ms));
}

} // namespace

int main(int argc, char** argv)
{
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const double h = argc > 2 ? std::atof(argv[2]) : 0.05;
  const double length = argc > 3 ? std::atof(argv[3]) : 6.0;
  const std::size_t n = 64;
  const double spacing = 2 * CGAL_PI / double(n - 1);

  const FAS::ABC_flow<K> abc(A, B, 0.);
  const auto grid = FAS::sample_on_grid(abc, Point(0, 0, 0), Vector(spacing, spacing, spacing), {n, n, n});

  vtkNew<vtkImageData> image;
  image->SetDimensions(int(n), int(n), int(n));
  image->SetOrigin(0, 0, 0);
  image->SetSpacing(spacing, spacing, spacing);
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(vtkIdType(n * n * n));
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const Vector v = *abc(Point(double(i) * spacing, double(j) * spacing, double(k) * spacing));
        velocity->SetTuple3(vtkIdType((k * n + j) * n + i), v.x(), v.y(), v.z());
      }
  image->GetPointData()->SetVectors(velocity);

  const double L = seed_length();
  const std::size_t segments = std::size_t(std::ceil(L / h));
  const std::vector<Point> coarse = seed_curve(segments), fine = seed_curve(100 * segments);

  vtkNew<vtkPoints> seed_points;
  vtkNew<vtkCellArray> seed_line;
  seed_line->InsertNextCell(vtkIdType(coarse.size()));
  for (const Point& p : coarse)
    seed_line->InsertCellPoint(seed_points->InsertNextPoint(p.x(), p.y(), p.z()));
  vtkNew<vtkPolyData> seeds;
  seeds->SetPoints(seed_points);
  seeds->SetLines(seed_line);

  const Row vtk = median_of_runs(runs, [&] {
    vtkNew<vtkStreamSurface> surface;
    surface->SetInputData(image);
    surface->SetSourceData(seeds);
    surface->SetUseIterativeSeeding(true);
    surface->SetIntegratorTypeToRungeKutta45();
    surface->SetIntegrationDirectionToForward();
    surface->SetIntegrationStepUnit(vtkStreamTracer::LENGTH_UNIT);
    surface->SetInitialIntegrationStep(h);
    surface->SetMaximumPropagation(length);
    surface->SetMaximumNumberOfSteps(100000);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(surface->GetOutputPort());
    triangles->Update();
    vtkPolyData* out = triangles->GetOutput();
    Soup soup;
    soup.positions.resize(out->GetNumberOfPoints(), 3);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
      double x[3];
      out->GetPoint(i, x);
      soup.positions.row(i) = Eigen::RowVector3d(x[0], x[1], x[2]);
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
      out->GetCellPoints(c, ids);
      if (ids->GetNumberOfIds() == 3)
        soup.triangles.push_back({ids->GetId(0), ids->GetId(1), ids->GetId(2)});
    }
    return soup;
  });

  // Ours on a field: the sampled grid (the comparison) and the analytic flow (what the
  // integration itself drifts, without the trilinear interpolation's error).
  FAS::Stream_surface_report report;
  const auto ours_with = [&](const auto& field, const auto& np) {
    return median_of_runs(runs, [&] {
      Mesh tm;
      report = FAS::integrate_stream_surface(
          field, fine, tm,
          FAS::parameters::front_spacing(
              h, FAS::parameters::arc_length_time_lines(true, FAS::parameters::max_length(length, np))));
      Soup soup;
      soup.positions.resize(Eigen::Index(tm.number_of_vertices()), 3);
      for (auto v : tm.vertices())
        soup.positions.row(Eigen::Index(v)) =
            Eigen::RowVector3d(tm.point(v).x(), tm.point(v).y(), tm.point(v).z());
      for (auto f : tm.faces()) {
        std::array<Eigen::Index, 3> t;
        int i = 0;
        for (auto v : vertices_around_face(tm.halfedge(f), tm))
          t[i++] = Eigen::Index(v);
        soup.triangles.push_back(t);
      }
      return soup;
    });
  };
  const auto ours_on = [&](const auto& field) { return ours_with(field, CGAL::parameters::default_values()); };
  const auto tolerances = [](double relative, double absolute) {
    return FAS::parameters::relative_tolerance(relative, FAS::parameters::absolute_tolerance(absolute));
  };
  const Row ours_analytic = ours_on(abc);
  const Row ours_cubic = ours_on(grid.with_interpolation(FAS::Grid_interpolation::TRICUBIC));
  const Row at_floor = ours_with(grid, tolerances(1e-12, 1e-12));
  const Row former = ours_with(grid, tolerances(1e-8, 1e-10));
  const Row ours = ours_on(grid); // last, so that `report` is the trilinear grid's

  std::printf("ABC C=0 at %zu^3, seed on I = %.1f (length %.3f), h = %g, length %g, median of %d runs\n", n,
              level, L, h, length, runs);
  std::printf("%-24s %10s %10s %12s %12s %12s %8s %9s %9s %9s\n", "", "time_ms", "triangles", "max_drift",
              "rms_drift", "flux", "x_max", "min_angle", "/floor", "VTK_ms/");
  const auto print = [&](const char* name, const Row& r) {
    std::printf("%-24s %10.1f %10.0f %12.3e %12.3e %12.3e %8.3f %9.2f %9.3f %9.2f\n", name, r.ms, r.triangles,
                r.max_drift, r.rms_drift, r.flux, r.x_max, r.min_angle, r.max_drift / at_floor.max_drift,
                vtk.ms / r.ms);
  };
  print("vtkStreamSurface", vtk);
  print("integrate_stream_surf", ours);
  print("  same, 1e-12 (floor)", at_floor);
  print("  same, 1e-8/1e-10", former);
  print("  same, tricubic grid", ours_cubic);
  print("  same, analytic field", ours_analytic);
  std::printf("ours (trilinear grid): %zu time lines, %zu inserted, %zu removed, %zu tears, %s\n",
              report.number_of_time_lines, report.number_of_inserted_particles,
              report.number_of_removed_particles, report.number_of_tears, report.message.c_str());
  return 0;
}
