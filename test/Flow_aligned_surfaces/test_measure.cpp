// normalized_flux and compute_face_normalized_flux against closed forms in uniform
// and piecewise uniform flows; the sampled area fraction of surfaces partly and wholly outside
// a box domain, in the measure and in the deformation's reports.

#include "centroid_area.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>

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
      EXPECT_NEAR(FAS::normalized_flux(tm, uniform).value.value(), std::abs(std::cos(tilt)), 1e-12)
          << "tilt " << tilt;
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
  const double sampled_area = fas_test::centroid_area(tm, [](const Point& c) { return c.x() < 0.25; }).area;
  const double orthogonal_area = fas_test::centroid_area(tm, [](const Point& c) { return c.x() < 0; }).area;
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

// A uniform flow u in the box [-1, 0.25] x [-1, 1] x [-1, 1], nothing outside.
const auto box_flow = [](const Point& p) -> std::optional<Vector> {
  if (p.x() < -1 || p.x() >= 0.25 || std::abs(p.y()) > 1 || std::abs(p.z()) > 1)
    return std::nullopt;
  return Vector(0.6, 0, 0.8);
};

// The faces of tm whose centroids are inside the box.
fas_test::Centroid_area inside_the_box(const Mesh& tm)
{
  return fas_test::centroid_area(tm, [](const Point& c) { return bool(box_flow(c)); });
}

double inside_the_box_fraction(const Mesh& tm)
{
  const fas_test::Centroid_area inside = inside_the_box(tm);
  return inside.area / inside.total_area;
}

TEST(Measure, ASurfaceOutsideTheDomainHasNoFluxValue)
{
  // Wholly outside the box: no face is sampled, so there is no value; 0 would read as "tangential".
  Mesh tm;
  FAS::make_planar_patch(tm, Point(3, 0, 0), Vector(0, 0, 1), 1.0, 1.0, 400);
  const FAS::Normalized_flux flux = FAS::normalized_flux(tm, box_flow);
  EXPECT_FALSE(flux.value.has_value());
  EXPECT_EQ(flux.sampled_area_fraction, 0.0);
  std::ostringstream os;
  os << flux;
  EXPECT_EQ(os.str(), "none (no face sampled)");

  const auto nowhere = [](const Point&) -> std::optional<Vector> { return std::nullopt; };
  Mesh disk;
  FAS::make_disk_patch(disk, Point(0, 0, 0), Vector(0, 0, 1), 1.0, 100);
  EXPECT_FALSE(FAS::normalized_flux(disk, nowhere).value.has_value());
}

TEST(Measure, ASurfacePartlyOutsideTheDomainGivesItsSampledAreaFraction)
{
  // The unit square in z = 0 about the origin, the box ending at x = 0.25: three quarters of its
  // area are inside (up to the faces the plane x = 0.25 cuts), where |n . u| / |u| = 0.8.
  Mesh tm;
  FAS::make_planar_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), 1.0, 1.0, 2000);
  const FAS::Normalized_flux flux = FAS::normalized_flux(tm, box_flow);
  EXPECT_NEAR(flux.value.value(), 0.8, 1e-12);
  EXPECT_NEAR(flux.sampled_area_fraction, 0.75, 0.02);
  EXPECT_NEAR(flux.sampled_area_fraction, inside_the_box_fraction(tm), 1e-12);
  std::ostringstream os;
  os << flux;
  EXPECT_NE(os.str().find("% of the area)"), std::string::npos) << os.str();

  // The deformation's reports say the same: of the surface an iteration starts from, and of
  // the final surface.
  FAS::Flow_aligned_deformation<Mesh, decltype(box_flow)> deformation(tm, box_flow,
                                                                      FAS::Alignment::ORTHOGONAL);
  const FAS::Iteration_report first = deformation.step();
  EXPECT_NEAR(first.normalized_flux.value.value(), 0.8, 1e-12);
  EXPECT_NEAR(first.normalized_flux.sampled_area_fraction, flux.sampled_area_fraction, 1e-12);
  const FAS::Alignment_report report = deformation.run(5);
  const FAS::Normalized_flux now = FAS::normalized_flux(tm, box_flow);
  EXPECT_NEAR(report.normalized_flux.value.value(), now.value.value(), 1e-12);
  EXPECT_NEAR(report.normalized_flux.sampled_area_fraction, now.sampled_area_fraction, 1e-12);
  EXPECT_NEAR(report.normalized_flux.sampled_area_fraction, inside_the_box_fraction(tm), 1e-12);
  EXPECT_LT(inside_the_box(tm).number_of_faces, tm.number_of_faces());

  // Moved out of the domain: the next iteration's report has no value.
  deformation.translate(Vector(5, 0, 0));
  const FAS::Iteration_report outside = deformation.step();
  EXPECT_FALSE(outside.normalized_flux.value.has_value());
  EXPECT_EQ(outside.normalized_flux.sampled_area_fraction, 0.0);
  EXPECT_EQ(outside.number_of_outside_samples, tm.number_of_faces());
  EXPECT_FALSE(deformation.current_normalized_flux().value.has_value());
}

} // namespace

} // namespace test_measure
