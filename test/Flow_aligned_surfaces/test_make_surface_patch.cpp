// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of make_planar_patch() and make_disk_patch() against answers known independently of
// the construction: areas of rectangles and inscribed polygons, the plane and its frame, the
// topology of a disk, and the angles of the lattice.

#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include "expect_invalid_argument.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_make_surface_patch {

namespace {

namespace FAS = CGAL::Flow_aligned_surfaces;
namespace PMP = CGAL::Polygon_mesh_processing;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Vector_3 = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Polyhedron = CGAL::Polyhedron_3<K>;

const double pi = std::acos(-1.0);

Vector_3 unit(const Vector_3& v)
{
  return v / std::sqrt(v.squared_length());
}

// The frame the documentation promises: n normalized, u the axis projected and normalized.
struct Frame {
  Vector_3 n, u, v;
  Frame(const Vector_3& normal, const Vector_3& axis)
  {
    n = unit(normal);
    u = unit(axis - (axis * n) * n);
    v = CGAL::cross_product(n, u);
  }
};

struct Mesh_stats {
  std::size_t faces = 0;
  double area = 0;
  double min_normal_agreement = 2; // min over faces of n_f · n
  double max_plane_distance = 0;   // max over vertices of |(p - c) · n|
  double min_angle_degrees = 180;
  double u_min = 1e300, u_max = -1e300, v_min = 1e300, v_max = -1e300;
};

template <class TM>
Mesh_stats compute_stats(const TM& tm, const Point_3& center, const Frame& frame)
{
  Mesh_stats s;
  auto vpm = get(CGAL::vertex_point, tm);
  for (auto f : faces(tm)) {
    std::vector<Point_3> p;
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      p.push_back(get(vpm, v));
    EXPECT_EQ(p.size(), 3u);
    const Vector_3 c = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const double twice_area = std::sqrt(c.squared_length());
    s.area += twice_area / 2;
    s.min_normal_agreement = std::min(s.min_normal_agreement, (c / twice_area) * frame.n);
    for (int i = 0; i < 3; ++i) {
      const Vector_3 a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
      const double angle = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
      s.min_angle_degrees = std::min(s.min_angle_degrees, angle * 180 / pi);
    }
    ++s.faces;
  }
  for (auto v : vertices(tm)) {
    const Vector_3 d = get(vpm, v) - center;
    s.max_plane_distance = std::max(s.max_plane_distance, std::abs(d * frame.n));
    s.u_min = std::min(s.u_min, d * frame.u);
    s.u_max = std::max(s.u_max, d * frame.u);
    s.v_min = std::min(s.v_min, d * frame.v);
    s.v_max = std::max(s.v_max, d * frame.v);
  }
  return s;
}

// Border cycles, counted by walking `next` from every border halfedge not yet visited.
template <class TM>
std::size_t number_of_border_cycles(const TM& tm)
{
  std::set<typename boost::graph_traits<TM>::halfedge_descriptor> seen;
  std::size_t cycles = 0;
  for (auto h : halfedges(tm)) {
    if (!is_border(h, tm) || seen.count(h))
      continue;
    ++cycles;
    for (auto g = h; seen.insert(g).second; g = next(g, tm)) {
    }
  }
  return cycles;
}

template <class TM>
std::size_t number_of_border_halfedges(const TM& tm)
{
  std::size_t n = 0;
  for (auto h : halfedges(tm))
    n += is_border(h, tm) ? 1 : 0;
  return n;
}

template <class TM>
void expect_topological_disk(const TM& tm)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  EXPECT_TRUE(CGAL::is_triangle_mesh(tm));
  EXPECT_EQ(number_of_border_cycles(tm), 1u);
  const long long chi = static_cast<long long>(num_vertices(tm)) - static_cast<long long>(num_edges(tm)) +
                        static_cast<long long>(num_faces(tm));
  EXPECT_EQ(chi, 1);
}

struct Pose {
  Point_3 center;
  Vector_3 normal;
  Vector_3 axis;
};

const std::vector<Pose> poses = {
    {Point_3(0, 0, 0), Vector_3(0, 0, 1), Vector_3(1, 0, 0)},
    {Point_3(10, -3, 5), Vector_3(1, 2, 3), Vector_3(0.3, -1, 0.7)},
    {Point_3(-2.5, 7, 0.125), Vector_3(-4, 0.1, 0), Vector_3(0, 0, -2)},
    {Point_3(1e3, 1e3, -1e3), Vector_3(0, -1, 0), Vector_3(1, 5, 1)},
    {Point_3(0.1, 0.2, 0.3), Vector_3(-1, -1, -1), Vector_3(2, 0, 0)},
};

// --- planar patch ---------------------------------------------------------------------------

TEST(MakePlanarPatch, FaceCountWithinTenPercentOfTarget)
{
  const std::vector<std::array<double, 2>> sizes = {{{1, 1}}, {{2, 0.5}}, {{0.3, 3}}, {{7, 1}}};
  for (const auto& wh : sizes)
    for (std::size_t target : {50, 73, 100, 333, 1000, 1234, 5000, 20000}) {
      Mesh tm;
      FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), wh[0], wh[1], target);
      const double F = static_cast<double>(num_faces(tm));
      const double T = static_cast<double>(target);
      EXPECT_LE(std::abs(F - T), 0.1 * T) << wh[0] << " x " << wh[1] << ", target " << target;
      if (target >= 1000) {
        EXPECT_LE(std::abs(F - T), 0.025 * T) << wh[0] << " x " << wh[1] << ", target " << target;
      }
    }
}

TEST(MakePlanarPatch, AreaPlaneNormalsAndExtentsInAnyPose)
{
  const std::vector<std::array<double, 2>> sizes = {{{1, 1}}, {{3, 0.25}}, {{0.5, 2}}};
  for (const Pose& pose : poses)
    for (const auto& wh : sizes) {
      const double w = wh[0], h = wh[1];
      Mesh tm;
      FAS::make_planar_patch(tm, pose.center, pose.normal, w, h, 800, FAS::parameters::patch_axis(pose.axis));
      const Frame frame(pose.normal, pose.axis);
      const Mesh_stats s = compute_stats(tm, pose.center, frame);
      const double scale = 1 + std::sqrt((pose.center - CGAL::ORIGIN).squared_length());
      EXPECT_NEAR(s.area, w * h, 1e-12 * w * h * scale);
      EXPECT_GT(s.min_normal_agreement, 1 - 1e-9);
      EXPECT_LT(s.max_plane_distance, 1e-12 * scale);
      EXPECT_NEAR(s.u_min, -w / 2, 1e-12 * scale);
      EXPECT_NEAR(s.u_max, w / 2, 1e-12 * scale);
      EXPECT_NEAR(s.v_min, -h / 2, 1e-12 * scale);
      EXPECT_NEAR(s.v_max, h / 2, 1e-12 * scale);
      expect_topological_disk(tm);
      // The boundary is the rectangle: 2 (columns + rows) edges, its length the perimeter.
      double perimeter = 0;
      auto vpm = get(CGAL::vertex_point, tm);
      for (auto hd : halfedges(tm))
        if (is_border(hd, tm))
          perimeter += std::sqrt(CGAL::squared_distance(get(vpm, source(hd, tm)), get(vpm, target(hd, tm))));
      EXPECT_NEAR(perimeter, 2 * (w + h), 1e-12 * scale);
    }
}

TEST(MakePlanarPatch, DefaultAxisIsXForNormalZ)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(1, 2, 3), Vector_3(0, 0, 5), 4.0, 2.0, 200);
  const Mesh_stats s = compute_stats(tm, Point_3(1, 2, 3), Frame(Vector_3(0, 0, 1), Vector_3(1, 0, 0)));
  EXPECT_NEAR(s.u_min, -2, 1e-14);
  EXPECT_NEAR(s.u_max, 2, 1e-14);
  EXPECT_NEAR(s.v_min, -1, 1e-14);
  EXPECT_NEAR(s.v_max, 1, 1e-14);
  EXPECT_GT(s.min_normal_agreement, 1 - 1e-12);
}

TEST(MakePlanarPatch, DefaultAxisIsOrthogonalToAnyNormal)
{
  for (const Pose& pose : poses) {
    Mesh tm;
    FAS::make_planar_patch(tm, pose.center, pose.normal, 1.0, 1.0, 100);
    double max_plane_distance = 0;
    for (auto v : vertices(tm))
      max_plane_distance =
          std::max(max_plane_distance, std::abs((tm.point(v) - pose.center) * unit(pose.normal)));
    const double scale = 1 + std::sqrt((pose.center - CGAL::ORIGIN).squared_length());
    EXPECT_LT(max_plane_distance, 1e-12 * scale);
    double area = 0;
    for (auto f : faces(tm))
      area += std::sqrt(CGAL::squared_area(tm.point(source(halfedge(f, tm), tm)),
                                           tm.point(target(halfedge(f, tm), tm)),
                                           tm.point(target(next(halfedge(f, tm), tm), tm))));
    EXPECT_NEAR(area, 1.0, 1e-12 * scale);
  }
}

TEST(MakePlanarPatch, MinimumAngleAtLeastThirtyDegrees)
{
  // Away from the side columns the lattice is near equilateral; at the sides the odd rows
  // end with half-width cells whose smallest angle is atan(h/s) ≈ 41 degrees; the bound 30
  // leaves room for the aspect adjustment the face-count target needs.
  const std::vector<std::array<double, 2>> sizes = {{{1, 1}}, {{5, 1}}, {{1, 5}}, {{1.37, 0.8}}};
  for (const auto& wh : sizes)
    for (std::size_t target : {50, 61, 200, 999, 5000}) {
      Mesh tm;
      FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), wh[0], wh[1], target);
      const Mesh_stats s = compute_stats(tm, Point_3(0, 0, 0), Frame(Vector_3(0, 0, 1), Vector_3(1, 0, 0)));
      EXPECT_GE(s.min_angle_degrees, 30.0) << wh[0] << " x " << wh[1] << ", target " << target;
    }
  // A square with many faces is close to equilateral everywhere but at the sides.
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 20000);
  const Mesh_stats s = compute_stats(tm, Point_3(0, 0, 0), Frame(Vector_3(0, 0, 1), Vector_3(1, 0, 0)));
  EXPECT_GE(s.min_angle_degrees, 38.0);
}

TEST(MakePlanarPatch, SmallTargets)
{
  for (std::size_t target = 2; target < 50; ++target) {
    Mesh tm;
    FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, target);
    expect_topological_disk(tm);
    EXPECT_GE(num_faces(tm), 2u);
    const Mesh_stats s = compute_stats(tm, Point_3(0, 0, 0), Frame(Vector_3(0, 0, 1), Vector_3(1, 0, 0)));
    EXPECT_NEAR(s.area, 1.0, 1e-14);
    EXPECT_GT(s.min_normal_agreement, 1 - 1e-12);
  }
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 2);
  EXPECT_EQ(num_faces(tm), 2u);
  EXPECT_EQ(num_vertices(tm), 4u);
}

TEST(MakePlanarPatch, ReturnsTheBorderHalfedgeAtTheFirstCorner)
{
  for (const Pose& pose : poses) {
    Mesh tm;
    const auto h = FAS::make_planar_patch(tm, pose.center, pose.normal, 2.0, 3.0, 300,
                                          FAS::parameters::patch_axis(pose.axis));
    ASSERT_TRUE(is_border(h, tm));
    const Frame frame(pose.normal, pose.axis);
    const Point_3 corner = pose.center - 1.0 * frame.u - 1.5 * frame.v;
    EXPECT_LT(std::sqrt(CGAL::squared_distance(tm.point(target(h, tm)), corner)), 1e-12 * 1e3);
    EXPECT_FALSE(is_border(opposite(h, tm), tm));
  }
}

// --- disk patch -----------------------------------------------------------------------------

TEST(MakeDiskPatch, FaceCountEqualsTarget)
{
  for (std::size_t target : {2, 3, 4, 7, 12, 13, 30, 50, 63, 100, 777, 1007, 5000, 20000}) {
    Mesh tm;
    FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, target);
    EXPECT_EQ(num_faces(tm), target);
    expect_topological_disk(tm);
  }
}

TEST(MakeDiskPatch, AreaIsTheInscribedPolygonAndCloseToPiRSquared)
{
  for (const Pose& pose : poses)
    for (std::size_t target : {2, 20, 100, 2000}) {
      const double R = 0.75;
      Mesh tm;
      FAS::make_disk_patch(tm, pose.center, pose.normal, R, target, FAS::parameters::patch_axis(pose.axis));
      const Frame frame(pose.normal, pose.axis);
      const Mesh_stats s = compute_stats(tm, pose.center, frame);
      const double scale = 1 + std::sqrt((pose.center - CGAL::ORIGIN).squared_length());
      // A regular N-gon inscribed in the circle has area N/2 R² sin(2π/N), and
      // 0 < πR² - that < πR² (2π/N)²/6 since sin x > x - x³/6.
      const double N = static_cast<double>(number_of_border_halfedges(tm));
      const double polygon = N / 2 * R * R * std::sin(2 * pi / N);
      EXPECT_NEAR(s.area, polygon, 1e-12 * scale);
      EXPECT_LT(s.area, pi * R * R);
      EXPECT_GT(s.area, pi * R * R * (1 - std::pow(2 * pi / N, 2) / 6));
      // The hexagonal disk with T faces has about sqrt(6T) boundary vertices.
      if (target >= 100) {
        const double hexagonal = std::sqrt(6.0 * static_cast<double>(target));
        EXPECT_NEAR(N, hexagonal, 0.15 * hexagonal);
      }
      EXPECT_GT(s.min_normal_agreement, 1 - 1e-9);
      EXPECT_LT(s.max_plane_distance, 1e-12 * scale);
    }
}

TEST(MakeDiskPatch, BoundaryOnTheCircleInteriorInside)
{
  for (const Pose& pose : poses) {
    const double R = 2.5;
    Mesh tm;
    FAS::make_disk_patch(tm, pose.center, pose.normal, R, 1500, FAS::parameters::patch_axis(pose.axis));
    const double scale = 1 + std::sqrt((pose.center - CGAL::ORIGIN).squared_length());
    std::size_t on_boundary = 0;
    for (auto v : vertices(tm)) {
      const double r = std::sqrt(CGAL::squared_distance(tm.point(v), pose.center));
      if (CGAL::is_border(v, tm)) {
        EXPECT_NEAR(r, R, 1e-12 * scale);
        ++on_boundary;
      }
      else {
        EXPECT_LT(r, R * (1 - 1e-3));
      }
    }
    EXPECT_EQ(on_boundary, number_of_border_halfedges(tm));
  }
}

TEST(MakeDiskPatch, MinimumAngleAtLeastThirtyDegrees)
{
  // Measured worst case of the construction: 30 degrees (the 12-triangle fan of target 12,
  // and the equilateral-triangle fan of target 3); about 43 degrees for large targets.
  for (std::size_t target : {3, 12, 29, 35, 64, 100, 250, 1007, 4321, 20000}) {
    Mesh tm;
    FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, target);
    const Mesh_stats s = compute_stats(tm, Point_3(0, 0, 0), Frame(Vector_3(0, 0, 1), Vector_3(1, 0, 0)));
    EXPECT_GE(s.min_angle_degrees, 30.0 - 1e-9) << "target " << target;
  }
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 50000);
  const Mesh_stats s = compute_stats(tm, Point_3(0, 0, 0), Frame(Vector_3(0, 0, 1), Vector_3(1, 0, 0)));
  EXPECT_GE(s.min_angle_degrees, 40.0);
}

TEST(MakeDiskPatch, ReturnsTheBorderHalfedgeOnTheAxis)
{
  for (const Pose& pose : poses)
    for (std::size_t number_of_faces : {2, 3, 500}) {
      Mesh tm;
      const auto h = FAS::make_disk_patch(tm, pose.center, pose.normal, 3.0, number_of_faces,
                                          FAS::parameters::patch_axis(pose.axis));
      ASSERT_TRUE(is_border(h, tm));
      const Frame frame(pose.normal, pose.axis);
      EXPECT_LT(std::sqrt(CGAL::squared_distance(tm.point(target(h, tm)), pose.center + 3.0 * frame.u)),
                1e-9);
    }
}

// --- both -----------------------------------------------------------------------------------

template <class TM>
std::multiset<std::array<double, 9>> face_set(const TM& tm)
{
  // Faces as point triples, rotated to start at the lexicographically smallest point, so that
  // the comparison does not depend on the halfedge each face starts from but does see the
  // orientation.
  std::multiset<std::array<double, 9>> result;
  auto vpm = get(CGAL::vertex_point, tm);
  for (auto f : faces(tm)) {
    std::vector<Point_3> p;
    for (auto v : vertices_around_face(halfedge(f, tm), tm))
      p.push_back(get(vpm, v));
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    std::array<double, 9> a;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        a[3 * i + j] = p[i][j];
    result.insert(a);
  }
  return result;
}

template <class TM>
std::vector<Point_3> vertex_points(const TM& tm)
{
  std::vector<Point_3> result;
  for (auto v : vertices(tm))
    result.push_back(get(CGAL::vertex_point, tm, v));
  return result;
}

TEST(MakeSurfacePatch, SurfaceMeshAndPolyhedronGetTheSamePatch)
{
  const Pose& pose = poses[1];
  {
    Mesh sm;
    Polyhedron ph;
    FAS::make_planar_patch(sm, pose.center, pose.normal, 2.0, 1.0, 500,
                           FAS::parameters::patch_axis(pose.axis));
    FAS::make_planar_patch(ph, pose.center, pose.normal, 2.0, 1.0, 500,
                           FAS::parameters::patch_axis(pose.axis));
    expect_topological_disk(ph);
    EXPECT_EQ(vertex_points(sm), vertex_points(ph));
    EXPECT_EQ(face_set(sm), face_set(ph));
  }
  {
    Mesh sm;
    Polyhedron ph;
    FAS::make_disk_patch(sm, pose.center, pose.normal, 2.0, 500);
    FAS::make_disk_patch(ph, pose.center, pose.normal, 2.0, 500);
    expect_topological_disk(ph);
    EXPECT_EQ(vertex_points(sm), vertex_points(ph));
    EXPECT_EQ(face_set(sm), face_set(ph));
  }
}

TEST(MakeSurfacePatch, AddsANewComponentToANonEmptyMesh)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 300);
  const std::vector<Point_3> before = vertex_points(tm);
  const std::size_t faces_before = num_faces(tm);

  // Overlapping in space on purpose: the new patch still shares no vertex with the old one.
  const auto h = FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 1, 1), 1.0, 1.0, 400);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  EXPECT_EQ(number_of_border_cycles(tm), 2u);
  const std::vector<Point_3> after = vertex_points(tm);
  ASSERT_GE(after.size(), before.size());
  EXPECT_TRUE(std::equal(before.begin(), before.end(), after.begin()));

  auto fcc = tm.add_property_map<Mesh::Face_index, std::size_t>("f:cc", 0).first;
  EXPECT_EQ(PMP::connected_components(tm, fcc), 2u);
  // The returned halfedge is on the new component, which holds all the new faces.
  const std::size_t new_component = fcc[face(opposite(h, tm), tm)];
  std::size_t in_new = 0;
  for (auto f : faces(tm))
    in_new += fcc[f] == new_component ? 1 : 0;
  EXPECT_EQ(in_new, num_faces(tm) - faces_before);
  EXPECT_LE(std::abs(static_cast<double>(in_new) - 400), 40);
}

TEST(MakeSurfacePatch, WritesThroughTheGivenVertexPointMap)
{
  Mesh tm;
  auto other = tm.add_property_map<Mesh::Vertex_index, Point_3>("v:other", Point_3(7, 7, 7)).first;
  FAS::make_disk_patch(
      tm, Point_3(1, 1, 1), Vector_3(1, 0, 0), 1.0, 100,
      FAS::parameters::patch_axis(Vector_3(0, 1, 0), CGAL::parameters::vertex_point_map(other)));
  ASSERT_EQ(num_faces(tm), 100u);
  for (auto v : vertices(tm))
    EXPECT_EQ(other[v].x(), 1.0); // the plane x = 1, written through `other`
  Mesh tm2;
  auto other2 = tm2.add_property_map<Mesh::Vertex_index, Point_3>("v:other").first;
  FAS::make_planar_patch(tm2, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 100,
                         CGAL::parameters::vertex_point_map(other2));
  for (auto v : vertices(tm2))
    EXPECT_EQ(other2[v].z(), 0.0);
}

TEST(MakeSurfacePatch, LargePatches)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 1.0, 320000);
  EXPECT_LE(std::abs(static_cast<double>(num_faces(tm)) - 320000), 0.01 * 320000);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  Mesh disk;
  FAS::make_disk_patch(disk, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 320000);
  EXPECT_EQ(num_faces(disk), 320000u);
}

// --- bad input ------------------------------------------------------------------------------

template <class F>
void expect_invalid_argument_naming(const F& f, const std::string& name)
{
  expect_invalid_argument(f, {"`" + name + "`"});
}

TEST(MakeSurfacePatch, BadInputThrowsNamingTheParameter)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Point_3 o(0, 0, 0);
  const Vector_3 z(0, 0, 1);
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(5, 5, 5), z, 1.0, 50); // must survive every failure below
  const std::vector<Point_3> before = vertex_points(tm);

  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, Vector_3(0, 0, 0), 1.0, 1.0, 100); },
                                 "normal");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, Vector_3(nan, 0, 1), 1.0, 1.0, 100); },
                                 "normal");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, 0.0, 1.0, 100); }, "width");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, -1.0, 1.0, 100); }, "width");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, nan, 1.0, 100); }, "width");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, 1.0, nan, 100); }, "height");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, 1.0, inf, 100); }, "height");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, 1.0, 1.0, 1); },
                                 "target_number_of_faces");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, o, z, 1.0, 1.0, 0); },
                                 "target_number_of_faces");
  expect_invalid_argument_naming([&] { FAS::make_planar_patch(tm, Point_3(nan, 0, 0), z, 1.0, 1.0, 100); },
                                 "center");
  expect_invalid_argument_naming(
      [&] {
        FAS::make_planar_patch(tm, o, z, 1.0, 1.0, 100, FAS::parameters::patch_axis(Vector_3(0, 0, -3)));
      },
      "patch_axis");
  expect_invalid_argument_naming(
      [&] {
        FAS::make_planar_patch(tm, o, z, 1.0, 1.0, 100, FAS::parameters::patch_axis(Vector_3(0, 0, 0)));
      },
      "patch_axis");

  expect_invalid_argument_naming([&] { FAS::make_disk_patch(tm, o, Vector_3(0, 0, 0), 1.0, 100); }, "normal");
  expect_invalid_argument_naming([&] { FAS::make_disk_patch(tm, o, z, 0.0, 100); }, "radius");
  expect_invalid_argument_naming([&] { FAS::make_disk_patch(tm, o, z, nan, 100); }, "radius");
  expect_invalid_argument_naming([&] { FAS::make_disk_patch(tm, o, z, -inf, 100); }, "radius");
  expect_invalid_argument_naming([&] { FAS::make_disk_patch(tm, o, z, 1.0, 1); }, "target_number_of_faces");
  expect_invalid_argument_naming(
      [&] { FAS::make_disk_patch(tm, o, z, 1.0, 100, FAS::parameters::patch_axis(Vector_3(0, 0, 1))); },
      "patch_axis");

  EXPECT_EQ(vertex_points(tm), before);
  EXPECT_EQ(num_faces(tm), 50u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
}

} // namespace

} // namespace test_make_surface_patch
