// Errors of a vertex scalar field of a CGAL::Surface_mesh against a closed form, shared by the
// parametrization tests.

#ifndef FAS_TEST_SCALAR_FIELD_ERRORS_H
#define FAS_TEST_SCALAR_FIELD_ERRORS_H

#include <cmath>
#include <functional>

namespace fas_test {

/// ||(f - g) - mean(f - g)|| / ||g - mean(g)|| over the vertices of `tm`: the relative error of
/// the vertex field `f` against the function `g` of the position, up to a constant.
template <class Mesh, class ScalarMap>
double relative_error_up_to_constant(const Mesh& tm, ScalarMap f,
                                     const std::function<double(const typename Mesh::Point&)>& g)
{
  double mean_difference = 0, mean_g = 0;
  for (auto v : tm.vertices()) {
    mean_difference += f[v] - g(tm.point(v));
    mean_g += g(tm.point(v));
  }
  mean_difference /= double(tm.number_of_vertices());
  mean_g /= double(tm.number_of_vertices());
  double error = 0, norm = 0;
  for (auto v : tm.vertices()) {
    error += std::pow(f[v] - g(tm.point(v)) - mean_difference, 2);
    norm += std::pow(g(tm.point(v)) - mean_g, 2);
  }
  return std::sqrt(error / norm);
}

} // namespace fas_test

#endif // FAS_TEST_SCALAR_FIELD_ERRORS_H
