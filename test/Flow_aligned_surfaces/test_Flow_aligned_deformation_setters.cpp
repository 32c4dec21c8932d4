// The parameters of Flow_aligned_deformation that do not enter L + W, changed after
// construction: a deformation given η, θmax, ε, the convergence step and the area correction by
// its setters iterates exactly (bit for bit) as one constructed with them, with no new
// factorization; a value out of range is refused with the parameter's name and the old value
// kept.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_Flow_aligned_deformation_setters {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Flow = CGAL::Flow_aligned_surfaces::Cylinder_potential_flow<K>;
namespace FAS = CGAL::Flow_aligned_surfaces;

Mesh tilted_patch()
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point(-2.0, 0.8, 0), Vector(0.3, 1.0, 0.4), 1.2, 1.2, 600);
  return tm;
}

std::vector<Point> points_of(const Mesh& tm)
{
  return std::vector<Point>(tm.points().begin(), tm.points().end());
}

TEST(FlowAlignedDeformationSetters, SetParametersIterateAsConstructedOnes)
{
  const Flow flow(1.0, 1.0);
  Mesh constructed_mesh = tilted_patch(), set_mesh = tilted_patch();
  FAS::Flow_aligned_deformation<Mesh, Flow> constructed(
      constructed_mesh, flow, FAS::Alignment::TANGENTIAL,
      FAS::parameters::max_rotation_angle(
          0.03, FAS::parameters::max_dihedral_angle(
                    1.0, FAS::parameters::convergence_angle(
                             1e-3, FAS::parameters::convergence_step(
                                       0, FAS::parameters::area_correction(false))))));
  FAS::Flow_aligned_deformation<Mesh, Flow> set(set_mesh, flow, FAS::Alignment::TANGENTIAL);
  // Some iterations with the defaults first, then back to the patch: the setters act between
  // iterations.
  set.run(3);
  const Mesh patch = tilted_patch();
  for (Mesh::Vertex_index v : set_mesh.vertices())
    set_mesh.point(v) = patch.point(v);
  set.set_max_rotation_angle(0.03);
  set.set_max_dihedral_angle(1.0);
  set.set_convergence_angle(1e-3);
  set.set_convergence_step(0);
  set.set_area_correction(false);
  EXPECT_EQ(set.max_rotation_angle(), 0.03);
  EXPECT_EQ(set.max_dihedral_angle(), 1.0);
  EXPECT_EQ(set.convergence_angle(), 1e-3);
  EXPECT_EQ(set.convergence_step(), 0);
  EXPECT_FALSE(set.area_correction());

  for (int k = 0; k < 12; ++k) {
    const FAS::Iteration_report a = constructed.step(), b = set.step();
    ASSERT_EQ(a.max_rotation_angle, b.max_rotation_angle) << "iteration " << k;
    ASSERT_EQ(a.converged, b.converged) << "iteration " << k;
    ASSERT_EQ(points_of(constructed_mesh), points_of(set_mesh)) << "iteration " << k;
  }
  EXPECT_EQ(set.number_of_factorizations(), 1u);
}

TEST(FlowAlignedDeformationSetters, TheRotationLimitActsAtOnce)
{
  // With η = 0.01 no face turns more than 0.01 in an iteration: the surface moves less in the
  // next iteration than with the default η = 0.1 from the same surface.
  const Flow flow(1.0, 1.0);
  Mesh slow_mesh = tilted_patch(), fast_mesh = tilted_patch();
  FAS::Flow_aligned_deformation<Mesh, Flow> slow(slow_mesh, flow, FAS::Alignment::TANGENTIAL);
  FAS::Flow_aligned_deformation<Mesh, Flow> fast(fast_mesh, flow, FAS::Alignment::TANGENTIAL);
  slow.set_max_rotation_angle(0.01);
  const FAS::Iteration_report s = slow.step(), f = fast.step();
  EXPECT_LT(s.max_vertex_step, 0.5 * f.max_vertex_step);
}

TEST(FlowAlignedDeformationSetters, OutOfRangeValuesAreRefusedAndKept)
{
  const Flow flow(1.0, 1.0);
  Mesh tm = tilted_patch();
  FAS::Flow_aligned_deformation<Mesh, Flow> d(tm, flow, FAS::Alignment::ORTHOGONAL);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto refused = [](const auto& set, const std::string& name) {
    try {
      set();
      ADD_FAILURE() << name << ": no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  refused([&] { d.set_max_rotation_angle(0); }, "max_rotation_angle");
  refused([&] { d.set_max_rotation_angle(4); }, "max_rotation_angle");
  refused([&] { d.set_max_dihedral_angle(nan); }, "max_dihedral_angle");
  refused([&] { d.set_convergence_angle(-1); }, "convergence_angle");
  refused([&] { d.set_convergence_step(nan); }, "convergence_step");
  EXPECT_EQ(d.max_rotation_angle(), 0.1);
  EXPECT_EQ(d.max_dihedral_angle(), CGAL_PI / 2);
  EXPECT_EQ(d.convergence_angle(), 1e-6);
  EXPECT_EQ(d.convergence_step(), 1e-4);
}

} // namespace

} // namespace test_Flow_aligned_deformation_setters
