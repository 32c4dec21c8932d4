// The parametrizations of Flow_aligned_deformation, which reuse its factored L + W on M_0,
// against the free functions of parametrize.h on the same surface and against closed forms on
// aligned surfaces: the potential of the flow past a cylinder on one of its stream surfaces
// (r = phi up to a constant) and the great-circle distance on the sphere that a patch becomes
// around a point source.

#include "expect_invalid_argument.h"
#include "scalar_field_errors.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Bbox_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_Flow_aligned_deformation_parametrize {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Scalar_map = Mesh::Property_map<Vertex, double>;

Scalar_map add_scalar(Mesh& tm, const std::string& name)
{
  return tm.add_property_map<Vertex, double>(name, 0.0).first;
}

// max |f - g| / (max g - min g) over the vertices.
double relative_max_difference(const Mesh& tm, Scalar_map f, Scalar_map g)
{
  double largest = 0, low = std::numeric_limits<double>::infinity(), high = -low;
  for (Vertex v : tm.vertices()) {
    largest = (std::max)(largest, std::abs(f[v] - g[v]));
    low = (std::min)(low, g[v]);
    high = (std::max)(high, g[v]);
  }
  return largest / (high - low);
}

Vertex nearest_vertex(const Mesh& tm, const Point_3& p)
{
  return *std::min_element(tm.vertices().begin(), tm.vertices().end(), [&](Vertex a, Vertex b) {
    return CGAL::squared_distance(tm.point(a), p) < CGAL::squared_distance(tm.point(b), p);
  });
}

using Cylinder_deformation = FAS::Flow_aligned_deformation<Mesh, FAS::Cylinder_potential_flow<K>>;

// The mean edge length over the bounding-box diagonal.
double relative_edge_length(const Mesh& tm)
{
  double length = 0;
  for (auto e : tm.edges())
    length += std::sqrt(CGAL::squared_distance(tm.point(tm.vertex(e, 0)), tm.point(tm.vertex(e, 1))));
  const CGAL::Bbox_3 box = CGAL::bbox_3(tm.points().begin(), tm.points().end());
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  return length / double(tm.number_of_edges()) / diagonal;
}

TEST(DeformationParametrize, OnTheReferenceSurfaceItMatchesTheFreeFunctions)
{
  // Before any iteration M_k = M_0, and the shared factorization must give the free functions'
  // answers up to its soft constraint: weight 1e-3 of the mean diagonal of L on the three
  // vertices of the constrained face, whose values differ by about h |grad r|, a relative
  // perturbation of the order of 1e-3 h / diameter (documented).
  const FAS::Cylinder_potential_flow<K> flow;
  Mesh tm; // the plane z = 0 is a stream surface of the flow past the cylinder
  FAS::make_planar_patch(tm, Point_3(-2.2, 0.8, 0), Vector_3(0, 0, 1), 1.2, 1.0, 4000);
  const double tolerance = 3e-3 * relative_edge_length(tm);
  const Cylinder_deformation deformation(tm, flow, FAS::Alignment::TANGENTIAL);

  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s"), r_free = add_scalar(tm, "v:rf"),
       s_free = add_scalar(tm, "v:sf");
  for (bool normalized : {false, true}) {
    deformation.parametrize_tangential(r, s, FAS::parameters::normalized(normalized));
    FAS::parametrize_tangential(tm, flow, r_free, s_free, FAS::parameters::normalized(normalized));
    EXPECT_LE(relative_max_difference(tm, r, r_free), tolerance) << "normalized " << normalized;
    EXPECT_LE(relative_max_difference(tm, s, s_free), tolerance) << "normalized " << normalized;
  }
  const Vertex corner = nearest_vertex(tm, Point_3(-2.8, 0.3, 0));
  deformation.compute_geodesic_distance(corner, r);
  FAS::compute_geodesic_distance(tm, corner, r_free);
  EXPECT_EQ(r[corner], 0.0);
  EXPECT_LE(relative_max_difference(tm, r, r_free), tolerance);

  Mesh across; // upstream, the plane x = -3 is nearly orthogonal to the flow
  FAS::make_planar_patch(across, Point_3(-3, 0.5, 0), Vector_3(1, 0, 0), 1.0, 1.0, 4000);
  const Cylinder_deformation orthogonal(across, flow, FAS::Alignment::ORTHOGONAL);
  auto ra = add_scalar(across, "v:r"), sa = add_scalar(across, "v:s"), ra_free = add_scalar(across, "v:rf"),
       sa_free = add_scalar(across, "v:sf");
  orthogonal.parametrize_orthogonal(ra, sa, FAS::parameters::angle(0.4));
  FAS::parametrize_orthogonal(across, flow, ra_free, sa_free, FAS::parameters::angle(0.4));
  EXPECT_LE(relative_max_difference(across, ra, ra_free), 3e-3 * relative_edge_length(across));
  EXPECT_LE(relative_max_difference(across, sa, sa_free), 3e-3 * relative_edge_length(across));
  // The same with a gradient direction instead of the Householder frame.
  const auto aimed = FAS::parameters::gradient_direction(Vector_3(0.2, 1, 1), FAS::parameters::angle(0.4));
  orthogonal.parametrize_orthogonal(ra, sa, aimed);
  FAS::parametrize_orthogonal(across, flow, ra_free, sa_free, aimed);
  EXPECT_LE(relative_max_difference(across, ra, ra_free), 3e-3 * relative_edge_length(across));
  EXPECT_LE(relative_max_difference(across, sa, sa_free), 3e-3 * relative_edge_length(across));
}

TEST(DeformationParametrize, OnAnAlignedStreamSurfaceTheUnnormalizedRIsThePotential)
{
  // A tilted patch beside the cylinder becomes a curved stream surface psi = const; there the
  // flow is tangential, grad r = v = grad phi, so r = phi up to a constant.
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(-1.9, 1.05, 0), Vector_3(0.15, 1, 0.25), 1.4, 0.8, 5000);
  const FAS::Cylinder_potential_flow<K> flow;
  Cylinder_deformation deformation(tm, flow, FAS::Alignment::TANGENTIAL,
                                   CGAL::parameters::number_of_iterations(60));
  deformation.run();
  ASSERT_LE(FAS::normalized_flux(tm, flow).value.value(), 0.01);

  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
  deformation.parametrize_tangential(r, s, FAS::parameters::normalized(false));
  const auto potential = [&](const Point_3& p) { return flow.potential(p); };
  const double shared_error = relative_error_up_to_constant(tm, r, potential);

  auto r_free = add_scalar(tm, "v:rf"), s_free = add_scalar(tm, "v:sf");
  FAS::parametrize_tangential(tm, flow, r_free, s_free, FAS::parameters::normalized(false));
  const double free_error = relative_error_up_to_constant(tm, r_free, potential);
  std::cout << "relative L2 error of r against the potential: shared factorization " << shared_error
            << ", own factorization " << free_error << std::endl;
  EXPECT_LE(shared_error, 1e-3);
  EXPECT_LE(free_error, 1e-3);
}

TEST(DeformationParametrize, OnAnAlignedSphereTheDistanceIsTheGreatCircleDistance)
{
  // Orthogonal to a point source a patch becomes a piece of a sphere about the source.
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 1), Vector_3(0, 0, 1), 0.9, 5000);
  const FAS::Point_source_flow<K> flow;
  FAS::Flow_aligned_deformation<Mesh, FAS::Point_source_flow<K>> deformation(
      tm, flow, FAS::Alignment::ORTHOGONAL, CGAL::parameters::number_of_iterations(60));
  deformation.run();
  ASSERT_GE(FAS::normalized_flux(tm, flow).value.value(), 0.999);

  const Vertex pole = nearest_vertex(tm, Point_3(0, 0, 2));
  auto d = add_scalar(tm, "v:d");
  deformation.compute_geodesic_distance(pole, d);
  const Vector_3 pole_direction =
      (tm.point(pole) - CGAL::ORIGIN) / std::sqrt((tm.point(pole) - CGAL::ORIGIN).squared_length());
  double error = 0;
  std::size_t count = 0;
  for (Vertex v : tm.vertices()) {
    const Vector_3 p = tm.point(v) - CGAL::ORIGIN;
    const double radius = std::sqrt(p.squared_length());
    const double exact = radius * std::acos(std::clamp(p * pole_direction / radius, -1.0, 1.0));
    if (exact > 0.05) {
      error += std::abs(d[v] - exact) / exact;
      ++count;
    }
  }
  error /= double(count);
  std::cout << "mean relative error against the great-circle distance: " << error << std::endl;
  EXPECT_LE(error, 0.01);
}

TEST(DeformationParametrize, BadInputIsRefusedAndTheMapsUntouched)
{
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(-2.2, 0.8, 0), Vector_3(0, 0, 1), 1.2, 1.0, 500);
  const FAS::Cylinder_potential_flow<K> flow;
  const Cylinder_deformation deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
  const Vertex missing(static_cast<Mesh::size_type>(tm.number_of_vertices() + 10));

  expect_invalid_argument(
      [&] { deformation.parametrize_tangential(r, s, FAS::parameters::constraint_vertex(missing)); },
      {"parametrize_tangential", "constraint_vertex", "not a vertex"});
  expect_invalid_argument(
      [&] { deformation.parametrize_orthogonal(r, s, FAS::parameters::angle(std::nan(""))); },
      {"parametrize_orthogonal", "angle", "finite"});
  expect_invalid_argument([&] { deformation.compute_geodesic_distance(missing, r); },
                          {"compute_geodesic_distance", "source", "not a vertex"});
  for (Vertex v : tm.vertices()) {
    EXPECT_EQ(r[v], 0.0);
    EXPECT_EQ(s[v], 0.0);
  }

  // A field that is outside its domain on the whole surface gives no direction.
  Mesh inside;
  FAS::make_planar_patch(inside, Point_3(0, 0, 0), Vector_3(0, 0, 1), 0.5, 0.5, 200);
  const auto nowhere = [](const Point_3&) { return std::optional<Vector_3>(); };
  FAS::Flow_aligned_deformation<Mesh, decltype(nowhere)> empty(inside, nowhere, FAS::Alignment::TANGENTIAL);
  auto ri = add_scalar(inside, "v:r"), si = add_scalar(inside, "v:s");
  expect_invalid_argument([&] { empty.parametrize_tangential(ri, si); },
                          {"parametrize_tangential", "no usable direction"});
}

} // namespace

} // namespace test_Flow_aligned_deformation_parametrize
