// Growing at the boundary (grow_boundary.h, Flow_aligned_deformation::grow()) against closed
// forms: a rectangle grown by d is the rectangle (W + 2d) x (H + 2d), a disk of radius R gains
// pi ((R + d)^2 - R^2), a side grown alone moves by d; aligned surfaces stay on their exact
// sphere or stream surface after growing and re-converging; M_0 follows M_k rigidly.

#ifdef FAS_HAVE_OPENMESH
// As in test_mesh_types.cpp: OpenMesh's add_vertex copies a deliberately uninitialized point,
// which GCC reports at -O2 inside the standard headers, so the pragma precedes them.
// Pushed here and popped after the includes, so that it reaches no file compiled after this
// one in a unity batch.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#endif

#include "expect_invalid_argument.h"
#include "triangle_angles.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#ifdef FAS_HAVE_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#if defined(FAS_HAVE_OPENMESH) && defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_grow_boundary {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;
namespace PMP = CGAL::Polygon_mesh_processing;

// A W x H rectangle in the plane z = 0 centered at the origin, width along x.
Mesh rectangle(double width, double height, std::size_t faces)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), width, height, faces,
                         FAS::parameters::patch_axis(Vector(1, 0, 0)));
  return tm;
}

using fas_test::smallest_angle_degrees;

// Faces added after the first `old_faces` (Surface_mesh appends, and growing removes nothing).
double smallest_new_angle(const Mesh& tm, std::size_t old_faces)
{
  double smallest = 180;
  for (auto f : tm.faces())
    if (std::size_t(f) >= old_faces)
      smallest = (std::min)(smallest, smallest_angle_degrees(tm, f));
  return smallest;
}

void expect_valid_surface(const Mesh& tm)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  EXPECT_TRUE(CGAL::is_triangle_mesh(tm));
  EXPECT_FALSE(tm.has_garbage()) << "growing must not leave removed elements behind";
  std::vector<Mesh::Halfedge_index> non_manifold;
  PMP::non_manifold_vertices(tm, std::back_inserter(non_manifold));
  EXPECT_TRUE(non_manifold.empty());
  EXPECT_FALSE(PMP::does_self_intersect(tm));
  std::vector<Mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(tm, std::back_inserter(borders));
  EXPECT_EQ(borders.size(), 1u) << "the grown patch stays a disk";
}

TEST(GrowBoundary, RectangleGrowsIntoTheLargerRectangle)
{
  const double W = 2.0, H = 1.0, d = 0.1;
  Mesh tm = rectangle(W, H, 2000);
  const std::size_t old_faces = tm.number_of_faces();
  const FAS::Growth_report report = FAS::grow_boundary(tm, d);
  EXPECT_NEAR(report.grown_boundary_length, 2 * (W + H), 1e-9);
  EXPECT_NEAR(report.added_area, (W + 2 * d) * (H + 2 * d) - W * H, 1e-9);
  EXPECT_NEAR(report.added_area / (d * report.grown_boundary_length), 1.0, 0.1);
  EXPECT_NEAR(PMP::area(tm), (W + 2 * d) * (H + 2 * d), 1e-9);
  EXPECT_EQ(tm.number_of_faces(), old_faces + report.number_of_new_faces);
  const CGAL::Bbox_3 box = PMP::bbox(tm);
  EXPECT_NEAR(box.xmin(), -W / 2 - d, 1e-12);
  EXPECT_NEAR(box.xmax(), W / 2 + d, 1e-12);
  EXPECT_NEAR(box.ymin(), -H / 2 - d, 1e-12);
  EXPECT_NEAR(box.ymax(), H / 2 + d, 1e-12);
  EXPECT_NEAR(box.zmin(), 0, 1e-12);
  EXPECT_NEAR(box.zmax(), 0, 1e-12);
  EXPECT_GE(smallest_new_angle(tm, old_faces), 20.0);
  expect_valid_surface(tm);
}

// A strip many edges wide is tessellated inside too, not only along the boundary.
TEST(GrowBoundary, WideStripIsTessellatedWithNearRegularTriangles)
{
  const double W = 1.0, H = 0.8, d = 0.5;
  Mesh tm = rectangle(W, H, 400);
  const std::size_t old_faces = tm.number_of_faces();
  const FAS::Growth_report report = FAS::grow_boundary(tm, d);
  EXPECT_NEAR(PMP::area(tm), (W + 2 * d) * (H + 2 * d), 1e-9);
  // The strip is about 3.3 times the patch's area, and so about as many faces.
  EXPECT_GT(report.number_of_new_faces, 2 * old_faces);
  EXPECT_GE(smallest_new_angle(tm, old_faces), 20.0);
  expect_valid_surface(tm);
}

TEST(GrowBoundary, DiskGainsTheAnnulusArea)
{
  const double R = 1.0, d = 0.15;
  Mesh tm;
  FAS::make_disk_patch(tm, Point(0.5, -0.2, 0.3), Vector(1, 2, 3), R, 3000);
  const std::size_t old_faces = tm.number_of_faces();
  const FAS::Growth_report report = FAS::grow_boundary(tm, d);
  // The disk patch is the inscribed polygon (N_K sides, ~ 2 pi R over the edge length): the
  // annulus area is met to O((pi / N_K)^2).
  EXPECT_NEAR(report.added_area / (CGAL_PI * ((R + d) * (R + d) - R * R)), 1.0, 0.01);
  EXPECT_NEAR(report.grown_boundary_length / (2 * CGAL_PI * R), 1.0, 0.01);
  EXPECT_NEAR(report.added_area / (d * report.grown_boundary_length), 1.0, 0.1);
  EXPECT_NEAR(PMP::area(tm) / (CGAL_PI * (R + d) * (R + d)), 1.0, 0.01);
  for (auto h : tm.halfedges())
    if (tm.is_border(h)) {
      const double r = std::sqrt((tm.point(tm.target(h)) - Point(0.5, -0.2, 0.3)).squared_length());
      EXPECT_NEAR(r, R + d, 0.01 * d);
    }
  EXPECT_GE(smallest_new_angle(tm, old_faces), 20.0);
  expect_valid_surface(tm);
}

TEST(GrowBoundary, GrowthDirectionGrowsOnlyTheSideFacingIt)
{
  const double W = 1.0, H = 1.5, d = 0.2;
  Mesh tm = rectangle(W, H, 1500);
  const std::size_t old_faces = tm.number_of_faces();
  // Tilted out of the plane: only its in-plane part (+x) counts.
  const FAS::Growth_report report =
      FAS::grow_boundary(tm, d, FAS::parameters::growth_direction(Vector(1, 0.3, 2.0)));
  EXPECT_NEAR(report.grown_boundary_length, H, 1e-9);
  EXPECT_NEAR(report.added_area, d * H, 1e-9);
  const CGAL::Bbox_3 box = PMP::bbox(tm);
  EXPECT_NEAR(box.xmin(), -W / 2, 1e-12);
  EXPECT_NEAR(box.xmax(), W / 2 + d, 1e-12);
  EXPECT_NEAR(box.ymin(), -H / 2, 1e-12);
  EXPECT_NEAR(box.ymax(), H / 2, 1e-12);
  EXPECT_GE(smallest_new_angle(tm, old_faces), 20.0);
  expect_valid_surface(tm);
}

TEST(GrowBoundary, DiskGrownTowardADirectionGrowsTheArcWithin60Degrees)
{
  const double R = 1.0, d = 0.1;
  Mesh tm;
  FAS::make_disk_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), R, 2000);
  const FAS::Growth_report report =
      FAS::grow_boundary(tm, d, FAS::parameters::growth_direction(Vector(0, 1, 0)));
  // The arc of outward directions within 60 degrees of +y: a third of the circle.
  EXPECT_NEAR(report.grown_boundary_length / (2 * CGAL_PI * R / 3), 1.0, 0.03);
  const CGAL::Bbox_3 box = PMP::bbox(tm);
  EXPECT_NEAR(box.ymax(), R + d, 0.01 * d);
  EXPECT_NEAR(box.ymin(), -R, 1e-9);
  EXPECT_NEAR(box.xmax(), R, 1e-9);
  EXPECT_NEAR(box.xmin(), -R, 1e-9);
  expect_valid_surface(tm);
}

TEST(GrowBoundary, AcrossFlowGrowsTheSidesAcrossAUniformFlow)
{
  const double W = 1.0, H = 0.6, d = 0.25;
  Mesh tm = rectangle(W, H, 1200);
  const FAS::Uniform_flow<K> flow(Vector(2, 0, 0));
  const FAS::Growth_report report =
      FAS::grow_boundary(tm, d, FAS::parameters::across_flow(true, FAS::parameters::flow_field(flow)));
  EXPECT_NEAR(report.grown_boundary_length, 2 * W, 1e-9);
  EXPECT_NEAR(report.added_area, 2 * d * W, 1e-9);
  const CGAL::Bbox_3 box = PMP::bbox(tm);
  EXPECT_NEAR(box.xmin(), -W / 2, 1e-12);
  EXPECT_NEAR(box.xmax(), W / 2, 1e-12);
  EXPECT_NEAR(box.ymin(), -H / 2 - d, 1e-12);
  EXPECT_NEAR(box.ymax(), H / 2 + d, 1e-12);
  expect_valid_surface(tm);
}

TEST(GrowBoundary, PolyhedronGrowsLikeSurfaceMesh)
{
  using Polyhedron = CGAL::Polyhedron_3<K>;
  const double W = 1.2, H = 0.8, d = 0.1;
  Polyhedron tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), W, H, 800,
                         FAS::parameters::patch_axis(Vector(1, 0, 0)));
  const std::size_t old_faces = tm.size_of_facets();
  const FAS::Growth_report report = FAS::grow_boundary(tm, d);
  EXPECT_NEAR(report.added_area, (W + 2 * d) * (H + 2 * d) - W * H, 1e-9);
  EXPECT_NEAR(PMP::area(tm), (W + 2 * d) * (H + 2 * d), 1e-9);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  EXPECT_EQ(tm.size_of_facets(), old_faces + report.number_of_new_faces);
  EXPECT_FALSE(PMP::does_self_intersect(tm));
}

TEST(GrowBoundary, DeformationOnPolyhedronGrowsAndReconverges)
{
  using Polyhedron = CGAL::Polyhedron_3<K>;
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Polyhedron tm;
  FAS::make_disk_patch(tm, Point(0.1, 0.2, 2.0), Vector(0.2, 0.1, 1.0), 0.5, 1000);
  FAS::Flow_aligned_deformation<Polyhedron, FAS::Point_source_flow<K>> deformation(
      tm, source, FAS::Alignment::ORTHOGONAL);
  deformation.run();
  const FAS::Growth_report report = deformation.grow(0.1);
  EXPECT_NEAR(report.added_area / (0.1 * report.grown_boundary_length), 1.0, 0.1);
  EXPECT_EQ(deformation.vertices().size(), tm.size_of_vertices());
  EXPECT_TRUE(deformation.run().converged);
  EXPECT_GE(FAS::normalized_flux(tm, source).value.value(), 0.995);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
}

#ifdef FAS_HAVE_OPENMESH
// OpenMesh's default TriMesh has float points (CGAL's vertex point map rounds to float).
TEST(GrowBoundary, OpenMeshGrowsLikeSurfaceMesh)
{
  using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;
  const double W = 1.2, H = 0.8, d = 0.1;
  OMesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), W, H, 800,
                         FAS::parameters::patch_axis(Vector(1, 0, 0)));
  const std::size_t old_faces = num_faces(tm);
  const FAS::Growth_report report = FAS::grow_boundary(tm, d);
  EXPECT_NEAR(report.added_area / ((W + 2 * d) * (H + 2 * d) - W * H), 1.0, 1e-5);
  EXPECT_NEAR(PMP::area(tm) / ((W + 2 * d) * (H + 2 * d)), 1.0, 1e-5);
  EXPECT_EQ(num_faces(tm), old_faces + report.number_of_new_faces);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
}
#endif

// Growing twice: the second growth sees the first one's faces as old faces.
TEST(GrowBoundary, RepeatedGrowthAddsUp)
{
  const double W = 1.0, H = 1.0, d = 0.05;
  Mesh tm = rectangle(W, H, 1000);
  for (int i = 0; i < 4; ++i)
    FAS::grow_boundary(tm, d);
  EXPECT_NEAR(PMP::area(tm), (W + 8 * d) * (H + 8 * d), 1e-9);
  expect_valid_surface(tm);
}

TEST(GrowBoundary, VertexPointMapIsHonoured)
{
  // The points live in a property of the mesh; the internal points are a decoy at the origin.
  const double W = 1.0, H = 0.5, d = 0.1;
  Mesh tm = rectangle(W, H, 600);
  auto points = tm.add_property_map<Mesh::Vertex_index, Point>("v:other").first;
  for (auto v : tm.vertices()) {
    points[v] = tm.point(v) + Vector(5, 0, 0);
    tm.point(v) = CGAL::ORIGIN;
  }
  const FAS::Growth_report report = FAS::grow_boundary(tm, d, CGAL::parameters::vertex_point_map(points));
  EXPECT_NEAR(report.added_area, (W + 2 * d) * (H + 2 * d) - W * H, 1e-9);
  EXPECT_NEAR(PMP::area(tm, CGAL::parameters::vertex_point_map(points)), (W + 2 * d) * (H + 2 * d), 1e-9);
  const CGAL::Bbox_3 box = PMP::bbox(tm, CGAL::parameters::vertex_point_map(points));
  EXPECT_NEAR(box.xmin(), 5 - W / 2 - d, 1e-12);
}

// --- The deformation -------------------------------------------------------------------

// An orthogonal patch of a point source lies on a sphere; grown and re-converged, it still does.
TEST(FlowAlignedDeformationGrow, OrthogonalPatchGrowsAndReconvergesOnTheSphere)
{
  const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1.0);
  Mesh tm;
  FAS::make_disk_patch(tm, Point(0.1, 0.2, 2.0), Vector(0.2, 0.1, 1.0), 0.5, 2000);
  FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>> deformation(tm, source,
                                                                             FAS::Alignment::ORTHOGONAL);
  ASSERT_TRUE(deformation.run().converged);
  const double area_before = PMP::area(tm);
  const FAS::Growth_report report = deformation.grow(0.1);
  EXPECT_EQ(deformation.number_of_factorizations(), 2u);
  EXPECT_NEAR(report.added_area / (0.1 * report.grown_boundary_length), 1.0, 0.1);
  EXPECT_EQ(deformation.vertices().size(), tm.number_of_vertices());
  const FAS::Alignment_report after = deformation.run();
  EXPECT_TRUE(after.converged);
  EXPECT_GE(after.normalized_flux.value.value(), 0.995);
  EXPECT_GE(FAS::normalized_flux(tm, source).value.value(), 0.995);
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (auto v : tm.vertices()) {
    const double r = std::sqrt((tm.point(v) - CGAL::ORIGIN).squared_length());
    lo = (std::min)(lo, r);
    hi = (std::max)(hi, r);
  }
  EXPECT_LE((hi - lo) / hi, 1e-3) << "the grown surface must stay on one sphere about the source";
  EXPECT_NEAR(PMP::area(tm) / (area_before + report.added_area), 1.0, 0.02);
  expect_valid_surface(tm);
}

// Helical flow v = (-y, x, c): the cylinders about z are stream surfaces.  On a cylinder of
// radius rho the streamlines are the lines of slope c / rho in the unrolled (rho phi, z) plane,
// so w = rho (z - c phi) / sqrt(rho^2 + c^2) is the distance across them.
TEST(FlowAlignedDeformationGrow, TangentialSurfaceGrownAcrossTheFlowStaysAStreamSurface)
{
  const double c = 0.5, d = 0.15;
  const FAS::Helical_flow<K> flow(c);
  Mesh tm;
  // Tangent to the unit cylinder at (1, 0, 0), sides along and across the flow (0, 1, c).
  FAS::make_planar_patch(tm, Point(1, 0, 0), Vector(1, 0, 0), 0.6, 0.4, 2000,
                         FAS::parameters::patch_axis(Vector(0, 1, c)));
  FAS::Flow_aligned_deformation<Mesh, FAS::Helical_flow<K>> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  ASSERT_TRUE(deformation.run().converged);
  ASSERT_LE(FAS::normalized_flux(tm, flow).value.value(), 0.01);
  auto across_extent = [&] {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (auto v : tm.vertices()) {
      const Point& p = tm.point(v);
      const double rho = std::hypot(p.x(), p.y());
      const double w = rho * (p.z() - c * std::atan2(p.y(), p.x())) / std::sqrt(rho * rho + c * c);
      lo = (std::min)(lo, w);
      hi = (std::max)(hi, w);
    }
    return hi - lo;
  };
  const double before = across_extent();
  const FAS::Growth_report report = deformation.grow(d, FAS::parameters::across_flow(true));
  EXPECT_GT(report.number_of_new_faces, 0u);
  const FAS::Alignment_report after = deformation.run();
  EXPECT_TRUE(after.converged);
  EXPECT_LE(after.normalized_flux.value.value(), 0.01);
  EXPECT_LE(FAS::normalized_flux(tm, flow).value.value(), 0.01);
  // Both sides across the flow grow.
  EXPECT_GE(across_extent() - before, 0.8 * 2 * d);
  expect_valid_surface(tm);
}

// The update of M_0: a deformation whose M_k is M_0 moved rigidly grows M_0 by the same strip
// moved back, since the offsets are carried in the boundary frames, which move with the surface.
TEST(FlowAlignedDeformationGrow, ReferenceMeshReceivesTheSameStripMovedBack)
{
  const FAS::Uniform_flow<K> flow(Vector(1, 0, 0));
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0.2, 0.1, -0.3), Vector(0.3, -1.0, 0.5), 1.0, 0.7, 800);
  FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> deformation(tm, flow, FAS::Alignment::ORTHOGONAL);
  // Unmoved: M_0's strip is M_k's.
  {
    Mesh copy = tm;
    FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> unmoved(copy, flow, FAS::Alignment::ORTHOGONAL);
    const std::size_t old_vertices = copy.number_of_vertices();
    unmoved.grow(0.1);
    for (std::size_t i = old_vertices; i < unmoved.vertices().size(); ++i)
      EXPECT_LE(std::sqrt((unmoved.reference_point(i) - copy.point(unmoved.vertices()[i])).squared_length()),
                1e-12);
  }
  const Point center(0.5, -0.5, 0.25);
  const Vector axis(0.3, 0.4, -0.8);
  const double angle = 0.7;
  deformation.translate(Vector(0.3, 1.1, -0.4));
  deformation.rotate(center, axis, angle);
  const std::size_t old_vertices = tm.number_of_vertices();
  deformation.grow(0.1);
  ASSERT_GT(deformation.vertices().size(), old_vertices);
  // Rodrigues' rotation by -angle about `axis` through `center`, then the translation undone.
  const Vector k = axis / std::sqrt(axis.squared_length());
  auto move_back = [&](const Point& p) {
    const Vector v = p - center;
    const double ca = std::cos(-angle), sa = std::sin(-angle);
    const Vector r = v * ca + CGAL::cross_product(k, v) * sa + k * ((k * v) * (1 - ca));
    return center + r - Vector(0.3, 1.1, -0.4);
  };
  for (std::size_t i = 0; i < deformation.vertices().size(); ++i) {
    const Point expected = move_back(tm.point(deformation.vertices()[i]));
    EXPECT_LE(std::sqrt((deformation.reference_point(i) - expected).squared_length()), 1e-9)
        << "vertex " << i;
  }
}

// --- Bad input: a clear message, nothing modified ----------------------------------------

template <class Call>
void expect_untouched_failure(Mesh& tm, const Call& call, const std::vector<std::string>& parts)
{
  const Mesh before = tm;
  expect_invalid_argument(call, parts);
  ASSERT_EQ(tm.number_of_vertices(), before.number_of_vertices());
  ASSERT_EQ(tm.number_of_faces(), before.number_of_faces());
  for (auto v : tm.vertices())
    EXPECT_EQ(tm.point(v), before.point(v));
}

TEST(GrowBoundaryBadInput, ClosedMesh)
{
  Mesh tm;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), tm);
  expect_untouched_failure(tm, [&] { FAS::grow_boundary(tm, 0.1); },
                           {"grow_boundary()", "no boundary", "closed"});
}

TEST(GrowBoundaryBadInput, DistanceNotPositiveOrNotFinite)
{
  Mesh tm = rectangle(1, 1, 200);
  for (double d :
       {0.0, -0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    expect_untouched_failure(tm, [&] { FAS::grow_boundary(tm, d); },
                             {"grow_boundary()", "distance", "positive"});
}

TEST(GrowBoundaryBadInput, DirectionZeroOrParallelToTheNormal)
{
  Mesh tm = rectangle(1, 1, 200);
  expect_untouched_failure(
      tm, [&] { FAS::grow_boundary(tm, 0.1, FAS::parameters::growth_direction(Vector(0, 0, -3))); },
      {"growth_direction", "parallel to the surface normal"});
  expect_untouched_failure(
      tm, [&] { FAS::grow_boundary(tm, 0.1, FAS::parameters::growth_direction(Vector(0, 0, 0))); },
      {"growth_direction", "non-zero"});
}

TEST(GrowBoundaryBadInput, AcrossFlowWithoutFieldOrWithoutFlow)
{
  Mesh tm = rectangle(1, 1, 200);
  expect_untouched_failure(tm, [&] { FAS::grow_boundary(tm, 0.1, FAS::parameters::across_flow(true)); },
                           {"across_flow", "flow_field"});
  const auto zero = [](const Point&) -> std::optional<Vector> { return Vector(0, 0, 0); };
  expect_untouched_failure(
      tm,
      [&] {
        FAS::grow_boundary(tm, 0.1, FAS::parameters::across_flow(true, FAS::parameters::flow_field(zero)));
      },
      {"across_flow", "zero, undefined"});
  // Flow along the normal: no in-plane direction across it.
  const FAS::Uniform_flow<K> normal_flow(Vector(0, 0, 1));
  expect_untouched_failure(
      tm,
      [&] {
        FAS::grow_boundary(tm, 0.1,
                           FAS::parameters::across_flow(true, FAS::parameters::flow_field(normal_flow)));
      },
      {"across_flow", "along the normal"});
  // Across a flow along x are the sides facing +-y; +x faces none of them.
  const FAS::Uniform_flow<K> flow(Vector(1, 0, 0));
  expect_untouched_failure(
      tm,
      [&] {
        FAS::grow_boundary(
            tm, 0.1,
            FAS::parameters::across_flow(
                true, FAS::parameters::flow_field(flow, FAS::parameters::growth_direction(Vector(1, 0, 0)))));
      },
      {"no boundary edge faces growth_direction and across the flow"});
}

// A narrow notch in the top side (depth 0.3, width ~0.1): its bottom curves with a radius far
// below the distance 0.3, so the offset curve folds over there.
TEST(GrowBoundaryBadInput, DistanceAboveTheRadiusOfAConcaveBoundaryFoldsOver)
{
  Mesh tm = rectangle(1, 1, 800);
  for (auto v : tm.vertices()) {
    const Point p = tm.point(v);
    tm.point(v) = Point(p.x(), p.y() - 0.3 * std::exp(-CGAL::square(p.x() / 0.05)) * (p.y() + 0.5), 0);
  }
  expect_untouched_failure(tm, [&] { FAS::grow_boundary(tm, 0.3); }, {"grow_boundary()", "folds over"});
  // A small step is fine.
  EXPECT_NO_THROW(FAS::grow_boundary(tm, 0.002));
}

TEST(GrowBoundaryBadInput, DeformationRejectsAcrossFlowWhenOrthogonalAndKeepsItsState)
{
  const FAS::Uniform_flow<K> flow(Vector(0, 0, 1));
  Mesh tm = rectangle(1, 1, 300);
  FAS::Flow_aligned_deformation<Mesh, FAS::Uniform_flow<K>> deformation(tm, flow, FAS::Alignment::ORTHOGONAL);
  expect_untouched_failure(tm, [&] { deformation.grow(0.1, FAS::parameters::across_flow(true)); },
                           {"Flow_aligned_deformation::grow()", "across_flow", "tangential"});
  expect_untouched_failure(tm, [&] { deformation.grow(-1); },
                           {"Flow_aligned_deformation::grow()", "distance"});
  EXPECT_EQ(deformation.number_of_factorizations(), 1u);
  EXPECT_EQ(deformation.vertices().size(), tm.number_of_vertices());
  EXPECT_TRUE(deformation.run().converged);
}

} // namespace

} // namespace test_grow_boundary
