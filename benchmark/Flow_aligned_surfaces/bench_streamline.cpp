// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// integrate_streamline() beside VTK's vtkStreamTracer (RK45) in the same run.  The ABC
// flow with C = 0, v = (A sin z, B sin x + A cos z, B cos x), A = √3, B = √2, is sampled on a
// n³ grid over [0, 2π]³ (n = 64 unless given); VTK traces through a vtkImageData holding the very same float samples,
// ours through Regular_grid_flow_field_3.  Same seeds (pseudo-random in [0.5, 2π - 0.5]³, fixed
// generator), same maximum length, forward.  Per tracer: median process CPU time and wall time
// over the runs of tracing every seed, the number of points, and the drift of the first integral
// I = A cos z + B sin x along each line, max_p |I(p) - I(seed)| / (A + B) (median and max over
// the lines), and the deviation: the largest distance of a line's points to the same line
// integrated at tolerance 1e-12 (median over the lines).  I is exact for the analytic flow only:
// the drift on the grid includes the interpolation's error, the deviation does not; the drift of
// ours on the analytic flow is printed too.  Plain main().
//
// The interpolation floor is the drift of the reference lines themselves: what no tracer of the
// grid's samples goes below.
//
//   bench_streamline [number_of_seeds (100)] [max_length (10)] [runs (7)] [grid nodes per axis (64)]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>

#ifdef FAS_HAVE_VTK_FLOW_PATHS
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStreamTracer.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
namespace FAS = CGAL::Flow_aligned_surfaces;

namespace {

const double A = std::sqrt(3.), B = std::sqrt(2.);
double first_integral(double x, double z)
{
  return A * std::cos(z) + B * std::sin(x);
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0. : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

struct Figures {
  double time_ms = 0, wall_ms = 0, median_drift = 0, max_drift = 0, mean_length = 0, median_deviation = 0;
  std::size_t points = 0;
  std::string reasons; // termination reasons and counts
};

using Line = std::vector<std::array<double, 3>>;

// The distance from p to the polyline `line` (brute force over its segments).
double distance_to_polyline(const std::array<double, 3>& p, const Line& line)
{
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    double d[3], w[3], dd = 0, dw = 0;
    for (int k = 0; k < 3; ++k) {
      d[k] = line[i + 1][k] - line[i][k];
      w[k] = p[k] - line[i][k];
      dd += d[k] * d[k];
      dw += d[k] * w[k];
    }
    const double t = dd > 0 ? std::clamp(dw / dd, 0., 1.) : 0.;
    double e = 0;
    for (int k = 0; k < 3; ++k)
      e += (w[k] - t * d[k]) * (w[k] - t * d[k]);
    best = std::min(best, e);
  }
  return std::sqrt(best);
}

// Drift of one line given as points; the first point is the seed.
double line_drift(const std::vector<std::array<double, 3>>& line)
{
  double worst = 0;
  for (const auto& p : line)
    worst = std::max(worst, std::abs(first_integral(p[0], p[2]) - first_integral(line[0][0], line[0][2])));
  return worst / (A + B);
}

double line_length(const std::vector<std::array<double, 3>>& line)
{
  double s = 0;
  for (std::size_t i = 1; i < line.size(); ++i)
    s += std::sqrt((line[i][0] - line[i - 1][0]) * (line[i][0] - line[i - 1][0]) +
                   (line[i][1] - line[i - 1][1]) * (line[i][1] - line[i - 1][1]) +
                   (line[i][2] - line[i - 1][2]) * (line[i][2] - line[i - 1][2]));
  return s;
}

// `reference`: the same lines at a tight tolerance; the deviation of a line is the largest
// distance of its points to its reference (its integration error, free of the interpolation's).
Figures summarize(const std::vector<Line>& lines, const std::vector<double>& times,
                  const std::vector<double>& wall, const std::vector<Line>* reference)
{
  Figures f;
  f.time_ms = median(times);
  f.wall_ms = median(wall);
  std::vector<double> drifts, deviations;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Line& line = lines[i];
    if (line.empty())
      continue;
    drifts.push_back(line_drift(line));
    if (reference) {
      double worst = 0;
      for (const auto& p : line)
        worst = std::max(worst, distance_to_polyline(p, (*reference)[i]));
      deviations.push_back(worst);
    }
    f.mean_length += line_length(line) / double(lines.size());
    f.points += line.size();
  }
  f.median_drift = median(drifts);
  f.median_deviation = median(deviations);
  f.max_drift = drifts.empty() ? 0. : *std::max_element(drifts.begin(), drifts.end());
  return f;
}

// The process CPU time of f (all threads: VTK may trace seeds in parallel), in ms; the wall time
// is added to `wall`.  On a loaded machine the CPU time is the steadier figure.
double cpu_ms(const std::function<void()>& f, std::vector<double>& wall)
{
  timespec a, b;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &a);
  const auto start = std::chrono::steady_clock::now();
  f();
  wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &b);
  return 1e3 * double(b.tv_sec - a.tv_sec) + 1e-6 * double(b.tv_nsec - a.tv_nsec);
}

// Our lines (`output_length_step` > 0: sampled densely, for a reference).
template <class Field>
std::vector<Line> our_lines(const Field& field, const std::vector<Point>& seeds, double max_length,
                            double relative_tolerance, std::vector<int>& reasons,
                            double output_length_step = 0)
{
  std::vector<Line> lines(seeds.size());
  std::vector<Point> points;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    points.clear();
    const auto np = FAS::parameters::max_length(
        max_length, FAS::parameters::relative_tolerance(
                        relative_tolerance, FAS::parameters::absolute_tolerance(relative_tolerance * 1e-2)));
    const FAS::Streamline_report r =
        output_length_step > 0
            ? FAS::integrate_streamline(field, seeds[i], std::back_inserter(points),
                                        FAS::parameters::output_length_step(output_length_step, np))
            : FAS::integrate_streamline(field, seeds[i], std::back_inserter(points), np);
    ++reasons[int(r.forward.termination)];
    for (const Point& p : points)
      lines[i].push_back({p.x(), p.y(), p.z()});
  }
  return lines;
}

template <class Field>
Figures run_ours(const Field& field, const std::vector<Point>& seeds, double max_length, int runs,
                 double relative_tolerance, const std::vector<Line>* reference)
{
  std::vector<Line> lines;
  std::vector<double> times, wall;
  std::vector<int> reasons(8, 0);
  for (int run = 0; run < runs; ++run) {
    std::fill(reasons.begin(), reasons.end(), 0);
    times.push_back(
        cpu_ms([&] { lines = our_lines(field, seeds, max_length, relative_tolerance, reasons); }, wall));
  }
  Figures f = summarize(lines, times, wall, reference);
  for (int k = 0; k < 8; ++k)
    if (reasons[std::size_t(k)] > 0)
      f.reasons += std::string(FAS::to_string(FAS::Streamline_termination(k))) + ":" +
                   std::to_string(reasons[std::size_t(k)]) + " ";
  return f;
}

#ifdef FAS_HAVE_VTK_FLOW_PATHS
Figures run_vtk(const FAS::Regular_grid_flow_field_3<K>& grid, int n, double h, const std::vector<Point>& seeds,
                double max_length, int runs, double maximum_error, const std::vector<Line>* reference)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->SetOrigin(0., 0., 0.);
  image->SetSpacing(h, h, h);
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(vtkIdType(n) * n * n);
  std::memcpy(velocity->GetPointer(0), grid.values().data(), grid.values().size() * sizeof(float));
  image->GetPointData()->SetVectors(velocity);
  vtkNew<vtkPoints> seed_points;
  for (const Point& p : seeds)
    seed_points->InsertNextPoint(p.x(), p.y(), p.z());
  vtkNew<vtkPolyData> source;
  source->SetPoints(seed_points);

  std::vector<Line> lines(seeds.size());
  std::vector<double> times, wall;
  std::vector<int> reasons(8, 0);
  for (int run = 0; run < runs; ++run) {
    vtkNew<vtkStreamTracer> tracer; // a new one each run: no state kept between runs
    tracer->SetInputData(image);
    tracer->SetSourceData(source);
    tracer->SetIntegratorTypeToRungeKutta45();
    tracer->SetIntegrationDirectionToForward();
    tracer->SetMaximumPropagation(max_length);
    tracer->SetMaximumError(maximum_error);
    tracer->SetMaximumNumberOfSteps(1000000);
    times.push_back(cpu_ms([&] { tracer->Update(); }, wall));
    vtkPolyData* out = tracer->GetOutput();
    vtkDataArray* seed_ids = out->GetCellData()->GetArray("SeedIds");
    vtkDataArray* why = out->GetCellData()->GetArray("ReasonForTermination");
    std::fill(reasons.begin(), reasons.end(), 0);
    for (auto& line : lines)
      line.clear();
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
      out->GetCellPoints(c, ids);
      const std::size_t seed = seed_ids ? std::size_t(seed_ids->GetTuple1(c)) : std::size_t(c);
      if (why)
        ++reasons[std::min<std::size_t>(7, std::size_t(why->GetTuple1(c)))];
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
        double p[3];
        out->GetPoint(ids->GetId(k), p);
        lines[seed].push_back({p[0], p[1], p[2]});
      }
    }
  }
  Figures f = summarize(lines, times, wall, reference);
  // vtkStreamTracer::ReasonForTermination
  const char* names[8] = {"?",
                          "OUT_OF_DOMAIN",
                          "NOT_INITIALIZED",
                          "UNEXPECTED_VALUE",
                          "OUT_OF_LENGTH",
                          "OUT_OF_STEPS",
                          "STAGNATION",
                          "?"};
  for (int k = 0; k < 8; ++k)
    if (reasons[std::size_t(k)] > 0)
      f.reasons += std::string(names[k]) + ":" + std::to_string(reasons[std::size_t(k)]) + " ";
  return f;
}
#endif

void print(const char* name, const Figures& f)
{
  std::printf("%-34s %8.2f %8.2f %8zu %10.3g %10.3g %10.3g %8.3f  %s\n", name, f.time_ms, f.wall_ms, f.points,
              f.median_drift, f.max_drift, f.median_deviation, f.mean_length, f.reasons.c_str());
}

} // namespace

int main(int argc, char** argv)
{
  const std::size_t number_of_seeds = argc > 1 ? std::size_t(std::atoi(argv[1])) : 100;
  const double max_length = argc > 2 ? std::atof(argv[2]) : 10.;
  const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 7;
  const int n = argc > 4 ? std::max(4, std::atoi(argv[4])) : 64;
  const double two_pi = 2. * std::acos(-1.), h = two_pi / double(n - 1);
  const FAS::ABC_flow<K> abc(A, B, 0.);
  const auto grid = FAS::sample_on_grid(abc, Point(0., 0., 0.), Vector(h, h, h), {std::size_t(n), std::size_t(n), std::size_t(n)});
  std::mt19937 generator(1);
  std::uniform_real_distribution<double> coordinate(0.5, two_pi - 0.5);
  std::vector<Point> seeds;
  for (std::size_t i = 0; i < number_of_seeds; ++i) {
    const double x = coordinate(generator), y = coordinate(generator), z = coordinate(generator);
    seeds.emplace_back(x, y, z);
  }
  std::printf("ABC (C = 0) on %d^3 over [0, 2pi]^3, %zu seeds, max length %g, median of %d runs\n", n,
              number_of_seeds, max_length, runs);
  // The reference lines on the grid: ours at tolerance 1e-12, sampled every 1e-3 of length.
  std::vector<int> unused(8, 0);
  const std::vector<Line> reference = our_lines(grid, seeds, max_length, 1e-12, unused, 1e-3);
  std::printf("%-34s %8s %8s %8s %10s %10s %10s %8s  %s\n", "tracer", "cpu_ms", "wall_ms", "points",
              "drift_med", "drift_max", "deviation", "mean_len", "reasons");
  print("interpolation floor (reference)", summarize(reference, {0.}, {0.}, nullptr));
  print("FAS grid (rtol 1e-8, default)", run_ours(grid, seeds, max_length, runs, 1e-8, &reference));
  print("FAS grid (rtol 1e-6)", run_ours(grid, seeds, max_length, runs, 1e-6, &reference));
  // The same samples interpolated tricubically: its own reference lines (the field differs).
  const auto cubic = grid.with_interpolation(FAS::Grid_interpolation::TRICUBIC);
  const std::vector<Line> cubic_reference = our_lines(cubic, seeds, max_length, 1e-12, unused, 1e-3);
  print("FAS tricubic grid (rtol 1e-8)", run_ours(cubic, seeds, max_length, runs, 1e-8, &cubic_reference));
  print("FAS tricubic grid (rtol 1e-6)", run_ours(cubic, seeds, max_length, runs, 1e-6, &cubic_reference));
#ifdef FAS_HAVE_VTK_FLOW_PATHS
  print("VTK RK45 grid (MaximumError 1e-6)", run_vtk(grid, n, h, seeds, max_length, runs, 1e-6, &reference));
  print("VTK RK45 grid (MaximumError 1e-8)", run_vtk(grid, n, h, seeds, max_length, runs, 1e-8, &reference));
#else
  std::printf("VTK's FiltersFlowPaths not found: no vtkStreamTracer row\n");
#endif
  // The analytic flow, where I is exact: the integrator's own drift (lines leave [0, 2pi]^3
  // freely here; the domain is R^3).
  print("FAS analytic (rtol 1e-8)", run_ours(abc, seeds, max_length, runs, 1e-8, nullptr));
  return 0;
}
