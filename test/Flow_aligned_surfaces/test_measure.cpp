// normalized_flux and compute_face_normalized_flux against closed forms in uniform
// and piecewise uniform flows.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_measure {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace FAS = CGAL::Flow_aligned_surfaces;

TEST(Measure, FluxOfATiltedPlaneInAUniformFlowIsTheCosineOfTheTilt)
{
  const auto uniform = [](const Point&) -> std::optional<Vector> { return Vector(0, 0, 2.5); };
  for (double tilt : {0.0, 0.3, 1.0, CGAL_PI / 2, 2.5}) {
    for (double sign : {1.0, -1.0}) { // the measure does not depend on the orientation
      Mesh tm;
      FAS::make_planar_patch(tm, Point(1, 2, 3), Vector(sign * std::sin(tilt), 0, sign * std::cos(tilt)), 1.0,
                             0.7, 300);
      EXPECT_NEAR(FAS::normalized_flux(tm, uniform).value.value(), std::abs(std::cos(tilt)), 1e-12) << "tilt " << tilt;
      auto flux = tm.add_property_map<Mesh::Face_index, double>("f:flux", 0).first;
      FAS::compute_face_normalized_flux(tm, uniform, flux);
      for (auto f : tm.faces())
        EXPECT_NEAR(flux[f], std::abs(std::cos(tilt)), 1e-12);
    }
  }
}

TEST(Measure, FluxIsAreaWeightedAndSkipsFacesWithoutASample)
{
  // Orthogonal flow where x < 0, tangential flow where 0 <= x < 0.25, outside the domain beyond.
  const auto piecewise = [](const Point& p) -> std::optional<Vector> {
    if (p.x() < 0)
      return Vector(0, 0, 1);
    if (p.x() < 0.25)
      return Vector(1, 0, 0);
    return std::nullopt;
  };
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), 1.0, 1.0, 2000);
  double orthogonal_area = 0, sampled_area = 0;
  for (auto f : tm.faces()) {
    const auto h = tm.halfedge(f);
    const double cx =
        (tm.point(tm.source(h)).x() + tm.point(tm.target(h)).x() + tm.point(tm.target(tm.next(h))).x()) / 3;
    const double area = CGAL::Polygon_mesh_processing::face_area(f, tm);
    if (cx < 0.25)
      sampled_area += area;
    if (cx < 0)
      orthogonal_area += area;
  }
  EXPECT_NEAR(FAS::normalized_flux(tm, piecewise).value.value(), orthogonal_area / sampled_area, 1e-12);

  auto flux = tm.add_property_map<Mesh::Face_index, double>("f:flux", 0).first;
  FAS::compute_face_normalized_flux(tm, piecewise, flux);
  std::size_t outside = 0;
  for (auto f : tm.faces()) {
    EXPECT_TRUE(flux[f] == -1 || std::abs(flux[f]) < 1e-12 || std::abs(flux[f] - 1) < 1e-12);
    outside += flux[f] == -1;
  }
  EXPECT_GT(outside, 0u);
}

TEST(Measure, NoUsableSampleGivesZero)
{
  const auto nowhere = [](const Point&) -> std::optional<Vector> { return std::nullopt; };
  Mesh tm;
  FAS::make_disk_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), 1.0, 100);
  EXPECT_EQ(FAS::normalized_flux(tm, nowhere).value.value(), 0.0);
}

} // namespace

} // namespace test_measure
