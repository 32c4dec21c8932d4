// Growing works whatever the patch's pose.  A rectangular patch is placed
// tangent to an exact stream surface of three analytic flows (the cylinders of the helical flow,
// the planes through a point source, the half-planes of the harmonic saddle), turned by 0..90
// degrees about its normal from the flow's direction, aligned tangentially, and grown across the
// flow, along a direction and all around by 2, 5 and 10% of its diameter.  Every result must be
// a valid manifold mesh without self-intersections (CGAL::Polygon_mesh_processing::
// does_self_intersect, a check independent of the growing code), with new faces of smallest
// angle >= 20 degrees, an added area of d times the grown boundary length (up to 10%, plus the
// closed-form d^2 of each of the rectangle's four mitred corners), a report that lists the grown
// edges, and, after growing the deformation itself, iterations that reach the alignment again.

#include "expect_invalid_argument.h"
#include "triangle_angles.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/grow_boundary.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own (unity batches).
namespace test_grow_boundary_poses {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;
namespace PMP = CGAL::Polygon_mesh_processing;

// The patch: W x H, about 300 faces (edges of about 0.04), diameter sqrt(W^2 + H^2).
constexpr double W = 0.6, H = 0.4;
constexpr std::size_t patch_faces = 300;
const double diameter = std::sqrt(W * W + H * H);

Vector unit(const Vector& v) { return v / std::sqrt(v.squared_length()); }

// A tangential patch of `flow`: centered at `center` with unit normal `normal` (orthogonal to the
// flow there), its long side turned by `pose` degrees from the flow about the normal.
template <class Flow>
Mesh posed_patch(const Flow& flow, const Point& center, const Vector& normal, int pose)
{
  const Vector f = unit(*flow(center));
  const Vector across = CGAL::cross_product(normal, f);
  const double a = pose * CGAL_PI / 180;
  Mesh tm;
  FAS::make_planar_patch(tm, center, normal, W, H, patch_faces,
                         FAS::parameters::patch_axis(std::cos(a) * f + std::sin(a) * across));
  return tm;
}

using fas_test::smallest_angle_degrees;

// What is wrong with `tm` grown by `d` (the first `old_faces` faces and `old_vertices` vertices
// are the old ones, `before` the old positions in vertex order); empty when all is right.
std::string check_grown(const Mesh& tm, std::size_t old_faces, const std::vector<Point>& before,
                        const FAS::Growth_report& report, double d)
{
  std::ostringstream problems;
  if (!CGAL::is_valid_polygon_mesh(tm) || !CGAL::is_triangle_mesh(tm))
    problems << " invalid mesh;";
  std::vector<Mesh::Halfedge_index> non_manifold;
  PMP::non_manifold_vertices(tm, std::back_inserter(non_manifold));
  if (!non_manifold.empty())
    problems << " " << non_manifold.size() << " non-manifold vertices;";
  if (PMP::does_self_intersect(tm))
    problems << " self-intersections;";
  std::vector<Mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(tm, std::back_inserter(borders));
  if (borders.size() != 1)
    problems << " " << borders.size() << " boundary cycles;";
  double smallest = 180;
  for (auto f : tm.faces())
    if (std::size_t(f) >= old_faces)
      smallest = (std::min)(smallest, smallest_angle_degrees(tm, f));
  if (smallest < 20)
    problems << " smallest new angle " << smallest << " degrees;";
  // The report's grown edges are old boundary edges, and their lengths add up to the grown length.
  double length = 0;
  for (const auto& e : report.grown_edges) {
    const Mesh::Vertex_index p(static_cast<Mesh::size_type>(e.first)), q(static_cast<Mesh::size_type>(e.second));
    const auto h = tm.halfedge(p, q);
    if (h == Mesh::null_halfedge() || std::size_t(tm.face(tm.opposite(h))) >= old_faces)
      problems << " grown edge " << e.first << "-" << e.second << " is not an old boundary edge;";
    length += std::sqrt((before[e.second] - before[e.first]).squared_length());
  }
  if (report.number_of_grown_edges != report.grown_edges.size() || report.grown_edges.empty())
    problems << " number_of_grown_edges " << report.number_of_grown_edges << " for " << report.grown_edges.size()
             << " listed;";
  if (std::abs(length - report.grown_boundary_length) > 1e-9 * (1 + length))
    problems << " grown edges' length " << length << " != grown_boundary_length " << report.grown_boundary_length
             << ";";
  const double strip = d * report.grown_boundary_length;
  if (std::abs(report.added_area - strip) > 0.1 * strip + 4 * d * d)
    problems << " added area " << report.added_area << " for d x length " << strip << ";";
  return problems.str();
}

const char* mode_name(int mode) { return mode == 0 ? "across the flow" : mode == 1 ? "along a direction" : "all around"; }

// The poses, in degrees from the flow's direction: every 5 degrees; under the sanitizers
// (FAS_TEST_SANITIZED, at -O0) every 15, the same code paths at a third of the cost.
#ifdef FAS_TEST_SANITIZED
constexpr int pose_step = 15;
#else
constexpr int pose_step = 5;
#endif

// Grows copies of the aligned patch at every pose, by every distance and in every mode, with
// grow_boundary(); returns the failures, one line each.
template <class Flow>
std::vector<std::string> sweep(const char* name, const Flow& flow, const Point& center, const Vector& normal)
{
  std::vector<std::string> failures;
  for (int pose = 0; pose <= 90; pose += pose_step) {
    Mesh aligned = posed_patch(flow, center, normal, pose);
    {
      FAS::Flow_aligned_deformation<Mesh, Flow> deformation(aligned, flow, FAS::Alignment::TANGENTIAL,
                                                            CGAL::parameters::number_of_iterations(200));
      deformation.run();
    }
    const Vector across = CGAL::cross_product(normal, unit(*flow(center)));
    for (int mode = 0; mode < 3; ++mode)
      for (double fraction : {0.02, 0.05, 0.1}) {
        const double d = fraction * diameter;
        Mesh tm = aligned;
        std::vector<Point> before(tm.points().begin(), tm.points().end());
        std::ostringstream label;
        label << name << ", pose " << pose << " degrees, " << mode_name(mode) << ", d = " << fraction
              << " x diameter:";
        try {
          const FAS::Growth_report report =
              mode == 0   ? FAS::grow_boundary(tm, d, FAS::parameters::across_flow(true, FAS::parameters::flow_field(flow)))
              : mode == 1 ? FAS::grow_boundary(tm, d, FAS::parameters::growth_direction(across))
                          : FAS::grow_boundary(tm, d);
          const std::string problems = check_grown(tm, aligned.number_of_faces(), before, report, d);
          if (!problems.empty())
            failures.push_back(label.str() + problems);
        } catch (const std::exception& e) {
          failures.push_back(label.str() + " refused: " + e.what());
        }
      }
  }
  return failures;
}

void expect_no_failures(const std::vector<std::string>& failures)
{
  std::ostringstream all;
  for (const std::string& f : failures)
    all << f << "\n";
  EXPECT_TRUE(failures.empty()) << failures.size() << " failing cases:\n" << all.str();
}

// The three flows and their stream surfaces through the patch's center.
const FAS::Helical_flow<K> helical(0.5);                  // the cylinder x^2 + y^2 = 1
const Point helical_center(1, 0, 0);
const Vector helical_normal(1, 0, 0);
const FAS::Point_source_flow<K> source(Point(0, 0, 0), 1); // the plane x = 0
const Point source_center(0, 0, 2);
const Vector source_normal(1, 0, 0);
const FAS::Linear_flow<K> saddle;                          // the half-plane y = 0, x > 0
const Point saddle_center(1, 0, 0.5);
const Vector saddle_normal(0, 1, 0);

TEST(GrowBoundaryPoses, HelicalFlowEveryPoseModeAndDistance)
{
  expect_no_failures(sweep("helical flow", helical, helical_center, helical_normal));
}

TEST(GrowBoundaryPoses, PointSourceEveryPoseModeAndDistance)
{
  expect_no_failures(sweep("point source", source, source_center, source_normal));
}

TEST(GrowBoundaryPoses, HarmonicSaddleEveryPoseModeAndDistance)
{
  expect_no_failures(sweep("harmonic saddle", saddle, saddle_center, saddle_normal));
}

// The case grow() exists for: the deformation itself grown across the flow at a pose where the
// flow runs along the diagonal at two corners, then iterated again: it must reach the alignment
// again.
template <class Flow>
void expect_reconverges(const Flow& flow, const Point& center, const Vector& normal, int pose, double fraction)
{
  SCOPED_TRACE("pose " + std::to_string(pose) + " degrees, d = " + std::to_string(fraction) + " x diameter");
  Mesh tm = posed_patch(flow, center, normal, pose);
  FAS::Flow_aligned_deformation<Mesh, Flow> deformation(tm, flow, FAS::Alignment::TANGENTIAL,
                                                        CGAL::parameters::number_of_iterations(400));
  ASSERT_TRUE(deformation.run().converged);
  const std::size_t old_faces = tm.number_of_faces();
  std::vector<Point> before(tm.points().begin(), tm.points().end());
  const double d = fraction * diameter;
  const FAS::Growth_report report = deformation.grow(d, FAS::parameters::across_flow(true));
  EXPECT_EQ(check_grown(tm, old_faces, before, report, d), "");
  const FAS::Alignment_report after = deformation.run();
  EXPECT_TRUE(after.converged) << after.number_of_iterations << " iterations, f_n " << after.normalized_flux;
  EXPECT_LE(after.normalized_flux.value.value(), 0.01);
  EXPECT_FALSE(PMP::does_self_intersect(tm));
}

TEST(GrowBoundaryPoses, DeformationGrownAcrossTheFlowReconverges)
{
  for (int pose : {15, 45, 60})
    for (double fraction : {0.02, 0.05, 0.1}) {
      expect_reconverges(helical, helical_center, helical_normal, pose, fraction);
      expect_reconverges(source, source_center, source_normal, pose, fraction);
      expect_reconverges(saddle, saddle_center, saddle_normal, pose, fraction);
    }
}

// --- Corners and where growing is impossible ------------------------------------------------

// A planar mesh of unit cells (two triangles each) at the cells (i, j) of an n x n grid for
// which `keep(i, j)` holds.
template <class Keep>
Mesh cells(int n, const Keep& keep)
{
  Mesh tm;
  std::vector<Mesh::Vertex_index> v((n + 1) * (n + 1));
  auto at = [&](int i, int j) -> Mesh::Vertex_index& { return v[std::size_t(j * (n + 1) + i)]; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      at(i, j) = tm.add_vertex(Point(i, j, 0));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (keep(i, j)) {
        tm.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        tm.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
  std::vector<Mesh::Vertex_index> isolated;
  for (auto w : tm.vertices())
    if (tm.is_isolated(w))
      isolated.push_back(w);
  for (auto w : isolated)
    tm.remove_vertex(w);
  tm.collect_garbage();
  return tm;
}

template <class Call>
void expect_refused_untouched(Mesh& tm, const Call& call, const std::vector<std::string>& parts)
{
  const std::size_t vertices = tm.number_of_vertices(), faces = tm.number_of_faces();
  const std::vector<Point> before(tm.points().begin(), tm.points().end());
  expect_invalid_argument(call, parts);
  EXPECT_EQ(tm.number_of_vertices(), vertices);
  EXPECT_EQ(tm.number_of_faces(), faces);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), tm.points().begin()));
}

// An equilateral triangle turns by 120 degrees at each corner: the offset curve goes round the
// corners on an arc of radius d (a fan), so every new boundary vertex is within d of the old
// triangle and no closer than the arc's chords (d cos 30 degrees); a miter would reach 2 d.
TEST(GrowBoundaryCorners, SharpConvexCornersGoRoundOnAnArc)
{
  const double s = 1.0, d = 0.1;
  const Point a(0, 0, 0), b(s, 0, 0), c(s / 2, s * std::sqrt(3.) / 2, 0);
  Mesh tm;
  CGAL::make_triangle(a, b, c, tm);
  const FAS::Growth_report report = FAS::grow_boundary(tm, d);
  EXPECT_EQ(report.number_of_grown_edges, 3u);
  EXPECT_NEAR(report.grown_boundary_length, 3 * s, 1e-12);
  const K::Triangle_3 old(a, b, c);
  for (auto h : tm.halfedges())
    if (tm.is_border(h)) {
      const double r = std::sqrt(CGAL::squared_distance(tm.point(tm.target(h)), old));
      EXPECT_LE(r, d * (1 + 1e-9));
      EXPECT_GE(r, d * std::cos(CGAL_PI / 6) * (1 - 1e-9));
    }
  // d x length plus three fans of two 60-degree pieces each.
  EXPECT_NEAR(report.added_area, 3 * s * d + 3 * 2 * 0.5 * d * d * std::sin(CGAL_PI / 3), 1e-12);
  EXPECT_FALSE(PMP::does_self_intersect(tm));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
}

// A square ring cut open by a slit one cell wide: grown all around by more than half the slit,
// the two ends would overlap.  The growth is refused, saying where, and nothing is modified.
TEST(GrowBoundaryCorners, OverlapAcrossASlitIsRefusedSayingWhere)
{
  Mesh tm = cells(5, [](int i, int j) { return !(i >= 1 && i <= 3 && j >= 1 && j <= 3) && !(i == 4 && j == 2); });
  expect_refused_untouched(tm, [&] { FAS::grow_boundary(tm, 0.6); },
                           {"grow_boundary()", "would cut through", "at (", "untouched"});
  // Below half the slit it grows.
  const FAS::Growth_report report = FAS::grow_boundary(tm, 0.3);
  EXPECT_GT(report.number_of_new_faces, 0u);
  EXPECT_FALSE(PMP::does_self_intersect(tm));
}

// Two blocks of cells one cell apart, grown toward +x only: the left block's strip reaches
// across the gap into the right block's faces, which do not grow.  The refusal names an old
// face, the pair the guard finds from the old face's side.
TEST(GrowBoundaryCorners, StripIntoOldFacesIsRefusedNamingThem)
{
  Mesh tm = cells(5, [](int i, int) { return i != 2; });
  const auto toward_x = FAS::parameters::growth_direction(Vector(1, 0, 0));
  expect_refused_untouched(tm, [&] { FAS::grow_boundary(tm, 1.5, toward_x); },
                           {"grow_boundary()", "would cut through an old face of the surface", "at (", "untouched"});
  // Within the gap it grows.
  const FAS::Growth_report report = FAS::grow_boundary(tm, 0.5, toward_x);
  EXPECT_GT(report.number_of_new_faces, 0u);
  EXPECT_FALSE(PMP::does_self_intersect(tm));
}

// An arrowhead whose notch has an inside angle of 58 degrees: its two sides cannot both grow.
TEST(GrowBoundaryCorners, TooSharpConcaveCornerIsRefusedNamingTheVertex)
{
  Mesh tm;
  const auto tip = tm.add_vertex(Point(2, 0, 0)), up = tm.add_vertex(Point(0, 1, 0)),
             notch = tm.add_vertex(Point(1.8, 0, 0)), down = tm.add_vertex(Point(0, -1, 0));
  tm.add_face(tip, up, notch);
  tm.add_face(tip, notch, down);
  expect_refused_untouched(tm, [&] { FAS::grow_boundary(tm, 0.05); },
                           {"concave corner of 58 degrees", "vertex 2 (1.8, 0, 0)", "untouched"});
}

} // namespace

} // namespace test_grow_boundary_poses
