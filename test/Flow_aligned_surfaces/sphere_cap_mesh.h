// A spherical cap of radius R about the north pole (0, 0, R), up to the polar angle `max_angle`:
// the disk patch of make_disk_patch() mapped by the inverse azimuthal equidistant projection, so
// that its vertices are as regular as the disk's and its center vertex is the pole.  With
// `jitter` > 0 the interior vertices but the center are first moved in the disk's plane by up to
// `jitter` times the mean edge length (a fixed generator), which leaves triangles that are not
// Delaunay.  Used by test_parametrize.cpp and by benchmark/.../bench_geodesic_distance.cpp.

#ifndef FAS_TEST_SPHERE_CAP_MESH_H
#define FAS_TEST_SPHERE_CAP_MESH_H

#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>

#include <cmath>
#include <cstddef>

namespace fas_test {

template <class Mesh>
Mesh make_sphere_cap(double R, double max_angle, std::size_t faces, double jitter = 0)
{
  using Point = typename Mesh::Point;
  using Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  Mesh tm;
  CGAL::Flow_aligned_surfaces::make_disk_patch(tm, Point(0, 0, 0), Vector(0, 0, 1), R * max_angle, faces);
  if (jitter > 0) {
    double edge = 0;
    for (auto e : tm.edges())
      edge += std::sqrt((tm.point(tm.vertex(e, 0)) - tm.point(tm.vertex(e, 1))).squared_length());
    edge /= double(tm.number_of_edges());
    unsigned state = 12345;
    const auto uniform = [&state] { // in [-1, 1]
      state = state * 1103515245u + 12345u;
      return double((state >> 8) & 0xffff) / 32767.5 - 1;
    };
    for (auto v : tm.vertices()) {
      const Point p = tm.point(v);
      if (!tm.is_border(v) && (p.x() != 0 || p.y() != 0)) {
        const double dx = jitter * edge * uniform(), dy = jitter * edge * uniform();
        tm.point(v) = Point(p.x() + dx, p.y() + dy, 0);
      }
    }
  }
  for (auto v : tm.vertices()) {
    const Point p = tm.point(v);
    const double rho = std::hypot(p.x(), p.y()), theta = rho / R;
    const double scale = rho > 0 ? R * std::sin(theta) / rho : 0;
    tm.point(v) = Point(scale * p.x(), scale * p.y(), R * std::cos(theta));
  }
  return tm;
}

} // namespace fas_test

#endif // FAS_TEST_SPHERE_CAP_MESH_H
