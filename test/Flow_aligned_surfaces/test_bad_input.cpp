// Bad input to Flow_aligned_deformation, align_to_flow and normalized_flux: broken meshes
// and parameters get a std::invalid_argument whose message names the input and what is
// wrong, and the mesh is left as it was; broken flow samples never reach the mesh; and a
// mesh of several components aligns every component.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Surface_mesh.h>

#include "expect_invalid_argument.h"
#include "planar_patch_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_bad_input {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

using Field = std::function<std::optional<Vector>(const Point&)>;
using Deformation = FAS::Flow_aligned_deformation<Mesh, Field>;

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

Field point_source()
{
  return FAS::Point_source_flow<K>(Point(0, 0, 0), 1.0);
}

using fas_test::planar_patch;

// The vertex positions and the combinatorics, to check that a failed call left the mesh alone.
struct Snapshot {
  std::size_t vertices, faces;
  std::vector<Point> points;
  explicit Snapshot(const Mesh& tm) : vertices(tm.number_of_vertices()), faces(tm.number_of_faces())
  {
    for (auto v : tm.vertices())
      points.push_back(tm.point(v));
  }
};

void expect_unchanged(const Snapshot& before, const Mesh& tm)
{
  const Snapshot after(tm);
  ASSERT_EQ(after.vertices, before.vertices);
  ASSERT_EQ(after.faces, before.faces);
  ASSERT_EQ(after.points.size(), before.points.size());
  for (std::size_t i = 0; i < before.points.size(); ++i) {
    // Bitwise: NaN coordinates given by the test must stay NaN, finite ones must not move.
    for (int d = 0; d < 3; ++d) {
      const double b = before.points[i][d], a = after.points[i][d];
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << "vertex " << i << " coordinate " << d;
    }
  }
}

// The three entry points on a bad mesh: each throws with `parts` in its message and leaves
// the mesh as it was.
void expect_every_entry_point_rejects(Mesh& tm, std::initializer_list<std::string> parts)
{
  const Snapshot before(tm);
  const Field field = point_source();
  expect_invalid_argument([&] { Deformation(tm, field, FAS::Alignment::ORTHOGONAL); }, parts);
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { FAS::align_to_flow(tm, field, FAS::Alignment::TANGENTIAL); }, parts);
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { FAS::normalized_flux(tm, field); }, parts);
  expect_unchanged(before, tm);
}

// ---------------------------------------------------------------------------------------------
// Broken meshes

TEST(BadInput, EmptyMesh)
{
  Mesh tm;
  expect_every_entry_point_rejects(tm, {"tm:", "no faces"});
}

TEST(BadInput, MeshWithVerticesButNoFaces)
{
  Mesh tm;
  tm.add_vertex(Point(0, 0, 0));
  tm.add_vertex(Point(1, 0, 0));
  expect_every_entry_point_rejects(tm, {"tm:", "no faces"});
}

TEST(BadInput, QuadFace)
{
  // A valid triangle patch, then a separate quad: the quad is the last face.
  Mesh tm = planar_patch(Point(0, 0, 2), Vector(0, 0, 1), 1.0, 50);
  const std::size_t quad = tm.number_of_faces();
  const auto a = tm.add_vertex(Point(3, 0, 2)), b = tm.add_vertex(Point(4, 0, 2)),
             c = tm.add_vertex(Point(4, 1, 2)), d = tm.add_vertex(Point(3, 1, 2));
  ASSERT_NE(tm.add_face(a, b, c, d), Mesh::null_face());
  expect_every_entry_point_rejects(tm,
                                   {"tm:", "face " + std::to_string(quad) + " has 4 vertices", "triangle"});
}

// Two triangles, the second one flat: its third vertex lies on the shared edge's line.
Mesh mesh_with_degenerate_face()
{
  Mesh tm;
  const auto a = tm.add_vertex(Point(0, 0, 2)), b = tm.add_vertex(Point(2, 0, 2)),
             c = tm.add_vertex(Point(0, 1, 2)), d = tm.add_vertex(Point(1, 0, 2));
  tm.add_face(a, b, c);
  tm.add_face(b, a, d);
  return tm;
}

TEST(BadInput, DegenerateFaceIsRejectedByTheDeformation)
{
  Mesh tm = mesh_with_degenerate_face();
  ASSERT_EQ(tm.number_of_faces(), 2u);
  const Snapshot before(tm);
  const Field field = point_source();
  expect_invalid_argument([&] { Deformation(tm, field, FAS::Alignment::ORTHOGONAL); },
                          {"tm:", "face 1", "degenerate"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { FAS::align_to_flow(tm, field, FAS::Alignment::ORTHOGONAL); },
                          {"tm:", "face 1", "degenerate"});
  expect_unchanged(before, tm);
}

TEST(BadInput, DegenerateFaceHasNoWeightInTheFlux)
{
  // A zero-area face has no normal, and no weight in f_n: the flux is that of face 0 alone,
  // |n . v| / |v| = 0.8 for n = z and v = (0.6, 0, 0.8).
  const Mesh tm = mesh_with_degenerate_face();
  const auto field = [](const Point&) -> std::optional<Vector> { return Vector(0.6, 0, 0.8); };
  EXPECT_NEAR(FAS::normalized_flux(tm, field).value.value(), 0.8, 1e-15);
}

TEST(BadInput, NonManifoldVertex)
{
  // Two triangles sharing vertex 0 only: a bow tie, whose vertex 0 has two fans.
  Mesh tm;
  const auto o = tm.add_vertex(Point(0, 0, 2));
  const auto a = tm.add_vertex(Point(1, 0, 2)), b = tm.add_vertex(Point(1, 1, 2));
  const auto c = tm.add_vertex(Point(-1, 0, 2)), d = tm.add_vertex(Point(-1, -1, 2));
  ASSERT_NE(tm.add_face(o, a, b), Mesh::null_face());
  ASSERT_NE(tm.add_face(o, c, d), Mesh::null_face());
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  expect_every_entry_point_rejects(tm, {"tm:", "vertex 0", "non-manifold"});
}

TEST(BadInput, NonManifoldVertexBetweenTwoPatches)
{
  // Two fans of a real patch glued at one corner vertex.
  Mesh tm;
  const auto o = tm.add_vertex(Point(0, 0, 2));
  std::vector<Mesh::Vertex_index> ring;
  for (int k = 0; k < 8; ++k) {
    const double angle = (k < 4 ? 0.0 : CGAL_PI) + 0.4 * (k % 4);
    ring.push_back(tm.add_vertex(Point(std::cos(angle), std::sin(angle), 2)));
  }
  for (int k = 0; k < 3; ++k) {
    ASSERT_NE(tm.add_face(o, ring[k], ring[k + 1]), Mesh::null_face());
    ASSERT_NE(tm.add_face(o, ring[4 + k], ring[5 + k]), Mesh::null_face());
  }
  expect_every_entry_point_rejects(tm, {"tm:", "vertex 0", "non-manifold"});
}

TEST(BadInput, IsolatedVertex)
{
  Mesh tm = planar_patch(Point(0, 0, 2), Vector(0, 0, 1), 1.0, 50);
  const std::size_t isolated = tm.number_of_vertices();
  tm.add_vertex(Point(5, 5, 5));
  expect_every_entry_point_rejects(tm, {"tm:", "vertex " + std::to_string(isolated), "isolated"});
}

TEST(BadInput, VertexWithNonFiniteCoordinate)
{
  // A NaN position makes the areas and the operators NaN: it must be refused, and the message
  // must say what is wrong (not, for instance, "zero area").
  for (const double bad : {nan, inf}) {
    Mesh tm = planar_patch(Point(0, 0, 2), Vector(0, 0, 1), 1.0, 50);
    const auto v = *std::next(tm.vertices().begin(), 7);
    tm.point(v) = Point(tm.point(v).x(), bad, tm.point(v).z());
    const Snapshot before(tm);
    const Field field = point_source();
    expect_invalid_argument([&] { Deformation(tm, field, FAS::Alignment::ORTHOGONAL); },
                            {"tm:", "vertex 7", "finite"});
    expect_unchanged(before, tm);
    expect_invalid_argument([&] { FAS::align_to_flow(tm, field, FAS::Alignment::ORTHOGONAL); },
                            {"tm:", "vertex 7", "finite"});
    expect_unchanged(before, tm);
  }
}

// ---------------------------------------------------------------------------------------------
// Parameters out of range

template <class NamedParameters>
void expect_parameter_rejected(const NamedParameters& np, const std::string& name)
{
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 100);
  const Snapshot before(tm);
  const Field field = point_source();
  SCOPED_TRACE(name);
  expect_invalid_argument([&] { Deformation(tm, field, FAS::Alignment::ORTHOGONAL, np); },
                          {"parameter " + name, "out of range"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { FAS::align_to_flow(tm, field, FAS::Alignment::ORTHOGONAL, np); },
                          {"parameter " + name, "out of range"});
  expect_unchanged(before, tm);
}

TEST(BadInput, MaxRotationAngleOutOfRange)
{
  // η must lie in (0, π].
  for (const double eta : {0.0, -0.1, nan, inf, -inf, 3.2})
    expect_parameter_rejected(FAS::parameters::max_rotation_angle(eta), "max_rotation_angle");
}

TEST(BadInput, ConvergenceAngleOutOfRange)
{
  for (const double epsilon : {-1e-6, nan, inf})
    expect_parameter_rejected(FAS::parameters::convergence_angle(epsilon), "convergence_angle");
}

TEST(BadInput, ConvergenceStepOutOfRange)
{
  for (const double step : {-1e-4, nan, inf})
    expect_parameter_rejected(FAS::parameters::convergence_step(step), "convergence_step");
}

TEST(BadInput, MaxDihedralAngleOutOfRange)
{
  // θmax must lie in (0, π].
  for (const double theta : {0.0, -1.0, nan, inf, 3.2})
    expect_parameter_rejected(FAS::parameters::max_dihedral_angle(theta), "max_dihedral_angle");
}

TEST(BadInput, ConstraintWeightOutOfRange)
{
  for (const double weight : {0.0, -1e-3, nan, inf})
    expect_parameter_rejected(FAS::parameters::constraint_weight(weight), "constraint_weight");
}

TEST(BadInput, BadParameterAmongGoodOnesIsFound)
{
  // Chained onto CGAL's own parameters, and with other package parameters in range.
  expect_parameter_rejected(
      FAS::parameters::max_rotation_angle(
          0.05, FAS::parameters::max_dihedral_angle(-0.5, CGAL::parameters::number_of_iterations(10))),
      "max_dihedral_angle");
}

TEST(BadInput, BoundaryValuesOfTheParametersAreAccepted)
{
  // The closed ends of the ranges: η = θmax = π, ε = 0, convergence_step = 0 (rule disabled).
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 100);
  const Field field = point_source();
  const auto np = FAS::parameters::max_rotation_angle(
      CGAL_PI,
      FAS::parameters::max_dihedral_angle(
          CGAL_PI,
          FAS::parameters::convergence_angle(
              0.0, FAS::parameters::convergence_step(0.0, CGAL::parameters::number_of_iterations(3)))));
  const FAS::Alignment_report report = FAS::align_to_flow(tm, field, FAS::Alignment::ORTHOGONAL, np);
  EXPECT_EQ(report.number_of_iterations, 3u);
  EXPECT_GT(report.normalized_flux.value.value(), 0.9);
}

// ---------------------------------------------------------------------------------------------
// Rigid moves with bad arguments

TEST(BadInput, RotateAboutZeroOrNonFiniteAxisThrowsAndKeepsTheMesh)
{
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 200);
  const Field field = point_source();
  Deformation deformation(tm, field, FAS::Alignment::ORTHOGONAL);
  deformation.step();
  const Snapshot before(tm);
  expect_invalid_argument([&] { deformation.rotate(Vector(0, 0, 0), 0.3); }, {"rotate", "axis", "non-zero"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { deformation.rotate(Point(0, 0, 0), Vector(0, 0, 0), 0.3); },
                          {"rotate", "axis", "non-zero"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { deformation.rotate(Vector(nan, 0, 1), 0.3); }, {"rotate", "axis", "finite"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { deformation.rotate(Vector(0, 0, 1), inf); }, {"rotate", "angle", "finite"});
  expect_unchanged(before, tm);
  // The deformation still works afterwards.
  EXPECT_GE(deformation.run().normalized_flux.value.value(), 0.995);
}

TEST(BadInput, RigidMovesWithNonFiniteArgumentsThrowAndKeepTheMesh)
{
  // A NaN translation or rotation center would write NaN into every vertex.
  Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 200);
  const Field field = point_source();
  Deformation deformation(tm, field, FAS::Alignment::ORTHOGONAL);
  const Snapshot before(tm);
  expect_invalid_argument([&] { deformation.translate(Vector(nan, 0, 0)); }, {"translate", "finite"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { deformation.translate(Vector(0, inf, 0)); }, {"translate", "finite"});
  expect_unchanged(before, tm);
  expect_invalid_argument([&] { deformation.rotate(Point(0, nan, 0), Vector(0, 0, 1), 0.3); },
                          {"rotate", "center", "finite"});
  expect_unchanged(before, tm);
}

// ---------------------------------------------------------------------------------------------
// Broken and missing flow samples

TEST(BadInput, FieldNonFiniteEverywhereLeavesTheSurfaceInPlace)
{
  // Every sample invalid: T = I everywhere, the soft constraints at the current positions, so
  // X_k is a fixed point and the paper's rule (no rotation requested) stops at once.
  for (const double bad : {nan, inf, -inf}) {
    const Field broken = [bad](const Point&) -> std::optional<Vector> { return Vector(0.1, bad, 1.0); };
    Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 500);
    const Snapshot before(tm);
    Deformation deformation(tm, broken, FAS::Alignment::ORTHOGONAL);
    const FAS::Iteration_report first = deformation.step();
    EXPECT_EQ(first.number_of_invalid_samples, tm.number_of_faces());
    EXPECT_EQ(first.number_of_outside_samples, 0u);
    EXPECT_EQ(first.number_of_zero_samples, 0u);
    EXPECT_EQ(first.max_rotation_angle, 0.0);
    // No face is sampled: no flux value, not 0 ("tangential").
    EXPECT_FALSE(first.normalized_flux.value.has_value());
    EXPECT_EQ(first.normalized_flux.sampled_area_fraction, 0.0);
    EXPECT_TRUE(first.converged);
    std::size_t i = 0;
    for (auto v : tm.vertices())
      EXPECT_LT(std::sqrt((tm.point(v) - before.points[i++]).squared_length()), 1e-9);
    EXPECT_FALSE(FAS::normalized_flux(tm, broken).value.has_value());
  }
}

TEST(BadInput, NonFiniteSamplesHaveNoWeightInTheFlux)
{
  // Flat patch in z = const; v = (0.6, 0, 0.8) where x < 0, NaN elsewhere: the faces with a
  // valid sample have |n . v| / |v| = 0.8, so f_n = 0.8 whatever the share of broken faces.
  const Mesh tm = planar_patch(Point(0, 0, 0), Vector(0, 0, 1), 1.0, 400);
  const auto half_broken = [](const Point& p) -> std::optional<Vector> {
    if (p.x() < 0)
      return Vector(0.6, 0, 0.8);
    return Vector(nan, nan, nan);
  };
  const FAS::Normalized_flux flux = FAS::normalized_flux(tm, half_broken);
  EXPECT_NEAR(flux.value.value(), 0.8, 1e-12);
  EXPECT_GT(flux.sampled_area_fraction, 0.4);
  EXPECT_LT(flux.sampled_area_fraction, 0.6);
}

TEST(BadInput, HugeAndTinyFiniteVectors)
{
  // Only the direction of a sample matters: 1e300 (whose squared norm overflows) aligns like a
  // unit vector; a subnormal vector (1e-310) is a zero sample, like v = 0.
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  const Field huge = [source](const Point& p) -> std::optional<Vector> { return *source(p) * 1e300; };
  const Field tiny = [](const Point&) -> std::optional<Vector> { return Vector(1e-310, 0, 0); };
  Mesh reference = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 500);
  Mesh scaled = reference;
  const FAS::Alignment_report expected = FAS::align_to_flow(reference, source, FAS::Alignment::ORTHOGONAL);
  const FAS::Alignment_report report = FAS::align_to_flow(scaled, huge, FAS::Alignment::ORTHOGONAL);
  EXPECT_GE(report.normalized_flux.value.value(), 0.995);
  EXPECT_EQ(report.number_of_iterations, expected.number_of_iterations);
  EXPECT_NEAR(report.normalized_flux.value.value(), expected.normalized_flux.value.value(), 1e-12);
  for (auto v : reference.vertices())
    EXPECT_LT(std::sqrt((scaled.point(v) - reference.point(v)).squared_length()), 1e-9);

  Mesh still = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 200);
  Deformation deformation(still, tiny, FAS::Alignment::TANGENTIAL);
  const FAS::Iteration_report first = deformation.step();
  EXPECT_EQ(first.number_of_zero_samples, still.number_of_faces());
  EXPECT_TRUE(first.converged);
  EXPECT_FALSE(FAS::normalized_flux(still, tiny).value.has_value());
  EXPECT_FALSE(first.normalized_flux.value.has_value());
}

TEST(BadInput, FieldOutsideEverywhereConvergesImmediatelyAndLeavesTheSurface)
{
  const Field nowhere = [](const Point&) -> std::optional<Vector> { return std::nullopt; };
  for (const FAS::Alignment alignment : {FAS::Alignment::ORTHOGONAL, FAS::Alignment::TANGENTIAL}) {
    Mesh tm = planar_patch(Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 500);
    const Snapshot before(tm);
    std::vector<FAS::Iteration_report> reports;
    const FAS::Alignment_report report = FAS::align_to_flow(
        tm, nowhere, alignment,
        CGAL::parameters::visitor([&](const FAS::Iteration_report& r) { reports.push_back(r); }));
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.number_of_iterations, 1u);
    EXPECT_FALSE(report.normalized_flux.value.has_value()) << "no face sampled: no flux, not 0";
    EXPECT_EQ(report.normalized_flux.sampled_area_fraction, 0.0);
    EXPECT_EQ(report.max_rotation_angle, 0.0);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_EQ(reports[0].number_of_outside_samples, tm.number_of_faces());
    EXPECT_EQ(reports[0].number_of_folds, 0u);
    std::size_t i = 0;
    for (auto v : tm.vertices())
      EXPECT_LT(std::sqrt((tm.point(v) - before.points[i++]).squared_length()), 1e-9);
    EXPECT_FALSE(FAS::normalized_flux(tm, nowhere).value.has_value());
  }
}

// ---------------------------------------------------------------------------------------------
// Several connected components

// f_n over the faces [first, last) of `tm`, computed here from its definition.
template <class Flow>
double flux_of_faces(const Mesh& tm, const Flow& flow, std::size_t first, std::size_t last)
{
  double flux = 0, area = 0;
  for (auto f : tm.faces()) {
    if (std::size_t(f) < first || std::size_t(f) >= last)
      continue;
    std::vector<Point> p;
    for (auto v : vertices_around_face(tm.halfedge(f), tm))
      p.push_back(tm.point(v));
    const Vector cross = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const Vector v = *flow(CGAL::centroid(p[0], p[1], p[2]));
    flux += 0.5 * std::abs(cross * v) / std::sqrt(v.squared_length());
    area += 0.5 * std::sqrt(cross.squared_length());
  }
  return flux / area;
}

struct Radius_statistics {
  double mean = 0, spread = 0;
};

Radius_statistics radii(const Mesh& tm, std::size_t first_vertex, std::size_t last_vertex)
{
  double lo = inf, hi = -inf, sum = 0;
  for (std::size_t i = first_vertex; i < last_vertex; ++i) {
    const double r = std::sqrt((tm.point(Mesh::Vertex_index(i)) - CGAL::ORIGIN).squared_length());
    lo = (std::min)(lo, r);
    hi = (std::max)(hi, r);
    sum += r;
  }
  return {sum / double(last_vertex - first_vertex), hi - lo};
}

TEST(BadInput, DisconnectedMeshAlignsEveryComponent)
{
  // Two patches around a point source, one above and one below it: each must become a piece
  // of a sphere, each near its own radius (2 and 3), which needs one constrained face per
  // component (a single one would leave the other component's translation free).
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0.2, -0.1, 2.0), Vector(0.3, 0.2, 1.0), 1.0, 1.0, 800);
  const std::size_t faces_a = tm.number_of_faces(), vertices_a = tm.number_of_vertices();
  FAS::make_planar_patch(tm, Point(-0.3, 0.2, -3.0), Vector(-0.2, 0.4, 1.0), 1.2, 1.2, 800);
  const std::size_t faces_b = tm.number_of_faces(), vertices_b = tm.number_of_vertices();
  ASSERT_LT(flux_of_faces(tm, source, 0, faces_a), 0.97);
  ASSERT_LT(flux_of_faces(tm, source, faces_a, faces_b), 0.97);

  FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>> deformation(tm, source,
                                                                             FAS::Alignment::ORTHOGONAL);
  const FAS::Alignment_report report = deformation.run();
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(deformation.number_of_factorizations(), 1u);
  EXPECT_GE(flux_of_faces(tm, source, 0, faces_a), 0.995);
  EXPECT_GE(flux_of_faces(tm, source, faces_a, faces_b), 0.995);
  EXPECT_NEAR(FAS::normalized_flux(tm, source).value.value(), report.normalized_flux.value.value(), 1e-12);

  const Radius_statistics a = radii(tm, 0, vertices_a), b = radii(tm, vertices_a, vertices_b);
  EXPECT_LE(a.spread / a.mean, 1e-3);
  EXPECT_LE(b.spread / b.mean, 1e-3);
  EXPECT_NEAR(a.mean, 2.0, 0.1);
  EXPECT_NEAR(b.mean, 3.0, 0.15);
}

TEST(BadInput, DisconnectedMeshAlignsEveryComponentTangentially)
{
  // Helical flow: both patches become pieces of cylinders around z, at their own radii.
  const FAS::Helical_flow<K> helix(0.5);
  Mesh tm;
  FAS::make_planar_patch(tm, Point(1.0, 0.2, 0.0), Vector(1.0, 0.3, 0.2), 0.8, 0.8, 800);
  const std::size_t faces_a = tm.number_of_faces();
  FAS::make_planar_patch(tm, Point(-0.3, -2.0, 0.5), Vector(0.2, 1.0, -0.3), 0.8, 0.8, 800);
  const std::size_t faces_b = tm.number_of_faces();
  ASSERT_GT(flux_of_faces(tm, helix, 0, faces_a), 0.05);
  ASSERT_GT(flux_of_faces(tm, helix, faces_a, faces_b), 0.05);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, helix, FAS::Alignment::TANGENTIAL);
  EXPECT_TRUE(report.converged);
  EXPECT_LE(flux_of_faces(tm, helix, 0, faces_a), 0.01);
  EXPECT_LE(flux_of_faces(tm, helix, faces_a, faces_b), 0.01);
}

} // namespace

} // namespace test_bad_input
