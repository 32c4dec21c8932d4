// The kernel of the test suites, its point and vector types, and the package's namespace
// alias; a suite takes them with `using namespace fas_test;`.

#ifndef FAS_TEST_TEST_KERNEL_H
#define FAS_TEST_TEST_KERNEL_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace CGAL {
namespace Flow_aligned_surfaces {
}
} // namespace CGAL

namespace fas_test {

namespace FAS = CGAL::Flow_aligned_surfaces;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;

} // namespace fas_test

#endif // FAS_TEST_TEST_KERNEL_H
