// parametrize_tangential, parametrize_orthogonal and compute_geodesic_distance against closed
// forms: stream functions and potentials of 2D flows on a plane, linear fields in uniform flows,
// Euclidean and great-circle distances, and CGAL's own heat method on the same mesh.

#include "expect_invalid_argument.h"
#include "scalar_field_errors.h"
#include "test_kernel.h"

#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/parametrize.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_parametrize {

namespace {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex = Mesh::Vertex_index;
using Scalar_map = Mesh::Property_map<Vertex, double>;
using Scalar = std::function<double(const Point_3&)>;

Scalar_map add_scalar(Mesh& tm, const std::string& name, double initial = 0)
{
  return tm.add_property_map<Vertex, double>(name, initial).first;
}

struct Planar_case {
  const char* name;
  std::function<std::optional<Vector_3>(const Point_3&)> field;
  Scalar exact; // the stream function (divergence-free) or the potential (curl-free)
};

// The unnormalized tangential parametrization of a 2 x 2 square centered at (0.3, 0.2) in the
// plane z = 0; returns the relative errors of r against `potential` (or of s against
// -`stream_function`) at 2.5e3 and 1e4 faces.
std::vector<double> planar_errors(const Planar_case& c, bool stream_function)
{
  std::vector<double> errors;
  for (std::size_t faces : {2500u, 10000u}) {
    Mesh tm;
    FAS::make_planar_patch(tm, Point_3(0.3, 0.2, 0), Vector_3(0, 0, 1), 2.0, 2.0, faces);
    auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
    FAS::parametrize_tangential(tm, c.field, r, s, FAS::parameters::normalized(false));
    if (stream_function)
      errors.push_back(relative_error_up_to_constant(tm, s, [&](const Point_3& p) { return -c.exact(p); }));
    else
      errors.push_back(relative_error_up_to_constant(tm, r, c.exact));
  }
  return errors;
}

TEST(Parametrize, UnnormalizedTangentialSIsMinusTheStreamFunctionOfADivergenceFreeFlow)
{
  // v = (d psi/dy, -d psi/dx, 0).
  const Planar_case cases[] = {
      {"saddle", [](const Point_3& p) { return std::optional<Vector_3>(Vector_3(p.x(), -p.y(), 0)); },
       [](const Point_3& p) { return p.x() * p.y(); }},
      {"vortex", [](const Point_3& p) { return std::optional<Vector_3>(Vector_3(-p.y(), p.x(), 0)); },
       [](const Point_3& p) { return -(p.x() * p.x() + p.y() * p.y()) / 2; }},
      {"cellular",
       [](const Point_3& p) {
         return std::optional<Vector_3>(
             Vector_3(std::sin(p.x()) * std::cos(p.y()), -std::cos(p.x()) * std::sin(p.y()), 0));
       },
       [](const Point_3& p) { return std::sin(p.x()) * std::sin(p.y()); }},
  };
  for (const Planar_case& c : cases) {
    const std::vector<double> errors = planar_errors(c, true);
    EXPECT_LE(errors[1], 1e-3) << c.name;
    EXPECT_LT(errors[1], errors[0]) << c.name;
  }
}

TEST(Parametrize, UnnormalizedTangentialRIsThePotentialOfACurlFreeFlow)
{
  const Planar_case cases[] = {
      {"source", [](const Point_3& p) { return std::optional<Vector_3>(Vector_3(p.x(), p.y(), 0)); },
       [](const Point_3& p) { return (p.x() * p.x() + p.y() * p.y()) / 2; }},
      {"cellular",
       [](const Point_3& p) {
         return std::optional<Vector_3>(
             Vector_3(std::cos(p.x()) * std::sin(p.y()), std::sin(p.x()) * std::cos(p.y()), 0));
       },
       [](const Point_3& p) { return std::sin(p.x()) * std::sin(p.y()); }},
  };
  for (const Planar_case& c : cases) {
    const std::vector<double> errors = planar_errors(c, false);
    EXPECT_LE(errors[1], 1e-3) << c.name;
    EXPECT_LT(errors[1], errors[0]) << c.name;
  }
}

// The vertex of `tm` nearest to `p`.
Vertex nearest_vertex(const Mesh& tm, const Point_3& p)
{
  Vertex best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (Vertex v : tm.vertices())
    if (CGAL::squared_distance(tm.point(v), p) < best_distance) {
      best_distance = CGAL::squared_distance(tm.point(v), p);
      best = v;
    }
  return best;
}

TEST(Parametrize, NormalizedTangentialInAUniformFlowIsTheDistanceAlongTheFlow)
{
  // A tilted plane containing u = (1, 2, 0): r = u.(x - x_c)/|u|, s = (u x n).(x - x_c)/|u|,
  // exactly (linear), with x_c the constrained vertex.
  const Vector_3 u(1, 2, 0), normal(2, -1, 1.5);
  const auto uniform = [&](const Point_3&) { return std::optional<Vector_3>(3 * u); };
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(1, -1, 2), normal, 1.5, 1.0, 800);
  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
  const Vertex c = *std::next(tm.vertices().begin(), 17);
  FAS::parametrize_tangential(tm, uniform, r, s, FAS::parameters::constraint_vertex(c));
  const Vector_3 a = u / std::sqrt(u.squared_length());
  const Vector_3 n = normal / std::sqrt(normal.squared_length());
  const Vector_3 b = CGAL::cross_product(a, n);
  EXPECT_EQ(r[c], 0.0);
  EXPECT_EQ(s[c], 0.0);
  for (Vertex v : tm.vertices()) {
    EXPECT_NEAR(r[v], a * (tm.point(v) - tm.point(c)), 1e-10);
    EXPECT_NEAR(s[v], b * (tm.point(v) - tm.point(c)), 1e-10);
  }
}

TEST(Parametrize, NormalizedTangentialInARadialFlowIsTheRadius)
{
  // v = (x, y)/|(x, y)|^3: the normalized guidance is the gradient of |(x, y)|.
  const auto radial = [](const Point_3& p) {
    const double r2 = p.x() * p.x() + p.y() * p.y();
    return std::optional<Vector_3>(Vector_3(p.x(), p.y(), 0) / (r2 * std::sqrt(r2)));
  };
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(2, 1, 0), Vector_3(0, 0, 1), 2.0, 1.0, 10000);
  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
  FAS::parametrize_tangential(tm, radial, r, s);
  EXPECT_LE(relative_error_up_to_constant(tm, r, [](const Point_3& p) { return std::hypot(p.x(), p.y()); }),
            1e-3);
}

TEST(Parametrize, DefaultConstraintIsTheVertexNearestToTheBarycenter)
{
  Mesh tm;
  // An L-shaped union is not needed: a rectangle's barycenter is its center.
  FAS::make_planar_patch(tm, Point_3(0.25, 0.5, 0), Vector_3(0, 0, 1), 1.0, 0.6, 600);
  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
  FAS::parametrize_tangential(
      tm, [](const Point_3& p) { return std::optional<Vector_3>(Vector_3(1 + p.y(), 0.5, 0)); }, r, s);
  const Vertex c = nearest_vertex(tm, Point_3(0.25, 0.5, 0));
  EXPECT_EQ(r[c], 0.0);
  EXPECT_EQ(s[c], 0.0);
}

TEST(Parametrize, OrthogonalOnAPlaneInAUniformFlowIsLinearAndTurnsWithTheAngle)
{
  const auto uniform = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(0, 0, 2)); };
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 1), Vector_3(0, 0, 1), 1.0, 500);
  // Gradient of a linear vertex field from a least-squares fit over the vertices.
  const auto gradient = [&](Scalar_map f) {
    Eigen::MatrixXd design(tm.number_of_vertices(), 3);
    Eigen::VectorXd values(tm.number_of_vertices());
    Eigen::Index i = 0;
    for (Vertex v : tm.vertices()) {
      design.row(i) << tm.point(v).x(), tm.point(v).y(), 1;
      values[i++] = f[v];
    }
    const Eigen::Vector3d fit = design.colPivHouseholderQr().solve(values);
    const Eigen::VectorXd residual = design * fit - values;
    EXPECT_LE(residual.cwiseAbs().maxCoeff(), 1e-10); // the field is exactly linear
    return Eigen::Vector2d(fit[0], fit[1]);
  };
  auto r0 = add_scalar(tm, "v:r0"), s0 = add_scalar(tm, "v:s0");
  auto r1 = add_scalar(tm, "v:r1"), s1 = add_scalar(tm, "v:s1");
  FAS::parametrize_orthogonal(tm, uniform, r0, s0);
  const Eigen::Vector2d g0 = gradient(r0);
  EXPECT_NEAR(g0.norm(), 2, 1e-10); // |a_j| = |v_j| for a unit turned direction orthogonal to v
  for (double alpha : {0.4, CGAL_PI / 2, -2.0}) {
    FAS::parametrize_orthogonal(tm, uniform, r1, s1, FAS::parameters::angle(alpha));
    const Eigen::Vector2d expected = Eigen::Rotation2Dd(alpha) * g0;
    EXPECT_NEAR((gradient(r1) - expected).norm(), 0, 1e-9) << alpha;
    if (alpha == CGAL_PI / 2) {
      for (Vertex v : tm.vertices())
        EXPECT_NEAR(r1[v], -s0[v], 1e-10);
    }
  }
  FAS::parametrize_orthogonal(tm, uniform, r1, s1, FAS::parameters::normalized(true));
  EXPECT_NEAR((gradient(r1) - g0 / 2).norm(), 0, 1e-10);
}

TEST(Parametrize, EachConnectedComponentHasItsOwnConstraint)
{
  // Two squares in the source flow v = (x, y): r = potential - potential(center vertex) on each.
  const auto source = [](const Point_3& p) { return std::optional<Vector_3>(Vector_3(p.x(), p.y(), 0)); };
  const auto potential = [](const Point_3& p) { return (p.x() * p.x() + p.y() * p.y()) / 2; };
  Mesh tm;
  const Point_3 centers[2] = {Point_3(0, 0, 0), Point_3(3, 1, 0)};
  for (const Point_3& center : centers)
    FAS::make_planar_patch(tm, center, Vector_3(0, 0, 1), 1.0, 1.0, 3000);
  auto r = add_scalar(tm, "v:r"), s = add_scalar(tm, "v:s");
  FAS::parametrize_tangential(tm, source, r, s, FAS::parameters::normalized(false));
  for (const Point_3& center : centers) {
    // The constrained vertex is where r is exactly 0; it must be one of the vertices nearest to
    // the square's center (its barycenter).
    std::optional<Vertex> zero;
    for (Vertex v : tm.vertices())
      if (r[v] == 0 && CGAL::squared_distance(tm.point(v), center) < 1) {
        EXPECT_FALSE(zero) << "two constrained vertices in one component";
        zero = v;
      }
    ASSERT_TRUE(zero);
    const Vertex c = *zero;
    EXPECT_NEAR(CGAL::squared_distance(tm.point(c), center),
                CGAL::squared_distance(tm.point(nearest_vertex(tm, center)), center), 1e-12);
    double largest_error = 0;
    for (Vertex v : tm.vertices())
      if (CGAL::squared_distance(tm.point(v), center) < 1)
        largest_error =
            (std::max)(largest_error, std::abs(r[v] - (potential(tm.point(v)) - potential(tm.point(c)))));
    EXPECT_LE(largest_error, 1e-3) << center;
  }
}

TEST(Parametrize, BadInputIsRefusedAndTheOutputUntouched)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 200);
  auto r = add_scalar(tm, "v:r", 7), s = add_scalar(tm, "v:s", 7);
  const auto uniform = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(1, 0, 0)); };
  expect_invalid_argument(
      [&] {
        FAS::parametrize_tangential(tm, uniform, r, s, FAS::parameters::constraint_vertex(Vertex(100000)));
      },
      {"parametrize_tangential", "constraint_vertex", "not a vertex of tm"});
  expect_invalid_argument(
      [&] {
        FAS::parametrize_orthogonal(tm, uniform, r, s,
                                    FAS::parameters::angle(std::numeric_limits<double>::quiet_NaN()));
      },
      {"parametrize_orthogonal", "angle must be finite"});
  expect_invalid_argument(
      [&] {
        FAS::parametrize_orthogonal(tm, uniform, r, s,
                                    FAS::parameters::angle(std::numeric_limits<double>::infinity()));
      },
      {"angle must be finite", "inf"});
  const auto zero = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(0, 0, 0)); };
  const auto nowhere = [](const Point_3&) { return std::optional<Vector_3>(); };
  const auto normal = [](const Point_3&) { return std::optional<Vector_3>(Vector_3(0, 0, 1)); };
  expect_invalid_argument([&] { FAS::parametrize_tangential(tm, zero, r, s); },
                          {"parametrize_tangential", "no usable direction on any face"});
  expect_invalid_argument([&] { FAS::parametrize_orthogonal(tm, nowhere, r, s); },
                          {"parametrize_orthogonal", "no usable direction on any face"});
  // Tangential guidance from a field normal to a plane does not exist.
  expect_invalid_argument([&] { FAS::parametrize_tangential(tm, normal, r, s); }, {"no usable direction"});
  Mesh empty;
  auto er = add_scalar(empty, "v:r"), es = add_scalar(empty, "v:s");
  expect_invalid_argument([&] { FAS::parametrize_tangential(empty, uniform, er, es); },
                          {"parametrize_tangential: tm", "no faces"});
  auto d = add_scalar(tm, "v:d", 7);
  expect_invalid_argument([&] { FAS::compute_geodesic_distance(tm, Vertex(100000), d); },
                          {"compute_geodesic_distance", "source", "not a vertex of tm"});
  for (Vertex v : tm.vertices()) {
    EXPECT_EQ(r[v], 7.0);
    EXPECT_EQ(s[v], 7.0);
    EXPECT_EQ(d[v], 7.0);
  }
}

// The mean of |d - exact| / exact over the vertices other than the source.
double mean_relative_error(const Mesh& tm, Scalar_map d, const Scalar& exact, Vertex source)
{
  double sum = 0;
  std::size_t count = 0;
  for (Vertex v : tm.vertices()) {
    if (v == source)
      continue;
    sum += std::abs(d[v] - exact(tm.point(v))) / exact(tm.point(v));
    ++count;
  }
  return sum / double(count);
}

TEST(GeodesicDistance, OnAPlaneItIsTheEuclideanDistance)
{
  Mesh tm;
  const Point_3 center(0.5, -1, 2);
  FAS::make_disk_patch(tm, center, Vector_3(1, 1, 1), 1.0, 10000);
  const Vertex source = nearest_vertex(tm, center);
  auto d = add_scalar(tm, "v:d");
  FAS::compute_geodesic_distance(tm, source, d);
  EXPECT_EQ(d[source], 0.0);
  const auto euclidean = [&](const Point_3& p) {
    return std::sqrt(CGAL::squared_distance(p, tm.point(source)));
  };
  EXPECT_LE(mean_relative_error(tm, d, euclidean, source), 0.01);
}

// A spherical cap of radius R about the north pole, up to the polar angle `max_angle`: the disk
// patch mapped by the inverse azimuthal equidistant projection, so that its vertices are as
// regular as the disk's.
Mesh make_sphere_cap(double R, double max_angle, std::size_t faces)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), R * max_angle, faces);
  for (Vertex v : tm.vertices()) {
    const Point_3 p = tm.point(v);
    const double rho = std::hypot(p.x(), p.y()), theta = rho / R;
    const double scale = rho > 0 ? R * std::sin(theta) / rho : 0;
    tm.point(v) = Point_3(scale * p.x(), scale * p.y(), R * std::cos(theta));
  }
  return tm;
}

TEST(GeodesicDistance, OnASphereCapItIsTheGreatCircleDistanceAndAgreesWithCGALsHeatMethod)
{
  const double R = 2;
  Mesh tm = make_sphere_cap(R, 1.2, 10000);
  const Vertex pole = nearest_vertex(tm, Point_3(0, 0, R));
  ASSERT_EQ(tm.point(pole), Point_3(0, 0, R));
  auto d = add_scalar(tm, "v:d");
  FAS::compute_geodesic_distance(tm, pole, d);
  const auto great_circle = [&](const Point_3& p) { return R * std::acos(std::clamp(p.z() / R, -1.0, 1.0)); };
  const double error = mean_relative_error(tm, d, great_circle, pole);
  EXPECT_LE(error, 0.01);

  auto cgal = add_scalar(tm, "v:cgal");
  CGAL::Heat_method_3::estimate_geodesic_distances(tm, cgal, pole);
  const double cgal_error = mean_relative_error(tm, cgal, great_circle, pole);
  double difference = 0;
  for (Vertex v : tm.vertices())
    if (v != pole)
      difference += std::abs(d[v] - cgal[v]) / cgal[v];
  difference /= double(tm.number_of_vertices() - 1);
  std::cout << "mean relative error: ours " << error << ", CGAL " << cgal_error << ", difference "
            << difference << std::endl;
  EXPECT_LE(difference, 0.01);
  EXPECT_LE(error, 1.5 * cgal_error);
}

TEST(GeodesicDistance, OtherComponentsAreInfinitelyFar)
{
  Mesh tm;
  FAS::make_disk_patch(tm, Point_3(0, 0, 0), Vector_3(0, 0, 1), 1.0, 2000);
  FAS::make_disk_patch(tm, Point_3(5, 0, 0), Vector_3(0, 0, 1), 1.0, 500);
  const Vertex source = nearest_vertex(tm, Point_3(0, 0, 0));
  auto d = add_scalar(tm, "v:d");
  FAS::compute_geodesic_distance(tm, source, d);
  const auto euclidean = [](const Point_3& p) { return std::hypot(p.x(), p.y()); };
  for (Vertex v : tm.vertices()) {
    if (tm.point(v).x() > 2.5) {
      EXPECT_EQ(d[v], std::numeric_limits<double>::infinity());
    }
    else if (v != source) {
      EXPECT_NEAR(d[v], euclidean(tm.point(v)), 0.05);
    }
  }
}

} // namespace

} // namespace test_parametrize
