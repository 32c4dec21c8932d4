// The workflows that the examples and the demo's programs run, checked against what is known
// independently (these checks were the programs' exit codes before they became examples and
// applications):
// - an interactive session: rigid moves need no refactorization, growing needs one, and the grown
//   surface is a stream surface again (the example interactive_deformation.cpp);
// - a LIC-like texture on a stream surface above a cylinder is barely masked (flow_texture);
// - seed curves on an orthogonal surface of a point source, iso-contours of the orthogonal
//   parametrization and of the geodesic distance, are orthogonal to the flow; iso-contours of the
//   tangential parametrization of a stream surface cross the flow (seed_curves);
// - stream lines from seed points on that orthogonal surface are the source's rays (streamlines);
// - stream surfaces seeded by the crossing curves keep the Burgers vortex's first integral
//   rho^2 z and have no flux (stream_surfaces).
// The scenes, sizes and thresholds are those of the programs' tests.

#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/align_to_flow.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/extract_iso_contours.h>
#include <CGAL/Flow_aligned_surfaces/flow_texture.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/integrate_streamline.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Flow_aligned_surfaces/seeds.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_workflows {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;
using Polyline = std::vector<Point_3>;

// The orthogonal surface of the seeding programs: a tilted disk beside the point source at the
// origin, aligned orthogonally (it becomes a piece of a sphere about the source).
FAS::Alignment_report orthogonal_disk(Mesh& tm, const FAS::Point_source_flow<K>& flow, std::size_t faces)
{
  FAS::make_disk_patch(tm, Point_3(0, 0, 1), Vector_3(0.3, 0, 1), 0.6, faces);
  return FAS::align_to_flow(tm, flow, FAS::Alignment::ORTHOGONAL);
}

// Seed curves across the flow (the paper's Figure 4, top): a disk beside the Burgers vortex's
// axis aligned tangentially (a piece of stream surface), the iso-contours of its tangential r.
struct Tangential_seed_curves {
  Mesh surface;
  FAS::Alignment_report alignment;
  std::vector<Polyline> curves;
};

Tangential_seed_curves tangential_seed_curves(const FAS::Burgers_vortex<K>& flow, std::size_t faces,
                                              std::size_t number_of_curves)
{
  Tangential_seed_curves seeds;
  Mesh& tm = seeds.surface;
  FAS::make_disk_patch(tm, Point_3(1.0, 0.0, 0.5), Vector_3(0.0, 1.0, 0.3), 0.5, faces);
  seeds.alignment = FAS::align_to_flow(tm, flow, FAS::Alignment::TANGENTIAL);
  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  FAS::parametrize_tangential(tm, flow, r, s);
  FAS::extract_iso_contours(tm, r, FAS::evenly_spaced_iso_values(tm, r, number_of_curves),
                            std::back_inserter(seeds.curves));
  return seeds;
}

// The mean over the segments of `curves` of |cos| between the segment and the flow at its midpoint.
template <class Flow>
double mean_cosine_to_flow(const Flow& flow, const std::vector<Polyline>& curves)
{
  double cosine = 0;
  std::size_t segments = 0;
  for (const Polyline& curve : curves)
    for (std::size_t i = 1; i < curve.size(); ++i) {
      const Vector_3 d = curve[i] - curve[i - 1];
      const Vector_3 v = *flow(CGAL::midpoint(curve[i - 1], curve[i]));
      if (d.squared_length() > 0) {
        cosine += std::abs(d * v) / std::sqrt(d.squared_length() * v.squared_length());
        ++segments;
      }
    }
  return segments > 0 ? cosine / double(segments) : 1.0;
}

// The point of `curve` at arc length u from its first point.
Point_3 point_at_arc_length(const Polyline& curve, double u)
{
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const double length = std::sqrt(CGAL::squared_distance(curve[i - 1], curve[i]));
    if (u <= length || i + 1 == curve.size())
      return curve[i - 1] + (std::min(u, length) / length) * (curve[i] - curve[i - 1]);
    u -= length;
  }
  return curve.front();
}

TEST(InteractiveDeformationWorkflow, RigidMovesNeedNoRefactorizationGrowingNeedsOne)
{
  const FAS::Burgers_vortex<K> flow;
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(1.0, 0.0, 0.5), Vector_3(0.0, 1.0, 0.3), 0.5, 2000);
  FAS::Flow_aligned_deformation<Mesh, FAS::Burgers_vortex<K>> deformation(
      tm, flow, FAS::Alignment::TANGENTIAL, FAS::parameters::max_rotation_angle(0.1));
  for (int k = 0; k < 3; ++k)
    deformation.step();
  deformation.run();

  deformation.translate(Vector_3(0.0, 0.0, 0.5));
  deformation.rotate(Vector_3(0.0, 0.0, 1.0), 0.3);
  const FAS::Alignment_report moved = deformation.run();
  EXPECT_TRUE(moved.converged);
  EXPECT_EQ(deformation.number_of_factorizations(), 1u) << "a rigid move refactored";

  deformation.grow(0.1, FAS::parameters::across_flow(true));
  const FAS::Alignment_report grown = deformation.run();
  EXPECT_TRUE(grown.converged);
  EXPECT_LE(grown.normalized_flux.value.value(), 0.01) << "the grown surface is a stream surface again";
  EXPECT_EQ(deformation.number_of_factorizations(), 2u) << "growing refactors once";
}

TEST(FlowTextureWorkflow, StreamSurfaceAboveCylinderIsBarelyMasked)
{
  const FAS::Cylinder_potential_flow<K> flow(1.0, 1.0);
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(0, 2.2, 0), Vector_3(0, 0.25, 1), 2.4, 2.0, 1500);
  const FAS::Alignment_report report = FAS::align_to_flow(tm, flow, FAS::Alignment::TANGENTIAL);
  EXPECT_LE(report.normalized_flux.value.value(), 0.01) << "a stream surface";

  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  FAS::parametrize_tangential(tm, flow, r, s, FAS::parameters::normalized(false));
  auto mask = tm.add_property_map<Face, double>("f:mask", 1).first;
  FAS::compute_flow_texture_mask(tm, flow, r, mask);
  double masked = 0;
  for (Face f : tm.faces())
    masked += mask[f] / double(tm.number_of_faces());
  EXPECT_LT(masked, 0.1) << "the texture follows the flow almost everywhere";
}

TEST(SeedCurvesWorkflow, SeedsOnAnOrthogonalSurfaceAreOrthogonalToTheFlow)
{
  const FAS::Point_source_flow<K> flow;
  Mesh tm;
  const FAS::Alignment_report report = orthogonal_disk(tm, flow, 3000);
  EXPECT_GE(report.normalized_flux.value.value(), 0.99);

  auto r = tm.add_property_map<Vertex, double>("v:r", 0).first;
  auto s = tm.add_property_map<Vertex, double>("v:s", 0).first;
  auto distance = tm.add_property_map<Vertex, double>("v:distance", 0).first;
  FAS::parametrize_orthogonal(tm, flow, r, s, FAS::parameters::angle(0.5));
  Vertex center = *tm.vertices().begin();
  for (Vertex v : tm.vertices()) // the constrained vertex, where r = 0
    if (std::abs(r[v]) < std::abs(r[center]))
      center = v;
  FAS::compute_geodesic_distance(tm, center, distance);

  std::vector<Polyline> curves; // the iso-contours of r, then the circular seeds
  FAS::extract_iso_contours(tm, r, FAS::evenly_spaced_iso_values(tm, r, 7), std::back_inserter(curves));
  const std::size_t number_of_seed_curves = curves.size();
  FAS::extract_iso_contours(tm, distance, std::vector<double>{0.1, 0.2, 0.3, 0.4},
                            std::back_inserter(curves));
  EXPECT_GT(number_of_seed_curves, 0u);
  EXPECT_EQ(curves.size() - number_of_seed_curves, 4u) << "one circle per distance";
  EXPECT_LT(mean_cosine_to_flow(flow, curves), 0.05);
}

TEST(SeedCurvesWorkflow, SeedCurvesOfAStreamSurfaceCrossTheFlow)
{
  const FAS::Burgers_vortex<K> flow;
  const Tangential_seed_curves seeds = tangential_seed_curves(flow, 3000, 5);
  EXPECT_LE(seeds.alignment.normalized_flux.value.value(), 0.01);
  EXPECT_FALSE(seeds.curves.empty());
  EXPECT_LT(mean_cosine_to_flow(flow, seeds.curves), 0.1);
}

TEST(StreamlinesWorkflow, SeedPointsOnAnOrthogonalSurfaceSeedRays)
{
  const FAS::Point_source_flow<K> flow;
  Mesh tm;
  orthogonal_disk(tm, flow, 800);
  std::vector<Point_3> seeds;
  FAS::sample_seed_points(tm, 0.15, std::back_inserter(seeds));
  ASSERT_FALSE(seeds.empty());

  double worst_off_ray = 0; // the stream lines of a point source are rays from it
  for (const Point_3& seed : seeds) {
    std::vector<Point_3> line;
    FAS::integrate_streamline(
        flow, seed, std::back_inserter(line),
        FAS::parameters::max_length(1.5, FAS::parameters::integration_direction(FAS::Integration_direction::BOTH)));
    EXPECT_GT(line.size(), 1u);
    const Vector_3 ray = (seed - CGAL::ORIGIN) / std::sqrt((seed - CGAL::ORIGIN).squared_length());
    for (const Point_3& p : line)
      worst_off_ray =
          std::max(worst_off_ray, std::sqrt(CGAL::cross_product(p - CGAL::ORIGIN, ray).squared_length()));
  }
  EXPECT_LE(worst_off_ray, 1e-6);
}

TEST(StreamSurfacesWorkflow, StreamSurfacesFromTangentialSeedCurves)
{
  const FAS::Burgers_vortex<K> flow;
  const Tangential_seed_curves seeds = tangential_seed_curves(flow, 800, 5);
  ASSERT_FALSE(seeds.curves.empty());
  for (std::size_t c = 0; c < seeds.curves.size(); ++c) {
    const Polyline& seed = seeds.curves[c];
    Mesh tm;
    auto u = tm.add_property_map<Vertex, double>("v:u", 0).first;
    auto t = tm.add_property_map<Vertex, double>("v:t", 0).first;
    FAS::integrate_stream_surface( // forward and backward, joined at the seed
        flow, seed, tm,
        FAS::parameters::front_spacing(
            0.02, FAS::parameters::max_time(
                      1.0, FAS::parameters::integration_direction(
                               FAS::Integration_direction::BOTH,
                               FAS::parameters::seed_parameter_map(u, FAS::parameters::integration_time_map(t))))));
    ASSERT_GT(tm.number_of_faces(), 0u) << "seed curve " << c;

    // rho^2 z is constant along the vortex's stream lines: each vertex keeps its seed point's.
    double drift = 0;
    for (Vertex v : tm.vertices()) {
      const double psi0 = flow.stokes_stream_function(point_at_arc_length(seed, u[v]));
      drift = std::max(drift, std::abs(flow.stokes_stream_function(tm.point(v)) - psi0) /
                                  std::max(std::abs(psi0), 1e-3));
    }
    EXPECT_LE(drift, 1e-5) << "seed curve " << c;
    EXPECT_LE(FAS::normalized_flux(tm, flow).value.value(), 0.01) << "seed curve " << c;
  }
}

} // namespace

} // namespace test_workflows
