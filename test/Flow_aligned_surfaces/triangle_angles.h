// The smallest interior angle of a triangle of a mesh, in degrees: how the growing tests judge
// the shape of the new faces.

#ifndef FAS_TEST_TRIANGLE_ANGLES_H
#define FAS_TEST_TRIANGLE_ANGLES_H

#include <CGAL/number_utils.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fas_test {

/// The smallest angle (degrees) of the triangle `f` of `tm`.
template <class Mesh>
double smallest_angle_degrees(const Mesh& tm, typename boost::graph_traits<Mesh>::face_descriptor f)
{
  using Point = typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type;
  std::vector<Point> p;
  for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
    p.push_back(get(CGAL::vertex_point, tm, v));
  double smallest = 180;
  for (int i = 0; i < 3; ++i) {
    const auto a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
    const double c = CGAL::to_double(a * b) / std::sqrt(CGAL::to_double(a.squared_length() * b.squared_length()));
    smallest = (std::min)(smallest, std::acos(std::clamp(c, -1.0, 1.0)) * 180 / CGAL_PI);
  }
  return smallest;
}

} // namespace fas_test

#endif // FAS_TEST_TRIANGLE_ANGLES_H
