// The flow-aligning deformation of Section 4 against surfaces known exactly:
// level sets of potentials (orthogonal) and stream surfaces (tangential).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include "planar_patch_mesh.h"
#include "skip_without_tool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <optional>
#include <cmath>
#include <limits>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Flow_aligned_deformation {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;
namespace PMP = CGAL::Polygon_mesh_processing;

using fas_test::planar_patch;

// max - min of a scalar function over the vertices.
template <class Function>
double spread_over_vertices(const Mesh& tm, const Function& f)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (auto v : tm.vertices()) {
    const double value = f(tm.point(v));
    lo = (std::min)(lo, value);
    hi = (std::max)(hi, value);
  }
  return hi - lo;
}

using fas_test::diameter;

// |v| averaged over the vertices: the scale of |grad phi| on the patch.
template <class Flow>
double mean_speed(const Mesh& tm, const Flow& flow)
{
  double speed = 0;
  for (auto v : tm.vertices())
    speed += std::sqrt(flow(tm.point(v))->squared_length());
  return speed / tm.number_of_vertices();
}

bool all_finite(const Mesh& tm)
{
  for (auto v : tm.vertices()) {
    const Point& p = tm.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  return true;
}

double largest_dihedral_angle(const Mesh& tm)
{
  double largest = 0;
  for (auto e : tm.edges()) {
    const auto h = tm.halfedge(e);
    if (tm.is_border(e))
      continue;
    const Vector n1 = PMP::compute_face_normal(tm.face(h), tm);
    const Vector n2 = PMP::compute_face_normal(tm.face(tm.opposite(h)), tm);
    largest = (std::max)(largest, std::acos(std::clamp(n1 * n2, -1.0, 1.0)));
  }
  return largest;
}

// Point source: the orthogonal surfaces are the spheres around the source.
TEST(FlowAlignedDeformation, OrthogonalPatchInPointSourceLiesOnSphere)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 4000);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, source, FAS::Alignment::ORTHOGONAL);
  EXPECT_TRUE(report.converged);
  EXPECT_GE(report.normalized_flux.value.value(), 0.995);
  double sum = 0;
  for (auto v : tm.vertices())
    sum += std::sqrt((tm.point(v) - CGAL::ORIGIN).squared_length());
  const double mean_radius = sum / tm.number_of_vertices();
  const double spread =
      spread_over_vertices(tm, [](const Point& p) { return std::sqrt((p - CGAL::ORIGIN).squared_length()); });
  EXPECT_LE(spread / mean_radius, 1e-3);
  EXPECT_NEAR(FAS::normalized_flux(tm, source).value.value(), report.normalized_flux.value.value(), 1e-12);
}

// Potential flow past a cylinder: the orthogonal surfaces are level sets of phi.
TEST(FlowAlignedDeformation, OrthogonalPatchInCylinderFlowLiesOnPotentialLevelSet)
{
  const FAS::Cylinder_potential_flow<K> flow(1.0, 1.0);
  Mesh tm = planar_patch(Point(-2.2, 0.6, 0.3), Vector(1.0, 0.4, 0.2), 1.2, 4000);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::ORTHOGONAL);
  EXPECT_TRUE(report.converged);
  EXPECT_GE(report.normalized_flux.value.value(), 0.995);
  const double speed = mean_speed(tm, flow);
  const double spread = spread_over_vertices(tm, [&](const Point& p) { return flow.potential(p); });
  EXPECT_LE(spread, 1e-3 * speed * diameter(tm));
}

// Symmetric linear flow v = A x: phi = x^T A x / 2.
TEST(FlowAlignedDeformation, OrthogonalPatchInSymmetricLinearFlowLiesOnPotentialLevelSet)
{
  const FAS::Linear_flow<K> flow(1.0, 0.2, 0.0, 0.2, 0.5, 0.1, 0.0, 0.1, -1.5);
  ASSERT_TRUE(flow.has_potential());
  Mesh tm = planar_patch(Point(1.5, 1.0, 0.5), Vector(1.0, 0.5, -0.5), 0.8, 3000);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::ORTHOGONAL);
  EXPECT_TRUE(report.converged);
  EXPECT_GE(report.normalized_flux.value.value(), 0.995);
  const double speed = mean_speed(tm, flow);
  EXPECT_LE(spread_over_vertices(tm, [&](const Point& p) { return flow.potential(p); }),
            1e-3 * speed * diameter(tm));
}

// A patch whose normal faces against the flow is aligned to -v, not turned over.
TEST(FlowAlignedDeformation, OrthogonalAlignmentDoesNotFlipAPatchFacingAgainstTheFlow)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh tm = planar_patch(Point(0, 0, 2.0), Vector(0.2, 0.0, -1.0), 1.0, 1000);
  const auto face = *tm.faces().begin();
  const Vector before = PMP::compute_face_normal(face, tm);
  FAS::align_to_flow(tm, source, FAS::Alignment::ORTHOGONAL);
  const Vector after = PMP::compute_face_normal(face, tm);
  EXPECT_GT(before * after, 0.9);
  EXPECT_GE(FAS::normalized_flux(tm, source).value.value(), 0.995);
}

template <class Flow>
void expect_tangential_alignment(Mesh tm, const Flow& flow, std::size_t max_iterations = 100)
{
  std::vector<double> initial_areas;
  for (auto f : tm.faces())
    initial_areas.push_back(PMP::face_area(f, tm));
  const FAS::Alignment_report report = FAS::align_to_flow(
      tm, flow, FAS::Alignment::TANGENTIAL, CGAL::parameters::number_of_iterations(max_iterations));
  EXPECT_LE(report.normalized_flux.value.value(), 0.01);
  EXPECT_LE(report.number_of_iterations, max_iterations);
  std::size_t i = 0;
  double worst = 0;
  for (auto f : tm.faces())
    worst = (std::max)(worst, std::abs(PMP::face_area(f, tm) / initial_areas[i++] - 1));
  EXPECT_LE(worst, 0.10) << "face areas must stay within 10% of M_0's";
  EXPECT_TRUE(all_finite(tm));
}

// Helical flow: the cylinders x^2 + y^2 = R^2 are stream surfaces.
TEST(FlowAlignedDeformation, TangentialPatchInHelicalFlowBecomesStreamSurface)
{
  expect_tangential_alignment(planar_patch(Point(1.0, 0.2, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 4000),
                              FAS::Helical_flow<K>(0.5));
}

// Cylinder potential flow: psi = const extruded along z are stream surfaces.
TEST(FlowAlignedDeformation, TangentialPatchInCylinderFlowBecomesStreamSurface)
{
  expect_tangential_alignment(planar_patch(Point(-2.0, 0.8, 0.0), Vector(0.3, 1.0, 0.4), 1.0, 4000),
                              FAS::Cylinder_potential_flow<K>(1.0, 1.0));
}

// Hill's spherical vortex: psi = const are stream surfaces (no swirl).
TEST(FlowAlignedDeformation, TangentialPatchInHillVortexBecomesStreamSurface)
{
  expect_tangential_alignment(planar_patch(Point(0.5, 0.1, 0.2), Vector(0.2, 1.0, 0.3), 0.4, 3000),
                              FAS::Hill_spherical_vortex<K>(1.0, 1.0));
}

// Two halves folded onto each other along the flow are both tangential; only the fold
// correction opens the crease to theta_max.
TEST(FlowAlignedDeformation, FoldedNeighboursAreUnfolded)
{
  const FAS::Uniform_flow<K> flow(Vector(1, 0, 0));
  Mesh tm = planar_patch(Point(0, 0, 0), Vector(0, 0, 1), 1.0, 2000);
  const double fold = 170.0 * CGAL_PI / 180.0;
  for (auto v : tm.vertices()) {
    const Point p = tm.point(v);
    if (p.y() > 0)
      tm.point(v) = Point(p.x(), p.y() * std::cos(fold), p.y() * std::sin(fold));
  }
  ASSERT_GT(largest_dihedral_angle(tm), 2.5);
  FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  const FAS::Iteration_report first = deformation.step();
  EXPECT_GT(first.number_of_folds, 0u);
  EXPECT_TRUE(deformation.run(200).converged);
  // The crease opens to theta_max (approached from above, as delta/2 shrinks with delta).
  EXPECT_LE(largest_dihedral_angle(tm), CGAL_PI / 2 + 0.02);
  EXPECT_LE(FAS::normalized_flux(tm, flow).value.value(), 0.01);
}

TEST(FlowAlignedDeformation, PatchPartlyOutsideTheDomainConvergesWithoutNaN)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const auto clipped = [source](const Point& p) -> std::optional<Vector> {
    if (p.x() > 0.2)
      return std::nullopt;
    return source(p);
  };
  Mesh tm = planar_patch(Point(0, 0, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 2000);
  FAS::Flow_aligned_deformation<Mesh, decltype(clipped)> deformation(tm, clipped, FAS::Alignment::ORTHOGONAL);
  const FAS::Iteration_report first = deformation.step();
  EXPECT_GT(first.number_of_outside_samples, 0u);
  const FAS::Alignment_report report = deformation.run();
  EXPECT_TRUE(report.converged);
  EXPECT_TRUE(all_finite(tm));
  EXPECT_GE(report.normalized_flux.value.value(), 0.99);
}

TEST(FlowAlignedDeformation, NonFiniteSamplesCountAsOutsideAndNeverReachTheMesh)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const auto broken = [source](const Point& p) -> std::optional<Vector> {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (p.x() > 0.2)
      return Vector(nan, 1, 0);
    if (p.y() > 0.3)
      return Vector(std::numeric_limits<double>::infinity(), 0, 0);
    return source(p);
  };
  Mesh tm = planar_patch(Point(0, 0, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 2000);
  FAS::Flow_aligned_deformation<Mesh, decltype(broken)> deformation(tm, broken, FAS::Alignment::ORTHOGONAL);
  const FAS::Iteration_report first = deformation.step();
  EXPECT_GT(first.number_of_invalid_samples, 0u);
  EXPECT_EQ(first.number_of_outside_samples, 0u);
  deformation.run();
  EXPECT_TRUE(all_finite(tm));
  EXPECT_TRUE(std::isfinite(FAS::normalized_flux(tm, broken).value.value()));
}

TEST(FlowAlignedDeformation, ZeroFieldLeavesTheSurfaceInPlace)
{
  // T = I everywhere and the constraints at the current positions: X_k is a fixed point.
  const auto still = [](const Point&) -> std::optional<Vector> { return Vector(0, 0, 0); };
  Mesh tm = planar_patch(Point(0.5, 0, 0), Vector(0.3, 0.2, 1.0), 1.0, 1000);
  const Mesh before = tm;
  FAS::Flow_aligned_deformation<Mesh, decltype(still)> deformation(tm, still, FAS::Alignment::ORTHOGONAL);
  const FAS::Iteration_report r = deformation.step();
  EXPECT_EQ(r.number_of_zero_samples, tm.number_of_faces());
  EXPECT_TRUE(r.converged);
  for (auto v : tm.vertices())
    EXPECT_LT(std::sqrt((tm.point(v) - before.point(v)).squared_length()), 1e-9);
}

TEST(FlowAlignedDeformation, RigidMovesReconvergeWithoutRefactorization)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 3000);
  FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>> deformation(tm, source,
                                                                             FAS::Alignment::ORTHOGONAL);
  EXPECT_TRUE(deformation.run().converged);
  deformation.translate(Vector(0.3, 0.2, 0.8));
  deformation.rotate(Vector(1, 1, 0), 0.4);
  EXPECT_LT(FAS::normalized_flux(tm, source).value.value(), 0.99);
  const FAS::Alignment_report report = deformation.run();
  EXPECT_TRUE(report.converged);
  EXPECT_GE(report.normalized_flux.value.value(), 0.995);
  EXPECT_EQ(deformation.number_of_factorizations(), 1u);
  double sum = 0;
  for (auto v : tm.vertices())
    sum += std::sqrt((tm.point(v) - CGAL::ORIGIN).squared_length());
  const double spread =
      spread_over_vertices(tm, [](const Point& p) { return std::sqrt((p - CGAL::ORIGIN).squared_length()); });
  EXPECT_LE(spread / (sum / tm.number_of_vertices()), 1e-3);
}

TEST(FlowAlignedDeformation, RigidMovesAreExact)
{
  const FAS::Uniform_flow<K> flow(Vector(0, 0, 1));
  Mesh tm = planar_patch(Point(0, 0, 0), Vector(0, 0, 1), 1.0, 200);
  const Mesh before = tm;
  FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> deformation(tm, flow, FAS::Alignment::ORTHOGONAL);
  deformation.translate(Vector(1, 2, 3));
  deformation.rotate(Point(1, 2, 3), Vector(0, 0, 1), CGAL_PI / 2);
  for (auto v : tm.vertices()) {
    const Point p = before.point(v), q = tm.point(v);
    EXPECT_NEAR(q.x(), 1 - p.y(), 1e-12);
    EXPECT_NEAR(q.y(), 2 + p.x(), 1e-12);
    EXPECT_NEAR(q.z(), 3 + p.z(), 1e-12);
  }
}

TEST(FlowAlignedDeformation, VisitorReceivesEveryIterationWithTheFluxBeforeIt)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 1000);
  const double initial_flux = FAS::normalized_flux(tm, source).value.value();
  std::vector<FAS::Iteration_report> reports;
  const FAS::Alignment_report report = FAS::align_to_flow(
      tm, source, FAS::Alignment::ORTHOGONAL,
      CGAL::parameters::visitor([&](const FAS::Iteration_report& r) { reports.push_back(r); }));
  ASSERT_EQ(reports.size(), report.number_of_iterations);
  EXPECT_NEAR(reports.front().normalized_flux.value.value(), initial_flux, 1e-12);
  for (std::size_t k = 0; k < reports.size(); ++k) {
    EXPECT_EQ(reports[k].iteration, k + 1);
    EXPECT_GE(reports[k].gradient_transformation_ms, 0);
    EXPECT_GE(reports[k].solve_ms, 0);
  }
  // The first rotation requested is the patch's initial misalignment, clamped to eta when applied.
  EXPECT_GT(reports.front().max_rotation_angle, 0.1);
  EXPECT_TRUE(reports.back().converged);
}

TEST(FlowAlignedDeformation, PackageParametersAreHonoured)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh slow = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.6, 0.2, 1.0), 1.0, 1000);
  Mesh fast = slow;
  const auto eta_small =
      FAS::parameters::max_rotation_angle(0.02, CGAL::parameters::number_of_iterations(500));
  const FAS::Alignment_report r_slow =
      FAS::align_to_flow(slow, source, FAS::Alignment::ORTHOGONAL, eta_small);
  const FAS::Alignment_report r_fast = FAS::align_to_flow(fast, source, FAS::Alignment::ORTHOGONAL);
  // The initial tilt is about 0.6 rad: at 0.02 rad per iteration it takes at least 25 iterations.
  EXPECT_GE(r_slow.number_of_iterations, 25u);
  EXPECT_LT(r_fast.number_of_iterations, r_slow.number_of_iterations);
  EXPECT_EQ(
      FAS::align_to_flow(fast, source, FAS::Alignment::ORTHOGONAL,
                         FAS::parameters::convergence_step(0.0, CGAL::parameters::number_of_iterations(1)))
          .number_of_iterations,
      1u);
}

} // namespace

namespace {

// The per-face work spread over threads gives the surfaces of the serial iteration.
TEST(FlowAlignedDeformation, ParallelIterationsGiveTheSerialSurfaces)
{
#ifndef CGAL_LINKED_WITH_TBB
  FAS_SKIP_WITHOUT_TOOL("built without TBB: use_parallelism has no effect");
#else
  // The per-face pass is parallel from 4096 faces on; under the sanitizers (FAS_TEST_SANITIZED,
  // at -O0) the patch has half the faces, still well above that, at half the cost.
#ifdef FAS_TEST_SANITIZED
  constexpr std::size_t faces = 6000;
#else
  constexpr std::size_t faces = 12000;
#endif
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh serial = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, faces);
  Mesh parallel = serial;
  ASSERT_GE(parallel.number_of_faces(), 4096u);
  std::vector<FAS::Iteration_report> serial_reports, parallel_reports;
  FAS::align_to_flow(
      serial, source, FAS::Alignment::ORTHOGONAL,
      CGAL::parameters::visitor([&](const FAS::Iteration_report& r) { serial_reports.push_back(r); }));
  FAS::align_to_flow(
      parallel, source, FAS::Alignment::ORTHOGONAL,
      FAS::parameters::use_parallelism(true, CGAL::parameters::visitor([&](const FAS::Iteration_report& r) {
                                         parallel_reports.push_back(r);
                                       })));
  ASSERT_EQ(serial_reports.size(), parallel_reports.size());
  for (std::size_t k = 0; k < serial_reports.size(); ++k) {
    EXPECT_EQ(serial_reports[k].max_rotation_angle, parallel_reports[k].max_rotation_angle);
    // Only the order of the flux sums differs.
    EXPECT_NEAR(serial_reports[k].normalized_flux.value.value(),
                parallel_reports[k].normalized_flux.value.value(), 1e-12);
  }
  auto p = parallel.vertices().begin();
  for (auto v : serial.vertices())
    EXPECT_EQ(serial.point(v), parallel.point(*p++));
#endif
}

#ifdef CGAL_FLOW_ALIGNED_SURFACES_USE_CHOLMOD
// The default solver with its single-precision copy forced on (or off) at every size.
template <bool single>
struct Single_precision_corrections : FAS::internal::Cholmod_LDLT_swept {
  Single_precision_corrections() { single_precision_from(single ? 0. : 1e300); }
};
template <class Flow, bool single>
using Corrected_deformation = FAS::Flow_aligned_deformation<Mesh, Flow, CGAL::Default, CGAL::Default,
                                                            CGAL::Eigen_solver_traits<Single_precision_corrections<single>>>;

// Aligns `start` with the single-precision corrections and with the double factor's; the
// positions of the two converged surfaces differ by at most `tolerance` times its diameter.
template <class Flow>
void expect_the_surface_of_the_double_factor(const Mesh& start, const Flow& flow, FAS::Alignment alignment)
{
  Mesh single = start, exact = start;
  Corrected_deformation<Flow, true> in_single(single, flow, alignment);
  Corrected_deformation<Flow, false> in_double(exact, flow, alignment);
  const FAS::Alignment_report a = in_single.run(), b = in_double.run();
  EXPECT_TRUE(a.converged);
  EXPECT_TRUE(b.converged);
  EXPECT_EQ(a.number_of_iterations, b.number_of_iterations);
  EXPECT_NEAR(a.normalized_flux.value.value(), b.normalized_flux.value.value(), 1e-9);
  double largest = 0;
  auto q = exact.vertices().begin();
  for (auto v : single.vertices())
    largest = (std::max)(largest, std::sqrt((single.point(v) - exact.point(*q++)).squared_length()));
  // A tenth of what single precision of the positions would give.
  EXPECT_LT(largest, 1e-8 * diameter(exact));
  EXPECT_GT(largest, 0.); // the single-precision sweeps were used
}

// Each step solves for the change of the positions (one step of iterative refinement from the
// current surface), and the translation of that change, where a single-precision factor errs
// most, is set exactly: the iterations and the converged surface are those of the double factor.
TEST(FlowAlignedDeformation, SinglePrecisionCorrectionsReachTheDoublePrecisionSurface)
{
  expect_the_surface_of_the_double_factor(planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 8000),
                                          FAS::Point_source_flow<K>(Point(0, 0, 0), 1.0),
                                          FAS::Alignment::ORTHOGONAL);
  expect_the_surface_of_the_double_factor(planar_patch(Point(1.0, 0.2, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 8000),
                                          FAS::Helical_flow<K>(0.5), FAS::Alignment::TANGENTIAL);
  // Two connected components, each translated by its own constrained vertices.
  Mesh two = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 5000);
  FAS::make_planar_patch(two, Point(-1.5, 0.4, 2.5), Vector(0.1, -0.3, 1.0), 0.8, 0.8, 5000);
  expect_the_surface_of_the_double_factor(two, FAS::Point_source_flow<K>(Point(0, 0, 0), 1.0),
                                          FAS::Alignment::ORTHOGONAL);
}
#else
TEST(FlowAlignedDeformation, SinglePrecisionCorrectionsReachTheDoublePrecisionSurface)
{
  FAS_SKIP_WITHOUT_CHOLMOD();
}
#endif

// next_sample_points() names, bit for bit, every point the next step() samples: a field that
// only knows the samples at those points (what a caller holding a distributed field fills in
// one batch) gives the surfaces of the field itself, and is never asked for another point.
// Checked after a rigid move and with a collapsed face, which step() does not sample.
TEST(FlowAlignedDeformation, NextSamplePointsAreThePointsTheNextStepSamples)
{
  const FAS::Cylinder_potential_flow<K> cylinder;
  Mesh direct = planar_patch(Point(-1.8, 0.5, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 600);
  Mesh batched = direct;
  // Looks the samples up in a table; counts the points it was not given.
  struct Table_field {
    std::map<std::array<double, 3>, std::optional<Vector>> samples;
    mutable std::size_t misses = 0;
    std::optional<Vector> operator()(const Point& p) const
    {
      const auto found = samples.find({p.x(), p.y(), p.z()});
      if (found == samples.end()) {
        ++misses;
        return std::nullopt;
      }
      return found->second;
    }
  } table;
  FAS::Flow_aligned_deformation<Mesh, FAS::Cylinder_potential_flow<K>> reference(
      direct, cylinder, FAS::Alignment::TANGENTIAL);
  FAS::Flow_aligned_deformation<Mesh, Table_field> deformation(batched, table, FAS::Alignment::TANGENTIAL);
  const auto fill_table = [&] {
    std::vector<Point> points;
    deformation.next_sample_points(std::back_inserter(points));
    table.samples.clear();
    for (const Point& p : points)
      table.samples[{p.x(), p.y(), p.z()}] = cylinder(p);
    return points.size();
  };
  const auto expect_same_surfaces = [&](const char* when) {
    auto q = batched.vertices().begin();
    for (auto v : direct.vertices())
      ASSERT_EQ(direct.point(v), batched.point(*q++)) << when;
  };
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(fill_table(), batched.number_of_faces());
    const FAS::Iteration_report expected = reference.step(), actual = deformation.step();
    EXPECT_EQ(expected.max_rotation_angle, actual.max_rotation_angle);
    EXPECT_EQ(actual.number_of_outside_samples, 0u);
  }
  expect_same_surfaces("after 5 iterations");
  EXPECT_EQ(table.misses, 0u);

  reference.translate(Vector(0.1, -0.2, 0.05));
  deformation.translate(Vector(0.1, -0.2, 0.05));
  fill_table();
  reference.step();
  deformation.step();
  expect_same_surfaces("after a translation");
  EXPECT_EQ(table.misses, 0u);

  // Faces collapsed by the user: no normal, no sample, no point.
  const auto f = *batched.faces().begin();
  std::vector<Mesh::Vertex_index> corners;
  for (auto v : CGAL::vertices_around_face(batched.halfedge(f), batched))
    corners.push_back(v);
  batched.point(corners[1]) = batched.point(corners[0]);
  batched.point(corners[2]) = batched.point(corners[0]);
  direct.point(*std::next(direct.vertices().begin(), corners[1].idx())) = batched.point(corners[0]);
  direct.point(*std::next(direct.vertices().begin(), corners[2].idx())) = batched.point(corners[0]);
  std::size_t collapsed = 0;
  for (auto g : batched.faces())
    collapsed += PMP::face_area(g, batched) == 0 ? 1 : 0;
  ASSERT_GE(collapsed, 1u);
  EXPECT_EQ(fill_table(), batched.number_of_faces() - collapsed);
  reference.step();
  deformation.step();
  expect_same_surfaces("with a collapsed face");
  EXPECT_EQ(table.misses, 0u);
}

} // namespace

} // namespace test_Flow_aligned_deformation
