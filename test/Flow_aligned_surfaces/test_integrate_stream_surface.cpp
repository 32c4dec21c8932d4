// integrate_stream_surface against what is known independently: the exact surfaces of the
// uniform and linear flows and of a path surface in a flow linear in time (closed forms of
// x(u, τ)); first integrals (Hill's vortex: the Stokes stream function; ABC with C = 0:
// A cos z + B sin x; the cylinder: its stream function) constant from the seed point c(u) of
// every vertex; the front spacing in [h/2, 2h]; a front split by a cylinder; a surface that
// reaches the boundary of a box where its particles leave (the exact trapezoid); bad input.

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Unsteady_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/internal/check_triangle_mesh.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <array>
#include <functional>
#include <iostream>
#include <map>
#include <limits>
#include <optional>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_integrate_stream_surface {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Polyline = std::vector<Point_3>;

// The output mesh with its u and t maps.
struct Surface {
  Mesh tm;
  Mesh::Property_map<Vertex, double> u, t;
  FAS::Stream_surface_report report;

  Surface()
  {
    u = tm.add_property_map<Vertex, double>("v:u", -1).first;
    t = tm.add_property_map<Vertex, double>("v:t", -1).first;
  }
  template <class Field, class NP>
  explicit Surface(const Field& field, const Polyline& seed, const NP& np) : Surface()
  {
    report = FAS::integrate_stream_surface(
        field, seed, tm,
        FAS::parameters::seed_parameter_map(u, FAS::parameters::integration_time_map(t, np)));
  }
};

// c(u): the seed polyline at arc length u, computed here independently of the header.
Point_3 seed_point(const Polyline& seed, double u)
{
  for (std::size_t i = 1; i < seed.size(); ++i) {
    const double length = std::sqrt(CGAL::squared_distance(seed[i - 1], seed[i]));
    if (u <= length || i + 1 == seed.size())
      return seed[i - 1] + (u / length) * (seed[i] - seed[i - 1]);
    u -= length;
  }
  return seed.front();
}

// Every vertex's t is a whole number of time-line steps (or the last time line's, at the
// maximal integration time), except where its particle left the domain (`on_boundary`, when the
// field has a boundary: `on_boundary(point, t)`), its u is in [0, L], and the vertices with
// t = 0 are their seed points.
void expect_parametrization(const Surface& s, const Polyline& seed,
                            const std::function<bool(const Point_3&, double)>& on_boundary = nullptr)
{
  ASSERT_GT(s.tm.number_of_faces(), 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(s.tm));
  // A manifold triangle mesh, also where the front tore (no vertex where two pieces touch in
  // one point only): the check the package's measures make (linear; PMP's per-vertex test is
  // quadratic over the mesh).
  EXPECT_NO_THROW(FAS::internal::check_triangle_mesh(s.tm, "the stream surface"));
  EXPECT_EQ(s.report.number_of_refused_faces, 0u);
  EXPECT_EQ(s.report.number_of_vertices, s.tm.number_of_vertices());
  EXPECT_EQ(s.report.number_of_faces, s.tm.number_of_faces());
  const double step = s.report.time_line_step;
  for (Vertex v : s.tm.vertices()) {
    const double k = s.t[v] / step;
    if (s.t[v] != s.report.final_parameter && std::abs(k - std::round(k)) > 1e-9) {
      ASSERT_TRUE(on_boundary && on_boundary(s.tm.point(v), s.t[v]))
          << "t = " << s.t[v] << " between time lines at " << s.tm.point(v);
    }
    ASSERT_GE(s.u[v], 0.);
    ASSERT_LE(s.u[v], s.report.seed_length * (1 + 1e-15));
    if (s.t[v] == 0.) {
      ASSERT_LE(CGAL::squared_distance(s.tm.point(v), seed_point(seed, s.u[v])), 1e-24);
    }
  }
}

// The time-line edges (both ends on one time line) are between h/2 and 2h long; returns their
// number.
std::size_t expect_front_spacing(const Surface& s)
{
  const double h = s.report.front_spacing;
  std::size_t n = 0;
  for (auto e : s.tm.edges()) {
    const Vertex a = s.tm.vertex(e, 0), b = s.tm.vertex(e, 1);
    if (s.t[a] != s.t[b])
      continue;
    const double d = std::sqrt(CGAL::squared_distance(s.tm.point(a), s.tm.point(b)));
    EXPECT_GE(d, 0.5 * h) << "at t = " << s.t[a];
    EXPECT_LE(d, 2 * h) << "at t = " << s.t[a];
    ++n;
  }
  return n;
}

// The largest |I(x) - I(c(u))| over the vertices.
template <class FirstIntegral>
double first_integral_drift(const Surface& s, const Polyline& seed, const FirstIntegral& first_integral)
{
  double drift = 0;
  for (Vertex v : s.tm.vertices())
    drift =
        std::max(drift, std::abs(first_integral(s.tm.point(v)) - first_integral(seed_point(seed, s.u[v]))));
  return drift;
}

TEST(IntegrateStreamSurface, UniformFlowTranslatesTheSeed)
{
  const Vector_3 U(0.5, 1, 0.25);
  const Polyline seed = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 0, 1)};
  const Surface s(FAS::Uniform_flow<K>(U), seed,
                  FAS::parameters::front_spacing(0.1, FAS::parameters::max_time(2.0)));
  expect_parametrization(s, seed);
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_DOUBLE_EQ(s.report.final_parameter, 2.0);
  EXPECT_DOUBLE_EQ(s.report.time_line_step, 0.1 / std::sqrt(U.squared_length()));
  for (Vertex v : s.tm.vertices()) // x(u, t) = c(u) + t U
    ASSERT_LE(std::sqrt(CGAL::squared_distance(s.tm.point(v), seed_point(seed, s.u[v]) + s.t[v] * U)), 1e-12);
  EXPECT_EQ(s.report.number_of_inserted_particles, 0u);
  EXPECT_EQ(s.report.number_of_removed_particles, 0u);
  // 21 particles (20 segments of 0.1) on 1 + 2.0 / step time lines.
  const std::size_t lines = 1 + static_cast<std::size_t>(std::round(2.0 / s.report.time_line_step));
  EXPECT_EQ(s.tm.number_of_vertices(), 21 * lines);
  EXPECT_EQ(s.tm.number_of_faces(), 2 * 20 * (lines - 1));
  EXPECT_GT(expect_front_spacing(s), 0u);
}

TEST(IntegrateStreamSurface, LinearFlowMatchesTheExponentialAndInsertsReintegratedParticles)
{
  // A = diag(1, 1, -2): x(u, t) = (x0 e^t, y0 e^t, z0 e^-2t) with (x0, y0, z0) = c(u).
  const Polyline seed = {Point_3(0.2, 0.1, 1.0), Point_3(0.4, 0.5, 0.8)};
  const Surface s(FAS::Linear_flow<K>(), seed,
                  FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(2.0)));
  expect_parametrization(s, seed);
  EXPECT_GT(s.report.number_of_inserted_particles, 20u); // the front is stretched e^2 times
  EXPECT_EQ(s.report.number_of_tears, 0u);
  for (Vertex v : s.tm.vertices()) {
    const Point_3 c = seed_point(seed, s.u[v]);
    const double e = std::exp(s.t[v]);
    const Point_3 exact(c.x() * e, c.y() * e, c.z() / (e * e));
    ASSERT_LE(std::sqrt(CGAL::squared_distance(s.tm.point(v), exact)),
              1e-7 * std::sqrt(exact.x() * exact.x() + exact.y() * exact.y() + exact.z() * exact.z()))
        << "u = " << s.u[v] << " t = " << s.t[v];
  }
  EXPECT_GT(expect_front_spacing(s), 100u);
}

TEST(IntegrateStreamSurface, HillsVortexKeepsTheStreamFunctionAndHasNoFlux)
{
  // An arc rho = 0.3 in the plane z = 0 inside the vortex: its surface is a piece of a vortex
  // torus psi = const; the particles move in their meridional planes out to rho = 0.955 and
  // back, so the front is stretched and compressed with rho (insertions and removals).  The
  // flux of the flat triangles is first order in their extent along the stream lines (whose
  // curvature is up to about 5 here): time lines h/12 apart.
  const FAS::Hill_spherical_vortex<K> hill(1.0, 1.0);
  Polyline seed;
  for (int i = 0; i <= 20; ++i)
    seed.push_back(Point_3(0.3 * std::cos(0.05 * i), 0.3 * std::sin(0.05 * i), 0.));
  const double h = 0.03, speed = 1.5 * (1 - 2 * 0.09); // |v| on the seed
  const Surface s(
      hill, seed,
      FAS::parameters::front_spacing(
          h, FAS::parameters::time_line_step(
                 h / 12 / speed, FAS::parameters::max_time(
                                     5.0, FAS::parameters::max_number_of_time_lines(std::size_t(3000))))));
  expect_parametrization(s, seed);
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_EQ(s.report.number_of_tears, 0u);
  EXPECT_GT(s.report.number_of_inserted_particles, 0u);
  EXPECT_GT(s.report.number_of_removed_particles, 0u);
  const double psi0 = std::abs(hill.stokes_stream_function(seed.front()));
  EXPECT_LE(first_integral_drift(s, seed, [&](const Point_3& p) { return hill.stokes_stream_function(p); }),
            1e-5 * psi0);
  EXPECT_LE(FAS::normalized_flux(s.tm, hill).value.value(), 1e-3);
  EXPECT_GT(expect_front_spacing(s), 100u);
}

TEST(IntegrateStreamSurface, ABCFlowWithoutCKeepsItsFirstIntegralAndHasNoFlux)
{
  const FAS::ABC_flow<K> abc(std::sqrt(3.), std::sqrt(2.), 0.);
  const Polyline seed = {Point_3(0.5, 0, 0.5), Point_3(1.0, 1.0, 0.7), Point_3(1.5, 2.0, 1.0)};
  // Time lines about h/5 apart (|v| is 1 to 2.2 here): the flux of the flat triangles is first
  // order in their extent along the stream lines.  (Up to time 1: 100 time lines.)
  const Surface s(abc, seed,
                  FAS::parameters::front_spacing(
                      0.05, FAS::parameters::time_line_step(0.01, FAS::parameters::max_time(1.0))));
  expect_parametrization(s, seed);
  const double scale = std::sqrt(3.) + std::sqrt(2.); // the range of A cos z + B sin x
  EXPECT_LE(first_integral_drift(s, seed, [&](const Point_3& p) { return abc.first_integral(p); }),
            1e-5 * scale);
  EXPECT_LE(FAS::normalized_flux(s.tm, abc).value.value(), 1e-3);
  EXPECT_GT(expect_front_spacing(s), 100u);
}

TEST(IntegrateStreamSurface, CylinderSplitsTheFront)
{
  const FAS::Cylinder_potential_flow<K> cylinder(1.0, 1.0);
  const Polyline seed = {Point_3(-3, -0.6, 0.2), Point_3(-3, 0.6, 0.2)};
  const Surface s(cylinder, seed,
                  FAS::parameters::front_spacing(
                      0.05, FAS::parameters::max_time(
                                10.0, FAS::parameters::max_number_of_time_lines(std::size_t(1000)))));
  expect_parametrization(s, seed);
  std::cout << "cylinder: " << s.report.number_of_time_lines << " time lines, "
            << s.report.number_of_inserted_particles << " inserted, " << s.report.number_of_removed_particles
            << " removed, " << s.report.number_of_tears << " tears, " << s.report.number_of_lost_particles
            << " lost, " << s.report.message << "\n";
  EXPECT_GE(s.report.number_of_tears + s.report.number_of_lost_particles, 1u);
  bool above = false, below = false;
  for (Vertex v : s.tm.vertices()) {
    const Point_3& p = s.tm.point(v);
    ASSERT_GE(p.x() * p.x() + p.y() * p.y(), 1 - 1e-9);
    if (p.x() > 1.5)
      (p.y() > 0 ? above : below) = true;
  }
  EXPECT_TRUE(above && below) << "the front passes on both sides";
  // No edge cuts the cylinder: each edge's segment stays (almost: chords of the wall) outside.
  for (auto e : s.tm.edges()) {
    const Point_3 a = s.tm.point(s.tm.vertex(e, 0)), b = s.tm.point(s.tm.vertex(e, 1));
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    const double l2 = dx * dx + dy * dy;
    const double s01 = l2 > 0 ? std::clamp(-(a.x() * dx + a.y() * dy) / l2, 0., 1.) : 0.;
    const double x = a.x() + s01 * dx, y = a.y() + s01 * dy;
    ASSERT_GE(std::sqrt(x * x + y * y), 0.99) << "edge from " << a << " to " << b;
  }
  EXPECT_GT(expect_front_spacing(s), 100u); // where the front is not torn
  // The stream function psi = U y (1 - R^2 / rho^2) is a first integral.
  EXPECT_LE(first_integral_drift(s, seed, [&](const Point_3& p) { return cylinder.stream_function(p); }),
            1e-6);
}

// The uniform flow U = (1, 0, 0) in the box [-2, 1] x [-2, 2]^2 from a seed segment in z = 0
// from (x0, y0, 0) to (x1, y1, 0) slanted across it: the particle from c(u) = (x, y, 0) leaves
// through x = 1 at t = 1 - x.  The surface is the trapezoid between the seed and x = 1, of area
// |y1 - y0| (1 - (x0 + x1) / 2).  Checks the surface against it; returns the report.
FAS::Stream_surface_report expect_the_trapezoid_up_to_the_box_face(const Polyline& seed, double h, double step)
{
  const auto boxed = [](const Point_3& p) -> std::optional<Vector_3> {
    if (p.x() < -2 || p.x() > 1 || std::abs(p.y()) > 2 || std::abs(p.z()) > 2)
      return std::nullopt;
    return Vector_3(1, 0, 0);
  };
  // The integrator's boundary tolerance, 1e-12 + 1e-10 |x| by default, with |x| <= 2.
  const double tolerance = 3e-8;
  const auto on_boundary = [&](const Point_3& p, double) { return std::abs(p.x() - 1) <= tolerance; };
  const Surface s(boxed, seed,
                  FAS::parameters::front_spacing(
                      h, FAS::parameters::time_line_step(
                             step, FAS::parameters::max_time(
                                       4.0, FAS::parameters::max_number_of_time_lines(std::size_t(1000))))));
  expect_parametrization(s, seed, on_boundary);
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::NO_PARTICLE_LEFT) << s.report.message;
  std::size_t at_boundary = 0;
  for (Vertex v : s.tm.vertices()) {
    const Point_3 c = seed_point(seed, s.u[v]);
    EXPECT_LE(std::sqrt(CGAL::squared_distance(s.tm.point(v), c + s.t[v] * Vector_3(1, 0, 0))), 1e-12);
    EXPECT_LE(s.tm.point(v).x(), 1.);
    if (on_boundary(s.tm.point(v), s.t[v])) {
      ++at_boundary;
      EXPECT_NEAR(s.t[v], 1 - c.x(), tolerance) << "u = " << s.u[v];
    }
  }
  // Every particle of the seed (L / h + 1 of them) ends on the boundary.
  const Point_3 &first = seed.front(), &last = seed.back();
  EXPECT_GE(at_boundary, static_cast<std::size_t>(std::sqrt(CGAL::squared_distance(first, last)) / h));
  // The surface reaches the boundary all along, without notches between the exits: the area
  // is the trapezoid's within the boundary tolerance times the boundary's length (stopping on
  // the last time line reached would miss up to Δ along it).
  const double width = std::abs(last.y() - first.y());
  const double exact = width * (1 - (first.x() + last.x()) / 2);
  const double area = CGAL::Polygon_mesh_processing::area(s.tm);
  std::cout.precision(10);
  std::cout << "box: area " << area << " of " << exact << ", " << at_boundary << " vertices on the boundary, "
            << s.report.number_of_inserted_particles << " inserted, " << s.report.number_of_lost_particles
            << " lost\n";
  EXPECT_LE(area, exact + 1e-9);
  EXPECT_GE(area, exact - 1e-7 * width);
  EXPECT_GT(expect_front_spacing(s), 100u);
  return s.report;
}

TEST(IntegrateStreamSurface, ReachesTheBoundaryWhereParticlesLeave)
{
  // Neighbours leave within one time line of each other (Δ = h = 0.05, 0.0375 apart in x)...
  expect_the_trapezoid_up_to_the_box_face({Point_3(-0.9, 0, 0), Point_3(0.3, 1, 0)}, 0.05, 0.05);
  // ... and several time lines apart, where the front grazes the boundary (Δ = h / 5, the
  // particles 0.05 apart in x): the strips fan out from each exit to the next.
  expect_the_trapezoid_up_to_the_box_face({Point_3(-1.9, 0, 0), Point_3(0.9, 0.1, 0)}, 0.05, 0.01);
  // The same with the seed reversed: the particle that leaves first is then the one of the
  // smaller seed parameter in each pair (the fans turn the other way).
  expect_the_trapezoid_up_to_the_box_face({Point_3(0.9, 0.1, 0), Point_3(-1.9, 0, 0)}, 0.05, 0.01);
}

TEST(IntegrateStreamSurface, AnyMutableFaceGraph)
{
  // The same surface in a Polyhedron_3 (BGL interface, no u/t maps) as in a Surface_mesh.
  const FAS::Hill_spherical_vortex<K> hill(1.0, 1.0);
  const Polyline seed = {Point_3(0.3, 0, 0), Point_3(0.3, 0.3, 0.1)};
  const auto np = FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(2.0));
  const Surface s(hill, seed, np);
  CGAL::Polyhedron_3<K> polyhedron;
  const FAS::Stream_surface_report report = FAS::integrate_stream_surface(hill, seed, polyhedron, np);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(polyhedron));
  EXPECT_EQ(report.number_of_refused_faces, 0u);
  EXPECT_EQ(polyhedron.size_of_vertices(), s.tm.number_of_vertices());
  EXPECT_EQ(polyhedron.size_of_facets(), s.tm.number_of_faces());
  EXPECT_GT(polyhedron.size_of_facets(), 100u);
}

TEST(IntegrateStreamSurface, PathSurfaceInAFlowLinearInTime)
{
  // v(t) = U0 + (t / 2) (U1 - U0) on t in [0, 2]: x(u, tau) = c(u) + U0 tau + (U1 - U0)
  // ((t0 + tau)^2 - t0^2) / 4.  After t = 2 the field has no value: the particles leave.
  const Vector_3 U0(1, 0, 0), U1(1, 2, 0);
  const FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>> flow(
      {0., 2.}, {FAS::Uniform_flow<K>(U0), FAS::Uniform_flow<K>(U1)});
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 0, 1)};
  const double t0 = 0.5;
  const Surface s(flow, seed,
                  FAS::parameters::front_spacing(
                      0.1, FAS::parameters::start_time(t0, FAS::parameters::time_line_step(0.1))));
  // The particles leave the field's time interval at t = 2 (tau = 1.5), located within the
  // integrator's boundary tolerance.
  expect_parametrization(s, seed, [](const Point_3&, double tau) { return std::abs(tau - 1.5) <= 1e-8; });
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::NO_PARTICLE_LEFT);
  EXPECT_NEAR(s.report.final_parameter, 1.5, 1e-12);
  for (Vertex v : s.tm.vertices()) {
    const double tau = s.t[v];
    const Point_3 exact =
        seed_point(seed, s.u[v]) + tau * U0 + ((t0 + tau) * (t0 + tau) - t0 * t0) / 4 * (U1 - U0);
    ASSERT_LE(std::sqrt(CGAL::squared_distance(s.tm.point(v), exact)), 1e-9);
  }
}

TEST(IntegrateStreamSurface, PathSurfaceEndingWhereTheFieldEndsLosesNoParticle)
{
  // The same flow integrated to t = 2 exactly (max_time 1.5): the end of the surface, not an
  // exit, so no particle is lost on the way, however long the integrator's steps would be.
  const Vector_3 U0(1, 0, 0), U1(1, 2, 0);
  const FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>> flow(
      {0., 2.}, {FAS::Uniform_flow<K>(U0), FAS::Uniform_flow<K>(U1)});
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 0, 1)};
  const Surface s(flow, seed,
                  FAS::parameters::front_spacing(
                      0.1, FAS::parameters::start_time(0.5, FAS::parameters::max_time(1.5))));
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_EQ(s.report.number_of_lost_particles, 0u);
  EXPECT_EQ(s.report.final_parameter, 1.5);
}

TEST(IntegrateStreamSurface, BackwardIntegrationReversesTheFlow)
{
  const Vector_3 U(1, 0, 0);
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 1, 0)};
  const Surface s(FAS::Uniform_flow<K>(U), seed,
                  FAS::parameters::integration_direction(FAS::Integration_direction::BACKWARD,
                                                         FAS::parameters::max_time(1.0)));
  expect_parametrization(s, seed);
  for (Vertex v : s.tm.vertices())
    ASSERT_LE(std::sqrt(CGAL::squared_distance(s.tm.point(v), seed_point(seed, s.u[v]) - s.t[v] * U)), 1e-12);
}

TEST(IntegrateStreamSurface, ArcLengthTimeLines)
{
  // In the linear flow the speed varies; with arc-length time lines each stream line's length
  // from the seed is t.  For the stream line of (x0, 0, 0) it is x0 (e^s - 1) at time s.
  const Polyline seed = {Point_3(0.5, 0, 0), Point_3(0.5, 0.5, 0)};
  const Surface s(FAS::Linear_flow<K>(), seed,
                  FAS::parameters::arc_length_time_lines(true, FAS::parameters::max_length(1.0)));
  expect_parametrization(s, seed);
  for (Vertex v : s.tm.vertices()) { // radial motion in z = 0: |x - c(u)| is the arc length
    const Point_3 c = seed_point(seed, s.u[v]);
    ASSERT_NEAR(std::sqrt(CGAL::squared_distance(s.tm.point(v), c)), s.t[v], 1e-8);
  }
}

TEST(IntegrateStreamSurface, SeedOutsideTheDomainGivesAnEmptyResult)
{
  const Polyline seed = {Point_3(-0.5, 0, 0), Point_3(0.5, 0, 0)}; // inside the cylinder
  Surface s(FAS::Cylinder_potential_flow<K>(1.0, 1.0), seed, CGAL::parameters::default_values());
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::SEED_OUTSIDE_DOMAIN);
  EXPECT_NE(s.report.message.find("outside"), std::string::npos);
  EXPECT_EQ(s.tm.number_of_vertices(), 0u);

  // A seed across the cylinder: the part inside is dropped, the two parts outside are
  // integrated as two front pieces.
  const Polyline across = {Point_3(0, -2, 0), Point_3(0, 2, 0)};
  const Surface a(FAS::Cylinder_potential_flow<K>(1.0, 1.0), across,
                  FAS::parameters::front_spacing(0.1, FAS::parameters::max_time(1.0)));
  expect_parametrization(a, across);
  EXPECT_GE(a.report.number_of_lost_particles, 19u); // the seed points with |y| < 1
  bool above = false, below = false;
  for (Vertex v : a.tm.vertices()) {
    const Point_3& p = a.tm.point(v);
    ASSERT_GE(p.x() * p.x() + p.y() * p.y(), 1 - 1e-9);
    (p.y() > 0 ? above : below) = true;
  }
  EXPECT_TRUE(above && below);
}

TEST(IntegrateStreamSurface, FieldAtRestOnTheSeedGivesAnEmptyResult)
{
  // Zero near the seed (the plane x = 0), moving elsewhere: no particle can start.
  const std::function<std::optional<Vector_3>(const Point_3&)> field = [](const Point_3& p) {
    return std::optional<Vector_3>(Vector_3(p.x(), 0, 0));
  };
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 1, 0)};
  Surface s(field, seed, CGAL::parameters::default_values());
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::SEED_AT_REST);
  EXPECT_EQ(s.tm.number_of_vertices(), 0u);
}

TEST(IntegrateStreamSurface, BadSeedsAndParametersAreNamed)
{
  const FAS::Uniform_flow<K> flow;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Mesh tm;
  const auto call = [&](const Polyline& seed) {
    return [&, seed] { FAS::integrate_stream_surface(flow, seed, tm); };
  };
  expect_invalid_argument(call({Point_3(0, 0, 0), Point_3(0, 1, 0), Point_3(0, 1, 0)}),
                          {"seed_polyline", "points 1 and 2", "distinct"});
  expect_invalid_argument(call({Point_3(0, 0, 0), Point_3(nan, 1, 0)}),
                          {"seed_polyline", "point 1", "finite"});
  expect_invalid_argument(call({Point_3(0, 0, 0)}), {"seed_polyline", "1 point", "at least 2"});
  expect_invalid_argument(call({}), {"seed_polyline", "0 point", "at least 2"});
  expect_invalid_argument(call({Point_3(1, 2, 3), Point_3(1, 2, 3)}), {"seed_polyline", "points 0 and 1"});
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 1, 0)};
  expect_invalid_argument(
      [&] { FAS::integrate_stream_surface(flow, seed, tm, FAS::parameters::front_spacing(-1.)); },
      {"front_spacing", "-1"});
  expect_invalid_argument(
      [&] { FAS::integrate_stream_surface(flow, seed, tm, FAS::parameters::time_line_step(nan)); },
      {"time_line_step", "nan"});
  expect_invalid_argument(
      [&] { FAS::integrate_stream_surface(flow, seed, tm, FAS::parameters::max_time(0.)); },
      {"integrate_stream_surface", "max_time", "0"});
  expect_invalid_argument(
      [&] { FAS::integrate_stream_surface(flow, seed, tm, FAS::parameters::max_number_of_time_lines(0)); },
      {"max_number_of_time_lines", "0"});
  const FAS::Unsteady_flow_field_3<FAS::Uniform_flow<K>> unsteady({0.}, {flow});
  expect_invalid_argument(
      [&] {
        FAS::integrate_stream_surface(unsteady, seed, tm, FAS::parameters::arc_length_time_lines(true));
      },
      {"arc_length_time_lines", "unsteady"});
  EXPECT_EQ(tm.number_of_vertices(), 0u); // nothing was added
}


// The smallest angle (degrees) of the triangles of `tm`.
double smallest_angle(const Mesh& tm)
{
  double smallest = 180;
  for (auto f : tm.faces()) {
    std::array<Point_3, 3> p;
    int i = 0;
    for (Vertex v : vertices_around_face(tm.halfedge(f), tm))
      p[i++] = tm.point(v);
    for (int k = 0; k < 3; ++k) {
      const Vector_3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
      const double c = a * b / std::sqrt(a.squared_length() * b.squared_length());
      smallest = std::min(smallest, std::acos(std::clamp(c, -1., 1.)) * 180 / CGAL_PI);
    }
  }
  return smallest;
}

TEST(IntegrateStreamSurface, DefaultTolerancesReachTheInterpolationFloor)
{
  // ABC with C = 0 sampled at 64^3 (trilinear): the interpolated field does not keep
  // I = A cos z + B sin x, so even an exact integration of it drifts.  That floor is measured
  // with tolerances of 1e-12; the defaults must stay within 1.5 times it (1e-8 gave 1.6 times).
  const double A = std::sqrt(3.), B = std::sqrt(2.);
  const FAS::ABC_flow<K> abc(A, B, 0.);
  const std::size_t n = 64;
  const double spacing = 2 * CGAL_PI / double(n - 1);
  const auto grid = FAS::sample_on_grid(abc, Point_3(0, 0, 0), Vector_3(spacing, spacing, spacing), {n, n, n});
  Polyline seed; // on the level set I = 0.5
  for (int i = 0; i <= 45; ++i) {
    const double x = 1 + i / 45.;
    seed.emplace_back(x, 2 + 2 * (x - 1), std::acos((0.5 - B * std::sin(x)) / A));
  }
  const auto drift = [&](const auto& np) {
    const Surface s(grid, seed,
                    FAS::parameters::arc_length_time_lines(true, FAS::parameters::max_length(6.0, np)));
    expect_parametrization(s, seed, [](const Point_3&, double) { return true; }); // it leaves the grid
    return first_integral_drift(s, seed, [&](const Point_3& p) { return abc.first_integral(p); });
  };
  const double floor = drift(FAS::parameters::relative_tolerance(1e-12, FAS::parameters::absolute_tolerance(1e-12)));
  const double at_defaults = drift(CGAL::parameters::default_values());
  std::cout << "first-integral drift: " << at_defaults << " at the defaults, " << floor << " at 1e-12\n";
  EXPECT_GT(floor, 1e-6); // the interpolation's, not the integrator's
  EXPECT_LE(at_defaults, 1.5 * floor);
}

TEST(IntegrateStreamSurface, ShearingFrontKeepsTrianglesWellShaped)
{
  // A rotation about z whose angular speed 1/r falls with the radius, and an axial drift w:
  // x(u, t) = (r cos(t / r), r sin(t / r), w t) with r = 0.5 + u.  The radial seed's time lines
  // wind up into spirals that turn towards the flow, so that strips one time-line step high get
  // ever flatter: 7.15 degrees with every time line in the mesh, 16 with thin strips skipped.
  // The corner where a time line meets a border stream line tends to atan(w / 1) = 16.7
  // degrees, a bound for any triangulation.
  const double w = 0.3;
  const auto swirl = [w](const Point_3& p) {
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    return std::optional<Vector_3>(Vector_3(-p.y() / r, p.x() / r, w));
  };
  Polyline seed;
  for (int i = 0; i <= 20; ++i)
    seed.emplace_back(0.5 + 0.05 * i, 0, 0);
  const Surface s(swirl, seed, FAS::parameters::max_time(20.0));
  expect_parametrization(s, seed);
  EXPECT_EQ(s.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  for (Vertex v : s.tm.vertices()) {
    const double r = 0.5 + s.u[v], t = s.t[v];
    const Point_3 exact(r * std::cos(t / r), r * std::sin(t / r), w * t);
    ASSERT_LE(std::sqrt(CGAL::squared_distance(s.tm.point(v), exact)), 1e-6);
  }
  EXPECT_GE(smallest_angle(s.tm), 10.);
}

// A face as its three corners (rounded to 1e-9), starting at the smallest: equal for the same
// oriented triangle in two meshes.
std::array<std::array<long long, 3>, 3> oriented_face(const Mesh& tm, Mesh::Face_index f)
{
  std::array<std::array<long long, 3>, 3> corners;
  int i = 0;
  for (Vertex v : vertices_around_face(tm.halfedge(f), tm))
    corners[i++] = {std::llround(tm.point(v).x() * 1e9), std::llround(tm.point(v).y() * 1e9),
                    std::llround(tm.point(v).z() * 1e9)};
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
  return corners;
}

TEST(IntegrateStreamSurface, BothDirectionsGiveOneSurfaceJoinedAtTheSeed)
{
  const FAS::Burgers_vortex<K> flow;
  const Polyline seed = {Point_3(0.8, 0, 0.5), Point_3(1.0, 0.1, 0.6), Point_3(1.2, 0, 0.5)};
  const auto np = [](FAS::Integration_direction d) {
    return FAS::parameters::integration_direction(
        d, FAS::parameters::front_spacing(0.02, FAS::parameters::max_time(0.5)));
  };
  const Surface both(flow, seed, np(FAS::Integration_direction::BOTH));
  const Surface forward(flow, seed, np(FAS::Integration_direction::FORWARD));
  const Surface backward(flow, seed, np(FAS::Integration_direction::BACKWARD));
  expect_parametrization(both, seed, [](const Point_3&, double t) { return t == -0.5; }); // the backward end
  ASSERT_TRUE(both.report.backward.has_value());
  EXPECT_EQ(both.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_EQ(both.report.backward->termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_EQ(both.report.number_of_time_lines, forward.report.number_of_time_lines);
  EXPECT_EQ(both.report.backward->number_of_time_lines, backward.report.number_of_time_lines);
  EXPECT_FALSE(forward.report.backward.has_value());

  // The union of the two halves, the seed's vertices once.
  std::size_t seed_vertices = 0;
  for (Vertex v : both.tm.vertices())
    if (both.t[v] == 0) {
      ++seed_vertices;
      if (both.u[v] > 0 && both.u[v] < both.report.seed_length) { // the two ends are on the border
        ASSERT_FALSE(both.tm.is_border(v)) << "seed vertex on the border: the halves are not joined";
      }
    }
  EXPECT_EQ(seed_vertices, std::size_t(std::ceil(both.report.seed_length / 0.02)) + 1);
  EXPECT_EQ(both.tm.number_of_faces(), forward.tm.number_of_faces() + backward.tm.number_of_faces());
  EXPECT_EQ(both.tm.number_of_vertices(),
            forward.tm.number_of_vertices() + backward.tm.number_of_vertices() - seed_vertices);
  std::map<std::array<std::array<long long, 3>, 3>, int> faces;
  for (auto f : forward.tm.faces())
    ++faces[oriented_face(forward.tm, f)];
  for (auto f : backward.tm.faces())
    ++faces[oriented_face(backward.tm, f)];
  for (auto f : both.tm.faces())
    ASSERT_EQ(--faces[oriented_face(both.tm, f)], 0) << "a face of BOTH is not one of FORWARD or BACKWARD";

  // Oriented as ∂x/∂u × v on both sides of the seed; τ negative on the backward half.
  for (auto f : both.tm.faces()) {
    std::array<Vertex, 3> v;
    int i = 0;
    for (Vertex w : vertices_around_face(both.tm.halfedge(f), both.tm))
      v[i++] = w;
    const Vector_3 normal = CGAL::cross_product(both.tm.point(v[1]) - both.tm.point(v[0]),
                                                both.tm.point(v[2]) - both.tm.point(v[0]));
    const Point_3 c = CGAL::centroid(both.tm.point(v[0]), both.tm.point(v[1]), both.tm.point(v[2]));
    // ∂x/∂u: from the corner of smallest u to that of largest, on the face.
    const auto [lo, hi] =
        std::minmax_element(v.begin(), v.end(), [&](Vertex a, Vertex b) { return both.u[a] < both.u[b]; });
    const Vector_3 du = both.tm.point(*hi) - both.tm.point(*lo);
    ASSERT_GT(CGAL::cross_product(du, *flow(c)) * normal, 0) << "face at " << c;
  }
  for (Vertex v : backward.tm.vertices())
    ASSERT_GE(backward.t[v], 0.);
  double most_negative = 0;
  for (Vertex v : both.tm.vertices())
    most_negative = std::min(most_negative, both.t[v]);
  EXPECT_DOUBLE_EQ(most_negative, -0.5);

  // A front that tears at the cylinder downstream and a seed across the cylinder (two pieces
  // from the start): still one manifold surface with every face accepted.
  const FAS::Cylinder_potential_flow<K> cylinder(1.0, 1.0);
  for (const Polyline& s : {Polyline{Point_3(-2, -0.6, 0.2), Point_3(-2, 0.6, 0.2)},
                            Polyline{Point_3(0, -2, 0.2), Point_3(0, 2, 0.2)}}) {
    const Surface torn(cylinder, s,
                       FAS::parameters::integration_direction(
                           FAS::Integration_direction::BOTH,
                           FAS::parameters::front_spacing(0.05, FAS::parameters::max_time(4.0))));
    expect_parametrization(torn, s, [](const Point_3& p, double t) { // the backward end, the cylinder
      return t == -4.0 || p.x() * p.x() + p.y() * p.y() < 1 + 1e-6;
    });
    EXPECT_EQ(torn.report.backward->termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  }
}

TEST(IntegrateStreamSurface, ReportsTheLimitThatStoppedIt)
{
  const Vector_3 U(1, 0, 0);
  const FAS::Uniform_flow<K> flow(U);
  const Polyline seed = {Point_3(0, 0, 0), Point_3(0, 1, 0)};
  const auto h = FAS::parameters::front_spacing(0.05);
  // max_length 6 at h = 0.05 needs 120 time lines: the default cap of 100 no longer applies
  // when a limit in τ is given.
  const Surface length(flow, seed,
                       FAS::parameters::arc_length_time_lines(true, FAS::parameters::max_length(6.0, h)));
  EXPECT_EQ(length.report.termination, FAS::Stream_surface_termination::MAX_LENGTH);
  EXPECT_DOUBLE_EQ(length.report.final_parameter, 6.0);
  EXPECT_EQ(length.report.number_of_time_lines, 120u);
  EXPECT_NE(length.report.message.find("max_length 6"), std::string::npos) << length.report.message;

  const Surface time(flow, seed, FAS::parameters::max_time(6.0, h));
  EXPECT_EQ(time.report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_DOUBLE_EQ(time.report.final_parameter, 6.0);
  EXPECT_NE(time.report.message.find("max_time 6"), std::string::npos) << time.report.message;

  const Surface lines(flow, seed, FAS::parameters::max_time(6.0, FAS::parameters::max_number_of_time_lines(10, h)));
  EXPECT_EQ(lines.report.termination, FAS::Stream_surface_termination::MAX_NUMBER_OF_TIME_LINES);
  EXPECT_EQ(lines.report.number_of_time_lines, 10u);
  EXPECT_NE(lines.report.message.find("max_number_of_time_lines (10) reached at time 0.5, before max_time 6"),
            std::string::npos)
      << lines.report.message;

  const Surface unbounded(flow, seed, h); // no limit in τ: 100 time lines by default
  EXPECT_EQ(unbounded.report.termination, FAS::Stream_surface_termination::MAX_NUMBER_OF_TIME_LINES);
  EXPECT_EQ(unbounded.report.number_of_time_lines, 100u);
  EXPECT_NE(unbounded.report.message.find("no max_time given"), std::string::npos) << unbounded.report.message;

  const Surface vertices(flow, seed, FAS::parameters::max_number_of_vertices(210, FAS::parameters::max_time(6.0, h)));
  EXPECT_EQ(vertices.report.termination, FAS::Stream_surface_termination::MAX_NUMBER_OF_VERTICES);
  EXPECT_EQ(vertices.tm.number_of_vertices(), 210u); // 21 particles on 10 time lines
  EXPECT_NE(vertices.report.message.find("max_number_of_vertices (210)"), std::string::npos);

  // Leaving a box: no particle left before max_time.
  const auto box = [U](const Point_3& p) { return p.x() < 1 ? std::optional<Vector_3>(U) : std::nullopt; };
  const Surface left(box, seed, FAS::parameters::max_time(6.0, h));
  EXPECT_EQ(left.report.termination, FAS::Stream_surface_termination::NO_PARTICLE_LEFT);
  EXPECT_STREQ(FAS::to_string(left.report.termination), "NO_PARTICLE_LEFT");
}

} // namespace

} // namespace test_integrate_stream_surface
