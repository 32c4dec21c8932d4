// The concept FlowField_3 is all that the algorithms ask of a field: each algorithm is
// instantiated with an archetype that has nothing but the concept's operations (a copy
// constructor and `std::optional<Vector_3> operator()(const Point_3&) const`: no default
// constructor, no assignment, no nested types), as CGAL's heat_method_concept.cpp does for its
// traits.  A requirement beyond the concept is a compile error here.  The archetype is a uniform
// flow u, so each run has an answer known without the package: a plane containing u is a
// stream surface (flux 0) and one orthogonal to u has flux 1; the stream lines are straight
// lines along u, the stream surface of a segment is the planar strip it sweeps, and the
// parametrizations of planes are the linear functions with the flow's directions as gradients.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <type_traits>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_FlowField_3_concept {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;
namespace FAS = CGAL::Flow_aligned_surfaces;
namespace PMP = CGAL::Polygon_mesh_processing;

// The archetype: exactly the operations FlowField_3 requires.
class FlowField_3_archetype {
public:
  explicit FlowField_3_archetype(const Vector& velocity) : m_velocity(velocity) {}
  FlowField_3_archetype(const FlowField_3_archetype&) = default;
  FlowField_3_archetype& operator=(const FlowField_3_archetype&) = delete;

  std::optional<Vector> operator()(const Point&) const { return m_velocity; }

private:
  Vector m_velocity;
};

static_assert(std::is_copy_constructible_v<FlowField_3_archetype>);
static_assert(!std::is_default_constructible_v<FlowField_3_archetype>);
static_assert(!std::is_copy_assignable_v<FlowField_3_archetype>);
static_assert(!std::is_move_assignable_v<FlowField_3_archetype>);
static_assert(!std::is_invocable_v<const FlowField_3_archetype&, const Point&, double>);

// The flow's direction (unit, along no axis), a unit normal of the planes that contain it, and
// the third direction of the frame.
const Vector u(1.0 / 3, 2.0 / 3, 2.0 / 3);
const Vector n_along(2 / std::sqrt(5.0), -1 / std::sqrt(5.0), 0);
const Vector w_across = CGAL::cross_product(n_along, u);

FlowField_3_archetype uniform_flow() { return FlowField_3_archetype(u); }

// A 2 x 1 rectangle of about 400 faces through `center`, its width along `axis`.
Mesh make_patch(const Point& center, const Vector& normal, const Vector& axis)
{
  Mesh tm;
  FAS::make_planar_patch(tm, center, normal, 2.0, 1.0, 400, FAS::parameters::patch_axis(axis));
  return tm;
}

// The largest |n_j · d| over the faces of `tm` (the unit face normals n_j).
double max_face_normal_component(const Mesh& tm, const Vector& d)
{
  double largest = 0;
  for (auto f : faces(tm)) {
    const Vector n = PMP::compute_face_normal(f, tm);
    largest = (std::max)(largest, std::abs(CGAL::to_double(n * d)));
  }
  return largest;
}

// The largest distance of a vertex of `tm` to the plane through `p` with unit normal `n`.
double max_distance_to_plane(const Mesh& tm, const Point& p, const Vector& n)
{
  double largest = 0;
  for (auto v : vertices(tm))
    largest = (std::max)(largest, std::abs(CGAL::to_double((tm.point(v) - p) * n)));
  return largest;
}

// The gradient of the affine function that fits `values` at the vertices of `tm` best (least
// squares), and the largest misfit: a misfit at rounding level means `values` is affine.
struct Affine_fit {
  Vector gradient;
  double max_misfit;
};

Affine_fit fit_affine(const Mesh& tm, const Mesh::Property_map<vertex_descriptor, double>& values)
{
  const Eigen::Index m = static_cast<Eigen::Index>(num_vertices(tm));
  Eigen::MatrixXd a(m, 4);
  Eigen::VectorXd b(m);
  Eigen::Index i = 0;
  for (auto v : vertices(tm)) {
    const Point& p = tm.point(v);
    a.row(i) << p.x(), p.y(), p.z(), 1.0;
    b[i] = values[v];
    ++i;
  }
  // The vertices are coplanar: the minimum-norm solution has no component along the normal.
  const Eigen::VectorXd c = a.completeOrthogonalDecomposition().solve(b);
  return {Vector(c[0], c[1], c[2]), (a * c - b).cwiseAbs().maxCoeff()};
}

// Plus or minus one: whether `a` and `b` are equal or opposite, up to `tolerance`.
bool equal_up_to_sign(const Vector& a, const Vector& b, double tolerance)
{
  return std::sqrt(CGAL::to_double((a - b).squared_length())) < tolerance ||
         std::sqrt(CGAL::to_double((a + b).squared_length())) < tolerance;
}

TEST(FlowField3Concept, NormalizedFluxOfPlanesAlongAndAcrossTheFlow)
{
  Mesh along = make_patch(Point(0.3, -0.2, 0.1), n_along, u);
  const Mesh across = make_patch(Point(0.3, -0.2, 0.1), u, n_along);
  EXPECT_NEAR(FAS::normalized_flux(along, uniform_flow()).value.value(), 0.0, 1e-12);
  EXPECT_NEAR(FAS::normalized_flux(across, uniform_flow()).value.value(), 1.0, 1e-12);

  auto face_flux = along.add_property_map<Mesh::Face_index, double>("f:flux", -1).first;
  FAS::compute_face_normalized_flux(along, uniform_flow(), face_flux);
  for (auto f : faces(along))
    EXPECT_NEAR(face_flux[f], 0.0, 1e-12);
}

TEST(FlowField3Concept, AlignToFlowMakesPlanesAlongAndAcrossTheFlow)
{
  // A plane tilted by 30 degrees from the flow turns into a plane containing it (tangential)
  // and into a plane orthogonal to it (orthogonal): a uniform flow has flat solutions only,
  // which reach the paper's criterion (every rotation below 1e-6 rad), so the practical
  // criterion is turned off.
  const Vector tilted = std::cos(CGAL_PI / 6) * n_along + std::sin(CGAL_PI / 6) * u;
  const auto paper_criterion_only = FAS::parameters::convergence_step(0.0);

  Mesh tangential = make_patch(Point(0, 0, 0), tilted, w_across);
  const FAS::Alignment_report t =
      FAS::align_to_flow(tangential, uniform_flow(), FAS::Alignment::TANGENTIAL, paper_criterion_only);
  EXPECT_TRUE(t.converged);
  EXPECT_LT(t.normalized_flux.value.value(), 1e-5);
  EXPECT_LT(max_face_normal_component(tangential, u), 1e-5);

  Mesh orthogonal = make_patch(Point(0, 0, 0), tilted, w_across);
  const FAS::Alignment_report o =
      FAS::align_to_flow(orthogonal, uniform_flow(), FAS::Alignment::ORTHOGONAL, paper_criterion_only);
  EXPECT_TRUE(o.converged);
  EXPECT_GT(o.normalized_flux.value.value(), 1 - 1e-5);
  EXPECT_LT(max_face_normal_component(orthogonal, n_along), 1e-5);
  EXPECT_LT(max_face_normal_component(orthogonal, w_across), 1e-5);
}

TEST(FlowField3Concept, DeformationStepsMovesAndGrowsAcrossTheFlow)
{
  // A stream surface from the start: the deformation leaves it in its plane through rigid
  // moves along the plane, and growing across the flow widens the 2 x 1 rectangle (its long
  // sides along the flow) to 2 x (1 + 2d).
  const Point center(0.5, 0.25, -0.75);
  Mesh tm = make_patch(center, n_along, u);
  const FlowField_3_archetype flow = uniform_flow(); // held by reference: outlives the deformation
  FAS::Flow_aligned_deformation<Mesh, FlowField_3_archetype> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  const FAS::Iteration_report first = deformation.step();
  EXPECT_NEAR(first.normalized_flux.value.value(), 0.0, 1e-12);
  EXPECT_LT(first.max_rotation_angle, 1e-9);

  deformation.translate(0.5 * u);
  deformation.rotate(n_along, 0.3);
  const FAS::Alignment_report run = deformation.run();
  EXPECT_TRUE(run.converged);
  EXPECT_NEAR(run.normalized_flux.value.value(), 0.0, 1e-9);
  EXPECT_LT(max_distance_to_plane(tm, center, n_along), 1e-9);

  // Turned back so that the long sides run along the flow again.
  deformation.rotate(n_along, -0.3);
  const double d = 0.1;
  const FAS::Growth_report grown = deformation.grow(d, FAS::parameters::across_flow(true));
  EXPECT_NEAR(grown.grown_boundary_length, 2 * 2.0, 1e-9);
  EXPECT_NEAR(grown.added_area, 2 * 2.0 * d, 1e-9);
  EXPECT_NEAR(CGAL::to_double(PMP::area(tm)), 2.0 * (1.0 + 2 * d), 1e-9);
  EXPECT_LT(max_distance_to_plane(tm, center, n_along), 1e-9);
  EXPECT_TRUE(deformation.step().converged);
}

TEST(FlowField3Concept, GrowBoundaryAcrossTheFlow)
{
  const double d = 0.2;
  Mesh tm = make_patch(Point(0, 0, 0), n_along, u);
  const FAS::Growth_report grown = FAS::grow_boundary(
      tm, d, FAS::parameters::across_flow(true, FAS::parameters::flow_field(uniform_flow())));
  EXPECT_NEAR(grown.added_area, 2 * 2.0 * d, 1e-9);
  EXPECT_NEAR(CGAL::to_double(PMP::area(tm)), 2.0 * (1.0 + 2 * d), 1e-9);
}

TEST(FlowField3Concept, ParametrizationsOfPlanesAreLinear)
{
  // Tangential, normalized: r grows at unit rate along the flow, s across it.
  Mesh along = make_patch(Point(0, 0, 0), n_along, u);
  auto r = along.add_property_map<vertex_descriptor, double>("v:r", 0).first;
  auto s = along.add_property_map<vertex_descriptor, double>("v:s", 0).first;
  FAS::parametrize_tangential(along, uniform_flow(), r, s, FAS::parameters::normalized(true));
  const Affine_fit rt = fit_affine(along, r), st = fit_affine(along, s);
  EXPECT_LT(rt.max_misfit, 1e-9);
  EXPECT_LT(st.max_misfit, 1e-9);
  EXPECT_TRUE(equal_up_to_sign(rt.gradient, u, 1e-9));
  EXPECT_TRUE(equal_up_to_sign(st.gradient, w_across, 1e-9));

  // The deformation's own parametrization of the same plane agrees with the free function's up
  // to its soft constraint (a relative difference of the order of 1e-3 h / diameter).
  const FlowField_3_archetype flow = uniform_flow();
  FAS::Flow_aligned_deformation<Mesh, FlowField_3_archetype> deformation(along, flow, FAS::Alignment::TANGENTIAL);
  auto r2 = along.add_property_map<vertex_descriptor, double>("v:r2", 0).first;
  auto s2 = along.add_property_map<vertex_descriptor, double>("v:s2", 0).first;
  deformation.parametrize_tangential(r2, s2);
  EXPECT_TRUE(equal_up_to_sign(fit_affine(along, r2).gradient, u, 1e-3));

  // Orthogonal, on a plane across the flow: r and s are linear with orthogonal gradients of
  // the flow's speed (1), in the plane.
  Mesh across = make_patch(Point(0, 0, 0), u, n_along);
  auto ro = across.add_property_map<vertex_descriptor, double>("v:r", 0).first;
  auto so = across.add_property_map<vertex_descriptor, double>("v:s", 0).first;
  FAS::parametrize_orthogonal(across, uniform_flow(), ro, so, FAS::parameters::angle(0.4));
  const Affine_fit ro_fit = fit_affine(across, ro), so_fit = fit_affine(across, so);
  EXPECT_LT(ro_fit.max_misfit, 1e-9);
  EXPECT_LT(so_fit.max_misfit, 1e-9);
  EXPECT_NEAR(std::sqrt(CGAL::to_double(ro_fit.gradient.squared_length())), 1.0, 1e-9);
  EXPECT_NEAR(std::sqrt(CGAL::to_double(so_fit.gradient.squared_length())), 1.0, 1e-9);
  EXPECT_NEAR(CGAL::to_double(ro_fit.gradient * so_fit.gradient), 0.0, 1e-9);
  EXPECT_NEAR(CGAL::to_double(ro_fit.gradient * u), 0.0, 1e-9);

  // The angle statistics of the tangential r: the gradient is the flow, 0 degrees everywhere.
  const FAS::Alignment_angle_statistics stats = FAS::alignment_angle_statistics(along, uniform_flow(), r);
  EXPECT_EQ(stats.number_of_faces, num_faces(along));
  EXPECT_NEAR(stats.mean, 0.0, 1e-5);
}

TEST(FlowField3Concept, FlowTextureMaskFollowsTheFlow)
{
  // r = u·p has its gradient along the flow (mask 0); r = w·p across it (mask 1).
  Mesh tm = make_patch(Point(0, 0, 0), n_along, u);
  auto along = tm.add_property_map<vertex_descriptor, double>("v:along", 0).first;
  auto across = tm.add_property_map<vertex_descriptor, double>("v:across", 0).first;
  for (auto v : vertices(tm)) {
    along[v] = CGAL::to_double((tm.point(v) - CGAL::ORIGIN) * u);
    across[v] = CGAL::to_double((tm.point(v) - CGAL::ORIGIN) * w_across);
  }
  auto mask = tm.add_property_map<Mesh::Face_index, double>("f:mask", -1).first;
  FAS::compute_flow_texture_mask(tm, uniform_flow(), along, mask);
  for (auto f : faces(tm))
    EXPECT_NEAR(mask[f], 0.0, 1e-9);
  FAS::compute_flow_texture_mask(tm, uniform_flow(), across, mask);
  for (auto f : faces(tm))
    EXPECT_NEAR(mask[f], 1.0, 1e-9);
}

TEST(FlowField3Concept, StreamlineIsAStraightLine)
{
  const Point seed(0.1, -0.4, 0.3);
  std::vector<Point> line;
  const FAS::Streamline_report report = FAS::integrate_streamline(
      uniform_flow(), seed, std::back_inserter(line),
      FAS::parameters::max_length(3.0, FAS::parameters::integration_direction(FAS::Integration_direction::BOTH)));
  EXPECT_EQ(report.forward.termination, FAS::Streamline_termination::MAX_LENGTH);
  EXPECT_EQ(report.backward.termination, FAS::Streamline_termination::MAX_LENGTH);
  EXPECT_NEAR(report.length(), 6.0, 1e-9);
  ASSERT_EQ(line.size(), report.number_of_points);
  ASSERT_GE(line.size(), 3u);
  for (const Point& p : line) {
    const Vector off_line = CGAL::cross_product(p - seed, u);
    EXPECT_LT(std::sqrt(CGAL::to_double(off_line.squared_length())), 1e-9);
  }
  // The ends are 3 upstream and 3 downstream.
  EXPECT_NEAR(CGAL::to_double((line.front() - seed) * u), -3.0, 1e-9);
  EXPECT_NEAR(CGAL::to_double((line.back() - seed) * u), 3.0, 1e-9);
}

TEST(FlowField3Concept, StreamSurfaceOfASegmentIsTheStripItSweeps)
{
  // A seed segment of length 1 across the flow, swept for the time 2 at speed 1: the 1 x 2
  // rectangle in the plane containing the segment and u.
  const Point a(0.0, 0.0, 0.0);
  const std::vector<Point> seed = {a, a + w_across};
  Mesh tm;
  const FAS::Stream_surface_report report =
      FAS::integrate_stream_surface(uniform_flow(), seed, tm,
                                    FAS::parameters::max_time(2.0, FAS::parameters::front_spacing(0.1)));
  EXPECT_EQ(report.termination, FAS::Stream_surface_termination::MAX_INTEGRATION_TIME);
  EXPECT_NEAR(report.final_parameter, 2.0, 1e-12);
  EXPECT_EQ(report.number_of_lost_particles, 0u);
  EXPECT_GT(num_faces(tm), 0u);
  EXPECT_LT(max_distance_to_plane(tm, a, n_along), 1e-9);
  EXPECT_NEAR(CGAL::to_double(PMP::area(tm)), 1.0 * 2.0, 1e-9);
  EXPECT_NEAR(FAS::normalized_flux(tm, uniform_flow()).value.value(), 0.0, 1e-9);
}

TEST(FlowField3Concept, SampledOnAGridTheFieldAnswersTheSame)
{
  const FAS::Regular_grid_flow_field_3<K> grid =
      FAS::sample_on_grid(uniform_flow(), Point(-1, -1, -1), Vector(0.5, 0.5, 0.5), {5, 5, 5});
  const std::optional<Vector> v = grid(Point(0.3, -0.2, 0.7));
  ASSERT_TRUE(v.has_value());
  // The nodes hold 32-bit floats.
  EXPECT_LT(std::sqrt(CGAL::to_double((*v - u).squared_length())), 1e-7);
}

} // namespace

} // namespace test_FlowField_3_concept
