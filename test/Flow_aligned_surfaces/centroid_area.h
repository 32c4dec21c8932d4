// The reference of the measures' tests: the area and number of the faces of a mesh whose
// centroids satisfy a predicate (the measures sample the flow at the face centroids, so a
// piecewise field's regions cover exactly these faces).

#ifndef FAS_TEST_CENTROID_AREA_H
#define FAS_TEST_CENTROID_AREA_H

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/centroid.h>

#include <cstddef>

namespace fas_test {

struct Centroid_area {
  double area = 0;                 ///< the area of the faces whose centroid satisfies the predicate
  std::size_t number_of_faces = 0; ///< their number
  double total_area = 0;           ///< the area of all faces
};

/// The faces of `tm` whose centroid `c` satisfies `predicate(c)`.
template <class Mesh, class Predicate>
Centroid_area centroid_area(const Mesh& tm, const Predicate& predicate)
{
  Centroid_area result;
  for (auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto c =
        CGAL::centroid(tm.point(source(h, tm)), tm.point(target(h, tm)), tm.point(target(next(h, tm), tm)));
    const double area = CGAL::Polygon_mesh_processing::face_area(f, tm);
    result.total_area += area;
    if (predicate(c)) {
      result.area += area;
      ++result.number_of_faces;
    }
  }
  return result;
}

} // namespace fas_test

#endif // FAS_TEST_CENTROID_AREA_H
