// Path_surface_flow_field_3: the flow a path surface saw.  On the path surface of a swirl whose
// axis drifts, v = (-y, x - 0.2 t, 0.3), released at t0 = 0 and integrated for 1.5: at every
// vertex the field is v at the vertex's own time t0 + tau, at a face centroid at the mean of its
// vertices' times.  On the path surface of a uniform flow that turns in time, the tangential
// parametrization in it follows the path lines (its gradient 4.3 degrees off them on average, the
// floor of these curved path lines), where the flow of the middle time leaves it 19.8 degrees
// off.  Bad surfaces are refused.

#include <CGAL/Flow_aligned_surfaces/Path_surface_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Time_slice_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/integrate_stream_surface.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>

#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "expect_invalid_argument.h"
#include "test_kernel.h"

#include <cmath>
#include <optional>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Path_surface_flow_field_3 {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Time_map = Mesh::Property_map<Vertex, double>;

std::optional<Vector_3> drifting_swirl(const Point_3& p, double t) { return Vector_3(-p.y(), p.x() - 0.2 * t, 0.3); }

// A uniform flow turning at one radian per unit of time and rising, then sinking: the path lines
// are helical arcs, and the flow of any one time is tangent to their surface along one line only.
std::optional<Vector_3> turning_flow(const Point_3&, double t)
{
  return Vector_3(std::cos(t), std::sin(t), t - 0.75);
}

using Unsteady = std::optional<Vector_3> (*)(const Point_3&, double);
using Flow_on_surface = FAS::Path_surface_flow_field_3<Unsteady, Mesh, Time_map>;

// The path surface of a radial seed segment released at t = 0, with the time of each vertex.
struct Path_surface {
  Mesh tm;
  Time_map time;

  explicit Path_surface(Unsteady flow = &drifting_swirl,
                        const std::vector<Point_3>& seed = {Point_3(0.4, 0, 0), Point_3(0.9, 0, 0)})
  {
    auto tau = tm.add_property_map<Vertex, double>("v:tau", 0.).first;
    FAS::integrate_stream_surface(flow, seed, tm,
                                  FAS::parameters::start_time(0., FAS::parameters::max_time(1.5,
                                    FAS::parameters::front_spacing(0.02, FAS::parameters::time_line_step(0.02,
                                      FAS::parameters::integration_time_map(tau))))));
    time = tm.add_property_map<Vertex, double>("v:time", 0.).first;
    for (Vertex v : tm.vertices())
      time[v] = 0. + tau[v];
  }
};

TEST(PathSurfaceFlowField, SamplesTheFlowAtTheTimeTheSurfacePassed)
{
  const Path_surface s;
  ASSERT_GT(s.tm.number_of_faces(), 100u);
  const Flow_on_surface flow(&drifting_swirl, s.tm, s.time);
  for (Vertex v : s.tm.vertices()) {
    const Point_3& p = s.tm.point(v);
    ASSERT_NEAR(flow.time(p), s.time[v], 1e-9);
    ASSERT_NEAR(flow(p)->y(), drifting_swirl(p, s.time[v])->y(), 1e-9);
  }
  for (Mesh::Face_index f : s.tm.faces()) {
    double mean = 0;
    Vector_3 centroid(0, 0, 0);
    for (Vertex v : s.tm.vertices_around_face(s.tm.halfedge(f))) {
      mean += s.time[v] / 3;
      centroid = centroid + (s.tm.point(v) - CGAL::ORIGIN) / 3;
    }
    ASSERT_NEAR(flow.time(CGAL::ORIGIN + centroid), mean, 1e-9);
  }
}

TEST(PathSurfaceFlowField, TangentialParametrizationFollowsThePathLines)
{
  Path_surface s(&turning_flow, {Point_3(0, 0, 0), Point_3(0, 0, 1)});
  const Flow_on_surface flow(&turning_flow, s.tm, s.time);
  auto r = s.tm.add_property_map<Vertex, double>("v:r", 0.).first;
  auto q = s.tm.add_property_map<Vertex, double>("v:s", 0.).first;
  ASSERT_TRUE(FAS::parametrize_tangential(s.tm, flow, r, q));
  const FAS::Alignment_angle_statistics along = FAS::alignment_angle_statistics(s.tm, flow, r);
  // The flow of the middle time, which the path surface is not tangent to.
  const FAS::Time_slice_flow_field_3<Unsteady> middle(&turning_flow, 0.75);
  auto r_middle = s.tm.add_property_map<Vertex, double>("v:r_middle", 0.).first;
  ASSERT_TRUE(FAS::parametrize_tangential(s.tm, middle, r_middle, q));
  const FAS::Alignment_angle_statistics frozen = FAS::alignment_angle_statistics(s.tm, flow, r_middle);
  EXPECT_LT(along.mean, 6.) << "frozen " << frozen.mean; // measured 4.3 (the curved path lines' floor), 19.8
  EXPECT_GT(frozen.mean, 3 * along.mean) << "along " << along.mean;
}

TEST(PathSurfaceFlowField, RefusesASurfaceWithoutFaces)
{
  Mesh empty;
  const Time_map time = empty.add_property_map<Vertex, double>("v:time", 0.).first;
  expect_invalid_argument([&] { Flow_on_surface(&drifting_swirl, empty, time); },
                          {"Path_surface_flow_field_3", "no face"});
}

} // namespace

} // namespace test_Path_surface_flow_field_3
