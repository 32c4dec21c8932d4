// What the tests of read_flow_field() share: the linear field that every grid and cell type
// reproduces exactly,
//   v(p) = (1 + x + 2y - z, -2 + x/2 - 3y + 2z, 1/2 - 2x + y + z/4),
// sampled on a small uniform grid, and the check that a file read gives it back.

#ifndef FAS_TEST_READ_FLOW_FIELD_TEST_HELPERS_H
#define FAS_TEST_READ_FLOW_FIELD_TEST_HELPERS_H

#include "test_files.h"

#include <CGAL/Flow_aligned_surfaces/IO/read_flow_field.h>
#include <CGAL/Flow_aligned_surfaces/Regular_grid_flow_field_3.h>
#include <CGAL/Flow_aligned_surfaces/Sampled_flow_field_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace fas_read_flow_field_test {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Sampled = CGAL::Flow_aligned_surfaces::Sampled_flow_field_3<K>;
namespace FAS = CGAL::Flow_aligned_surfaces;

inline Vector linear(const Point& p)
{
  const double x = p.x(), y = p.y(), z = p.z();
  return Vector(1 + x + 2 * y - z, -2 + x / 2 - 3 * y + 2 * z, 0.5 - 2 * x + y + z / 4);
}

inline std::string scratch(const std::string& name)
{
  return temporary_file("fas_read_flow_field_", name);
}

// Reads `file`, expects the alternative `Field`, and compares with the linear field at the
// points of the bounding box where the field is defined (a few cells of the unstructured
// test meshes cover a fifth of their box: at least a tenth of the points must be inside).
template <class Field>
void expect_reads_linear_field(const std::string& file)
{
  SCOPED_TRACE(file);
  Sampled field;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_flow_field(file, field, FAS::parameters::error_message(&error))) << error;
  ASSERT_NE(field.get_if<Field>(), nullptr) << "the file was read into another kind of field";
  const CGAL::Bbox_3 box = field.bbox();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0., 1.);
  int defined = 0;
  const int samples = 400;
  for (int s = 0; s < samples; ++s) {
    const Point p(box.xmin() + u(random) * (box.xmax() - box.xmin()),
                  box.ymin() + u(random) * (box.ymax() - box.ymin()),
                  box.zmin() + u(random) * (box.zmax() - box.zmin()));
    const std::optional<Vector> v = field(p);
    // The sampled field forwards to the field it holds (up to rounding: a cells field starts
    // Newton's iteration from its thread's previous query).
    const std::optional<Vector> direct = (*field.get_if<Field>())(p);
    ASSERT_EQ(bool(v), bool(direct));
    if (!v)
      continue;
    ++defined;
    EXPECT_LT(std::sqrt((*v - *direct).squared_length()), 1e-12) << "at " << p;
    const Vector e = linear(p);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR((*v)[d], e[d], 1e-5 * (1 + std::abs(e[d]))) << "at " << p; // float storage
  }
  EXPECT_GE(defined, samples / 10);
}

// The linear field sampled on a 4 x 3 x 5 uniform grid.
inline Sampled::Regular_grid linear_grid()
{
  return FAS::sample_on_grid([](const Point& p) { return std::optional<Vector>(linear(p)); },
                             Point(0.25, -1., 0.5), Vector(0.5, 0.25, 0.75), {{4, 3, 5}});
}

} // namespace fas_read_flow_field_test

#endif // FAS_TEST_READ_FLOW_FIELD_TEST_HELPERS_H
