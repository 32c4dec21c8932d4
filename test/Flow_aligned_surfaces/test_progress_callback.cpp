// CGAL's `callback` named parameter on the long-running functions: the fractions it receives
// (one per unit of work: iteration, growth stage, time line), a stop requested by returning
// `false` (the output as of the last unit, valid, and a report that says so), and results that
// a callback which never stops leaves bit for bit as they are without one.

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_progress_callback {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Polyline = std::vector<Point_3>;

// Records every fraction; returns false from the `stop_at`-th call on (0: never).
struct Recorder {
  std::size_t stop_at = 0;
  std::vector<double> fractions;

  auto callback()
  {
    return [this](double fraction) {
      fractions.push_back(fraction);
      return stop_at == 0 || fractions.size() < stop_at;
    };
  }
};

// The fractions of `calls` units of work: within [0, 1], non-decreasing, and 1 at the end of
// work that was not stopped.
void expect_fractions(const std::vector<double>& fractions, std::size_t calls, bool stopped)
{
  ASSERT_EQ(fractions.size(), calls);
  for (std::size_t i = 0; i < fractions.size(); ++i) {
    EXPECT_GE(fractions[i], 0.) << "call " << i;
    EXPECT_LE(fractions[i], 1.) << "call " << i;
    if (i > 0) {
      EXPECT_GE(fractions[i], fractions[i - 1]) << "call " << i;
    }
  }
  if (!stopped && !fractions.empty()) {
    EXPECT_EQ(fractions.back(), 1.);
  }
}

void expect_valid(const Mesh& tm)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  for (auto v : tm.vertices())
    ASSERT_TRUE(std::isfinite(tm.point(v).x()) && std::isfinite(tm.point(v).y()) &&
                std::isfinite(tm.point(v).z()))
        << "vertex " << v;
}

// Bit for bit: the same vertices, points and faces, in the same order.
void expect_same(const Mesh& a, const Mesh& b)
{
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  for (auto v : a.vertices())
    ASSERT_EQ(a.point(v), b.point(v)) << "vertex " << v;
  for (auto f : a.faces()) {
    std::vector<Mesh::Vertex_index> fa, fb;
    for (auto v : vertices_around_face(a.halfedge(f), a))
      fa.push_back(v);
    for (auto v : vertices_around_face(b.halfedge(f), b))
      fb.push_back(v);
    ASSERT_EQ(fa, fb) << "face " << f;
  }
}

// A flat patch one unit in front of a point source: the orthogonal alignment bends it into a
// sphere over several iterations (η = 0.1 per iteration).
Mesh patch_before_the_source()
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 1), Vector_3(0, 0, 1), 1.2, 1.2, 400);
  return tm;
}

const FAS::Point_source_flow<K> source(Point_3(0, 0, 0), 1.0);

TEST(ProgressCallback, AlignToFlowReportsEachIterationAndChangesNothing)
{
  Mesh plain = patch_before_the_source(), observed = plain;
  const FAS::Alignment_report expected = FAS::align_to_flow(plain, source, FAS::Alignment::ORTHOGONAL,
                                                            CGAL::parameters::number_of_iterations(15));
  Recorder recorder;
  const FAS::Alignment_report report =
      FAS::align_to_flow(observed, source, FAS::Alignment::ORTHOGONAL,
                         CGAL::parameters::number_of_iterations(15).callback(recorder.callback()));
  EXPECT_FALSE(report.stopped);
  EXPECT_EQ(report.number_of_iterations, expected.number_of_iterations);
  EXPECT_EQ(report.converged, expected.converged);
  ASSERT_GT(report.number_of_iterations, 3u);
  expect_fractions(recorder.fractions, report.number_of_iterations, false);
  for (std::size_t k = 1; k < report.number_of_iterations; ++k)
    EXPECT_DOUBLE_EQ(recorder.fractions[k - 1], double(k) / 15) << "iteration " << k;
  expect_same(observed, plain);
}

TEST(ProgressCallback, AlignToFlowStopsAfterTheIterationThatReturnedFalse)
{
  Mesh three_iterations = patch_before_the_source(), stopped = three_iterations;
  FAS::align_to_flow(three_iterations, source, FAS::Alignment::ORTHOGONAL,
                     CGAL::parameters::number_of_iterations(3));
  Recorder recorder;
  recorder.stop_at = 3;
  const FAS::Alignment_report report =
      FAS::align_to_flow(stopped, source, FAS::Alignment::ORTHOGONAL,
                         CGAL::parameters::number_of_iterations(50).callback(recorder.callback()));
  EXPECT_TRUE(report.stopped);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.number_of_iterations, 3u);
  expect_fractions(recorder.fractions, 3, true);
  EXPECT_DOUBLE_EQ(recorder.fractions.back(), 3. / 50);
  ASSERT_TRUE(report.normalized_flux.value.has_value());
  expect_valid(stopped);
  expect_same(stopped, three_iterations); // the surface of the third iteration
}

TEST(ProgressCallback, AStopAfterTheLastIterationStopsNothing)
{
  Mesh tm = patch_before_the_source();
  Recorder recorder;
  recorder.stop_at = 4;
  FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>> deformation(
      tm, source, FAS::Alignment::ORTHOGONAL, CGAL::parameters::callback(recorder.callback()));
  const FAS::Alignment_report report = deformation.run(4);
  EXPECT_FALSE(report.stopped);
  EXPECT_EQ(report.number_of_iterations, 4u);
  expect_fractions(recorder.fractions, 4, false);
  // step() is one iteration, not a run: it does not call the callback.
  deformation.step();
  EXPECT_EQ(recorder.fractions.size(), 4u);
}

Mesh flat_square()
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 200);
  return tm;
}

TEST(ProgressCallback, GrowBoundaryReportsTheStripThenTheGrownMesh)
{
  Mesh plain = flat_square(), observed = plain;
  const FAS::Growth_report expected = FAS::grow_boundary(plain, 0.05);
  Recorder recorder;
  const FAS::Growth_report report =
      FAS::grow_boundary(observed, 0.05, CGAL::parameters::callback(recorder.callback()));
  EXPECT_FALSE(report.stopped);
  EXPECT_EQ(report.number_of_new_vertices, expected.number_of_new_vertices);
  ASSERT_GT(report.number_of_new_faces, 0u);
  expect_fractions(recorder.fractions, 2, false);
  EXPECT_EQ(recorder.fractions.front(), 0.5);
  expect_same(observed, plain);
}

TEST(ProgressCallback, GrowBoundaryStoppedLeavesTheMeshUntouched)
{
  const Mesh before = flat_square();
  Mesh tm = before;
  Recorder recorder;
  recorder.stop_at = 1;
  const FAS::Growth_report report = FAS::grow_boundary(
      tm, 0.05,
      FAS::parameters::growth_direction(Vector_3(1, 0, 0), CGAL::parameters::callback(recorder.callback())));
  EXPECT_TRUE(report.stopped);
  EXPECT_EQ(report.number_of_new_vertices, 0u);
  EXPECT_EQ(report.number_of_new_faces, 0u);
  EXPECT_EQ(report.number_of_grown_edges, 0u);
  EXPECT_TRUE(report.grown_edges.empty());
  expect_fractions(recorder.fractions, 1, true);
  expect_valid(tm);
  expect_same(tm, before);
}

TEST(ProgressCallback, DeformationGrowReportsAndAStoppedGrowthKeepsTheObjectUsable)
{
  const FAS::Uniform_flow<K> flow(Vector_3(1, 0, 0));
  Mesh plain = flat_square(), observed = plain;
  FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> expected(plain, flow, FAS::Alignment::TANGENTIAL);
  FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> deformation(observed, flow,
                                                                        FAS::Alignment::TANGENTIAL);

  Recorder stopping;
  stopping.stop_at = 1;
  const FAS::Growth_report stopped = deformation.grow(0.05, CGAL::parameters::callback(stopping.callback()));
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(stopped.number_of_new_vertices, 0u);
  expect_fractions(stopping.fractions, 1, true);
  EXPECT_EQ(deformation.number_of_factorizations(), 1u);
  EXPECT_EQ(deformation.vertices().size(), observed.number_of_vertices());
  expect_same(observed, plain);

  Recorder recorder;
  const FAS::Growth_report report = deformation.grow(0.05, CGAL::parameters::callback(recorder.callback()));
  const FAS::Growth_report plain_report = expected.grow(0.05);
  EXPECT_FALSE(report.stopped);
  EXPECT_EQ(report.number_of_new_vertices, plain_report.number_of_new_vertices);
  expect_fractions(recorder.fractions, 2, false);
  EXPECT_EQ(deformation.number_of_factorizations(), 2u);
  expect_same(observed, plain);
  // The iterations continue on the grown surface as they do after a growth without callback.
  deformation.step();
  expected.step();
  expect_valid(observed);
  expect_same(observed, plain);
}

// A stream surface and its report.
struct Surface {
  Mesh tm;
  FAS::Stream_surface_report report;

  template <class Field, class NamedParameters>
  Surface(const Field& field, const Polyline& seed, const NamedParameters& np)
  {
    report = FAS::integrate_stream_surface(field, seed, tm, np);
  }
};

const Polyline seed = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 0, 1)};
const FAS::Uniform_flow<K> uniform(Vector_3(0.5, 1, 0.25));

// The uniform flow's surface from `seed` up to τ = 2, reporting to `recorder`.
Surface uniform_surface(Recorder& recorder)
{
  return Surface(uniform, seed,
                 FAS::parameters::front_spacing(
                     0.1, FAS::parameters::max_time(2.0, CGAL::parameters::callback(recorder.callback()))));
}

TEST(ProgressCallback, StreamSurfaceReportsEachTimeLineAndChangesNothing)
{
  const Surface plain(uniform, seed, FAS::parameters::front_spacing(0.1, FAS::parameters::max_time(2.0)));
  Recorder recorder;
  const Surface observed = uniform_surface(recorder);
  EXPECT_FALSE(observed.report.stopped);
  EXPECT_EQ(observed.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_EQ(observed.report.number_of_time_lines, plain.report.number_of_time_lines);
  ASSERT_GT(observed.report.number_of_time_lines, 10u);
  expect_fractions(recorder.fractions, observed.report.number_of_time_lines, false);
  // With max_time as the only limit, the fraction is τ / max_time: k Δ / 2 before the last line.
  for (std::size_t k = 1; k < observed.report.number_of_time_lines; ++k)
    EXPECT_DOUBLE_EQ(recorder.fractions[k - 1], double(k) * observed.report.time_line_step / 2.0);
  expect_same(observed.tm, plain.tm);
}

TEST(ProgressCallback, StreamSurfaceStopsAfterTheTimeLineThatReturnedFalse)
{
  Recorder recorder;
  recorder.stop_at = 5;
  const Surface stopped = uniform_surface(recorder);
  EXPECT_TRUE(stopped.report.stopped);
  EXPECT_EQ(stopped.report.termination, FAS::Stream_surface_termination::STOPPED);
  EXPECT_STREQ(FAS::to_string(stopped.report.termination), "STOPPED");
  EXPECT_EQ(stopped.report.number_of_time_lines, 5u);
  EXPECT_DOUBLE_EQ(stopped.report.final_parameter, 5 * stopped.report.time_line_step);
  expect_fractions(recorder.fractions, 5, true);
  expect_valid(stopped.tm);
  // 21 particles on the seed and on each of the 5 time lines: the surface up to the fifth.
  EXPECT_EQ(stopped.tm.number_of_vertices(), 21u * 6);
  EXPECT_EQ(stopped.tm.number_of_faces(), 2u * 20 * 5);
  EXPECT_EQ(stopped.report.number_of_vertices, stopped.tm.number_of_vertices());
  const Surface five_lines(
      uniform, seed,
      FAS::parameters::front_spacing(
          0.1, FAS::parameters::max_time(2.0, FAS::parameters::max_number_of_time_lines(std::size_t(5)))));
  expect_same(stopped.tm, five_lines.tm);
}

TEST(ProgressCallback, StreamSurfaceBothHalvesShareTheFractions)
{
  const auto both = FAS::parameters::integration_direction(FAS::Integration_direction::BOTH,
                                                           FAS::parameters::front_spacing(0.1));
  Recorder recorder;
  const Surface observed(uniform, seed, FAS::parameters::max_time(1.0, both.callback(recorder.callback())));
  const Surface plain(uniform, seed, FAS::parameters::max_time(1.0, both));
  ASSERT_TRUE(observed.report.backward);
  const std::size_t backward_lines = observed.report.backward->number_of_time_lines;
  EXPECT_FALSE(observed.report.stopped);
  expect_fractions(recorder.fractions, backward_lines + observed.report.number_of_time_lines, false);
  EXPECT_EQ(recorder.fractions[backward_lines - 1], 0.5); // the backward half's last time line
  expect_same(observed.tm, plain.tm);

  Recorder stopping;
  stopping.stop_at = 3;
  const Surface stopped(uniform, seed, FAS::parameters::max_time(1.0, both.callback(stopping.callback())));
  EXPECT_TRUE(stopped.report.stopped);
  ASSERT_TRUE(stopped.report.backward);
  EXPECT_EQ(stopped.report.backward->termination, FAS::Stream_surface_termination::STOPPED);
  EXPECT_EQ(stopped.report.backward->number_of_time_lines, 3u);
  expect_fractions(stopping.fractions, 3, true);
  EXPECT_LT(stopping.fractions.back(), 0.5);
  expect_valid(stopped.tm);
  EXPECT_EQ(stopped.tm.number_of_vertices(), 21u * 4); // no forward half
}

TEST(ProgressCallback, StreamSurfaceEndingBeforeItsLimitsEndsAtOne)
{
  // The flow's domain ends at x = 1: every particle leaves it long before max_time.
  const auto field = [](const Point_3& p) -> std::optional<Vector_3> {
    if (p.x() > 1)
      return std::nullopt;
    return Vector_3(1, 0, 0);
  };
  const Polyline line = {Point_3(0, 0, 0), Point_3(0, 1, 0)};
  Recorder recorder;
  const Surface s(field, line,
                  FAS::parameters::front_spacing(
                      0.1, FAS::parameters::max_time(10.0, CGAL::parameters::callback(recorder.callback()))));
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::NO_PARTICLE_LEFT);
  EXPECT_FALSE(s.report.stopped);
  expect_fractions(recorder.fractions, s.report.number_of_time_lines, false);
  ASSERT_GE(recorder.fractions.size(), 2u);
  EXPECT_LT(recorder.fractions[recorder.fractions.size() - 2], 0.2);
}

// The parametrizations: r and s written by runs with and without a callback, and by a run
// stopped after `stop_at` reports (0: never), into maps that start at -1.
struct Parametrization_run {
  bool returned = false;
  std::vector<double> r, s, fractions;
};

template <class Parametrize>
Parametrization_run run_parametrization(const Mesh& tm, std::size_t stop_at, const Parametrize& parametrize)
{
  Mesh copy = tm;
  auto r = copy.add_property_map<Mesh::Vertex_index, double>("v:r", -1.).first;
  auto s = copy.add_property_map<Mesh::Vertex_index, double>("v:s", -1.).first;
  Recorder recorder;
  recorder.stop_at = stop_at;
  Parametrization_run run;
  run.returned = parametrize(copy, r, s, recorder.callback());
  for (auto v : copy.vertices()) {
    run.r.push_back(r[v]);
    run.s.push_back(s[v]);
  }
  run.fractions = recorder.fractions;
  return run;
}

// A plane patch in the point source's flow: the tangential and the orthogonal parametrizations.
void expect_parametrization_reports(bool tangential)
{
  const Mesh tm = patch_before_the_source();
  const auto parametrize = [&](Mesh& m, auto r, auto s, auto callback) {
    return tangential ? FAS::parametrize_tangential(m, source, r, s, CGAL::parameters::callback(callback))
                      : FAS::parametrize_orthogonal(m, source, r, s, CGAL::parameters::callback(callback));
  };
  const auto plain = [&](Mesh& m, auto r, auto s, auto) {
    return tangential ? FAS::parametrize_tangential(m, source, r, s) : FAS::parametrize_orthogonal(m, source, r, s);
  };
  const Parametrization_run expected = run_parametrization(tm, 0, plain);
  const Parametrization_run observed = run_parametrization(tm, 0, parametrize);
  EXPECT_TRUE(expected.returned);
  EXPECT_TRUE(observed.returned);
  EXPECT_EQ(observed.fractions, (std::vector<double>{1. / 3, 2. / 3, 1.}));
  EXPECT_EQ(observed.r, expected.r); // bit for bit
  EXPECT_EQ(observed.s, expected.s);
  for (std::size_t stop_at : {1u, 2u}) {
    const Parametrization_run stopped = run_parametrization(tm, stop_at, parametrize);
    EXPECT_FALSE(stopped.returned) << "stopped at report " << stop_at;
    EXPECT_EQ(stopped.fractions.size(), stop_at);
    EXPECT_EQ(stopped.r, std::vector<double>(tm.number_of_vertices(), -1.)) << "r written after a stop";
    EXPECT_EQ(stopped.s, std::vector<double>(tm.number_of_vertices(), -1.)) << "s written after a stop";
  }
}

TEST(ProgressCallback, TangentialParametrizationReportsItsStagesAndAStopWritesNothing)
{
  expect_parametrization_reports(true);
}

TEST(ProgressCallback, OrthogonalParametrizationReportsItsStagesAndAStopWritesNothing)
{
  expect_parametrization_reports(false);
}

TEST(ProgressCallback, GeodesicDistanceReportsTheHeatStepAndAStopWritesNothing)
{
  const Mesh tm = patch_before_the_source();
  const Mesh::Vertex_index middle = *tm.vertices().begin();
  const auto distance = [&](Mesh& m, auto d, auto, auto callback) {
    return FAS::compute_geodesic_distance(m, middle, d, CGAL::parameters::callback(callback));
  };
  const auto plain = [&](Mesh& m, auto d, auto, auto) { return FAS::compute_geodesic_distance(m, middle, d); };
  const Parametrization_run expected = run_parametrization(tm, 0, plain);
  const Parametrization_run observed = run_parametrization(tm, 0, distance);
  EXPECT_TRUE(observed.returned);
  EXPECT_EQ(observed.fractions, (std::vector<double>{0.5, 1.}));
  EXPECT_EQ(observed.r, expected.r);
  const Parametrization_run stopped = run_parametrization(tm, 1, distance);
  EXPECT_FALSE(stopped.returned);
  EXPECT_EQ(stopped.r, std::vector<double>(tm.number_of_vertices(), -1.));
}

} // namespace

} // namespace test_progress_callback
